// issue 20 item 13 (plots a user reads): sweep plots against the swept
// parameters, mode-shape bars by body name, schematic labels that do not
// overprint. The pure parts (table reading, layout, grouping, label
// placement) are checked on hand-made inputs; the drawings are checked to be
// PNGs of a real size.
#include "driver/outputs/Schematic.h"
#include "driver/outputs/SweepPlots.h"
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

#include <unistd.h>

namespace milldyn {
namespace {

std::string freshDir(const std::string& name) {
    const std::string dir = std::filesystem::temp_directory_path().string() + "/milldyn-outputplots-" + name + "-" +
                            std::to_string(::getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

/// A PNG: the 8-byte signature, and more than a blank picture's few bytes.
void expectPng(const std::string& path) {
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    std::ifstream in(path, std::ios::binary);
    std::string head(8, '\0');
    in.read(&head[0], 8);
    EXPECT_EQ(head, std::string("\x89PNG\r\n\x1a\n", 8)) << path;
    EXPECT_GT(std::filesystem::file_size(path), 8000u) << path;
}

// A 3 x 2 grid, one failed point (no results, a diagnostic with commas and quotes).
const std::string kGrid =
    "index[1],elements.a.torque[N*m],elements.b.damping[SI],status,power_mean[W],speed[rad/s],diagnostic\n"
    "0,10,0.1,ok,100,5,\n"
    "1,10,0.5,ok,110,5.5,\n"
    "2,20,0.1,ok,200,6,\n"
    "3,20,0.5,failed,,,\"the motor stalled, at t = 1 s \"\"here\"\"\"\n"
    "4,30,0.1,ok,300,7,\n"
    "5,30,0.5,ok,330,7.5,\n";

TEST(SweepPlots, TableReadsInputsResultsAndGaps) {
    const SweepTable t = parseSweepTable(kGrid);
    EXPECT_EQ(t.inputNames, (std::vector<std::string>{"elements.a.torque", "elements.b.damping"}));
    EXPECT_EQ(t.inputUnits, (std::vector<std::string>{"N*m", "SI"}));
    EXPECT_EQ(t.resultNames, (std::vector<std::string>{"power_mean", "speed"}));
    EXPECT_EQ(t.resultUnits, (std::vector<std::string>{"W", "rad/s"}));
    ASSERT_EQ(t.inputs.size(), 6u);
    EXPECT_EQ(t.inputs[5], (std::vector<double>{30, 0.5}));
    EXPECT_DOUBLE_EQ(t.results[4][0], 300);
    EXPECT_TRUE(std::isnan(t.results[3][0]));
    EXPECT_THROW(parseSweepTable("a,b\n1,2\n"), std::invalid_argument);
    EXPECT_THROW(parseSweepTable(kGrid + "6,40,0.1,ok,1\n"), std::invalid_argument);
}

TEST(SweepPlots, GridIsToldFromASample) {
    EXPECT_EQ(inferSweepLayout(parseSweepTable(kGrid)), SweepLayout::Grid);
    const std::string lhs =
        "index[1],x[m],y[s],status,r[1],diagnostic\n0,1,0.3,ok,1,\n1,2,0.1,ok,2,\n2,3,0.2,ok,3,\n";
    EXPECT_EQ(inferSweepLayout(parseSweepTable(lhs)), SweepLayout::Sample);
}

TEST(SweepPlots, TwoAxisGridGivesALinePerValueOfTheSecondAxis) {
    const auto lines = sweepLines(parseSweepTable(kGrid), 1);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_DOUBLE_EQ(lines[0].first, 0.1);
    EXPECT_EQ(lines[0].second, (std::vector<std::size_t>{0, 2, 4}));
    EXPECT_DOUBLE_EQ(lines[1].first, 0.5);
    EXPECT_EQ(lines[1].second, (std::vector<std::size_t>{1, 3, 5}));
}

TEST(SweepPlots, FileStemsAreSafe) {
    EXPECT_EQ(plotFileStem("natural_frequency_1"), "natural_frequency_1");
    EXPECT_EQ(plotFileStem("a/b c"), "a_b_c");
}

TEST(SweepPlots, EveryResultIsDrawnForGridsAndSamples) {
    if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
    // 2-axis grid, 1-axis grid (unsorted rows), Latin hypercube.
    const std::string oneAxis = "index[1],x[m],status,r[W],diagnostic\n0,3,ok,9,\n1,1,ok,1,\n2,2,ok,4,\n";
    const std::string lhs =
        "index[1],x[m],y[s],status,r[1],q[1],diagnostic\n0,1,0.3,ok,1,,\n1,2,0.1,ok,2,,\n2,3,0.2,ok,3,,\n";
    for (const auto& [name, csv, layout, expected] :
         std::vector<std::tuple<std::string, std::string, SweepLayout, std::size_t>>{
             {"grid2", kGrid, SweepLayout::Infer, 2}, {"grid1", oneAxis, SweepLayout::Grid, 1},
             {"lhs", lhs, SweepLayout::Sample, 1}}) {
        const std::string dir = freshDir(name);
        writeText(dir + "/sweep.csv", csv);
        std::string warning;
        const auto files = writeSweepPlots(dir, layout, warning);
        ASSERT_EQ(files.size(), expected) << name << ": " << warning;
        for (const auto& f : files) expectPng(f);
        expectPng(dir + "/sweep_" + (name == "grid2" ? std::string("power_mean") : "r") + ".png");
        if (name == "lhs") {
            // q has no value anywhere: said, not drawn.
            EXPECT_NE(warning.find("q"), std::string::npos) << warning;
            EXPECT_FALSE(std::filesystem::exists(dir + "/sweep_q.png"));
        } else {
            EXPECT_EQ(warning, "") << name;
        }
        // Nothing but the table and the plots is left behind (no scripts).
        std::size_t entries = 0;
        for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
        EXPECT_EQ(entries, files.size() + 1) << name;
        std::filesystem::remove_all(dir);
    }
}

// Issue 29 item 3: a sweep wrote 56 PNGs, most of them energy bookkeeping.
// By default only the headline results are drawn; outputs.sweep_plots names
// others (a name, NAME* for a family, all).
TEST(SweepPlots, ByDefaultOnlyTheHeadlineResultsAreDrawn) {
    const std::string csv =
        "index[1],x[m],status,energy_balance_residual[J],energy_split.grinding[J],final.belt.torque[N*m],"
        "kinetic_energy_change[J],mean_power.motor_input[W],mean_power.residual[W],peak_drive_torque[N*m],"
        "power[W],start_time[s],diagnostic\n"
        "0,1,ok,1e-9,5,3,2,100,1e-6,40,90,1.5,\n1,2,ok,2e-9,6,4,3,110,2e-6,41,95,1.6,\n";
    const SweepTable t = parseSweepTable(csv);
    auto names = [&](const std::vector<std::size_t>& chosen) {
        std::vector<std::string> out;
        for (std::size_t r : chosen) out.push_back(t.resultNames[r]);
        return out;
    };
    std::vector<std::string> unmatched;
    const std::vector<std::string> headline = {"mean_power.motor_input", "peak_drive_torque", "power", "start_time"};
    EXPECT_EQ(names(selectSweepResults(t, {}, unmatched)), headline);
    EXPECT_EQ(names(selectSweepResults(t, {"headline"}, unmatched)), headline);
    EXPECT_EQ(selectSweepResults(t, {"all"}, unmatched).size(), 9u);
    EXPECT_EQ(names(selectSweepResults(t, {"power", "energy_split.*"}, unmatched)),
              (std::vector<std::string>{"energy_split.grinding", "power"}));
    EXPECT_TRUE(unmatched.empty());
    EXPECT_TRUE(selectSweepResults(t, {"nonesuch"}, unmatched).empty());
    EXPECT_EQ(unmatched, (std::vector<std::string>{"nonesuch"}));

    if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
    const std::string dir = freshDir("headline");
    writeText(dir + "/sweep.csv", csv);
    std::string warning;
    auto files = writeSweepPlots(dir, SweepLayout::Grid, warning);
    EXPECT_EQ(files.size(), 4u) << warning;
    for (const std::string& n : headline) expectPng(dir + "/sweep_" + n + ".png");
    EXPECT_FALSE(std::filesystem::exists(dir + "/sweep_energy_balance_residual.png"));
    std::size_t pngs = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) pngs += e.path().extension() == ".png";
    EXPECT_EQ(pngs, 4u);
    // A name that matches nothing is said.
    warning.clear();
    files = writeSweepPlots(dir, SweepLayout::Grid, warning, {"power", "nonesuch"});
    EXPECT_EQ(files.size(), 1u);
    EXPECT_NE(warning.find("no result named nonesuch"), std::string::npos) << warning;
    std::filesystem::remove_all(dir);
}

TEST(SweepPlots, MissingTableIsAWarningNotACrash) {
    const std::string dir = freshDir("missing");
    std::string warning;
    EXPECT_TRUE(writeSweepPlots(dir, SweepLayout::Infer, warning).empty());
    EXPECT_NE(warning.find("no sweep plots"), std::string::npos);
    std::filesystem::remove_all(dir);
}

AnalysisResult modeTable() {
    AnalysisResult r;
    r.tableName = "mode_shapes";
    r.columnNames = {"mode", "natural_frequency", "motor.rotor", "mill.drum", "pinion"};
    r.columnUnits = {"1", "Hz", "1", "1", "1"};
    r.rows = {{1, 0, 1, 1, 1}, {2, 14.25, 1, -0.2, 0.5}, {3, 80, 0.01, 1, -0.7}};
    return r;
}

TEST(ModeShapePlot, ABarChartPerModeWithBodiesByName) {
    const auto modes = modeShapeBars(modeTable());
    ASSERT_EQ(modes.size(), 3u);
    EXPECT_EQ(modes[1].title, "mode 2: 14.25 Hz");
    ASSERT_EQ(modes[1].bars.size(), 3u);
    EXPECT_EQ(modes[1].bars[1].first, "mill.drum");
    EXPECT_DOUBLE_EQ(modes[1].bars[1].second, -0.2);
    AnalysisResult other = modeTable();
    other.tableName = "timeseries";
    EXPECT_TRUE(modeShapeBars(other).empty());
}

TEST(ModeShapePlot, WritesAPng) {
    if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
    const std::string dir = freshDir("modes");
    std::string warning;
    const auto files = writePlots(dir, dir + "/mode_shapes.csv", modeTable(), warning);
    ASSERT_EQ(files, (std::vector<std::string>{dir + "/mode_shapes.png"})) << warning;
    expectPng(files[0]);
    std::filesystem::remove_all(dir);
}

TEST(LabelPlacement, OverlapIsStrict) {
    EXPECT_TRUE(labelBoxesOverlap({0, 0, 10, 10}, {5, 5, 10, 10}));
    EXPECT_FALSE(labelBoxesOverlap({0, 0, 10, 10}, {10, 0, 10, 10}));  // touching
    EXPECT_FALSE(labelBoxesOverlap({0, 0, 10, 10}, {0, 20, 10, 10}));
}

TEST(LabelPlacement, FreeLabelsStayAndOverlappingOnesMoveClear) {
    // Three labels at one place and one far away.
    const std::vector<LabelBox> wanted = {{100, 100, 60, 11}, {110, 102, 60, 11}, {100, 100, 40, 11}, {400, 300, 50, 11}};
    const auto placed = placeLabels(wanted);
    ASSERT_EQ(placed.size(), wanted.size());
    EXPECT_DOUBLE_EQ(placed[0].y, 100);  // the first keeps its place
    EXPECT_DOUBLE_EQ(placed[3].x, 400);  // so does one nobody overlaps
    EXPECT_DOUBLE_EQ(placed[3].y, 300);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        EXPECT_DOUBLE_EQ(placed[i].width, wanted[i].width);
        for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(labelBoxesOverlap(placed[i], placed[j])) << i << " " << j;
    }
    // The nearest free place: one step of height + 2 px.
    EXPECT_DOUBLE_EQ(placed[1].y, 102 + 13);
}

TEST(LabelPlacement, TextBoxFollowsTheAnchor) {
    const LabelBox start = textBox("abcd", 50, 100, 10, false), middle = textBox("abcd", 50, 100, 10, true);
    EXPECT_DOUBLE_EQ(start.x, 50);
    EXPECT_DOUBLE_EQ(middle.x + middle.width / 2, 50);
    EXPECT_DOUBLE_EQ(start.y + start.height, 100 + 0.2 * 10);
    EXPECT_DOUBLE_EQ(textBox("αβ", 0, 0, 10, false).width, textBox("ab", 0, 0, 10, false).width);  // UTF-8
}

TEST(LabelPlacement, SchematicLabelsOfConcentricCirclesDoNotOverprint) {
    // Two circles of one radius at one centre (a pinion and a drum drawn on
    // one axis): their labels would land on the same spot.
    SchematicFrame f;
    f.drawn = true;
    for (const char* name : {"pinion_gear", "drum_shell"}) {
        Sketch::Shape s;
        s.kind = Sketch::Kind::Circle;
        s.role = "drum";
        s.label = name;
        s.radius = 1;
        f.shapes.push_back(s);
    }
    const std::string svg = renderSchematicSvg(f, "t", "c", 0, 0);
    const std::regex text(R"re(<text class="label" x="([-0-9.]+)" y="([-0-9.]+)" font-size="11"[^>]*>([^<]*)<)re");
    std::vector<LabelBox> boxes;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it)
        boxes.push_back(textBox((*it)[3], std::stod((*it)[1]), std::stod((*it)[2]), 11, false));
    ASSERT_EQ(boxes.size(), 2u) << svg;
    EXPECT_FALSE(labelBoxesOverlap(boxes[0], boxes[1]));
}

}  // namespace
}  // namespace milldyn
