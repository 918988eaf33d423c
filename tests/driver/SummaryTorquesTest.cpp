// The transient summary never adds torques on different shafts (issue 32:
// a faked vertical roller mill reported one "resistance torque" summed over
// the table and the motor shaft). Two shafts, each with its own load and
// drive: the summary reports each on its shaft, with no sum; loads on one
// shaft are summed under the one name.
#include <gtest/gtest.h>

#include <string>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

namespace milldyn {
namespace {

std::string twoShafts(const std::string& secondLoadBody) {
    return "format_version: 1\n"
           "name: two shafts\n"
           "bodies:\n"
           "  - {name: a, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}, initial_speed: 10 rad/s}\n"
           "  - {name: b, inertia: 4 kg*m^2, joint: {type: pin, parent: ground}, initial_speed: 20 rad/s}\n"
           "elements:\n"
           "  - {type: AppliedTorque, name: drive_a, body: a, torque: 5 N*m}\n"
           "  - {type: AppliedTorque, name: drive_b, body: b, torque: 7 N*m}\n"
           "  - {type: ResistanceTorque, name: load_a, body: a, constant_torque: 3 N*m}\n"
           "  - {type: ResistanceTorque, name: load_b, body: " + secondLoadBody + ", constant_torque: 11 N*m}\n"
           "scenario: {analysis: transient, initial_state: file, end_time: 0.5 s, speed_body: a}\n"
           "integrator: {name: RungeKuttaMerson, accuracy: 1e-9}\n"
           "outputs: {sample_interval: 0.1 s}\n";
}

TEST(SummaryTorques, TorquesOnDifferentShaftsAreReportedEachOnItsShaftNeverAdded) {
    const AnalysisResult r = runAnalysis(readModelText(twoShafts("b"), "two.yaml", defaultModelReader()));
    EXPECT_EQ(r.find("resistance_torque"), nullptr);
    EXPECT_EQ(r.find("drive_torque"), nullptr);
    EXPECT_EQ(r.find("peak_drive_torque"), nullptr);
    ASSERT_NE(r.find("resistance_torque.load_a.torque"), nullptr);
    ASSERT_NE(r.find("resistance_torque.load_b.torque"), nullptr);
    EXPECT_NEAR(r.find("resistance_torque.load_a.torque")->value, 3.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque.load_a.torque")->referredTo, "a");
    EXPECT_NEAR(r.find("resistance_torque.load_b.torque")->value, 11.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque.load_b.torque")->referredTo, "b");
    ASSERT_NE(r.find("drive_torque.drive_b.torque"), nullptr);
    EXPECT_NEAR(r.find("drive_torque.drive_b.torque")->value, 7.0, 1e-12);
    ASSERT_NE(r.find("peak_drive_torque.drive_a.torque"), nullptr);
    EXPECT_NEAR(r.find("peak_drive_torque.drive_a.torque")->value, 5.0, 1e-12);
    // Power adds across shafts: 3·ω_a + 11·ω_b at the end, ω from the
    // torque balances (5 − 3)/1 and (7 − 11)/4 rad/s².
    const double wa = 10 + 2.0 * 0.5, wb = 20 - 1.0 * 0.5;
    EXPECT_NEAR(r.find("power")->value, 3 * wa + 11 * wb, 1e-6);
}

TEST(SummaryTorques, LoadsOnOneShaftAreSummedUnderOneName) {
    const AnalysisResult r = runAnalysis(readModelText(twoShafts("a"), "two.yaml", defaultModelReader()));
    ASSERT_NE(r.find("resistance_torque"), nullptr);
    EXPECT_NEAR(r.find("resistance_torque")->value, 14.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque")->referredTo, "a");
    EXPECT_EQ(r.find("resistance_torque.load_a.torque"), nullptr);
}

}  // namespace
}  // namespace milldyn
