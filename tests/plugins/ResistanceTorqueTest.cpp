// Tests of ResistanceTorque (plugins/loads/ResistanceTorque.h). Expected values are
// worked out by hand in the comments, or computed here from the class
// comment's equations written out afresh (loadTorque below), or come from
// Simbody's own elements -- never from the element's output.
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
#include "plugins/loads/ResistanceTorque.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

using test::ShaftSystem;
using test::number;
using test::word;
using Law = ResistanceTorqueParams::Law;

constexpr double kShaftInertia = 0.1;    // kg*m^2
constexpr double kSmoothingSpeed = 0.01; // rad/s, the schema default
constexpr double kKgPerHour = 1.0 / 3600; // kg/s
constexpr double kKgPerMinute = 1.0 / 60; // kg/s

// Closed forms in double against the element's few operations: ulps.
constexpr double kRoundingRelTolerance = 1e-12;
// Accelerations from Simbody's solve of the same torques: ulps.
constexpr double kSolverRelTolerance = 1e-12;
// Energy and impulse of a 1 s coast-down, relative to the change: Simpson on
// 2000 intervals of a smooth decay (time constant J/b2 = 10 s) errs far
// below 1e-12, and the 0.5 ms sample grid keeps the integrator's steps far
// shorter than accuracy 1e-9 needs. 1e-10 leaves margin across platforms
// yet fails a torque or power wrong by 1 part in 1e10.
constexpr double kTrajectoryRelTolerance = 1e-10;

ResistanceTorqueParams speedLinear(double M0, double b2, double smoothing = kSmoothingSpeed) {
    ResistanceTorqueParams p;
    p.law = Law::SpeedLinear;
    p.constantTorque = M0;
    p.viscousCoefficient = b2;
    p.smoothingSpeed = smoothing;
    return p;
}

// Seed 003's feed law with the paper's a = 4.8 N*m (q in kg/min), belt
// u_p = 3.12, m = 1, q = 130 kg/h: the feed part on the motor shaft is
// 4.8·(130/60)/3.12 = 10.4/3.12 = 10/3 N*m; with M0 = 10 N*m idle the
// constant part is 40/3 N*m.
ResistanceTorqueParams paperFeed() {
    ResistanceTorqueParams p;
    p.law = Law::Feed;
    p.constantTorque = 10.0;
    p.feedRate = 130 * kKgPerHour;
    p.feedCoefficient = 4.8;
    p.feedExponent = 1.0;
    p.reductionRatio = 3.12;
    return p;
}

// The class comment's speed_linear law, written out again:
// Mc = M0·tanh(ω/ωs) + b2·ω.
double loadTorque(double M0, double b2, double omega) {
    return M0 * std::tanh(omega / kSmoothingSpeed) + b2 * omega;
}

// One ResistanceTorque on one shaft (kShaftInertia unless given).
struct LoadOnShaft : test::ElementOnShaft<ResistanceTorque, ResistanceTorqueParams> {
    explicit LoadOnShaft(const ResistanceTorqueParams& p, double J = kShaftInertia) : ElementOnShaft(p, J) {}
};

// ---- 1. force vs closed form ------------------------------------------------

TEST(ResistanceTorqueTest, SpeedLinearLawOpposesRotationWithConstantPlusViscousPart) {
    LoadOnShaft m(speedLinear(3.0, 0.02));
    // ω = 100 = 1e4·ωs: tanh = 1 in double; Mc = 3 + 0.02·100 = 5 N*m.
    EXPECT_NEAR(m.torqueAt(100.0), -5.0, kRoundingRelTolerance * 5);
    EXPECT_NEAR(m.torqueAt(-100.0), 5.0, kRoundingRelTolerance * 5);
}

TEST(ResistanceTorqueTest, ConstantPartFollowsTanhNearStandstill) {
    LoadOnShaft m(speedLinear(2.0, 0.0, 0.5));
    // ω = ωs: 2·tanh(1) = 2·0.76159415595576 = 1.52318831191153 N*m.
    EXPECT_NEAR(m.torqueAt(0.5), -1.5231883119115297, kRoundingRelTolerance * 2);
    EXPECT_NEAR(m.torqueAt(-0.5), 1.5231883119115297, kRoundingRelTolerance * 2);
    // ω = ωs/10: 2·tanh(0.1) = 2·0.0996679946249558 = 0.19933598924991 N*m,
    // close to the stiff viscous M0·ω/ωs = 0.2 the class comment promises.
    EXPECT_NEAR(m.torqueAt(0.05), -0.19933598924991164, kRoundingRelTolerance * 2);
    EXPECT_EQ(m.torqueAt(0.0), 0.0);
}

// 1 − tanh(x) = 2e^(−2x)/(1 + e^(−2x)), so at x = 10 the constant part is
// short of M0 by 2e^(−20) = 4.12e-9 of M0. (The class comment says "below
// 2e-9·M0" for ω > 10·ωs; that holds only from ω ≈ 10.35·ωs on.)
TEST(ResistanceTorqueTest, TenSmoothingSpeedsFromRestConstantPartIsShortByTwoExpMinusTwenty) {
    const double M0 = 100.0;
    LoadOnShaft m(speedLinear(M0, 0.0));
    const double shortfall = M0 + m.torqueAt(10 * kSmoothingSpeed);
    // 2e^(−20) is the shortfall to 1 part in 1e8 (the dropped e^(−20) in the
    // denominator), and M0 − |M| keeps ~8 digits of it; 1e-3 is loose for
    // both yet tells 4.12e-9 from the documented 2e-9.
    constexpr double kShortfallRelTolerance = 1e-3;
    const double expected = 2 * std::exp(-20.0) * M0;
    EXPECT_NEAR(shortfall, expected, kShortfallRelTolerance * expected);
}

TEST(ResistanceTorqueTest, WithoutConstantPartTorqueIsViscous) {
    LoadOnShaft m(speedLinear(0.0, 0.04));
    // 0.04·25 = 1 N*m.
    EXPECT_NEAR(m.torqueAt(25.0), -1.0, kRoundingRelTolerance);
    EXPECT_NEAR(m.torqueAt(-25.0), 1.0, kRoundingRelTolerance);
}

TEST(ResistanceTorqueTest, FeedLawAddsCoefficientTimesFeedPerMinuteOverReductionRatio) {
    LoadOnShaft m(paperFeed());
    // Far from standstill: Mc = 10 + 10/3 = 40/3 N*m (see paperFeed()).
    EXPECT_NEAR(m.torqueAt(50.0), -40.0 / 3, kRoundingRelTolerance * 40);
    EXPECT_NEAR(m.element->constantPart(), 40.0 / 3, kRoundingRelTolerance * 40);
}

TEST(ResistanceTorqueTest, FeedLawRaisesFeedPerMinuteToTheExponent) {
    ResistanceTorqueParams p;
    p.law = Law::Feed;
    p.feedRate = 2 * kKgPerMinute;
    p.feedCoefficient = 4.8;
    p.feedExponent = 2.0;
    p.reductionRatio = 3.2;
    p.viscousCoefficient = 0.05;
    LoadOnShaft m(p);
    // a·q^m/u = 4.8·2²/3.2 = 19.2/3.2 = 6 N*m, plus b2·ω = 0.05·100 = 5.
    EXPECT_NEAR(m.torqueAt(100.0), -11.0, kRoundingRelTolerance * 11);
}

TEST(ResistanceTorqueTest, SpeedLinearLawIgnoresFeedParameters) {
    ResistanceTorqueParams p = paperFeed();
    p.law = Law::SpeedLinear;
    LoadOnShaft m(p);
    EXPECT_NEAR(m.torqueAt(50.0), -10.0, kRoundingRelTolerance * 10);
}

TEST(ResistanceTorqueTest, FeedIsOffBeforeFeedStartTimeAndOnWhenOpened) {
    ResistanceTorqueParams p = paperFeed();
    p.feedStartTime = 1.5;
    LoadOnShaft m(p);
    EXPECT_FALSE(m.element->isFeeding(m.state));
    // Only the idle part, 10 N*m. Realize before opening the feed, so a
    // stale Dynamics cache would show below.
    EXPECT_NEAR(m.torqueAt(50.0), -10.0, kRoundingRelTolerance * 10);
    EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shaft), -10.0 / kShaftInertia,
                kSolverRelTolerance * 100);
    m.element->setFeeding(m.state, true);
    EXPECT_TRUE(m.element->isFeeding(m.state));
    EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shaft),
                -40.0 / 3 / kShaftInertia, kSolverRelTolerance * 140);
    EXPECT_NEAR(m.torqueAt(50.0), -40.0 / 3, kRoundingRelTolerance * 40);
}

TEST(ResistanceTorqueTest, FeedIsOnFromTheStartWhenStartTimeIsZero) {
    LoadOnShaft m(paperFeed());
    EXPECT_TRUE(m.element->isFeeding(m.state));
    EXPECT_NEAR(m.torqueAt(50.0), -40.0 / 3, kRoundingRelTolerance * 40);
}

// ---- 2. action = reaction ---------------------------------------------------

// The reaction +Mc goes to ground (the mill housing), which is not
// modelled. The shaft must see exactly −Mc through its pin.
TEST(ResistanceTorqueTest, PinCarriesResistanceBetweenGroundAndShaft) {
    LoadOnShaft m(speedLinear(3.0, 0.02));
    test::setShaft(m.state, m.shaft, 0.0, 100.0);
    m.rig.system().realize(m.state, SimTK::Stage::Acceleration);
    SimTK::Vector_<SimTK::SpatialVec> reactions;
    m.rig.matter().calcMobilizerReactionForces(m.state, reactions);
    EXPECT_NEAR(reactions[m.shaft.getMobilizedBodyIndex()][0][2], -5.0, kSolverRelTolerance * 5);
    EXPECT_NEAR(kShaftInertia * m.shaft.getOneUDot(m.state, SimTK::MobilizerUIndex(0)), -5.0,
                kSolverRelTolerance * 5);
}

// ---- 3. energy balance along a trajectory -----------------------------------

TEST(ResistanceTorqueTest, CoastDownLosesResistanceWorkAsKineticEnergyAndImpulseAsMomentum) {
    const double M0 = 2.0, b2 = 0.01, w0 = 50.0;
    LoadOnShaft m(speedLinear(M0, b2));
    test::setShaft(m.state, m.shaft, 0.0, w0);
    const SimTK::MobilizedBody shaft = m.shaft;
    auto power = [=](const SimTK::State& s) {
        const double w = test::shaftSpeed(s, shaft);
        return loadTorque(M0, b2, w) * w;
    };
    auto torque = [=](const SimTK::State& s) { return loadTorque(M0, b2, test::shaftSpeed(s, shaft)); };
    const double H0 = test::angularMomentumZ(m.rig.system(), m.state);
    std::vector<double> loss;
    const SimTK::State end =
        test::integrateWithQuadrature(m.rig.system(), m.state, 1.0, 2000, {power, torque}, loss);
    const double w1 = test::shaftSpeed(end, m.shaft);
    // About (2 + 0.01·40)/0.1 = 24 rad/s² for 1 s: well clear of standstill.
    EXPECT_GT(w1, 20.0);
    EXPECT_LT(w1, 30.0);
    const double energyLoss = 0.5 * kShaftInertia * (w0 * w0 - w1 * w1);
    EXPECT_NEAR(energyLoss, loss[0], kTrajectoryRelTolerance * energyLoss);
    const double momentumLoss = H0 - test::angularMomentumZ(m.rig.system(), end);
    EXPECT_NEAR(momentumLoss, kShaftInertia * (w0 - w1), kSolverRelTolerance * momentumLoss);
    EXPECT_NEAR(momentumLoss, loss[1], kTrajectoryRelTolerance * momentumLoss);
}

// Stopping from 5 rad/s under 2 N*m takes J·ω0/M0 = 0.25 s; inside |ω| < ωs
// the torque turns into the stiff viscous M0·ω/ωs, so the speed decays to
// rest (time constant J·ωs/M0 = 0.5 ms) and never changes sign. A Coulomb
// torque without the regularisation would chatter through zero.
TEST(ResistanceTorqueTest, CoastsToRestWithoutReversing) {
    LoadOnShaft m(speedLinear(2.0, 0.0));
    test::setShaft(m.state, m.shaft, 0.0, 5.0);
    const SimTK::MobilizedBody shaft = m.shaft;
    double minSpeed = 5.0;
    std::vector<double> none;
    const SimTK::State end = test::integrateWithQuadrature(
        m.rig.system(), m.state, 0.5, 100, {}, none,
        [&](const SimTK::State& s, const std::vector<double>&) {
            minSpeed = std::min(minSpeed, test::shaftSpeed(s, shaft));
        });
    // Reversal would show as a speed near −ωs. The integrator's absolute
    // error on u near rest is ~1e-9 rad/s: 1e-3·ωs = 1e-5 rad/s is far above
    // that and far below a reversal.
    const double kRestTolerance = 1e-3 * kSmoothingSpeed;
    EXPECT_GT(minSpeed, -kRestTolerance);
    EXPECT_LT(std::abs(test::shaftSpeed(end, m.shaft)), kRestTolerance);
}

// ---- 4. reduces to Simbody's built-ins --------------------------------------

// With M0 = 0 (and no feed) Mc = b2·ω: Force::MobilityLinearDamper(b2).
TEST(ResistanceTorqueTest, WithoutConstantPartMatchesMobilityLinearDamper) {
    const double b2 = 0.04;
    ResistanceTorqueParams feedClosed = paperFeed();
    feedClosed.constantTorque = 0;
    feedClosed.feedRate = 0;
    feedClosed.viscousCoefficient = b2;
    for (const ResistanceTorqueParams& p : {speedLinear(0.0, b2), feedClosed}) {
        LoadOnShaft m(p);
        ShaftSystem reference;
        SimTK::MobilizedBody::Pin alone = reference.addShaft(kShaftInertia);
        const SimTK::Force::MobilityLinearDamper damper(reference.forces(), alone,
                                                        SimTK::MobilizerUIndex(0), b2);
        SimTK::State refState = reference.defaultState();
        for (double w : {-30.0, -0.001, 0.0, 0.005, 1.0, 157.0}) {
            test::setShaft(m.state, m.shaft, 0.2, w);
            test::setShaft(refState, alone, 0.2, w);
            const double expected = test::shaftAcceleration(reference.system(), refState, alone);
            EXPECT_NEAR(test::shaftAcceleration(m.rig.system(), m.state, m.shaft), expected,
                        kSolverRelTolerance * (1 + std::abs(expected)))
                << "law " << static_cast<int>(p.law) << ", ω = " << w;
        }
    }
}

// ---- 5. bad parameters ------------------------------------------------------

void expectRejected(const ResistanceTorqueParams& p, const std::string& parameter) {
    ShaftSystem rig;
    const SimTK::MobilizedBody::Pin shaft = rig.addShaft(kShaftInertia);
    test::expectInvalidArgumentNaming(
        parameter, [&] { (void)std::make_unique<ResistanceTorque>(rig.forces(), shaft, p); });
}

TEST(ResistanceTorqueTest, NegativeConstantTorqueThrowsNamingConstantTorque) {
    ResistanceTorqueParams p = paperFeed();
    p.constantTorque = -1.0;
    expectRejected(p, "constant_torque");
}

TEST(ResistanceTorqueTest, NegativeViscousCoefficientThrowsNamingViscousCoefficient) {
    ResistanceTorqueParams p = paperFeed();
    p.viscousCoefficient = -0.01;
    expectRejected(p, "viscous_coefficient");
}

TEST(ResistanceTorqueTest, NegativeFeedRateThrowsNamingFeedRate) {
    ResistanceTorqueParams p = paperFeed();
    p.feedRate = -130 * kKgPerHour;
    expectRejected(p, "feed_rate");
}

TEST(ResistanceTorqueTest, NegativeFeedCoefficientThrowsNamingFeedCoefficient) {
    ResistanceTorqueParams p = paperFeed();
    p.feedCoefficient = -4.8;
    expectRejected(p, "feed_coefficient");
}

TEST(ResistanceTorqueTest, NonPositiveFeedExponentThrowsNamingFeedExponent) {
    for (double bad : {0.0, -2.5}) {
        ResistanceTorqueParams p = paperFeed();
        p.feedExponent = bad;
        expectRejected(p, "feed_exponent");
    }
}

TEST(ResistanceTorqueTest, NonPositiveReductionRatioThrowsNamingReductionRatio) {
    for (double bad : {0.0, -3.12}) {
        ResistanceTorqueParams p = paperFeed();
        p.reductionRatio = bad;
        expectRejected(p, "reduction_ratio");
    }
}

TEST(ResistanceTorqueTest, NonPositiveSmoothingSpeedThrowsNamingSmoothingSpeed) {
    for (double bad : {0.0, -0.01}) {
        ResistanceTorqueParams p = paperFeed();
        p.smoothingSpeed = bad;
        expectRejected(p, "smoothing_speed");
    }
}

TEST(ResistanceTorqueTest, NegativeFeedStartTimeThrowsNamingFeedStartTime) {
    ResistanceTorqueParams p = paperFeed();
    p.feedStartTime = -1.5;
    expectRejected(p, "feed_start_time");
}

TEST(ResistanceTorqueTest, NonFiniteParametersThrowNamingTheParameter) {
    struct Field { double ResistanceTorqueParams::*member; const char* name; };
    const Field fields[] = {
        {&ResistanceTorqueParams::constantTorque, "constant_torque"},
        {&ResistanceTorqueParams::viscousCoefficient, "viscous_coefficient"},
        {&ResistanceTorqueParams::feedRate, "feed_rate"},
        {&ResistanceTorqueParams::feedCoefficient, "feed_coefficient"},
        {&ResistanceTorqueParams::feedExponent, "feed_exponent"},
        {&ResistanceTorqueParams::reductionRatio, "reduction_ratio"},
        {&ResistanceTorqueParams::smoothingSpeed, "smoothing_speed"},
        {&ResistanceTorqueParams::feedStartTime, "feed_start_time"},
    };
    for (const Field& f : fields) {
        for (double bad : {std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
            ResistanceTorqueParams p = paperFeed();
            p.*f.member = bad;
            expectRejected(p, f.name);
        }
    }
}

TEST(ResistanceTorqueTest, MessageGivesTheOffendingValue) {
    ResistanceTorqueParams p = paperFeed();
    p.smoothingSpeed = -0.25;
    expectRejected(p, "-0.25");
}

// ---- 6. registry -----------------------------------------------------------



ElementSpec feedSpec() {
    ElementSpec e;
    e.type = "ResistanceTorque";
    e.name = "grinding";
    e.params["body"] = word("millstone");
    e.params["law"] = word("feed");
    e.params["constant_torque"] = number(10.0);
    e.params["viscous_coefficient"] = number(0.0);
    e.params["feed_rate"] = number(130 * kKgPerHour);
    e.params["feed_coefficient"] = number(4.8);
    e.params["feed_exponent"] = number(1.0);
    e.params["reduction_ratio"] = number(3.12);
    e.params["smoothing_speed"] = number(kSmoothingSpeed);
    e.params["feed_start_time"] = number(1.5);
    return e;
}

const ElementType& loadType() { return test::registeredType("ResistanceTorque"); }

TEST(ResistanceTorqueRegistryTest, SchemaListsTheDocumentedKeys) {
    ASSERT_NE(ElementRegistry::instance().find("ResistanceTorque"), nullptr);
    const ElementSchema& schema = loadType().schema;
    std::set<std::string> keys;
    for (const auto& p : schema.params) keys.insert(p.key);
    EXPECT_EQ(keys, (std::set<std::string>{"body", "law", "constant_torque", "viscous_coefficient",
                                           "feed_rate", "feed_coefficient", "feed_exponent",
                                           "reduction_ratio", "smoothing_speed",
                                           "feed_start_time", "schedule"}));
    EXPECT_EQ(schema.find("law")->choices, (std::vector<std::string>{"speed_linear", "feed"}));
    EXPECT_EQ(schema.find("law")->defaultText, "speed_linear");
    EXPECT_EQ(schema.find("feed_rate")->unit, "kg/s");
    EXPECT_EQ(schema.find("viscous_coefficient")->unit, "N*m*s/rad");
    EXPECT_EQ(schema.find("smoothing_speed")->defaultValue, kSmoothingSpeed);
    EXPECT_TRUE(schema.find("smoothing_speed")->minExclusive);
}

TEST(ResistanceTorqueRegistryTest, BuiltFeedLoadStartsEmptyAndSchedulesTheFeed) {
    Scene scene;
    const SimTK::Body::Rigid body(SimTK::MassProperties(
        1, SimTK::Vec3(0), SimTK::Inertia(kShaftInertia / 2, kShaftInertia / 2, kShaftInertia)));
    SimTK::MobilizedBody::Pin shaft(scene.matter().updGround(), SimTK::Transform(), body,
                                    SimTK::Transform());
    scene.addBody("millstone", shaft);
    loadType().build(feedSpec(), scene);
    scene.system().realizeTopology();
    SimTK::State state = scene.system().getDefaultState();
    test::setShaft(state, shaft, 0.0, 50.0);
    const SimTK::Force& force = scene.forces().getForce(scene.findForce("grinding"));
    EXPECT_NEAR(test::torqueOn(scene.system(), force, state, shaft), -10.0, kRoundingRelTolerance * 10);

    ASSERT_EQ(scene.switchEvents().size(), 1u);
    const Scene::SwitchEvent& feed = scene.switchEvents()[0];
    EXPECT_EQ(feed.kind, Scene::SwitchEvent::Kind::LoadOn);
    EXPECT_EQ(feed.time, 1.5);
    feed.apply(state);
    EXPECT_NEAR(test::torqueOn(scene.system(), force, state, shaft), -40.0 / 3,
                kRoundingRelTolerance * 40);
}

}  // namespace
}  // namespace milldyn
