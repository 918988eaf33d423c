// Issue 20 item 13: charge lags are plotted in the engineer's convention,
// the one the model's `lag_from` names, in degrees, with the y axis saying
// which convention it is (docs/charges.md).
#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace milldyn {
namespace {

/// The belt-drive planetary mill started from rest for 0.2 s, its charges
/// free to swing (`elastic` level, dynamic_lag) unless `held` (the `paper`
/// level, lag 130 deg), lag_from set on both charges unless empty (then
/// `auto`: carrier_radius on a carried drum).
AnalysisResult runBeltMill(const std::string& lagFrom, bool held = false) {
    std::vector<Override> o = {{"fidelity.level", held ? "paper" : "elastic"},
                               {"scenario.analysis", "transient"},
                               {"scenario.end_time", "0.2 s"},
                               {"scenario.initial_state", "rest"}};
    if (!lagFrom.empty()) {
        o.push_back({"elements.charge1.lag_from", lagFrom});
        o.push_back({"elements.charge2.lag_from", lagFrom});
    }
    return runAnalysis(
        readModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/planetary_belt_200x1000.yaml", defaultModelReader(), o));
}

/// The charge_lags plot's gnuplot commands; empty if there is no such plot.
std::string lagPlot(const AnalysisResult& r) {
    for (const auto& p : r.plots)
        if (p.first == "charge_lags") return formatPlotCommands(r, p.first, p.second, "timeseries.csv");
    return "";
}

TEST(LagPlotLabel, AxisNamesTheCarrierRadiusConventionOnACarriedDrum) {
    const AnalysisResult r = runBeltMill("");  // auto
    const std::string gp = lagPlot(r);
    ASSERT_FALSE(gp.empty()) << "no charge_lags plot";
    EXPECT_NE(gp.find("set ylabel 'lag from leading tangent to carrier radius (lag_from: carrier_radius) [deg]'"),
              std::string::npos)
        << gp;
    // Both charges' columns, drawn in degrees.
    const std::size_t c1 = r.findColumn("charge1.lag"), c2 = r.findColumn("charge2.lag");
    ASSERT_NE(c1, std::string::npos);
    ASSERT_NE(c2, std::string::npos);
    EXPECT_NE(gp.find("using 1:($" + std::to_string(c1 + 1) + "*180/pi)"), std::string::npos) << gp;
    EXPECT_NE(gp.find("using 1:($" + std::to_string(c2 + 1) + "*180/pi)"), std::string::npos) << gp;
}

TEST(LagPlotLabel, AxisFollowsLagFromVertical) {
    const AnalysisResult r = runBeltMill("vertical");
    const std::string gp = lagPlot(r);
    ASSERT_FALSE(gp.empty()) << "no charge_lags plot";
    EXPECT_NE(gp.find("set ylabel 'lag from downward vertical, + turning (lag_from: vertical) [deg]'"),
              std::string::npos)
        << gp;
    EXPECT_EQ(gp.find("carrier_radius"), std::string::npos) << gp;
}

TEST(LagPlotLabel, HeldLagsAreNotPlotted) {
    // A held charge's lag is the model's number (130 deg) at every sample:
    // a flat line, no plot.
    const AnalysisResult r = runBeltMill("", true);
    ASSERT_NE(r.findColumn("charge1.lag"), std::string::npos);
    EXPECT_NEAR(r.value(r.rows.size() - 1, "charge1.lag"), 130 * M_PI / 180, 1e-9);
    EXPECT_TRUE(lagPlot(r).empty());
}

TEST(LagPlotLabel, PanelOfUnlabelledColumnsKeepsThePlotTitle) {
    AnalysisResult r;
    r.columnNames = {"time", "a.speed", "b.speed"};
    r.columnUnits = {"s", "rad/s", "rad/s"};
    r.rows = {{0, 1, 2}, {1, 2, 3}};
    const std::string gp = formatPlotCommands(r, "speeds", {1, 2}, "x.csv");
    EXPECT_NE(gp.find("set ylabel 'speeds [rad/s]'"), std::string::npos) << gp;
    EXPECT_NE(gp.find("using 1:2 with lines"), std::string::npos) << gp;
}

}  // namespace
}  // namespace milldyn
