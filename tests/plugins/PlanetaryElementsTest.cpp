// Tests of the planetary-mill elements: SegmentCharge, GearMesh,
// CarrierDrive, JournalFriction, JointReaction, and the model keys they
// need (gravity, mass_centre). Expected values are derived by hand in the
// comments (rigid-body mechanics of the configuration at hand) or by
// numerical integration of the segment's area, never from the elements'
// outputs nor from the seed-000 oracle (which judges them elsewhere).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "plugins/motors/CarrierDrive.h"
#include "plugins/transmissions/GearMesh.h"
#include "plugins/bearings/JournalFriction.h"
#include "plugins/charges/SegmentCharge.h"
#include "tests/driver/ReaderTestHelpers.h"

namespace milldyn {
namespace {

using test::readErrorOf;
using test::readText;

// A closed form against Simbody's O(n) solve of the same rigid bodies: ulps
// of the largest term.
constexpr double kRigidTolerance = 1e-10;

// Drum radius r, sun radius R, carrier arm R + r; drum shell J about its axis.
constexpr double kR = 0.10, kr = 0.05, kArm = kR + kr;  // m
constexpr double kDrumMass = 2.0;                       // kg
constexpr double kDrumInertia = 0.004;                  // kg*m^2
constexpr double kCarrierInertia = 0.02;                // kg*m^2

/// One carrier and one drum rolling on a sun gear; `extra` appended to the
/// elements, `gravity` the model's gravity line (may be empty).
std::string mill(const std::string& extra, const std::string& gravity = "", const std::string& rolling = "external",
                 double drumX = kArm) {
    return "format_version: 1\nname: test mill\n" + gravity +
           "bodies:\n"
           "  - {name: carrier, mass: 1 kg, inertia: 0.02 kg*m^2, joint: {type: pin, parent: ground}}\n"
           "  - {name: drum, mass: 2 kg, inertia: 0.004 kg*m^2, joint: {type: pin, parent: carrier, location: [" +
           std::to_string(drumX) +
           " m, 0 m, 0 m]}}\n"
           "elements:\n"
           "  - {type: GearMesh, name: mesh, carrier: carrier, planet: drum, fixed_pitch_radius: 0.1 m, "
           "planet_pitch_radius: 0.05 m, rolling: " +
           rolling + "}\n  - {type: JointReaction, name: RB, body: drum}\n" + extra +
           "scenario: {analysis: kinetostatic, angle_points: 1}\n";
}

std::string fmt(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

double probe(const Scene& scene, const SimTK::State& s, const std::string& name) {
    for (const auto& p : scene.probes())
        if (p.name == name) return p.value(s);
    ADD_FAILURE() << "no probe " << name;
    return NAN;
}

// ---- SegmentCharge: the segment's mass geometry ------------------------

/// Area, first moment (along the segment's axis) and polar second moment
/// about the centre of the segment of half-angle g of a unit disc, by
/// composite Simpson over the polar angle θ from the segment's axis: the
/// rays |θ| <= g leave the chord at ρ = c/cos θ (c = cos g) for the arc at 1,
///   A = ∫ (1 − c²/cos²θ)/2,  M = ∫ cos θ (1 − c³/cos³θ)/3,  I = ∫ (1 − c⁴/cos⁴θ)/4.
/// For g > π/2 the segment is the disc less the segment of π − g on the
/// other side. Smooth integrands: 4000 intervals give ~1e-14.
struct SegmentIntegrals { double area, firstMoment, polar; };
SegmentIntegrals integrateSegment(double g) {
    if (g > M_PI / 2) {
        const SegmentIntegrals other = integrateSegment(M_PI - g);
        return {M_PI - other.area, other.firstMoment, M_PI / 2 - other.polar};
    }
    const double c = std::cos(g);
    const int n = 4000;
    const double h = 2 * g / n;
    SegmentIntegrals out{0, 0, 0};
    for (int i = 0; i <= n; ++i) {
        const double t = -g + i * h, ct = std::cos(t);
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        out.area += w * (1 - std::pow(c / ct, 2)) / 2;
        out.firstMoment += w * ct * (1 - std::pow(c / ct, 3)) / 3;
        out.polar += w * (1 - std::pow(c / ct, 4)) / 4;
    }
    out.area *= h / 3;
    out.firstMoment *= h / 3;
    out.polar *= h / 3;
    return out;
}

TEST(SegmentCharge, MassCentroidAndInertiaMatchAreaIntegrals) {
    // (γ = π/2 exactly is the half disc, checked exactly below; the polar
    // integrand jumps at its ends there.)
    for (double g : {0.05, 0.4, 1.2, 2.3, 3.1}) {
        SegmentChargeParams p;
        p.drumRadius = 1;
        p.length = 1;
        p.bulkDensity = 1;
        p.halfAngle = g;
        SimTK::MultibodySystem sys;
        SimTK::SimbodyMatterSubsystem matter(sys);
        const SegmentCharge charge(matter, matter.getGround(), matter.getGround(), p);
        const SegmentIntegrals I = integrateSegment(g);
        EXPECT_NEAR(charge.calcMass(), I.area, 1e-10 * I.area) << "γ = " << g;
        EXPECT_NEAR(charge.calcCentroidDistance() * charge.calcMass(), I.firstMoment, 1e-10 * I.firstMoment)
            << "γ = " << g;
        EXPECT_NEAR(charge.calcAxisInertia(), I.polar, 1e-10 * I.polar) << "γ = " << g;
    }
}

TEST(SegmentCharge, HalfDiscValuesAndFillInverse) {
    // γ = π/2: area π/2, centroid 4/(3π), polar moment π/4 (unit disc).
    SegmentChargeParams p;
    p.drumRadius = 1;
    p.length = 1;
    p.bulkDensity = 1;
    p.halfAngle = M_PI / 2;
    SimTK::MultibodySystem sys;
    SimTK::SimbodyMatterSubsystem matter(sys);
    const SegmentCharge charge(matter, matter.getGround(), matter.getGround(), p);
    EXPECT_NEAR(charge.calcMass(), M_PI / 2, 1e-15);
    EXPECT_NEAR(charge.calcCentroidDistance(), 4 / (3 * M_PI), 1e-15);
    EXPECT_NEAR(charge.calcAxisInertia(), M_PI / 4, 1e-15);
    for (double fill : {0.01, 0.3, 0.5, 0.77, 1.0})
        EXPECT_NEAR(SegmentCharge::calcFillFraction(SegmentCharge::calcHalfAngleForFill(fill)), fill, 1e-14);
    EXPECT_NEAR(SegmentCharge::calcHalfAngleForFill(0.5), M_PI / 2, 1e-14);
}

TEST(SegmentCharge, RejectsImpossibleGeometry) {
    SimTK::MultibodySystem sys;
    SimTK::SimbodyMatterSubsystem matter(sys);
    SegmentChargeParams p;
    p.drumRadius = 0.05;
    p.length = 0.2;
    p.bulkDensity = 4800;
    p.halfAngle = 0;
    EXPECT_THROW(SegmentCharge(matter, matter.getGround(), matter.getGround(), p), std::invalid_argument);
    p.halfAngle = 4;
    EXPECT_THROW(SegmentCharge(matter, matter.getGround(), matter.getGround(), p), std::invalid_argument);
    p.halfAngle = 1;
    p.drumRadius = -1;
    EXPECT_THROW(SegmentCharge(matter, matter.getGround(), matter.getGround(), p), std::invalid_argument);
}

// ---- GearMesh ----------------------------------------------------------

TEST(GearMesh, StartUpForcesAndReactionFromRigidBodyMechanics) {
    // Carrier at rest, prescribed ε = 10 rad/s^2, no gravity, drum at +x.
    // Drum: absolute angular acceleration ε2 = κ ε, κ = (R + r)/r = 3; its
    // centre accelerates tangentially (+y) at ε (R + r). The gear's
    // tangential force F at the pitch point (B − r e_x) must turn it:
    // about B, the force F e_y at −r e_x has moment −r F, so −r F = J ε2
    // would make F negative: F = −J κ ε / r. The pin force P then closes
    // m a_B = P + F e_y + N e_x with N = |F| tan 20° pushing it outwards:
    //   P_x = −N,  P_y = m ε (R + r) − F.
    const double eps = 10;
    // The exponential law with t_p = τ = 1 s has ε0 = ω_y/(1 − e^−1).
    const double wy = eps * (1 - std::exp(-1.0));
    const ModelSpec s2 = readText("t.yaml",
                                  mill("  - {type: CarrierDrive, name: drive, body: carrier, steady_speed: " +
                                       fmt(wy) + " rad/s, acceleration_time: 1 s, time_constant: 1 s}\n"),
                                  {});
    auto scene = buildScene(s2);
    SimTK::State state = initialState(*scene, s2);
    scene->system().realize(state, SimTK::Stage::Acceleration);
    const double kappa = kArm / kr;
    const double F = -kDrumInertia * kappa * eps / kr;
    const double N = std::abs(F) * std::tan(20 * M_PI / 180);
    EXPECT_NEAR(probe(*scene, state, "mesh.tangential_force"), F, kRigidTolerance * std::abs(F));
    EXPECT_NEAR(probe(*scene, state, "mesh.separating_force"), N, kRigidTolerance * std::abs(F));
    EXPECT_NEAR(probe(*scene, state, "RB.on_drum_at_axis_x_ground"), -N, kRigidTolerance * std::abs(F));
    EXPECT_NEAR(probe(*scene, state, "RB.on_drum_at_axis_y_ground"), kDrumMass * eps * kArm - F,
                kRigidTolerance * std::abs(F));
    // The carrier's drive torque, by the power balance at rest: the reduced
    // inertia times ε, J_pr = J1 + m (R+r)^2 + J κ^2.
    const double Jpr = kCarrierInertia + kDrumMass * kArm * kArm + kDrumInertia * kappa * kappa;
    EXPECT_NEAR(probe(*scene, state, "drive.torque"), Jpr * eps, kRigidTolerance * Jpr * eps);
}

TEST(GearMesh, KeepsThePhaseExternalAndInternal) {
    // Carrier turned at a steady 10 rad/s for 0.3 s: the drum's absolute
    // angle is κ times the carrier's: κ = (R + r)/r = 3 external, and
    // −(R − r)/r = −1 for a drum inside a ring (R = 0.1, r = 0.05, arm 0.05).
    for (const std::string rolling : {"external", "internal"}) {
        const double arm = rolling == "external" ? kArm : kR - kr;
        const double kappa = rolling == "external" ? kArm / kr : -(kR - kr) / kr;
        std::string text = mill("  - {type: CarrierDrive, name: drive, body: carrier, law: steady, steady_speed: "
                                "10 rad/s}\n",
                                "", rolling, arm);
        text = test::replacedIn(text, "{name: carrier, mass: 1 kg,", "{name: carrier, initial_speed: 10 rad/s, mass: 1 kg,");
        text = test::replacedIn(text, "scenario: {analysis: kinetostatic, angle_points: 1}",
                                "scenario: {analysis: transient, end_time: 0.3 s, initial_state: file}");
        const ModelSpec spec = readText("t.yaml", text, {});
        auto scene = buildScene(spec);
        Simulation sim(*scene, IntegratorSpec{"RungeKuttaMerson", 1e-9, 0, {}});
        sim.initialize(initialState(*scene, spec));
        sim.run(0.3, 0.1, {});
        const SimTK::State& s = sim.state();
        const double carrier = scene->findBody("carrier")->mobod.getOneQ(s, SimTK::MobilizerQIndex(0));
        const double drumRelative = scene->findBody("drum")->mobod.getOneQ(s, SimTK::MobilizerQIndex(0));
        EXPECT_NEAR(carrier, 3.0, 1e-9) << rolling;
        EXPECT_NEAR(carrier + drumRelative, kappa * carrier, 1e-9) << rolling;
    }
}

TEST(GearMesh, RefusesAPlanetLargerThanItsRing) {
    const std::string text = mill("", "", "internal");
    const std::string tooBig = test::replacedIn(text, "planet_pitch_radius: 0.05 m", "planet_pitch_radius: 0.2 m");
    const SpecError e = readErrorOf("t.yaml", tooBig, {});
    EXPECT_EQ(e.key(), "mesh.planet_pitch_radius");
    EXPECT_NE(std::string(e.what()).find("r < R"), std::string::npos) << e.what();
}

// ---- CarrierDrive ------------------------------------------------------

TEST(CarrierDrive, ExponentialLawReachesTheSteadySpeedAtTheAccelerationTime) {
    CarrierDriveParams p;
    p.steadySpeed = 78.54;
    p.accelerationTime = 4.6;
    p.timeConstant = 1;
    const CarrierDrive d(p);
    // ε0 = ω_y/(1 − e^(−4.6)) = 79.34 (the paper's (24): 0.793 J_pr = 0.01 ε0 J_pr)
    EXPECT_NEAR(d.calcInitialAcceleration(), 78.54 / (1 - std::exp(-4.6)), 1e-12);
    EXPECT_NEAR(d.calcSpeed(4.6), 78.54, 1e-12);
    EXPECT_NEAR(d.calcAcceleration(std::log(100.0)), 0.01 * d.calcInitialAcceleration(), 1e-12);
    p.timeConstant = -1;
    EXPECT_THROW(CarrierDrive{p}, std::invalid_argument);
}

// ---- JournalFriction ---------------------------------------------------

TEST(JournalFriction, WheelUnderGravityDeceleratesAtItsWeightTimesFrictionArm) {
    // A wheel (mass centre on its pin) spinning at 20 rad/s under g: the
    // pin carries its weight m g whatever the friction, so
    // M = m g f d/2 (tanh = 1 to 1e-300 above 1 rad/s) and the wheel slows
    // at M/J: u(t) = 20 − M t/J, exactly, for both couplings.
    const double m = 3, J = 0.05, f = 0.1, d = 0.04, g = 9.80665;
    for (const std::string coupling : {"lagged", "iterated", "extrapolated"}) {
        const std::string text =
            "format_version: 1\nname: wheel\ngravity: [0, -9.80665 m/s^2, 0]\n"
            "bodies:\n  - {name: wheel, mass: 3 kg, inertia: 0.05 kg*m^2, initial_speed: 20 rad/s, joint: {type: "
            "pin}}\n"
            "elements:\n  - {type: JournalFriction, name: journal, body: wheel, friction_coefficient: 0.1, "
            "journal_diameter: 40 mm, reaction: " +
            coupling + "}\nscenario: {analysis: transient, end_time: 1 s, initial_state: file}\n";
        const ModelSpec spec = readText("t.yaml", text, {});
        auto scene = buildScene(spec);
        Simulation sim(*scene, IntegratorSpec{"RungeKuttaMerson", 1e-10, 0, {}});
        sim.initialize(initialState(*scene, spec));
        sim.run(1.0, 0.5, {});
        const double M = m * g * f * d / 2;
        EXPECT_NEAR(pinSpeed(sim.state(), scene->bodies().front().mobod), 20 - M / J, 1e-9) << coupling;
        EXPECT_NEAR(probe(*scene, sim.state(), "journal.load"), m * g, 1e-9 * m * g) << coupling;
    }
}

TEST(JournalFriction, OpposesRotationInBothDirectionsAndVanishesAtRest) {
    const std::string base =
        "format_version: 1\nname: wheel\ngravity: [0, -10 m/s^2, 0]\n"
        "bodies:\n  - {name: wheel, mass: 2 kg, inertia: 0.05 kg*m^2, initial_speed: SPEED, joint: {type: pin}}\n"
        "elements:\n  - {type: JournalFriction, name: journal, body: wheel, friction_coefficient: 0.2, "
        "journal_diameter: 50 mm}\nscenario: {analysis: kinetostatic, angle_points: 1, carrier_speed: SPEED}\n";
    // M = m g f d/2 = 2*10*0.2*0.025 = 0.1 N*m, applied against the motion:
    // journal.torque is what the journal takes from the wheel, + about +z
    // (every load's sign), so it has the speed's sign; the wheel gets −M.
    for (double speed : {-3.0, 0.0, 3.0}) {
        std::string text = base;
        for (auto pos = text.find("SPEED"); pos != std::string::npos; pos = text.find("SPEED"))
            text.replace(pos, 5, fmt(speed) + " rad/s");
        const ModelSpec spec = readText("t.yaml", text, {});
        const AnalysisResult r = runAnalysis(spec);
        double torque = NAN;
        for (std::size_t i = 0; i < r.columnNames.size(); ++i)
            if (r.columnNames[i] == "journal.torque") torque = r.rows[0][i];
        EXPECT_NEAR(torque, speed == 0 ? 0.0 : std::copysign(0.1, speed), 1e-12) << speed;
    }
}

// ---- Model keys: gravity, mass_centre ---------------------------------

TEST(PlanetaryModelKeys, MassCentreOffTheAxisNeedsMassAndParallelAxisInertia) {
    const std::string ok =
        "format_version: 1\nname: p\nbodies:\n"
        "  - {name: arm, mass: 1 kg, inertia: 0.02 kg*m^2, mass_centre: [0.1 m, 0 m, 0 m], joint: {type: pin}}\n"
        "scenario: {analysis: kinetostatic, angle_points: 1}\n";
    EXPECT_NO_THROW(readText("t.yaml", ok, {}));
    // 1 kg at 0.2 m needs more than 0.04 kg*m^2 about the axis.
    const SpecError e = readErrorOf("t.yaml", test::replacedIn(ok, "[0.1 m", "[0.2 m"), {});
    test::expectSpecError(e, "t.yaml", 4, 64, "arm.mass_centre", "parallel-axis");
    const SpecError e2 = readErrorOf("t.yaml", test::replacedIn(ok, "mass: 1 kg, ", ""), {});
    EXPECT_EQ(e2.key(), "arm.mass_centre");
}

TEST(PlanetaryModelKeys, PendulumUnderGravityHoldsWithTheStaticTorque) {
    // 1 kg at 0.1 m on a horizontal arm, held still by a steady drive at
    // 0 rad/s: the drive must supply m g l = 0.980665 N*m (counterclockwise,
    // lifting the arm at +x), and the pin carries m g upwards.
    const std::string text =
        "format_version: 1\nname: p\ngravity: [0, -9.80665 m/s^2, 0]\nbodies:\n"
        "  - {name: arm, mass: 1 kg, inertia: 0.02 kg*m^2, mass_centre: [0.1 m, 0 m, 0 m], joint: {type: pin}}\n"
        "elements:\n  - {type: CarrierDrive, name: hold, body: arm, law: steady, steady_speed: 0 rad/s}\n"
        "  - {type: JointReaction, name: RA, body: arm}\n"
        "scenario: {analysis: kinetostatic, angle_points: 1}\n";
    const ModelSpec spec = readText("t.yaml", text, {});
    auto scene = buildScene(spec);
    SimTK::State s = initialState(*scene, spec);
    scene->system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_NEAR(probe(*scene, s, "hold.torque"), 0.980665, 1e-12);
    EXPECT_NEAR(probe(*scene, s, "RA.on_arm_at_axis_y_ground"), 9.80665, 1e-12);
    EXPECT_NEAR(probe(*scene, s, "RA.on_arm_at_axis_x_ground"), 0.0, 1e-12);
}

TEST(PlanetaryModelKeys, AHeldChargeIsRefusedOutsideKinetostatics) {
    const std::string text =
        mill("  - {type: SegmentCharge, name: charge, drum: drum, drum_radius: 0.05 m, length: 0.2 m, bulk_density: "
             "4800 kg/m^3, motion: held, lag: 45 deg}\n");
    const std::string transient = test::replacedIn(text, "scenario: {analysis: kinetostatic, angle_points: 1}",
                                                   "scenario: {analysis: transient, end_time: 1 s}");
    const ModelSpec spec = readText("t.yaml", transient, {});
    try {
        runAnalysis(spec);
        ADD_FAILURE() << "a transient with a held charge was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "charge.motion");
        EXPECT_EQ(e.where().line, 9);
    }
    EXPECT_NO_THROW(runAnalysis(readText("t.yaml", text, {})));
}

}  // namespace
}  // namespace milldyn
