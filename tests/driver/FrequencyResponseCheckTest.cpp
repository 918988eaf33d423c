// issue 20 item 6: frequency_response's time-simulation check takes its
// length from the damping, or refuses with the reason (an undamped 10-mass
// chain ran more than 8 minutes before).
#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace milldyn {
namespace {

const std::string kCrusher = std::string(MILLDYN_SOURCE_DIR) + "/models/roll_crusher.yaml";

std::vector<Override> undampedChain() {
    std::vector<Override> o = {{"use_scenario", "response"}, {"outputs.plots", "false"}};
    for (const std::string n : {"reducer@10-mass", "shaft_1_2", "shaft_2_3", "shaft_3_4", "shaft_4_5", "shaft_5_6",
                                "shaft_6_7", "shaft_7_8", "shaft_8_9"})
        o.push_back({"elements." + n + ".damping", "0"});
    return o;
}

TEST(FrequencyResponseCheck, NearlyUndampedChainIsRefusedWithTheSlowestModeAndTheLength) {
    try {
        runAnalysis(readModelFile(kCrusher, defaultModelReader(), undampedChain()));
        ADD_FAILURE() << "the check ran";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.check_frequencies");
        const std::string why = e.what();
        EXPECT_NE(why.find("more than 20000"), std::string::npos) << why;
        EXPECT_NE(why.find("decays at"), std::string::npos) << why;
        EXPECT_NE(why.find("give settle_time"), std::string::npos) << why;
    }
}

TEST(FrequencyResponseCheck, WithoutChecksTheLinearResponseStillRuns) {
    std::vector<Override> o = undampedChain();
    o.push_back({"scenarios.response.check_frequencies", "[]"});
    o.push_back({"scenarios.response.points", "20"});
    const AnalysisResult r = runAnalysis(readModelFile(kCrusher, defaultModelReader(), o));
    EXPECT_EQ(r.rows.size(), 20u);
}

}  // namespace
}  // namespace milldyn
