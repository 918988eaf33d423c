// Presets (issue #7): a model file's `presets:` block, chosen by `preset:`
// or --preset. A preset changes exactly the settings its `set:` lists (as
// if written in the file), an explicit --set still wins, every shipped
// preset of every shipped model reads, and an unknown preset is a one-line
// located error with exit code 2.

#include "driver/Cli.h"
#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace milldyn {
namespace {

using test::contains;
using test::expectSpecError;
using test::readErrorOf;
using test::readText;

const std::string kSourceDir = MILLDYN_SOURCE_DIR;

const std::string kModel = R"(format_version: 1
name: preset test
fidelity: {level: fine, levels: [coarse, fine]}
bodies:
  - {name: shaft, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}}
  - {name: load, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}, fidelity: [fine]}
elements:
  - {type: ResistanceTorque, name: drag, body: shaft, law: speed_linear, constant_torque: 1 N*m}
scenario: {analysis: transient, initial_state: rest, end_time: 1 s}
integrator: {name: CPodes, accuracy: 1e-6}
presets:
  fast:
    why: "coarse level, loose RK3"
    set: {integrator.name: RungeKutta3, integrator.accuracy: 1e-3, fidelity.level: coarse}
  accurate:
    why: "fine level, tight Merson, short steps"
    set: {integrator.name: RungeKuttaMerson, integrator.accuracy: 1e-9, integrator.max_step: 1e-4 s}
)";

TEST(Preset, ChangesExactlyTheSettingsItLists) {
    const ModelSpec plain = readText("p.yaml", kModel, {});
    EXPECT_EQ(plain.integrator.name, "CPodes");
    EXPECT_EQ(plain.fidelity, "fine");
    EXPECT_TRUE(plain.preset.empty());
    EXPECT_EQ(plain.presetNames, (std::vector<std::string>{"fast", "accurate"}));

    const ModelSpec fast = readText("p.yaml", kModel, {{"preset", "fast"}});
    EXPECT_EQ(fast.preset, "fast");
    EXPECT_EQ(fast.presetWhy, "coarse level, loose RK3");
    EXPECT_EQ(fast.integrator.name, "RungeKutta3");
    EXPECT_DOUBLE_EQ(fast.integrator.accuracy, 1e-3);
    EXPECT_DOUBLE_EQ(fast.integrator.maxStep, 0);
    EXPECT_EQ(fast.fidelity, "coarse");
    EXPECT_EQ(fast.bodies.size(), 1u);  // the fine level's body is dropped

    const ModelSpec accurate = readText("p.yaml", kModel, {{"preset", "accurate"}});
    EXPECT_EQ(accurate.integrator.name, "RungeKuttaMerson");
    EXPECT_DOUBLE_EQ(accurate.integrator.accuracy, 1e-9);
    EXPECT_DOUBLE_EQ(accurate.integrator.maxStep, 1e-4);
    EXPECT_EQ(accurate.fidelity, "fine");
}

TEST(Preset, FromTheFileAndExplicitSettingsWin) {
    const ModelSpec inFile = readText("p.yaml", kModel + "preset: fast\n", {});
    EXPECT_EQ(inFile.preset, "fast");
    EXPECT_EQ(inFile.integrator.name, "RungeKutta3");
    // --preset overrides the file's preset:, --set overrides the preset.
    const ModelSpec both = readText("p.yaml", kModel + "preset: fast\n",
                                    {{"integrator.accuracy", "1e-5"}, {"preset", "accurate"}});
    EXPECT_EQ(both.preset, "accurate");
    EXPECT_EQ(both.integrator.name, "RungeKuttaMerson");
    EXPECT_DOUBLE_EQ(both.integrator.accuracy, 1e-5);
}

TEST(Preset, UnknownPresetIsLocated) {
    expectSpecError(readErrorOf("p.yaml", kModel + "preset: balanced\n", {}), "p.yaml", 18, 9, "preset",
                    "unknown preset 'balanced' (expected one of fast, accurate)");
    expectSpecError(readErrorOf("p.yaml", kModel, {{"preset", "fsat"}}), "<--set preset>", 1, 1, "preset",
                    "did you mean 'fast'");
    const std::string noPresets = kModel.substr(0, kModel.find("presets:"));
    expectSpecError(readErrorOf("p.yaml", noPresets, {{"preset", "fast"}}), "<--set preset>", 1, 1, "preset",
                    "the model defines no presets: block");
}

TEST(Preset, BadPresetBlocksAreLocated) {
    expectSpecError(readErrorOf("p.yaml", test::replacedIn(kModel, "    why: \"coarse level, loose RK3\"\n", ""), {}),
                    "p.yaml", 13, 5, "presets.fast.why", "missing required key 'why'");
    expectSpecError(readErrorOf("p.yaml", test::replacedIn(kModel, "integrator.name: RungeKutta3", "integrator.name: RK3"),
                                {{"preset", "fast"}}),
                    "p.yaml", 14, 28, "integrator.name", "unknown integrator 'RK3'");
}

TEST(Preset, CliUnknownPresetExitsTwoWithOneLine) {
    std::ostringstream out, err;
    const int code = runCli({"run", kSourceDir + "/models/roll_crusher.yaml", "--preset", "fastest", "--out",
                             ::testing::TempDir() + "/preset_cli"},
                            out, err);
    EXPECT_EQ(code, 2);
    const std::string e = err.str();
    EXPECT_EQ(e.find('\n'), e.size() - 1) << e;
    EXPECT_TRUE(contains(e, "<--set preset>:1:1: error: preset: unknown preset 'fastest'")) << e;
}

TEST(Preset, EveryShippedPresetReadsAndSaysWhy) {
    int models = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kSourceDir + "/models")) {
        if (entry.path().extension() != ".yaml") continue;
        const ModelSpec spec = readModelFile(entry.path().string(), defaultModelReader(), {});
        for (const auto& name : spec.presetNames) {
            SCOPED_TRACE(entry.path().string() + " preset " + name);
            const ModelSpec p = readModelFile(entry.path().string(), defaultModelReader(), {{"preset", name}});
            EXPECT_EQ(p.preset, name);
            EXPECT_FALSE(p.presetWhy.empty());
        }
        if (!spec.presetNames.empty()) {
            ++models;
            EXPECT_EQ(spec.presetNames, (std::vector<std::string>{"fast", "balanced", "accurate"})) << entry.path();
        }
    }
    EXPECT_GE(models, 4);  // burr mill, roll crusher, planetary gear, planetary belt
}

TEST(Preset, RunSummarySaysWhatItPicked) {
    std::ostringstream out, err;
    const std::string dir = ::testing::TempDir() + "/preset_run";
    const int code = runCli({"run", kSourceDir + "/models/roll_crusher.yaml", "--preset", "fast", "--set",
                             "scenario.end_time=0.2 s", "--set", "outputs.plots=false", "--out", dir},
                            out, err);
    ASSERT_EQ(code, 0) << err.str();
    const ModelSpec p = readModelFile(kSourceDir + "/models/roll_crusher.yaml", defaultModelReader(), {{"preset", "fast"}});
    EXPECT_TRUE(contains(out.str(), "note: preset fast: " + p.integrator.name)) << out.str();
    EXPECT_TRUE(contains(out.str(), p.presetWhy)) << out.str();
    EXPECT_TRUE(contains(out.str(), "integrator " + p.integrator.name)) << out.str();
}

}  // namespace
}  // namespace milldyn
