#pragma once
// The files of a campbell result beyond the generic ones: the crossings
// table with the excitation line's name, and campbell.png (modes as lines,
// excitation lines dashed, crossings marked, operating speeds as verticals).

#include "driver/analyses/Analysis.h"

#include <string>

namespace milldyn {

/// The excitation lines' names, in the order the campbell table has their
/// columns (`NAME_hz`, `NAME_rad_per_s` after the modes' columns).
std::vector<std::string> campbellLineNames(const AnalysisResult& result);

/// campbell_crossings.csv: its `order` column (unit "name": the index of an
/// excitation line) written as the line's name; every other as formatCsv.
std::string formatCampbellCrossingsCsv(const AnalysisResult& result, const DataTable& crossings);

/// The gnuplot commands (without terminal and output) of campbell.png from
/// the table `csvName` (a bare file name in the output directory); empty
/// when `result` is not a campbell result.
std::string campbellPlotCommands(const AnalysisResult& result, const std::string& csvName);

}  // namespace milldyn
