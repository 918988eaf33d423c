// The registry of report sections: one line per machine. A new machine
// writes its section next to its cases (validation/cases/<Machine>Report.cpp)
// and adds it here; the report writer does not change.

#include "validation/report/ReportSection.h"

#include <cmath>
#include <cstdio>

namespace milldyn {

std::vector<ReportSection> reportSections() {
    return {burrMillReportSection(), rollCrusherReportSection(), planetaryGearReportSection(),
            planetaryBeltReportSection(), beadMillReportSection(), tumblingMillReportSection(),
            planetaryMotorStartReportSection()};
}

const ValidationRow* findRow(const std::vector<ValidationRow>& rows, const std::string& caseName,
                             const std::string& quantity) {
    for (const auto& r : rows)
        if (r.caseName == caseName && r.quantity == quantity) return &r;
    return nullptr;
}

std::string formatCell(double v, int digits) {
    if (!std::isfinite(v)) return "—";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

}  // namespace milldyn
