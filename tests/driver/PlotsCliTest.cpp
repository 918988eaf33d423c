// issue 20 item 13 through the CLI: a sweep writes its plots (the headline
// results, issue 29 item 3) unless
// --no-plots or outputs.plots: false says not to; linearize draws its mode
// shapes by body name.
#include "tests/driver/BinaryRunFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace milldyn {
namespace {

const std::string kBurr = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";
const std::string kGrid =
    " --set 'scenario.end_time=0.3 s' --set scenario.initial_state=steady"
    " --grid 'elements.grinding.constant_torque=10 N*m:30 N*m:2' --jobs 1 --quiet";

class CliPlots : public test::BinaryRunFixture {
protected:
    CliPlots() : BinaryRunFixture("plotscli") {}

    std::size_t plotsIn(const std::string& dir, const std::string& prefix) const {
        std::size_t n = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            if (name.rfind(prefix, 0) == 0 && e.path().extension() == ".png") {
                std::ifstream in(e.path(), std::ios::binary);
                std::string head(4, '\0');
                in.read(&head[0], 4);
                EXPECT_EQ(head, "\x89PNG") << name;
                EXPECT_GT(std::filesystem::file_size(e.path()), 8000u) << name;
                ++n;
            }
        }
        return n;
    }
    /// The number of result columns of DIR/sweep.csv (between status and diagnostic).
    std::size_t resultsIn(const std::string& dir) const {
        std::ifstream in(dir + "/sweep.csv");
        std::string header;
        std::getline(in, header);
        const auto status = header.find(",status,");
        std::size_t n = 0;
        for (std::size_t i = status + 8; i < header.size(); ++i) n += header[i] == ',';
        return n;
    }
};

// Issue 29 item 3: by default the headline results only (no energy
// bookkeeping, no last-instant values); outputs.sweep_plots names others.
TEST_F(CliPlots, SweepWritesTheHeadlinePlotsByDefaultAndTheNamedOnesOnRequest) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    const std::string out = (m_dir / "sweep").string();
    const auto r = run("", "sweep " + kBurr + kGrid + " --out " + out);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    // The bookkeeping, by this test's own reading of the header.
    std::ifstream in(out + "/sweep.csv");
    std::string header;
    std::getline(in, header);
    std::size_t headline = 0, bookkeeping = 0;
    for (std::size_t at = header.find(",status,") + 8, end; at < header.size(); at = end + 1) {
        end = header.find(',', at);
        if (end == std::string::npos) break;  // the diagnostic
        const std::string name = header.substr(at, header.find('[', at) - at);
        const bool energy = name.rfind("energy", 0) == 0 || name.find("_energy_change") != std::string::npos ||
                            name.rfind("final.", 0) == 0 ||
                            (name.rfind("mean_power.", 0) == 0 && name != "mean_power.motor_input" &&
                             name != "mean_power.shaft_input");
        (energy ? bookkeeping : headline) += 1;
        EXPECT_EQ(std::filesystem::exists(out + "/sweep_" + name + ".png"), !energy) << name;
    }
    EXPECT_GT(headline, 0u);
    EXPECT_GT(bookkeeping, headline);  // most of what a sweep reports is bookkeeping
    EXPECT_EQ(plotsIn(out, "sweep_"), headline) << r.err;

    // Named: `all`, and a family with a name. The --set is no part of the
    // sweep's identity: the same directory is the same sweep (another one
    // would be refused, exit 2), only the plots are drawn anew.
    const auto all = run("", "sweep " + kBurr + kGrid + " --set outputs.sweep_plots=all --out " + out);
    ASSERT_EQ(all.code, 0) << all.out << all.err;
    EXPECT_EQ(plotsIn(out, "sweep_"), resultsIn(out));
    const std::string named = (m_dir / "named").string();
    const auto some = run("", "sweep " + kBurr + kGrid + " --set 'outputs.sweep_plots=power,energy_split.*' --out " + named);
    ASSERT_EQ(some.code, 0) << some.out << some.err;
    std::size_t split = 0;
    for (const auto& e : std::filesystem::directory_iterator(named))
        split += e.path().filename().string().rfind("sweep_energy_split.", 0) == 0;
    EXPECT_GT(split, 0u);
    EXPECT_TRUE(std::filesystem::exists(named + "/sweep_power.png"));
    EXPECT_EQ(plotsIn(named, "sweep_"), split + 1);
}

TEST_F(CliPlots, NoPlotsAndOutputsPlotsFalseAreRespected) {
    for (const std::string& option : {std::string(" --no-plots"), std::string(" --set outputs.plots=false")}) {
        const std::string out = (m_dir / ("sweep" + std::to_string(option.size()))).string();
        const auto r = run("", "sweep " + kBurr + kGrid + option + " --out " + out);
        ASSERT_EQ(r.code, 0) << option << r.out << r.err;
        EXPECT_GT(resultsIn(out), 0u) << option;  // there was something to draw
        EXPECT_EQ(plotsIn(out, "sweep_"), 0u) << option;
    }
}

// Issue 29 item 3: a run draws the figures per question it has data for.
TEST_F(CliPlots, RunDrawsTheFiguresItHasDataFor) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    const std::string start = (m_dir / "start").string();
    auto r = run("", "run " + std::string(MILLDYN_SOURCE_DIR) + "/models/start_bench_star_delta.yaml --quiet --out " + start);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    for (const std::string name : {"start", "currents", "torques", "speeds"}) EXPECT_EQ(plotsIn(start, name + ".png"), 1u) << name;
    EXPECT_EQ(plotsIn(start, "steady"), 0u);  // no periodic load
    EXPECT_EQ(plotsIn(start, "belts"), 0u);   // no belt
    const std::string jaw = (m_dir / "jaw").string();
    r = run("", "run " + std::string(MILLDYN_SOURCE_DIR) + "/models/jaw_crusher_900x600.yaml --quiet --out " + jaw);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    for (const std::string name : {"start", "currents", "torques", "steady", "belts"}) EXPECT_EQ(plotsIn(jaw, name + ".png"), 1u) << name;
}

TEST_F(CliPlots, LinearizeDrawsModeShapesByBody) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    const std::string out = (m_dir / "modes").string();
    const auto r = run("", "run " + std::string(MILLDYN_SOURCE_DIR) +
                               "/models/tumbling_ball_mill_3x4m.yaml --scenario modes --quiet --out " + out);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_EQ(plotsIn(out, "mode_shapes"), 1u);
}

}  // namespace
}  // namespace milldyn
