// Tests of the motor laws and starters (plugins/motors/TorqueSpeedCurve.h,
// Starter.h, InductionMotor.h). Expected values are worked out by hand in
// the comments or from the closed forms written out afresh here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "driver/analyses/Analysis.h"
#include "driver/ModelFile.h"
#include "plugins/motors/CurrentCircle.h"
#include "plugins/motors/DqInductionMotor.h"
#include "plugins/motors/InductionMotor.h"
#include "plugins/motors/Starter.h"
#include "plugins/motors/TorqueSpeedCurve.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRpm = 2 * kPi / 60;
constexpr double kRounding = 1e-12;

TorqueSpeedCurveParams catalogue() {
    TorqueSpeedCurveParams p;
    p.law = TorqueSpeedCurveParams::Law::Catalogue;
    p.ratedTorque = 100;
    p.ratedSpeed = 1470 * kRpm;
    p.synchronousSpeed = 1500 * kRpm;
    p.breakdownRatio = 2.8;
    p.breakdownSpeed = 1320 * kRpm;
    p.lockedRotorRatio = 2.2;
    p.pullUpRatio = 1.9;
    p.pullUpSpeed = 450 * kRpm;
    return p;
}

TEST(MonotoneCubic, PassesThroughItsPointsAndNeverOvershoots) {
    // A torque-speed shape: rises to a peak at x = 3, falls to 0 at x = 4.
    const std::vector<double> x = {0, 1, 2, 3, 4}, y = {2.2, 1.9, 2.3, 2.8, 0};
    const MonotoneCubic f(x, y);
    for (std::size_t k = 0; k < x.size(); ++k) EXPECT_EQ(f(x[k]), y[k]);
    for (int i = 0; i <= 4000; ++i) {
        const double xi = 4.0 * i / 4000;
        EXPECT_LE(f(xi), 2.8) << xi;  // the peak is the data's
        EXPECT_GE(f(xi), 0.0) << xi;
        // monotone where the data are: between 1 and 3 rising, 3 to 4 falling
        if (xi > 1 && xi < 3) {
            EXPECT_GE(f(xi + 1e-6), f(xi)) << xi;
        }
        if (xi > 3 && xi < 4 - 1e-6) {
            EXPECT_LE(f(xi + 1e-6), f(xi)) << xi;
        }
        // between 0 and 1 falling, never below the pull-up point 1.9
        if (xi < 1) {
            EXPECT_GE(f(xi), 1.9) << xi;
        }
    }
    EXPECT_EQ(f(-1), 2.2);  // holds below the first point
}

TEST(MonotoneCubic, RejectsSpeedsThatDoNotIncrease) {
    EXPECT_THROW(MonotoneCubic({0, 2, 1}, {1, 2, 3}), std::invalid_argument);
    EXPECT_THROW(MonotoneCubic({0}, {1}), std::invalid_argument);
}

TEST(TorqueSpeedCurve, CatalogueReproducesItsPoints) {
    const TorqueSpeedCurve c(catalogue());
    EXPECT_NEAR(c.torque(0), 220, kRounding * 220);
    EXPECT_NEAR(c.torque(450 * kRpm), 190, kRounding * 190);
    EXPECT_NEAR(c.torque(1320 * kRpm), 280, kRounding * 280);
    EXPECT_NEAR(c.torque(1470 * kRpm), 100, kRounding * 100);
    EXPECT_NEAR(c.torque(1500 * kRpm), 0, kRounding * 100);
    EXPECT_LT(c.torque(1510 * kRpm), 0);  // generating above synchronous
}

TEST(TorqueSpeedCurve, CatalogueRejectsABreakdownAboveRatedSpeed) {
    TorqueSpeedCurveParams p = catalogue();
    p.breakdownSpeed = 1480 * kRpm;
    EXPECT_THROW(TorqueSpeedCurve{p}, std::invalid_argument);
    p = catalogue();
    p.breakdownRatio = 0.9;  // breakdown below rated
    EXPECT_THROW(TorqueSpeedCurve{p}, std::invalid_argument);
}

TEST(TorqueSpeedCurve, TableInterpolatesTorqueAndCurrent) {
    TorqueSpeedCurveParams p;
    p.law = TorqueSpeedCurveParams::Law::Table;
    p.ratedTorque = 100;
    p.ratedSpeed = 1470 * kRpm;
    p.synchronousSpeed = 1500 * kRpm;
    p.tableSpeeds = {0, 100, 150};
    p.tableTorques = {200, 250, 100};
    p.tableCurrents = {600, 500, 120};
    const TorqueSpeedCurve c(p);
    EXPECT_EQ(c.torque(100), 250);
    EXPECT_EQ(c.current(150), 120);
    EXPECT_NEAR(c.torque(1500 * kRpm), 0, 1e-12);  // (ωc, 0) appended
    p.tableSpeeds = {0, 150, 100};
    EXPECT_THROW(TorqueSpeedCurve{p}, std::invalid_argument);
}

TEST(Starter, SupplyStatesByHand) {
    StarterParams p;
    p.kind = StarterParams::Kind::SoftStart;
    p.initialVoltage = 0.4;
    p.rampTime = 2;
    // V(1 s) = 0.4 + 0.6·0.5 = 0.7; after the ramp 1.
    EXPECT_NEAR(Starter(p).supply(1.0, 0).voltage, 0.7, kRounding);
    EXPECT_EQ(Starter(p).supply(3.0, 0).voltage, 1.0);
    p.kind = StarterParams::Kind::StarDelta;
    p.switchTimes = {2};
    EXPECT_NEAR(Starter(p).supply(1.0, 0).connection, 1.0 / 3, kRounding);
    EXPECT_EQ(Starter(p).supply(1.0, 1).connection, 1.0);
    p.kind = StarterParams::Kind::RotorResistance;
    p.switchTimes = {1, 2};
    p.resistanceRatios = {8, 3};
    EXPECT_EQ(Starter(p).supply(0.5, 0).resistance, 8.0);
    EXPECT_EQ(Starter(p).supply(1.5, 1).resistance, 3.0);
    EXPECT_EQ(Starter(p).supply(2.5, 2).resistance, 1.0);
    p.resistanceRatios = {3, 8};  // not decreasing
    EXPECT_THROW(Starter{p}, std::invalid_argument);
    p = StarterParams();
    p.kind = StarterParams::Kind::FrequencyConverter;
    p.rampTime = 0;  // a ramp of zero length
    EXPECT_THROW(Starter{p}, std::invalid_argument);
    p.rampTime = 4;
    p.initialFrequency = 0.2;
    EXPECT_NEAR(Starter(p).supply(2.0, 0).frequency, 0.6, kRounding);
    p.switchTimes = {-1};
    p.kind = StarterParams::Kind::StarDelta;
    EXPECT_THROW(Starter{p}, std::invalid_argument);  // switching before t = 0
}

struct Bench {
    test::ShaftSystem sys;
    SimTK::MobilizedBody::Pin shaft;
    InductionMotor* motor;
    explicit Bench(const InductionMotorParams& p) : shaft(sys.addShaft(1.0)) {
        motor = new InductionMotor(sys.forces(), shaft, p);
        SimTK::Force::Custom force(sys.forces(), motor);
    }
};

InductionMotorParams kloss() {
    InductionMotorParams p;
    p.law = TorqueSpeedCurveParams::Law::Kloss;
    p.ratedTorque = 97.4;
    p.ratedSpeed = 1470 * kRpm;
    p.synchronousSpeed = 1500 * kRpm;
    p.breakdownRatio = 2.5;
    return p;
}

// Kloss written out afresh: sn = 0.02, sk = sn·(λ + √(λ² − 1)).
double klossByHand(double s, double skScale = 1) {
    const double sk = 0.02 * (2.5 + std::sqrt(2.5 * 2.5 - 1)) * skScale, Mk = 2.5 * 97.4;
    return 2 * Mk * s * sk / (s * s + sk * sk);
}

TEST(InductionMotorSupply, ConverterShiftsTheCurveBySlipSpeed) {
    Bench b(kloss());
    const double wc = 1500 * kRpm;
    SupplyState u;
    u.frequency = 0.5;
    // At ω = 0.4·ωc under f = 0.5 the slip speed is 0.1·ωc: natural slip 0.1.
    EXPECT_NEAR(b.motor->torqueAtSpeed(0.4 * wc, u), klossByHand(0.1), kRounding * 200);
    u.torqueLimit = 50;
    EXPECT_EQ(b.motor->torqueAtSpeed(0.4 * wc, u), 50.0);
}

TEST(InductionMotorSupply, RotorResistanceScalesTheBreakdownSlip) {
    Bench b(kloss());
    const double wc = 1500 * kRpm;
    SupplyState u;
    u.resistance = 5;
    for (double s : {1.0, 0.6, 0.3, 0.05})
        EXPECT_NEAR(b.motor->torqueAtSpeed(wc * (1 - s), u), klossByHand(s, 5), kRounding * 200) << s;
    u = SupplyState();
    u.voltage = 0.5;
    u.connection = 1.0 / 3;
    EXPECT_NEAR(b.motor->torqueAtSpeed(0.5 * wc, u), klossByHand(0.5) * 0.25 / 3, kRounding * 200);
}

TEST(InductionMotorSupply, StarterStepIsADiscreteStateStartingAtZero) {
    InductionMotorParams p = kloss();
    p.starter.kind = StarterParams::Kind::StarDelta;
    p.starter.switchTimes = {1};
    Bench b(p);
    SimTK::State s = b.sys.defaultState();
    EXPECT_EQ(b.motor->getStarterStep(s), 0);
    test::setShaft(s, b.shaft, 0, 0);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_NEAR(b.motor->calcTorque(s), klossByHand(1) / 3, kRounding * 200);
    b.motor->setStarterStep(s, 1);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_NEAR(b.motor->calcTorque(s), klossByHand(1), kRounding * 200);
}

// Bad input: one line file:line:col: error: key: reason.
std::string errorOf(const std::string& motorKeys) {
    const std::string text = "format_version: 1\nname: t\nbodies:\n  - name: shaft\n    inertia: 1 kg*m^2\n"
                             "    joint: {type: pin, parent: ground}\nelements:\n  - type: InductionMotor\n"
                             "    name: motor\n    body: shaft\n    rated_torque: 97.4 N*m\n    rated_speed: 1470 rpm\n"
                             "    synchronous_speed: 1500 rpm\n" +
                             motorKeys + "scenario:\n  analysis: transient\n  end_time: 1 s\n";
    try {
        readModelText(text, "m.yaml", defaultModelReader());
    } catch (const SpecError& e) {
        return e.formatted();
    }
    return "";
}

TEST(InductionMotorInput, BadStartInputsGiveOneLocatedLine) {
    EXPECT_EQ(errorOf("    law: table\n    curve_speeds: [0 rpm, 900 rpm, 600 rpm]\n    curve_torques: [1 N*m, 2 N*m, 3 N*m]\n")
                  .rfind("m.yaml:15:", 0),
              0u);
    EXPECT_NE(errorOf("    law: table\n    curve_speeds: [0 rpm, 900 rpm, 600 rpm]\n    curve_torques: [1 N*m, 2 N*m, 3 N*m]\n")
                  .find("error: motor.curve_speeds: torque-speed points must increase strictly"),
              std::string::npos);
    EXPECT_NE(errorOf("    breakdown_ratio: 0.8\n").find("m.yaml:14:22: error: motor.breakdown_ratio: must be > 1"),
              std::string::npos)
        << errorOf("    breakdown_ratio: 0.8\n");
    EXPECT_NE(errorOf("    starter: star_delta\n    switch_times: [-1 s]\n").find("error: motor.switch_times: must be > 0"),
              std::string::npos)
        << errorOf("    starter: star_delta\n    switch_times: [-1 s]\n");
    EXPECT_NE(errorOf("    starter: soft_start\n    ramp_time: 0 s\n").find("error: motor.ramp_time: a ramp of zero length"),
              std::string::npos)
        << errorOf("    starter: soft_start\n    ramp_time: 0 s\n");
    EXPECT_NE(errorOf("    starter: soft_start\n    switch_times: [1 s]\n    ramp_time: 1 s\n")
                  .find("error: motor.switch_times: not used with starter soft_start"),
              std::string::npos);
    EXPECT_NE(errorOf("    law: catalogue\n    locked_rotor_ratio: 2\n    breakdown_speed: 1490 rpm\n")
                  .find("error: motor.breakdown_speed: the breakdown speed"),
              std::string::npos);
}

// A star-delta switch at a speed: the step is taken at the end of the first
// accepted step past 60 rad/s, so every sample below it is in star (1/3 of
// the Kloss torque) and every sample clearly above it in delta.
TEST(InductionMotorStarter, StarDeltaSwitchesAtASpeed) {
    const std::string text = "format_version: 1\nname: t\nbodies:\n  - name: shaft\n    inertia: 1.5 kg*m^2\n"
                             "    joint: {type: pin, parent: ground}\nelements:\n  - type: InductionMotor\n"
                             "    name: motor\n    body: shaft\n    rated_torque: 97.4 N*m\n    rated_speed: 1470 rpm\n"
                             "    synchronous_speed: 1500 rpm\n    breakdown_ratio: 2.5\n    starter: star_delta\n"
                             "    switch_speeds: [60 rad/s]\nscenario:\n  analysis: transient\n  end_time: 10 s\n"
                             "integrator:\n  name: RungeKuttaMerson\n  accuracy: 1e-9\noutputs:\n  sample_interval: 5 ms\n";
    const AnalysisResult r = runAnalysis(readModelText(text, "t.yaml", defaultModelReader()));
    const double wc = 1500 * kRpm;
    int star = 0, delta = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const double w = r.value(i, "shaft.speed");
        const double ratio = r.value(i, "motor.torque") / klossByHand((wc - w) / wc);
        if (w < 60) {
            EXPECT_NEAR(ratio, 1.0 / 3, 1e-12) << w;
            ++star;
        } else if (w > 61) {
            EXPECT_NEAR(ratio, 1.0, 1e-12) << w;
            ++delta;
        }
    }
    EXPECT_GT(star, 10);
    EXPECT_GT(delta, 10);
    EXPECT_EQ(r.verdict, "completed") << r.verdictText;
}

// The switch speed is a located event (StarterSpeedTrigger): the switch is
// at the crossing, to within the event's 1e-6 s window, not at the first
// step end past it, whatever the sampling and the integrator's accuracy.
// Oracle: in star the Kloss torque is a third, T(s)/3 = (2·Mk/3)/(s/sk +
// sk/s), and J·dω/dt = T/3 from rest integrates in closed form (dω = −ωs·ds):
//   t(ω) = 3·J·ωs/(2·Mk) · [(1 − s²)/(2·sk) − sk·ln s],   s = 1 − ω/ωs.
TEST(InductionMotorStarter, StarDeltaSwitchIsLocatedAtTheSwitchSpeed) {
    const double J = 1.5, ws = 1500 * kRpm, Mk = 2.5 * 97.4, sk = 0.02 * (2.5 + std::sqrt(2.5 * 2.5 - 1));
    const double v = 60, s = 1 - v / ws;
    const double tSwitch = 3 * J * ws / (2 * Mk) * ((1 - s * s) / (2 * sk) - sk * std::log(s));
    const std::string text = "format_version: 1\nname: t\nbodies:\n  - name: shaft\n    inertia: 1.5 kg*m^2\n"
                             "    joint: {type: pin, parent: ground}\nelements:\n  - type: InductionMotor\n"
                             "    name: motor\n    body: shaft\n    rated_torque: 97.4 N*m\n    rated_speed: 1470 rpm\n"
                             "    synchronous_speed: 1500 rpm\n    breakdown_ratio: 2.5\n    starter: star_delta\n"
                             "    switch_speeds: [60 rad/s]\nscenario:\n  analysis: transient\n  end_time: 8 s\n"
                             "integrator:\n  name: RungeKuttaMerson\n  accuracy: 1e-9\noutputs:\n  sample_interval: 5 ms\n";
    for (const char* accuracy : {"1e-6", "1e-9"})
        for (const char* dt : {"5 ms", "0.37 s"}) {
            const AnalysisResult r =
                runAnalysis(readModelText(text, "t.yaml", defaultModelReader(),
                                          {{"integrator.accuracy", accuracy}, {"outputs.sample_interval", dt}}));
            const ResultScalar* end = r.find("sequence_end.motor");
            ASSERT_NE(end, nullptr) << accuracy << " " << dt;
            // 1e-6 s window, and the crossing instant's integration error
            // (accuracy·ω / (dω/dt ≈ 16 rad/s²): 4e-6 s at 1e-6).
            EXPECT_NEAR(end->value, tSwitch, 1e-5) << accuracy << " " << dt;
            // Every row below the speed is in star, every row above it in
            // delta (the rows lie within 0.1 rad/s of 60 rad/s only at 5 ms).
            for (std::size_t i = 0; i < r.rows.size(); ++i) {
                const double w = r.value(i, "shaft.speed");
                const double ratio = r.value(i, "motor.torque") / klossByHand((ws - w) / ws);
                EXPECT_NEAR(ratio, w < v ? 1.0 / 3 : 1.0, 1e-9) << accuracy << " " << dt << " at " << w << " rad/s";
            }
        }
}


// The converter's hold slip: where the Kloss torque reaches the limit,
// s = sk·(Mk/M_lim − √((Mk/M_lim)² − 1)) (the stable root of Kloss = M_lim);
// a limit above breakdown holds at the breakdown slip.
TEST(InductionMotorConverter, HoldSlipIsWhereTheCurveReachesTheLimit) {
    const double wc = 1500 * kRpm, sk = 0.02 * (2.5 + std::sqrt(2.5 * 2.5 - 1)), Mk = 2.5 * 97.4;
    const TorqueSpeedCurve kl(kloss());
    const double q = Mk / 146.1;
    EXPECT_NEAR(calcHoldSlipSpeed(kl, 146.1) / wc, sk * (q - std::sqrt(q * q - 1)), 1e-14);
    EXPECT_NEAR(calcHoldSlipSpeed(kl, 1e9) / wc, sk, 1e-15);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NEAR(calcHoldSlipSpeed(kl, inf) / wc, sk, 1e-15);
    // Catalogue: breakdown at 1320 rpm, torque 280 N*m.
    const TorqueSpeedCurve cat(catalogue());
    EXPECT_NEAR(calcHoldSlipSpeed(cat, 500), (1500 - 1320) * kRpm, 1e-12);
    const double held = calcHoldSlipSpeed(cat, 150);
    EXPECT_NEAR(cat.torque(wc - held), 150, 1e-9);
    EXPECT_GT(held, (1500 - 1470) * kRpm);  // beyond the rated point (100 N*m)
    EXPECT_LT(held, (1500 - 1320) * kRpm);
}

// The ramp pauses at the limit and resumes from where it was held: a shaft
// whose limit acceleration is below the ramp's is held (slip = hold slip),
// and the hold state follows the rules of the class comment.
TEST(InductionMotorConverter, RampHoldsAtTheLimitAndReleasesWhenTheRotorKeepsUp) {
    InductionMotorParams p = kloss();
    p.starter.kind = StarterParams::Kind::FrequencyConverter;
    p.starter.initialFrequency = 0.1;
    p.starter.rampTime = 1;  // R·ωc = 0.9·157.08 = 141 rad/s^2
    p.starter.torqueLimit = 146.1;
    Bench b(p);  // J = 1 kg*m^2: 146.1 rad/s^2 at the limit without load
    const double wc = 1500 * kRpm, dwh = b.motor->holdSlipSpeed();
    SimTK::State s = b.sys.defaultState();
    test::setShaft(s, b.shaft, 0, 0);
    b.sys.system().realize(s, SimTK::Stage::Acceleration);
    // Ramp at 0.1 is ahead of f_lim = Δω_h/ωc = 0.032: limited, torque = M_lim.
    EXPECT_NEAR(b.motor->supply(s).frequency, dwh / wc, 1e-15);
    EXPECT_NEAR(b.motor->calcTorque(s), 146.1, 1e-12);
    EXPECT_EQ(b.motor->calcRampHold(s), 1.0);
    EXPECT_EQ(b.motor->setRampHold(s, 1.0), 1.0);
    EXPECT_TRUE(b.motor->isRampHeld(s));
    // Held, the rotor accelerates at 146.1 rad/s^2 >= 141 rad/s^2: it keeps up, release.
    b.sys.system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_EQ(b.motor->calcRampHold(s), 0.0);
    // At t = 0.5 s and 50 rad/s the release restarts the ramp from f = (50 + Δω_h)/ωc.
    s.setTime(0.5);
    test::setShaft(s, b.shaft, 0, 50);
    EXPECT_EQ(b.motor->setRampHold(s, 0.0), 1.0);
    EXPECT_FALSE(b.motor->isRampHeld(s));
    s.setTime(0.6);
    test::setShaft(s, b.shaft, 0, 200);  // far ahead of the ramp: f = the ramp
    b.sys.system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_NEAR(b.motor->supply(s).frequency, (50 + dwh) / wc + 0.9 * 0.1, 1e-14);
    EXPECT_EQ(b.motor->calcRampHold(s), 0.0);
}

CurrentCircleParams circleData() {
    return {0.02, 28.5, 0.85, 7.0};  // IEC 15 kW 4-pole: I_N 28.5 A, cos φ 0.85, I_LR/I_N 7
}

TEST(CurrentCircle, ReproducesTheCatalogueCurrentsAndPowerFactor) {
    const CurrentCircle c(circleData());
    EXPECT_NEAR(c.current(0.02), 28.5, 1e-12 * 28.5);
    EXPECT_NEAR(c.current(1.0), 7.0 * 28.5, 1e-12 * 200);
    EXPECT_NEAR(c.current(0.0), c.magnetisingCurrent(), 1e-12);
    // The rated point's reactive part is I_N·sin φ_N: Iμ + the rotor's
    // reactive part, so Iμ < I_N·sin φ_N = 15.0 A.
    EXPECT_GT(c.magnetisingCurrent(), 0.0);
    EXPECT_LT(c.magnetisingCurrent(), 28.5 * std::sqrt(1 - 0.85 * 0.85));
    // Current rises monotonically with slip on [0, 1] (the circle's lower half).
    for (int i = 1; i <= 100; ++i) EXPECT_GT(c.current(i / 100.0), c.current((i - 1) / 100.0)) << i;
    EXPECT_GT(c.lockedRotorPowerFactor(), 0.0);
    EXPECT_LT(c.lockedRotorPowerFactor(), 0.85);
}

TEST(CurrentCircle, RejectsDataNoCircleFits) {
    CurrentCircleParams p = circleData();
    p.lockedRotorRatio = 0.9;  // below rated current
    EXPECT_THROW(CurrentCircle{p}, std::invalid_argument);
    p.lockedRotorRatio = 60;  // beyond the circle slip 1
    EXPECT_THROW(CurrentCircle{p}, std::invalid_argument);
    p = circleData();
    p.ratedPowerFactor = 1.0;
    EXPECT_THROW(CurrentCircle{p}, std::invalid_argument);
}

// Star-delta: in star the line current is a third of delta's at the same
// speed, so it jumps ×3 at the switch; soft start scales it by V.
TEST(InductionMotorCurrent, StarDeltaThirdsAndSoftStartScalesTheCurrent) {
    InductionMotorParams p = kloss();
    p.ratedCurrent = 28.5;
    p.ratedPowerFactor = 0.85;
    p.lockedRotorCurrentRatio = 7.0;
    p.starter.kind = StarterParams::Kind::StarDelta;
    p.starter.switchTimes = {1};
    Bench b(p);
    SimTK::State s = b.sys.defaultState();
    test::setShaft(s, b.shaft, 0, 100);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    const double star = b.motor->calcCurrent(s);
    b.motor->setStarterStep(s, 1);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_NEAR(b.motor->calcCurrent(s) / star, 3.0, 1e-13);
    const CurrentCircle c(circleData());
    EXPECT_NEAR(b.motor->calcCurrent(s), c.current((1500 * kRpm - 100) / (1500 * kRpm)), 1e-12 * 200);
    SupplyState u;
    u.voltage = 0.4;
    EXPECT_NEAR(b.motor->currentAtSpeed(0, u), 0.4 * 7.0 * 28.5, 1e-12 * 200);
}

TEST(InductionMotorInput, BadConverterAndCurrentInputsGiveOneLocatedLine) {
    const std::string limit = errorOf("    starter: frequency_converter\n    ramp_time: 5 s\n    torque_limit: 0 N*m\n");
    EXPECT_NE(limit.find("m.yaml:16:19: error: motor.torque_limit: must be > 0"), std::string::npos) << limit;
    const std::string ratio =
        errorOf("    rated_current: 28.5 A\n    rated_power_factor: 0.85\n    locked_rotor_current_ratio: 0.8\n");
    EXPECT_NE(ratio.find("m.yaml:16:33: error: motor.locked_rotor_current_ratio: must be > 1"), std::string::npos)
        << ratio;
    const std::string partial = errorOf("    rated_current: 28.5 A\n");
    EXPECT_EQ(partial.rfind("m.yaml:14:", 0), 0u) << partial;
    EXPECT_NE(partial.find("error: motor.rated_current: the circle diagram of the current needs"), std::string::npos)
        << partial;
    const std::string noFit =
        errorOf("    rated_current: 28.5 A\n    rated_power_factor: 0.85\n    locked_rotor_current_ratio: 1.5\n");
    EXPECT_NE(noFit.find("error: motor.locked_rotor_current_ratio: no circle diagram through these data"),
              std::string::npos)
        << noFit;
    const std::string amps = errorOf("    rated_current: 28.5 N*m\n    rated_power_factor: 0.85\n"
                                     "    locked_rotor_current_ratio: 7\n");
    EXPECT_NE(amps.find("error: motor.rated_current:"), std::string::npos) << amps;
    EXPECT_EQ(std::count(limit.begin(), limit.end(), '\n') + std::count(ratio.begin(), ratio.end(), '\n'), 0);
}

// The loss model from the rated efficiency, by hand for the bench motor
// (Mn = 97.4 N*m, ωn = 153.94 rad/s, ωc = 157.08 rad/s): η = 0.915, P0 =
// 450 W give P_in,n = Mn·ωn/η, P_Cu1,n = P_in,n − Mn·ωc − P0.
InductionMotorParams lossy(bool currentData) {
    InductionMotorParams p = kloss();
    p.ratedEfficiency = 0.915;
    p.noLoadLoss = 450;
    if (currentData) {
        p.ratedCurrent = 28.5;
        p.ratedPowerFactor = 0.85;
        p.lockedRotorCurrentRatio = 7.0;
    }
    return p;
}

double ratedCopperByHand() {
    const double Mn = 97.4, wn = 1470 * kRpm, wc = 1500 * kRpm;
    return Mn * wn / 0.915 - Mn * wc - 450;
}

TEST(InductionMotorLosses, RatedPointDrawsTheRatedInput) {
    const double Mn = 97.4, wn = 1470 * kRpm;
    for (bool currentData : {true, false}) {
        Bench b(lossy(currentData));
        const SupplyState dol;
        EXPECT_NEAR(b.motor->ratedStatorCopperLoss(), ratedCopperByHand(), 1e-9) << currentData;
        EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(wn, dol), ratedCopperByHand(), 1e-9) << currentData;
        EXPECT_NEAR(b.motor->electricalPowerAtSpeed(wn, dol), Mn * wn / 0.915, 1e-9) << currentData;
    }
    // Without a rated efficiency there are no stator-side losses.
    Bench plain(kloss());
    EXPECT_EQ(plain.motor->statorCopperLossAtSpeed(0, SupplyState()), 0.0);
    EXPECT_EQ(plain.motor->noLoadLossAt(SupplyState()), 0.0);
}

// With current data the stator copper loss follows the phase current
// squared: 7² at standstill (I_LR = 7 I_N); in star the phase current is
// 1/√3 of delta's, so a third; at 0.4 V, 0.16. The no-load loss goes with
// the terminal voltage squared: a third in star, 0.16 at 0.4 V, f² under
// V/f (0.25 at half frequency); nothing when switched off.
TEST(InductionMotorLosses, StatorLossesFollowTheSupply) {
    Bench b(lossy(true));
    const double P = ratedCopperByHand();
    SupplyState u;
    EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(0, u), 49 * P, 1e-9 * 49 * P);
    u.connection = 1.0 / 3;
    EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(0, u), 49 * P / 3, 1e-9 * 49 * P);
    EXPECT_NEAR(b.motor->noLoadLossAt(u), 150, 1e-12);
    u = SupplyState();
    u.voltage = 0.4;
    EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(0, u), 0.16 * 49 * P, 1e-9 * 49 * P);
    EXPECT_NEAR(b.motor->noLoadLossAt(u), 0.16 * 450, 1e-12);
    u = SupplyState();
    u.frequency = 0.5;
    EXPECT_NEAR(b.motor->noLoadLossAt(u), 0.25 * 450, 1e-12);
    SimTK::State s = b.sys.defaultState();
    test::setShaft(s, b.shaft, 0, 0);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_NEAR(b.motor->calcStatorLoss(s), 49 * P + 450, 1e-9 * 49 * P);
    EXPECT_NEAR(b.motor->calcElectricalPower(s), klossByHand(1) * 1500 * kRpm + 49 * P + 450, 1e-9 * 49 * P);
    b.motor->setOn(s, false);
    b.sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_EQ(b.motor->calcStatorLoss(s), 0.0);
    EXPECT_EQ(b.motor->calcElectricalPower(s), 0.0);
}

// Without current data the stator copper loss scales as the heat in the
// rotor's own resistance, M·Δω/r over its rated Mn·(ωc − ωn).
TEST(InductionMotorLosses, WithoutCurrentDataTheStatorLossFollowsTheRotorHeat) {
    Bench b(lossy(false));
    const double wc = 1500 * kRpm, P = ratedCopperByHand(), rated = 97.4 * (wc - 1470 * kRpm);
    SupplyState u;
    EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(0, u), P * klossByHand(1) * wc / rated, 1e-9 * P);
    u.resistance = 5;  // r = 5: torque at slip 0.6 is the natural torque at 0.12, heat in R_rotor a fifth
    EXPECT_NEAR(b.motor->statorCopperLossAtSpeed(0.4 * wc, u), P * klossByHand(0.6, 5) * 0.6 * wc / 5 / rated,
                1e-9 * P);
}

// The stator-side losses add to the input without touching the mechanics:
// the DOL bench (no current data) with and without the two keys has the
// same rotor heat, and the electrical input exceeds the air-gap work by
// exactly the stator heat; the balance closes with the stator heat in it.
TEST(InductionMotorLosses, StatorHeatAddsToTheInputAndTheBalanceCloses) {
    const std::string model = std::string(MILLDYN_SOURCE_DIR) + "/models/start_bench_dol.yaml";
    const std::vector<Override> tight = {{"integrator.accuracy", "1e-9"}, {"outputs.plots", "false"}};
    std::vector<Override> lossy = tight;
    lossy.push_back({"elements.motor.rated_efficiency", "0.915"});
    lossy.push_back({"elements.motor.no_load_loss", "450 W"});
    const AnalysisResult plain = runModelFile(model, tight), withLosses = runModelFile(model, lossy);
    auto value = [](const AnalysisResult& r, const std::string& name) {
        const ResultScalar* v = r.find(name);
        return v ? v->value : std::nan("");
    };
    const double rotor = value(plain, "energy.motor.rotor_heat");
    EXPECT_NEAR(value(withLosses, "energy.motor.rotor_heat"), rotor, 1e-7 * rotor);
    const double stator = value(withLosses, "energy.motor.stator_heat");
    EXPECT_GT(stator, 0.0);
    EXPECT_NEAR(value(withLosses, "energy.motor") - value(plain, "energy.motor"), stator, 1e-7 * stator);
    EXPECT_NEAR(value(withLosses, "energy_split.motor_loss"), rotor + stator, 1e-7 * (rotor + stator));
    EXPECT_LE(std::abs(value(withLosses, "energy_balance_relative")), 1e-8);
    EXPECT_TRUE(std::isnan(value(plain, "energy.motor.stator_heat")));
}

// The converter's current hold: the slip speed where the circle current is
// the limit; a limit above the breakdown current holds at breakdown; one at
// or below the magnetising current, or a curve without current, is refused.
TEST(InductionMotorConverter, CurrentHoldSlipIsWhereTheCurrentReachesTheLimit) {
    const double wc = 1500 * kRpm, sk = 0.02 * (2.5 + std::sqrt(2.5 * 2.5 - 1));
    const TorqueSpeedCurve curve(lossy(true));
    const double held = calcCurrentHoldSlipSpeed(curve, 42.75);
    EXPECT_NEAR(curve.current(wc - held), 42.75, 1e-12 * 42.75);
    EXPECT_GT(held, 0.02 * wc);  // above rated current: beyond the rated slip
    EXPECT_NEAR(calcCurrentHoldSlipSpeed(curve, 1e4) / wc, sk, 1e-15);
    const double Imu = CurrentCircle(circleData()).magnetisingCurrent();
    EXPECT_THROW(calcCurrentHoldSlipSpeed(curve, Imu), std::invalid_argument);
    EXPECT_THROW(calcCurrentHoldSlipSpeed(TorqueSpeedCurve(kloss()), 42.75), std::invalid_argument);
    // The motor holds at the smaller of the torque and current slips.
    InductionMotorParams p = lossy(true);
    p.starter.kind = StarterParams::Kind::FrequencyConverter;
    p.starter.rampTime = 1;
    p.starter.currentLimit = 42.75;
    p.starter.torqueLimit = 200;
    Bench current(p);
    EXPECT_TRUE(current.motor->holdsAtCurrentLimit());
    EXPECT_EQ(current.motor->holdSlipSpeed(), held);
    p.starter.torqueLimit = 120;
    Bench torque(p);
    EXPECT_FALSE(torque.motor->holdsAtCurrentLimit());
    EXPECT_EQ(torque.motor->holdSlipSpeed(), calcHoldSlipSpeed(curve, 120));
}

TEST(InductionMotorInput, BadLossAndCurrentLimitInputsGiveOneLocatedLine) {
    const std::string circle = "    rated_current: 28.5 A\n    rated_power_factor: 0.85\n    locked_rotor_current_ratio: 7\n";
    const std::string alone = errorOf("    rated_efficiency: 0.9\n");
    EXPECT_EQ(alone.rfind("m.yaml:14:23: error: motor.rated_efficiency: give rated_efficiency and no_load_loss together",
                          0),
              0u)
        << alone;
    // η = 0.975 at sn = 0.02 leaves P_in,n = 15378 W < Mn·ωc + P0 = 15750 W.
    const std::string high = errorOf("    rated_efficiency: 0.975\n    no_load_loss: 450 W\n");
    EXPECT_EQ(high.rfind("m.yaml:14:23: error: motor.rated_efficiency: no stator copper loss is left", 0), 0u) << high;
    EXPECT_NE(high.find("P_Cu1,n = -3"), std::string::npos) << high;
    const std::string range = errorOf("    rated_efficiency: 1.2\n    no_load_loss: 450 W\n");
    EXPECT_NE(range.find("error: motor.rated_efficiency: must be < 1"), std::string::npos) << range;
    const std::string converter = "    starter: frequency_converter\n    ramp_time: 1 s\n";
    const std::string noData = errorOf(converter + "    current_limit: 40 A\n");
    EXPECT_EQ(noData.rfind("m.yaml:16:20: error: motor.current_limit: a current limit needs the motor's current data", 0),
              0u)
        << noData;
    const std::string low = errorOf(circle + converter + "    current_limit: 10 A\n");
    EXPECT_NE(low.find("error: motor.current_limit: current_limit = 10 A is not above the no-load "
                       "(magnetising) current 11.87"),
              std::string::npos)
        << low;
    const std::string other = errorOf(circle + "    starter: soft_start\n    ramp_time: 1 s\n    current_limit: 40 A\n");
    EXPECT_NE(other.find("error: motor.current_limit: not used with starter soft_start"), std::string::npos) << other;
    for (const std::string* e : {&alone, &high, &range, &noData, &low, &other})
        EXPECT_EQ(std::count(e->begin(), e->end(), '\n'), 0) << *e;
}

// The dq machine's currents and torque from its flux states, by hand:
// with ψs = 1 Wb (α axis) and ψr = 0.9j Wb, is = (Lr·ψs − Lm·ψr)/D and
// T = 1.5·p·Im(conj(ψs)·is).
TEST(DqInductionMotor, CurrentsAndTorqueFromTheFluxStates) {
    DqInductionMotorParams p;
    p.statorResistance = 0.03;
    p.rotorResistance = 0.04;
    p.statorLeakage = 3e-4;
    p.rotorLeakage = 4e-4;
    p.mainInductance = 9e-3;
    p.polePairs = 2;
    p.phaseVoltage = 100;
    p.frequency = 50;
    test::ShaftSystem sys;
    auto shaft = sys.addShaft(1.0);
    auto* m = new DqInductionMotor(sys.forces(), shaft, p);
    SimTK::Force::Custom force(sys.forces(), m);
    SimTK::State s = sys.defaultState();
    s.updZ()[0] = 1.0;  // ψs = 1 + 0j (this force's Z are the system's only ones)
    s.updZ()[3] = 0.9;  // ψr = 0 + 0.9j
    sys.system().realize(s, SimTK::Stage::Dynamics);
    const double Ls = 9.3e-3, Lr = 9.4e-3, Lm = 9e-3, D = Ls * Lr - Lm * Lm;
    // is = (Lr·1 − Lm·0.9j)/D: real Lr/D, imaginary −0.9·Lm/D.
    EXPECT_NEAR(m->calcStatorCurrent(s).real(), Lr / D, 1e-9);
    EXPECT_NEAR(m->calcStatorCurrent(s).imag(), -0.9 * Lm / D, 1e-9);
    // Im(conj(1)·is) = −0.9·Lm/D, times 1.5·p = 3.
    EXPECT_NEAR(m->calcTorque(s), 3 * (-0.9 * Lm / D), 1e-9);
    // Supply at t = 5 ms: √2·100·e^(j·π/2).
    EXPECT_NEAR(m->calcSupplyVoltage(0.005).imag(), 100 * std::sqrt(2.0), 1e-9);
    p.rotorResistance = -1;
    EXPECT_THROW(DqInductionMotor(sys.forces(), shaft, p), std::invalid_argument);
}

TEST(DqInductionMotor, BadInputGivesOneLocatedLine) {
    auto errorOfDq = [](const std::string& keys) {
        const std::string text = "format_version: 1\nname: t\nbodies:\n  - name: shaft\n    inertia: 1 kg*m^2\n"
                                 "    joint: {type: pin, parent: ground}\nelements:\n  - type: DqInductionMotor\n"
                                 "    name: motor\n    body: shaft\n" + keys +
                                 "scenario:\n  analysis: transient\n  end_time: 1 s\n";
        try {
            readModelText(text, "m.yaml", defaultModelReader());
        } catch (const SpecError& e) {
            return e.formatted();
        }
        return std::string();
    };
    const std::string good = "    rotor_resistance: 0.04 ohm\n    stator_leakage_inductance: 0.3 mH\n"
                             "    rotor_leakage_inductance: 0.3 mH\n    main_inductance: 9 mH\n    phase_voltage: 100 V\n";
    EXPECT_EQ(errorOfDq("    stator_resistance: 0.03 ohm\n" + good), "");
    const std::string negative = errorOfDq("    stator_resistance: -0.03 ohm\n" + good);
    EXPECT_NE(negative.find("m.yaml:11:24: error: motor.stator_resistance: must be > 0"), std::string::npos) << negative;
    const std::string unit = errorOfDq("    stator_resistance: 0.03 H\n" + good);
    EXPECT_NE(unit.find("m.yaml:11:29: error: motor.stator_resistance: incompatible unit"), std::string::npos) << unit;
    const std::string poles = errorOfDq("    stator_resistance: 0.03 ohm\n    pole_pairs: 1.5\n" + good);
    EXPECT_NE(poles.find("error: motor.pole_pairs: must be a whole number"), std::string::npos) << poles;
}

}  // namespace
}  // namespace milldyn
