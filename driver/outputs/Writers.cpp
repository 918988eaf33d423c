#include "driver/outputs/Writers.h"

#include "driver/outputs/CampbellPlot.h"

#include "driver/outputs/AtomicFile.h"
#include "plugins/scene/EngineTag.h"
#include "plugins/scene/Format.h"
#include "driver/outputs/OutputSet.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace milldyn {

std::string formatDouble(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
    std::vector<std::vector<std::string>> records;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, wasQuoted = false, any = false;
    auto endField = [&] {
        record.push_back(field);
        field.clear();
        wasQuoted = false;
    };
    auto endRecord = [&] {
        endField();
        records.push_back(record);
        record.clear();
        any = false;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c != '"') {
                field += c;
            } else if (i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else {
                quoted = false;
                wasQuoted = true;
            }
            continue;
        }
        if (c == ',') {
            endField();
            any = true;
        } else if (c == '\n' || (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
            if (c == '\r') ++i;
            endRecord();
        } else if (c == '"' && field.empty() && !wasQuoted) {
            quoted = true;
            any = true;
        } else if (wasQuoted) {
            throw std::invalid_argument("CSV: text after a closing quote in record " + std::to_string(records.size() + 1));
        } else {
            field += c;
            any = true;
        }
    }
    if (quoted) throw std::invalid_argument("CSV: a quoted field is not closed (record " + std::to_string(records.size() + 1) + ")");
    if (any || !field.empty() || !record.empty() || wasQuoted) endRecord();
    return records;
}

std::size_t csvHeaderLines(const std::vector<std::string>& names, const std::vector<std::string>& units) {
    std::size_t lines = 1;
    for (const auto* list : {&names, &units})
        for (const auto& s : *list) lines += static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
    return lines;
}

std::string formatCsv(const std::vector<std::string>& names, const std::vector<std::string>& units,
                      const std::vector<std::vector<double>>& rows) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) out += (i ? "," : "") + csvField(names[i] + "[" + units[i] + "]");
    out += '\n';
    for (const auto& row : rows) {
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
    if (!result.verdict.empty()) j["verdict"] = {{"status", result.verdict}, {"reason", result.verdictText}};
    nlohmann::ordered_json results = nlohmann::ordered_json::object();
    for (const auto& r : result.results) {
        results[r.name] = {{"value", r.value}, {"unit", r.unit}, {"description", r.doc}};
        if (!r.referredTo.empty()) results[r.name]["referred_to"] = r.referredTo;
    }
    j["results"] = results;
    nlohmann::ordered_json derived = nlohmann::ordered_json::object();
    for (const auto& r : result.derived)
        derived[r.name] = {{"value", r.value}, {"unit", r.unit}, {"description", r.doc}};
    j["derived"] = derived;
    j["notes"] = result.notes;
    j["settings"] = {{"integrator", result.statistics.integrator},
                     {"accuracy", result.statistics.accuracy},
                     {"sample_interval", spec.outputs.sampleInterval}};
    j["statistics"] = {{"steps", result.statistics.steps},
                       {"step_attempts", result.statistics.stepAttempts},
                       {"realizations", result.statistics.realizations},
                       {"samples", result.rows.size()}};
    j["tables"] = nlohmann::ordered_json::array();
    j["tables"].push_back(result.tableName + ".csv");
    for (const auto& t : result.extraTables) j["tables"].push_back(t.name + ".csv");
    j["run"] = {{"wall_time", info.wallSeconds}, {"wall_time_unit", "s"}, {"host", info.host},
                {"milldyn_version", info.version}, {"engine", kSimbodyEngine}};
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";  // bytes that are not UTF-8: U+FFFD
}

std::string formatLinearModelJson(const AnalysisResult& result) {
    nlohmann::ordered_json j;
    j["dofs"] = result.dofNames;
    j["equation"] = "M*q'' + C*q' + K*q = f, deviations from the operating point; A = [[0, I], [-M^-1 K, -M^-1 C]]";
    for (const auto& m : result.matrices) j[m.name] = {{"unit", m.unit}, {"rows", m.rows}};
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";  // bytes that are not UTF-8: U+FFFD
}

std::vector<std::string> writeResultFiles(const std::string& dir, const ModelSpec& spec,
                                          const AnalysisResult& result, const RunInfo& info, std::string& warning) {
    std::vector<std::string> written;
    const std::string main = dir + "/" + result.tableName + ".csv";
    writeFileAtomically(main, formatCsv(result.columnNames, result.columnUnits, result.rows));
    written.push_back(main);
    for (const auto& t : result.extraTables) {
        const std::string path = dir + "/" + t.name + ".csv";
        // The crossings of a Campbell diagram name their excitation line.
        writeFileAtomically(path, t.name == "campbell_crossings" ? formatCampbellCrossingsCsv(result, t)
                                                                  : formatCsv(t.columnNames, t.columnUnits, t.rows));
        written.push_back(path);
    }
    if (!result.matrices.empty()) {
        writeFileAtomically(dir + "/linear_model.json", formatLinearModelJson(result));
        written.push_back(dir + "/linear_model.json");
    }
    writeFileAtomically(dir + "/summary.json", formatSummaryJson(spec, result, info));
    written.push_back(dir + "/summary.json");
    if (spec.outputs.plots) {
        const auto plots = writePlots(dir, main, result, warning);
        written.insert(written.end(), plots.begin(), plots.end());
    }
    return written;
}

std::string quoteForGnuplot(const std::string& s) {
    // A line break would end gnuplot's command inside the string: a space.
    std::string out = "'";
    for (char c : s) out += (c == '\'') ? std::string("''") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
    return out + "'";
}

bool gnuplotAvailable() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

bool renderGnuplotPng(const std::string& png, const std::string& commands, int width, int height) {
    const std::filesystem::path where = std::filesystem::path(png).parent_path();
    const std::string tmpPng = temporaryNameBeside(png);
    const std::string scriptPath = temporaryNameBeside(png + ".gp");
    // Bare names, gnuplot started in their directory: the directory's name
    // (a '$' reads as a data block, a line break ends a command) stays out.
    auto bare = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
    std::ostringstream script;
    script << "set terminal pngcairo noenhanced size " << width << "," << height << " font 'DejaVu Sans,10'\n"
           << "set output " << quoteForGnuplot(bare(tmpPng)) << "\n"
           << commands;
    writeFileAtomically(scriptPath, script.str());
    // Not std::system (it ignores SIGINT); and gnuplot exits 0 on a full
    // disk, so the PNG itself is checked.
    const bool ok = runTool({"gnuplot", bare(scriptPath)}, where.empty() ? "." : where.string()) && isCompletePng(tmpPng);
    discardTemporary(scriptPath);
    if (!ok) {
        discardTemporary(tmpPng);
        return false;
    }
    commitFile(tmpPng, png);
    return true;
}

std::vector<std::vector<std::size_t>> plotPanels(const AnalysisResult& result, const std::vector<std::size_t>& columns) {
    std::vector<double> peak(columns.size(), 0.0);
    for (std::size_t k = 0; k < columns.size(); ++k)
        for (const auto& row : result.rows)
            if (columns[k] < row.size() && std::isfinite(row[columns[k]]))
                peak[k] = std::max(peak[k], std::abs(row[columns[k]]));
    std::vector<std::vector<std::size_t>> panels;
    std::vector<std::pair<double, double>> range;  // smallest and largest peak of each panel
    for (std::size_t k = 0; k < columns.size(); ++k) {
        bool placed = false;
        for (std::size_t p = 0; p < panels.size() && !placed; ++p) {
            const double lo = std::min(range[p].first, peak[k]), hi = std::max(range[p].second, peak[k]);
            if (peak[k] == 0 || range[p].second == 0 || hi <= 10 * lo) {
                panels[p].push_back(columns[k]);
                if (peak[k] > 0) range[p] = range[p].second == 0 ? std::make_pair(peak[k], peak[k]) : std::make_pair(lo, hi);
                placed = true;
            }
        }
        if (!placed) {
            panels.push_back({columns[k]});
            range.emplace_back(peak[k], peak[k]);
        }
    }
    return panels;
}

std::vector<ModeShapeBars> modeShapeBars(const AnalysisResult& result) {
    std::vector<ModeShapeBars> out;
    if (result.tableName != "mode_shapes" || result.columnNames.size() < 3 || result.columnNames[0] != "mode" ||
        result.columnNames[1] != "natural_frequency")
        return out;
    for (const auto& row : result.rows) {
        if (row.size() != result.columnNames.size()) continue;
        char title[96];
        // Mode 0: a rigid-body mode (elastic modes are numbered from 1, as in
        // the summary's natural_frequency_k).
        if (row[0] == 0)
            std::snprintf(title, sizeof title, "mode 0 (rigid body): %.4g Hz", row[1]);
        else
            std::snprintf(title, sizeof title, "mode %.0f: %.4g Hz", row[0], row[1]);
        ModeShapeBars m{title, {}};
        for (std::size_t c = 2; c < row.size(); ++c) m.bars.emplace_back(result.columnNames[c], row[c]);
        out.push_back(m);
    }
    return out;
}

namespace {

/// mode_shapes.png: one bar panel per mode, two columns when there are
/// more than four modes.
bool writeModeShapePlot(const std::string& png, const std::vector<ModeShapeBars>& modes) {
    const std::size_t columns = modes.size() > 4 ? 2 : 1;
    const std::size_t rows = (modes.size() + columns - 1) / columns;
    std::ostringstream s;
    s << "set grid ytics\nset style fill solid 0.7 border -1\nset boxwidth 0.6\nset yrange [*<0:0<*]\nset offsets 0.5, 0.5, 0, 0\n"
      << "set xtics rotate by -30 left\nset ylabel 'amplitude [1]'\nset xzeroaxis lt -1\n";
    for (std::size_t m = 0; m < modes.size(); ++m) {
        s << "$mode" << m << " << EOD\n";
        for (std::size_t b = 0; b < modes[m].bars.size(); ++b) {
            std::string name = modes[m].bars[b].first;  // a data-file string: double quotes, none inside
            std::replace(name.begin(), name.end(), '"', '\'');
            s << b << ' ' << formatDouble(modes[m].bars[b].second) << " \"" << name << "\"\n";
        }
        s << "EOD\n";
    }
    s << "set multiplot layout " << rows << "," << columns << " title 'mode shapes by body'\n";
    for (std::size_t m = 0; m < modes.size(); ++m)
        s << "set title " << quoteForGnuplot(modes[m].title) << "\nplot $mode" << m
          << " using 1:2:xtic(3) with boxes lc rgb '#1f77b4' notitle\n";
    s << "unset multiplot\n";
    return renderGnuplotPng(png, s.str(), columns == 1 ? 900 : 1400, static_cast<int>(260 * rows) + 80);
}

}  // namespace

std::string panelYAxisCommands(const AnalysisResult& result, const std::vector<std::size_t>& columns, double scale) {
    std::vector<std::vector<double>> curves;
    for (std::size_t col : columns) {
        std::vector<double> v;
        for (const auto& row : result.rows)
            if (col < row.size()) v.push_back(scale * row[col]);
        curves.push_back(v);
    }
    return yAxisCommands(curves);
}

std::string yAxisCommands(const std::vector<std::vector<double>>& curves) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& c : curves)
        for (double v : c)
            if (std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
    if (!(lo <= hi)) return "set autoscale y\nset format y '% h'\n";
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    std::ostringstream out;
    out << std::setprecision(17);
    // gnuplot's own tick format (6 significant digits) labels every tick of a
    // range narrower than ~1e-5 of its level alike ("500, 500, 500"): a level
    // constant to 1e-9 is drawn as constant on a ±5 % axis, a narrow band with
    // the digits that tell its ticks apart.
    if (hi - lo <= 1e-9 * magnitude || magnitude == 0) {
        const double pad = magnitude > 0 ? 0.05 * magnitude : 1.0;
        out << "set yrange [" << lo - pad << ":" << hi + pad << "]\nset format y '% h'\n";
        return out.str();
    }
    const int digits = static_cast<int>(std::ceil(std::log10(magnitude / (hi - lo)))) + 2;
    if (digits <= 6) return "set autoscale y\nset format y '% h'\n";
    out << "set autoscale y\nset format y '%." << std::min(digits, 15) << "g'\n";
    return out.str();
}

std::string formatPlotCommands(const AnalysisResult& result, const std::string& title,
                               const std::vector<std::size_t>& columns, const std::string& csvPath) {
    auto labelOf = [&](std::size_t col) {
        return col < result.columnLabels.size() ? result.columnLabels[col] : std::string();
    };
    // One panel per group of like magnitudes, each with its own axis.
    const auto panels = plotPanels(result, columns);
    // The header's lines (a quoted name may hold a line break), not data.
    const std::size_t headerLines = csvHeaderLines(result.columnNames, result.columnUnits);
    std::ostringstream script;
    script << "set datafile separator ','\nset key outside right\nset grid\n"
           << (result.plotXLabel.find("frequency") != std::string::npos ? "set logscale x\n" : "");
    if (panels.size() > 1) script << "set multiplot layout " << panels.size() << ",1 title " << quoteForGnuplot(title) << "\n";
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const bool last = p + 1 == panels.size();
        const std::size_t first = panels[p][0];
        const bool degrees = result.columnUnits[first] == "rad";
        std::string label = labelOf(first);
        for (std::size_t col : panels[p])
            if (labelOf(col) != label) label.clear();
        script << "set xlabel " << quoteForGnuplot(last ? result.plotXLabel : "") << "\nset ylabel "
               << quoteForGnuplot((label.empty() ? title : label) + " [" +
                                  (degrees ? std::string("deg") : result.columnUnits[first]) + "]")
               << "\n";
        if (panels.size() == 1) script << "set title " << quoteForGnuplot(title) << "\n";
        script << panelYAxisCommands(result, panels[p], degrees ? 180 / 3.14159265358979323846 : 1.0);
        script << "plot ";
        for (std::size_t k = 0; k < panels[p].size(); ++k) {
            const std::size_t col = panels[p][k];
            script << (k ? ", " : "") << quoteForGnuplot(csvPath) << " skip " << headerLines << " using 1:";
            if (result.columnUnits[col] == "rad")
                script << "($" << col + 1 << "*180/pi)";
            else
                script << col + 1;
            script << " with lines lw 1.5 title " << quoteForGnuplot(result.columnNames[col]);
        }
        script << "\n";
    }
    if (panels.size() > 1) script << "unset multiplot\n";
    return script.str();
}

std::vector<double> plotCurveValues(const AnalysisResult& result, const PlotCurve& curve) {
    std::vector<double> out;
    out.reserve(result.rows.size());
    for (const auto& row : result.rows) {
        double sum = 0;
        for (std::size_t col : curve.columns) sum += col < row.size() ? row[col] : std::numeric_limits<double>::quiet_NaN();
        out.push_back(sum);
    }
    return out;
}

std::string plotCurveUsing(const AnalysisResult& result, const PlotCurve& curve) {
    if (curve.columns.size() == 1) {
        const std::size_t col = curve.columns[0];
        return result.columnUnits[col] == "rad" ? "1:($" + std::to_string(col + 1) + "*180/pi)"
                                                 : "1:" + std::to_string(col + 1);
    }
    std::string sum;
    for (std::size_t col : curve.columns) sum += (sum.empty() ? "$" : "+$") + std::to_string(col + 1);
    return "1:(" + sum + ")";
}

std::string formatFigureCommands(const AnalysisResult& result, const PlotFigure& figure, const std::string& csvPath) {
    const std::size_t headerLines = csvHeaderLines(result.columnNames, result.columnUnits);
    const bool ranged = figure.xTo > figure.xFrom;
    std::ostringstream script;
    script << std::setprecision(17);
    script << "set datafile separator ','\nset key outside right\nset grid\n";
    if (ranged) script << "set xrange [" << figure.xFrom << ":" << figure.xTo << "]\n";
    // The panels share one x axis: fixed margins (the keys' widths differ).
    script << "set lmargin at screen 0.08\nset rmargin at screen 0.74\n";
    // Markers: a dashed line over the whole height of each panel, labelled
    // on the first (gnuplot keeps arrows and labels across panels); markers
    // at one instant share a line and a label ("a, b 2 s").
    std::vector<PlotMarker> merged;
    for (const auto& m : figure.markers) {
        if (ranged && (m.x < figure.xFrom || m.x > figure.xTo)) continue;
        auto same = std::find_if(merged.begin(), merged.end(), [&](const PlotMarker& o) { return o.x == m.x; });
        if (same == merged.end())
            merged.push_back(m);
        else
            same->label += ", " + m.label;
    }
    std::size_t tag = 1;
    for (const auto& m : merged) {
        script << "set arrow " << tag << " from first " << m.x << ", graph 0 to first " << m.x
               << ", graph 1 nohead dt 2 lw 1.2 lc rgb '#cc0000'\n"
               << "set label " << tag << " " << quoteForGnuplot(m.label + " " + formatNumber(m.x, 4) + " s") << " at first "
               << m.x << ", graph 0.97 rotate by 90 right offset -0.6,0 font ',8' tc rgb '#cc0000'\n";
        ++tag;
    }
    const std::size_t n = figure.panels.size();
    script << "set multiplot layout " << n << ",1 title " << quoteForGnuplot(figure.title) << "\n";
    for (std::size_t p = 0; p < n; ++p) {
        const PlotPanel& panel = figure.panels[p];
        if (p == 1) script << "unset label\n";
        script << "set title " << quoteForGnuplot(panel.title) << "\nset xlabel "
               << quoteForGnuplot(p + 1 == n ? result.plotXLabel : "") << "\nset ylabel "
               << quoteForGnuplot(panel.yLabel) << "\n";
        // The axis from the values drawn (a sum included), inside the range.
        std::vector<std::vector<double>> drawn;
        for (const auto& c : panel.curves) {
            std::vector<double> v = plotCurveValues(result, c), inside;
            const double scale = c.columns.size() == 1 && result.columnUnits[c.columns[0]] == "rad" ? 180 / 3.14159265358979323846 : 1.0;
            for (std::size_t i = 0; i < v.size(); ++i)
                if (!ranged || (!result.rows[i].empty() && result.rows[i][0] >= figure.xFrom && result.rows[i][0] <= figure.xTo))
                    inside.push_back(scale * v[i]);
            drawn.push_back(inside);
        }
        script << yAxisCommands(drawn) << "plot ";
        for (std::size_t k = 0; k < panel.curves.size(); ++k) {
            const PlotCurve& c = panel.curves[k];
            script << (k ? ", " : "") << quoteForGnuplot(csvPath) << " skip " << headerLines << " using "
                   << plotCurveUsing(result, c) << " with lines lw " << (c.columns.size() > 1 ? "2.5" : "1.5")
                   << " title " << quoteForGnuplot(c.title);
        }
        script << "\n";
    }
    script << "unset multiplot\n";
    return script.str();
}

std::vector<std::string> writePlots(const std::string& dir, const std::string& csvPath,
                                    const AnalysisResult& result, std::string& warning) {
    std::vector<std::string> written;
    if (!gnuplotAvailable()) {
        warning = "gnuplot not found: no plots written (scripts/install-deps installs it)";
        return written;
    }
    // Every plot is tried; any that is not drawn fails the set, naming all
    // of them (issue 26 item 8: a full disk gave exit 0 and named the last).
    std::vector<std::string> missing;
    const auto modes = modeShapeBars(result);
    if (!modes.empty()) {
        if (writeModeShapePlot(dir + "/mode_shapes.png", modes))
            written.push_back(dir + "/mode_shapes.png");
        else
            missing.push_back("mode_shapes.png");
    }
    // gnuplot runs in `dir`: the table by its bare name (renderGnuplotPng).
    const std::string csvName = std::filesystem::path(csvPath).filename().string();
    const std::string campbell = campbellPlotCommands(result, csvName);
    if (!campbell.empty()) {
        if (renderGnuplotPng(dir + "/campbell.png", campbell, 1200, 700))
            written.push_back(dir + "/campbell.png");
        else
            missing.push_back("campbell.png");
    }
    // A figure named as a plot replaces it, in its place; the others follow.
    auto findFigure = [&](const std::string& name) -> const PlotFigure* {
        for (const auto& f : result.figures)
            if (f.name == name && !f.panels.empty()) return &f;
        return nullptr;
    };
    auto drawFigure = [&](const PlotFigure& f) {
        const std::string png = dir + "/" + f.name + ".png";
        const int height = static_cast<int>(260 * f.panels.size()) + 80;
        if (renderGnuplotPng(png, formatFigureCommands(result, f, csvName), 1100, height))
            written.push_back(png);
        else
            missing.push_back(f.name + ".png");
    };
    for (const auto& plot : result.plots) {
        if (const PlotFigure* f = findFigure(plot.first)) {
            drawFigure(*f);
            continue;
        }
        if (plot.second.empty()) continue;
        const std::string png = dir + "/" + plot.first + ".png";
        const std::size_t panels = plotPanels(result, plot.second).size();
        const int height = panels > 1 ? static_cast<int>(300 * panels) + 60 : 560;
        if (!renderGnuplotPng(png, formatPlotCommands(result, plot.first, plot.second, csvName), 1000, height)) {
            missing.push_back(plot.first + ".png");
            continue;
        }
        written.push_back(png);
    }
    for (const auto& f : result.figures) {
        const bool asPlot = std::any_of(result.plots.begin(), result.plots.end(),
                                        [&](const auto& plot) { return plot.first == f.name; });
        if (!asPlot && !f.panels.empty()) drawFigure(f);
    }
    if (!missing.empty()) {
        std::string list;
        for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
        throw OutputError(std::to_string(missing.size()) + " of " + std::to_string(missing.size() + written.size()) +
                          " plots not drawn (gnuplot failed or left an incomplete PNG: a full disk?): " + list +
                          "; no output of this run was kept (outputs.plots: false or --no-plots skips the plots)");
    }
    return written;
}

std::string escapeMarkup(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace milldyn
