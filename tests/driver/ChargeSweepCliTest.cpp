// A tumbling mill's fill and lag sweeps through the CLI (issue 19 item 2/3):
// the torque-arm load m g r_c sin α changes as the physics says, row by row
// against the oracle's closed form; bad charge keys give exit 2 with
// file:line:col.

#include "tests/driver/BinaryRunFixture.h"
#include "validation/oracles/TumblingMillOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kMill = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata/charges/tumbling_mill.yaml";
const std::string kSteady =
    " --set scenario.analysis=transient --set scenario.end_time=0.2s --set scenario.initial_state=steady";

class CliChargeSweep : public test::BinaryRunFixture {
protected:
    CliChargeSweep() : BinaryRunFixture("charge-sweep") {}

    /// sweep.csv as columns by header name (unit stripped).
    std::map<std::string, std::vector<std::string>> sweep(const std::string& grid) {
        const std::string out = (m_dir / "sweep").string();
        const auto r = run("", "sweep " + kMill + kSteady + " --grid '" + grid + "' --out " + out);
        EXPECT_EQ(r.code, 0) << r.out << r.err;
        std::istringstream csv(test::slurp(out + "/sweep.csv"));
        std::string line;
        std::getline(csv, line);
        std::vector<std::string> names;
        std::istringstream header(line);
        for (std::string cell; std::getline(header, cell, ',');) names.push_back(cell.substr(0, cell.find('[')));
        std::map<std::string, std::vector<std::string>> columns;
        while (std::getline(csv, line)) {
            std::istringstream row(line);
            std::size_t i = 0;
            for (std::string cell; std::getline(row, cell, ',') && i < names.size(); ++i)
                columns[names[i]].push_back(cell);
        }
        return columns;
    }
};

std::vector<double> numbers(const std::vector<std::string>& cells) {
    std::vector<double> v;
    for (const auto& c : cells) v.push_back(std::stod(c));
    return v;
}

// Fill 10 … 70 %: the load torque is m g r_c sin α with m r_c ∝ sin³γ,
// largest at 50 %; the power P = M ω follows it (the motor's slip moves ω
// by under 1 %).
TEST_F(CliChargeSweep, FillSweepFollowsTheTorqueArm) {
    auto c = sweep("elements.charge.fill=0.1:0.7:7");
    ASSERT_EQ(c["status"].size(), 7u);
    for (const auto& s : c["status"]) EXPECT_EQ(s, "ok");
    const auto fill = numbers(c["elements.charge.fill"]), torque = numbers(c["resistance_torque"]),
               power = numbers(c["power"]);
    for (std::size_t i = 0; i < fill.size(); ++i) {
        const double expected = oracles::torqueArmTorque({1.5, 4.0, 4800.0, fill[i]}, 40 * kPi / 180, 9.81);
        EXPECT_NEAR(torque[i], expected, 1e-9 * expected) << fill[i];
    }
    for (std::size_t i = 1; i < fill.size(); ++i) {
        if (fill[i] <= 0.5 + 1e-12) EXPECT_GT(power[i], power[i - 1]) << fill[i];
        else EXPECT_LT(power[i], power[i - 1]) << fill[i];
    }
}

// Lag 10 … 60°: M ∝ sin α.
TEST_F(CliChargeSweep, LagSweepFollowsSinAlpha) {
    auto c = sweep("elements.charge.lag=10deg:60deg:6");
    ASSERT_EQ(c["status"].size(), 6u);
    const auto lag = numbers(c["elements.charge.lag"]), torque = numbers(c["resistance_torque"]),
               power = numbers(c["power"]);
    for (std::size_t i = 0; i < lag.size(); ++i) {
        EXPECT_EQ(c["status"][i], "ok");
        // The grid column keeps the unit of its bounds: elements.charge.lag[deg].
        const double expected = oracles::torqueArmTorque({1.5, 4.0, 4800.0, 0.30}, lag[i] * kPi / 180, 9.81);
        EXPECT_NEAR(torque[i], expected, 1e-9 * expected) << lag[i];
        if (i > 0) {
            EXPECT_GT(power[i], power[i - 1]);
        }
    }
}

TEST_F(CliChargeSweep, UnusedKeyIsExit2WithTheMode) {
    const auto r = run("", "run " + kMill + " --set elements.charge.motion=dynamic_lag --set elements.charge.wall_drag=1e5 --out " +
                               (m_dir / "x").string());
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("tumbling_mill.yaml:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("error: charge.lag: not used with motion: dynamic_lag"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace milldyn
