#include "driver/Sweep.h"

#include "driver/Api.h"

#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/OutputSet.h"
#include "driver/outputs/Writers.h"
#include "plugins/scene/ElementRegistry.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <thread>

namespace milldyn {
namespace {

using Json = nlohmann::ordered_json;

SpecError optionError(const std::string& option, const std::string& text, const std::string& reason) {
    return SpecError({"<" + option + " " + text + ">", 1, 1}, option, reason);
}

/// "12.5 N*m" → (12.5, "N*m"); the number must be the whole prefix.
std::pair<double, std::string> splitValue(const std::string& option, const std::string& all, const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    // Decimal numbers only, as the model reader takes them (strtod would
    // also take hex and "infinity").
    const bool decimal = end != begin && std::all_of(begin, static_cast<const char*>(end), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E';
    });
    if (!decimal || !std::isfinite(v)) throw optionError(option, all, "'" + text + "' is not a number");
    std::string unit(end);
    unit.erase(0, unit.find_first_not_of(' '));
    unit.erase(unit.find_last_not_of(' ') + 1);
    return {v, unit};
}

/// Splits "path=rest" and rest on ':'.
std::pair<std::string, std::vector<std::string>> splitSpec(const std::string& option, const std::string& text) {
    const auto eq = text.find('=');
    if (eq != std::string::npos) checkOverridePath(text.substr(0, eq));  // before any echo of it
    checkModelText(text, "<" + option + ">");  // the path lands in JSON point files
    if (eq == std::string::npos || eq == 0) throw optionError(option, text, "expected path=a:b" + std::string(option == "--grid" ? ":n" : ""));
    std::vector<std::string> parts;
    std::stringstream ss(text.substr(eq + 1));
    for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
    return {text.substr(0, eq), parts};
}

std::string formatSignificant(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return buf;
}

std::string valueText(double v, const std::string& unit) {
    return formatDouble(v) + (unit.empty() ? "" : " " + unit);
}

std::string pointFile(const std::string& dir, std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.json", index);
    return dir + "/points/" + name;
}

/// JSON text safe for any bytes: invalid UTF-8 (a file name, a --grid
/// path) is written as U+FFFD instead of throwing from the writer.
std::string jsonText(const Json& j) { return j.dump(1, ' ', false, Json::error_handler_t::replace) + "\n"; }

std::string manifestFile(const std::string& dir) { return dir + "/sweep-plan.json"; }

/// 64-bit FNV-1a, as 16 hex digits: tells sweeps apart, not a signature.
std::string digestOf(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

Json axesJson(const SweepPlan& plan, std::size_t point) {
    Json inputs = Json::array();
    for (std::size_t a = 0; a < plan.axes.size(); ++a)
        inputs.push_back({{"path", plan.axes[a].path},
                          {"value", plan.axes[a].values[plan.valueIndex(point, a)]},
                          {"unit", plan.axes[a].unit}});
    return inputs;
}

Json runPoint(const SweepPlan& plan, const SweepOptions& options, const Json& sweepTag, std::size_t point) {
    Json j;
    j["index"] = point;
    j["inputs"] = axesJson(plan, point);
    j["sweep"] = sweepTag;
    std::vector<Override> overrides = options.baseOverrides;
    const auto mine = plan.overrides(point);
    overrides.insert(overrides.end(), mine.begin(), mine.end());
    try {
        const ModelSpec spec = readModelFile(options.model, defaultModelReader(), overrides);
        const AnalysisResult r = runAnalysis(spec, options.cancel ? cancellableProgress(*options.cancel) : ProgressFn());
        Json results = Json::object();
        for (const auto& s : r.results) {
            if (!std::isfinite(s.value))
                throw AnalysisError("result " + s.name + " is not finite (the analysis diverged)");
            results[s.name] = {{"value", s.value}, {"unit", s.unit}};
        }
        // A start that stalled or did not finish (or a run-out that did not
        // end) is recorded as such; a run from a given state that ran or
        // held its speed is ok.
        const bool started = verdictKind(r.verdict) == VerdictKind::Done;  // one rule with run (driver/Api.h)
        j["status"] = started ? "ok" : r.verdict;
        j["diagnostic"] = started ? "" : r.verdictText;
        j["results"] = results;
    } catch (const RunCancelled&) {
        throw;  // not a result of the point: the sweep stops
    } catch (const SpecError& e) {
        j["status"] = "bad_input";
        j["diagnostic"] = e.formatted();
        j["results"] = Json::object();
    } catch (const AnalysisError& e) {
        j["status"] = "failed";
        j["diagnostic"] = e.what();
        j["results"] = Json::object();
    } catch (const std::exception& e) {  // one point's surprise is that point's failure, not the sweep's
        j["status"] = "failed";
        j["diagnostic"] = std::string("internal error: ") + e.what();
        j["results"] = Json::object();
    }
    return j;
}

/// Reads a point file; empty when absent or unreadable.
Json readPoint(const std::string& path) {
    std::ifstream in(path);
    if (!in) return Json();
    try {
        return Json::parse(in);
    } catch (const std::exception&) {
        return Json();  // a damaged file is recomputed
    }
}

/// The table from point files, in point order.
std::string formatTable(const std::vector<Json>& points) {
    std::vector<std::pair<std::string, std::string>> inputs;  // path, unit
    std::map<std::string, std::string> results;               // name → unit (sorted)
    for (const auto& p : points) {
        if (inputs.empty())
            for (const auto& in : p["inputs"]) inputs.emplace_back(in["path"], in["unit"]);
        for (auto it = p["results"].begin(); it != p["results"].end(); ++it)
            results.emplace(it.key(), it.value()["unit"].get<std::string>());
    }
    // Every text field per RFC 4180 (csvField): a path or result name with
    // a comma or line break stays one field.
    std::string out = "index[1]";
    for (const auto& in : inputs) out += "," + csvField(in.first + "[" + (in.second.empty() ? "SI" : in.second) + "]");
    out += ",status";
    for (const auto& r : results) out += "," + csvField(r.first + "[" + r.second + "]");
    out += ",diagnostic\n";
    for (const auto& p : points) {
        out += std::to_string(p["index"].get<std::size_t>());
        for (const auto& in : p["inputs"]) out += "," + formatDouble(in["value"].get<double>());
        out += "," + csvField(p["status"].get<std::string>());
        for (const auto& r : results) {
            out += ",";
            if (p["results"].contains(r.first)) out += formatDouble(p["results"][r.first]["value"].get<double>());
        }
        out += "," + csvField(p["diagnostic"].get<std::string>()) + "\n";
    }
    return out;
}

SweepSummary writeTable(const std::string& outDir, std::vector<Json> points, SweepSummary summary) {
    std::sort(points.begin(), points.end(),
              [](const Json& a, const Json& b) { return a["index"].get<std::size_t>() < b["index"].get<std::size_t>(); });
    for (const auto& p : points) {
        summary.failed += p["status"] != "ok";
        summary.errors += p["status"] == "failed" || p["status"] == "bad_input";
    }
    summary.total = points.size();
    writeFileAtomically(outDir + "/sweep.csv", formatTable(points));
    summary.files.push_back(outDir + "/sweep.csv");
    return summary;
}

/// What a sweep is: the digest of everything that determines its points
/// (the model document after includes, preset and --set; the --set list
/// itself, analysis, integrator and scenario included; the plan's kind,
/// axes and values) and the manifest DIR/sweep-plan.json that records it.
Json sweepManifest(const SweepPlan& plan, const SweepOptions& options) {
    // Plots are no part of what a sweep computes (isPresentationPath): the
    // document is taken with outputs.plots set one way, whatever the file
    // or --set say, and such --set are left out of the list.
    std::vector<Override> identity;
    for (const auto& o : options.baseOverrides)
        if (!isPresentationPath(o.path)) identity.push_back(o);
    std::vector<Override> forDigest = identity;
    forDigest.push_back({"outputs.plots", "true"});
    std::string resolved;
    // outputs.sweep_plots in the file likewise (set one way only when the
    // file has it, so the digest of a model without it is unchanged).
    if (!readModelFile(options.model, defaultModelReader(), forDigest, &resolved).outputs.sweepPlots.empty()) {
        forDigest.push_back({"outputs.sweep_plots", "headline"});
        readModelFile(options.model, defaultModelReader(), forDigest, &resolved);
    }
    Json overrides = Json::array();
    for (const auto& o : identity) overrides.push_back(o.path + "=" + o.value);
    Json axes = Json::array();
    for (const auto& a : plan.axes) {
        std::string values;
        for (double v : a.values) values += formatDouble(v) + "\n";
        Json axis = {{"path", a.path},
                     {"unit", a.unit},
                     {"count", a.values.size()},
                     {"first", a.values.empty() ? 0.0 : a.values.front()},
                     {"last", a.values.empty() ? 0.0 : a.values.back()},
                     {"values_digest", digestOf(values)}};
        if (a.tiedToPrevious) axis["tied_to_previous"] = true;  // absent otherwise: older digests stay
        axes.push_back(axis);
    }
    Json m;
    m["kind"] = plan.cartesian ? "grid" : "lhs";
    m["count"] = plan.count;
    m["axes"] = axes;
    m["overrides"] = overrides;
    m["model_digest"] = digestOf(resolved);
    m["digest"] = digestOf(jsonText(m));  // all of the above; not the model's path
    m["model"] = options.model;           // for the reason when a directory is refused
    return m;
}

/// The tag every point file carries: which sweep, and how many points it has.
Json sweepTag(const Json& manifest) { return {{"digest", manifest["digest"]}, {"count", manifest["count"]}}; }

/// Why the sweep recorded in `theirs` is not the one of `mine`.
std::string differences(const Json& theirs, const Json& mine) {
    std::vector<std::string> what;
    if (theirs.value("model", "") != mine.value("model", "")) what.push_back("model " + theirs.value("model", std::string("?")));
    if (theirs.value("model_digest", "") != mine.value("model_digest", ""))
        what.push_back("other model content (the file, a part it includes, its preset or analysis)");
    if (theirs.value("overrides", Json()) != mine["overrides"]) what.push_back("other --set/--integrator/--accuracy/--scenario/--preset");
    if (theirs.value("kind", "") != mine["kind"] || theirs.value("count", Json()) != mine["count"] ||
        theirs.value("axes", Json()) != mine["axes"])
        what.push_back("another plan (" + theirs.value("kind", std::string("?")) + " of " +
                       (theirs.contains("count") ? theirs["count"].dump() : std::string("?")) + " points)");
    std::string out;
    for (const auto& w : what) out += (out.empty() ? "" : "; ") + w;
    return out.empty() ? "another digest" : out;
}

/// Makes DIR the directory of this sweep: creates its manifest, or checks
/// that the one there is this sweep's. Another sweep's directory is refused
/// (two sweeps into one directory would mix their points).
void claimDirectory(const std::string& dir, const Json& manifest) {
    const std::string path = manifestFile(dir);
    for (int attempt = 0; attempt < 3; ++attempt) {
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) {
            const Json theirs = readPoint(path);
            if (theirs.is_object() && theirs.value("digest", "") == manifest["digest"]) return;
            if (!theirs.is_object())
                throw SpecError({path, 1, 1}, "--out",
                                "not a sweep plan (damaged?): delete it or choose another --out");
            throw SpecError({path, 1, 1}, "--out",
                            dir + " holds another sweep (" + differences(theirs, manifest) +
                                "): choose another --out, or delete " + dir + " to start over");
        }
        if (createFileExclusively(path, jsonText(manifest))) return;
    }
    throw OutputError("cannot claim " + dir + " for the sweep: " + path + " keeps changing");
}

}  // namespace

namespace {

/// The dimension (group of tied axes) of each axis, and each group's size.
std::vector<std::size_t> groupsOf(const std::vector<SweepAxis>& axes) {
    std::vector<std::size_t> group;
    for (std::size_t a = 0; a < axes.size(); ++a)
        group.push_back(a == 0 ? 0 : group.back() + (axes[a].tiedToPrevious ? 0 : 1));
    return group;
}

/// The two ends of a range "a:b" with one unit: a bare 0 takes the other
/// end's unit; any other bare number beside a unit is refused (issue 26
/// item 7: `25 %:0.45` swept to 0.45 %).
std::string commonUnit(const std::string& option, const std::string& text,
                       const std::vector<std::pair<double, std::string>>& values) {
    std::string unit;
    for (const auto& v : values)
        if (!v.second.empty()) unit = v.second;
    for (const auto& v : values) {
        if (v.second == unit || (v.second.empty() && v.first == 0)) continue;
        std::string written;
        for (const auto& w : values)
            written += (written.empty() ? "'" : ", '") + formatSignificant(w.first) + (w.second.empty() ? "" : " " + w.second) + "'";
        throw optionError(option, text,
                          v.second.empty() || unit.empty()
                              ? "every value needs the same unit (" + written + "): write the unit on each"
                              : "every value must be in the same unit (" + written + ")");
    }
    return unit;
}

/// Splits "spec;spec;..." (tied paths) into its parts.
std::vector<std::string> tiedParts(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ';');) {
        p.erase(0, p.find_first_not_of(' '));
        p.erase(p.find_last_not_of(' ') + 1);
        parts.push_back(p);
    }
    if (!text.empty() && text.back() == ';') parts.push_back("");
    return parts;
}

}  // namespace

std::size_t SweepPlan::valueIndex(std::size_t point, std::size_t axis) const {
    if (!cartesian) return point;
    // Row-major over the dimensions: the last one varies fastest; tied
    // axes share their dimension's index.
    const auto group = groupsOf(axes);
    std::size_t stride = 1;
    for (std::size_t a = axes.size(); a-- > 0;)
        if (group[a] > group[axis] && (a + 1 == axes.size() || group[a + 1] != group[a])) stride *= axes[a].values.size();
    return (point / stride) % axes[axis].values.size();
}

std::vector<Override> SweepPlan::overrides(std::size_t point) const {
    std::vector<Override> out;
    for (std::size_t a = 0; a < axes.size(); ++a)
        out.push_back({axes[a].path, valueText(axes[a].values[valueIndex(point, a)], axes[a].unit),
                       axes[a].bareNumberIsSI && axes[a].unit.empty()});
    return out;
}

SweepAxis parseGrid(const std::string& text) {
    if (text.find(';') != std::string::npos)
        throw optionError("--grid", text, "one path here (paths tied with ';' go through parseGridAxes)");
    const auto [path, parts] = splitSpec("--grid", text);
    const std::string listed = text.substr(text.find('=') + 1);
    // A value list: "v1,v2,...".
    if (parts.size() == 1 && listed.find(',') != std::string::npos) {
        std::vector<std::pair<double, std::string>> values;
        std::stringstream ss(listed);
        for (std::string v; std::getline(ss, v, ',');) {
            v.erase(0, v.find_first_not_of(' '));
            values.push_back(splitValue("--grid", text, v));
        }
        if (values.size() > 100000) throw optionError("--grid", text, "at most 100000 values");
        SweepAxis axis{path, commonUnit("--grid", text, values), {}, false};
        for (const auto& v : values) axis.values.push_back(v.first);
        return axis;
    }
    if (parts.size() != 3 && !(parts.size() == 4 && (parts[3] == "log" || parts[3] == "lin")))
        throw optionError("--grid", text, "expected path=a:b:n, path=a:b:n:log or path=v1,v2,...");
    const auto a = splitValue("--grid", text, parts[0]);
    const auto b = splitValue("--grid", text, parts[1]);
    const std::string unit = commonUnit("--grid", text, {a, b});
    char* end = nullptr;
    const long n = std::strtol(parts[2].c_str(), &end, 10);
    if (parts[2].empty() || *end != '\0' || n < 1 || n > 100000)
        throw optionError("--grid", text, "n must be a whole number 1..100000");
    const bool log = parts.size() == 4 && parts[3] == "log";
    if (log && !(a.first * b.first > 0))
        throw optionError("--grid", text, "a log-spaced axis needs both ends of one sign and not 0");
    SweepAxis axis{path, unit, {}, false};
    // 12 significant digits: 0.1:0.5:3 gives 0.3, not 0.30000000000000004.
    for (long i = 0; i < n; ++i) {
        const double f = n == 1 ? 0.0 : double(i) / double(n - 1);
        const double v = log ? a.first * std::pow(b.first / a.first, f) : a.first + (b.first - a.first) * f;
        axis.values.push_back(std::stod(formatSignificant(v)));
    }
    return axis;
}

std::vector<SweepAxis> parseGridAxes(const std::string& text) {
    std::vector<SweepAxis> axes;
    for (const auto& part : tiedParts(text)) {
        axes.push_back(parseGrid(part));
        axes.back().tiedToPrevious = axes.size() > 1;
        if (axes.back().values.size() != axes.front().values.size())
            throw optionError("--grid", text,
                              "tied paths need the same number of values (" + axes.front().path + ": " +
                                  std::to_string(axes.front().values.size()) + ", " + axes.back().path + ": " +
                                  std::to_string(axes.back().values.size()) + ")");
    }
    return axes;
}

SweepAxis parseRange(const std::string& text) {
    const auto [path, parts] = splitSpec("--range", text);
    if (parts.size() != 2) throw optionError("--range", text, "expected path=a:b");
    const auto a = splitValue("--range", text, parts[0]);
    const auto b = splitValue("--range", text, parts[1]);
    return {path, commonUnit("--range", text, {a, b}), {a.first, b.first}, false};
}

std::vector<SweepAxis> parseRangeAxes(const std::string& text) {
    std::vector<SweepAxis> axes;
    for (const auto& part : tiedParts(text)) {
        axes.push_back(parseRange(part));
        axes.back().tiedToPrevious = axes.size() > 1;
    }
    return axes;
}

bool isPresentationPath(const std::string& path) {
    return path == "outputs.plots" || path == "outputs.sweep_plots";
}

void checkSweepPaths(const std::vector<SweepAxis>& axes, const std::vector<Override>& base) {
    for (std::size_t a = 0; a < axes.size(); ++a) {
        for (std::size_t b = 0; b < a; ++b)
            if (axes[b].path == axes[a].path)
                throw optionError("--grid", axes[a].path,
                                  axes[a].path + " is swept twice: the first axis would never be used (one axis per path)");
        for (const auto& o : base)
            if (o.path == axes[a].path)
                throw optionError("--set", o.path + "=" + o.value,
                                  o.path + " is set and swept: the sweep would override the set value at every "
                                           "point (leave out the --set or the axis)");
    }
}

SweepPlan makeGrid(std::vector<SweepAxis> axes) {
    SweepPlan plan;
    plan.cartesian = true;
    plan.count = axes.empty() ? 0 : 1;
    // Refused up front: the product of a few long axes is beyond any run
    // (three axes of 100,000 values: 1e15 points).
    double points = 1;
    std::string sizes;
    for (const auto& a : axes) {
        if (a.tiedToPrevious) continue;
        points *= double(a.values.size());
        sizes += (sizes.empty() ? "" : " x ") + std::to_string(a.values.size());
    }
    if (!axes.empty() && points > double(kMaxSweepPoints))
        throw optionError("--grid", sizes, "the grid has " + formatSignificant(points) + " points (" + sizes +
                                               "), more than the " + std::to_string(kMaxSweepPoints) +
                                               " a sweep may have: use fewer values or --lhs");
    checkSweepPaths(axes);
    for (std::size_t a = 0; a < axes.size(); ++a) {
        if (axes[a].values.empty()) throw optionError("--grid", axes[a].path, "an axis needs at least one value");
        if (a > 0 && axes[a].tiedToPrevious && axes[a].values.size() != axes[a - 1].values.size())
            throw optionError("--grid", axes[a].path, "tied paths need the same number of values");
        if (!axes[a].tiedToPrevious) plan.count *= axes[a].values.size();
    }
    plan.axes = std::move(axes);
    return plan;
}

SweepPlan makeLatinHypercube(std::vector<SweepAxis> ranges, std::size_t n, unsigned long seed) {
    // mt19937_64 and our own mapping to [0, 1): the standard distributions
    // are not specified bit for bit, the engine is.
    std::mt19937_64 rng(seed);
    auto uniform = [&rng] { return double(rng() >> 11) * 0x1.0p-53; };
    SweepPlan plan;
    plan.cartesian = false;
    plan.count = n;
    checkSweepPaths(ranges);
    // One draw per dimension; tied ranges take the same fractions.
    std::vector<double> fractions;
    for (auto& r : ranges) {
        const double lo = r.values[0], hi = r.values[1];
        if (!r.tiedToPrevious) {
            std::vector<std::size_t> strata(n);
            std::iota(strata.begin(), strata.end(), 0);
            for (std::size_t i = n; i > 1; --i) std::swap(strata[i - 1], strata[rng() % i]);  // Fisher-Yates
            fractions.clear();
            for (std::size_t i = 0; i < n; ++i) fractions.push_back((double(strata[i]) + uniform()) / double(n));
        }
        r.values.clear();
        for (std::size_t i = 0; i < n; ++i) r.values.push_back(lo + (hi - lo) * fractions[i]);
    }
    plan.axes = std::move(ranges);
    return plan;
}

SweepPart runSweepPart(const SweepPlan& plan, const SweepOptions& options,
                       const std::function<void(std::size_t, std::size_t, std::size_t)>& progress) {
    ElementRegistry::instance();  // built once, before the workers read it
    checkSweepPaths(plan.axes, options.baseOverrides);
    const Json manifest = sweepManifest(plan, options);
    const Json tag = sweepTag(manifest);
    ensureDirectory(options.outDir + "/points");
    claimDirectory(options.outDir, manifest);
    // Temporaries of a sweep killed by SIGKILL (its point files being
    // written): removed once their process is gone.
    removeStaleStaging(options.outDir);
    removeStaleStaging(options.outDir + "/points");

    std::vector<std::size_t> mine;
    for (std::size_t i = 0; i < plan.count; ++i)
        if (i % options.shardCount == options.shardIndex) mine.push_back(i);

    SweepSummary summary;
    std::vector<Json> points(mine.size());
    std::vector<std::size_t> todo;
    for (std::size_t k = 0; k < mine.size(); ++k) {
        Json cached = readPoint(pointFile(options.outDir, mine[k]));
        // A point is reused only if it belongs to this very sweep: same
        // digest (model content, --set, analysis, integrator) and inputs.
        if (cached.is_object() && cached.value("sweep", Json()) == tag && cached.contains("inputs") &&
            cached["inputs"] == axesJson(plan, mine[k]) && cached.contains("status") && cached.contains("results") &&
            cached.contains("diagnostic")) {
            points[k] = cached;
            ++summary.resumed;
        } else {
            todo.push_back(k);
        }
    }

    std::atomic<std::size_t> next{0};
    std::mutex progressMutex;
    std::size_t done = 0, failed = 0;
    std::exception_ptr fatal;
    auto worker = [&] {
        for (std::size_t t; (t = next++) < todo.size();) {
            const std::size_t k = todo[t];
            if (options.cancel && options.cancel->cancelled) {
                next = todo.size();
                return;
            }
            try {
                points[k] = runPoint(plan, options, tag, mine[k]);
                writeFileAtomically(pointFile(options.outDir, mine[k]), jsonText(points[k]));
            } catch (...) {
                std::lock_guard<std::mutex> lock(progressMutex);
                if (!fatal) fatal = std::current_exception();
                next = todo.size();
                return;
            }
            std::lock_guard<std::mutex> lock(progressMutex);
            ++done;
            failed += points[k]["status"] != "ok";
            if (progress) progress(done, todo.size(), failed);
        }
    };
    const unsigned jobs = std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(std::max<std::size_t>(1, todo.size()))));
    std::vector<std::thread> threads;
    for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(worker);
    worker();
    for (auto& t : threads) t.join();
    if (fatal) std::rethrow_exception(fatal);
    if (options.cancel && options.cancel->cancelled)
        throw RunCancelled("sweep cancelled after " + std::to_string(done) + " of " + std::to_string(todo.size()) +
                           " points (they are kept and resume)");
    summary.run = todo.size();
    SweepPart part;
    part.summary = summary;
    for (const auto& p : points) part.points.push_back(jsonText(p));  // the point file's text
    return part;
}

SweepSummary runSweep(const SweepPlan& plan, const SweepOptions& options,
                      const std::function<void(std::size_t, std::size_t, std::size_t)>& progress) {
    const SweepPart part = runSweepPart(plan, options, progress);
    return writeSweepTable(options.outDir, part.points, part.summary, false);
}

SweepSummary writeSweepTable(const std::string& outDir, const std::vector<std::string>& texts,
                             SweepSummary summary, bool writePoints) {
    std::vector<Json> points;
    for (const auto& text : texts) {
        Json p = Json::parse(text, nullptr, false);
        if (p.is_discarded() || !p.contains("index") || !p.contains("inputs"))
            throw SpecError({outDir, 1, 1}, "<point>", "not a sweep point");
        points.push_back(std::move(p));
    }
    if (writePoints) {
        ensureDirectory(outDir + "/points");
        for (std::size_t k = 0; k < points.size(); ++k)
            writeFileAtomically(pointFile(outDir, points[k]["index"].get<std::size_t>()), texts[k]);
    }
    return writeTable(outDir, points, summary);
}

SweepSummary mergeSweeps(const std::vector<std::string>& dirs, const std::string& outDir) {
    std::map<std::size_t, Json> byIndex;
    Json tag, manifest;
    std::string tagFrom;
    for (const auto& dir : dirs) {
        std::error_code ec;
        if (!std::filesystem::is_directory(dir + "/points", ec))
            throw SpecError({dir, 1, 1}, "<dir>", "not a sweep directory (no points/)");
        const Json theirs = readPoint(manifestFile(dir));
        if (theirs.is_object() && manifest.is_null()) manifest = theirs;
        for (const auto& entry : std::filesystem::directory_iterator(dir + "/points")) {
            if (entry.path().extension() != ".json") continue;
            const std::string file = entry.path().string();
            Json p = readPoint(file);
            if (!p.is_object() || !p.contains("index") || !p["index"].is_number_unsigned())
                throw SpecError({file, 1, 1}, "<file>", "not a sweep point file");
            // The plan travels with every point: parts of one sweep only.
            const Json mine = p.value("sweep", Json());
            if (!mine.is_object() || !mine.contains("digest") || !mine.contains("count") ||
                !mine["count"].is_number_unsigned())
                throw SpecError({file, 1, 1}, "sweep",
                                "the point records no sweep plan (written by an older milldyn): rerun that part");
            if (tag.is_null()) {
                tag = mine;
                tagFrom = file;
            } else if (mine != tag) {
                throw SpecError({file, 1, 1}, "sweep",
                                "belongs to another sweep than " + tagFrom + " (digest " +
                                    mine["digest"].get<std::string>() + ", not " + tag["digest"].get<std::string>() +
                                    "): merge the parts of one sweep only");
            }
            const std::size_t index = p["index"];
            if (index >= tag["count"].get<std::size_t>())
                throw SpecError({file, 1, 1}, "index", "point " + std::to_string(index) + " lies outside the sweep's " +
                                                           tag["count"].dump() + " points");
            auto it = byIndex.find(index);
            if (it != byIndex.end() && it->second["inputs"] != p["inputs"])
                throw SpecError({file, 1, 1}, "inputs",
                                "point " + std::to_string(index) + " has different inputs in two parts");
            byIndex[index] = p;
        }
    }
    if (tag.is_null()) throw SpecError({dirs.front(), 1, 1}, "<dir>", "no sweep points to merge");
    // All points or nothing: a short table would read as a complete one.
    const std::size_t count = tag["count"];
    if (byIndex.size() != count) {
        std::string missing;
        std::size_t shown = 0;
        for (std::size_t i = 0; i < count && shown < 10; ++i)
            if (!byIndex.count(i)) missing += (shown++ ? ", " : "") + std::to_string(i);
        if (count - byIndex.size() > shown) missing += ", ...";
        throw SpecError({dirs.front(), 1, 1}, "points",
                        std::to_string(count - byIndex.size()) + " of the sweep's " + std::to_string(count) +
                            " points are missing (" + missing + "): a shard not run or not finished; nothing merged");
    }
    ensureDirectory(outDir + "/points");
    if (manifest.is_object() && manifest.value("digest", "") == tag["digest"]) claimDirectory(outDir, manifest);
    std::vector<Json> points;
    for (auto& kv : byIndex) {
        writeFileAtomically(pointFile(outDir, kv.first), jsonText(kv.second));
        points.push_back(kv.second);
    }
    SweepSummary summary;
    summary.resumed = points.size();
    return writeTable(outDir, points, summary);
}

}  // namespace milldyn
