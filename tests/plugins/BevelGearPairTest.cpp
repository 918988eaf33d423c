// Tests of BevelGearPair (issue 32 item 2): the torsional ratio, the tooth
// forces on both shafts against validation/oracles/BevelGearOracle (the
// textbook straight- and spiral-bevel formulas, per gear), the compliant
// mesh's natural frequency against the two-inertia formula.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "tests/driver/ReaderTestHelpers.h"
#include "validation/oracles/BevelGearOracle.h"

namespace milldyn {
namespace {

using test::contains;
using test::readErrorOf;
using test::readText;

namespace oc = milldyn::oracles;
const double kDeg = M_PI / 180;

/// Pinion (z1 = 17, r_m1 = 0.1 m) driven by a linear motor, wheel (z2 =
/// 53) braked by 5000 N*m.
std::string pair(const std::string& extra) {
    return "format_version: 1\nname: bevel\n"
           "bodies:\n"
           "  - {name: pinion, inertia: 1.5 kg*m^2, joint: {type: pin, parent: ground}}\n"
           "  - {name: wheel, inertia: 40 kg*m^2, joint: {type: pin, parent: ground, location: [1 m, 0 m, 0 m]}}\n"
           "elements:\n"
           "  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 3000 N*m,"
           " rated_speed: 1485 rpm, synchronous_speed: 1500 rpm}\n"
           "  - {type: BevelGearPair, name: bevel, bodies: [pinion, wheel], teeth: [17, 53], mean_pitch_radius: 0.1 m" +
           extra +
           "}\n"
           "  - {type: ResistanceTorque, name: load, body: wheel, constant_torque: 5000 N*m}\n"
           "scenario: {analysis: transient, end_time: 1 s}\n";
}

struct Steady {
    std::map<std::string, double> probe;
    double pinion = 0, wheel = 0;
};

Steady steadyOf(const std::string& text, LinearModel* lm = nullptr) {
    const ModelSpec spec = readText("bevel.yaml", text, {});
    auto scene = buildScene(spec);
    SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(s, SimTK::Stage::Acceleration);
    Steady out;
    for (const auto& p : scene->probes()) out.probe[p.name] = p.value(s);
    out.pinion = pinSpeed(s, scene->findBody("pinion")->mobod);
    out.wheel = pinSpeed(s, scene->findBody("wheel")->mobod);
    if (lm) *lm = linearizeScene(*scene, s, true, true);
    return out;
}

// ω2/ω1 = −z1/z2 (both axes away from the apex) or +z1/z2; the tangential
// force from the wheel's load, T_L = r_m2 F_t, r_m2 = r_m1 z2/z1.
TEST(BevelGearPair, RatioAndTangentialForce) {
    for (const std::string sense : {"", ", wheel_axis: towards_apex"}) {
        for (const std::string law : {"", ", law: compliant, mesh_stiffness: 1e9 N/m, mesh_damping: 1e4 N*s/m"}) {
            SCOPED_TRACE(sense + law);
            const Steady st = steadyOf(pair(sense + law));
            const double s = sense.empty() ? 1.0 : -1.0;
            EXPECT_GT(st.pinion, 150);
            EXPECT_NEAR(st.wheel / st.pinion, -s * 17.0 / 53.0, 1e-9);
            const double rm2 = 0.1 * 53 / 17;
            EXPECT_NEAR(st.probe.at("bevel.tangential_force"), 5000 / rm2, 1e-8 * 5000 / rm2);
            EXPECT_NEAR(st.probe.at("bevel.torque"), 5000 * 17.0 / 53.0, 1e-8 * 5000);
            EXPECT_NEAR(st.probe.at("bevel.mesh_frequency"), 17 * st.pinion / (2 * M_PI), 1e-9 * st.pinion);
        }
    }
}

// Forces on both shafts against the textbook per-gear formulas. The
// pinion turns at +ω about its +z (away from the apex): counterclockwise
// seen from its large end, and it drives.
TEST(BevelGearPair, ForcesAgainstTextbookStraightAndSpiral) {
    struct Case {
        double shaftDeg, spiralDeg;
        bool right;
    };
    for (const Case c : {Case{90, 0, true}, Case{70, 0, true}, Case{90, 35, true}, Case{90, 35, false},
                         Case{105, 30, true}, Case{105, 30, false}}) {
        char extra[200];
        std::snprintf(extra, sizeof extra, ", shaft_angle: %g deg, spiral_angle: %g deg%s", c.shaftDeg, c.spiralDeg,
                      c.spiralDeg > 0 ? (c.right ? ", hand: right" : ", hand: left") : "");
        SCOPED_TRACE(extra);
        const Steady st = steadyOf(pair(extra));
        oc::BevelPairModel m;
        m.pinionTeeth = 17;
        m.gearTeeth = 53;
        m.pinionMeanRadius = 0.1;
        m.shaftAngle = c.shaftDeg * kDeg;
        m.normalPressureAngle = 20 * kDeg;
        m.spiralAngle = c.spiralDeg * kDeg;
        m.pinionRightHand = c.right;
        m.pinionClockwiseFromLargeEnd = false;
        const oc::BevelLoads o = oc::bevelLoads(m, 5000 * 17.0 / 53.0);
        const double tol = 1e-8 * o.tangential;
        EXPECT_NEAR(st.probe.at("bevel.tangential_force"), o.tangential, tol);
        EXPECT_NEAR(st.probe.at("bevel.pinion_axial_force"), o.pinionThrust, tol);
        EXPECT_NEAR(st.probe.at("bevel.pinion_radial_force"), o.pinionSeparating, tol);
        EXPECT_NEAR(st.probe.at("bevel.wheel_axial_force"), o.gearThrust, tol);
        EXPECT_NEAR(st.probe.at("bevel.wheel_radial_force"), o.gearSeparating, tol);
    }
}

// Turning the pinion the other way (the motor's rotor backwards) reverses
// the spiral term: a right-hand pinion driving clockwise takes the upper
// signs.
TEST(BevelGearPair, SpiralTermFollowsTheSenseOfRotation) {
    // The motor turns a shaft that drives the pinion through an external
    // spur pair of ratio −1.
    std::string text = pair(", spiral_angle: 35 deg, hand: right");
    text = test::replacedIn(text, "elements:\n",
                            "  - {name: drive, inertia: 1 kg*m^2, joint: {type: pin, parent: ground, location: [-0.4 m, "
                            "0 m, 0 m]}}\nelements:\n  - {type: GearPair, name: spur, bodies: [drive, pinion], "
                            "pitch_radii: [0.2 m, 0.2 m]}\n");
    text = test::replacedIn(text, "body: pinion, law: linear", "body: drive, law: linear");
    const Steady st = steadyOf(text);
    ASSERT_LT(st.pinion, -150);
    oc::BevelPairModel m;
    m.pinionTeeth = 17;
    m.gearTeeth = 53;
    m.pinionMeanRadius = 0.1;
    m.shaftAngle = 90 * kDeg;
    m.normalPressureAngle = 20 * kDeg;
    m.spiralAngle = 35 * kDeg;
    m.pinionRightHand = true;
    m.pinionClockwiseFromLargeEnd = true;
    const oc::BevelLoads o = oc::bevelLoads(m, 5000 * 17.0 / 53.0);
    const double tol = 1e-8 * o.tangential;
    EXPECT_NEAR(st.probe.at("bevel.pinion_axial_force"), o.pinionThrust, tol);
    EXPECT_NEAR(st.probe.at("bevel.pinion_radial_force"), o.pinionSeparating, tol);
    EXPECT_NEAR(st.probe.at("bevel.wheel_axial_force"), o.gearThrust, tol);
    EXPECT_NEAR(st.probe.at("bevel.wheel_radial_force"), o.gearSeparating, tol);
    // RH driving clockwise pulls the pinion towards the apex at 35 deg spiral.
    EXPECT_LT(st.probe.at("bevel.pinion_axial_force"), 0);
}

// Compliant mesh: one elastic mode, k_t = k cos²α_t, referred to the mesh
// line: ω² = k_t (r_m1²/J1 + r_m2²/J2), as GearPair's.
TEST(BevelGearPair, CompliantMeshNaturalFrequency) {
    LinearModel lm;
    steadyOf(pair(", spiral_angle: 30 deg, law: compliant, mesh_stiffness: 1e9 N/m"), &lm);
    const double at = std::atan(std::tan(20 * kDeg) / std::cos(30 * kDeg));
    const double kt = 1e9 * std::cos(at) * std::cos(at), r1 = 0.1, r2 = 0.1 * 53 / 17;
    const double w = std::sqrt(kt * (r1 * r1 / 1.5 + r2 * r2 / 40));
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_NEAR(lm.naturalFrequencies[1], w, 1e-6 * w);
}

// ShaftBearings with `mesh:` (issue 32 item 2): the tooth forces reach both
// shafts' bearings. Pinion overhung (mean point at z 0, bearings at 0.15 and
// 0.45 m, mean point at 30 deg), wheel straddle-mounted (-0.3 and 0.4 m,
// mean point at z 0.1 m and 200 deg, its +z towards the apex, bearing 2
// locating), against the textbook tooth forces and the shafts' statics
// (validation/oracles/BevelGearOracle: bevelShaftReactions).
std::string withBearings(const std::string& extra) {
    std::string text = pair(", spiral_angle: 35 deg, wheel_axis: towards_apex" + extra);
    return test::replacedIn(
        text, "scenario:",
        "  - {type: ShaftBearings, name: pb, body: pinion, positions: [0.15 m, 0.45 m], mesh: bevel, mesh_position: "
        "0 m, mesh_angle: 30 deg}\n"
        "  - {type: ShaftBearings, name: wb, body: wheel, positions: [-0.3 m, 0.4 m], thrust_bearing: bearing_2, "
        "mesh: bevel, mesh_position: 0.1 m, mesh_angle: 200 deg}\nscenario:");
}

TEST(BevelGearPair, ShaftBearingsCarryTheToothForces) {
    for (const std::string hand : {"right", "left"}) {
        for (const std::string law : {"", ", law: compliant, mesh_stiffness: 1e9 N/m, mesh_damping: 1e4 N*s/m"}) {
            SCOPED_TRACE(hand + law);
            const Steady st = steadyOf(withBearings(", hand: " + hand + law));
            ASSERT_GT(st.pinion, 150);
            oc::BevelPairModel m;
            m.pinionTeeth = 17;
            m.gearTeeth = 53;
            m.pinionMeanRadius = 0.1;
            m.shaftAngle = 90 * kDeg;
            m.normalPressureAngle = 20 * kDeg;
            m.spiralAngle = 35 * kDeg;
            m.pinionRightHand = hand == "right";
            m.pinionClockwiseFromLargeEnd = false;
            const oc::BevelLoads f = oc::bevelLoads(m, 5000 * 17.0 / 53.0);
            // The pinion drives turning +z-wise: the force on it is along −e_θ;
            // the wheel (+z towards the apex) turns +z-wise too and is driven.
            ASSERT_GT(st.wheel, 0);
            const auto pin = oc::bevelShaftReactions({0.15, 0.45, 0, 0.1, 1, -1}, f.pinionThrust,
                                                     f.pinionSeparating, f.tangential);
            const auto whl = oc::bevelShaftReactions({-0.3, 0.4, 0.1, 0.1 * 53 / 17, -1, 1}, f.gearThrust,
                                                     f.gearSeparating, f.tangential);
            const double tol = 1e-8 * f.tangential;
            auto check = [&](const std::string& e, double th, const oc::BevelShaftReactions& o, int locating) {
                SCOPED_TRACE(e);
                const double c = std::cos(th), sn = std::sin(th);
                const double x1 = st.probe.at(e + ".bearing_1.x_ground"), y1 = st.probe.at(e + ".bearing_1.y_ground");
                const double x2 = st.probe.at(e + ".bearing_2.x_ground"), y2 = st.probe.at(e + ".bearing_2.y_ground");
                EXPECT_NEAR(x1 * c + y1 * sn, o.Ay, tol);
                EXPECT_NEAR(-x1 * sn + y1 * c, o.Az, tol);
                EXPECT_NEAR(x2 * c + y2 * sn, o.By, tol);
                EXPECT_NEAR(-x2 * sn + y2 * c, o.Bz, tol);
                EXPECT_NEAR(st.probe.at(e + ".bearing_1.radial_load"), o.radialA, tol);
                EXPECT_NEAR(st.probe.at(e + ".bearing_2.radial_load"), o.radialB, tol);
                EXPECT_NEAR(st.probe.at(e + ".bearing_" + std::to_string(locating) + ".axial_load"), o.thrust, tol);
                EXPECT_NEAR(st.probe.at(e + ".axial_load"), o.thrust, tol);
                EXPECT_EQ(st.probe.count(e + ".bearing_" + std::to_string(3 - locating) + ".axial_load"), 0u);
            };
            check("pb", 30 * kDeg, pin, 1);
            check("wb", 200 * kDeg, whl, 2);
            // Not zero: the loads are there only because of the mesh.
            EXPECT_GT(st.probe.at("pb.bearing_1.radial_load"), 0.5 * f.tangential);
        }
    }
}

// Without mesh: the shaft's pin reaction alone, which a pure torque leaves
// at zero: the tooth forces reach the bearings only through mesh:.
TEST(BevelGearPair, ShaftBearingsWithoutMeshSeeNoToothForce) {
    std::string text = withBearings(", hand: right");
    text = test::replacedIn(text, ", mesh: bevel, mesh_position: 0 m, mesh_angle: 30 deg", "");
    const Steady st = steadyOf(text);
    EXPECT_NEAR(st.probe.at("pb.bearing_1.radial_load"), 0.0, 1e-9);
    EXPECT_NEAR(st.probe.at("pb.axial_load"), 0.0, 1e-9);
    EXPECT_GT(st.probe.at("wb.bearing_1.radial_load"), 1000.0);
}

TEST(BevelGearPair, ShaftBearingsMeshRefusals) {
    const std::string ok = withBearings(", hand: right");
    auto error = [](const std::string& text) {
        const SpecError e = readErrorOf("b.yaml", text, {});
        return e.key() + ": " + e.what();
    };
    auto buildError = [](const std::string& text) {
        try {
            auto scene = buildScene(readText("b.yaml", text, {}));
            (void)scene;
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_TRUE(contains(error(test::replacedIn(ok, "mesh: bevel, mesh_position: 0 m, ", "mesh: bevel, ")),
                         "pb.mesh: needs mesh_position"));
    const std::string noMesh = error(test::replacedIn(ok, "mesh: bevel, mesh_position: 0 m, ", ""));
    EXPECT_TRUE(contains(noMesh, "pb.mesh_angle: only with mesh")) << noMesh;
    EXPECT_TRUE(contains(buildError(test::replacedIn(ok, "mesh: bevel, mesh_position: 0 m", "mesh: spur, mesh_position: 0 m")),
                         "no BevelGearPair named 'spur' listed before this element"));
    // Listed before the bevel pair: refused, saying so.
    const std::string pb = "  - {type: ShaftBearings, name: pb, body: pinion, positions: [0.15 m, 0.45 m], mesh: bevel, "
                           "mesh_position: 0 m, mesh_angle: 30 deg}\n";
    std::string early = test::replacedIn(ok, pb, "");
    early = test::replacedIn(early, "elements:\n", "elements:\n" + pb);
    EXPECT_TRUE(contains(buildError(early), "no BevelGearPair named 'bevel' listed before this element"));
    std::string other = test::replacedIn(ok, "  - {type: ShaftBearings, name: pb, body: pinion",
                                         "  - {type: ShaftBearings, name: pb, body: pinion2");
    other = test::replacedIn(other, "elements:\n", "  - {name: pinion2, inertia: 1 kg*m^2, joint: {type: pin, parent: "
                                                  "ground, location: [3 m, 0 m, 0 m]}}\nelements:\n");
    EXPECT_TRUE(contains(buildError(other), "'pinion2' is neither the pinion nor the wheel of bevel"));
}

TEST(BevelGearPair, RefusesBadInput) {
    EXPECT_TRUE(contains(readErrorOf("b.yaml", pair(", hand: left"), {}).what(), "has no hand"));
    EXPECT_TRUE(contains(readErrorOf("b.yaml", pair(", mesh_stiffness: 1e9 N/m"), {}).what(), "not used by law: rigid"));
    EXPECT_TRUE(contains(readErrorOf("b.yaml", pair(", shaft_angle: 180 deg"), {}).what(), "must be < 3.14"));
}

}  // namespace
}  // namespace milldyn
