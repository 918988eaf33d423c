// Sweeps: the table does not depend on the number of jobs or shards, an
// interrupted sweep resumes, bad points are recorded, not fatal.

#include "driver/Sweep.h"
#include "driver/outputs/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace milldyn {
namespace {

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";

std::string freshDir(const std::string& name) {
    const std::string dir = std::filesystem::temp_directory_path().string() + "/milldyn-sweeptest-" + name;
    std::filesystem::remove_all(dir);
    return dir;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

SweepOptions options(const std::string& dir, unsigned jobs) {
    SweepOptions o;
    o.model = kModel;
    // Short runs: 0.3 s from steady running is enough to make every point
    // different (a 0.3 s start from rest would be an unfinished start, a
    // status of its own: StartVerdictTest).
    o.baseOverrides = {{"scenario.end_time", "0.3 s"}, {"scenario.initial_state", "steady"}, {"outputs.plots", "false"}};
    o.jobs = jobs;
    o.outDir = dir;
    return o;
}

SweepPlan smallGrid() {
    return makeGrid({parseGrid("elements.grinding.constant_torque=10 N*m:30 N*m:3"),
                     parseGrid("elements.belt.damping=0.1 N*m*s/rad:0.5 N*m*s/rad:2")});
}

TEST(SweepTest, GridValuesAreEvenlySpacedWithUnitsAndRoundedToTwelveDigits) {
    const SweepAxis a = parseGrid("elements.belt.damping=0.1 N*m*s/rad:0.5 N*m*s/rad:3");
    ASSERT_EQ(a.values.size(), 3u);
    EXPECT_EQ(a.values[1], 0.3);  // exactly, after rounding to 12 digits
    const SweepAxis b = parseGrid("scenario.runout_time=1.0 s:2.0 s:5");
    EXPECT_EQ(b.unit, "s");
    EXPECT_DOUBLE_EQ(b.values[2], 1.5);
    const SweepPlan plan = makeGrid({a, b});
    EXPECT_EQ(plan.count, 15u);
    // Row-major: the last axis varies fastest.
    EXPECT_EQ(plan.overrides(1)[1].value, "1.25 s");
    EXPECT_EQ(plan.overrides(5)[0].value, "0.3 N*m*s/rad");
}

TEST(SweepTest, BadGridOrRangeIsASpecErrorNamingTheOption) {
    for (const std::string bad : {"x=1:2", "=1:2:3", "x=a:2:3", "x=1 m:2 s:3", "x=1:2:0", "x=1:2:1.5"}) {
        try {
            parseGrid(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const SpecError& e) {
            EXPECT_EQ(e.key(), "--grid") << bad;
        }
    }
    EXPECT_THROW(parseRange("x=1:2:3"), SpecError);
}

TEST(SweepTest, LatinHypercubeHitsEveryStratumOnceAndIsReproducible) {
    const auto make = [] {
        return makeLatinHypercube({parseRange("a=0:10"), parseRange("b=100:200")}, 10, 7);
    };
    const SweepPlan p1 = make(), p2 = make();
    ASSERT_EQ(p1.count, 10u);
    for (std::size_t axis = 0; axis < 2; ++axis) {
        std::set<int> strata;
        const double lo = axis == 0 ? 0 : 100, width = axis == 0 ? 1 : 10;
        for (double v : p1.axes[axis].values) strata.insert(static_cast<int>((v - lo) / width));
        EXPECT_EQ(strata.size(), 10u) << "axis " << axis;
        EXPECT_EQ(p1.axes[axis].values, p2.axes[axis].values);
    }
}

TEST(SweepTest, TableIsIdenticalForOneAndTwoJobs) {
    const SweepPlan plan = smallGrid();
    const std::string d1 = freshDir("jobs1"), d2 = freshDir("jobs2");
    const SweepSummary s1 = runSweep(plan, options(d1, 1));
    const SweepSummary s2 = runSweep(plan, options(d2, 2));
    EXPECT_EQ(s1.total, 6u);
    EXPECT_EQ(s1.failed, 0u);
    EXPECT_EQ(slurp(d1 + "/sweep.csv"), slurp(d2 + "/sweep.csv"));
    EXPECT_NE(slurp(d1 + "/sweep.csv").find("resistance_torque[N*m]"), std::string::npos);
}

TEST(SweepTest, SecondRunResumesEveryFinishedPoint) {
    const SweepPlan plan = smallGrid();
    const std::string d = freshDir("resume");
    runSweep(plan, options(d, 2));
    const std::string before = slurp(d + "/sweep.csv");
    std::filesystem::remove(d + "/points/000004.json");  // as if interrupted before point 4
    const SweepSummary again = runSweep(plan, options(d, 2));
    EXPECT_EQ(again.resumed, 5u);
    EXPECT_EQ(again.run, 1u);
    EXPECT_EQ(slurp(d + "/sweep.csv"), before);
}

TEST(SweepTest, ShardsMergeIntoTheUnshardedTable) {
    const SweepPlan plan = smallGrid();
    const std::string full = freshDir("full"), a = freshDir("shard0"), b = freshDir("shard1"), merged = freshDir("merged");
    runSweep(plan, options(full, 1));
    SweepOptions o0 = options(a, 1), o1 = options(b, 1);
    o0.shardIndex = 0;
    o0.shardCount = 2;
    o1.shardIndex = 1;
    o1.shardCount = 2;
    EXPECT_EQ(runSweep(plan, o0).total, 3u);
    EXPECT_EQ(runSweep(plan, o1).total, 3u);
    const SweepSummary m = mergeSweeps({a, b}, merged);
    EXPECT_EQ(m.total, 6u);
    EXPECT_EQ(slurp(merged + "/sweep.csv"), slurp(full + "/sweep.csv"));
}

TEST(SweepTest, BadPointIsRecordedWithItsDiagnosticAndTheOthersRun) {
    const SweepPlan plan = makeGrid({parseGrid("elements.belt.stiffness=-100 N*m/rad:500 N*m/rad:3")});
    const std::string d = freshDir("bad");
    const SweepSummary s = runSweep(plan, options(d, 2));
    EXPECT_EQ(s.total, 3u);
    EXPECT_EQ(s.failed, 1u);
    const std::string table = slurp(d + "/sweep.csv");
    EXPECT_NE(table.find("bad_input"), std::string::npos);
    EXPECT_NE(table.find("belt.stiffness: must be >= 0"), std::string::npos) << table;
}

}  // namespace
}  // namespace milldyn
