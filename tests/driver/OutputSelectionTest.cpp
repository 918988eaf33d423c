// "Model only what a scene requires" (issue #7 §3): outputs.columns skips
// output-only elements and unnamed outputs, outputs.energy_balance: false
// skips the energy meter. What is left out must not change what is kept.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"

#include "tests/driver/ReadFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";
const std::string kGear = kModels + "planetary_gear_100x200.yaml";

bool hasColumn(const AnalysisResult& r, const std::string& name) { return r.findColumn(name) != std::string::npos; }

TEST(OutputSelectionTest, ColumnsSkipUnnamedOutputsAndLeaveTheRestUnchanged) {
    const std::vector<Override> turn = {{"use_scenario", "turn"}, {"outputs.plots", "false"}};
    std::vector<Override> selected = turn;
    selected.push_back({"outputs.columns", "drive.torque, reaction_A"});
    const AnalysisResult all = runAnalysis(readModelFile(kGear, defaultModelReader(), turn));
    const AnalysisResult some = runAnalysis(readModelFile(kGear, defaultModelReader(), selected));
    EXPECT_TRUE(hasColumn(some, "drive.torque"));
    EXPECT_TRUE(hasColumn(some, "reaction_A.on_carrier_at_axis_magnitude"));  // an element: all its outputs
    EXPECT_TRUE(hasColumn(some, "friction_B1.torque"));  // a load torque: the summaries read it
    EXPECT_FALSE(hasColumn(some, "reaction_B1.on_drum1_at_axis_magnitude"));  // element not built
    EXPECT_FALSE(hasColumn(some, "mesh1.tangential_force"));
    EXPECT_FALSE(hasColumn(some, "friction_A.reaction"));
    EXPECT_LT(some.columnNames.size(), all.columnNames.size());
    // Output-only elements and unevaluated outputs change nothing kept:
    // the same numbers to the last bit.
    ASSERT_EQ(some.rows.size(), all.rows.size());
    for (const std::string column : {"drive.torque", "reaction_A.on_carrier_at_axis_magnitude", "friction_B1.torque"})
        for (std::size_t i = 0; i < all.rows.size(); ++i)
            EXPECT_EQ(some.value(i, column), all.value(i, column)) << column << " row " << i;
}

TEST(OutputSelectionTest, AColumnThatNamesNothingIsALocatedError) {
    // In a file: the error points at the list item.
    std::string text = test::slurp(kGear);
    const std::string outputs = "outputs:\n  sample_interval: 10 ms\n";
    const std::size_t at = text.find(outputs);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, outputs.size(), outputs + "  columns:\n    - drive.torque\n    - reaction_Z\n");
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + text.find("- reaction_Z"), '\n'));
    const ModelSpec spec = readModelText(text, "gear.yaml", defaultModelReader());
    try {
        buildScene(spec);
        FAIL() << "expected a SpecError";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().line, line);
        EXPECT_EQ(e.key(), "outputs.columns");
        EXPECT_NE(std::string(e.what()).find("no element or output named 'reaction_Z'"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("did you mean 'reaction_A'"), std::string::npos) << e.what();
    }
    // From --set: comma-separated; an empty name is refused by the reader.
    EXPECT_THROW(readModelFile(kGear, defaultModelReader(), {{"outputs.columns", "drive.torque,,reaction_A"}}),
                 SpecError);
}

TEST(OutputSelectionTest, NoEnergyMeterWithoutEnergyBalance) {
    const std::string burr = kModels + "burr_mill_5p5kW_idle.yaml";
    const std::vector<Override> base = {{"outputs.plots", "false"}, {"scenario.end_time", "2 s"}};
    std::vector<Override> off = base;
    off.push_back({"outputs.energy_balance", "false"});
    const ModelSpec withMeter = readModelFile(burr, defaultModelReader(), base);
    const ModelSpec withoutMeter = readModelFile(burr, defaultModelReader(), off);
    EXPECT_NE(buildScene(withMeter)->energyMeter(), nullptr);
    EXPECT_EQ(buildScene(withoutMeter)->energyMeter(), nullptr);
    const AnalysisResult a = runAnalysis(withMeter), b = runAnalysis(withoutMeter);
    EXPECT_NE(a.find("energy_balance_residual"), nullptr);
    EXPECT_EQ(b.find("energy_balance_residual"), nullptr);
    // The meter's integrals only enter the step-size control: the motion
    // agrees to the integration accuracy (1e-6 relative per step).
    const double wa = a.find("steady_speed")->value, wb = b.find("steady_speed")->value;
    EXPECT_NEAR(wb, wa, 1e-5 * wa);
}

}  // namespace
}  // namespace milldyn
