#include "driver/outputs/Writers.h"

#include "driver/outputs/AtomicFile.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace milldyn {

std::string formatDouble(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string formatTimeseriesCsv(const AnalysisResult& result) {
    std::string out;
    for (std::size_t i = 0; i < result.columnNames.size(); ++i)
        out += (i ? "," : "") + result.columnNames[i] + "[" + result.columnUnits[i] + "]";
    out += '\n';
    for (const auto& row : result.rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i) out += ',';
            out += formatDouble(row[i]);
        }
        out += '\n';
    }
    return out;
}

std::string formatSummaryJson(const ModelSpec& spec, const AnalysisResult& result, const RunInfo& info) {
    nlohmann::ordered_json j;
    j["model"] = {{"name", spec.name}, {"file", spec.file}, {"format_version", spec.formatVersion}};
    j["analysis"] = result.analysis;
    nlohmann::ordered_json results = nlohmann::ordered_json::object();
    for (const auto& r : result.results)
        results[r.name] = {{"value", r.value}, {"unit", r.unit}, {"description", r.doc}};
    j["results"] = results;
    j["notes"] = result.notes;
    j["settings"] = {{"integrator", result.statistics.integrator},
                     {"accuracy", result.statistics.accuracy},
                     {"sample_interval", spec.outputs.sampleInterval}};
    j["statistics"] = {{"steps", result.statistics.steps},
                       {"step_attempts", result.statistics.stepAttempts},
                       {"realizations", result.statistics.realizations},
                       {"samples", result.rows.size()}};
    j["run"] = {{"wall_time", info.wallSeconds}, {"wall_time_unit", "s"}, {"host", info.host},
                {"milldyn_version", info.version}};
    return j.dump(2) + "\n";
}

namespace {

std::string quoteForGnuplot(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += (c == '\'') ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string quoteForShell(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

std::vector<std::string> writePlots(const std::string& dir, const std::string& csvPath,
                                    const AnalysisResult& result, std::string& warning) {
    std::vector<std::string> written;
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        warning = "gnuplot not found: no plots written (scripts/install-deps installs it)";
        return written;
    }
    for (const auto& plot : result.plots) {
        if (plot.second.empty()) continue;
        const std::string png = dir + "/" + plot.first + ".png";
        const std::string tmpPng = temporaryNameBeside(png);
        std::ostringstream script;
        script << "set terminal pngcairo noenhanced size 1000,560 font 'DejaVu Sans,10'\n"
               << "set output " << quoteForGnuplot(tmpPng) << "\n"
               << "set datafile separator ','\nset key outside right\nset grid\n"
               << "set xlabel 'time [s]'\nset ylabel " << quoteForGnuplot(plot.first + " [" +
                                                                            result.columnUnits[plot.second[0]] + "]")
               << "\nset title " << quoteForGnuplot(plot.first) << "\nplot ";
        for (std::size_t k = 0; k < plot.second.size(); ++k) {
            const std::size_t col = plot.second[k];
            script << (k ? ", " : "") << quoteForGnuplot(csvPath) << " every ::1 using 1:" << col + 1
                   << " with lines lw 1.5 title " << quoteForGnuplot(result.columnNames[col]);
        }
        script << "\n";
        const std::string scriptPath = temporaryNameBeside(dir + "/" + plot.first + ".gp");
        writeFileAtomically(scriptPath, script.str());
        const std::string cmd = "gnuplot " + quoteForShell(scriptPath) + " 2>/dev/null";
        const int rc = std::system(cmd.c_str());
        std::remove(scriptPath.c_str());
        if (rc != 0) {
            std::remove(tmpPng.c_str());
            warning = "gnuplot failed for plot " + plot.first;
            continue;
        }
        commitFile(tmpPng, png);
        written.push_back(png);
    }
    return written;
}

}  // namespace milldyn
