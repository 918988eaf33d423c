// Tests of GearPair and ShaftBearings (issue 19 items 3-4). Expected values
// are derived by hand in the comments (statics of the configuration at
// hand, the rolling condition, the force triangle), never from the
// elements' outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "plugins/transmissions/GearPair.h"
#include "tests/driver/ReaderTestHelpers.h"

namespace milldyn {
namespace {

using test::contains;
using test::readErrorOf;
using test::readText;
using test::replacedIn;

constexpr double kDeg = M_PI / 180;

/// Pinion (r1 = 0.2 m) driven by a linear motor, wheel (r2 = 0.8 m) loaded
/// by 3000 N*m, pins 1 m apart on ground; pinion on two bearings.
std::string pair(const std::string& gearExtra, const std::string& wheelX = "1.0 m") {
    return "format_version: 1\nname: gear pair\n"
           "gravity: [0, -9.81 m/s^2, 0]\n"
           "bodies:\n"
           "  - {name: pinion, inertia: 2 kg*m^2, mass: 100 kg, joint: {type: pin, parent: ground}}\n"
           "  - {name: wheel, inertia: 50 kg*m^2, mass: 500 kg, joint: {type: pin, parent: ground, location: [" +
           wheelX +
           ", 0 m, 0 m]}}\n"
           "elements:\n"
           "  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 1000 N*m,"
           " rated_speed: 1450 rpm, synchronous_speed: 1500 rpm}\n"
           "  - {type: GearPair, name: mesh, bodies: [pinion, wheel], pitch_radii: [0.2 m, 0.8 m]" +
           gearExtra +
           "}\n"
           "  - {type: ResistanceTorque, name: load, body: wheel, constant_torque: 3000 N*m}\n"
           "  - {type: ShaftBearings, name: pb, body: pinion, positions: [-0.2 m, 0.5 m]}\n"
           "scenario: {analysis: transient, end_time: 1 s}\n";
}

struct Steady {
    std::map<std::string, double> probe;
    double pinionSpeed = 0, wheelSpeed = 0;
};

Steady steadyOf(const std::string& text) {
    const ModelSpec spec = readText("pair.yaml", text, {});
    auto scene = buildScene(spec);
    SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
    // Journal loads kept consistent with the steady state (fixed point).
    for (int i = 0; i < 50 && !scene->laggedValues().empty(); ++i) {
        const double change = refreshLaggedValues(*scene, s);
        s = solveSteadyState(*scene, s);
        if (change < 1e-14) break;
    }
    scene->system().realize(s, SimTK::Stage::Acceleration);
    Steady out;
    for (const auto& p : scene->probes()) out.probe[p.name] = p.value(s);
    out.pinionSpeed = pinSpeed(s, scene->findBody("pinion")->mobod);
    out.wheelSpeed = pinSpeed(s, scene->findBody("wheel")->mobod);
    return out;
}

/// The SpecError building `text` throws (the reader accepts it).
SpecError buildErrorOf(const std::string& text) {
    const ModelSpec spec = readText("pair.yaml", text, {});
    try {
        buildScene(spec);
    } catch (const SpecError& e) {
        return e;
    }
    ADD_FAILURE() << "no SpecError";
    return SpecError({}, "", "");
}

TEST(GearPair, RigidSpurSteadyForcesAndPinionBearingsFromStatics) {
    const Steady st = steadyOf(pair(", pressure_angle: 20 deg"));
    // Rolling: r1 ω1 + r2 ω2 = 0 (external gears turn opposite).
    EXPECT_NEAR(st.wheelSpeed, -0.2 / 0.8 * st.pinionSpeed, 1e-12 * st.pinionSpeed);
    // Wheel torque balance: F_t r2 = 3000 N*m (the pinion drives, F_t > 0).
    const double ft = 3000 / 0.8, fr = ft * std::tan(20 * kDeg);
    EXPECT_NEAR(st.probe.at("mesh.tangential_force"), ft, 1e-9 * ft);
    EXPECT_NEAR(st.probe.at("mesh.radial_force"), fr, 1e-9 * ft);
    EXPECT_NEAR(st.probe.at("mesh.normal_force"), ft / std::cos(20 * kDeg), 1e-9 * ft);
    EXPECT_NEAR(st.probe.at("mesh.torque"), ft * 0.2, 1e-9 * ft);
    // Pinion: the wheel (at +x) pushes it at P = (0.2, 0, 0) with −F_t
    // along y (resisting) and F_r along −x (separating); weight 981 N at
    // z = 0. Bearings at z = −0.2 and 0.5 (span 0.7): all loads at z = 0, so
    // bearing 2 takes 0.2/0.7 and bearing 1 0.5/0.7 of the total.
    const double sumX = fr, sumY = ft + 100 * 9.81;
    EXPECT_NEAR(st.probe.at("pb.bearing_1.x_ground"), sumX * 0.5 / 0.7, 1e-9 * sumY);
    EXPECT_NEAR(st.probe.at("pb.bearing_2.x_ground"), sumX * 0.2 / 0.7, 1e-9 * sumY);
    EXPECT_NEAR(st.probe.at("pb.bearing_1.y_ground"), sumY * 0.5 / 0.7, 1e-9 * sumY);
    EXPECT_NEAR(st.probe.at("pb.bearing_2.y_ground"), sumY * 0.2 / 0.7, 1e-9 * sumY);
    EXPECT_NEAR(st.probe.at("pb.axial_load"), 0, 1e-9 * sumY);
}

TEST(GearPair, HelicalMeshOffsetTiltsThePinionAndCompliantAgreesWithRigid) {
    const std::string helical = ", pressure_angle: 20 deg, helix_angle: 10 deg, axial_position: 0.3 m";
    const Steady rigid = steadyOf(pair(helical));
    const Steady comp = steadyOf(pair(helical + ", law: compliant, mesh_stiffness: 2e9 N/m, mesh_damping: 2e4 N*s/m"));
    const double ft = 3000 / 0.8, fr = ft * std::tan(20 * kDeg) / std::cos(10 * kDeg), fa = ft * std::tan(10 * kDeg);
    for (const Steady* st : {&rigid, &comp}) {
        EXPECT_NEAR(st->probe.at("mesh.tangential_force"), ft, 1e-8 * ft);
        EXPECT_NEAR(st->probe.at("mesh.radial_force"), fr, 1e-8 * ft);
        EXPECT_NEAR(st->probe.at("mesh.axial_force"), fa, 1e-8 * ft);
        // On the pinion at (0.2, 0, 0.3): (−fr, −ft, −fa); weight (0, −981)
        // at z = 0. Moments about the x axis: the y-loads at z (−ft at 0.3)
        // and, about y, the x-loads and the axial force's couple −x·F_z =
        // −0.2·(−fa). Bearing 2 (z = 0.5) from moments about bearing 1 (z = −0.2):
        //   x: R2x·0.7 + (−fr)(0.3 + 0.2) − 0.2·(−fa) = 0
        //   y: R2y·0.7 + (−ft)(0.5) + (−981)(0.2) = 0
        const double r2x = (fr * 0.5 - 0.2 * fa) / 0.7, r2y = (ft * 0.5 + 981 * 0.2) / 0.7;
        EXPECT_NEAR(st->probe.at("pb.bearing_2.x_ground"), r2x, 1e-8 * ft);
        EXPECT_NEAR(st->probe.at("pb.bearing_2.y_ground"), r2y, 1e-8 * ft);
        EXPECT_NEAR(st->probe.at("pb.bearing_1.x_ground"), fr - r2x, 1e-8 * ft);
        EXPECT_NEAR(st->probe.at("pb.bearing_1.y_ground"), ft + 981 - r2y, 1e-8 * ft);
        // The pinion is pushed along −z, its pin holds it: +fa.
        EXPECT_NEAR(st->probe.at("pb.axial_load"), fa, 1e-8 * ft);
    }
    // The compliant mesh deflects δ = F_t/(k cos² α_t) along the pitch line.
    const double alphaT = std::atan(std::tan(20 * kDeg) / std::cos(10 * kDeg));
    EXPECT_NEAR(comp.probe.at("mesh.mesh_deflection"), ft / (2e9 * std::pow(std::cos(alphaT), 2)), 1e-6 * ft / 2e9);
}

TEST(GearPair, InternalMeshTurnsTheRingTheSameWayAndPushesThePinionInwards) {
    // Ring r1 = 1.0 m about the origin, pinion r2 = 0.3 m at 0.7 m.
    const std::string text =
        "format_version: 1\nname: ring\n"
        "bodies:\n"
        "  - {name: ring, inertia: 80 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: pinion, inertia: 1 kg*m^2, joint: {type: pin, parent: ground, location: [0.7 m, 0 m, 0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 1000 N*m,"
        " rated_speed: 1450 rpm, synchronous_speed: 1500 rpm}\n"
        "  - {type: GearPair, name: mesh, bodies: [ring, pinion], pitch_radii: [1.0 m, 0.3 m], mesh: internal}\n"
        "  - {type: ResistanceTorque, name: load, body: ring, constant_torque: 2000 N*m}\n"
        "  - {type: ShaftBearings, name: pb, body: pinion, positions: [-0.5 m, 0.5 m]}\n"
        "scenario: {analysis: transient, end_time: 1 s}\n";
    const ModelSpec spec = readText("ring.yaml", text, {});
    auto scene = buildScene(spec);
    SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(s, SimTK::Stage::Acceleration);
    std::map<std::string, double> v;
    for (const auto& p : scene->probes()) v[p.name] = p.value(s);
    const double wRing = pinSpeed(s, scene->findBody("ring")->mobod);
    const double wPinion = pinSpeed(s, scene->findBody("pinion")->mobod);
    // r1 ω1 = r2 ω2: same direction, ratio 0.3.
    EXPECT_GT(wRing, 0);
    EXPECT_NEAR(wRing, 0.3 * wPinion, 1e-12 * wPinion);
    const double ft = 2000 / 1.0, fr = ft * std::tan(20 * kDeg);
    EXPECT_NEAR(std::abs(v.at("mesh.tangential_force")), ft, 1e-9 * ft);
    // The ring pushes the pinion towards the ring's centre (−x): the
    // pinion's bearings push back along +x with F_r in total; tangential
    // along y.
    EXPECT_NEAR(v.at("pb.bearing_1.x_ground") + v.at("pb.bearing_2.x_ground"), fr, 1e-9 * ft);
    EXPECT_NEAR(std::abs(v.at("pb.bearing_1.y_ground") + v.at("pb.bearing_2.y_ground")), ft, 1e-9 * ft);
}

TEST(GearPair, BacklashIsAForceFreeBandAlongTheLineOfAction) {
    const std::string text = pair(", law: compliant, mesh_stiffness: 1e9 N/m, backlash: 0.2 mm");
    const ModelSpec spec = readText("pair.yaml", text, {});
    auto scene = buildScene(spec);
    const auto* mesh = scene->findElement<GearPairForce>("mesh");
    ASSERT_NE(mesh, nullptr);
    SimTK::State s = scene->system().getDefaultState();
    const auto& pinion = scene->findBody("pinion")->mobod;
    const double cosA = std::cos(20 * kDeg);
    // δ_b = r1 q1 cos α: inside ±j/2 = ±0.1 mm no force.
    pinion.setOneQ(s, SimTK::MobilizerQIndex(0), 0.09e-3 / (0.2 * cosA));
    scene->system().realize(s, SimTK::Stage::Velocity);
    EXPECT_EQ(mesh->calcTangentialForce(s), 0.0);
    EXPECT_EQ(mesh->calcPotentialEnergy(s), 0.0);
    // Beyond: F_t = k (δ_b − j/2) cos α.
    pinion.setOneQ(s, SimTK::MobilizerQIndex(0), 0.3e-3 / (0.2 * cosA));
    scene->system().realize(s, SimTK::Stage::Velocity);
    EXPECT_NEAR(mesh->calcTangentialForce(s), 1e9 * 0.2e-3 * cosA, 1e-6);
    pinion.setOneQ(s, SimTK::MobilizerQIndex(0), -0.3e-3 / (0.2 * cosA));
    scene->system().realize(s, SimTK::Stage::Velocity);
    EXPECT_NEAR(mesh->calcTangentialForce(s), -1e9 * 0.2e-3 * cosA, 1e-6);
    EXPECT_NEAR(mesh->calcPotentialEnergy(s), 0.5 * 1e9 * 0.2e-3 * 0.2e-3, 1e-9);
}

TEST(GearPair, CompliantStartClosesItsEnergyBalanceAndReportsTheMeshFrequency) {
    const ModelSpec spec = readText(
        "pair.yaml",
        pair(", law: compliant, mesh_stiffness: 2e9 N/m, mesh_damping: 2e4 N*s/m, teeth: [20, 80]"), {});
    const AnalysisResult r = runAnalysis(spec);
    EXPECT_LT(std::abs(r.find("energy_balance_relative")->value), 1e-6);
    EXPECT_GT(r.find("energy_dissipated")->value, 0);
    // f_z = z1 n1 at the end (the last row): 20 · ω1/(2π).
    const auto& last = r.rows.back();
    int f = -1, w = -1;
    for (std::size_t i = 0; i < r.columnNames.size(); ++i) {
        if (r.columnNames[i] == "mesh.mesh_frequency") f = int(i);
        if (r.columnNames[i] == "pinion.speed") w = int(i);
    }
    ASSERT_GE(f, 0);
    ASSERT_GE(w, 0);
    EXPECT_NEAR(last[f], 20 * last[w] / (2 * M_PI), 1e-12 * last[f]);
}

TEST(GearPair, GeometryThatCannotMeshIsAnInputErrorWithBothNumbers) {
    const SpecError e = buildErrorOf(pair("", "1.01 m"));
    EXPECT_EQ(e.key(), "mesh.pitch_radii");
    EXPECT_TRUE(contains(e.what(), "1.01 m apart")) << e.what();
    EXPECT_TRUE(contains(e.what(), "centre distance of 1 m")) << e.what();
    // Within the stated tolerance (1e-4 of a) it meshes.
    EXPECT_NO_THROW(buildScene(readText("pair.yaml", pair("", "1.00005 m"), {})));
}

TEST(GearPair, KeysALawDoesNotUseAndBadTeethAreInputErrors) {
    EXPECT_EQ(readErrorOf("pair.yaml", pair(", mesh_stiffness: 1e9 N/m"), {}).key(), "mesh.mesh_stiffness");
    EXPECT_TRUE(contains(readErrorOf("pair.yaml", pair(", law: compliant"), {}).what(), "needs mesh_stiffness"));
    EXPECT_TRUE(contains(readErrorOf("pair.yaml", pair(", mesh: internal"), {}).what(), "ring (gear 1) larger"));
    // 2·0.2 m / 30 mm = 13.3 teeth.
    EXPECT_TRUE(contains(buildErrorOf(pair(", module: 30 mm")).what(), "not a whole number"));
    EXPECT_TRUE(contains(buildErrorOf(pair(", teeth: [20, 70]")).what(), "tooth ratio"));
    // Gears on different parents are not a GearPair.
    const std::string text = replacedIn(pair(""), "parent: ground, location: [1.0 m", "parent: pinion, location: [1.0 m");
    EXPECT_TRUE(contains(buildErrorOf(text).what(), "same parent")) << buildErrorOf(text).what();
}

TEST(ShaftBearings, RefusesOtherThanTwoBearingsAndFrictionWithoutDiameter) {
    EXPECT_TRUE(contains(
        readErrorOf("pair.yaml", replacedIn(pair(""), "[-0.2 m, 0.5 m]", "[-0.2 m, 0.1 m, 0.5 m]"), {}).what(),
        "statically indeterminate"));
    EXPECT_TRUE(contains(readErrorOf("pair.yaml", replacedIn(pair(""), "[-0.2 m, 0.5 m]", "[0.5 m, 0.5 m]"), {}).what(),
                         "different axial positions"));
    EXPECT_EQ(readErrorOf("pair.yaml",
                          replacedIn(pair(""), "positions: [-0.2 m, 0.5 m]",
                                     "positions: [-0.2 m, 0.5 m], friction_coefficient: 0.01"),
                          {})
                  .key(),
              "pb.journal_diameter");
}

TEST(ShaftBearings, FrictionPerBearingIsTheJournalLawOfItsLoadAndAddsUp) {
    const Steady st = steadyOf(replacedIn(pair(""), "positions: [-0.2 m, 0.5 m]",
                                          "positions: [-0.2 m, 0.5 m], friction_coefficient: 0.01, "
                                          "journal_diameter: 0.1 m, reaction: iterated"));
    for (int i = 1; i <= 2; ++i) {
        const std::string b = "pb.bearing_" + std::to_string(i);
        // M_i = f·|F_i|·d/2 at full speed (tanh = 1).
        EXPECT_NEAR(st.probe.at(b + ".friction_torque"), 0.01 * st.probe.at(b + ".radial_load") * 0.05, 1e-9);
    }
    // The applied torque uses the kept load |F1| + |F2|, converged here.
    EXPECT_NEAR(st.probe.at("pb.torque"),
                st.probe.at("pb.bearing_1.friction_torque") + st.probe.at("pb.bearing_2.friction_torque"), 1e-6);
}

/// Issue 20 item 1: `coupling: first_order` takes the bearings' load from
/// the frictionless mechanism (seed 000 eq 21's convention). Checked against
/// a second model without friction put in the same state: its bearing loads
/// are what the first-order friction must be computed from.
TEST(ShaftBearings, FirstOrderCouplingTakesTheLoadsOfTheFrictionlessMechanism) {
    const std::string withFriction = "positions: [-0.2 m, 0.5 m], friction_coefficient: 0.01, journal_diameter: 0.1 m";
    for (const std::string key : {"coupling: first_order", "reaction: first_order"}) {  // the key and its alias
        SCOPED_TRACE(key);
        const ModelSpec spec =
            readText("pair.yaml", replacedIn(pair(""), "positions: [-0.2 m, 0.5 m]", withFriction + ", " + key), {});
        auto scene = buildScene(spec);
        SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
        for (int i = 0; i < 50; ++i) {
            const double change = refreshLaggedValues(*scene, s);
            s = solveSteadyState(*scene, s);
            if (change < 1e-14) break;
        }
        refreshLaggedValues(*scene, s);
        scene->system().realize(s, SimTK::Stage::Acceleration);
        std::map<std::string, double> probe;
        for (const auto& p : scene->probes()) probe[p.name] = p.value(s);

        const ModelSpec frictionless = readText("pair.yaml", pair(""), {});
        auto scene0 = buildScene(frictionless);
        SimTK::State s0 = scene0->system().getDefaultState();
        s0.setTime(s.getTime());
        s0.updQ() = s.getQ();
        s0.updU() = s.getU();
        scene0->system().realize(s0, SimTK::Stage::Acceleration);
        double load0 = 0;
        for (const auto& p : scene0->probes())
            if (p.name == "pb.bearing_1.radial_load" || p.name == "pb.bearing_2.radial_load") load0 += p.value(s0);
        ASSERT_GT(load0, 1000);
        // M = f·(|F1| + |F2|)_frictionless·d/2 at full speed (tanh = 1).
        EXPECT_NEAR(probe.at("pb.torque"), 0.01 * load0 * 0.05, 1e-9 * load0);
        // The consistent loads include the friction's own effect: they differ, at first order in f.
        const double consistent = probe.at("pb.bearing_1.radial_load") + probe.at("pb.bearing_2.radial_load");
        EXPECT_GT(std::abs(consistent - load0), 1e-6 * load0);
        EXPECT_LT(std::abs(consistent - load0), 0.01 * load0);
    }
    // coupling: first_order leaves reaction: unused (a shipped model's
    // `reaction: extrapolated` stays valid under --set coupling=first_order);
    // an explicit consistent coupling with the first_order alias contradicts.
    EXPECT_NO_THROW(readText("pair.yaml",
                             replacedIn(pair(""), "positions: [-0.2 m, 0.5 m]",
                                        withFriction + ", coupling: first_order, reaction: extrapolated"),
                             {}));
    EXPECT_EQ(readErrorOf("pair.yaml",
                          replacedIn(pair(""), "positions: [-0.2 m, 0.5 m]",
                                     withFriction + ", coupling: consistent, reaction: first_order"),
                          {})
                  .key(),
              "pb.coupling");
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

TEST(GearPair, ToothMeshFrequencyMeetsTheMeshModeInTheResonanceMap) {
    // Pinion J1 = 2, wheel J2 = 50 kg*m^2, r = 0.2/0.8 m, k = 2e8 N/m, α = 20°:
    // one elastic mode, ω² = k cos²α r1² (1/J1 + (r2/r1)²... referred to the
    // pinion: J2' = J2 (r1/r2)² = 3.125, k_t = k cos²α r1² = 7.064e6 N*m/rad.
    std::string text = pair(", law: compliant, mesh_stiffness: 2e8 N/m, teeth: [20, 80]");
    text = replacedIn(text, "scenario: {analysis: transient, end_time: 1 s}",
                      "scenario: {analysis: resonance_map, rotor: wheel, speed_min: 1 rad/s, speed_max: 40 rad/s}");
    const AnalysisResult r = runAnalysis(readText("pair.yaml", text, {}));
    const double kt = 2e8 * std::pow(std::cos(20 * kDeg) * 0.2, 2);
    const double w = std::sqrt(kt * (1 / 2.0 + 1 / (50 * 0.0625)));
    // The mesh frequency is 20 teeth x the pinion's speed = 20 x 4 x the wheel's.
    EXPECT_NEAR(r.find("mesh.mesh_frequency.per_rotor_speed")->value, 80, 1e-9);
    EXPECT_NEAR(r.find("mesh.mesh_frequency.meets_mode_1_at_rotor_speed")->value, w / 80, 1e-6 * w / 80);
    // Without a load and without a rotor the map has nothing to sweep.
    const std::string none = replacedIn(text, "rotor: wheel, ", "");
    EXPECT_TRUE(contains(readErrorOf("pair.yaml", none, {}).what(), "rotor body"));
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

TEST(GearMesh, PitchRadiiThatDoNotFitThePinDistanceAreAnInputError) {
    // Issue 20 item 9: sun R = 0.1 m, planet r = 0.05 m need the planet's pin
    // 0.15 m from the carrier axis; at 0.16 m they cannot mesh.
    auto text = [](const std::string& x) {
        return "format_version: 1\nname: planet\n"
               "bodies:\n"
               "  - {name: carrier, inertia: 0.02 kg*m^2, joint: {type: pin, parent: ground}}\n"
               "  - {name: drum, inertia: 0.004 kg*m^2, joint: {type: pin, parent: carrier, location: [" +
               x +
               ", 0 m, 0 m]}}\n"
               "elements:\n"
               "  - {type: GearMesh, name: mesh, carrier: carrier, planet: drum, fixed_pitch_radius: 0.1 m,"
               " planet_pitch_radius: 0.05 m}\n"
               "scenario: {analysis: transient, end_time: 1 s}\n";
    };
    const SpecError e = buildErrorOf(text("0.16 m"));
    EXPECT_EQ(e.key(), "mesh.planet_pitch_radius");
    EXPECT_TRUE(contains(e.what(), "0.16 m apart")) << e.what();
    EXPECT_TRUE(contains(e.what(), "centre distance of 0.15 m")) << e.what();
    EXPECT_NO_THROW(buildScene(readText("planet.yaml", text("0.15 m"), {})));
}

}  // namespace
}  // namespace milldyn
