#pragma once
// The validation report a person reads: DIR/report.md and DIR/report.html
// with its plots (DIR/*.png, gnuplot) beside them. Every file is written
// atomically; the HTML is self-contained (relative image paths, inline
// style, no script, nothing fetched).
//
// The writer knows no machine: each ReportSection (validation/report/
// ReportSection.h) says what its paper claims and what to plot; the writer
// adds, from the rows, the counts, the per-case summary, the flagged
// misprints and the observations with their bands and notes, any failure,
// and every comparison.

#include "validation/report/ReportSection.h"

#include <string>
#include <vector>

namespace milldyn {

using ReportCounts = StatusCounts;
/// The rows' counts by status (countStatuses: the same numbers `validate`
/// and docs/validation.md give).
ReportCounts countRows(const std::vector<ValidationRow>& rows);

/// Writes the report into `dir` (created if needed). Sections without rows
/// are left out (a --filter run); rows no section claims go into an "Other
/// cases" section. Returns the files written; `warning` says what could
/// not be plotted (no gnuplot, or gnuplot failed). Throws OutputError.
std::vector<std::string> writeValidationReport(const std::string& dir, const std::vector<ValidationRow>& rows,
                                               const std::vector<ReportSection>& sections, std::string& warning);

}  // namespace milldyn
