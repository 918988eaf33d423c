#include "driver/analyses/Analysis.h"

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/EnergyMeter.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace milldyn {

std::vector<ResultScalar> derivedResults(const Scene& scene) {
    std::vector<ResultScalar> out;
    for (const DerivedValue& d : scene.derivedValues()) out.push_back({d.name, d.value, d.unit, d.doc});
    return out;
}

const ResultScalar* AnalysisResult::find(const std::string& name) const {
    for (const auto& r : results)
        if (r.name == name) return &r;
    return nullptr;
}

std::size_t AnalysisResult::findColumn(const std::string& name) const {
    for (std::size_t i = 0; i < columnNames.size(); ++i)
        if (columnNames[i] == name) return i;
    return std::numeric_limits<std::size_t>::max();
}

double AnalysisResult::value(std::size_t row, const std::string& name) const {
    const std::size_t c = findColumn(name);
    if (c == std::numeric_limits<std::size_t>::max()) throw std::runtime_error(tableName + " table has no column " + name);
    return rows.at(row)[c];
}

ParamSchema stopSpeedParam() {
    return ParamSchema::quantity("stop_speed", "rad/s",
                                 "standstill is detected at this speed and extrapolated to zero; keep it above "
                                 "the loads' regularisation band (>= 5 smoothing_speed)")
        .optional(0.1)
        .above(0);
}

ElementSpec defaultScenario(const std::string& kind) {
    const ElementSchema* schema = findAnalysisSchema(kind);
    if (!schema) throw std::invalid_argument("unknown analysis '" + kind + "'");
    ElementSpec s;
    s.type = kind;
    s.name = "scenario";
    for (const auto& p : schema->params) {
        ParamValue v;
        v.number = p.defaultValue.value_or(0.0);
        v.text = p.defaultText;
        s.params[p.key] = v;
    }
    return s;
}

ModelFileReader defaultModelReader() {
    ModelFileReader r;
    const ElementRegistry& registry = ElementRegistry::instance();
    r.elementSchema = [&registry](const std::string& type) -> const ElementSchema* {
        const ElementType* t = registry.find(type);
        return t ? &t->schema : nullptr;
    };
    r.elementTypes = registry.typeNames();
    r.analysisSchema = findAnalysisSchema;
    r.analysisKinds = analysisKinds();
    return r;
}

AnalysisResult runModelFile(const std::string& path, const std::vector<Override>& overrides, ModelSpec* specOut) {
    const ModelSpec spec = readModelFile(path, defaultModelReader(), overrides);
    if (specOut) *specOut = spec;
    return runAnalysis(spec);
}

namespace {

AnalysisResult dispatchAnalysis(const ModelSpec& spec, const ProgressFn& progress, const SampleObserver& observer) {
    const std::string& analysis = spec.scenario.type;
    const AnalysisKind* kind = findAnalysisKind(analysis);
    if (!kind) throw AnalysisError("analysis '" + analysis + "' is not implemented");
    // What an element's setting needs of the analysis (a condition of each
    // instant, a history along a run; its schema's analysisNeeds), and
    // keys that set the state at t = 0: the transient checks its own
    // (replayed or integrated) once its scene is built.
    for (const auto& e : spec.elements) {
        const ElementSchema* s = schemaOf(e);
        if (!s) continue;
        for (const auto& need : s->analysisNeeds) {
            if (!need.matches(e)) continue;
            using Kind = ElementSchema::AnalysisNeed::Kind;
            if (need.kind == Kind::EachInstant && !kind->solvesEachInstant)
                throw e.error(need.key, need.value + ": " + need.why + " (a kinetostatic model): analysis '" +
                                            analysis + "' cannot solve it; use " + need.alternative);
            if (need.kind == Kind::StepHistory && !kind->carriesStepHistory)
                throw e.error(need.key, need.value + ": " + need.why + ": analysis '" + analysis +
                                            "' has no run to carry it along (transient only); use " +
                                            need.alternative);
        }
        for (const auto& [key, what] : s->initialStateKeys)
            if (e.params.count(key) && e.params.at(key).given &&
                !(kind->keepsInitialState && kind->keepsInitialState(spec.scenario)))
                throw e.error(key, "sets " + what + " at t = 0, which only a transient with initial_state: file keeps");
    }
    return kind->run(spec, progress, observer);
}

}  // namespace

namespace {
/// Tumbling-mill charges (SegmentCharge torque_arm, frozen): a warning when
/// the drum ran above 90 % of its critical speed, and a frozen charge's
/// outcome against its safe angle (docs/charges.md).
void addChargeChecks(const ModelSpec& spec, AnalysisResult& result) {
    for (const auto& e : spec.elements) {
        if (e.type != "SegmentCharge") continue;
        // A transient warns from its integrated trajectory (runTransient:
        // the largest fraction located inside the steps, not the rows'); the
        // other analyses' rows are their configurations themselves.
        const std::size_t phiColumn = result.findColumn(e.name + ".fraction_of_critical");
        if (result.analysis != "transient" && phiColumn != std::string::npos && !result.rows.empty()) {
            double top = 0;
            for (const auto& row : result.rows) top = std::max(top, std::abs(row[phiColumn]));
            if (top > 0.9)
                result.notes.push_back("warning: charge '" + e.name + "' ran at up to " + formatNumber(100 * top, 4) +
                                       " % of its critical speed (above 90 %: the charge nears centrifuging)");
        }
        if (e.text("motion") != "frozen") continue;
        const std::size_t released = result.findColumn(e.name + ".released");
        const std::size_t reached = result.findColumn(e.name + ".angle_reached");
        if (released == std::string::npos || reached == std::string::npos || result.rows.empty()) continue;
        const auto& last = result.rows.back();
        const bool fell = last[released] > 0.5;
        const double angle = last[reached], safe = e.number("safe_angle"), release = e.number("release_angle");
        const ResultScalar* mass = nullptr;
        const ResultScalar* radius = nullptr;
        for (const auto& d : result.derived) {
            if (d.name == e.name + ".mass") mass = &d;
            if (d.name == e.name + ".centroid_radius") radius = &d;
        }
        result.results.push_back({e.name + ".angle_reached", angle, "rad",
                                  "largest lag of the packed charge (the release angle once it fell)"});
        result.results.push_back({e.name + ".released", fell ? 1.0 : 0.0, "1", "1: the packed charge broke loose"});
        if (mass && radius) {
            const double g = std::hypot(spec.gravity[0], spec.gravity[1]);
            const double fall = fell ? mass->value * g * radius->value * (1 - std::cos(release)) : 0.0;
            result.results.push_back({e.name + ".fall_energy", fall, "J", "m g r_c (1 − cos θ_r) of the fall, 0 if none"});
        }
        const std::string deg = " deg";
        std::string verdict;
        if (angle > safe)
            verdict = "unsafe: the shell lifted packed charge '" + e.name + "' to " +
                      formatNumber(angle * 180 / M_PI, 4) + deg + ", past the safe angle " +
                      formatNumber(safe * 180 / M_PI, 4) + deg +
                      " (frozen-charge protection trips the drive there)" + (fell ? ", then it fell" : "");
        else
            verdict = "safe: packed charge '" + e.name + "'" + (fell ? " broke loose at " : " was lifted to ") +
                      formatNumber(angle * 180 / M_PI, 4) + deg + ", within the safe angle " +
                      formatNumber(safe * 180 / M_PI, 4) + deg;
        result.notes.push_back("frozen charge: " + verdict);
    }
}
/// Schedules started by an event (`after:`): when each one's clock started,
/// from its `NAME.schedule_clock` column at the last row (t − clock), or a
/// note that it never started (its factor stayed at its clock's 0).
void addScheduleTriggerChecks(const ModelSpec& spec, AnalysisResult& result) {
    if (result.analysis != "transient" || result.rows.empty()) return;
    for (const auto& e : spec.elements)
        for (const auto& [key, v] : e.params) {
            if (v.names.empty() || !v.given) continue;
            if (key != "schedule") continue;
            const std::size_t column = result.findColumn(e.name + ".schedule_clock");
            if (column == std::string::npos) continue;
            const auto& last = result.rows.back();
            const double t = last[result.findColumn("time")], clock = last[column];
            const std::string what = "schedule of " + e.name + " (after " + v.names[0] + " reaches " +
                                     formatNumber(v.number) + " rad/s)";
            if (clock > 0) {
                result.results.push_back({e.name + ".schedule_start_time", t - clock, "s",
                                          "when " + v.names[0] + " first rose through " + formatNumber(v.number) +
                                              " rad/s: the schedule's clock starts (a located event)"});
                result.notes.push_back(what + ": started at " + formatNumber(t - clock) + " s");
            } else {
                result.notes.push_back("warning: " + what + " never started: " + v.names[0] +
                                       " did not reach the speed by " + formatNumber(t) +
                                       " s; its factor stayed at its value at the clock's 0");
            }
        }
}
}  // namespace

AnalysisResult runAnalysis(const ModelSpec& spec, const ProgressFn& progress, const SampleObserver& observer) {
    // Simbody reports refused calls (a singular assembly, a bad argument) as
    // SimTK::Exception::Base: one located line, never "internal error".
    try {
        AnalysisResult result = dispatchAnalysis(spec, progress, observer);
        addChargeChecks(spec, result);
        addScheduleTriggerChecks(spec, result);
        return result;
    } catch (const SimTK::Exception::Base& e) {
        throw AnalysisError(spec.scenario.type + " analysis of " + spec.name + ": Simbody refused it: " +
                            simbodyMessage(e.what()));
    }
}

std::string probeShaft(const ModelSpec& spec, const std::string& probeName) {
    const std::size_t dot = probeName.find('.');
    if (dot == std::string::npos || probeName.find('.', dot + 1) != std::string::npos) return "";
    const ElementSpec* e = spec.findElement(probeName.substr(0, dot));
    return e ? elementShaft(*e) : "";
}

std::string elementsOnBody(const ModelSpec& spec, const std::string& body) {
    std::string out;
    for (const ElementSpec& e : spec.elements) {
        const ElementType* type = ElementRegistry::instance().find(e.type);
        if (!type) continue;
        bool on = false;
        for (const auto& p : type->schema.params) {
            const auto v = e.params.find(p.key);
            if (v == e.params.end()) continue;
            if (p.kind == ParamKind::BodyRef) on = on || v->second.text == body;
            if (p.kind == ParamKind::BodyPair || p.kind == ParamKind::BodyList)
                on = on || std::find(v->second.names.begin(), v->second.names.end(), body) != v->second.names.end();
        }
        if (on) out += (out.empty() ? "" : ", ") + e.name;
    }
    return out;
}

std::string probeShafts(const ModelSpec& spec, const Scene& scene, ProbeRole role) {
    std::vector<std::string> distinct;
    for (const auto& p : scene.probes()) {
        if (p.role != role) continue;
        const std::string shaft = probeShaft(spec, p.name);
        if (!shaft.empty() && std::find(distinct.begin(), distinct.end(), shaft) == distinct.end())
            distinct.push_back(shaft);
    }
    std::string out;
    for (const auto& n : distinct) out += (out.empty() ? "" : ", ") + n;
    return out;
}

double sumProbes(const Scene& scene, const SimTK::State& state, ProbeRole role) {
    double sum = 0;
    for (const auto& p : scene.probes())
        if (p.role == role) sum += p.value(state);
    return sum;
}

const ElementSchema* schemaOf(const ElementSpec& e) {
    const ElementType* type = ElementRegistry::instance().find(e.type);
    return type ? &type->schema : nullptr;
}

void checkStopSpeed(const ModelSpec& spec) {
    const double stop = spec.scenario.number("stop_speed");
    for (const auto& e : spec.elements) {
        const ElementSchema* s = schemaOf(e);
        if (!s || s->regularisationSpeedKey.empty()) continue;
        const std::string& key = s->regularisationSpeedKey;
        if (stop < 5 * e.number(key))
            throw spec.scenario.error("stop_speed", "must be at least 5 times the " + key + " of " + e.name + " (" +
                                                        std::to_string(e.number(key)) +
                                                        " rad/s): below that the load is no longer the model's law");
    }
}

Simulation::Watch speedWatch(const SimTK::MobilizedBody& body, double threshold, double notBefore,
                             const std::string& what) {
    Simulation::Watch w;
    // |ω| falls to the threshold whichever way the shaft turns (a wheel
    // behind one external gear stage turns against its motor).
    w.value = [body](const SimTK::State& s) { return std::abs(pinSpeed(s, body)); };
    w.rate = [body](const SimTK::State& s) {
        return (pinSpeed(s, body) < 0 ? -1.0 : 1.0) * body.getOneUDot(s, SimTK::MobilizerUIndex(0));
    };
    w.threshold = threshold;
    w.notBefore = notBefore;
    w.what = what;
    return w;
}

const SceneBody& scenarioBody(const Scene& scene, const ElementSpec& scenario, const std::string& key) {
    const std::string& name = scenario.text(key);
    return name.empty() ? scene.bodies().front() : *scene.findBody(name);
}

namespace {

/// The categories present in a meter, in the order of EnergyCategory.
std::vector<EnergyCategory> presentCategories(const EnergyMeter& meter) {
    std::vector<EnergyCategory> out;
    for (int c = 0; c < kEnergyCategories; ++c)
        for (std::size_t i = 0; i < meter.flows().size(); ++i)
            if (static_cast<int>(meter.category(i)) == c) {
                out.push_back(static_cast<EnergyCategory>(c));
                break;
            }
    return out;
}

}  // namespace

void addEnergyBalance(const Scene& scene, const SimTK::State& start, const SimTK::State& end,
                      AnalysisResult& result) {
    const EnergyMeter* meter = scene.energyMeter();
    if (!meter) return;
    const SimTK::MultibodySystem& system = scene.system();
    system.realize(start, SimTK::Stage::Dynamics);
    system.realize(end, SimTK::Stage::Dynamics);
    double sources = 0, loads = 0, dissipated = 0;
    std::vector<ResultScalar> parts;
    for (std::size_t i = 0; i < meter->flows().size(); ++i) {
        // The meter's integrals start at 0 with the run; differences keep
        // this right for a run that starts from a later state.
        const double w = meter->work(end, i) - meter->work(start, i);
        const EnergyFlow& f = meter->flows()[i];
        switch (f.kind) {
            case EnergyFlow::Kind::Source: sources += w; break;
            case EnergyFlow::Kind::Load: loads += w; break;
            case EnergyFlow::Kind::Dissipation: dissipated += w; break;
        }
        parts.push_back({"energy." + f.name, w, "J", meter->describe(i)});
    }
    const EnergySplit split = calcEnergySplit(*meter, system, start, end);
    const double dKE = split.kinetic, dPE = split.gravitational + split.elastic;
    const double residual = dKE + dPE - (sources - loads - dissipated);
    const double scale = std::max({std::abs(sources), std::abs(loads) + std::abs(dissipated),
                                   system.calcKineticEnergy(start), system.calcKineticEnergy(end),
                                   std::numeric_limits<double>::min()});
    result.results.push_back({"energy_from_sources", sources, "J",
                              "work of the drives (a motor's electrical input, or its air-gap power without "
                              "rated_efficiency; a prescribed drive's work)"});
    result.results.push_back({"energy_to_loads", loads, "J", "work taken by the loads (grinding, crushing)"});
    result.results.push_back({"energy_dissipated", dissipated, "J",
                              "heat: motors (rotors; stators where rated_efficiency is given), friction (journals, "
                              "brakes, clutch slip) and damping (couplings, belts, gear meshes); energy_split.* and "
                              "energy.* split it"});
    result.results.push_back({"kinetic_energy_change", dKE, "J", "end minus start"});
    result.results.push_back({"potential_energy_change", dPE, "J",
                              "end minus start: gravitational plus elastic (the two lines below)"});
    result.results.push_back({"gravitational_energy_change", split.gravitational, "J",
                              "end minus start: gravity on lifted bodies, including a charge carried up the shell"});
    result.results.push_back({"elastic_energy_change", split.elastic, "J",
                              "end minus start: strain of couplings, belts, gear meshes and shafts"});
    result.results.push_back({"energy_balance_residual", residual, "J",
                              "dKE + dPE - (sources - loads - dissipated): the integration error"});
    result.results.push_back({"energy_balance_relative", residual / scale, "1",
                              "the residual over the largest energy of the run"});
    // By category (EnergyMeter's one classification), then each flow by
    // name, so the parts of every sum can be read (and add up).
    for (EnergyCategory c : presentCategories(*meter))
        result.results.push_back({"energy_split." + energyCategoryKey(c), split.of(c), "J", energyCategoryLabel(c)});
    result.results.insert(result.results.end(), parts.begin(), parts.end());
}

bool addMeanPower(const Scene& scene, const SimTK::State& from, const SimTK::State& to, const std::string& window,
                  AnalysisResult& result) {
    const EnergyMeter* meter = scene.energyMeter();
    const double dt = to.getTime() - from.getTime();
    if (!meter || !(dt > 0)) return false;
    const SimTK::MultibodySystem& system = scene.system();
    system.realize(from, SimTK::Stage::Dynamics);
    system.realize(to, SimTK::Stage::Dynamics);
    const EnergySplit split = calcEnergySplit(*meter, system, from, to);
    const std::string over = ", mean over " + window;
    const std::vector<EnergyCategory> present = presentCategories(*meter);
    auto has = [&](EnergyCategory c) { return std::find(present.begin(), present.end(), c) != present.end(); };
    double scale = std::numeric_limits<double>::min();
    for (EnergyCategory c : present) {
        result.results.push_back({"mean_power." + energyCategoryKey(c), split.of(c) / dt, "W", energyCategoryLabel(c) + over});
        scale = std::max(scale, std::abs(split.of(c)));
    }
    if (has(EnergyCategory::MotorLoss))
        result.results.push_back(
            {"mean_power.shaft_input",
             (split.of(EnergyCategory::MotorInput) - split.of(EnergyCategory::MotorLoss)) / dt, "W",
             "mechanical power the drives put into the shafts: motor_input less motor_loss" + over});
    result.results.push_back({"mean_power.stored_change", split.stored() / dt, "W",
                              "rate of change of the stored energy (kinetic + gravitational + elastic)" + over});
    result.results.push_back({"mean_power.kinetic_change", split.kinetic / dt, "W", "rate of change of kinetic energy" + over});
    result.results.push_back({"mean_power.gravitational_change", split.gravitational / dt, "W",
                              "rate of change of gravitational energy (lifted bodies, a charge's lift)" + over});
    result.results.push_back({"mean_power.elastic_change", split.elastic / dt, "W",
                              "rate of change of elastic energy (couplings, belts, gear meshes, shafts)" + over});
    scale = std::max({scale, std::abs(split.kinetic), std::abs(split.gravitational), std::abs(split.elastic)});
    result.results.push_back({"mean_power.residual", split.residual() / dt, "W",
                              "motor_input - motor_loss - (grinding + friction + damping + stored_change): the "
                              "integration error" + over});
    result.results.push_back({"mean_power.residual_relative", split.residual() / scale, "1",
                              "mean_power.residual over the largest term of the split"});
    return true;
}

void addDefaultPlots(AnalysisResult& result) {
    std::vector<std::size_t> speeds, torques;
    for (std::size_t i = 1; i < result.columnNames.size(); ++i) {
        if (result.columnUnits[i] == "rad/s") speeds.push_back(i);
        if (result.columnUnits[i] == "N*m") torques.push_back(i);
    }
    result.plots.push_back({"speeds", speeds});
    result.plots.push_back({"torques", torques});
    // Bearings where they stand (ShaftBearings): each bearing's radial load.
    std::vector<std::size_t> loads;
    const std::string suffix = ".radial_load";
    for (std::size_t i = 1; i < result.columnNames.size(); ++i) {
        const std::string& n = result.columnNames[i];
        if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
            loads.push_back(i);
    }
    if (!loads.empty()) result.plots.push_back({"bearing_loads", loads});
    // Charge lags (SegmentCharge `NAME.lag`) that move (a held or
    // torque-arm lag is the model's number, a flat line), labelled in their
    // lag_from convention by the probe.
    std::vector<std::size_t> lags;
    for (std::size_t i = 1; i < result.columnNames.size(); ++i) {
        const std::string& n = result.columnNames[i];
        if (result.columnUnits[i] != "rad" || n.size() <= 4 || n.compare(n.size() - 4, 4, ".lag") != 0) continue;
        const bool moves = std::any_of(result.rows.begin(), result.rows.end(), [&](const std::vector<double>& row) {
            return i < row.size() && i < result.rows.front().size() && row[i] != result.rows.front()[i];
        });
        if (moves) lags.push_back(i);
    }
    if (!lags.empty()) result.plots.push_back({"charge_lags", lags});
}

std::string speedColumnName(const Scene& scene, const SceneBody& body) {
    const SimTK::MobilizedBodyIndex parent = body.mobod.getParentMobilizedBody().getMobilizedBodyIndex();
    if (parent == SimTK::GroundIndex) return body.name + ".speed";
    for (const auto& other : scene.bodies())
        if (other.mobod.getMobilizedBodyIndex() == parent) return body.name + ".speed_rel_" + other.name;
    return body.name + ".speed_rel_parent";
}

SampleTable::SampleTable(const Scene& scene, AnalysisResult& result) : m_scene(scene), m_result(result) {
    result.columnNames = {"time"};
    result.columnUnits = {"s"};
    for (const auto& b : scene.bodies()) {
        result.columnNames.push_back(b.name + ".angle");
        result.columnUnits.push_back("rad");
        result.columnNames.push_back(speedColumnName(scene, b));
        result.columnUnits.push_back("rad/s");
    }
    result.columnLabels.assign(result.columnNames.size(), "");
    for (const auto& p : scene.probes()) {
        result.columnNames.push_back(p.name);
        result.columnUnits.push_back(p.unit);
        result.columnLabels.push_back(p.label);
    }
}

void SampleTable::record(const SimTK::State& s, const std::vector<double>& probeValues) {
    std::vector<double> row;
    row.reserve(m_result.columnNames.size());
    row.push_back(s.getTime());
    for (const auto& b : m_scene.bodies()) {
        row.push_back(pinAngle(s, b.mobod));
        row.push_back(pinSpeed(s, b.mobod));
    }
    row.insert(row.end(), probeValues.begin(), probeValues.end());
    m_result.rows.push_back(std::move(row));
}

std::size_t SampleTable::column(const std::string& name) const { return m_result.findColumn(name); }

}  // namespace milldyn
