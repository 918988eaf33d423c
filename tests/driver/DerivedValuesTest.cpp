// Issue 20 item 4: the intermediates the papers print, read the way a user
// reads them (`milldyn info --json`, "derived", full precision), each against
// its closed form written here from the paper's equation, not from the model.
#include "driver/Cli.h"
#include "tests/driver/SetArgs.h"
#include "validation/oracles/PlanetaryBeltOracle.h"
#include "validation/oracles/PlanetaryGearOracle.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";
constexpr double kRpm = M_PI / 30;

/// `milldyn info MODEL --json [args]`'s "derived" object.
nlohmann::json derivedOf(const std::string& model, std::vector<std::string> args = {}) {
    std::vector<std::string> all = {"info", model, "--json"};
    all.insert(all.end(), args.begin(), args.end());
    std::ostringstream out, err;
    const int code = runCli(all, out, err);
    EXPECT_EQ(code, 0) << err.str();
    if (code != 0) return nlohmann::json::object();
    return nlohmann::json::parse(out.str()).at("derived");
}

double valueOf(const nlohmann::json& derived, const std::string& name) {
    if (!derived.contains(name)) {
        ADD_FAILURE() << "no derived value " << name << " in " << derived.dump();
        return std::nan("");
    }
    return derived.at(name).at("value").get<double>();
}

/// Shafts a (2 kg*m^2) and b (50 kg*m^2) on pins 1 m apart, with `elements`.
std::string twoShaftModel(const std::string& tag, const std::string& elements) {
    const std::string file = testing::TempDir() + "/milldyn_derived_" + tag + ".yaml";
    std::ofstream(file) << "format_version: 1\nname: two shafts\n"
                           "bodies:\n"
                           "  - {name: a, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}\n"
                           "  - {name: b, inertia: 50 kg*m^2, joint: {type: pin, parent: ground,"
                           " location: [1.0 m, 0 m, 0 m]}}\n"
                        << elements << "scenario: {analysis: transient, end_time: 1 s}\n";
    return file;
}

TEST(DerivedValues, BurrMillReducedInertiaIsJ1PlusJ2AndTheLinearLawIsAsPrinted) {
    const nlohmann::json d = derivedOf(kModels + "burr_mill_5p5kW_idle.yaml");
    // Seed 003: everything reduced to the motor shaft, belt ratio 1 in the
    // model: J1 + J2 = 190.7e-4 + 982.4e-4 kg*m^2 (the (J1 + J2) of eqs 12, 14).
    EXPECT_NEAR(valueOf(d, "motor_shaft.reduced_inertia"), 190.7e-4 + 982.4e-4, 1e-12);
    EXPECT_NEAR(valueOf(d, "millstone.reduced_inertia"), 190.7e-4 + 982.4e-4, 1e-12);
    // The kloss model still reports the linear branch: the printed M00, b0.
    EXPECT_EQ(valueOf(d, "motor.linear_stall_torque"), 1010.0);
    EXPECT_EQ(valueOf(d, "motor.linear_slope"), 6.428);
    // Without the printed values, eq (4) from the nameplate.
    const nlohmann::json n = derivedOf(kModels + "burr_mill_5p5kW_idle.yaml",
                                       {"--set", "elements.motor.linear_stall_torque=0 N*m", "--set",
                                        "elements.motor.linear_slope=0 N*m*s/rad"});
    const double Mn = 36.3, wc = 1500 * kRpm, wn = 1446 * kRpm;
    EXPECT_NEAR(valueOf(n, "motor.linear_stall_torque"), Mn * wc / (wc - wn), 1e-9 * Mn * wc / (wc - wn));
    EXPECT_NEAR(valueOf(n, "motor.linear_slope"), Mn / (wc - wn), 1e-9 * Mn / (wc - wn));
    EXPECT_NEAR(valueOf(n, "motor.rated_slip"), (wc - wn) / wc, 1e-15);
}

TEST(DerivedValues, RollCrusherReducedInertiaThroughTheReducerRatio) {
    // Seed 004's I0 = I1 + I with the rotor referred through u = 125, and
    // the same train referred to the rotor; the linear law's γ = b0 (eq 1, 15).
    const nlohmann::json d = derivedOf(kModels + "roll_crusher.yaml", {"--set", "fidelity.level=2-mass"});
    const double I1 = 3.5, I = 639, u = 125;
    EXPECT_NEAR(valueOf(d, "motor.reduced_inertia"), I1 + I / (u * u), 1e-12);
    EXPECT_NEAR(valueOf(d, "rotor.reduced_inertia"), (I1 + I / (u * u)) * u * u, 1e-8);
    const double Mn = 893.2, w0 = 600 * kRpm, wn = 588 * kRpm;
    EXPECT_NEAR(valueOf(d, "drive.linear_slope"), Mn / (w0 - wn), 1e-9 * Mn / (w0 - wn));
    EXPECT_NEAR(valueOf(d, "drive.linear_stall_torque"), Mn * w0 / (w0 - wn), 1e-9 * Mn * w0 / (w0 - wn));
}

TEST(DerivedValues, PlanetaryMillReducedInertiaIsTheCorrectedJprOfEq1) {
    // Seed 000 eq (1) with the carrier counted once (PHYSICS.md), the
    // charges hanging, for docs/planetary_gear.md's free parameters.
    namespace oc = milldyn::oracles;
    oc::PlanetaryGearParameters p;
    p.drumRadius = 0.05;
    p.drumLength = 0.2;
    p.wallThickness = 0.004;
    p.shellDensity = 7850;
    p.chargeDensity = 4800;
    p.sunRadius = 0.10;
    p.carrierMass = 2;
    p.carrierJournalDiameter = 0.025;
    p.drumJournalDiameter = 0.020;
    p.fillHalfAngle = M_PI / 2;
    p.lagAngle = M_PI / 2;
    const double Jpr = oc::PlanetaryGearOracle(p).calcReducedInertia(0.0);  // (1), the start-up
    const nlohmann::json d = derivedOf(kModels + "planetary_gear_100x200.yaml");
    EXPECT_NEAR(valueOf(d, "carrier.reduced_inertia"), Jpr, 1e-7 * Jpr);
    // Referred to a drum: divided by κ² = ((R + r)/r)².
    const double kappa = (0.10 + 0.05) / 0.05;
    EXPECT_NEAR(valueOf(d, "drum1.reduced_inertia"), Jpr / (kappa * kappa), 1e-7 * Jpr / (kappa * kappa));
}

TEST(DerivedValues, GearPairReducedInertiaIsJ1PlusJ2TimesTheRatioSquared) {
    const std::string file = twoShaftModel("pair", "elements:\n  - {type: GearPair, name: mesh, bodies: [a, b], "
                                                   "pitch_radii: [0.2 m, 0.8 m]}\n");
    const nlohmann::json d = derivedOf(file);
    // J1 + J2 (r1/r2)² on the pinion, times (r2/r1)² on the wheel.
    EXPECT_NEAR(valueOf(d, "a.reduced_inertia"), 2 + 50 * 0.0625, 1e-12);
    EXPECT_NEAR(valueOf(d, "b.reduced_inertia"), (2 + 50 * 0.0625) * 16, 1e-10);
    EXPECT_NEAR(std::abs(valueOf(d, "mesh.ratio")), 4.0, 1e-15);
}

TEST(DerivedValues, TwoIndependentDrivesHaveNoReducedInertiaAndSaySo) {
    const std::string file = twoShaftModel("two", "");
    const nlohmann::json d = derivedOf(file);
    EXPECT_FALSE(d.contains("a.reduced_inertia")) << d.dump();
    std::ostringstream out, err;
    ASSERT_EQ(runCli({"info", file}, out, err), 0) << err.str();
    EXPECT_NE(out.str().find("2 independent motions, not one rigid train"), std::string::npos) << out.str();
}

// Issue 20 item 3 (docs/reproducing-papers.md, every seed's intermediates):
// the values added for it, on parameters changed by --set.

using testing_helpers::setArgs;

// Seed 002 eqs (1)-(8): the criteria, the belt angle, the drum's speed ratio
// and its instantaneous centre, on an arm and sheaves the paper did not use,
// against the oracle's.
TEST(DerivedValues, Seed002CriteriaAndBeltKinematicsOnANewMill) {
    const nlohmann::json d = derivedOf(kModels + "planetary_belt_200x1000.yaml",
                                       setArgs({"bodies.drum1.joint.location=[0.75 m, 0 m, 0 m]",
                                                "elements.belt1.fixed_sheave_radius=0.06 m",
                                                "elements.belt1.drum_sheave_radius=0.12 m"}));
    oracles::PlanetaryBeltGeometry g;
    g.drumRadius = 0.1;
    g.drumSheaveRadius = 0.12;
    g.fixedSheaveRadius = 0.06;
    g.carrierArm = 0.75;
    const oracles::PlanetaryBeltCriteria c = oracles::criteriaFromGeometry(g);
    const oracles::PlanetaryBeltKinematics kin = oracles::calcKinematics(g, 1.0);
    EXPECT_NEAR(valueOf(d, "belt1.arm"), 0.75, 1e-15);
    EXPECT_NEAR(valueOf(d, "belt1.criterion_k"), c.k, 1e-15);  // 0.12/0.87
    EXPECT_NEAR(valueOf(d, "belt1.criterion_c"), c.c, 1e-15);  // 0.5
    EXPECT_NEAR(valueOf(d, "belt1.sin_belt_angle"), oracles::calcSinBeltAngle(g), 1e-15);  // 0.08
    EXPECT_NEAR(valueOf(d, "belt1.drum_speed_ratio"), kin.drumRate, 1e-15);                 // ω/Ω = 0.5
    ASSERT_TRUE(kin.hasInstantaneousCentre);
    EXPECT_NEAR(valueOf(d, "belt1.instant_centre_distance"), kin.centreOffsetFromA, 1e-14);  // −1.5 m
    // belt2 keeps the shipped mill: k = 0.1, c = 0.5 (the Fig. 3 case).
    EXPECT_NEAR(valueOf(d, "belt2.criterion_k"), 0.1, 1e-15);
    EXPECT_NEAR(valueOf(d, "belt2.criterion_c"), 0.5, 1e-15);
}

TEST(DerivedValues, Seed002NoInstantCentreWhenTheDrumTranslates) {
    // c = 1: ω = 0, l_AD infinite (eq 4): no value rather than inf.
    const nlohmann::json d =
        derivedOf(kModels + "planetary_belt_200x1000.yaml", setArgs({"elements.belt1.fixed_sheave_radius=0.1 m"}));
    EXPECT_EQ(valueOf(d, "belt1.drum_speed_ratio"), 0.0);
    EXPECT_FALSE(d.contains("belt1.instant_centre_distance")) << d.dump();
}

// Seed 000, the start's initial acceleration ε0 (Fig. 6): ω(t_p) = ω_y for
// ε = ε0 e^(−t), so ε0 = ω_y/(1 − e^(−t_p)).
TEST(DerivedValues, Seed000InitialAccelerationOnANewStart) {
    const double wy = 600 * kRpm;
    const nlohmann::json d =
        derivedOf(kModels + "planetary_gear_100x200.yaml",
                  setArgs({"elements.drive.steady_speed=600 rpm", "elements.drive.acceleration_time=2.5 s"}));
    EXPECT_NEAR(valueOf(d, "drive.initial_acceleration"), wy / (1 - std::exp(-2.5)), 1e-12 * wy);
    // Another time constant: ε0 = ω_y/(τ (1 − e^(−t_p/τ))).
    const nlohmann::json d2 = derivedOf(kModels + "planetary_gear_100x200.yaml",
                                        setArgs({"elements.drive.steady_speed=600 rpm",
                                                 "elements.drive.acceleration_time=2.5 s",
                                                 "elements.drive.time_constant=0.5 s"}));
    EXPECT_NEAR(valueOf(d2, "drive.initial_acceleration"), wy / (0.5 * (1 - std::exp(-5.0))), 1e-12 * wy);
}

// Seed 000 eqs (4), (15): κ = ω2/ω1 = (R + r)/r, on gears that still fit
// the shipped arm R + r = 0.15 m.
TEST(DerivedValues, Seed000SpeedRatioKappaOnNewGears) {
    const nlohmann::json d = derivedOf(
        kModels + "planetary_gear_100x200.yaml",
        setArgs({"elements.mesh1.fixed_pitch_radius=0.11 m", "elements.mesh1.planet_pitch_radius=0.04 m"}));
    EXPECT_NEAR(valueOf(d, "mesh1.speed_ratio"), (0.11 + 0.04) / 0.04, 1e-14);
    EXPECT_NEAR(valueOf(d, "mesh2.speed_ratio"), (0.10 + 0.05) / 0.05, 1e-14);  // as shipped
}

}  // namespace
}  // namespace milldyn
