// issue 20 item 13 through the CLI: a sweep writes a plot per result unless
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

TEST_F(CliPlots, SweepWritesAPlotPerResult) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    const std::string out = (m_dir / "sweep").string();
    const auto r = run("", "sweep " + kBurr + kGrid + " --out " + out);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_GT(resultsIn(out), 0u);
    EXPECT_EQ(plotsIn(out, "sweep_"), resultsIn(out)) << r.err;
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
