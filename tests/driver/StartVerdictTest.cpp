// The start verdicts of a transient (driver/analyses/Transient.cpp), the
// exit code of a run whose start did not complete, a sweep's status per
// point, and the start validation cases (validation/cases/StartCases.cpp).
#include "../validation/SectionCounts.h"

#include <gtest/gtest.h>

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

TEST(StartValidation, EveryStartCasePasses) {
    const auto rows = startCases("");
    EXPECT_GE(rows.size(), 46u);  // converter, currents, roll-back, backstop and dq rows included
    for (const auto& r : rows) EXPECT_EQ(r.status, "pass") << r.caseName << " " << r.quantity << " rel " << r.relError;
    test::expectSectionCounts(rows, "Motor starts (issue 15)", {64, 0, 0, 0});
}


}  // namespace
}  // namespace milldyn
