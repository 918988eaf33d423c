#pragma once
// The files `milldyn run` writes: timeseries.csv, summary.json, plots.

#include "driver/ModelSpec.h"
#include "driver/analyses/Analysis.h"

#include <string>
#include <vector>

namespace milldyn {

/// Facts about the run that differ between runs (kept apart in the JSON so
/// the rest can be compared bit for bit).
struct RunInfo {
    double wallSeconds = 0;
    std::string host;
    std::string version;
};

/// One CSV field per RFC 4180: as is, or in double quotes (a quote inside
/// doubled) when it holds a comma, a double quote, CR or LF. Every CSV
/// milldyn writes puts its text fields (headers, statuses, diagnostics)
/// through this (issue 26 item 4: an element named `lo,ad` gave a header of
/// more fields than its rows).
std::string csvField(const std::string& text);
/// The records of a CSV text per RFC 4180: quoted fields may hold commas,
/// doubled quotes and line breaks; CRLF and LF both end a record; a final
/// line break adds no record. Throws std::invalid_argument for a quote left
/// open or text after a closing quote.
std::vector<std::vector<std::string>> parseCsv(const std::string& text);
/// How many lines of the file a CSV header of these names and units spans
/// (1, plus one per line break inside a name): what gnuplot must skip.
std::size_t csvHeaderLines(const std::vector<std::string>& names, const std::vector<std::string>& units);

/// CSV with header `name[unit]` (each quoted per csvField when needed),
/// numbers in shortest round-trip form.
std::string formatCsv(const std::vector<std::string>& names, const std::vector<std::string>& units,
                      const std::vector<std::vector<double>>& rows);
/// linear_model.json: degree-of-freedom names and matrices.
std::string formatLinearModelJson(const AnalysisResult& result);

/// Writes every file of a result into `dir` (each atomically): the main
/// table, extra tables, summary.json, linear_model.json, plots. Returns the
/// paths written; `warning` says what could not be plotted.
std::vector<std::string> writeResultFiles(const std::string& dir, const ModelSpec& spec,
                                          const AnalysisResult& result, const RunInfo& info, std::string& warning);
/// summary.json: model, results with units, settings, statistics, and a
/// separate "run" section with wall time and host.
std::string formatSummaryJson(const ModelSpec& spec, const AnalysisResult& result, const RunInfo& info);
/// Writes one PNG per plot of the result with gnuplot, reading `csvPath`,
/// and for a mode_shapes table mode_shapes.png: a bar chart per mode with
/// the bodies by name on the x axis.
/// Returns the files written; a missing gnuplot yields none and a warning.
/// The panels of one plot: its columns grouped so that within a panel the
/// largest |value| of each column is within a factor 10 of the others
/// (a 1.9 rad/s mill and a 157 rad/s motor get a panel and an axis each),
/// in the plot's order of first appearance. Columns that stay 0 join the
/// first panel.
std::vector<std::vector<std::size_t>> plotPanels(const AnalysisResult& result, const std::vector<std::size_t>& columns);
/// gnuplot y-axis commands for one panel of `columns` (values × `scale`):
/// autoscale with gnuplot's tick format, unless the panel's range is too
/// narrow for it to tell the ticks apart: a constant level (to 1e-9) on a
/// ±5 % axis, a narrow band with enough significant digits.
std::string panelYAxisCommands(const AnalysisResult& result, const std::vector<std::size_t>& columns, double scale);
/// The same for the values of a panel's curves (already scaled).
std::string yAxisCommands(const std::vector<std::vector<double>>& curves);

std::vector<std::string> writePlots(const std::string& dir, const std::string& csvPath,
                                    const AnalysisResult& result, std::string& warning);

/// The gnuplot commands of plot `title` (columns `columns` of `csvPath`),
/// without terminal and output: one panel per plotPanels group. A panel's
/// y axis names what its columns are where they share a label
/// (AnalysisResult::columnLabels: a charge lag's convention), else the
/// plot's title; angles (unit rad) are drawn in degrees.
std::string formatPlotCommands(const AnalysisResult& result, const std::string& title,
                               const std::vector<std::size_t>& columns, const std::string& csvPath);

/// The values a figure's curve draws in each row of the main table: its
/// column, or the sum of its columns (NaN where a column is missing).
std::vector<double> plotCurveValues(const AnalysisResult& result, const PlotCurve& curve);
/// The gnuplot `using` expression of a curve: `1:5`, `1:($5+$7)` for a sum,
/// an angle (rad) in degrees.
std::string plotCurveUsing(const AnalysisResult& result, const PlotCurve& curve);
/// The gnuplot commands of a figure (without terminal and output): one
/// panel per PlotPanel, stacked; each marker a dashed vertical line at its
/// x with its label, on every panel; the x range [xFrom, xTo] when set
/// (markers outside it left out).
std::string formatFigureCommands(const AnalysisResult& result, const PlotFigure& figure, const std::string& csvPath);

/// One bar chart of a mode shape: its title ("mode 2: 14.3 Hz") and the
/// amplitude of every body, by name, in the table's column order.
struct ModeShapeBars {
    std::string title;
    std::vector<std::pair<std::string, double>> bars;
};
/// The bar charts of a `linearize` mode_shapes table (columns mode,
/// natural_frequency, then one per body): one per row. Empty for any other
/// table.
std::vector<ModeShapeBars> modeShapeBars(const AnalysisResult& result);

/// A string as a gnuplot string literal.
std::string quoteForGnuplot(const std::string& s);
/// Whether gnuplot is on the PATH.
bool gnuplotAvailable();
/// Runs gnuplot on `commands` (everything after the terminal and output
/// lines) to draw `png` (pngcairo, width x height pixels), atomically.
/// gnuplot runs in png's directory and is given file names relative to it
/// (the output directory's own name, which may hold '$', quotes or line
/// breaks, never reaches a gnuplot string): `commands` must name the files
/// it reads in that directory by their bare names.
/// Returns false, leaving nothing behind, when gnuplot fails.
bool renderGnuplotPng(const std::string& png, const std::string& commands, int width, int height);

/// A number in the shortest form that reads back to the same double.
std::string formatDouble(double v);

/// `s` with &, <, > and " escaped, for HTML and SVG text and attributes.
std::string escapeMarkup(const std::string& s);

}  // namespace milldyn
