// Issue 26 items 4, 8 and 9 through the built milldyn: tables of one shape
// whatever the names hold, sweeps that refuse what they would ignore, plots
// that fail as a set, staging directories a SIGKILL left, output
// directories whose names hold '$' or a line break. Issue 29 item 4: the
// sweep options docs/sweeps.md lists. (ctest: reliability_cli.)

#include "driver/outputs/OutputSet.h"
#include "driver/outputs/Writers.h"
#include "tests/driver/BinaryRunFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

namespace fs = std::filesystem;

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";

class ReliabilityCliOutputs : public test::BinaryRunFixture {
protected:
    ReliabilityCliOutputs() : BinaryRunFixture("outputs") {}

    /// A stand-in for gnuplot on PATH, running `body` (sh).
    std::string fakeTool(const std::string& name, const std::string& body) const {
        const fs::path bin = m_dir / "bin";
        fs::create_directories(bin);
        std::ofstream(bin / name) << "#!/bin/sh\n" << body << "\n";
        fs::permissions(bin / name, fs::perms::owner_all);
        return "PATH=" + bin.string() + ":$PATH ";
    }

    /// A motor and a load named `load` on one shaft, from steady running.
    fs::path shaftModel(const std::string& load, const std::string& extra = "") const {
        const fs::path model = m_dir / "shaft.yaml";
        std::ofstream(model)
            << "format_version: 1\nname: one shaft\nbodies:\n"
               "  - {name: shaft, inertia: 10 kg*m^2, joint: {type: pin, parent: ground}}\n"
               "elements:\n"
               "  - {type: InductionMotor, name: motor, body: shaft, rated_torque: 1000 N*m, rated_speed: 990 rpm, "
               "synchronous_speed: 1000 rpm}\n"
               "  - {type: ResistanceTorque, name: "
            << load << ", body: shaft, constant_torque: 500 N*m}\n"
            << "scenario: {analysis: transient, initial_state: steady, end_time: 0.05 s}\n"
               "outputs: {sample_interval: 10 ms" << extra << "}\n";
        return model;
    }

    static std::vector<std::string> stagingIn(const fs::path& dir) {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(dir)) {
            const std::string n = e.path().filename().string();
            if (n.find(".milldyn-staging") != std::string::npos || n.find(".tmp.") != std::string::npos) out.push_back(n);
        }
        return out;
    }
};

// 26.4: an element named `lo,ad` gave a 10-field header over 8-field rows; a
// line break in a name split the header.
TEST_F(ReliabilityCliOutputs, NamesWithCommasQuotesOrLineBreaksKeepTheTableInShape) {
    for (const std::string name : {"\"lo,ad\"", "\"say \\\"hi\\\"\"", "\"new\\nline\""}) {
        const fs::path model = shaftModel(name);
        const auto r = run("", "run " + model.string() + " --out " + (m_dir / "o").string());
        ASSERT_EQ(r.code, 0) << name << ": " << r.err;
        const auto records = parseCsv(test::slurp((m_dir / "o" / "timeseries.csv").string()));
        ASSERT_GT(records.size(), 2u);
        for (const auto& rec : records) ASSERT_EQ(rec.size(), records.front().size()) << name;
        if (gnuplotAvailable()) {
            EXPECT_TRUE(fs::exists(m_dir / "o" / "torques.png")) << name;
        }
    }
    // The sweep's table likewise, with the name in its input path.
    const fs::path model = shaftModel("\"lo,ad\"", ", plots: false");
    const auto r = run("", "sweep " + model.string() + " --grid 'elements.lo,ad.constant_torque=400 N*m:500 N*m:2' "
                           "--jobs 1 --no-plots --out " + (m_dir / "s").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto records = parseCsv(test::slurp((m_dir / "s" / "sweep.csv").string()));
    ASSERT_EQ(records.size(), 3u);
    for (const auto& rec : records) EXPECT_EQ(rec.size(), records.front().size());
    EXPECT_EQ(records[0][1], "elements.lo,ad.constant_torque[N*m]");
}

// 26.4: the same --grid path twice swept a table whose first axis was never
// used; a --set of a swept path was silently overridden.
TEST_F(ReliabilityCliOutputs, APathSweptTwiceOrSetAndSweptIsRefused) {
    const std::string out = " --out " + (m_dir / "s").string();
    auto r = run("", "sweep " + kModel + " --grid 'elements.grinding.constant_torque=10 N*m:20 N*m:2' "
                     "--grid 'elements.grinding.constant_torque=30 N*m:40 N*m:2'" + out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("is swept twice"), std::string::npos) << r.err;
    r = run("", "sweep " + kModel + " --grid 'elements.grinding.constant_torque=10 N*m:20 N*m:2' "
                "--set 'elements.grinding.constant_torque=5 N*m'" + out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("is set and swept"), std::string::npos) << r.err;
    r = run("", "sweep " + kModel + " --grid 'scenario.end_time=1 s:2 s:2' --end-time 3" + out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("scenario.end_time is set and swept"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(m_dir / "s" / "sweep-plan.json"));  // refused before the directory was claimed
}

// 26.9: `--set outputs.plots=false` changed the sweep's digest (its resume
// was refused) where `--no-plots` did not.
TEST_F(ReliabilityCliOutputs, PlotsAreNoPartOfASweepsIdentity) {
    const std::string sweep = "sweep " + kModel + " --grid 'elements.grinding.constant_torque=10 N*m:12 N*m:2' "
                              "--set 'scenario.end_time=0.3 s' --set scenario.initial_state=steady --jobs 1 --out " +
                              (m_dir / "s").string();
    auto r = run("", sweep + " --set outputs.plots=false");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("(2 run, 0 resumed)"), std::string::npos) << r.out;
    r = run("", sweep + " --no-plots");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("(0 run, 2 resumed)"), std::string::npos) << r.out;
    r = run("", sweep + " --set outputs.plots=true --no-plots");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("(0 run, 2 resumed)"), std::string::npos) << r.out;
    // What the points compute is the identity: another accuracy is another sweep.
    r = run("", sweep + " --no-plots --accuracy 1e-5");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("holds another sweep"), std::string::npos) << r.err;
}

// 29.4: `sweep --accuracy/--integrator/--end-time`, as docs/sweeps.md lists
// them; value lists, log spacing and tied paths on the command line.
TEST_F(ReliabilityCliOutputs, SweepTakesTheRunOptionsListsLogGridsAndTiedPaths) {
    auto r = run("", "sweep " + kModel + " --grid 'elements.grinding.constant_torque=10 N*m,14 N*m,12 N*m' "
                     "--set scenario.initial_state=steady --end-time 0.3 --accuracy 1e-5 --integrator RungeKuttaMerson "
                     "--jobs 1 --no-plots --out " + (m_dir / "a").string());
    ASSERT_EQ(r.code, 0) << r.err;
    auto records = parseCsv(test::slurp((m_dir / "a" / "sweep.csv").string()));
    ASSERT_EQ(records.size(), 4u);
    EXPECT_EQ(records[2][1], "14");
    const std::string plan = test::slurp((m_dir / "a" / "sweep-plan.json").string());
    EXPECT_NE(plan.find("integrator.accuracy=1e-5"), std::string::npos) << plan;
    EXPECT_NE(plan.find("scenario.end_time=0.3 s"), std::string::npos) << plan;
    r = run("", "sweep " + kModel + " --grid 'elements.grinding.constant_torque=1 N*m:100 N*m:3:log;"
                "elements.motor.rated_torque=36 N*m:38 N*m:3' --set scenario.initial_state=steady --end-time 0.2 "
                "--jobs 1 --no-plots --out " + (m_dir / "b").string());
    ASSERT_EQ(r.code, 0) << r.err;
    records = parseCsv(test::slurp((m_dir / "b" / "sweep.csv").string()));
    ASSERT_EQ(records.size(), 4u);  // one tied axis of 3 values: 3 points, not 9
    EXPECT_EQ(records[1][1], "1");
    EXPECT_EQ(records[2][1], "10");
    EXPECT_EQ(records[3][1], "100");
    EXPECT_EQ(records[2][2], "37");
}

// 26.8: a full disk while plotting gave exit 0, the plots missing, and named
// only the last. Here gnuplot leaves a truncated torques.png (as it does on
// a full disk, exiting 0) and draws the others.
TEST_F(ReliabilityCliOutputs, APlotNotDrawnFailsTheSetAndEveryMissingPlotIsNamed) {
    const std::string good =
        "printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\0IEND\\256B`\\202' > \"$out\"";
    const std::string out = (m_dir / "o").string();
    auto r = run(fakeTool("gnuplot", "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\"); " + good),
                 "run " + kModel + " --end-time '0.2 s' --out " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string before = test::slurp(out + "/timeseries.csv");
    fs::remove_all(m_dir / "bin");
    r = run(fakeTool("gnuplot", "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\"); "
                                "case \"$out\" in torques*|speeds*) printf '\\211PNG' > \"$out\" ;; *) " + good +
                                " ;; esac"),
            "run " + kModel + " --end-time '0.3 s' --out " + out);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("speeds.png, torques.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("2 of "), std::string::npos) << r.err;
    EXPECT_EQ(test::slurp(out + "/timeseries.csv"), before);  // the old set untouched
    EXPECT_TRUE(fs::exists(out + "/speeds.png"));
    EXPECT_TRUE(stagingIn(out).empty());
}

// 26.8: SIGKILL leaves `.milldyn-staging.PID.N` (no handler runs); the next
// run in that directory removes it.
TEST_F(ReliabilityCliOutputs, StagingLeftBySigkillIsRemovedByTheNextRun) {
    const std::string out = (m_dir / "o").string();
    const fs::path code = m_dir / "code", script = m_dir / "kill.sh";
    std::ofstream(script) << fakeTool("gnuplot", "exec sleep 5") << MILLDYN_BINARY << " run " << kModel
                          << " --end-time '0.2 s' --out " << out << " </dev/null >/dev/null 2>&1 &\np=$!\n"
                          << "for i in $(seq 100); do ls -a " << out
                          << " 2>/dev/null | grep -q staging && break; sleep 0.1; done\nsleep 0.5\nkill -KILL $p\nwait $p\ntrue\n";
    ASSERT_EQ(std::system(("sh " + script.string()).c_str()), 0);
    ASSERT_FALSE(stagingIn(out).empty());
    const auto r = run("", "run " + kModel + " --end-time '0.2 s' --set outputs.plots=false --out " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(stagingIn(out).empty());
    EXPECT_TRUE(fs::exists(out + "/timeseries.csv"));
}

// 26.8: `--out` paths with '$' (gnuplot read 'a$b/...' as a data block) or a
// line break (it ended gnuplot's command) lost their plots.
TEST_F(ReliabilityCliOutputs, OutDirectoriesWithDollarOrLineBreakGetTheirPlots) {
    if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
    for (const std::string name : {"$HOME", "two\nlines", "it's"}) {
        const fs::path dir = m_dir / name;
        fs::create_directories(dir);
        std::ofstream(m_dir / "outname") << dir.string();
        const auto r = run("", "run " + kModel + " --end-time '0.2 s' --out \"$(cat " + (m_dir / "outname").string() +
                                   ")\"");
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(isCompletePng((dir / "speeds.png").string())) << name;
        EXPECT_TRUE(isCompletePng((dir / "torques.png").string())) << name;
    }
}

}  // namespace
}  // namespace milldyn
