// The start verdicts of a transient (driver/analyses/Transient.cpp), the
// exit code of a run whose start did not complete, a sweep's status per
// point, and the start validation cases (validation/cases/StartCases.cpp).
#include "../validation/SectionCounts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/Cli.h"
#include "driver/analyses/Analysis.h"
#include "validation/cases/ValidationCases.h"

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

TEST(StartVerdict, DirectOnLineStartOfAnInertiaCompletes) {
    const AnalysisResult r = runModelFile(kModels + "start_bench_dol.yaml", {});
    EXPECT_EQ(r.verdict, "completed") << r.verdictText;
    ASSERT_NE(r.find("start_time"), nullptr);
    EXPECT_NE(r.find("steady_speed"), nullptr);
}

// Kloss gives 2·Mk·sk/(1 + sk²) = 2·243.5·0.09583/1.00918 = 46.2 N*m at
// standstill: a 60 N*m load never moves.
TEST(StartVerdict, ALoadAboveTheLockedRotorTorqueStallsWithNumbersAndNoStartTime) {
    const AnalysisResult r = runModelFile(kModels + "start_bench_dol.yaml", {{"elements.load.constant_torque", "60 N*m"},
                                                                           {"scenario.end_time", "1 s"}});
    EXPECT_EQ(r.verdict, "stalled") << r.verdictText;
    EXPECT_NE(r.verdictText.find("motor.torque = 46.2"), std::string::npos) << r.verdictText;
    EXPECT_NE(r.verdictText.find("load.torque = 46.2"), std::string::npos) << r.verdictText;
    EXPECT_EQ(r.find("start_time"), nullptr);
    EXPECT_EQ(r.find("steady_speed"), nullptr);
    ASSERT_NE(r.find("speed_at_end"), nullptr);
    // It creeps in the load's regularisation band: 60·tanh(ω/0.01) = 46.24 at ω = 0.0102 rad/s.
    EXPECT_LT(r.find("speed_at_end")->value, 0.02);
}

// Catalogue curve with a deep pull-up dip (0.5 Mn at 600 rpm) against
// 0.8 Mn: the motor accelerates off the locked-rotor torque 2 Mn and
// crawls where the curve falls through 0.8 Mn, below 600 rpm.
TEST(StartVerdict, ACrawlInThePullUpDipIsAStall) {
    const AnalysisResult r =
        runModelFile(kModels + "start_bench_catalogue.yaml", {{"elements.motor.locked_rotor_ratio", "2"},
                                                              {"elements.motor.pull_up_ratio", "0.5"},
                                                              {"elements.motor.pull_up_speed", "600 rpm"},
                                                              {"elements.load.constant_torque", "77.9 N*m"}});
    EXPECT_EQ(r.verdict, "stalled") << r.verdictText;
    ASSERT_NE(r.find("speed_at_end"), nullptr);
    EXPECT_GT(r.find("speed_at_end")->value, 1.0);
    EXPECT_LT(r.find("speed_at_end")->value, 600 * 3.14159265358979 / 30);
    EXPECT_EQ(r.find("start_time"), nullptr);
}

TEST(StartVerdict, ARunEndedMidAccelerationIsUnfinished) {
    const AnalysisResult r = runModelFile(kModels + "start_bench_dol.yaml", {{"scenario.end_time", "1.5 s"}});
    EXPECT_EQ(r.verdict, "unfinished") << r.verdictText;
    EXPECT_EQ(r.find("start_time"), nullptr);
    EXPECT_EQ(r.find("steady_speed"), nullptr);
}

TEST(StartVerdict, CliExitsThreeOnAStallAndSaysWhyOnScreenAndInTheSummary) {
    const std::string dir = ::testing::TempDir() + "/stall_cli";
    std::ostringstream out, err;
    const int code = runCli({"run", kModels + "start_bench_dol.yaml", "--set", "elements.load.constant_torque=60 N*m",
                             "--set", "scenario.end_time=1 s", "--out", dir},
                            out, err);
    EXPECT_EQ(code, 3) << err.str();
    EXPECT_NE(out.str().find("verdict: start stalled"), std::string::npos) << out.str();
    EXPECT_EQ(out.str().find("start_time"), std::string::npos) << out.str();
    std::ifstream summary(dir + "/summary.json");
    std::stringstream text;
    text << summary.rdbuf();
    EXPECT_NE(text.str().find("\"status\": \"stalled\""), std::string::npos);
}

TEST(StartVerdict, SweepRecordsTheVerdictPerPointAndContinues) {
    const std::string dir = ::testing::TempDir() + "/stall_sweep";
    std::filesystem::remove_all(dir);
    std::ostringstream out, err;
    runCli({"sweep", kModels + "start_bench_dol.yaml", "--grid", "elements.load.constant_torque=0 N*m:60 N*m:2", "--set",
            "scenario.end_time=3.5 s", "--jobs", "1", "--out", dir},
           out, err);
    std::ifstream table(dir + "/sweep.csv");
    std::string header, row0, row1;
    std::getline(table, header);
    std::getline(table, row0);
    std::getline(table, row1);
    EXPECT_NE(row0.find(",ok,"), std::string::npos) << row0;
    EXPECT_NE(row1.find(",stalled,"), std::string::npos) << row1;
}

// A drive below the load with no hinted running speed: ω_ref is the final
// speed itself, so the shaft's creep inside the loads' sign regularisation
// (tanh(ω/ωs), ωs = 0.01 rad/s) held "100 % of ω_ref" and was called a
// completed start. 10 N*m against a crushing load of mean 100 N*m (at most
// 100 + 30 + 80 = 210 N*m, at least 100 − 30 − 80 < 0 but never passed:
// the shaft starts at angle 0 where it is 210 N*m) balances at
// ω = ωs·atanh(10/210) ≈ 0.000477 rad/s.
std::string writeCreepModel(const std::string& name, const std::string& drive, const std::string& extra,
                            const std::string& scenario) {
    const std::string path = ::testing::TempDir() + "/" + name + ".yaml";
    std::ofstream(path) << "format_version: 1\nname: creep\nbodies:\n"
                           "  - {name: b, inertia: 1 kg*m^2, joint: {type: pin}}\nelements:\n"
                           "  - {type: AppliedTorque, name: drive, body: b, torque: "
                        << drive
                        << "}\n"
                           "  - {type: AngleLoad, name: crushing, bodies: [b], shape: fourier, mean_torque: 100 N*m, "
                           "cosine_amplitudes: [30 N*m, 80 N*m]}\n"
                        << extra << "scenario: {analysis: transient, " << scenario << "}\n";
    return path;
}

TEST(StartVerdict, ACreepInsideTheLoadsRegularisationBandIsAStallWithoutAHintedSpeed) {
    const AnalysisResult r = runModelFile(writeCreepModel("creep_stall", "10 N*m", "", "end_time: 0.1 s"), {});
    EXPECT_EQ(r.verdict, "stalled") << r.verdictText;
    EXPECT_NE(r.verdictText.find("inside the regularisation band of the loads on b (|ω| < 0.05 rad/s"),
              std::string::npos)
        << r.verdictText;
    EXPECT_NE(r.verdictText.find("crushing.smoothing_speed = 0.01 rad/s"), std::string::npos) << r.verdictText;
    EXPECT_NE(r.verdictText.find("drive.torque = 10 N*m"), std::string::npos) << r.verdictText;
    EXPECT_NE(r.verdictText.find("crushing.torque = "), std::string::npos) << r.verdictText;
    ASSERT_NE(r.find("speed_at_end"), nullptr);
    EXPECT_NEAR(r.find("speed_at_end")->value, 0.01 * std::atanh(10.0 / 210.0), 0.05 * 0.01 * std::atanh(10.0 / 210.0));
    EXPECT_EQ(r.find("steady_speed"), nullptr);
    EXPECT_EQ(r.find("start_time"), nullptr);
}

// The same shaft driven past the load (300 N*m > 210 N*m) with a viscous
// drag 10 N*m*s/rad: it runs up to about (300 − 100)/10 = 20 rad/s, far
// above every band, and holds it (period means over whole revolutions):
// with no hinted speed a held final speed is a completed start.
TEST(StartVerdict, TheSameShaftDrivenPastTheLoadToAHeldSpeedAboveTheBandCompletes) {
    const std::string drag = "  - {type: ResistanceTorque, name: drag, body: b, viscous_coefficient: 10 N*m*s/rad}\n";
    const AnalysisResult r =
        runModelFile(writeCreepModel("creep_run", "300 N*m", drag, "end_time: 3 s, hold_time: 1 s"), {});
    EXPECT_EQ(r.verdict, "completed") << r.verdictText;
    EXPECT_EQ(r.verdictText.find("regularisation band"), std::string::npos) << r.verdictText;
    ASSERT_NE(r.find("steady_speed"), nullptr);
    EXPECT_NEAR(r.find("steady_speed")->value, 20.0, 0.5);
    // The drag alone at 10 N*m, the rest as before: the creep stalls.
    const AnalysisResult creep =
        runModelFile(writeCreepModel("creep_drag", "10 N*m", drag, "end_time: 3 s, hold_time: 1 s"), {});
    EXPECT_EQ(creep.verdict, "stalled") << creep.verdictText;
    EXPECT_NE(creep.verdictText.find("drag.smoothing_speed"), std::string::npos) << creep.verdictText;
}

// A drive that hints its rated speed keeps its verdicts: the bench's start
// completes far above the band, the 60 N*m load stalls it (there below the
// stall fraction of the hinted speed, and also inside the band).
TEST(StartVerdict, AHintedSpeedModelKeepsItsVerdicts) {
    const AnalysisResult ok = runModelFile(kModels + "start_bench_dol.yaml", {});
    EXPECT_EQ(ok.verdict, "completed") << ok.verdictText;
    EXPECT_EQ(ok.verdictText.find("regularisation band"), std::string::npos) << ok.verdictText;
    EXPECT_NE(ok.verdictText.find("the drives' running speed"), std::string::npos) << ok.verdictText;
    const AnalysisResult stall = runModelFile(
        kModels + "start_bench_dol.yaml", {{"elements.load.constant_torque", "60 N*m"}, {"scenario.end_time", "1 s"}});
    EXPECT_EQ(stall.verdict, "stalled") << stall.verdictText;
}

TEST(StartValidation, EveryStartCasePasses) {
    const auto rows = startCases("");
    EXPECT_GE(rows.size(), 46u);  // converter, currents, roll-back, backstop and dq rows included
    for (const auto& r : rows) EXPECT_EQ(r.status, "pass") << r.caseName << " " << r.quantity << " rel " << r.relError;
    test::expectSectionCounts(rows, "Motor starts (issue 15)", {64, 0, 0, 0});
}


}  // namespace
}  // namespace milldyn
