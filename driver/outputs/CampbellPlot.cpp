#include "driver/outputs/CampbellPlot.h"

#include "driver/outputs/Writers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace milldyn {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
bool isModeColumn(const std::string& name) {
    return name.rfind("natural_frequency_", 0) == 0 && endsWith(name, "_hz");
}
const DataTable* findTable(const AnalysisResult& result, const std::string& name) {
    for (const auto& t : result.extraTables)
        if (t.name == name) return &t;
    return nullptr;
}

}  // namespace

std::vector<std::string> campbellLineNames(const AnalysisResult& result) {
    std::vector<std::string> names;
    for (std::size_t c = 0; c < result.columnNames.size(); ++c) {
        const std::string& n = result.columnNames[c];
        if (result.columnUnits[c] == "Hz" && endsWith(n, "_hz") && !isModeColumn(n))
            names.push_back(n.substr(0, n.size() - 3));
    }
    return names;
}

std::string formatCampbellCrossingsCsv(const AnalysisResult& result, const DataTable& t) {
    const std::vector<std::string> names = campbellLineNames(result);
    std::string out;
    for (std::size_t i = 0; i < t.columnNames.size(); ++i)
        out += (i ? "," : "") + csvField(t.columnUnits[i] == "name" ? t.columnNames[i]
                                                                      : t.columnNames[i] + "[" + t.columnUnits[i] + "]");
    out += '\n';
    for (const auto& row : t.rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i) out += ',';
            const auto k = static_cast<std::size_t>(row[i]);
            out += t.columnUnits[i] == "name" && k < names.size() ? csvField(names[k]) : formatDouble(row[i]);
        }
        out += '\n';
    }
    return out;
}

std::string campbellPlotCommands(const AnalysisResult& result, const std::string& csvName) {
    if (result.analysis != "campbell" || result.tableName != "campbell") return {};
    const std::size_t rpm = result.findColumn("speed_rpm");
    if (rpm == std::string::npos) return {};
    // The y axis up to the highest excitation line or the lowest mode,
    // whichever is higher: the crossings are there; a mode far above every
    // line stays in the key, off the axis.
    std::vector<std::size_t> modes, lines;
    double lowestMode = std::numeric_limits<double>::infinity(), highestLine = 0;
    for (std::size_t c = 0; c < result.columnNames.size(); ++c) {
        const std::string& n = result.columnNames[c];
        if (result.columnUnits[c] != "Hz" || !endsWith(n, "_hz")) continue;
        (isModeColumn(n) ? modes : lines).push_back(c);
        for (const auto& row : result.rows)
            if (isModeColumn(n))
                lowestMode = std::min(lowestMode, row[c]);
            else
                highestLine = std::max(highestLine, row[c]);
    }
    double top = std::max(highestLine, std::isfinite(lowestMode) ? lowestMode : 0.0);
    for (std::size_t c : modes)
        for (const auto& row : result.rows)
            if (row[c] <= 1.5 * top) top = std::max(top, row[c]);
    const std::size_t headerLines = csvHeaderLines(result.columnNames, result.columnUnits);
    std::ostringstream s;
    s << "set datafile separator ','\nset key outside right\nset grid\n"
      << "set xlabel " << quoteForGnuplot(result.plotXLabel) << "\nset ylabel 'frequency [Hz]'\n"
      << "set title 'Campbell diagram: natural frequencies (solid), excitation lines (dashed), crossings (circles)'\n";
    if (top > 0) s << "set yrange [0:" << formatDouble(1.15 * top) << "]\n";
    if (!result.rows.empty())
        s << "set xrange [" << formatDouble(result.rows.front()[rpm]) << ":" << formatDouble(result.rows.back()[rpm])
          << "]\n";
    // Operating speeds as vertical lines.
    for (const auto& r : result.results)
        if (r.name.rfind("operating_speed_", 0) == 0 && r.unit == "rpm")
            s << "set arrow from " << formatDouble(r.value) << ", graph 0 to " << formatDouble(r.value)
              << ", graph 1 nohead dt 3 lc rgb '#444444'\n";
    const DataTable* crossings = findTable(result, "campbell_crossings");
    bool marks = false;
    if (crossings && !crossings->rows.empty()) {
        const auto col = [&](const std::string& name) {
            for (std::size_t i = 0; i < crossings->columnNames.size(); ++i)
                if (crossings->columnNames[i] == name) return i;
            return std::string::npos;
        };
        const std::size_t x = col("speed_rpm"), y = col("frequency_hz");
        if (x != std::string::npos && y != std::string::npos) {
            s << "$crossings << EOD\n";
            // Comma-separated like the table (the datafile separator is ',').
            for (const auto& row : crossings->rows) s << formatDouble(row[x]) << ',' << formatDouble(row[y]) << "\n";
            s << "EOD\n";
            marks = true;
        }
    }
    s << "plot ";
    bool first = true;
    auto series = [&](std::size_t c, const std::string& style) {
        std::string title = result.columnNames[c].substr(0, result.columnNames[c].size() - 3);
        s << (first ? "" : ", ") << quoteForGnuplot(csvName) << " skip " << headerLines << " using " << rpm + 1 << ":"
          << c + 1 << " with lines " << style << " title " << quoteForGnuplot(title);
        first = false;
    };
    for (std::size_t c : modes) series(c, "lw 2.5");
    for (std::size_t c : lines) series(c, "lw 1 dt 2");
    if (marks)
        s << (first ? "" : ", ") << "$crossings using 1:2 with points pt 6 ps 1.8 lw 2 lc rgb '#d62728' title 'crossing'";
    s << "\n";
    return s.str();
}

}  // namespace milldyn
