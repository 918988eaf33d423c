#include "driver/analyses/TransientFigures.h"

#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace milldyn {
namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

const Probe* probeNamed(const Scene& scene, const std::string& name) {
    for (const auto& p : scene.probes())
        if (p.name == name) return &p;
    return nullptr;
}

/// The body a key of `element` names: a body key's value, or the second of
/// a body pair for "driven"; empty if none.
std::string bodyOfKey(const ElementSpec& e, const std::string& key) {
    const auto v = e.params.find(key);
    if (v != e.params.end() && !v->second.text.empty()) return v->second.text;
    if (key == "driven") {
        const auto pair = e.params.find("bodies");
        if (pair != e.params.end() && pair->second.names.size() == 2) return pair->second.names[1];
    }
    return "";
}

/// The one shaft a torque column acts on: a drive's, load's or coupling's
/// (a coupling's driving shaft, probeShaft), a `torque_on_KEY` or
/// `driven_torque` on the body of that key, else the probe's own shaft when
/// it has one. Empty when its element acts on several shafts and the name
/// does not say which.
std::string shaftOf(const Scene& scene, const ModelSpec& spec, const std::string& name) {
    const Probe* p = probeNamed(scene, name);
    if (!p) return "";
    const std::size_t dot = name.rfind('.');
    const ElementSpec* e = dot == std::string::npos ? nullptr : spec.findElement(name.substr(0, dot));
    const std::string quantity = dot == std::string::npos ? name : name.substr(dot + 1);
    if (e && quantity.rfind("torque_on_", 0) == 0)
        if (const std::string b = bodyOfKey(*e, quantity.substr(10)); !b.empty()) return b;
    if (e && quantity == "driven_torque")
        if (const std::string b = bodyOfKey(*e, "driven"); !b.empty()) return b;
    if (p->role != ProbeRole::Generic) {
        const std::string shaft = probeShaft(spec, name);
        if (!shaft.empty() && shaft.find(',') == std::string::npos) return shaft;
    }
    return p->shaft.find(',') == std::string::npos ? p->shaft : std::string();
}

ProbeRole roleOf(const Scene& scene, const std::string& name) {
    const Probe* p = probeNamed(scene, name);
    return p ? p->role : ProbeRole::Generic;
}

PlotCurve single(const AnalysisResult& r, std::size_t col) { return {r.columnNames[col], {col}}; }

/// Columns of unit `unit` whose names end with one of `tails`.
std::vector<std::size_t> columnsEndingWith(const AnalysisResult& r, const std::vector<std::string>& tails,
                                           const std::string& unit = "") {
    std::vector<std::size_t> out;
    for (std::size_t i = 1; i < r.columnNames.size(); ++i)
        if ((unit.empty() || r.columnUnits[i] == unit) &&
            std::any_of(tails.begin(), tails.end(), [&](const std::string& t) { return endsWith(r.columnNames[i], t); }))
            out.push_back(i);
    return out;
}

/// The body speed columns (NAME.speed, NAME.speed_rel_PARENT), one panel per
/// group of like magnitudes (plotPanels' rule, so a 1.9 rad/s mill beside a
/// 157 rad/s motor is no flat line).
std::vector<PlotPanel> speedPanels(const Scene& scene, const AnalysisResult& r) {
    std::vector<std::size_t> speeds;
    for (const auto& b : scene.bodies()) {
        const std::size_t c = r.findColumn(speedColumnName(scene, b));
        if (c != std::string::npos) speeds.push_back(c);
    }
    std::vector<PlotPanel> panels;
    // plotPanels lives with the writers; the same rule here: within a factor 10.
    std::vector<std::pair<double, std::vector<std::size_t>>> groups;  // largest |value|, columns
    for (std::size_t c : speeds) {
        double peak = 0;
        for (const auto& row : r.rows)
            if (c < row.size() && std::isfinite(row[c])) peak = std::max(peak, std::abs(row[c]));
        bool placed = false;
        for (auto& g : groups)
            if (!placed && (peak == 0 || g.first == 0 || (std::max(peak, g.first) <= 10 * std::min(peak, g.first)))) {
                g.second.push_back(c);
                g.first = std::max(g.first, peak);
                placed = true;
            }
        if (!placed) groups.push_back({peak, {c}});
    }
    for (const auto& g : groups) {
        PlotPanel p{"speeds", "speed [rad/s]", "", {}};
        for (std::size_t c : g.second) p.curves.push_back(single(r, c));
        panels.push_back(p);
    }
    return panels;
}

/// One panel per element of the columns `cols` (by the name before the dot).
std::vector<PlotPanel> panelsPerElement(const AnalysisResult& r, const std::vector<std::size_t>& cols,
                                        const std::string& what, const std::string& quantity) {
    std::vector<PlotPanel> panels;
    std::map<std::string, std::size_t> at;
    for (std::size_t c : cols) {
        const std::string element = r.columnNames[c].substr(0, r.columnNames[c].rfind('.'));
        const std::string key = element + "|" + r.columnUnits[c];
        if (!at.count(key)) {
            at[key] = panels.size();
            // A slip is a distance (m, the belt's creep summed) or a speed.
            const std::string q = quantity != "slip" ? quantity : r.columnUnits[c] == "m" ? "slip distance" : "slip speed";
            panels.push_back({(quantity != "slip" ? what : q) + " of " + element, q + " [" + r.columnUnits[c] + "]", "", {}});
        }
        panels[at[key]].curves.push_back(single(r, c));
    }
    return panels;
}

void append(std::vector<PlotPanel>& to, const std::vector<PlotPanel>& more) { to.insert(to.end(), more.begin(), more.end()); }

/// One panel per shaft of the torques of `roles` (all torques if empty),
/// with the sum of the loads on the shaft when it has several loads.
std::vector<PlotPanel> torquePanels(const Scene& scene, const ModelSpec& spec, const AnalysisResult& r,
                                    const std::vector<ProbeRole>& roles, const std::string& what, bool loadSum) {
    std::vector<PlotPanel> panels;
    for (const auto& [shaft, columns] : torqueColumnsByShaft(scene, spec, r)) {
        // Torques of elements on several shafts whose name says not which:
        // a panel per element, never one with a shaft's.
        if (shaft.empty()) {
            std::vector<std::size_t> chosen;
            for (std::size_t c : columns)
                if (roles.empty() || std::find(roles.begin(), roles.end(), roleOf(scene, r.columnNames[c])) != roles.end())
                    chosen.push_back(c);
            append(panels, panelsPerElement(r, chosen, what, "torque"));
            continue;
        }
        PlotPanel p{what + " on " + shaft, "torque [N*m]", shaft, {}};
        std::vector<std::size_t> loads;
        for (std::size_t c : columns) {
            const ProbeRole role = roleOf(scene, r.columnNames[c]);
            if (!roles.empty() && std::find(roles.begin(), roles.end(), role) == roles.end()) continue;
            p.curves.push_back(single(r, c));
            if (role == ProbeRole::ResistanceTorque) loads.push_back(c);
        }
        if (loadSum && loads.size() > 1)
            p.curves.push_back({"sum of the " + std::to_string(loads.size()) + " loads on " + shaft, loads});
        if (!p.curves.empty()) panels.push_back(p);
    }
    return panels;
}

}  // namespace

std::vector<std::pair<std::string, std::vector<std::size_t>>> torqueColumnsByShaft(const Scene& scene,
                                                                                  const ModelSpec& spec,
                                                                                  const AnalysisResult& result) {
    std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
    for (const auto& b : scene.bodies()) groups.push_back({b.name, {}});
    groups.push_back({"", {}});
    for (std::size_t i = 1; i < result.columnNames.size(); ++i) {
        if (result.columnUnits[i] != "N*m") continue;
        const std::string shaft = shaftOf(scene, spec, result.columnNames[i]);
        auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == shaft; });
        (g == groups.end() ? groups.back() : *g).second.push_back(i);
    }
    groups.erase(std::remove_if(groups.begin(), groups.end(), [](const auto& g) { return g.second.empty(); }),
                 groups.end());
    return groups;
}

void addTransientFigures(const Scene& scene, const ModelSpec& spec, const TransientFigureTimes& times,
                         AnalysisResult& result) {
    const AnalysisResult& r = result;
    const std::vector<std::size_t> currents = columnsEndingWith(r, {".current", ".line_current"}, "A");
    const std::vector<std::size_t> slips = columnsEndingWith(r, {".slip_speed", ".slip"});

    // Torques: one panel per shaft, every torque on it, the loads' sum.
    PlotFigure torques{"torques", "torques, one panel per shaft (a coupling's on its driving shaft)", {}, {}};
    torques.panels = torquePanels(scene, spec, r, {}, "torques", true);
    if (!torques.panels.empty()) result.figures.push_back(torques);

    // The start: speeds, drive torques, currents, coupling torques, slips,
    // and the verdict's instants.
    if (times.fromRest) {
        PlotFigure start{"start", "start: " + (r.verdict.empty() ? std::string("no verdict") : r.verdict), {}, {}};
        start.panels = speedPanels(scene, r);
        append(start.panels, torquePanels(scene, spec, r, {ProbeRole::DriveTorque}, "drive torque", false));
        append(start.panels, panelsPerElement(r, currents, "current", "current"));
        append(start.panels, torquePanels(scene, spec, r, {ProbeRole::CouplingTorque}, "coupling torque", false));
        append(start.panels, panelsPerElement(r, slips, "slip", "slip"));
        // A wound rotor's starter: the heat in the winding and in the
        // external resistance (issue 29 item 6).
        append(start.panels, panelsPerElement(r, columnsEndingWith(r, {".rotor_winding_loss", ".starter_loss"}, "W"),
                                              "rotor heat rate", "heat rate"));
        double last = 0;
        for (const auto& res : r.results)
            if (res.name == "start_time" || res.name.rfind("sequence_end.", 0) == 0) {
                start.markers.push_back({res.value, res.name});
                last = std::max(last, res.value);
            }
        for (const auto& e : times.steps)
            if (e.x >= 0 && e.x <= times.endTime) {
                start.markers.push_back(e);
                last = std::max(last, e.x);
            }
        for (const auto& e : times.switchOffs)
            if (e.x >= 0 && e.x <= times.endTime) start.markers.push_back(e);
        // The start and a quarter beyond its last instant, within the run.
        if (last > 0 && 1.25 * last < times.endTime) {
            start.xFrom = 0;
            start.xTo = 1.25 * last;
        }
        if (!start.panels.empty()) result.figures.push_back(start);
    }

    // Steady operation over whole load periods: speeds, the loads and their
    // sum per shaft, drive and coupling torques.
    if (times.steadyTo > times.steadyFrom) {
        PlotFigure steady{"steady", "steady operation: " + times.steadyWhat, {}, {}};
        // A panel per speed of speed_body and of each drive's shaft, so that
        // a fluctuation of a few per cent is not flattened beside another
        // shaft's speed.
        std::vector<std::string> shown = {times.speedBody};
        for (const auto& [shaft, columns] : torqueColumnsByShaft(scene, spec, r))
            for (std::size_t c : columns)
                if (roleOf(scene, r.columnNames[c]) == ProbeRole::DriveTorque &&
                    std::find(shown.begin(), shown.end(), shaft) == shown.end())
                    shown.push_back(shaft);
        for (const auto& body : shown)
            for (const auto& b : scene.bodies())
                if (b.name == body)
                    if (const std::size_t c = r.findColumn(speedColumnName(scene, b)); c != std::string::npos)
                        steady.panels.push_back({"speed of " + body, "speed [rad/s]", "", {single(r, c)}});
        append(steady.panels, torquePanels(scene, spec, r, {ProbeRole::ResistanceTorque}, "loads", true));
        append(steady.panels, torquePanels(scene, spec, r, {ProbeRole::DriveTorque}, "drive torque", false));
        append(steady.panels, torquePanels(scene, spec, r, {ProbeRole::CouplingTorque}, "coupling torque", false));
        steady.xFrom = times.steadyFrom;
        steady.xTo = times.steadyTo;
        if (!steady.panels.empty()) result.figures.push_back(steady);
    }

    // Belt tensions and slip, per belt.
    const std::vector<std::size_t> tensions =
        columnsEndingWith(r, {".tension_tight", ".tension_slack", ".tension_lead", ".tension_trail"}, "N");
    if (!tensions.empty()) {
        PlotFigure belts{"belts", "belt tensions and slip", {}, {}};
        belts.panels = panelsPerElement(r, tensions, "tensions", "tension");
        std::vector<std::size_t> beltSlips;
        for (std::size_t c : slips) {
            const std::string element = r.columnNames[c].substr(0, r.columnNames[c].rfind('.'));
            for (std::size_t t : tensions)
                if (r.columnNames[t].rfind(element + ".", 0) == 0) {
                    beltSlips.push_back(c);
                    break;
                }
        }
        append(belts.panels, panelsPerElement(r, beltSlips, "slip", "slip"));
        result.figures.push_back(belts);
    }

    // Currents, per motor.
    if (!currents.empty()) {
        PlotFigure fig{"currents", "currents", panelsPerElement(r, currents, "current", "current"), {}};
        if (times.fromRest)
            for (const auto& f : result.figures)
                if (f.name == "start") fig.markers = f.markers;
        result.figures.push_back(fig);
    }
}

}  // namespace milldyn
