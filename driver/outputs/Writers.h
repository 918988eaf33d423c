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

/// CSV with header `name[unit]`, numbers in shortest round-trip form.
std::string formatTimeseriesCsv(const AnalysisResult& result);
/// summary.json: model, results with units, settings, statistics, and a
/// separate "run" section with wall time and host.
std::string formatSummaryJson(const ModelSpec& spec, const AnalysisResult& result, const RunInfo& info);
/// Writes one PNG per plot of the result with gnuplot, reading `csvPath`.
/// Returns the files written; a missing gnuplot yields none and a warning.
std::vector<std::string> writePlots(const std::string& dir, const std::string& csvPath,
                                    const AnalysisResult& result, std::string& warning);

/// A number in the shortest form that reads back to the same double.
std::string formatDouble(double v);

}  // namespace milldyn
