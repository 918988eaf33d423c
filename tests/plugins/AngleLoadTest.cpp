// Tests of AngleLoad (plugins/loads/AngleLoad.h). Expected values come from
// closed forms: the half-sine pulse's Fourier coefficients and work from
// validation/oracles/JawCrusherOracle (written from the integrals, not from
// the element's quadrature), the law of the class comment written out
// afresh, or Simbody's own energy bookkeeping -- never from the element.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "plugins/loads/AngleLoad.h"
#include "tests/plugins/ShaftFixture.h"
#include "validation/oracles/JawCrusherOracle.h"

namespace milldyn {
namespace {

using test::ShaftSystem;

const double kPi = SimTK::Pi;

AngleLoadParams pulseParams(double peak, double start, double width, int cycles) {
    AngleLoadParams p;
    p.shape = AngleLoadParams::Shape::HalfSinePulse;
    p.peakTorque = peak;
    p.pulseStart = start;
    p.pulseWidth = width;
    p.cyclesPerRevolution = cycles;
    return p;
}

struct LoadOnShaft {
    explicit LoadOnShaft(const AngleLoadParams& p, double J = 10.0)
        : shaft(rig.addShaft(J)), element(new AngleLoad(rig.forces(), {shaft}, p)), force(rig.forces(), element),
          state(rig.defaultState()) {}
    /// The load torque (> 0 opposing) at shaft angle θ and speed ω.
    double loadAt(double theta, double omega) {
        test::setShaft(state, shaft, theta, omega);
        return -test::torqueOn(rig.system(), force, state, shaft);
    }
    ShaftSystem rig;
    SimTK::MobilizedBody::Pin shaft;
    AngleLoad* element;
    SimTK::Force::Custom force;
    SimTK::State state;
};

// ---- 1. one pulse element equals its own Fourier series ---------------------

// The quadrature of the element is O(h²) at the pulse's kinks: h = 2π/65536
// gives ~1e-8 of the peak; 1e-6 leaves room and still fails on any wrong
// coefficient (they are ~1e-3 of the peak at k = 20).
constexpr double kCoefficientTolerance = 1e-6;

TEST(AngleLoadTest, HalfSinePulseCoefficientsMatchTheClosedForm) {
    for (double width : {kPi, 2.0, 0.7}) {
        const oracle::HalfSinePulse pulse{1000.0, 0.4, width};
        LoadOnShaft m(pulseParams(pulse.peak, pulse.start, pulse.width, 2));
        const oracle::FourierSeries f = oracle::halfSinePulseSeries(pulse, 20);
        EXPECT_NEAR(m.element->meanTorque(), f.mean, kCoefficientTolerance * pulse.peak) << "w = " << width;
        for (int k = 1; k <= 20; ++k) {
            EXPECT_NEAR(m.element->cosineCoefficient(k), f.cosine[k - 1], kCoefficientTolerance * pulse.peak)
                << "a_" << k << ", w = " << width;
            EXPECT_NEAR(m.element->sineCoefficient(k), f.sine[k - 1], kCoefficientTolerance * pulse.peak)
                << "b_" << k << ", w = " << width;
        }
    }
}

TEST(AngleLoadTest, PulseElementEqualsItsFourierSeriesElement) {
    // The closed-form series, truncated at K, as a second element: the two
    // loads differ by at most the series' tail bound at every angle.
    const oracle::HalfSinePulse pulse{1500.0, 0.3, kPi};
    const int K = 1000;
    const oracle::FourierSeries f = oracle::halfSinePulseSeries(pulse, K);
    AngleLoadParams series;
    series.shape = AngleLoadParams::Shape::Fourier;
    series.meanTorque = f.mean;
    series.cosineAmplitudes = f.cosine;
    series.sineAmplitudes = f.sine;
    series.cyclesPerRevolution = 1;
    LoadOnShaft a(pulseParams(pulse.peak, pulse.start, pulse.width, 1)), b(series);
    const double bound = oracle::halfSinePulseTailBound(pulse, K);
    ASSERT_LT(bound, 3e-3 * pulse.peak);  // the comparison means something
    const double omega = 20.0;            // tanh(2000) = 1
    for (int i = 0; i < 360; ++i) {
        const double theta = 2 * kPi * i / 360 + 0.001;
        EXPECT_NEAR(a.loadAt(theta, omega), b.loadAt(theta, omega), bound) << "θ = " << theta;
    }
    // and the pulse itself, written out: P·sin(π(θ − ψ0)/w) inside, 0 outside
    EXPECT_NEAR(a.loadAt(pulse.start + kPi / 2, omega), pulse.peak, 1e-9 * pulse.peak);
    EXPECT_EQ(a.loadAt(pulse.start + kPi + 0.5, omega), 0.0);
}

TEST(AngleLoadTest, HalfWavePulseHasNoOddHarmonicsAboveTheFirst) {
    // w = π: P/π + (P/2) sin u − Σ_{k even} 2P/(π(k² − 1)) cos ku
    const double P = 800.0;
    LoadOnShaft m(pulseParams(P, 0.0, kPi, 1));
    EXPECT_NEAR(m.element->runningHarmonicAmplitude(1), P / 2, kCoefficientTolerance * P);
    EXPECT_NEAR(m.element->runningHarmonicAmplitude(2), 2 * P / (3 * kPi), kCoefficientTolerance * P);
    EXPECT_NEAR(m.element->runningHarmonicAmplitude(3), 0.0, kCoefficientTolerance * P);
    EXPECT_NEAR(m.element->runningHarmonicAmplitude(4), 2 * P / (15 * kPi), kCoefficientTolerance * P);
    EXPECT_NEAR(m.element->meanTorque(), P / kPi, kCoefficientTolerance * P);
}

// ---- 2. no work on a standing shaft --------------------------------------------

TEST(AngleLoadTest, StandingShaftGetsNoTorqueAtAnyAngle) {
    LoadOnShaft m(pulseParams(2000.0, 0.0, kPi, 1));
    for (int i = 0; i < 72; ++i) {
        const double theta = 2 * kPi * i / 72;
        EXPECT_EQ(m.loadAt(theta, 0.0), 0.0) << "θ = " << theta;
        m.rig.system().realize(m.state, SimTK::Stage::Acceleration);
        EXPECT_EQ(m.shaft.getOneUDot(m.state, SimTK::MobilizerUIndex(0)), 0.0);
        EXPECT_EQ(m.element->getValues(m.state).totalPower, 0.0);
    }
    // and the sign follows the motion: reversed speed, reversed torque
    EXPECT_NEAR(m.loadAt(kPi / 2, -5.0), -2000.0, 1e-9 * 2000.0);
    // regularised over ωs: at ω = ωs the crushing part is tanh(1) of g
    EXPECT_NEAR(m.loadAt(kPi / 2, 0.01), 2000.0 * std::tanh(1.0), 1e-9 * 2000.0);
}

TEST(AngleLoadTest, ShaftLeftAtRestStaysAtRest) {
    // PeriodicLoad drove a standing shaft (its periodic part is a function
    // of time); the angle-tied load must not.
    LoadOnShaft m(pulseParams(2000.0, 0.0, kPi, 1), 1.0);
    test::setShaft(m.state, m.shaft, kPi / 2, 0.0);
    std::vector<double> work;
    const SimTK::State end = test::integrateWithQuadrature(m.rig.system(), m.state, 1.0, 10, {}, work);
    EXPECT_EQ(test::shaftSpeed(end, m.shaft), 0.0);
    EXPECT_EQ(m.shaft.getOneQ(end, SimTK::MobilizerQIndex(0)), kPi / 2);
}

// ---- 3. mean power = mean torque × ω ----------------------------------------------

TEST(AngleLoadTest, MeanPowerOverACycleIsMeanTorqueTimesSpeed) {
    const oracle::HalfSinePulse pulse{3000.0, 1.0, 2.5};
    const int n = 2;
    LoadOnShaft m(pulseParams(pulse.peak, pulse.start, pulse.width, n));
    const double omega = 25.0;
    const int N = 20000;  // midpoint rule over one revolution: smooth pieces, kinks at O(h²)
    double power = 0;
    for (int i = 0; i < N; ++i) {
        test::setShaft(m.state, m.shaft, 2 * kPi * (i + 0.5) / N, omega);
        m.rig.system().realize(m.state, SimTK::Stage::Velocity);
        power += m.element->getValues(m.state).totalPower / N;
    }
    const double meanTorque = oracle::halfSinePulseSeries(pulse, 1).mean;
    EXPECT_NEAR(power, meanTorque * omega, 1e-6 * meanTorque * omega);
}

TEST(AngleLoadTest, KineticEnergyLostIsTheClosedFormWorkOfTheStrokes) {
    // A free flywheel coasting through the strokes loses exactly the pulses'
    // work ∫ g dθ over the angle it turned, whatever its speed did.
    const oracle::HalfSinePulse pulse{500.0, 0.0, kPi};
    const int n = 1;
    LoadOnShaft m(pulseParams(pulse.peak, pulse.start, pulse.width, n), 50.0);
    test::setShaft(m.state, m.shaft, 0.0, 30.0);
    m.rig.system().realize(m.state, SimTK::Stage::Velocity);
    const double KE0 = m.rig.matter().calcKineticEnergy(m.state);
    // ~ 3 revolutions
    std::vector<double> work;
    const SimTK::State end = test::integrateWithQuadrature(m.rig.system(), m.state, 0.7, 700, {}, work);
    m.rig.system().realize(end, SimTK::Stage::Velocity);
    const double theta = m.shaft.getOneQ(end, SimTK::MobilizerQIndex(0));
    // ∫0^θ g dθ for the half-wave pulse: 2P per whole revolution, P(1 − cos r) over the rest r < π
    const double whole = std::floor(theta / (2 * kPi));
    const double rest = theta - 2 * kPi * whole;
    const double expected = whole * oracle::halfSinePulseWorkPerStroke(pulse, n) +
                            (rest < kPi ? pulse.peak * (1 - std::cos(rest)) : 2 * pulse.peak);
    EXPECT_GT(whole, 2.0);
    const double lost = KE0 - m.rig.matter().calcKineticEnergy(end);
    // tanh(ω/ωs) = 1 in double at these speeds; the integrator's 1e-9.
    EXPECT_NEAR(lost, expected, 1e-6 * expected);
}

// ---- 4. the conservative part returns its energy -------------------------------------

TEST(AngleLoadTest, SpringPartConservesKineticPlusPotentialEnergy) {
    AngleLoadParams p;
    p.shape = AngleLoadParams::Shape::Fourier;
    p.cyclesPerRevolution = 2;
    p.springCosineAmplitudes = {300.0, 0.0, 50.0};
    p.springSineAmplitudes = {-120.0, 80.0};
    LoadOnShaft m(p, 20.0);
    // dV/dθ = c(ψ): finite difference of the potential against the torque
    for (double theta : {0.1, 1.3, 2.9, 4.4}) {
        const double h = 1e-5;
        test::setShaft(m.state, m.shaft, theta + h, 0.0);
        m.rig.system().realize(m.state, SimTK::Stage::Dynamics);
        const double vPlus = m.rig.system().calcPotentialEnergy(m.state);
        test::setShaft(m.state, m.shaft, theta - h, 0.0);
        m.rig.system().realize(m.state, SimTK::Stage::Dynamics);
        const double vMinus = m.rig.system().calcPotentialEnergy(m.state);
        EXPECT_NEAR((vPlus - vMinus) / (2 * h), m.loadAt(theta, 0.0), 1e-5 * 300.0) << "θ = " << theta;
    }
    // V repeats after a revolution
    test::setShaft(m.state, m.shaft, 0.7, 0.0);
    m.rig.system().realize(m.state, SimTK::Stage::Dynamics);
    const double v0 = m.rig.system().calcPotentialEnergy(m.state);
    test::setShaft(m.state, m.shaft, 0.7 + 2 * kPi, 0.0);
    m.rig.system().realize(m.state, SimTK::Stage::Dynamics);
    EXPECT_NEAR(m.rig.system().calcPotentialEnergy(m.state), v0, 1e-9 * 300.0);
    // a trajectory: KE + V constant
    test::setShaft(m.state, m.shaft, 0.0, 15.0);
    m.rig.system().realize(m.state, SimTK::Stage::Dynamics);
    const double H0 = m.rig.system().calcEnergy(m.state);
    std::vector<double> work;
    double worst = 0;
    test::integrateWithQuadrature(m.rig.system(), m.state, 2.0, 200, {}, work,
                                  [&](const SimTK::State& s, const std::vector<double>&) {
                                      worst = std::max(worst, std::abs(m.rig.system().calcEnergy(s) - H0));
                                  });
    EXPECT_LT(worst, 1e-6 * H0);
    // and it did swing: the speed is not constant
    EXPECT_GT(m.element->params().springCosineAmplitudes[0], 0.0);
}

// ---- 5. orders, shafts, table ----------------------------------------------------------

TEST(AngleLoadTest, EachShaftRunsItsOwnPhase) {
    ShaftSystem rig;
    auto s1 = rig.addShaft(1.0), s2 = rig.addShaft(1.0);
    AngleLoadParams p = pulseParams(100.0, 0.0, kPi, 1);
    p.phases = {0.0, kPi};
    auto* e = new AngleLoad(rig.forces(), {s1, s2}, p);
    SimTK::Force::Custom force(rig.forces(), e);
    SimTK::State s = rig.defaultState();
    test::setShaft(s, s1, kPi / 2, 5.0);
    test::setShaft(s, s2, kPi / 2, 5.0);
    // shaft 1 at ψ = π/2: the peak; shaft 2 at ψ = π/2 − π: outside the pulse
    EXPECT_NEAR(-test::torqueOn(rig.system(), force, s, s1), 100.0, 1e-9);
    EXPECT_EQ(-test::torqueOn(rig.system(), force, s, s2), 0.0);
    test::setShaft(s, s2, 3 * kPi / 2, 5.0);
    EXPECT_NEAR(-test::torqueOn(rig.system(), force, s, s2), 100.0, 1e-9);
}

TEST(AngleLoadTest, TableIsPeriodicPiecewiseLinear) {
    AngleLoadParams p;
    p.shape = AngleLoadParams::Shape::Table;
    p.tableAngles = {0.5, 2.0, 4.0};
    p.tableTorques = {100.0, 400.0, 0.0};
    LoadOnShaft m(p);
    EXPECT_NEAR(m.loadAt(1.25, 10.0), 250.0, 1e-9);
    EXPECT_NEAR(m.loadAt(3.0, 10.0), 200.0, 1e-9);
    // wrap: from (4.0, 0) to (0.5 + 2π, 100)
    const double span = 0.5 + 2 * kPi - 4.0;
    EXPECT_NEAR(m.loadAt(0.2, 10.0), 100.0 * (0.2 + 2 * kPi - 4.0) / span, 1e-9);
    EXPECT_NEAR(m.loadAt(5.0, 10.0), 100.0 * (5.0 - 4.0) / span, 1e-9);
    EXPECT_NEAR(m.loadAt(5.0 + 2 * kPi, 10.0), 100.0 * (5.0 - 4.0) / span, 1e-9);
    // mean: trapezoids over the cycle / 2π
    const double area = (100.0 + 400.0) / 2 * 1.5 + (400.0 + 0.0) / 2 * 2.0 + (0.0 + 100.0) / 2 * span;
    EXPECT_NEAR(m.element->meanTorque(), area / (2 * kPi), 1e-6 * 400.0);
}

TEST(AngleLoadTest, BadParametersAreRefusedNamingTheKey) {
    auto make = [](const AngleLoadParams& p) {
        ShaftSystem rig;
        auto s = rig.addShaft(1.0);
        (void)std::make_unique<AngleLoad>(rig.forces(), std::vector<SimTK::MobilizedBody>{s}, p);
    };
    AngleLoadParams p = pulseParams(100.0, 0.0, 0.0, 1);
    test::expectInvalidArgumentNaming("pulse_width", [&] { make(p); });
    p = pulseParams(-1.0, 0.0, 1.0, 1);
    test::expectInvalidArgumentNaming("peak_torque", [&] { make(p); });
    p = pulseParams(100.0, 0.0, 1.0, 0);
    test::expectInvalidArgumentNaming("cycles_per_revolution", [&] { make(p); });
    p = pulseParams(100.0, 0.0, 1.0, 1);
    p.smoothingSpeed = 0;
    test::expectInvalidArgumentNaming("smoothing_speed", [&] { make(p); });
    AngleLoadParams t;
    t.shape = AngleLoadParams::Shape::Table;
    t.tableAngles = {1.0, 0.5};
    t.tableTorques = {1.0, 2.0};
    test::expectInvalidArgumentNaming("table_angles", [&] { make(t); });
}

}  // namespace
}  // namespace milldyn
