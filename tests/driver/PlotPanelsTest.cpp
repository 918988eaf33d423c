// issue 20 item 13: one panel per group of like magnitudes, each with its
// own axis, so a 1.9 rad/s mill beside a 157 rad/s motor is no flat line.
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace milldyn {
namespace {

AnalysisResult table(const std::vector<std::vector<double>>& rows) {
    AnalysisResult r;
    r.rows = rows;
    return r;
}

TEST(PlotPanels, MillAndMotorSpeedsGetAPanelEach) {
    // time, motor 157 rad/s, mill 1.9 rad/s, a second motor-like 150.
    const AnalysisResult r = table({{0, 0, 0, 0}, {1, 157, 1.9, 150}, {2, 156, -1.8, 149}});
    const auto panels = plotPanels(r, {1, 2, 3});
    ASSERT_EQ(panels.size(), 2u);
    EXPECT_EQ(panels[0], (std::vector<std::size_t>{1, 3}));
    EXPECT_EQ(panels[1], (std::vector<std::size_t>{2}));
}

TEST(PlotPanels, LikeMagnitudesAndZeroColumnsShareOnePanel) {
    const AnalysisResult r = table({{0, 10, 0, -50}, {1, 20, 0, 30}});
    const auto panels = plotPanels(r, {1, 2, 3});
    ASSERT_EQ(panels.size(), 1u);
    EXPECT_EQ(panels[0], (std::vector<std::size_t>{1, 2, 3}));
}

// torques.png labelled every tick "500" for a constant 500 N*m column
// (gnuplot widens an almost-flat range and its 6-digit tick format cannot
// tell the ticks apart).
TEST(PlotPanels, AConstantColumnIsDrawnOnAFivePercentAxis) {
    const AnalysisResult r = table({{0, 500}, {1, 500}, {2, 500}});
    EXPECT_EQ(panelYAxisCommands(r, {1}, 1.0), "set yrange [475:525]\nset format y '% h'\n");
    const AnalysisResult zero = table({{0, 0}, {1, 0}});
    EXPECT_EQ(panelYAxisCommands(zero, {1}, 1.0), "set yrange [-1:1]\nset format y '% h'\n");
}

TEST(PlotPanels, ANarrowBandGetsDigitsThatTellItsTicksApart) {
    const AnalysisResult r = table({{0, 500.0001}, {1, 500.0002}});
    const std::string cmd = panelYAxisCommands(r, {1}, 1.0);
    const auto at = cmd.find("set format y '%.");
    ASSERT_NE(at, std::string::npos) << cmd;
    const std::string format = cmd.substr(at + 14, cmd.find('\'', at + 14) - at - 14);
    // Ticks a fifth of the band apart must print differently.
    char a[64], b[64];
    std::snprintf(a, sizeof a, format.c_str(), 500.0001);
    std::snprintf(b, sizeof b, format.c_str(), 500.0001 + 0.2e-4);
    EXPECT_STRNE(a, b) << format;
    // An ordinary range keeps gnuplot's own format.
    EXPECT_EQ(panelYAxisCommands(table({{0, 10}, {1, 20}}), {1}, 1.0), "set autoscale y\nset format y '% h'\n");
}

}  // namespace
}  // namespace milldyn
