// Issue 29 item 3: plots per question. The torques of each shaft in a panel
// of their own with the sum of its loads, the start with the verdict's
// instants, steady operation over whole load periods, belt tensions and
// currents — checked on the figures' structure and on the gnuplot commands
// drawn from it (driver/outputs/Writers: formatFigureCommands).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/Writers.h"

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

/// Two shafts joined by a coupling: the motor shaft m carries the motor and
/// a fan, the mill d a periodic load (period 2π/31.4159 = 0.2 s) and its
/// bearings. Every torque and the shaft it acts on, as this file says it.
const char* kTwoShafts = R"(format_version: 1
name: two shafts, a coupling, two loads on the mill
bodies:
  - {name: m, inertia: 10 kg*m^2, joint: {type: pin, parent: ground}}
  - {name: d, inertia: 40 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: InductionMotor, name: motor, body: m, law: linear, rated_torque: 1000 N*m,
     rated_speed: 1450 rpm, synchronous_speed: 1500 rpm}
  - {type: TorsionalCoupling, name: coupling, bodies: [m, d], stiffness: 1e5 N*m/rad, damping: 100 N*m*s/rad}
  - {type: ResistanceTorque, name: fan, body: m, constant_torque: 50 N*m}
  - {type: PeriodicLoad, name: load, bodies: [d], rows: 1, mean_torque: 600 N*m,
     amplitudes: [1500 N*m], fundamental_frequency: 31.41592653589793 rad/s}
  - {type: ResistanceTorque, name: bearings, body: d, constant_torque: 80 N*m}
scenario: {analysis: transient, initial_state: steady, end_time: 2 s, hold_time: 1 s, speed_body: d}
integrator: {name: RungeKuttaMerson, accuracy: 1e-8}
outputs: {sample_interval: 5 ms, plots: false}
)";
const std::map<std::string, std::string> kShaftOf = {{"motor.torque", "m"},    {"fan.torque", "m"},
                                                     {"coupling.torque", "m"}, {"load.torque", "d"},
                                                     {"bearings.torque", "d"}};

const PlotFigure* figure(const AnalysisResult& r, const std::string& name) {
    for (const auto& f : r.figures)
        if (f.name == name) return &f;
    return nullptr;
}

/// The `using` expressions of every curve a figure's commands plot, in order.
std::vector<std::string> usingExpressions(const std::string& commands) {
    std::vector<std::string> out;
    const std::regex re(R"(using (\S+) with lines)");
    for (auto it = std::sregex_iterator(commands.begin(), commands.end(), re); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1]);
    return out;
}

/// Evaluates `1:($a+$b+...)` or `1:a` on one CSV record (fields as text).
double evaluateUsing(const std::string& expr, const std::vector<std::string>& record) {
    std::string y = expr.substr(expr.find(':') + 1);
    if (y.front() != '(') return std::stod(record.at(std::stoul(y) - 1));
    y = y.substr(1, y.size() - 2);
    double sum = 0;
    std::size_t at = 0;
    while ((at = y.find('$', at)) != std::string::npos) {
        std::size_t end = at + 1;
        while (end < y.size() && std::isdigit(static_cast<unsigned char>(y[end]))) ++end;
        sum += std::stod(record.at(std::stoul(y.substr(at + 1, end - at - 1)) - 1));
        at = end;
    }
    return sum;
}

TEST(PlotFigures, TorquesGetOnePanelPerShaftAndTheSumOfItsLoads) {
    const AnalysisResult r = runAnalysis(readModelText(kTwoShafts, "two.yaml", defaultModelReader()));
    const PlotFigure* torques = figure(r, "torques");
    ASSERT_NE(torques, nullptr);
    // One panel per shaft, each holding only torques on that shaft.
    ASSERT_EQ(torques->panels.size(), 2u);
    std::set<std::string> shafts;
    for (const auto& panel : torques->panels) {
        shafts.insert(panel.shaft);
        for (const auto& curve : panel.curves)
            for (std::size_t col : curve.columns) {
                const auto known = kShaftOf.find(r.columnNames[col]);
                ASSERT_NE(known, kShaftOf.end()) << r.columnNames[col];
                EXPECT_EQ(known->second, panel.shaft) << r.columnNames[col] << " drawn in " << panel.title;
            }
    }
    EXPECT_EQ(shafts, (std::set<std::string>{"m", "d"}));
    // d's panel: its two loads and their sum; m has one load, no sum.
    const PlotPanel& d = torques->panels[0].shaft == "d" ? torques->panels[0] : torques->panels[1];
    const PlotPanel& m = torques->panels[0].shaft == "m" ? torques->panels[0] : torques->panels[1];
    EXPECT_EQ(m.curves.size(), 3u);  // motor, coupling, fan
    ASSERT_EQ(d.curves.size(), 3u);  // load, bearings, their sum
    const PlotCurve& sum = d.curves.back();
    std::set<std::string> summed;
    for (std::size_t col : sum.columns) summed.insert(r.columnNames[col]);
    EXPECT_EQ(summed, (std::set<std::string>{"load.torque", "bearings.torque"}));

    // The commands gnuplot runs: the sum curve's expression, evaluated on
    // the CSV as written, equals the sum of the two load columns there.
    const std::string csv = formatCsv(r.columnNames, r.columnUnits, r.rows);
    const std::string commands = formatFigureCommands(r, *torques, "timeseries.csv");
    EXPECT_EQ(std::count(commands.begin(), commands.end(), '\n') > 0, true);
    EXPECT_NE(commands.find("set multiplot layout 2,1"), std::string::npos) << commands;
    EXPECT_NE(commands.find("'sum of the 2 loads on d'"), std::string::npos) << commands;
    const auto exprs = usingExpressions(commands);
    ASSERT_EQ(exprs.size(), 6u) << commands;
    const std::string sumExpr = exprs[torques->panels[0].shaft == "d" ? 2 : 5];
    EXPECT_EQ(sumExpr.substr(0, 4), "1:($") << sumExpr;
    const auto records = parseCsv(csv);
    const auto header = records.front();
    const std::size_t load = std::find(header.begin(), header.end(), "load.torque[N*m]") - header.begin();
    const std::size_t bearings = std::find(header.begin(), header.end(), "bearings.torque[N*m]") - header.begin();
    ASSERT_LT(load, header.size());
    ASSERT_LT(bearings, header.size());
    double largestLoad = 0;
    for (std::size_t k = 1; k < records.size(); ++k) {
        const double expected = std::stod(records[k][load]) + std::stod(records[k][bearings]);
        EXPECT_NEAR(evaluateUsing(sumExpr, records[k]), expected, 1e-12 * std::abs(expected)) << k;
        largestLoad = std::max(largestLoad, std::stod(records[k][load]));
    }
    EXPECT_GT(largestLoad, 2000.0);  // the periodic load did ripple: 600 + 1500 at its crest
}

TEST(PlotFigures, SteadyFigureShowsWholeLoadPeriodsOfTheSteadyWindow) {
    const AnalysisResult r = runAnalysis(readModelText(kTwoShafts, "two.yaml", defaultModelReader()));
    const PlotFigure* steady = figure(r, "steady");
    ASSERT_NE(steady, nullptr);
    // Whole periods of 0.2 s (at most 3) ending in the hold window [1, 2] s.
    const double periods = (steady->xTo - steady->xFrom) / 0.2;
    EXPECT_NEAR(periods, std::round(periods), 1e-6) << steady->xFrom << " " << steady->xTo;
    EXPECT_GE(std::round(periods), 1.0);
    EXPECT_LE(std::round(periods), 3.0);
    EXPECT_GE(steady->xFrom, 1.0 - 1e-9);
    EXPECT_LE(steady->xTo, 2.0 + 1e-9);
    // The loads' sum of the mill among its panels, and the x range drawn.
    bool sumOfLoads = false;
    for (const auto& panel : steady->panels)
        for (const auto& curve : panel.curves) sumOfLoads = sumOfLoads || (curve.columns.size() == 2 && panel.shaft == "d");
    EXPECT_TRUE(sumOfLoads);
    const std::string commands = formatFigureCommands(r, *steady, "timeseries.csv");
    std::ostringstream range;
    range << std::setprecision(17) << "set xrange [" << steady->xFrom << ":" << steady->xTo << "]";
    EXPECT_NE(commands.find(range.str()), std::string::npos) << commands;
    // No start was simulated: no start figure; no current data: no currents.
    EXPECT_EQ(figure(r, "start"), nullptr);
    EXPECT_EQ(figure(r, "currents"), nullptr);
}

/// The x of every `set arrow` of a figure's commands, by its label.
std::map<std::string, double> markersDrawn(const std::string& commands) {
    std::map<std::string, double> out;
    const std::regex arrow(R"(set arrow (\d+) from first (\S+), graph 0)");
    const std::regex label(R"(set label (\d+) '([^']*) \S+ s' at first)");
    std::map<std::string, double> byTag;
    for (auto it = std::sregex_iterator(commands.begin(), commands.end(), arrow); it != std::sregex_iterator(); ++it)
        byTag[(*it)[1]] = std::stod((*it)[2]);
    // Markers at one instant share a label: "a, b 2 s".
    for (auto it = std::sregex_iterator(commands.begin(), commands.end(), label); it != std::sregex_iterator(); ++it) {
        const std::string names = (*it)[2];
        for (std::size_t from = 0, comma; from <= names.size(); from = comma + 2) {
            comma = names.find(", ", from);
            if (comma == std::string::npos) comma = names.size();
            out[names.substr(from, comma - from)] = byTag.at((*it)[1]);
        }
    }
    return out;
}

TEST(PlotFigures, StartFigureMarksTheVerdictsInstantsAtTheSummarysValues) {
    // Star-delta switched at 2 s, current data given: speeds, motor torque,
    // current; the instants start_time, the star-delta step and the end of
    // the starting sequence.
    const AnalysisResult r = runModelFile(kModels + "start_bench_star_delta.yaml", {{"outputs.plots", "false"}});
    ASSERT_EQ(r.verdict, "completed") << r.verdictText;
    const PlotFigure* start = figure(r, "start");
    ASSERT_NE(start, nullptr);
    const std::string commands = formatFigureCommands(r, *start, "timeseries.csv");
    const auto drawn = markersDrawn(commands);
    ASSERT_NE(r.find("start_time"), nullptr);
    ASSERT_NE(r.find("sequence_end.motor"), nullptr);
    ASSERT_EQ(drawn.count("start_time"), 1u) << commands;
    ASSERT_EQ(drawn.count("sequence_end.motor"), 1u) << commands;
    EXPECT_EQ(drawn.at("start_time"), r.find("start_time")->value);  // exactly: 17 digits round-trip
    EXPECT_EQ(drawn.at("sequence_end.motor"), r.find("sequence_end.motor")->value);
    ASSERT_EQ(drawn.count("motor star_delta step 1"), 1u) << commands;
    EXPECT_EQ(drawn.at("motor star_delta step 1"), 2.0);
    // The panels: speed, motor torque, current; the current's column drawn.
    std::set<std::string> columns;
    for (const auto& panel : start->panels)
        for (const auto& curve : panel.curves)
            for (std::size_t col : curve.columns) columns.insert(r.columnNames[col]);
    EXPECT_TRUE(columns.count("shaft.speed"));
    EXPECT_TRUE(columns.count("motor.torque"));
    EXPECT_TRUE(columns.count("motor.current"));
    const std::size_t current = r.findColumn("motor.current");
    EXPECT_NE(commands.find("using 1:" + std::to_string(current + 1) + " "), std::string::npos) << commands;
    // The window: the start and a quarter beyond its last instant.
    const double last = std::max({r.find("start_time")->value, r.find("sequence_end.motor")->value, 2.0});
    EXPECT_DOUBLE_EQ(start->xTo, 1.25 * last);
    // A currents figure of its own, with the same instants.
    ASSERT_NE(figure(r, "currents"), nullptr);
    EXPECT_EQ(markersDrawn(formatFigureCommands(r, *figure(r, "currents"), "timeseries.csv")).at("start_time"),
              r.find("start_time")->value);
}

TEST(PlotFigures, BeltTensionsAndSlipGetAFigure) {
    const AnalysisResult r =
        runModelFile(kModels + "jaw_crusher_900x600.yaml", {{"outputs.plots", "false"}, {"scenario.end_time", "1 s"}});
    const PlotFigure* belts = figure(r, "belts");
    ASSERT_NE(belts, nullptr);
    std::set<std::string> columns;
    for (const auto& panel : belts->panels)
        for (const auto& curve : panel.curves)
            for (std::size_t col : curve.columns) columns.insert(r.columnNames[col]);
    EXPECT_EQ(columns, (std::set<std::string>{"belt.tension_tight", "belt.tension_slack", "belt.slip_speed", "belt.slip"}));
    // Torques: every panel on one shaft; the eccentric shaft's crushing and
    // bearings summed; belt.driven_torque on the flywheel it drives.
    const PlotFigure* torques = figure(r, "torques");
    ASSERT_NE(torques, nullptr);
    for (const auto& panel : torques->panels) {
        EXPECT_FALSE(panel.shaft.empty()) << panel.title;
        for (const auto& curve : panel.curves)
            for (std::size_t col : curve.columns) {
                const std::string& name = r.columnNames[col];
                if (name == "belt.driven_torque") {
                    EXPECT_EQ(panel.shaft, "flywheel_drive");
                } else if (name == "crushing.torque" || name == "bearings.torque") {
                    EXPECT_EQ(panel.shaft, "eccentric_shaft");
                }
            }
    }
}

}  // namespace
}  // namespace milldyn
