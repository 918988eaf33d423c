// Tests of PeriodicLoad (plugins/loads/PeriodicLoad.h). Expected values are worked
// out by hand in the comments, or computed here from the class comment's
// equations written out afresh (rowLoad below) or from sums derived by hand,
// or come from Simbody's own solve and bookkeeping -- never from the
// element's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "plugins/scene/ElementRegistry.h"
#include "plugins/loads/PeriodicLoad.h"
#include "driver/analyses/Analysis.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

using test::ShaftSystem;
using test::number;
using test::word;
using test::names;
using test::numbers;

constexpr double kShaftInertia = 0.1;     // kg*m^2
constexpr double kSmoothingSpeed = 0.01;  // rad/s, the schema default
// Far from standstill: tanh(1000) is 1 in double, so the mean acts in full.
constexpr double kRunningSpeed = 10.0;  // rad/s

// Closed forms in double against the element's few operations: ulps of
// torques ~1e2 N*m.
constexpr double kRoundingRelTolerance = 1e-12;
// Accelerations from Simbody's solve of the same torques: ulps.
constexpr double kSolverRelTolerance = 1e-12;

PeriodicLoadParams loadParams(int rows, double mean, std::vector<double> amplitudes, double P1,
                              bool staggered) {
    PeriodicLoadParams p;
    p.rows = rows;
    p.meanTorque = mean;
    p.amplitudes = std::move(amplitudes);
    p.fundamentalFrequency = P1;
    p.staggered = staggered;
    p.smoothingSpeed = kSmoothingSpeed;
    return p;
}

// The class comment's row law, written out again:
// M_r(t) = M̄·tanh(ω/ωs) + Σ_k b_k·sin(k·(P1·t + φ_r)), φ_r = 2πr/n or 0.
double rowLoad(const PeriodicLoadParams& p, int row, double t, double omega) {
    const double phase = p.staggered ? 2 * SimTK::Pi * row / p.rows : 0.0;
    double M = p.meanTorque * std::tanh(omega / p.smoothingSpeed);
    for (std::size_t i = 0; i < p.amplitudes.size(); ++i) {
        const double k = static_cast<double>(i + 1);
        M += p.amplitudes[i] * std::sin(k * (p.fundamentalFrequency * t + phase));
    }
    return M;
}

// Shafts with the given inertias and one PeriodicLoad on them.
struct LoadOnShafts {
    LoadOnShafts(const PeriodicLoadParams& p, const std::vector<double>& inertias)
        : shafts(makeShafts(rig, inertias)),
          load(new PeriodicLoad(rig.forces(), asMobods(shafts), p)),
          force(rig.forces(), load),
          state(rig.defaultState()) {}

    static std::vector<SimTK::MobilizedBody::Pin> makeShafts(ShaftSystem& rig,
                                                             const std::vector<double>& inertias) {
        std::vector<SimTK::MobilizedBody::Pin> out;
        for (double J : inertias) out.push_back(rig.addShaft(J));
        return out;
    }
    static std::vector<SimTK::MobilizedBody> asMobods(const std::vector<SimTK::MobilizedBody::Pin>& pins) {
        return std::vector<SimTK::MobilizedBody>(pins.begin(), pins.end());
    }

    /// Every shaft at speed ω and time t.
    void set(double t, double omega) {
        state.setTime(t);
        for (const auto& s : shafts) test::setShaft(state, s, 0.0, omega);
    }
    /// The mobility torque this element applies to shaft i.
    double torqueOn(std::size_t i) { return test::torqueOn(rig.system(), force, state, shafts[i]); }

    ShaftSystem rig;  // first: the members below are built on it
    std::vector<SimTK::MobilizedBody::Pin> shafts;
    PeriodicLoad* load;  // owned by force
    SimTK::Force::Custom force;
    SimTK::State state;
};

// ---- 1. torque vs closed form -----------------------------------------------

TEST(PeriodicLoadTest, OneRowTorqueIsMeanPlusFourierSeriesOpposingRotation) {
    LoadOnShafts m(loadParams(1, 100.0, {30.0, 20.0}, 2.0, true), {kShaftInertia});
    // t = 0.25 s, P1 = 2 rad/s: θ = 0.5 rad, one row so φ_0 = 0.
    // M = 100 + 30·sin(0.5) + 20·sin(1.0)
    //   = 100 + 30·0.479425538604203 + 20·0.8414709848078965
    //   = 100 + 14.38276615812609 + 16.82941969615793 = 131.21218585428403 N*m.
    m.set(0.25, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -131.21218585428403, kRoundingRelTolerance * 131);
    // t = π/4 s: θ = π/2, sin(π/2) = 1, sin(π) = 0: M = 100 + 30 = 130 N*m.
    m.set(SimTK::Pi / 4, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -130.0, kRoundingRelTolerance * 130);
    // t = 0: every sine is 0, the mean alone.
    m.set(0.0, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -100.0, kRoundingRelTolerance * 100);
}

TEST(PeriodicLoadTest, MeanReversesWithRotationButPeriodicPartIsAFunctionOfTimeOnly) {
    LoadOnShafts m(loadParams(1, 100.0, {30.0, 20.0}, 2.0, true), {kShaftInertia});
    // ω = −10: tanh = −1, so M = −100 + 31.21218585428403 = −68.78781414571598
    // N*m and the shaft gets +68.78781414571598.
    m.set(0.25, -kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), 68.78781414571598, kRoundingRelTolerance * 131);
}

TEST(PeriodicLoadTest, MeanFollowsTanhNearStandstill) {
    LoadOnShafts m(loadParams(1, 2.0, {}, 1.0, true), {kShaftInertia});
    // No harmonics. ω = ωs: 2·tanh(1) = 2·0.7615941559557649 = 1.5231883119115297.
    m.set(0.3, kSmoothingSpeed);
    EXPECT_NEAR(m.torqueOn(0), -1.5231883119115297, kRoundingRelTolerance * 2);
    m.set(0.3, -kSmoothingSpeed);
    EXPECT_NEAR(m.torqueOn(0), 1.5231883119115297, kRoundingRelTolerance * 2);
    m.set(0.3, 0.0);
    EXPECT_EQ(m.torqueOn(0), 0.0);
}

TEST(PeriodicLoadTest, RowPhasesAreEvenlySpreadOverTheFundamentalOrZero) {
    LoadOnShafts staggered(loadParams(4, 1.0, {1.0}, 1.0, true), {kShaftInertia});
    LoadOnShafts inPhase(loadParams(4, 1.0, {1.0}, 1.0, false), {kShaftInertia});
    for (int r = 0; r < 4; ++r) {
        // φ_r = 2πr/4 = r·π/2.
        EXPECT_NEAR(staggered.load->rowPhase(r), r * SimTK::Pi / 2, kRoundingRelTolerance * 5);
        EXPECT_EQ(inPhase.load->rowPhase(r), 0.0);
    }
}

// ---- 2. rows on one body: staggered cancels, in phase adds -------------------

// Derivation. For row r of n with φ_r = 2πr/n,
//   Σ_{r=0}^{n−1} sin(k(θ + 2πr/n)) = Im(e^{ikθ} Σ_r q^r),  q = e^{i2πk/n}.
// If n divides k, q = 1 and the sum is n·sin(kθ). Otherwise q ≠ 1 and
// q^n = e^{i2πk} = 1, so the geometric sum (1 − q^n)/(1 − q) is 0. So
//   Σ_r M_r(t) = n·M̄ + n·Σ_{k: n|k} b_k·sin(kθ),   θ = P1·t.
TEST(PeriodicLoadTest, StaggeredRowsOnOneBodyKeepOnlyHarmonicsThatAreMultiplesOfRowCount) {
    // n = 3, b_1..b_6 = 5, 7, 11, 13, 17, 19: only k = 3 (11) and k = 6 (19)
    // survive, times 3: Σ = 3·2 + 33·sin(3θ) + 57·sin(6θ).
    LoadOnShafts m(loadParams(3, 2.0, {5, 7, 11, 13, 17, 19}, 3.0, true), {kShaftInertia});
    // t = 0.1 s: θ = 0.3, sin(0.9) = 0.7833269096274834,
    // sin(1.8) = 0.9738476308781951: Σ = 6 + 25.849788017706953 +
    // 55.509314960057125 = 87.35910297776408 N*m.
    m.set(0.1, kRunningSpeed);
    const double sumOfAmplitudes = 3 * (2 + 5 + 7 + 11 + 13 + 17 + 19);  // rounding scale
    EXPECT_NEAR(m.torqueOn(0), -87.35910297776408, kRoundingRelTolerance * sumOfAmplitudes);
    for (double t : {0.0, 0.05, 0.37, 1.0, 2.9, 17.3}) {
        m.set(t, kRunningSpeed);
        const double theta = 3.0 * t;
        const double expected = 6 + 33 * std::sin(3 * theta) + 57 * std::sin(6 * theta);
        EXPECT_NEAR(m.torqueOn(0), -expected, kRoundingRelTolerance * sumOfAmplitudes) << "t = " << t;
        EXPECT_NEAR(m.load->getTotalTorque(m.state), expected, kRoundingRelTolerance * sumOfAmplitudes)
            << "t = " << t;
    }
}

// The crusher's case: nine staggered rows, harmonics 1..4, none a multiple
// of 9: the rotor as one body feels the mean alone, 9·M̄.
TEST(PeriodicLoadTest, NineStaggeredRowsCancelTheFirstFourHarmonicsOnOneBody) {
    LoadOnShafts m(loadParams(9, 7440.0, {4464, 2232, 1488, 1116}, 3.973, true), {639.0});
    for (double t : {0.0, 0.1, 0.5, 1.234, 7.7}) {
        m.set(t, 0.4966);
        // 36 sines of up to 4464 N*m each cancel: rounding ~ 36·4464·1e-16.
        EXPECT_NEAR(m.torqueOn(0), -9 * 7440.0, kRoundingRelTolerance * 9 * (7440 + 9300)) << "t = " << t;
    }
}

TEST(PeriodicLoadTest, InPhaseRowsOnOneBodySumToRowCountTimesEachHarmonic) {
    // All φ_r = 0: Σ = 3·(2 + 5·sin θ + 7·sin 2θ).
    LoadOnShafts m(loadParams(3, 2.0, {5, 7}, 3.0, false), {kShaftInertia});
    for (double t : {0.0, 0.1, 0.37, 2.9}) {
        m.set(t, kRunningSpeed);
        const double theta = 3.0 * t;
        const double expected = 3 * (2 + 5 * std::sin(theta) + 7 * std::sin(2 * theta));
        EXPECT_NEAR(m.torqueOn(0), -expected, kRoundingRelTolerance * 42) << "t = " << t;
    }
    // t = π/6 s: θ = π/2, sin θ = 1, sin 2θ = 0: 3·(2 + 5) = 21 N*m.
    m.set(SimTK::Pi / 6, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -21.0, kRoundingRelTolerance * 42);
}

// ---- 3. one body per row ------------------------------------------------------

// n = 3 staggered, M̄ = 10, b = (4, 2), t = 0 (θ = 0):
//   row 0: φ = 0:     10 + 0                                   = 10
//   row 1: φ = 2π/3:  10 + 4·sin(2π/3) + 2·sin(4π/3) = 10 + 4·√3/2 − 2·√3/2 = 10 + √3
//   row 2: φ = 4π/3:  10 + 4·sin(4π/3) + 2·sin(8π/3) = 10 − 4·√3/2 + 2·√3/2 = 10 − √3
TEST(PeriodicLoadTest, OneBodyPerRowEachBodyGetsItsOwnRow) {
    const double sqrt3 = 1.7320508075688772;
    LoadOnShafts m(loadParams(3, 10.0, {4.0, 2.0}, 5.0, true), {0.1, 0.2, 0.4});
    m.set(0.0, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -10.0, kRoundingRelTolerance * 16);
    EXPECT_NEAR(m.torqueOn(1), -(10.0 + sqrt3), kRoundingRelTolerance * 16);
    EXPECT_NEAR(m.torqueOn(2), -(10.0 - sqrt3), kRoundingRelTolerance * 16);
    for (int r = 0; r < 3; ++r) EXPECT_EQ(m.load->bodyOfRow(r), r);
    // Later, against the law written out again.
    const PeriodicLoadParams p = m.load->params();
    for (double t : {0.11, 0.9, 3.3}) {
        m.set(t, kRunningSpeed);
        for (int r = 0; r < 3; ++r)
            EXPECT_NEAR(m.torqueOn(r), -rowLoad(p, r, t, kRunningSpeed), kRoundingRelTolerance * 16)
                << "row " << r << ", t = " << t;
    }
}

TEST(PeriodicLoadTest, OneBodyCarriesEveryRow) {
    LoadOnShafts m(loadParams(5, 1.0, {1.0}, 1.0, true), {kShaftInertia});
    for (int r = 0; r < 5; ++r) EXPECT_EQ(m.load->bodyOfRow(r), 0);
}

TEST(PeriodicLoadTest, EachRowUsesItsOwnBodySpeedForTheMean) {
    // Excitation off, so only M̄·tanh(ω_r/ωs): body 0 at ωs (tanh 1), body 1
    // at rest (0), body 2 backwards at 1000·ωs (−1).
    LoadOnShafts m(loadParams(3, 2.0, {5.0}, 1.0, true), {0.1, 0.2, 0.4});
    m.load->setExcitationOn(m.state, false);
    m.state.setTime(0.7);
    test::setShaft(m.state, m.shafts[0], 0.0, kSmoothingSpeed);
    test::setShaft(m.state, m.shafts[1], 0.0, 0.0);
    test::setShaft(m.state, m.shafts[2], 0.0, -kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -1.5231883119115297, kRoundingRelTolerance * 2);
    EXPECT_EQ(m.torqueOn(1), 0.0);
    EXPECT_NEAR(m.torqueOn(2), 2.0, kRoundingRelTolerance * 2);
}

// ---- 4. excitation off ---------------------------------------------------------

TEST(PeriodicLoadTest, ExcitationOffLeavesOnlyTheSmoothedMean) {
    const std::vector<double> J = {0.1, 0.2, 0.4};
    LoadOnShafts m(loadParams(3, 4.0, {3.0, 2.0, 1.0}, 2.0, true), J);
    EXPECT_TRUE(m.load->isExcitationOn(m.state));
    m.set(0.25, kRunningSpeed);
    // On: row 1 at t = 0.25 (against the law written out again). Realize the
    // accelerations before switching, so a stale Dynamics cache would show.
    const PeriodicLoadParams p = m.load->params();
    const double on = rowLoad(p, 1, 0.25, kRunningSpeed);
    EXPECT_GT(std::abs(on - 4.0), 0.1) << "the test needs a periodic part to switch off";
    EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shafts[1]), -on / J[1],
                kSolverRelTolerance * 100);
    m.load->setExcitationOn(m.state, false);
    EXPECT_FALSE(m.load->isExcitationOn(m.state));
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shafts[i]), -4.0 / J[i],
                    kSolverRelTolerance * 100)
            << "shaft " << i;
    for (double t : {0.0, 0.25, 1.9}) {
        m.set(t, kRunningSpeed);
        for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(m.torqueOn(i), -4.0, kRoundingRelTolerance * 4);
        EXPECT_NEAR(m.load->getTotalTorque(m.state), 12.0, kRoundingRelTolerance * 12);
    }
    // Near standstill the mean is still smoothed: 4·tanh(1).
    m.set(0.25, kSmoothingSpeed);
    EXPECT_NEAR(m.torqueOn(0), -4 * 0.7615941559557649, kRoundingRelTolerance * 4);
    m.load->setExcitationOn(m.state, true);
    m.set(0.25, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(1), -on, kRoundingRelTolerance * 10);
}

// ---- 5. action on every body ---------------------------------------------------

// Each shaft obeys J_i·u̇_i = −M_i (the fixture's thin discs on pins), so
// Simbody's solve must give u̇_i = −M_i/J_i for every body at once, a
// shaft not in the list must feel nothing, and the reactions go to ground.
TEST(PeriodicLoadTest, EveryListedBodyIsAcceleratedByItsRowAndNoOtherBody) {
    ShaftSystem rig;
    const std::vector<double> J = {0.1, 0.2, 0.4};
    std::vector<SimTK::MobilizedBody> bodies;
    std::vector<SimTK::MobilizedBody::Pin> pins;
    for (double j : J) {
        pins.push_back(rig.addShaft(j));
        bodies.push_back(pins.back());
    }
    const SimTK::MobilizedBody::Pin bystander = rig.addShaft(0.3);
    const PeriodicLoadParams p = loadParams(3, 1.5, {0.7, 0.4, 0.2}, 4.0, true);
    auto* load = new PeriodicLoad(rig.forces(), bodies, p);
    const SimTK::Force::Custom force(rig.forces(), load);
    SimTK::State state = rig.defaultState();
    const double t = 0.63;
    state.setTime(t);
    for (const auto& s : pins) test::setShaft(state, s, 0.1, kRunningSpeed);
    test::setShaft(state, bystander, 0.0, kRunningSpeed);
    double total = 0;
    for (int r = 0; r < 3; ++r) {
        const double M = rowLoad(p, r, t, kRunningSpeed);
        total += M;
        EXPECT_NEAR(test::shaftAcceleration(rig.system(), state, pins[r]), -M / J[r],
                    kSolverRelTolerance * 100)
            << "row " << r;
    }
    EXPECT_EQ(test::shaftAcceleration(rig.system(), state, bystander), 0.0);
    EXPECT_EQ(test::torqueOn(rig.system(), force, state, bystander), 0.0);
    EXPECT_NEAR(load->getTotalTorque(state), total, kRoundingRelTolerance * 10);
    // The reaction −(−M_r) acts on ground through each pin.
    rig.system().realize(state, SimTK::Stage::Acceleration);
    SimTK::Vector_<SimTK::SpatialVec> reactions;
    rig.matter().calcMobilizerReactionForces(state, reactions);
    for (int r = 0; r < 3; ++r)
        EXPECT_NEAR(reactions[pins[r].getMobilizedBodyIndex()][0][2], -rowLoad(p, r, t, kRunningSpeed),
                    kSolverRelTolerance * 100)
            << "row " << r;
}

// ---- 6. energy and momentum along a trajectory -----------------------------------

// Three shafts, one staggered row each, spinning down for 1 s under the
// load: ΔKE = ∫ Σ_r −M_r·ω_r dt and ΔH = ∫ Σ_r −M_r dt, with M_r the law
// written out again. Speeds fall by at most (1.5 + 0.7 + 0.4 + 0.2)/0.1 =
// 28 rad/s per second from 60, 40, 30 rad/s: far from standstill, so the
// mean is M̄ = 1.5 N*m throughout. P1 = 4π rad/s: 1 s is two whole periods,
// over which every sine integrates to 0, so each shaft ends at
// ω0 − M̄·1 s/J = 45, 32.5, 26.25 rad/s, and
//   ΔKE = ½·0.1·(45² − 60²) + ½·0.2·(32.5² − 40²) + ½·0.4·(26.25² − 30²)
//       = −78.75 − 54.375 − 42.1875 = −175.3125 J,
//   ΔH  = −3·1.5·1 s = −4.5 N*m*s.
// Harmonic 3 is at 37.7 rad/s: 2000 Simpson intervals of 0.5 ms err by
// (37.7·5e-4)^4/180 ~ 7e-10 of a power amplitude per period, and the
// periodic power is a small share of the work; seen 7e-13 of ΔKE. 1e-10
// leaves margin yet fails a torque or power wrong by 1 part in 1e10.
constexpr double kTrajectoryRelTolerance = 1e-10;
// End speeds against the hand values: the integrator holds its local error
// near 1e-9 relative (seen 5e-15 on this smooth run).
constexpr double kEndSpeedRelTolerance = 1e-8;
// Σ J·u is a linear invariant, which every Runge-Kutta method conserves up
// to rounding (seen 1e-15 of ΔH).
constexpr double kMomentumRelTolerance = 1e-12;

TEST(PeriodicLoadTest, KineticEnergyChangeEqualsIntegralOfAppliedPower) {
    const std::vector<double> J = {0.1, 0.2, 0.4};
    const PeriodicLoadParams p = loadParams(3, 1.5, {0.7, 0.4, 0.2}, 4 * SimTK::Pi, true);
    LoadOnShafts m(p, J);
    const std::vector<double> w0 = {60.0, 40.0, 30.0};
    for (std::size_t i = 0; i < 3; ++i) test::setShaft(m.state, m.shafts[i], 0.0, w0[i]);
    const std::vector<SimTK::MobilizedBody::Pin> shafts = m.shafts;
    auto power = [=](const SimTK::State& s) {
        double P = 0;
        for (int r = 0; r < 3; ++r) {
            const double w = test::shaftSpeed(s, shafts[r]);
            P -= rowLoad(p, r, s.getTime(), w) * w;
        }
        return P;
    };
    auto torque = [=](const SimTK::State& s) {
        double T = 0;
        for (int r = 0; r < 3; ++r) T -= rowLoad(p, r, s.getTime(), test::shaftSpeed(s, shafts[r]));
        return T;
    };
    m.rig.system().realize(m.state, SimTK::Stage::Velocity);
    const double KE0 = m.rig.matter().calcKineticEnergy(m.state);
    const double H0 = test::angularMomentumZ(m.rig.system(), m.state);
    std::vector<double> work;
    const SimTK::State end =
        test::integrateWithQuadrature(m.rig.system(), m.state, 1.0, 2000, {power, torque}, work);
    const std::vector<double> w1 = {45.0, 32.5, 26.25};
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(test::shaftSpeed(end, m.shafts[i]), w1[i], kEndSpeedRelTolerance * w1[i]) << "shaft " << i;
    m.rig.system().realize(end, SimTK::Stage::Velocity);
    const double dKE = m.rig.matter().calcKineticEnergy(end) - KE0;
    EXPECT_NEAR(dKE, -175.3125, kEndSpeedRelTolerance * 2 * 175.3125);
    EXPECT_NEAR(dKE, work[0], kTrajectoryRelTolerance * std::abs(dKE));
    const double dH = test::angularMomentumZ(m.rig.system(), end) - H0;
    EXPECT_NEAR(dH, -4.5, kEndSpeedRelTolerance * 4.5);
    EXPECT_NEAR(dH, work[1], kMomentumRelTolerance * std::abs(dH));
}

// ---- 7. bad parameters ---------------------------------------------------------

PeriodicLoadParams goodParams() { return loadParams(3, 10.0, {4.0, 2.0}, 5.0, true); }

void expectRejected(const PeriodicLoadParams& p, const std::string& parameter, int bodyCount = 1) {
    ShaftSystem rig;
    std::vector<SimTK::MobilizedBody> bodies;
    for (int i = 0; i < bodyCount; ++i) bodies.push_back(rig.addShaft(kShaftInertia));
    test::expectInvalidArgumentNaming(
        parameter, [&] { (void)std::make_unique<PeriodicLoad>(rig.forces(), bodies, p); });
}

TEST(PeriodicLoadTest, GoodParametersAreAcceptedWithOneBodyOrOnePerRow) {
    for (int n : {1, 3}) {
        ShaftSystem rig;
        std::vector<SimTK::MobilizedBody> bodies;
        for (int i = 0; i < n; ++i) bodies.push_back(rig.addShaft(kShaftInertia));
        EXPECT_NO_THROW((void)std::make_unique<PeriodicLoad>(rig.forces(), bodies, goodParams()))
            << n << " bodies";
    }
}

TEST(PeriodicLoadTest, NonPositiveRowsThrowNamingRows) {
    for (int bad : {0, -2}) {
        PeriodicLoadParams p = goodParams();
        p.rows = bad;
        expectRejected(p, "rows");
    }
}

TEST(PeriodicLoadTest, WrongNumberOfBodiesThrowsNamingBodies) {
    expectRejected(goodParams(), "bodies", 0);  // none
    expectRejected(goodParams(), "bodies", 2);  // neither 1 nor rows = 3
    expectRejected(goodParams(), "bodies", 4);
}

TEST(PeriodicLoadTest, NegativeMeanTorqueThrowsNamingMeanTorque) {
    PeriodicLoadParams p = goodParams();
    p.meanTorque = -1.0;
    expectRejected(p, "mean_torque");
}

TEST(PeriodicLoadTest, NegativeAmplitudeThrowsNamingAmplitudes) {
    PeriodicLoadParams p = goodParams();
    p.amplitudes = {4.0, -2.0};
    expectRejected(p, "amplitudes");
}

TEST(PeriodicLoadTest, NonPositiveFundamentalFrequencyThrowsNamingIt) {
    for (double bad : {0.0, -5.0}) {
        PeriodicLoadParams p = goodParams();
        p.fundamentalFrequency = bad;
        expectRejected(p, "fundamental_frequency");
    }
}

TEST(PeriodicLoadTest, NonPositiveSmoothingSpeedThrowsNamingSmoothingSpeed) {
    for (double bad : {0.0, -0.01}) {
        PeriodicLoadParams p = goodParams();
        p.smoothingSpeed = bad;
        expectRejected(p, "smoothing_speed");
    }
}

TEST(PeriodicLoadTest, NonFiniteParametersThrowNamingTheParameter) {
    struct Field { double PeriodicLoadParams::*member; const char* name; };
    const Field fields[] = {
        {&PeriodicLoadParams::meanTorque, "mean_torque"},
        {&PeriodicLoadParams::fundamentalFrequency, "fundamental_frequency"},
        {&PeriodicLoadParams::smoothingSpeed, "smoothing_speed"},
    };
    for (double bad : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::quiet_NaN()}) {
        for (const Field& f : fields) {
            PeriodicLoadParams p = goodParams();
            p.*f.member = bad;
            expectRejected(p, f.name);
        }
        PeriodicLoadParams p = goodParams();
        p.amplitudes = {4.0, bad};
        expectRejected(p, "amplitudes");
    }
}

TEST(PeriodicLoadTest, MessageGivesTheOffendingValue) {
    PeriodicLoadParams p = goodParams();
    p.smoothingSpeed = -0.25;
    expectRejected(p, "-0.25");
}

// ---- 8. registry ---------------------------------------------------------------





// Three rows of M̄ = 10 N*m, b = (4, 2), P1 = 5 rad/s, as the model-file
// reader would hand them over (every key present).
ElementSpec loadSpec(const std::vector<std::string>& bodies, double rows = 3,
                     const std::string& arrangement = "staggered") {
    ElementSpec e;
    e.type = "PeriodicLoad";
    e.name = "crushing";
    e.params["bodies"] = names(bodies);
    e.params["rows"] = number(rows);
    e.params["mean_torque"] = number(10.0);
    e.params["amplitudes"] = numbers({4.0, 2.0});
    e.params["fundamental_frequency"] = number(5.0);
    e.params["arrangement"] = word(arrangement);
    e.params["smoothing_speed"] = number(kSmoothingSpeed);
    return e;
}

const ElementType& loadType() { return test::registeredType("PeriodicLoad"); }

TEST(PeriodicLoadRegistryTest, SchemaListsTheDocumentedKeys) {
    ASSERT_NE(ElementRegistry::instance().find("PeriodicLoad"), nullptr);
    const ElementSchema& schema = loadType().schema;
    std::set<std::string> keys;
    for (const auto& p : schema.params) keys.insert(p.key);
    EXPECT_EQ(keys, (std::set<std::string>{"bodies", "rows", "mean_torque", "amplitudes",
                                           "fundamental_frequency", "arrangement", "phases", "smoothing_speed", "schedule"}));
    EXPECT_EQ(schema.find("bodies")->kind, ParamKind::BodyList);
    EXPECT_EQ(schema.find("amplitudes")->kind, ParamKind::QuantityList);
    EXPECT_EQ(schema.find("amplitudes")->unit, "N*m");
    EXPECT_EQ(schema.find("mean_torque")->unit, "N*m");
    EXPECT_EQ(schema.find("fundamental_frequency")->unit, "rad/s");
    EXPECT_TRUE(schema.find("fundamental_frequency")->required);
    EXPECT_TRUE(schema.find("fundamental_frequency")->minExclusive);
    EXPECT_EQ(schema.find("rows")->unit, "1");
    EXPECT_EQ(schema.find("arrangement")->choices, (std::vector<std::string>{"in_phase", "staggered"}));
    EXPECT_EQ(schema.find("arrangement")->defaultText, "staggered");
    EXPECT_EQ(schema.find("mean_torque")->defaultValue, 0.0);
    EXPECT_EQ(schema.find("smoothing_speed")->defaultValue, kSmoothingSpeed);
    EXPECT_TRUE(schema.find("smoothing_speed")->minExclusive);
}

TEST(PeriodicLoadRegistryTest, CrossCheckAcceptsOneBodyOrOnePerRow) {
    ASSERT_TRUE(loadType().schema.crossCheck);
    EXPECT_NO_THROW(loadType().schema.crossCheck(loadSpec({"rotor"})));
    EXPECT_NO_THROW(loadType().schema.crossCheck(loadSpec({"row1", "row2", "row3"})));
}

TEST(PeriodicLoadRegistryTest, CrossCheckRejectsRowsNotWholeNamingRows) {
    try {
        loadType().schema.crossCheck(loadSpec({"rotor"}, 2.5));
        ADD_FAILURE() << "no SpecError for rows = 2.5";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "crushing.rows");
    }
}

TEST(PeriodicLoadRegistryTest, CrossCheckRejectsWrongNumberOfBodiesNamingBodies) {
    for (const auto& bodies : {std::vector<std::string>{"row1", "row2"},
                               std::vector<std::string>{"row1", "row2", "row3", "row4"}}) {
        try {
            loadType().schema.crossCheck(loadSpec(bodies));
            ADD_FAILURE() << "no SpecError for " << bodies.size() << " bodies and 3 rows";
        } catch (const SpecError& e) {
            EXPECT_EQ(e.key(), "crushing.bodies");
        }
    }
}

// Builds through the registry into a Scene of three shafts and checks the
// torques, the probe and the excitation switch the analyses use.
struct BuiltLoad {
    explicit BuiltLoad(const std::string& arrangement) {
        const SimTK::Body::Rigid body(SimTK::MassProperties(
            1, SimTK::Vec3(0), SimTK::Inertia(kShaftInertia / 2, kShaftInertia / 2, kShaftInertia)));
        for (const char* name : {"row1", "row2", "row3"}) {
            SimTK::MobilizedBody::Pin pin(scene.matter().updGround(), SimTK::Transform(), body,
                                          SimTK::Transform());
            scene.addBody(name, pin);
            pins.push_back(pin);
        }
        loadType().build(loadSpec({"row1", "row2", "row3"}, 3, arrangement), scene);
        scene.system().realizeTopology();
        state = scene.system().getDefaultState();
        for (const auto& pin : pins) test::setShaft(state, pin, 0.0, kRunningSpeed);
    }
    double torqueOn(std::size_t i) {
        const SimTK::Force& force = scene.forces().getForce(scene.findForce("crushing"));
        return test::torqueOn(scene.system(), force, state, pins[i]);
    }
    const Probe* probe(const std::string& name) const {
        for (const auto& p : scene.probes())
            if (p.name == name) return &p;
        return nullptr;
    }

    Scene scene;
    std::vector<SimTK::MobilizedBody::Pin> pins;
    SimTK::State state;
};

TEST(PeriodicLoadRegistryTest, BuiltStaggeredLoadAppliesItsRowsAndSwitchesItsExcitation) {
    BuiltLoad b("staggered");
    // t = 0: 10, 10 + √3, 10 − √3 N*m (worked out for OneBodyPerRow...).
    const double sqrt3 = 1.7320508075688772;
    EXPECT_NEAR(b.torqueOn(0), -10.0, kRoundingRelTolerance * 16);
    EXPECT_NEAR(b.torqueOn(1), -(10.0 + sqrt3), kRoundingRelTolerance * 16);
    EXPECT_NEAR(b.torqueOn(2), -(10.0 - sqrt3), kRoundingRelTolerance * 16);
    const Probe* torque = b.probe("crushing.torque");
    ASSERT_NE(torque, nullptr);
    EXPECT_EQ(torque->role, ProbeRole::ResistanceTorque);
    EXPECT_EQ(torque->unit, "N*m");
    b.scene.system().realize(b.state, torque->stage);
    EXPECT_NEAR(torque->value(b.state), 30.0, kRoundingRelTolerance * 30);  // √3 cancels
    // The steady-state solver's switch: every row falls back to the mean.
    // t = π/10 s: row 0 at θ = π/2 gets 10 + 4·1 + 2·sin(π) = 14 N*m.
    b.state.setTime(SimTK::Pi / 10);
    EXPECT_NEAR(b.torqueOn(0), -14.0, kRoundingRelTolerance * 16);
    b.scene.setExcitationsOn(b.state, false);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(b.torqueOn(i), -10.0, kRoundingRelTolerance * 10);
    b.scene.setExcitationsOn(b.state, true);
    EXPECT_NEAR(b.torqueOn(0), -14.0, kRoundingRelTolerance * 16);
}

TEST(PeriodicLoadRegistryTest, BuiltInPhaseLoadGivesEveryRowTheSameTorque) {
    BuiltLoad b("in_phase");
    // t = π/10 s: θ = P1·t = π/2, sin θ = 1, sin 2θ = 0: 10 + 4 = 14 N*m on each row.
    b.state.setTime(SimTK::Pi / 10);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(b.torqueOn(i), -14.0, kRoundingRelTolerance * 16);
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

// ---- issue 20 item 5: a phase per row (any stagger) ---------------------------

// Two rows on one body with φ = 0 and φ = 40°, b = (5, 3), M̄ = 2:
//   Σ = 2·2 + 5·(sin θ + sin(θ + φ)) + 3·(sin 2θ + sin(2θ + 2φ)),  θ = P1·t,
// neither the in-phase nor the 360°/n stagger.
TEST(PeriodicLoadPhases, ListedPhasesReplaceTheArrangement) {
    const double phi = 40 * SimTK::Pi / 180;
    PeriodicLoadParams p = loadParams(2, 2.0, {5, 3}, 3.0, true);
    p.phases = {0.0, phi};
    LoadOnShafts m(p, {kShaftInertia});
    EXPECT_EQ(m.load->rowPhase(0), 0.0);
    EXPECT_EQ(m.load->rowPhase(1), phi);
    for (double t : {0.0, 0.1, 0.37, 2.9}) {
        m.set(t, kRunningSpeed);
        const double th = 3.0 * t;
        const double expected = 4 + 5 * (std::sin(th) + std::sin(th + phi)) +
                                3 * (std::sin(2 * th) + std::sin(2 * th + 2 * phi));
        EXPECT_NEAR(m.torqueOn(0), -expected, kRoundingRelTolerance * 20) << "t = " << t;
    }
    // t = 0: 5·sin 40° + 3·sin 80° = 3.2139380484326967 + 2.954423259036624
    //        = 6.16836130746932, plus 4: 10.16836130746932 N*m.
    m.set(0.0, kRunningSpeed);
    EXPECT_NEAR(m.torqueOn(0), -10.16836130746932, kRoundingRelTolerance * 20);
}

TEST(PeriodicLoadPhases, WrongNumberOfPhasesThrowsNamingPhases) {
    ShaftSystem rig;
    std::vector<SimTK::MobilizedBody> bodies{rig.addShaft(kShaftInertia)};
    PeriodicLoadParams p = loadParams(3, 1.0, {1.0}, 1.0, true);
    p.phases = {0.0, 1.0};
    test::expectInvalidArgumentNaming("phases", [&] { (void)std::make_unique<PeriodicLoad>(rig.forces(), bodies, p); });
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

TEST(PeriodicLoadPhases, ModelFileChecksThePhaseCountAndRefusesPhasesWithArrangement) {
    const std::string text = R"(format_version: 1
name: rows
bodies:
  - {name: rotor, inertia: 1 kg*m^2, joint: {type: pin}}
elements:
  - type: PeriodicLoad
    name: crushing
    bodies: [rotor]
    rows: 3
    amplitudes: [1 N*m]
    fundamental_frequency: 2 rad/s
    phases: [0 deg, 40 deg, 80 deg]
scenario: {analysis: transient, end_time: 1 s}
)";
    const ModelSpec ok = readModelText(text, "m.yaml", defaultModelReader(), {});
    EXPECT_NEAR(ok.findElement("crushing")->numbers("phases")[2], 80 * SimTK::Pi / 180, 1e-15);
    try {
        readModelText(text, "m.yaml", defaultModelReader(), {{"elements.crushing.rows", "4"}});
        ADD_FAILURE() << "3 phases for 4 rows accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "crushing.phases");
        EXPECT_NE(std::string(e.what()).find("one phase per row (4), got 3"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readModelText(text, "m.yaml", defaultModelReader(), {{"elements.crushing.arrangement", "in_phase"}}),
                 SpecError);
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

// ---- issue 18 follow-up: the harmonics by recurrence, the load cached -----------

// The direct sum Σ_k b_k·sin(k·θ) in long double: k·θ is exact there (θ has
// 53 bits, k ≤ 64 six more, the x87 mantissa 64), so this is the series at
// the element's own θ to ~1e-19, free of the argument rounding of k·θ in
// double (kθ·ε/2: 2e-13 at k = 50, θ = 40).
long double directSeriesLong(const std::vector<double>& b, double theta) {
    long double sum = 0;
    for (std::size_t i = 0; i < b.size(); ++i)
        sum += static_cast<long double>(b[i]) * std::sin(static_cast<long double>(i + 1) * theta);
    return sum;
}

// The element's θ for row r at time t, as the class comment writes it.
double rowAngle(const PeriodicLoad& load, int row, double t) {
    return load.params().fundamentalFrequency * t + load.rowPhase(row);
}

// The recurrence's rounding grows like k·ε; 1e-13 of Σ|b_k| leaves room for
// ~50·(a few ε) at 50 harmonics (seen: 1.5e-16 for the crusher's 4, 9.1e-16
// for 50 flat, 3.2e-15 for the 50th harmonic alone; docs/benchmarks.md).
constexpr double kRecurrenceRelTolerance = 1e-13;

TEST(PeriodicLoadRecurrence, MatchesTheDirectSumForTheModelsHarmonicsAndForFifty) {
    // The crusher's spectrum (4 harmonics, roll_crusher.yaml), a flat one of
    // 50 (the worst case for a k·ε growth: the top harmonics weigh as much
    // as the first) and a 1/k one of 50; 1, 2 and 3 harmonics for the
    // recurrence's start.
    // Last, the 50th harmonic alone (b_50 = 1, the rest 0): its error
    // relative to its own amplitude, the recurrence's worst term.
    std::vector<double> flat50(50, 100.0), inverse50, top50(50, 0.0);
    for (int k = 1; k <= 50; ++k) inverse50.push_back(7440.0 * 0.6 / k);
    top50.back() = 1.0;
    const std::vector<std::vector<double>> spectra = {
        {4464, 2232, 1488, 1116}, {5.0}, {5.0, 3.0}, {5.0, 3.0, 1.0}, flat50, inverse50, top50};
    for (const auto& b : spectra) {
        double worst = 0;
        double scale = 0;
        for (double bk : b) scale += bk;
        // Nine staggered rows at the crusher's P_1, times up to 1000 s
        // (θ up to ~4000 rad: the long runs of a sweep).
        LoadOnShafts m(loadParams(9, 7440.0, b, 3.973, true), {639.0});
        for (double t : {0.0, 1e-3, 0.37, 1.58, 2.5, 5.0, 9.999, 10.0, 47.3, 100.0, 333.3, 1000.0})
            for (int r = 0; r < 9; ++r) {
                const double theta = rowAngle(*m.load, r, t);
                const double err = std::abs(m.load->periodicPart(r, t) -
                                            static_cast<double>(directSeriesLong(b, theta))) / scale;
                worst = std::max(worst, err);
                EXPECT_LE(err, kRecurrenceRelTolerance) << b.size() << " harmonics, t = " << t << ", row " << r;
            }
        std::cout << "[          ] " << b.size() << " harmonics (b_1 = " << b[0]
                  << "): largest |recurrence - direct| / sum |b_k| = " << worst << "\n";
    }
}

// At the crusher's 4 harmonics and times of its runs (θ ≤ 40 rad) the
// direct sum in double, sin(k·θ) per harmonic as the element had it before,
// agrees as closely: the argument rounding kθ·ε/2 ≤ 9e-15 there.
TEST(PeriodicLoadRecurrence, MatchesTheDoubleDirectSumOverTheCrushersRun) {
    const std::vector<double> b = {4464, 2232, 1488, 1116};
    const double scale = 4464 + 2232 + 1488 + 1116;
    LoadOnShafts m(loadParams(9, 7440.0, b, 3.973, true), {639.0});
    for (int i = 0; i <= 1000; ++i) {
        const double t = 0.01 * i;
        for (int r = 0; r < 9; ++r) {
            const double theta = rowAngle(*m.load, r, t);
            double direct = 0;
            for (std::size_t k = 0; k < b.size(); ++k) direct += b[k] * std::sin((k + 1) * theta);
            EXPECT_LE(std::abs(m.load->periodicPart(r, t) - direct) / scale, kRecurrenceRelTolerance)
                << "t = " << t << ", row " << r;
        }
    }
}

// The cache entry follows every input: time, each speed, and the excitation
// switch, which invalidates Dynamics only (so the entry names it as a
// prerequisite). Each value is checked against the law written out again,
// after the entry was filled for the previous input.
TEST(PeriodicLoadCache, ValuesFollowTimeSpeedAndTheExcitationSwitch) {
    const std::vector<double> J = {0.1, 0.2, 0.4};
    const PeriodicLoadParams p = loadParams(3, 4.0, {3.0, 2.0, 1.0}, 2.0, true);
    LoadOnShafts m(p, J);
    const SimTK::MultibodySystem& system = m.rig.system();
    auto expectRows = [&](double t, const std::vector<double>& w, bool excited, const char* what) {
        const PeriodicLoad::Values& v = m.load->getValues(m.state);
        double total = 0, power = 0;
        for (int r = 0; r < 3; ++r) {
            const double M = excited ? rowLoad(p, r, t, w[r]) : p.meanTorque * std::tanh(w[r] / p.smoothingSpeed);
            EXPECT_NEAR(v.rowTorques[r], M, kRoundingRelTolerance * 10) << what << ", row " << r;
            EXPECT_NEAR(v.bodyTorques[r], M, kRoundingRelTolerance * 10) << what << ", row " << r;
            total += M;
            power += M * w[r];
        }
        EXPECT_NEAR(m.load->getTotalTorque(m.state), total, kRoundingRelTolerance * 30) << what;
        EXPECT_NEAR(m.load->getAbsorbedPower(m.state), power, kRoundingRelTolerance * 30 * 10) << what;
    };
    m.set(0.25, kRunningSpeed);
    system.realize(m.state, SimTK::Stage::Acceleration);
    expectRows(0.25, {10, 10, 10}, true, "start");
    m.state.setTime(0.8);
    system.realize(m.state, SimTK::Stage::Acceleration);
    expectRows(0.8, {10, 10, 10}, true, "time changed");
    test::setShaft(m.state, m.shafts[1], 0.0, -3.0);
    system.realize(m.state, SimTK::Stage::Acceleration);
    expectRows(0.8, {10, -3, 10}, true, "speed changed");
    // The switch alone: the State stays realized through Velocity.
    m.load->setExcitationOn(m.state, false);
    EXPECT_GE(m.state.getSystemStage(), SimTK::Stage::Velocity);
    expectRows(0.8, {10, -3, 10}, false, "excitation off");
    m.load->setExcitationOn(m.state, true);
    expectRows(0.8, {10, -3, 10}, true, "excitation on again");
    // A copy of the State carries a valid entry; changing the copy leaves
    // the original's.
    SimTK::State copy = m.state;
    copy.setTime(1.1);
    system.realize(copy, SimTK::Stage::Velocity);
    EXPECT_NEAR(m.load->getTotalTorque(copy), rowLoad(p, 0, 1.1, 10) + rowLoad(p, 1, 1.1, -3) + rowLoad(p, 2, 1.1, 10),
                kRoundingRelTolerance * 30);
    expectRows(0.8, {10, -3, 10}, true, "original after the copy changed");
}

// Nine rows on one body in phase, and nine staggered: the body gets the sum
// of its rows, rows of equal phase the same torque.
TEST(PeriodicLoadCache, RowsOnOneBodySumIntoItsTorque) {
    for (bool staggered : {false, true}) {
        const PeriodicLoadParams p = loadParams(9, 7440.0, {4464, 2232, 1488, 1116}, 3.973, staggered);
        LoadOnShafts m(p, {639.0});
        m.set(2.3, 0.4966);
        m.rig.system().realize(m.state, SimTK::Stage::Velocity);
        const PeriodicLoad::Values& v = m.load->getValues(m.state);
        double sum = 0;
        for (int r = 0; r < 9; ++r) {
            EXPECT_NEAR(v.rowTorques[r], rowLoad(p, r, 2.3, 0.4966), kRoundingRelTolerance * 17000) << "row " << r;
            sum += rowLoad(p, r, 2.3, 0.4966);
        }
        ASSERT_EQ(v.bodyTorques.size(), 1u);
        EXPECT_NEAR(v.bodyTorques[0], sum, kRoundingRelTolerance * 9 * 17000);
        EXPECT_NEAR(m.torqueOn(0), -sum, kRoundingRelTolerance * 9 * 17000);
    }
}

TEST(PeriodicLoadCache, ValuesBelowVelocityStageAreRefused) {
    LoadOnShafts m(loadParams(1, 1.0, {1.0}, 1.0, true), {kShaftInertia});
    m.set(0.1, 1.0);  // invalidates Velocity
    EXPECT_THROW((void)m.load->getValues(m.state), std::exception);
}

}  // namespace
}  // namespace milldyn
