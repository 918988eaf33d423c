// The PlanetaryLayout plugin's test: its closed form on its own (textbook
// special cases, energy vs free bodies, statics), then the multibody model
// that milldyn builds with the plugin (`run --plugin`, `validate --plugin`)
// against it, and the plugin's input errors.

#include "PlanetaryLayoutOracle.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

using planetary_layout::LayoutLoads;
using planetary_layout::LayoutParameters;
using planetary_layout::PlanetaryLayoutOracle;

/// The 100 x 200 mm internal-rolling mill of internal_rolling_100x200.yaml,
/// typed from its comments (not from the plugin's own copy of them).
LayoutParameters mill() {
    LayoutParameters p;
    p.internal = true;
    p.drums = 2;
    p.firstDrumAngle = M_PI;
    p.ringRadius = 0.20;
    p.planetRadius = 0.05;
    p.pressureAngle = 20 * M_PI / 180;
    p.carrierMass = 2;
    p.carrierInertia = 0.015;
    p.drumMass = 2.46615023;
    p.drumInertia = 0.00554883802;
    p.drumRadius = 0.05;
    p.drumLength = 0.2;
    p.bulkDensity = 4800;
    p.fillHalfAngle = M_PI / 2;
    p.chargeDirection0 = -M_PI / 2;
    p.gravity = 9.80665;
    return p;
}

const double kOmegaY = 750 * M_PI / 30;                    // [rad/s]
const double kEps0 = kOmegaY / (1 - std::exp(-4.6));       // [rad/s^2], τ = 1 s, t_p = 4.6 s

TEST(PlanetaryLayoutOracle, InternalRollingTurnsTheDrumsBackwards) {
    const PlanetaryLayoutOracle o(mill());
    EXPECT_DOUBLE_EQ(o.calcArm(), 0.15);
    EXPECT_DOUBLE_EQ(o.calcDrumRateRatio(), -(0.20 - 0.05) / 0.05);  // the issue's ω2 = ω1 (R − r)/r, reversed
    LayoutParameters ext = mill();
    ext.internal = false;
    EXPECT_DOUBLE_EQ(PlanetaryLayoutOracle(ext).calcDrumRateRatio(), (0.20 + 0.05) / 0.05);
}

TEST(PlanetaryLayoutOracle, SegmentGivesTheHalfAndFullDiscOfTheTextbook) {
    LayoutParameters p = mill();
    const double r = p.drumRadius, m = p.bulkDensity * p.drumLength * M_PI * r * r;
    const PlanetaryLayoutOracle half(p);
    EXPECT_NEAR(half.calcChargeMass(), m / 2, 1e-12 * m);
    EXPECT_NEAR(half.calcCentroidDistance(), 4 * r / (3 * M_PI), 1e-14);
    EXPECT_NEAR(half.calcChargeAxisInertia(), m / 2 * r * r / 2, 1e-12 * m * r * r);
    p.fillHalfAngle = M_PI;
    const PlanetaryLayoutOracle full(p);
    EXPECT_NEAR(full.calcChargeMass(), m, 1e-12 * m);
    EXPECT_NEAR(full.calcCentroidDistance(), 0, 1e-14);
    EXPECT_NEAR(full.calcChargeAxisInertia(), m * r * r / 2, 1e-12 * m * r * r);
}

TEST(PlanetaryLayoutOracle, FreeBodyTorqueEqualsTheEnergyForm) {
    // T = J_pr ε + ½ J_pr' ω² + V' (Lagrange, one coordinate) against the
    // free-body sum, at states off every symmetry, both rollings, 2-4 drums.
    for (bool internal : {true, false}) {
        for (int n : {2, 3, 4}) {
            LayoutParameters p = mill();
            p.internal = internal;
            p.drums = n;
            p.fillHalfAngle = 1.1;  // not a half disc
            const PlanetaryLayoutOracle o(p);
            for (double q : {0.0, 0.4, 2.3, -1.7}) {
                const double w = 13.0, e = -7.0, h = 1e-5;
                const double dJ = (o.calcReducedInertia(q + h) - o.calcReducedInertia(q - h)) / (2 * h);
                const double dV = (o.calcPotentialEnergy(q + h) - o.calcPotentialEnergy(q - h)) / (2 * h);
                const double energy = o.calcReducedInertia(q) * e + 0.5 * dJ * w * w + dV;
                const double freeBody = o.calcLoads(q, w, e).driveTorque;
                EXPECT_NEAR(freeBody, energy, 1e-7 * (std::abs(energy) + 1)) << internal << " n=" << n << " q=" << q;
            }
        }
    }
}

TEST(PlanetaryLayoutOracle, AtRestTheGroundCarriesTheWholeWeight) {
    const LayoutParameters p = mill();
    const PlanetaryLayoutOracle o(p);
    const LayoutLoads l = o.calcLoads(0.3, 0, 0);
    const double weight = (p.carrierMass + p.drums * (p.drumMass + o.calcChargeMass())) * p.gravity;
    EXPECT_NEAR(l.carrierForce.x(), 0, 1e-12 * weight);
    EXPECT_NEAR(l.carrierForce.y(), weight, 1e-12 * weight);
    const double h = 1e-6;
    EXPECT_NEAR(l.driveTorque, (o.calcPotentialEnergy(0.3 + h) - o.calcPotentialEnergy(0.3 - h)) / (2 * h), 1e-6);
}

// ---- the multibody model, through the built milldyn and the plugin ------

struct CommandResult {
    int code;
    std::string out, err;
};

CommandResult milldyn(const std::string& args) {
    const std::string dir = std::filesystem::temp_directory_path().string();
    const std::string outFile = dir + "/planetary-layout-test.out", errFile = dir + "/planetary-layout-test.err";
    const std::string cmd = std::string(MILLDYN_BINARY) + " " + args + " >" + outFile + " 2>" + errFile;
    const int status = std::system(cmd.c_str());
    auto slurp = [](const std::string& f) {
        std::ifstream in(f);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(outFile), slurp(errFile)};
}

const std::string kModel = std::string(PLANETARY_LAYOUT_DIR) + "/internal_rolling_100x200.yaml";
const std::string kPlugin = std::string(" --plugin ") + PLANETARY_LAYOUT_PLUGIN;

/// The first data row of a milldyn CSV, by column name (header `name[unit]`).
std::map<std::string, double> firstRow(const std::string& file) {
    std::ifstream in(file);
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    std::map<std::string, double> values;
    std::stringstream h(header), v(row);
    std::string name, value;
    while (std::getline(h, name, ',') && std::getline(v, value, ','))
        values[name.substr(0, name.find('['))] = std::stod(value);
    return values;
}

TEST(PlanetaryLayoutModel, StartInstantMatchesTheClosedForm) {
    const std::string out = std::filesystem::temp_directory_path().string() + "/planetary-layout-start";
    const CommandResult r = milldyn("run " + kModel + kPlugin + " --out " + out + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto m = firstRow(out + "/kinetostatics.csv");
    const PlanetaryLayoutOracle o(mill());
    const LayoutLoads l = o.calcLoads(0, 0, kEps0);
    const double tol = 1e-6;
    const double J = o.calcReducedInertia(0);
    EXPECT_NEAR(m.at("reduced_inertia"), J, tol * J);
    EXPECT_NEAR(m.at("drive.torque"), J * kEps0, tol * J * kEps0);
    EXPECT_NEAR(m.at("drive.torque"), l.driveTorque, tol * std::abs(l.driveTorque));
    EXPECT_NEAR(m.at("mesh1.tangential_force"), l.drums[0].tangentialForce, tol * std::abs(l.drums[0].tangentialForce));
    EXPECT_NEAR(m.at("mesh2.separating_force"), l.drums[1].separatingForce, tol * l.drums[1].separatingForce);
    auto expectForce = [&](const std::string& column, const Eigen::Vector2d& f) {
        EXPECT_NEAR(m.at(column + "_x_ground"), f.x(), tol * f.norm()) << column;
        EXPECT_NEAR(m.at(column + "_y_ground"), f.y(), tol * f.norm()) << column;
    };
    expectForce("reaction_A.on_carrier_at_axis", l.carrierForce);
    expectForce("reaction_B1.on_drum1_at_axis", l.drums[0].bearingForce);
    expectForce("reaction_B2.on_drum2_at_axis", l.drums[1].bearingForce);
    // The ring pulls drum 1 (ε2 < 0: backwards) and pushes it towards A.
    EXPECT_LT(l.drums[0].tangentialForce, 0);
}

/// The last data row of a milldyn CSV, by column name.
std::map<std::string, double> lastRow(const std::string& file) {
    std::ifstream in(file);
    std::string header, line, row;
    std::getline(in, header);
    while (std::getline(in, line))
        if (!line.empty()) row = line;
    std::map<std::string, double> values;
    std::stringstream h(header), v(row);
    std::string name, value;
    while (std::getline(h, name, ',') && std::getline(v, value, ','))
        values[name.substr(0, name.find('['))] = std::stod(value);
    return values;
}

TEST(PlanetaryLayoutModel, StartFromRestKeepsTheDrumsTurningBackwards) {
    // The transient start (time integration, not kinetostatics): the carrier
    // follows ω(t) = ε0 (1 − e^(−t)), and each drum turns at −R/r relative
    // to the carrier, i.e. −(R − r)/r = −3 absolutely: internal rolling.
    const std::string out = std::filesystem::temp_directory_path().string() + "/planetary-layout-transient";
    const CommandResult r = milldyn("run " + kModel + kPlugin + " --scenario start --set scenarios.start.end_time=0.2s" +
                                    " --out " + out + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto m = lastRow(out + "/timeseries.csv");
    ASSERT_DOUBLE_EQ(m.at("time"), 0.2);
    const double w1 = kEps0 * (1 - std::exp(-0.2));
    EXPECT_NEAR(m.at("carrier.speed"), w1, 1e-6 * w1);
    for (const char* drum : {"drum1", "drum2"}) {
        const double absolute = m.at(std::string(drum) + ".speed_rel_carrier") + m.at("carrier.speed");
        EXPECT_NEAR(absolute / m.at("carrier.speed"), -(0.20 - 0.05) / 0.05, 1e-9) << drum;
    }
}

TEST(PlanetaryLayoutModel, ValidateWithThePluginRunsItsCasesAndAllPass) {
    const CommandResult r = milldyn("validate --json --filter internal_rolling" + kPlugin);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto rows = nlohmann::json::parse(r.out);
    std::map<std::string, int> perCase;
    for (const auto& row : rows) {
        ++perCase[row["case"].get<std::string>()];
        EXPECT_EQ(row["status"], "pass") << row.dump();
        // rel_error is null where the oracle is 0; abs_error says how far from 0.
        if (row["rel_error"].is_null())
            EXPECT_LE(row["abs_error"].get<double>(), 1e-6) << row.dump();
        else
            EXPECT_LE(row["rel_error"].get<double>(), 1e-6) << row.dump();
    }
    EXPECT_EQ(perCase["internal_rolling_100x200_start_up"], 11);  // J, 2 torques, F_t, N, A/B1/B2 x,y
    EXPECT_EQ(perCase["internal_rolling_100x200_turn"], 4);
    EXPECT_EQ(perCase["internal_rolling_4drums_start_up"], 15);   // ... A/B1..B4 x,y
}

TEST(PlanetaryLayoutModel, WithoutThePluginTheLayoutIsUnknown) {
    const CommandResult r = milldyn("run " + kModel + " --out /dev/null");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("unknown element type 'PlanetaryLayout'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(PlanetaryLayoutModel, BadLayoutInputIsOneLocatedLineAndExitTwo) {
    const std::string out = " --out " + std::filesystem::temp_directory_path().string() + "/planetary-layout-bad";
    struct Bad {
        std::string set, expect;
    };
    const Bad cases[] = {
        {"elements.mill.drums=2.5", "mill.drums: must be a whole number"},
        {"elements.mill.planet_pitch_radius=0.25m", "planet_pitch_radius: drums rolling inside a ring need r < R"},
        {"elements.mill.drums=10", "10 drums of pitch radius"},
        {"elements.mill.rolling=inside", "rolling"},
    };
    for (const auto& c : cases) {
        const CommandResult r = milldyn("run " + kModel + kPlugin + out + " --set " + c.set);
        EXPECT_EQ(r.code, 2) << c.set << ": " << r.err;
        EXPECT_EQ(r.err.rfind("<--set elements.mill.", 0), 0u) << "located at the --set: " << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.set << ": " << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    }
    // Written in the file: located at the key's value there.
    std::ifstream in(kModel);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "    drums: 2\n";
    const std::size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, key.size(), "    drums: 2.5\n");
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    const std::string bad = std::filesystem::temp_directory_path().string() + "/planetary-layout-bad.yaml";
    std::ofstream(bad) << text;
    const CommandResult r = milldyn("run " + bad + kPlugin + out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(bad + ":" + std::to_string(line) + ":12: error: mill.drums: must be a whole number"),
              std::string::npos)
        << r.err;
}

}  // namespace
