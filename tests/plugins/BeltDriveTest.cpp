// BeltDrive: span geometry, the rigid law's kinematics and tensions (T1 = 2 T2
// from the constraint's multiplier, pull in the drum's Simbody reaction), the
// elastic law's stick, Euler–Eytelwein cap and slip speed, and bad input.
// Expected values are hand-derived here, never read back from the code.

#include "plugins/transmissions/BeltDrive.h"

#include "driver/SceneBuilder.h"
#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace milldyn {
namespace {

using namespace SimTK;

const MobilizerQIndex kQ(0);
const MobilizerUIndex kU(0);

// The seed-002 Fig. 3 geometry: l_OA = 0.9 m, r0 = 0.05 m, r_A = 0.1 m.
constexpr double kArm = 0.9, kR0 = 0.05, kRA = 0.1;

TEST(BeltSpans, TangentPointsTouchBothSheavesAndSpansAreTangent) {
    const BeltSpans b = calcBeltSpans(Vec3(0), kR0, Vec3(kArm, 0, 0), kRA);
    EXPECT_NEAR(b.sinBeta, -0.05 / 0.9, 1e-15);
    EXPECT_NEAR(b.beta, std::asin(0.05 / 0.9), 1e-15);
    EXPECT_NEAR(b.wrapFixed + b.wrapDrum, 2 * M_PI, 1e-14);
    EXPECT_LT(b.wrapFixed, M_PI);  // the smaller sheave has the smaller wrap
    const double spanLength = std::sqrt(kArm * kArm - (kR0 - kRA) * (kR0 - kRA));
    for (int side = 0; side < 2; ++side) {
        const Vec3 onDrum = side ? b.trailPoint : b.leadPoint;
        const Vec3 onFixed = side ? b.trailFixedPoint : b.leadFixedPoint;
        const Vec3 dir = side ? b.trailDir : b.leadDir;
        EXPECT_NEAR((onDrum - Vec3(kArm, 0, 0)).norm(), kRA, 1e-15);
        EXPECT_NEAR(onFixed.norm(), kR0, 1e-15);
        const Vec3 span = onFixed - onDrum;
        EXPECT_NEAR(span.norm(), spanLength, 1e-14);
        EXPECT_NEAR((span / span.norm() - dir).norm(), 0, 1e-14);
        // Tangent: the span is perpendicular to both radii.
        EXPECT_NEAR(dot(span, onDrum - Vec3(kArm, 0, 0)), 0, 1e-15);
        EXPECT_NEAR(dot(span, onFixed), 0, 1e-15);
    }
    EXPECT_GT(b.leadPoint[1], 0);  // the lead span is on the side A moves to (+y)
    EXPECT_LT(b.trailPoint[1], 0);
}

TEST(BeltSpans, EqualSheavesGiveParallelSpansAndOversizeSheavesThrow) {
    const BeltSpans b = calcBeltSpans(Vec3(0), kRA, Vec3(0, kArm, 0), kRA);  // any direction of O→A
    EXPECT_EQ(b.sinBeta, 0.0);
    EXPECT_NEAR(b.wrapFixed, M_PI, 1e-15);
    EXPECT_NEAR((b.leadDir - Vec3(0, -1, 0)).norm(), 0, 1e-15);
    EXPECT_THROW(calcBeltSpans(Vec3(0), 1.2, Vec3(kArm, 0, 0), 0.2), std::invalid_argument);
}

/// Carrier on ground (speed prescribed), drum on the carrier at (l_OA, 0).
struct BeltFixture {
    MultibodySystem system;
    SimbodyMatterSubsystem matter{system};
    GeneralForceSubsystem forces{system};
    MobilizedBody::Pin carrier, drum;
    Force::MobilityConstantForce* drumTorque = nullptr;

    BeltFixture(double carrierSpeed, double torqueOnDrum) {
        carrier = MobilizedBody::Pin(matter.Ground(), Transform(),
                                     Body::Rigid(MassProperties(10, Vec3(0), UnitInertia(1))), Transform());
        drum = MobilizedBody::Pin(carrier, Transform(Vec3(kArm, 0, 0)),
                                  Body::Rigid(MassProperties(5, Vec3(0), UnitInertia(0.01))), Transform());
        Motion::Steady(carrier, carrierSpeed);
        Force::MobilityConstantForce(forces, drum, kU, torqueOnDrum);
    }
};

BeltDriveParams rigidParams(double r0 = kR0) {
    BeltDriveParams p;
    p.fixedSheaveRadius = r0;
    p.drumSheaveRadius = kRA;
    p.law = BeltLaw::Rigid;
    p.tightToSlack = 2;
    p.frictionCoefficient = 0.3;
    return p;
}

TEST(RigidBelt, DrumTurnsAtOmegaTimesOneMinusR0OverRA) {
    for (double r0 : {0.05, 0.1, 0.15}) {
        BeltFixture f(30, 0);
        auto* impl = new RigidBeltConstraint(f.matter, f.carrier, f.drum, rigidParams(r0));
        Constraint::Custom belt(impl);
        f.system.realizeTopology();
        State s = f.system.getDefaultState();
        f.carrier.setOneQ(s, kQ, 0.7);
        f.drum.setOneQ(s, kQ, impl->calcDrumAngle(0.7));
        f.system.prescribe(s);  // the carrier's speed, from its Motion
        f.system.projectU(s, 1e-14);  // the belt sets the drum's
        f.system.realize(s, Stage::Acceleration);
        const double absolute = f.carrier.getOneU(s, kU) + f.drum.getOneU(s, kU);
        EXPECT_NEAR(absolute, 30 * (1 - r0 / kRA), 1e-12) << "r0 = " << r0;
        EXPECT_NEAR(impl->calcDrumAbsoluteSpeed(s), absolute, 1e-15);
        EXPECT_NEAR(f.drum.getOneUDot(s, kU), 0, 1e-9);  // steady: no tension needed
        double lead = 1, trail = 1;
        impl->calcTensions(s, f.matter.getConstraint(belt.getConstraintIndex()), lead, trail);
        EXPECT_NEAR(lead, 0, 1e-6);
        EXPECT_NEAR(trail, 0, 1e-6);
        EXPECT_EQ(impl->calcInverseCentreOffset() == 0, r0 == kRA);
    }
}

TEST(RigidBelt, TorqueOnDrumGivesTightTwiceSlackAndLoadsTheDrumPin) {
    for (double torque : {500.0, -500.0}) {
        BeltFixture f(0, torque);
        auto* impl = new RigidBeltConstraint(f.matter, f.carrier, f.drum, rigidParams());
        Constraint::Custom belt(impl);
        f.system.realizeTopology();
        State s = f.system.getDefaultState();
        f.system.realize(s, Stage::Acceleration);
        EXPECT_NEAR(f.drum.getOneUDot(s, kU), 0, 1e-9);
        double lead = 0, trail = 0;
        impl->calcTensions(s, f.matter.getConstraint(belt.getConstraintIndex()), lead, trail);
        // The belt cancels the torque: r_A (T_lead − T_trail) = −torque, T_tight = 2 T_slack.
        EXPECT_NEAR(kRA * (lead - trail), -torque, 1e-9);
        const double slack = std::abs(torque) / kRA;
        EXPECT_NEAR(std::min(lead, trail), slack, 1e-9);
        EXPECT_NEAR(std::max(lead, trail), 2 * slack, 1e-9);
        // A counter-clockwise torque on the drum is held by the trailing span.
        EXPECT_EQ(trail > lead, torque > 0);
        // At rest without gravity the pin carries the belt's pull exactly.
        const BeltSpans b = calcBeltSpans(Vec3(0), kR0, Vec3(kArm, 0, 0), kRA);
        const Vec3 pull = lead * b.leadDir + trail * b.trailDir;
        Vector_<SpatialVec> reactions;
        f.matter.calcMobilizerReactionForces(s, reactions);
        const Vec3 pin = reactions[f.drum.getMobilizedBodyIndex()][1];
        EXPECT_NEAR((pin + pull).norm(), 0, 1e-8 * pull.norm()) << pin << " vs " << -pull;
        EXPECT_NEAR(pull[0], -3 * slack * std::cos(b.beta), 1e-8);  // (16): 3 T2 cos β
        EXPECT_NEAR(std::abs(pull[1]), slack * std::sin(b.beta), 1e-8);  // (17): T2 sin β
    }
}

BeltDriveParams elasticParams(double mu) {
    BeltDriveParams p = rigidParams();
    p.law = BeltLaw::Elastic;
    p.pretension = 10e3;
    p.spanStiffness = 1e6;
    p.spanDamping = 1e3;
    p.frictionCoefficient = mu;
    return p;
}

struct ElasticFixture : BeltFixture {
    ElasticBeltForce* impl;
    State state;
    explicit ElasticFixture(double mu) : BeltFixture(0, 0) {
        impl = new ElasticBeltForce(forces, carrier, drum, elasticParams(mu));
        Force::Custom force(forces, impl);
        system.realizeTopology();
        state = system.getDefaultState();
    }
};

TEST(ElasticBelt, StickingSpansFollowPretensionStiffnessAndDamping) {
    ElasticFixture f(0.5);
    f.drum.setOneQ(f.state, kQ, 0.002 / kRA);  // x = r_A q2 = 2 mm
    f.drum.setOneU(f.state, kU, 0.01 / kRA);   // x' = 10 mm/s
    f.system.realize(f.state, Stage::Acceleration);
    const auto t = f.impl->calcTensions(f.state);
    const double y = 1e6 * 0.002 + 1e3 * 0.01;  // 2010 N
    EXPECT_FALSE(t.slipping);
    EXPECT_EQ(t.slipSpeed, 0.0);
    EXPECT_NEAR(t.lead, 10e3 - y, 1e-9);
    EXPECT_NEAR(t.trail, 10e3 + y, 1e-9);
    // Torque on the drum r_A (T_lead − T_trail) = −2 r_A y: J q2'' with the
    // carrier held (J = 5 kg · 0.01 m²).
    EXPECT_NEAR(f.drum.getOneUDot(f.state, kU), -2 * kRA * y / 0.05, 1e-6);
    // Potential energy of the two springs, zero at rest.
    EXPECT_NEAR(f.impl->calcPotentialEnergy(f.state), 1e6 * 0.002 * 0.002, 1e-9);
}

TEST(ElasticBelt, EulerEytelweinCapsTheRatioAndSetsTheSlipSpeed) {
    const double mu = 0.2;
    ElasticFixture f(mu);
    const BeltSpans b = calcBeltSpans(Vec3(0), kR0, Vec3(kArm, 0, 0), kRA);
    const double E = std::exp(mu * (M_PI - 2 * b.beta));  // smaller wrap: the fixed sheave
    const double yMax = 10e3 * (E - 1) / (E + 1);
    f.drum.setOneQ(f.state, kQ, 0.02 / kRA);  // k x = 20 kN: far beyond the grip
    f.system.realize(f.state, Stage::Acceleration);
    const auto t = f.impl->calcTensions(f.state);
    EXPECT_TRUE(t.slipping);
    EXPECT_NEAR(t.trail / t.lead, E, 1e-12);
    EXPECT_NEAR(t.lead, 2 * 10e3 / (E + 1), 1e-9);  // the slack span keeps tension: it cannot go slack
    EXPECT_NEAR(t.y, yMax, 1e-9);
    // x_e' = (y_max − k x_e)/c with x' = 0: s' = −x_e'.
    EXPECT_NEAR(t.slipSpeed, (1e6 * 0.02 - yMax) / 1e3, 1e-9);
    EXPECT_NEAR(f.impl->calcGripRatio(f.state), E, 1e-12);
    // The slip is a state: its rate is the slip speed.
    EXPECT_NEAR(f.forces.getZDot(f.state)[0], t.slipSpeed, 1e-12);
    // Dissipation: damping c x_e'^2 ... here all power into the belt is 0
    // (no motion) and the elastic energy falls at 2 k x_e x_e'.
    EXPECT_GT(f.impl->calcDissipatedPower(f.state), 0);
    // The stretch the kinetostatic analysis sets.
    f.impl->setStretch(f.state, 0.001);
    EXPECT_NEAR(f.impl->calcStretch(f.state), 0.001, 1e-15);
}

const char* kModelText = R"(format_version: 1
name: belt
bodies:
  - {name: carrier, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}}
  - {name: drum, mass: 5 kg, inertia: 0.05 kg*m^2, joint: {type: pin, parent: carrier, location: [0.9 m, 0 m, 0 m]}}
elements:
  - {type: BeltDrive, name: belt, carrier: carrier, drum: drum, fixed_sheave_radius: 0.05 m, drum_sheave_radius: 0.1 m}
scenario: {analysis: kinetostatic, carrier_speed: 30 rad/s, angle_points: 3}
)";

TEST(BeltDriveElement, BuildsFromAModelFileAndRejectsBadInput) {
    const ModelSpec ok = test::readText("belt.yaml", kModelText, {});
    EXPECT_NO_THROW(buildScene(ok));
    // Sheaves that do not fit the arm: sin β > 1, located at the element.
    const ModelSpec tooBig = test::readText("belt.yaml", kModelText, {{"elements.belt.fixed_sheave_radius", "1.5 m"}});
    try {
        buildScene(tooBig);
        ADD_FAILURE() << "accepted sheaves larger than the arm";
    } catch (const SpecError& e) {
        EXPECT_TRUE(test::contains(e.what(), "sin β > 1")) << e.what();
    }
    // The elastic law needs its three constants.
    const SpecError e = test::readErrorOf("belt.yaml", kModelText, {{"elements.belt.law", "elastic"}});
    EXPECT_EQ(e.key(), "belt.pretension") << e.formatted();
    // A drum that is not on the carrier.
    const std::string onGround = test::replacedIn(kModelText, "parent: carrier", "parent: ground");
    EXPECT_THROW(buildScene(test::readText("belt.yaml", onGround, {})), SpecError);
    const SpecError neg = test::readErrorOf("belt.yaml", kModelText, {{"elements.belt.drum_sheave_radius", "-1 m"}});
    EXPECT_TRUE(test::contains(neg.formatted(), "drum_sheave_radius")) << neg.formatted();
}


// ------------------------------------------------------------- ShaftBelt

const char* kShaftBeltText = R"(format_version: 1
name: two shafts and a belt
bodies:
  - name: a
    inertia: 0.1 kg*m^2
    initial_speed: 100 rad/s
    joint: {type: pin, parent: ground}
  - name: b
    inertia: 0.1 kg*m^2
    joint: {type: pin, parent: ground, location: [0.5 m, 0 m, 0 m]}
elements:
  - {type: ShaftBelt, name: belt, driver: a, driven: b, driver_sheave_radius: 0.05 m, driven_sheave_radius: 0.1 m, pretension: 100 N, span_stiffness: 1e5 N/m, span_damping: 50 N*s/m, friction_coefficient: 0.5}
scenario: {analysis: transient, initial_state: file, end_time: 1 s}
integrator: {name: RungeKuttaMerson, accuracy: 1e-8}
outputs: {sample_interval: 1 ms, plots: false, peaks: [belt.tension_tight, belt.slipping, belt.slip]}
)";

TEST(ShaftBeltElement, SlipsAtTheEulerEytelweinRatioAndKeepsItsEnergy) {
    // A shaft spinning at 100 rad/s belted to one at rest: the belt slips
    // until the speeds match the ratio; while it slips T_tight/T_slack is
    // e^(μθ), θ = π − 2 asin((r2 − r1)/C) on the small sheave.
    const AnalysisResult r = runAnalysis(test::readText("shaft_belt.yaml", kShaftBeltText, {}));
    const double E = std::exp(0.5 * (M_PI - 2 * std::asin(0.05 / 0.5)));
    int slipping = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        if (r.value(i, "belt.slipping") == 1.0) {
            ++slipping;
            EXPECT_NEAR(r.value(i, "belt.tension_tight") / r.value(i, "belt.tension_slack"), E, 1e-9 * E);
            EXPECT_NEAR(r.value(i, "belt.tension_tight") + r.value(i, "belt.tension_slack"), 200.0, 1e-9);
        }
    EXPECT_GT(slipping, 10);
    EXPECT_EQ(r.find("peak.belt.slipping")->value, 1.0);
    EXPECT_GT(r.find("final.belt.slip")->value, 0.0);  // the driver's sheave ran ahead
    // The same span force F acts on both sheaves (−r1·F on a, +r2·F on b),
    // so J_a·ω_a·r2 + J_b·ω_b·r1 is conserved: once the belt grips at
    // ω_a = 2ω_b, ω_b = 0.1·100·0.1/(0.1·2·0.1 + 0.1·0.05) = 40 rad/s, and the
    // belt has turned ½·0.1·100² − ½·0.1·(80² + 40²) = 100 J into heat
    // (the span oscillation left after 0.7 s is within 1e-3).
    const std::size_t last = r.rows.size() - 1;
    EXPECT_NEAR(r.value(last, "b.speed"), 40.0, 40e-3);
    EXPECT_NEAR(r.value(last, "a.speed"), 2 * r.value(last, "b.speed"), 80e-3);
    EXPECT_NEAR(r.find("energy.belt")->value, 100.0, 0.1);
    EXPECT_LT(std::abs(r.find("energy_balance_relative")->value), 1e-6);
}

TEST(ShaftBeltElement, RejectsBadInputAtItsKey) {
    const SpecError same = test::readErrorOf("shaft_belt.yaml", kShaftBeltText, {{"elements.belt.driven", "a"}});
    EXPECT_EQ(same.key(), "belt.driven") << same.formatted();
    try {
        buildScene(test::readText("shaft_belt.yaml", kShaftBeltText, {{"elements.belt.driven_sheave_radius", "0.6 m"}}));
        ADD_FAILURE() << "accepted sheaves wider apart than the centre distance";
    } catch (const SpecError& e) {
        EXPECT_TRUE(test::contains(e.formatted(), "belt.driven_sheave_radius")) << e.formatted();
        EXPECT_TRUE(test::contains(e.what(), "no open belt")) << e.what();
    }
    const std::string onA = test::replacedIn(kShaftBeltText, "parent: ground, location", "parent: a, location");
    EXPECT_THROW(buildScene(test::readText("shaft_belt.yaml", onA, {})), SpecError);
    const SpecError neg = test::readErrorOf("shaft_belt.yaml", kShaftBeltText, {{"elements.belt.pretension", "-1 N"}});
    EXPECT_TRUE(test::contains(neg.formatted(), "pretension")) << neg.formatted();
    // outputs.peaks must name an output.
    try {
        buildScene(test::readText("shaft_belt.yaml", kShaftBeltText, {{"outputs.peaks", "[belt.tension_tigth]"}}));
        ADD_FAILURE() << "accepted a peak that names no output";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "outputs.peaks") << e.formatted();
        EXPECT_TRUE(test::contains(e.what(), "belt.tension_tight")) << e.what();  // the suggestion
    }
}

}  // namespace
}  // namespace milldyn
