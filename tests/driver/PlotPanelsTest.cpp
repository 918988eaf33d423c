// issue 20 item 13: one panel per group of like magnitudes, each with its
// own axis, so a 1.9 rad/s mill beside a 157 rad/s motor is no flat line.
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace milldyn
