// The CLI11 command line in-process (runCli with string streams): help for
// every command, the schema-generated references (`elements`, `analyses`,
// `schema`, `completion`), `info --json`, and one-line exit-2 diagnostics.
#include "driver/Cli.h"
#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

struct Ran {
    int code = -1;
    std::string out, err;
};

Ran cli(const std::vector<std::string>& args) {
    std::ostringstream out, err;
    Ran r;
    r.code = runCli(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

TEST(CliCommands, HelpForEveryCommandByHelpAndByDashDashHelp) {
    for (const std::string command : {"run", "info", "validate", "sweep", "merge", "front", "elements", "analyses",
                                      "schema", "completion"}) {
        SCOPED_TRACE(command);
        const Ran a = cli({"help", command}), b = cli({command, "--help"});
        EXPECT_EQ(a.code, 0) << a.err;
        EXPECT_EQ(b.code, 0) << b.err;
        EXPECT_EQ(a.out, b.out);
        EXPECT_TRUE(contains(a.out, "Usage: " + command)) << a.out;
    }
    const Ran run = cli({"run", "--help"});
    for (const std::string option : {"--set", "--end-time", "--integrator", "--schematic-at", "--plugin"})
        EXPECT_TRUE(contains(run.out, option)) << option;
    const Ran top = cli({"help"});
    EXPECT_EQ(top.code, 0);
    EXPECT_TRUE(contains(top.out, "milldyn elements [TYPE]")) << top.out;
}

TEST(CliCommands, BadOptionsAndCommandsExitTwoWithOneLine) {
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{"run", kModels + "roll_crusher.yaml", "--bogus"},
                                               {"runn", "x.yaml"},
                                               {"help", "nothing"},
                                               {"sweep", kModels + "roll_crusher.yaml", "--jobs", "-3"},
                                               {"elements", "InductionMotr"},
                                               {}}) {
        const Ran r = cli(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
    EXPECT_TRUE(contains(cli({"runn", "x.yaml"}).err, "did you mean 'run'?"));
    EXPECT_TRUE(contains(cli({"info", "x.yaml", "--schematic"}).err, "--schematic goes with run"));
    EXPECT_TRUE(contains(cli({"run", "x.yaml", "--report=out"}).err, "--report goes with validate"));
    EXPECT_TRUE(contains(cli({"elements", "InductionMotr"}).err, "did you mean 'InductionMotor'?"));
}

TEST(CliCommands, ElementsListsEveryRegisteredTypeWithKeysUnitsDefaultsAndRanges) {
    const Ran all = cli({"elements"});
    ASSERT_EQ(all.code, 0) << all.err;
    for (const auto& type : defaultModelReader().elementTypes) EXPECT_TRUE(contains(all.out, type + " — ")) << type;
    const Ran motor = cli({"elements", "InductionMotor"});
    ASSERT_EQ(motor.code, 0) << motor.err;
    EXPECT_TRUE(contains(motor.out, "  rated_speed: number in rad/s, > 0, required")) << motor.out;
    EXPECT_TRUE(contains(motor.out, "  breakdown_ratio: number (dimensionless), > 1, <= 10, default 2.2")) << motor.out;
    // The motor laws in registration order (plugins/motors/InductionMotor.cpp), default first.
    EXPECT_TRUE(contains(motor.out, "  law: one of kloss|linear|catalogue|table")) << motor.out;
    EXPECT_TRUE(contains(motor.out, ", default kloss")) << motor.out;
    EXPECT_FALSE(contains(motor.out, "ResistanceTorque")) << motor.out;
    const Ran analyses = cli({"analyses"});
    for (const auto& kind : defaultModelReader().analysisKinds) EXPECT_TRUE(contains(analyses.out, kind)) << kind;
}

TEST(CliCommands, SchemaIsJsonSchemaCoveringEveryTypeAndKey) {
    const Ran r = cli({"schema"});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json s = nlohmann::json::parse(r.out);
    EXPECT_EQ(s["$schema"], "https://json-schema.org/draft/2020-12/schema");
    const auto& variants = s["properties"]["elements"]["items"]["allOf"];
    ASSERT_EQ(variants.size(), defaultModelReader().elementTypes.size());
    bool sawMotor = false;
    for (const auto& v : variants) {
        if (v["if"]["properties"]["type"]["const"] != "InductionMotor") continue;
        sawMotor = true;
        const auto& then = v["then"];
        EXPECT_EQ(then["additionalProperties"], false);
        EXPECT_TRUE(then["properties"].contains("rated_speed"));
        const auto laws = then["properties"]["law"]["enum"].get<std::vector<std::string>>();
        for (const char* law : {"kloss", "linear", "catalogue", "table"})
            EXPECT_NE(std::find(laws.begin(), laws.end(), law), laws.end()) << law;
        const auto req = then["required"].get<std::vector<std::string>>();
        EXPECT_NE(std::find(req.begin(), req.end(), "rated_speed"), req.end());
    }
    EXPECT_TRUE(sawMotor);
    EXPECT_EQ(s["properties"]["scenario"]["allOf"].size(), defaultModelReader().analysisKinds.size());
}

TEST(CliCommands, CompletionScriptNamesCommandsTypesAndIntegrators) {
    const Ran r = cli({"completion"});
    ASSERT_EQ(r.code, 0);
    EXPECT_TRUE(contains(r.out, "complete -F _milldyn milldyn"));
    EXPECT_TRUE(contains(r.out, "run info validate sweep merge front elements analyses schema completion help"));
    EXPECT_TRUE(contains(r.out, "InductionMotor"));
    EXPECT_TRUE(contains(r.out, "RungeKuttaMerson"));
}

TEST(CliCommands, InfoJsonGivesDerivedValuesAtFullPrecision) {
    const Ran r = cli({"info", kModels + "burr_mill_5p5kW_idle.yaml", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["mobilities"], 2);
    EXPECT_EQ(j["elements"]["motor"], "InductionMotor");
    // 982.4e-4 kg*m^2 as written, not rounded to 6 digits.
    EXPECT_EQ(j["body"]["millstone"]["inertia"]["value"].get<double>(), 982.4e-4);
    EXPECT_TRUE(j.contains("derived"));
    EXPECT_EQ(j["outputs"]["belt.torque"], "N*m");
}

TEST(CliCommands, EndTimeOptionReadsABareNumberAsSecondsButSetNeedsTheUnit) {
    const Ran bare = cli({"info", kModels + "burr_mill_5p5kW_idle.yaml", "--set", "scenario.end_time=0.3"});
    EXPECT_EQ(bare.code, 2);
    EXPECT_TRUE(contains(bare.err, "did you mean 0.3 s?")) << bare.err;
}

// Issue 20 item 4: a grid value without its unit on a dimensional key is
// refused before any point runs (exit 2, one line, the unit suggested), as
// --set refuses it, instead of every point failing. A bare 0 needs no unit,
// so a grid starting at 0 is judged by its other values.
TEST(CliCommands, SweepGridWithoutUnitIsRefusedBeforeAnyPoint) {
    const std::string out = testing::TempDir() + "/milldyn_grid_without_unit";
    std::filesystem::remove_all(out);
    for (const std::string grid : {"elements.grinding.constant_torque=10:20:3",
                                   "elements.grinding.constant_torque=0:20:3"}) {
        SCOPED_TRACE(grid);
        const Ran r = cli({"sweep", kModels + "burr_mill_5p5kW_idle.yaml", "--grid", grid, "--out", out,
                           "--no-plots", "--jobs", "1"});
        EXPECT_EQ(r.code, 2);
        EXPECT_TRUE(contains(r.err, "<--grid elements.grinding.constant_torque=...>:1:1: error: "
                                    "elements.grinding.constant_torque: a bare number needs a unit here "
                                    "(did you mean 20 N*m?)"))
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(std::ifstream(out + "/sweep.csv").good()) << "no point may have run";
    }
    // A dimensionless key takes bare numbers, so its grid passes the check.
    const Ran ratio = cli({"sweep", kModels + "burr_mill_5p5kW_idle.yaml", "--grid",
                           "elements.belt.ratio=1:1:1", "--out", out, "--no-plots", "--jobs", "1",
                           "--set", "scenario.end_time=0.01 s"});
    EXPECT_FALSE(contains(ratio.err, "needs a unit")) << ratio.err;
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

TEST(CliCommands, ModelWithoutGravityWarnsNamingTheElementsLoadedByWeight) {
    const std::string model = std::string(MILLDYN_SOURCE_DIR) + "/models/planetary_gear_100x200.yaml";
    const Ran with = cli({"info", model});
    ASSERT_EQ(with.code, 0) << with.err;
    EXPECT_FALSE(contains(with.out, "warning")) << with.out;
    const Ran without = cli({"info", model, "--set", "gravity=[0, 0, 0]"});
    ASSERT_EQ(without.code, 0) << without.err;
    EXPECT_TRUE(contains(without.out, "warning: the model has no gravity: but ")) << without.out;
    EXPECT_TRUE(contains(without.out, "charge1 (SegmentCharge)")) << without.out;
    EXPECT_TRUE(contains(without.out, "(JournalFriction)")) << without.out;
    EXPECT_FALSE(contains(cli({"info", kModels + "burr_mill_5p5kW_idle.yaml"}).out, "warning"));
}

}  // namespace
}  // namespace milldyn

#include "validation/oracles/BeadMillOracle.h"

namespace milldyn {
namespace {

TEST(CliCommands, InfoJsonGivesTheEq2ShaftDiameterAtFullPrecision) {
    const Ran r = cli({"info", kModels + "bead_mill_5disc_0p1m.yaml", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j["derived"].contains("rotor.shaft_diameter")) << r.out;
    // The oracle's eq (2) for 5 discs of 0.1 m at L_p = 0.267 m; both read
    // papers/BeadMillTable1, so they agree to rounding.
    EXPECT_NEAR(j["derived"]["rotor.shaft_diameter"]["value"].get<double>(),
                oracles::beadMillShaftDiameter(5, 0.1, 0.267), 1e-15);
    EXPECT_EQ(j["derived"]["rotor.shaft_diameter"]["unit"], "m");
}

}  // namespace
}  // namespace milldyn
