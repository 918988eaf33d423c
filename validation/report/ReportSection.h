#pragma once
// What one machine contributes to the validation report
// (`milldyn validate --report DIR`, validation/report/ReportWriter.h).
//
// A machine's section lives next to its cases (validation/cases/
// <Machine>Report.cpp) and is listed once in reportSections()
// (validation/report/ReportSections.cpp); the writer knows no machine. The
// numbers in the report come from the validation rows themselves, and the
// explanation of a single difference is the row's note: the section only
// adds what the paper claims, the prose that spans many rows, and its
// tables and plots.

#include "validation/cases/ValidationCases.h"

#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// One curve (or one bar series) of a report plot.
struct ReportSeries {
    enum class Style { Lines, DashedLines, Points, Impulses };
    std::string label;
    std::vector<double> x, y;  ///< for a bar chart only y (one per category)
    Style style = Style::Lines;
    int colour = 0;  ///< 0: the next automatic colour; k > 0: colour k (series that belong together share it)
};

/// A plot the writer renders with gnuplot as DIR/<file>.png.
struct ReportPlot {
    std::string file;     ///< base name, unique in the report: <machine>_...
    std::string title;
    std::string caption;  ///< what to look at, shown under the image
    std::string xLabel, yLabel;
    bool logX = false, logY = false;
    /// One unit on x is as long as one on y (a polar curve drawn as x = r cos φ, y = r sin φ).
    bool equalAxes = false;
    /// Non-empty: x tick labels at x = 1, 2, ... (e.g. body names).
    std::vector<std::string> xTicLabels;
    /// Non-empty: a clustered bar chart, one cluster per category, one bar per series.
    std::vector<std::string> categories;
    std::vector<ReportSeries> series;
};

/// A table of already formatted cells.
struct ReportTable {
    std::string title;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::string caption;
};

struct ReportSection {
    /// Case-name prefix: the section owns every row whose case starts with it.
    std::string machine;
    std::string title;       ///< e.g. "MMP-50 burr mill (seed 003)"
    std::string paper;       ///< the paper, in one line
    std::string claims;      ///< what the paper claims
    std::string oracle;      ///< what the oracle is and how it differs from the printed text
    std::string multibody;   ///< what the multibody model is and what it is compared on
    /// Differences that span many rows, each with its explanation (one
    /// paragraph each). A single row's explanation is its note.
    std::vector<std::string> differences;
    std::string docs;        ///< where the details are (repository paths)
    /// Side-by-side tables built from this machine's rows.
    std::function<std::vector<ReportTable>(const std::vector<ValidationRow>&)> tables;
    /// Plots: may run the oracle and the multibody model for curves.
    std::function<std::vector<ReportPlot>(const std::vector<ValidationRow>&)> plots;
};

/// Every machine's section, in report order (the registry).
std::vector<ReportSection> reportSections();

/// The sections of each machine (one function per machine, next to its cases).
ReportSection burrMillReportSection();
ReportSection rollCrusherReportSection();
ReportSection planetaryGearReportSection();
ReportSection planetaryBeltReportSection();
ReportSection beadMillReportSection();
ReportSection planetaryMotorStartReportSection();
ReportSection tumblingMillReportSection();

/// Helpers for sections: the row of `caseName` whose quantity is exactly
/// `quantity`, or null.
const ValidationRow* findRow(const std::vector<ValidationRow>& rows, const std::string& caseName,
                             const std::string& quantity);
/// A number for a table cell: %.*g with `digits` significant digits, "—" for NaN.
std::string formatCell(double v, int digits = 6);

}  // namespace milldyn
