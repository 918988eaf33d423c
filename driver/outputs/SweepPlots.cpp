#include "driver/outputs/SweepPlots.h"

#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/Writers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

namespace milldyn {
namespace {

/// "path[unit]" → (path, unit).
std::pair<std::string, std::string> splitHeader(const std::string& h) {
    const auto open = h.rfind('[');
    if (open == std::string::npos || h.back() != ']') return {h, ""};
    return {h.substr(0, open), h.substr(open + 1, h.size() - open - 2)};
}

double parseNumber(const std::string& text) {
    if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("sweep.csv: '" + text + "' is not a number");
    return v;
}

std::string axisLabel(const SweepTable& t, std::size_t a) {
    return t.inputNames[a] + " [" + t.inputUnits[a] + "]";
}

/// A gnuplot data block `name` of (x, y) rows; a NaN y breaks the line.
void dataBlock(std::ostringstream& s, const std::string& name, const std::vector<std::pair<double, double>>& xy) {
    s << "$" << name << " << EOD\n";
    for (const auto& p : xy) {
        if (std::isfinite(p.second))
            s << formatDouble(p.first) << ' ' << formatDouble(p.second) << '\n';
        else
            s << '\n';
    }
    s << "EOD\n";
}

}  // namespace

SweepTable parseSweepTable(const std::string& csv) {
    // RFC 4180 as written (csvField): a quoted name may hold commas and
    // line breaks, so records, not lines.
    const auto records = parseCsv(csv);
    if (records.empty()) throw std::invalid_argument("sweep.csv is empty");
    const auto& header = records.front();
    const auto status = std::find(header.begin(), header.end(), "status");
    if (header.empty() || header.front() != "index[1]" || status == header.end() || header.back() != "diagnostic")
        throw std::invalid_argument("sweep.csv: header is not index[1],inputs...,status,results...,diagnostic");
    const std::size_t firstResult = std::size_t(status - header.begin()) + 1;
    SweepTable t;
    for (std::size_t i = 1; i + 1 < header.size(); ++i) {
        if (i + 1 == firstResult) continue;
        const auto nu = splitHeader(header[i]);
        if (i < firstResult) {
            t.inputNames.push_back(nu.first);
            t.inputUnits.push_back(nu.second);
        } else {
            t.resultNames.push_back(nu.first);
            t.resultUnits.push_back(nu.second);
        }
    }
    for (std::size_t k = 1; k < records.size(); ++k) {
        const auto& f = records[k];
        if (f.size() == 1 && f[0].empty()) continue;
        if (f.size() != header.size())
            throw std::invalid_argument("sweep.csv: a row has " + std::to_string(f.size()) + " fields, the header " +
                                        std::to_string(header.size()));
        std::vector<double> inputs, results;
        for (std::size_t i = 1; i + 1 < firstResult; ++i) inputs.push_back(parseNumber(f[i]));
        for (std::size_t i = firstResult; i + 1 < f.size(); ++i) results.push_back(parseNumber(f[i]));
        t.inputs.push_back(inputs);
        t.results.push_back(results);
    }
    return t;
}

SweepLayout inferSweepLayout(const SweepTable& t) {
    std::set<std::vector<double>> combinations(t.inputs.begin(), t.inputs.end());
    std::size_t product = 1;
    for (std::size_t a = 0; a < t.inputNames.size(); ++a) {
        std::set<double> distinct;
        for (const auto& row : t.inputs) distinct.insert(row[a]);
        product *= distinct.size();
    }
    return combinations.size() == t.inputs.size() && product == t.inputs.size() ? SweepLayout::Grid
                                                                                 : SweepLayout::Sample;
}

std::vector<std::pair<double, std::vector<std::size_t>>> sweepLines(const SweepTable& t, std::size_t groupAxis) {
    const std::size_t xAxis = groupAxis == 0 ? 1 : 0;
    std::vector<std::pair<double, std::vector<std::size_t>>> lines;
    std::set<double> values;
    for (const auto& row : t.inputs) values.insert(row[groupAxis]);
    for (double v : values) {
        std::vector<std::size_t> points;
        for (std::size_t i = 0; i < t.inputs.size(); ++i)
            if (t.inputs[i][groupAxis] == v) points.push_back(i);
        std::stable_sort(points.begin(), points.end(),
                         [&](std::size_t a, std::size_t b) { return t.inputs[a][xAxis] < t.inputs[b][xAxis]; });
        lines.emplace_back(v, points);
    }
    return lines;
}

std::string plotFileStem(const std::string& name) {
    std::string out;
    for (char c : name)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.') ? c : '_';
    return out.empty() ? "_" : out;
}

bool isHeadlineResult(const std::string& name) {
    auto begins = [&](const std::string& head) { return name.compare(0, head.size(), head) == 0; };
    auto ends = [&](const std::string& tail) {
        return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (begins("energy") || ends("_energy_change") || begins("final.")) return false;
    if (begins("mean_power.")) return name == "mean_power.motor_input" || name == "mean_power.shaft_input";
    return true;
}

std::vector<std::size_t> selectSweepResults(const SweepTable& t, const std::vector<std::string>& select,
                                            std::vector<std::string>& unmatched) {
    const std::vector<std::string> asked = select.empty() ? std::vector<std::string>{"headline"} : select;
    std::vector<bool> chosen(t.resultNames.size(), false);
    for (const std::string& a : asked) {
        bool any = false;
        for (std::size_t r = 0; r < t.resultNames.size(); ++r) {
            const std::string& n = t.resultNames[r];
            const bool match = a == "all" || (a == "headline" && isHeadlineResult(n)) || a == n ||
                               (a.size() > 1 && a.back() == '*' && n.compare(0, a.size() - 1, a, 0, a.size() - 1) == 0);
            if (match) chosen[r] = any = true;
        }
        if (!any) unmatched.push_back(a);
    }
    std::vector<std::size_t> out;
    for (std::size_t r = 0; r < chosen.size(); ++r)
        if (chosen[r]) out.push_back(r);
    return out;
}

std::vector<std::string> writeSweepPlots(const std::string& dir, SweepLayout layout, std::string& warning,
                                         const std::vector<std::string>& select) {
    std::vector<std::string> written;
    std::ifstream in(dir + "/sweep.csv");
    std::stringstream text;
    text << in.rdbuf();
    SweepTable t;
    try {
        t = parseSweepTable(text.str());
    } catch (const std::exception& e) {
        warning = std::string("no sweep plots: ") + e.what();
        return written;
    }
    if (t.inputNames.empty() || t.resultNames.empty() || t.inputs.empty()) {
        warning = "no sweep plots: no point has a result";
        return written;
    }
    if (!gnuplotAvailable()) {
        warning = "gnuplot not found: no sweep plots written (scripts/install-deps.sh installs it)";
        return written;
    }
    if (layout == SweepLayout::Infer) layout = inferSweepLayout(t);
    const std::size_t axes = t.inputNames.size();
    const bool lines = layout == SweepLayout::Grid && axes <= 2;
    std::vector<std::string> skipped, missing, unmatched;
    const std::vector<std::size_t> chosen = selectSweepResults(t, select, unmatched);
    for (std::size_t r : chosen) {
        const bool any = std::any_of(t.results.begin(), t.results.end(),
                                     [&](const std::vector<double>& row) { return std::isfinite(row[r]); });
        if (!any) {
            skipped.push_back(t.resultNames[r]);
            continue;
        }
        const std::string yLabel = t.resultNames[r] + " [" + t.resultUnits[r] + "]";
        std::ostringstream s;
        s << "set grid\nset key outside right\n";
        int height = 560;
        if (lines) {
            // x: the first axis; one line per value of the second, if any.
            const auto groups = axes == 2 ? sweepLines(t, 1) : sweepLines(t, 0);
            std::vector<std::string> titles;
            for (std::size_t g = 0; g < groups.size() && axes == 2; ++g) {
                std::vector<std::pair<double, double>> xy;
                for (std::size_t i : groups[g].second) xy.emplace_back(t.inputs[i][0], t.results[i][r]);
                dataBlock(s, "line" + std::to_string(g), xy);
                titles.push_back(t.inputNames[1] + " = " + formatDouble(groups[g].first) + " " + t.inputUnits[1]);
            }
            if (axes == 1) {
                std::vector<std::size_t> order(t.inputs.size());
                std::iota(order.begin(), order.end(), 0);
                std::stable_sort(order.begin(), order.end(),
                                 [&](std::size_t a, std::size_t b) { return t.inputs[a][0] < t.inputs[b][0]; });
                std::vector<std::pair<double, double>> xy;
                for (std::size_t i : order) xy.emplace_back(t.inputs[i][0], t.results[i][r]);
                dataBlock(s, "line0", xy);
                titles.push_back(t.resultNames[r]);
            }
            s << "set title " << quoteForGnuplot(t.resultNames[r] + " against " + t.inputNames[0]) << "\n"
              << "set xlabel " << quoteForGnuplot(axisLabel(t, 0)) << "\nset ylabel " << quoteForGnuplot(yLabel)
              << "\nplot ";
            for (std::size_t g = 0; g < titles.size(); ++g)
                s << (g ? ", " : "") << "$line" << g << " using 1:2 with linespoints lw 1.5 pt 7 ps 0.6 title "
                  << quoteForGnuplot(titles[g]);
            s << "\n";
        } else {
            // A scatter against every axis, one panel each.
            if (axes > 1)
                s << "set multiplot layout " << axes << ",1 title "
                  << quoteForGnuplot(t.resultNames[r] + " at the sampled points") << "\n";
            for (std::size_t a = 0; a < axes; ++a) {
                std::vector<std::pair<double, double>> xy;
                for (std::size_t i = 0; i < t.inputs.size(); ++i)
                    if (std::isfinite(t.results[i][r])) xy.emplace_back(t.inputs[i][a], t.results[i][r]);
                dataBlock(s, "axis" + std::to_string(a), xy);
                if (axes == 1)
                    s << "set title " << quoteForGnuplot(t.resultNames[r] + " at the sampled points") << "\n";
                s << "set xlabel " << quoteForGnuplot(axisLabel(t, a)) << "\nset ylabel " << quoteForGnuplot(yLabel)
                  << "\nplot $axis" << a << " using 1:2 with points pt 7 ps 0.8 notitle\n";
            }
            if (axes > 1) s << "unset multiplot\n";
            height = axes > 1 ? static_cast<int>(300 * axes) + 60 : 560;
        }
        const std::string png = dir + "/sweep_" + plotFileStem(t.resultNames[r]) + ".png";
        if (!renderGnuplotPng(png, s.str(), 1000, height)) {
            missing.push_back(std::filesystem::path(png).filename().string());
            continue;
        }
        written.push_back(png);
    }
    // An asked-for plot not drawn (a full disk) is a failed output, every
    // one of them named; the table and the points stay (issue 26 item 8).
    if (!missing.empty()) {
        std::string list;
        for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
        throw OutputError(std::to_string(missing.size()) + " of " + std::to_string(missing.size() + written.size()) +
                          " sweep plots not drawn (gnuplot failed or left an incomplete PNG: a full disk?): " + list +
                          "; sweep.csv and points/ are complete (--no-plots skips the plots)");
    }
    if (!skipped.empty() && warning.empty()) {
        warning = "no sweep plot of";
        for (const auto& n : skipped) warning += " " + n;
        warning += ": no point has a value";
    }
    if (!unmatched.empty()) {
        std::string list;
        for (const auto& n : unmatched) list += (list.empty() ? "" : ", ") + n;
        warning += (warning.empty() ? "" : "; ") + std::string("outputs.sweep_plots: no result named ") + list +
                   " in sweep.csv (its columns are the results; `all` draws every one)";
    }
    return written;
}

}  // namespace milldyn
