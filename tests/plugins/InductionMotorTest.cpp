// Tests of InductionMotor (plugins/motors/InductionMotor.h). Expected values are
// worked out by hand in the comments, or computed here from the class
// comment's equations written out afresh (klossTorque below), or come from
// Simbody's own elements -- never from the motor's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "plugins/scene/ElementRegistry.h"
#include "plugins/motors/InductionMotor.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

using test::ShaftSystem;
using test::number;
using test::word;
using Law = InductionMotorParams::Law;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRpm = 2 * kPi / 60;  // rad/s per rpm

// Seed 003's MMP-50 motor (5.5 kW), typed in from the paper.
constexpr double kRatedTorque = 36.3;             // N*m
constexpr double kRatedSpeed = 1446 * kRpm;       // rad/s
constexpr double kSynchronousSpeed = 1500 * kRpm; // rad/s
constexpr double kBreakdownRatio = 2.2;
constexpr double kPrintedM00 = 1010.0;  // N*m
constexpr double kPrintedB0 = 6.428;    // N*m*s/rad

// Kloss breakdown slip by hand: sn = 54/1500 = 0.036,
// sk = 0.036·(2.2 + √3.84) = 0.036·4.1595917942 = 0.14974530459.
constexpr double kBreakdownSlip = 0.14974530459215554;
constexpr double kBreakdownTorque = 79.86;  // N*m, λ·Mn = 2.2·36.3

constexpr double kShaftInertia = 0.2;  // kg*m^2

// Closed forms in double against the element's: a few ulps of ~1e3 N*m
// (M00 − b0·ω cancels ~1500 − 1450, so relative to the larger term).
constexpr double kRoundingRelTolerance = 1e-12;
// Accelerations from Simbody's solve of the same torques: ulps.
constexpr double kSolverRelTolerance = 1e-12;
// Energy and impulse of a 0.5 s run-up, relative to the change: Simpson on
// 2000 intervals of a motion whose fastest time constant is ~30 ms errs by
// ~(h/τ)^4/180 ~ 2e-11, and the 0.25 ms sample grid keeps the integrator's
// steps far shorter than accuracy 1e-9 needs (seen: 4e-13). A torque or
// power wrong by more than 1 part in 1e10 fails.
constexpr double kTrajectoryRelTolerance = 1e-10;

InductionMotorParams klossMotor() {
    InductionMotorParams p;
    p.law = Law::Kloss;
    p.ratedTorque = kRatedTorque;
    p.ratedSpeed = kRatedSpeed;
    p.synchronousSpeed = kSynchronousSpeed;
    p.breakdownRatio = kBreakdownRatio;
    return p;
}

// A round-number nameplate for the linear law: Mn = 100 N*m, ωn = 140,
// ωc = 150 rad/s, so by eq (4) b0 = 100/10 = 10 N*m*s/rad and
// M00 = 100·150/10 = 1500 N*m.
InductionMotorParams linearNameplateMotor() {
    InductionMotorParams p;
    p.law = Law::Linear;
    p.ratedTorque = 100.0;
    p.ratedSpeed = 140.0;
    p.synchronousSpeed = 150.0;
    return p;
}

InductionMotorParams linearPrintedMotor() {
    InductionMotorParams p = klossMotor();
    p.law = Law::Linear;
    p.linearStallTorque = kPrintedM00;
    p.linearSlope = kPrintedB0;
    return p;
}

// The Kloss curve of the class comment in its textbook form
// M = 2·Mk/(s/sk + sk/s), Mk = λ·Mn, for s ≠ 0.
double klossTorque(double omega) {
    const double s = (kSynchronousSpeed - omega) / kSynchronousSpeed;
    return 2 * kBreakdownTorque / (s / kBreakdownSlip + kBreakdownSlip / s);
}

// One InductionMotor on one shaft (kShaftInertia unless given).
struct MotorOnShaft : test::ElementOnShaft<InductionMotor, InductionMotorParams> {
    explicit MotorOnShaft(const InductionMotorParams& p, double J = kShaftInertia) : ElementOnShaft(p, J) {}
};

// ---- 1. force vs closed form ------------------------------------------------

TEST(InductionMotorTest, LinearLawFollowsNameplateEquationFour) {
    MotorOnShaft m(linearNameplateMotor());
    // M = 1500 − 10·ω: at ωn = 140 it is Mn = 100, at ωc = 150 it is 0,
    // at 145 it is 50, at rest 1500 (the ≈15·Mn the class comment warns of).
    EXPECT_NEAR(m.torqueAt(140.0), 100.0, kRoundingRelTolerance * 1500);
    EXPECT_NEAR(m.torqueAt(150.0), 0.0, kRoundingRelTolerance * 1500);
    EXPECT_NEAR(m.torqueAt(145.0), 50.0, kRoundingRelTolerance * 1500);
    EXPECT_NEAR(m.torqueAt(0.0), 1500.0, kRoundingRelTolerance * 1500);
    EXPECT_NEAR(m.element->linearStallTorque(), 1500.0, kRoundingRelTolerance * 1500);
    EXPECT_NEAR(m.element->linearSlope(), 10.0, kRoundingRelTolerance * 10);
}

TEST(InductionMotorTest, LinearLawUsesPrintedStallTorqueAndSlopeWhenBothGiven) {
    MotorOnShaft m(linearPrintedMotor());
    // 1010 − 6.428·155 = 1010 − 996.34 = 13.66 N*m (the nameplate pair
    // 1008.33 − 6.4192·155 would give 13.35).
    EXPECT_NEAR(m.torqueAt(155.0), 13.66, kRoundingRelTolerance * 1010);
    EXPECT_NEAR(m.torqueAt(0.0), 1010.0, kRoundingRelTolerance * 1010);
}

TEST(InductionMotorTest, LinearLawFallsBackToNameplateWhenOnlyOnePrintedCoefficientGiven) {
    InductionMotorParams p = linearPrintedMotor();
    p.linearSlope = 0;  // only M00 given: eq (4) for both
    MotorOnShaft m(p);
    // Eq (4) passes through (ωn, Mn) and (ωc, 0) whatever the nameplate.
    EXPECT_NEAR(m.torqueAt(kRatedSpeed), kRatedTorque, kRoundingRelTolerance * 1010);
    EXPECT_NEAR(m.torqueAt(kSynchronousSpeed), 0.0, kRoundingRelTolerance * 1010);
}

// With x = sk/sn = λ + √(λ²−1), 1/x = λ − √(λ²−1), so x + 1/x = 2λ and
// M(ωn) = 2λMn/(x + 1/x) = Mn exactly.
TEST(InductionMotorTest, KlossTorqueEqualsRatedTorqueAtRatedSpeed) {
    MotorOnShaft m(klossMotor());
    EXPECT_NEAR(m.torqueAt(kRatedSpeed), kRatedTorque, kRoundingRelTolerance * kRatedTorque);
}

TEST(InductionMotorTest, KlossTorqueVanishesAtSynchronousSpeed) {
    MotorOnShaft m(klossMotor());
    EXPECT_EQ(m.torqueAt(kSynchronousSpeed), 0.0);
}

TEST(InductionMotorTest, KlossTorquePeaksAtBreakdownTorqueAtBreakdownSlip) {
    MotorOnShaft m(klossMotor());
    // s = sk: M = 2Mk·sk²/(2sk²) = Mk = 79.86 N*m.
    const double omegaBreakdown = kSynchronousSpeed * (1 - kBreakdownSlip);
    EXPECT_NEAR(m.torqueAt(omegaBreakdown), kBreakdownTorque, kRoundingRelTolerance * kBreakdownTorque);
    // And it is the maximum over the motoring range: scan 0..ωc.
    double maxTorque = -1, argMax = -1;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
        const double w = kSynchronousSpeed * i / n;
        const double M = m.element->torqueAtSpeed(w);
        if (M > maxTorque) { maxTorque = M; argMax = w; }
    }
    EXPECT_LE(maxTorque, kBreakdownTorque * (1 + kRoundingRelTolerance));
    EXPECT_NEAR(argMax, omegaBreakdown, kSynchronousSpeed / n);
}

TEST(InductionMotorTest, KlossStartingTorqueIsAboutTwoThirdsOfRated) {
    MotorOnShaft m(klossMotor());
    // s = 1: M = 2·79.86·0.149745/(1 + 0.149745²) = 23.9173/1.022424
    // = 23.39277 N*m ≈ 0.644·Mn (the burr-mill models say "~0.65 Mn").
    EXPECT_NEAR(m.torqueAt(0.0), 23.39276864665167, kRoundingRelTolerance * 23.4);
}

TEST(InductionMotorTest, KlossAboveSynchronousSpeedBrakesAsGenerator) {
    MotorOnShaft m(klossMotor());
    // M is odd in s: at s = −sk it is −Mk.
    EXPECT_NEAR(m.torqueAt(kSynchronousSpeed * (1 + kBreakdownSlip)), -kBreakdownTorque,
                kRoundingRelTolerance * kBreakdownTorque);
}

TEST(InductionMotorTest, KlossCurveMatchesTextbookFormAcrossSpeeds) {
    MotorOnShaft m(klossMotor());
    for (double w : {-50.0, 0.0, 30.0, 100.0, 140.0, 150.0, 155.0, 157.0, 160.0, 300.0})
        EXPECT_NEAR(m.torqueAt(w), klossTorque(w), kRoundingRelTolerance * kBreakdownTorque)
            << "ω = " << w;
}

TEST(InductionMotorTest, SwitchedOffMotorAppliesNoTorque) {
    MotorOnShaft m(klossMotor());
    EXPECT_TRUE(m.element->isOn(m.state));
    // Realize with the supply on first, so a stale Dynamics cache would show.
    test::setShaft(m.state, m.shaft, 0.0, 100.0);
    EXPECT_GT(test::shaftAcceleration(m.rig.system(), m.state, m.shaft), 0.0);
    m.element->setOn(m.state, false);
    EXPECT_FALSE(m.element->isOn(m.state));
    EXPECT_EQ(test::shaftAcceleration(m.rig.system(), m.state, m.shaft), 0.0);
    EXPECT_EQ(m.torqueAt(100.0), 0.0);
    EXPECT_EQ(m.torqueAt(0.0), 0.0);
    m.element->setOn(m.state, true);
    EXPECT_NEAR(m.torqueAt(kRatedSpeed), kRatedTorque, kRoundingRelTolerance * kRatedTorque);
}

// ---- 2. action = reaction ---------------------------------------------------

// The stator reaction −M goes to ground, which is not modelled. What the
// shaft sees must be exactly M: the pin reaction about z (Simbody includes
// applied mobility forces in it) and the angular momentum rate J·u̇.
TEST(InductionMotorTest, PinCarriesMotorTorqueBetweenGroundAndShaft) {
    MotorOnShaft m(klossMotor());
    test::setShaft(m.state, m.shaft, 0.0, kRatedSpeed);
    m.rig.system().realize(m.state, SimTK::Stage::Acceleration);
    SimTK::Vector_<SimTK::SpatialVec> reactions;
    m.rig.matter().calcMobilizerReactionForces(m.state, reactions);
    EXPECT_NEAR(reactions[m.shaft.getMobilizedBodyIndex()][0][2], kRatedTorque,
                kSolverRelTolerance * kRatedTorque);
    EXPECT_NEAR(kShaftInertia * m.shaft.getOneUDot(m.state, SimTK::MobilizerUIndex(0)),
                kRatedTorque, kSolverRelTolerance * kRatedTorque);
}

// ---- 3. energy balance along a trajectory -----------------------------------

TEST(InductionMotorTest, RunUpGainsMotorWorkAsKineticEnergyAndImpulseAsMomentum) {
    MotorOnShaft m(klossMotor());
    const double w0 = 100.0;
    test::setShaft(m.state, m.shaft, 0.0, w0);
    const SimTK::MobilizedBody shaft = m.shaft;
    // Power and torque from the closed form, not from the element.
    auto power = [shaft](const SimTK::State& s) {
        const double w = test::shaftSpeed(s, shaft);
        return klossTorque(w) * w;
    };
    auto torque = [shaft](const SimTK::State& s) { return klossTorque(test::shaftSpeed(s, shaft)); };
    const double H0 = test::angularMomentumZ(m.rig.system(), m.state);
    std::vector<double> work;
    const SimTK::State end =
        test::integrateWithQuadrature(m.rig.system(), m.state, 0.5, 2000, {power, torque}, work);
    const double w1 = test::shaftSpeed(end, m.shaft);
    // The run must have got near synchronous speed, through the steep branch.
    EXPECT_GT(w1, kRatedSpeed);
    const double energyGain = 0.5 * kShaftInertia * (w1 * w1 - w0 * w0);
    EXPECT_NEAR(energyGain, work[0], kTrajectoryRelTolerance * energyGain);
    const double momentumGain = test::angularMomentumZ(m.rig.system(), end) - H0;
    EXPECT_NEAR(momentumGain, kShaftInertia * (w1 - w0), kSolverRelTolerance * momentumGain);
    EXPECT_NEAR(momentumGain, work[1], kTrajectoryRelTolerance * momentumGain);
}

TEST(InductionMotorTest, SwitchedOffShaftCoastsAtConstantSpeed) {
    MotorOnShaft m(klossMotor());
    test::setShaft(m.state, m.shaft, 0.0, kRatedSpeed);
    m.element->setOn(m.state, false);
    std::vector<double> none;
    const SimTK::State end = test::integrateWithQuadrature(m.rig.system(), m.state, 0.5, 100, {}, none);
    EXPECT_EQ(test::shaftSpeed(end, m.shaft), kRatedSpeed);
}

// ---- 4. reduces to Simbody's built-ins --------------------------------------

// M = M00 − b0·ω is Force::MobilityConstantForce(M00) plus
// Force::MobilityLinearDamper(b0).
TEST(InductionMotorTest, LinearLawMatchesMobilityConstantForcePlusLinearDamper) {
    struct Case { InductionMotorParams p; double M00, b0; };
    // Nameplate pair by eq (4) as derived above; printed pair typed in.
    for (const Case& c : {Case{linearNameplateMotor(), 1500.0, 10.0},
                          Case{linearPrintedMotor(), kPrintedM00, kPrintedB0}}) {
        MotorOnShaft m(c.p);
        ShaftSystem reference;
        SimTK::MobilizedBody::Pin alone = reference.addShaft(kShaftInertia);
        const SimTK::Force::MobilityConstantForce stall(reference.forces(), alone, SimTK::MobilizerUIndex(0), c.M00);
        const SimTK::Force::MobilityLinearDamper slope(reference.forces(), alone, SimTK::MobilizerUIndex(0), c.b0);
        SimTK::State refState = reference.defaultState();
        for (double w : {-20.0, 0.0, 100.0, 140.0, 150.0, 157.0, 200.0}) {
            test::setShaft(m.state, m.shaft, 0.3, w);
            test::setShaft(refState, alone, 0.3, w);
            const double expected = test::shaftAcceleration(reference.system(), refState, alone);
            EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shaft), expected,
                        kSolverRelTolerance * c.M00 / kShaftInertia)
                << "M00 = " << c.M00 << ", ω = " << w;
        }
    }
}

// ---- 5. bad parameters ------------------------------------------------------

void expectRejected(const InductionMotorParams& p, const std::string& parameter) {
    ShaftSystem rig;
    const SimTK::MobilizedBody::Pin shaft = rig.addShaft(kShaftInertia);
    test::expectInvalidArgumentNaming(
        parameter, [&] { (void)std::make_unique<InductionMotor>(rig.forces(), shaft, p); });
}

TEST(InductionMotorTest, NonPositiveRatedTorqueThrowsNamingRatedTorque) {
    for (double bad : {0.0, -36.3, std::numeric_limits<double>::quiet_NaN()}) {
        InductionMotorParams p = klossMotor();
        p.ratedTorque = bad;
        expectRejected(p, "rated_torque");
    }
}

TEST(InductionMotorTest, NonPositiveSynchronousSpeedThrowsNamingSynchronousSpeed) {
    for (double bad : {0.0, -kSynchronousSpeed, std::numeric_limits<double>::quiet_NaN()}) {
        InductionMotorParams p = klossMotor();
        p.synchronousSpeed = bad;
        expectRejected(p, "synchronous_speed");
    }
}

TEST(InductionMotorTest, RatedSpeedOutsideZeroToSynchronousThrowsNamingRatedSpeed) {
    for (double bad : {0.0, -kRatedSpeed, kSynchronousSpeed, 1.1 * kSynchronousSpeed,
                       std::numeric_limits<double>::quiet_NaN()}) {
        InductionMotorParams p = klossMotor();
        p.ratedSpeed = bad;
        expectRejected(p, "rated_speed");
    }
}

TEST(InductionMotorTest, KlossBreakdownRatioNotAboveOneThrowsNamingBreakdownRatio) {
    for (double bad : {1.0, 0.5, std::numeric_limits<double>::quiet_NaN()}) {
        InductionMotorParams p = klossMotor();
        p.breakdownRatio = bad;
        expectRejected(p, "breakdown_ratio");
    }
}

TEST(InductionMotorTest, LinearLawIgnoresBreakdownRatio) {
    InductionMotorParams p = linearNameplateMotor();
    p.breakdownRatio = 0.5;
    MotorOnShaft m(p);
    EXPECT_NEAR(m.torqueAt(145.0), 50.0, kRoundingRelTolerance * 1500);
}

TEST(InductionMotorTest, NegativeLinearStallTorqueThrowsNamingLinearStallTorque) {
    InductionMotorParams p = linearPrintedMotor();
    p.linearStallTorque = -1010.0;
    expectRejected(p, "linear_stall_torque");
}

TEST(InductionMotorTest, NegativeLinearSlopeThrowsNamingLinearSlope) {
    InductionMotorParams p = linearPrintedMotor();
    p.linearSlope = -6.428;
    expectRejected(p, "linear_slope");
}

TEST(InductionMotorTest, NaNSwitchOffTimeThrowsNamingSwitchOffTime) {
    InductionMotorParams p = klossMotor();
    p.switchOffTime = std::numeric_limits<double>::quiet_NaN();
    expectRejected(p, "switch_off_time");
}

// ">= 0" must reject NaN as the sibling elements do; a NaN M00 or b0 is
// otherwise silently replaced by the nameplate pair.
TEST(InductionMotorTest, NaNLinearCoefficientsThrowNamingTheParameter) {
    InductionMotorParams p = linearPrintedMotor();
    p.linearStallTorque = std::numeric_limits<double>::quiet_NaN();
    expectRejected(p, "linear_stall_torque");
    p = linearPrintedMotor();
    p.linearSlope = std::numeric_limits<double>::quiet_NaN();
    expectRejected(p, "linear_slope");
}

// An infinite torque, speed or ratio passes "> 0" but makes every torque
// inf or NaN (ωc = inf: M00 = inf/inf; λ = inf: sk = inf).
TEST(InductionMotorTest, InfiniteTorqueSpeedOrRatioThrowsNamingTheParameter) {
    const double inf = std::numeric_limits<double>::infinity();
    InductionMotorParams p = klossMotor();
    p.ratedTorque = inf;
    expectRejected(p, "rated_torque");
    p = klossMotor();
    p.synchronousSpeed = inf;
    expectRejected(p, "synchronous_speed");
    p = klossMotor();
    p.breakdownRatio = inf;
    expectRejected(p, "breakdown_ratio");
}

TEST(InductionMotorTest, MessageGivesTheOffendingValue) {
    InductionMotorParams p = klossMotor();
    p.ratedSpeed = 200.0;
    expectRejected(p, "200");
}

TEST(InductionMotorTest, NeverSwitchingOffIsAccepted) {
    InductionMotorParams p = klossMotor();
    p.switchOffTime = std::numeric_limits<double>::infinity();
    MotorOnShaft m(p);
    EXPECT_TRUE(m.element->isOn(m.state));
}

// ---- 6. registry -----------------------------------------------------------



// As the reader would hand it over: every key present, defaults not given.
ElementSpec motorSpec(double ratedSpeed, double synchronousSpeed) {
    ElementSpec e;
    e.type = "InductionMotor";
    e.name = "motor";
    e.where = {"model.yaml", 12, 5};
    e.params["body"] = word("motor_shaft");
    e.params["law"] = word("kloss");
    e.params["rated_torque"] = number(kRatedTorque);
    e.params["rated_speed"] = number(ratedSpeed);
    e.params["rated_speed"].where = {"model.yaml", 15, 18};
    e.params["synchronous_speed"] = number(synchronousSpeed);
    e.params["breakdown_ratio"] = number(kBreakdownRatio);
    ParamValue zero = number(0.0);
    zero.given = false;
    e.params["linear_stall_torque"] = zero;
    e.params["linear_slope"] = zero;
    e.params["switch_off_time"] = number(4.0);
    // Every other key at its default, as the model reader leaves it.
    for (const auto& p : test::registeredType("InductionMotor").schema.params)
        if (!e.params.count(p.key)) {
            ParamValue v;
            v.number = p.defaultValue.value_or(0.0);
            v.text = p.defaultText;
            v.given = false;
            e.params[p.key] = v;
        }
    return e;
}

const ElementType& motorType() { return test::registeredType("InductionMotor"); }

TEST(InductionMotorRegistryTest, SchemaListsTheDocumentedKeys) {
    ASSERT_NE(ElementRegistry::instance().find("InductionMotor"), nullptr);
    const ElementSchema& schema = motorType().schema;
    std::set<std::string> keys;
    for (const auto& p : schema.params) keys.insert(p.key);
    EXPECT_EQ(keys, (std::set<std::string>{"body", "law", "rated_torque", "rated_speed",
                                           "synchronous_speed", "breakdown_ratio",
                                           "linear_stall_torque", "linear_slope",
                                           "locked_rotor_ratio", "pull_up_ratio", "pull_up_speed",
                                           "breakdown_speed", "curve_speeds", "curve_torques",
                                           "curve_currents", "rated_current", "rated_power_factor",
                                           "locked_rotor_current_ratio", "starter", "switch_times", "switch_speeds",
                                           "resistance_ratios", "initial_voltage", "initial_frequency",
                                           "initial_resistance_ratio", "ramp_time", "torque_limit",
                                           "current_limit", "rated_efficiency", "no_load_loss",
                                           "switch_off_time"}));
    EXPECT_EQ(schema.find("law")->choices, (std::vector<std::string>{"kloss", "linear", "catalogue", "table", "kloss_modified"}));
    EXPECT_EQ(schema.find("starter")->defaultText, "direct_on_line");
    EXPECT_EQ(schema.find("law")->defaultText, "kloss");
    EXPECT_EQ(schema.find("breakdown_ratio")->defaultValue, 2.2);
    EXPECT_EQ(schema.find("rated_torque")->unit, "N*m");
    EXPECT_EQ(schema.find("rated_speed")->unit, "rad/s");
    EXPECT_EQ(schema.find("linear_slope")->unit, "N*m*s/rad");
    EXPECT_TRUE(std::isinf(*schema.find("switch_off_time")->defaultValue));
    EXPECT_EQ(schema.find("current_limit")->unit, "A");
    EXPECT_EQ(schema.find("no_load_loss")->unit, "W");
    EXPECT_EQ(schema.find("rated_efficiency")->unit, "1");
}

TEST(InductionMotorRegistryTest, CrossCheckRejectsRatedSpeedNotBelowSynchronousNamingRatedSpeed) {
    ASSERT_TRUE(motorType().schema.crossCheck);
    EXPECT_NO_THROW(motorType().schema.crossCheck(motorSpec(kRatedSpeed, kSynchronousSpeed)));
    for (double ratedSpeed : {kSynchronousSpeed, 1.1 * kSynchronousSpeed}) {
        try {
            motorType().schema.crossCheck(motorSpec(ratedSpeed, kSynchronousSpeed));
            ADD_FAILURE() << "no SpecError for rated_speed " << ratedSpeed;
        } catch (const SpecError& e) {
            EXPECT_EQ(e.key(), "motor.rated_speed");
            EXPECT_EQ(e.where().line, 15) << "points at the rated_speed line";
        }
    }
}

TEST(InductionMotorRegistryTest, CrossCheckRejectsOnlyOneLinearCoefficientNamingIt) {
    ElementSpec e = motorSpec(kRatedSpeed, kSynchronousSpeed);
    e.params["linear_stall_torque"] = number(kPrintedM00);
    try {
        motorType().schema.crossCheck(e);
        ADD_FAILURE() << "no SpecError for M00 without b0";
    } catch (const SpecError& err) {
        EXPECT_EQ(err.key(), "motor.linear_stall_torque");
    }
    e.params["linear_slope"] = number(kPrintedB0);
    EXPECT_NO_THROW(motorType().schema.crossCheck(e));
}

TEST(InductionMotorRegistryTest, BuiltMotorDrivesItsShaftAndSchedulesTheSwitchOff) {
    Scene scene;
    const SimTK::Body::Rigid body(SimTK::MassProperties(
        1, SimTK::Vec3(0), SimTK::Inertia(kShaftInertia / 2, kShaftInertia / 2, kShaftInertia)));
    SimTK::MobilizedBody::Pin shaft(scene.matter().updGround(), SimTK::Transform(), body,
                                    SimTK::Transform());
    scene.addBody("motor_shaft", shaft);
    motorType().build(motorSpec(kRatedSpeed, kSynchronousSpeed), scene);
    scene.system().realizeTopology();
    SimTK::State state = scene.system().getDefaultState();
    test::setShaft(state, shaft, 0.0, kRatedSpeed);
    const SimTK::Force& force = scene.forces().getForce(scene.findForce("motor"));
    EXPECT_NEAR(test::torqueOn(scene.system(), force, state, shaft), kRatedTorque,
                kRoundingRelTolerance * kRatedTorque);

    ASSERT_EQ(scene.switchEvents().size(), 1u);
    const Scene::SwitchEvent& off = scene.switchEvents()[0];
    EXPECT_EQ(off.kind, Scene::SwitchEvent::Kind::DriveOff);
    EXPECT_EQ(off.time, 4.0);
    off.apply(state);
    EXPECT_EQ(test::torqueOn(scene.system(), force, state, shaft), 0.0);
}

}  // namespace
}  // namespace milldyn
