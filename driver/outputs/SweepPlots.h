#pragma once
// Plots of a sweep's results against its swept parameters (issue 20 item
// 13), drawn from DIR/sweep.csv with gnuplot: for each result, a line
// against the axis of a 1-axis grid, a line per value of the second axis for
// a 2-axis grid, and a scatter against every axis for a Latin hypercube (and
// for grids of 3 or more axes). Points that are not ok have no result and
// leave a gap. docs/sweeps.md describes the files.

#include <string>
#include <vector>

namespace milldyn {

/// sweep.csv read back: the swept inputs and the results of every point
/// (NaN where a point has no value).
struct SweepTable {
    std::vector<std::string> inputNames, inputUnits;    ///< "path", "unit" of each axis
    std::vector<std::string> resultNames, resultUnits;  ///< each result column
    std::vector<std::vector<double>> inputs;            ///< [point][axis]
    std::vector<std::vector<double>> results;           ///< [point][result]
};

/// Parses the text of a sweep.csv (index, inputs..., status, results...,
/// diagnostic; quoted fields allowed). Throws std::invalid_argument.
SweepTable parseSweepTable(const std::string& csv);

enum class SweepLayout { Infer, Grid, Sample };

/// How a table's points are laid out: Grid when every combination of the
/// axes' distinct values occurs exactly once (a full grid), else Sample.
SweepLayout inferSweepLayout(const SweepTable& table);

/// The lines of a 2-axis grid: for each distinct value of axis `groupAxis`
/// (in increasing order), the points having it, sorted by the other axis.
std::vector<std::pair<double, std::vector<std::size_t>>> sweepLines(const SweepTable& table, std::size_t groupAxis);

/// A file-name stem made of letters, digits, '_', '-' and '.' only.
std::string plotFileStem(const std::string& name);

/// Whether a result is a headline of a sweep (issue 29 item 3): the
/// verdict, steady values, peaks, power, statistics, natural frequencies...
/// — every result but the energy bookkeeping (energy*, *_energy_change,
/// mean_power.* other than motor_input and shaft_input) and the last
/// instant's values (final.*).
bool isHeadlineResult(const std::string& name);

/// The result columns of `table` that `select` names (outputs.sweep_plots):
/// a result name, NAME* for every result whose name begins with NAME,
/// `headline` for the headline results, `all`; empty: `headline`. In the
/// table's order. Entries that match no result go to `unmatched`.
std::vector<std::size_t> selectSweepResults(const SweepTable& table, const std::vector<std::string>& select,
                                            std::vector<std::string>& unmatched);

/// Writes DIR/sweep_<result>.png for the result columns of DIR/sweep.csv
/// that `select` names (selectSweepResults; default the headline results),
/// each atomically. `layout` Infer decides from the table. Returns the files
/// written; `warning` says what could not be plotted (no gnuplot, no
/// results, a selection naming no result). Throws OutputError when a file
/// cannot be written.
std::vector<std::string> writeSweepPlots(const std::string& dir, SweepLayout layout, std::string& warning,
                                         const std::vector<std::string>& select = {});

}  // namespace milldyn
