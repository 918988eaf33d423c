// Issue 20 item 3 (docs/reproducing-papers.md, the papers' intermediates):
// values the papers print that are now readable as derived values
// (`milldyn info --json` → "derived", full precision), on parameters changed
// by --set, each against its closed form written here or the oracle's, not
// the model's.
#include "driver/Cli.h"
#include "validation/oracles/PlanetaryBeltOracle.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

/// `milldyn info MODEL --json --set ...`'s "derived" object.
nlohmann::json derivedWith(const std::string& model, const std::vector<std::string>& sets) {
    std::vector<std::string> all = {"info", model, "--json"};
    for (const auto& s : sets) {
        all.push_back("--set");
        all.push_back(s);
    }
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

// Seed 002 eqs (1)-(8): the criteria, the belt angle, the drum's speed ratio
// and its instantaneous centre, on an arm and sheaves the paper did not use.
TEST(Intermediates, Seed002CriteriaAndBeltKinematicsOnANewMill) {
    const nlohmann::json d = derivedWith(kModels + "planetary_belt_200x1000.yaml",
                                         {"bodies.drum1.joint.location=[0.75 m, 0 m, 0 m]",
                                          "elements.belt1.fixed_sheave_radius=0.06 m",
                                          "elements.belt1.drum_sheave_radius=0.12 m"});
    oc::PlanetaryBeltGeometry g;
    g.drumRadius = 0.1;
    g.drumSheaveRadius = 0.12;
    g.fixedSheaveRadius = 0.06;
    g.carrierArm = 0.75;
    const oc::PlanetaryBeltCriteria c = oc::criteriaFromGeometry(g);
    const oc::PlanetaryBeltKinematics kin = oc::calcKinematics(g, 1.0);
    EXPECT_NEAR(valueOf(d, "belt1.arm"), 0.75, 1e-15);
    EXPECT_NEAR(valueOf(d, "belt1.criterion_k"), c.k, 1e-15);  // 0.12/0.87
    EXPECT_NEAR(valueOf(d, "belt1.criterion_c"), c.c, 1e-15);  // 0.5
    EXPECT_NEAR(valueOf(d, "belt1.sin_belt_angle"), oc::calcSinBeltAngle(g), 1e-15);  // 0.08
    EXPECT_NEAR(valueOf(d, "belt1.drum_speed_ratio"), kin.drumRate, 1e-15);            // ω/Ω = 0.5
    ASSERT_TRUE(kin.hasInstantaneousCentre);
    EXPECT_NEAR(valueOf(d, "belt1.instant_centre_distance"), kin.centreOffsetFromA, 1e-14);  // −1.5 m
    // belt2 keeps the shipped mill: k = 0.1, c = 0.5 (the Fig. 3 case).
    EXPECT_NEAR(valueOf(d, "belt2.criterion_k"), 0.1, 1e-15);
    EXPECT_NEAR(valueOf(d, "belt2.criterion_c"), 0.5, 1e-15);
}

TEST(Intermediates, Seed002NoInstantCentreWhenTheDrumTranslates) {
    // c = 1: ω = 0, l_AD infinite (eq 4): no value rather than inf.
    const nlohmann::json d = derivedWith(kModels + "planetary_belt_200x1000.yaml",
                                         {"elements.belt1.fixed_sheave_radius=0.1 m"});
    EXPECT_EQ(valueOf(d, "belt1.drum_speed_ratio"), 0.0);
    EXPECT_FALSE(d.contains("belt1.instant_centre_distance")) << d.dump();
}

// Seed 000, the start's initial acceleration ε0 (Fig. 6): ω(t_p) = ω_y for
// ε = ε0 e^(−t), so ε0 = ω_y/(1 − e^(−t_p)).
TEST(Intermediates, Seed000InitialAccelerationOnANewStart) {
    const nlohmann::json d = derivedWith(kModels + "planetary_gear_100x200.yaml",
                                         {"elements.drive.steady_speed=600 rpm", "elements.drive.acceleration_time=2.5 s"});
    const double wy = 600 * M_PI / 30;
    EXPECT_NEAR(valueOf(d, "drive.initial_acceleration"), wy / (1 - std::exp(-2.5)), 1e-12 * wy);
    // Another time constant: ε0 = ω_y/(τ (1 − e^(−t_p/τ))).
    const nlohmann::json d2 = derivedWith(kModels + "planetary_gear_100x200.yaml",
                                          {"elements.drive.steady_speed=600 rpm", "elements.drive.acceleration_time=2.5 s",
                                           "elements.drive.time_constant=0.5 s"});
    EXPECT_NEAR(valueOf(d2, "drive.initial_acceleration"), wy / (0.5 * (1 - std::exp(-5.0))), 1e-12 * wy);
}

// Seed 000 eqs (4), (15): κ = ω2/ω1 = (R + r)/r, on gears that still fit
// the shipped arm R + r = 0.15 m.
TEST(Intermediates, Seed000SpeedRatioKappaOnNewGears) {
    const nlohmann::json d = derivedWith(kModels + "planetary_gear_100x200.yaml",
                                         {"elements.mesh1.fixed_pitch_radius=0.11 m",
                                          "elements.mesh1.planet_pitch_radius=0.04 m"});
    EXPECT_NEAR(valueOf(d, "mesh1.speed_ratio"), (0.11 + 0.04) / 0.04, 1e-14);
    EXPECT_NEAR(valueOf(d, "mesh2.speed_ratio"), (0.10 + 0.05) / 0.05, 1e-14);  // as shipped
}

}  // namespace
}  // namespace milldyn
