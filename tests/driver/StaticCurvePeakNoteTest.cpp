// A start on a static torque-speed curve says what its peaks leave out, for
// every starter (issue 28 item 3): the 110 kW crusher drive
// (models/crusher_belt_start_static.yaml) with its datasheet's current data.

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace milldyn {
namespace {

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/models/crusher_belt_start_static.yaml";

AnalysisResult run(std::vector<Override> overrides) {
    overrides.push_back({"scenario.end_time", "1 s"});  // the switch-on and the first switchings
    return runAnalysis(readModelFile(kModel, defaultModelReader(), overrides));
}

std::string peakNote(const AnalysisResult& r) {
    for (const auto& n : r.notes)
        if (n.rfind("peak torque: drive", 0) == 0) return n;
    return "";
}

double derived(const AnalysisResult& r, const std::string& name) {
    for (const auto& d : r.derived)
        if (d.name == name) return d.value;
    ADD_FAILURE() << "no derived value " << name;
    return 0;
}

TEST(StaticCurvePeakNote, EveryStarterSaysWhatTheStaticCurveLeavesOut) {
    // Direct on line: the full-voltage estimate above the curve's largest torque.
    const AnalysisResult dol = run({});
    const double full = derived(dol, "drive.dq_switch_on_peak_estimate"), curve = derived(dol, "drive.static_curve_peak");
    ASSERT_GT(full, curve);
    EXPECT_NE(peakNote(dol).find("starts direct_on_line"), std::string::npos) << peakNote(dol);
    EXPECT_NE(peakNote(dol).find("no design load"), std::string::npos) << peakNote(dol);

    // Star-delta: the switch-on in star at V/√3 (u² = 1/3 of the full-voltage
    // estimate: the machine is linear in the voltage) and the reclosure.
    const AnalysisResult sd = run({{"elements.drive.starter", "star_delta"}, {"elements.drive.switch_times", "[0.5 s]"}});
    EXPECT_NEAR(derived(sd, "drive.dq_starter_switch_on_peak_estimate"), full / 3, 1e-12 * full);
    EXPECT_NE(peakNote(sd).find("reclosure in delta"), std::string::npos) << peakNote(sd);

    // Soft start from 40 % voltage: 0.16 of it at switch-on.
    const AnalysisResult soft = run({{"elements.drive.starter", "soft_start"}, {"elements.drive.initial_voltage", "0.4"},
                                     {"elements.drive.ramp_time", "2 s"}});
    EXPECT_NEAR(derived(soft, "drive.dq_starter_switch_on_peak_estimate"), 0.16 * full, 1e-12 * full);
    EXPECT_NE(peakNote(soft).find("starts soft_start"), std::string::npos) << peakNote(soft);

    // A frequency converter ramps the fundamental: no note.
    const AnalysisResult vf = run({{"elements.drive.starter", "frequency_converter"}, {"elements.drive.ramp_time", "2 s"}});
    EXPECT_EQ(peakNote(vf), "");

    // Steady running switches nothing on: no note.
    EXPECT_EQ(peakNote(run({{"scenario.initial_state", "steady"}})), "");

}

TEST(StaticCurvePeakNote, WithoutTheCurrentDataTheRunSaysWhichDataWouldGiveTheEstimate) {
    // The 3 × 4 m mill's motor has no current data: no estimate, but the
    // run's notes (not only `milldyn info`) say its peaks are no design load.
    const AnalysisResult r = runAnalysis(readModelFile(std::string(MILLDYN_SOURCE_DIR) +
                                                           "/models/tumbling_ball_mill_3x4m_start_dol.yaml",
                                                       defaultModelReader(), {{"scenario.end_time", "0.5 s"}}));
    std::string note;
    for (const auto& n : r.notes)
        if (n.rfind("peak torque: motor", 0) == 0) note = n;
    EXPECT_NE(note.find("not estimated: rated_current"), std::string::npos) << note;
    EXPECT_NE(note.find("no design load"), std::string::npos) << note;
}

}  // namespace
}  // namespace milldyn
