#include "plugins/scene/Scene.h"

#include "plugins/scene/Format.h"
#include "plugins/scene/MobilizerReactions.h"

#include <cmath>
#include <stdexcept>

namespace milldyn {

Scene::Scene() : m_matter(m_system), m_forces(m_system) {}

void Scene::addBody(const std::string& name, const SimTK::MobilizedBody& mobod) {
    m_bodies.push_back({name, mobod});
}

const MobilizerReactions& Scene::mobilizerReactions() {
    if (!m_reactions) {
        auto* impl = new MobilizerReactions(m_matter);
        SimTK::Force::Custom(m_forces, impl);  // Simbody owns impl
        m_reactions = impl;
    }
    return *m_reactions;
}

std::size_t Scene::retainProbes(const std::function<bool(const Probe&)>& keep) {
    const std::size_t before = m_probes.size();
    std::vector<Probe> kept;
    for (auto& p : m_probes)
        if (keep(p)) kept.push_back(std::move(p));
    m_probes = std::move(kept);
    return before - m_probes.size();
}

const SceneBody* Scene::findBody(const std::string& name) const {
    for (const auto& b : m_bodies)
        if (b.name == name) return &b;
    return nullptr;
}

void Scene::addForce(const std::string& name, const std::string& type, SimTK::ForceIndex index,
                     const SimTK::Force::Custom::Implementation* impl) {
    m_forceIndex[name] = {type, index, impl};
}

SimTK::ForceIndex Scene::findForce(const std::string& name) const {
    auto it = m_forceIndex.find(name);
    if (it == m_forceIndex.end()) return SimTK::ForceIndex();
    return it->second.index;
}

void Scene::addSwitchable(const std::string& name, std::function<void(SimTK::State&, bool)> setOn) {
    m_switchables.emplace_back(name, std::move(setOn));
}

void Scene::addDrive(Drive d) {
    const std::string who = "drive '" + d.element + "': ";
    if (d.element.empty()) throw std::invalid_argument("a drive without an element name");
    if (d.shaft.empty()) throw std::invalid_argument(who + "no shaft");
    if (!std::isfinite(d.speedHint)) throw std::invalid_argument(who + "no finite speed hint");
    if (std::isnan(d.switchOffTime)) throw std::invalid_argument(who + "no switch-off time (+inf: never)");
    if (!d.setOn) throw std::invalid_argument(who + "no on/off switch");
    if (d.startingSequence.empty()) throw std::invalid_argument(who + "no starting sequence");
    addSwitchable(d.element, d.setOn);
    if (std::isfinite(d.switchOffTime)) {
        auto setOn = d.setOn;
        addSwitchEvent({SwitchEvent::Kind::DriveOff, d.switchOffTime, d.element + " switched off",
                        [setOn](SimTK::State& s) { setOn(s, false); }});
    }
    addSpeedHint(d.shaft, d.speedHint);
    m_drives.push_back(std::move(d));
}

void Scene::setDrivesOn(SimTK::State& state, bool on) const {
    for (const auto& s : m_switchables) s.second(state, on);
}

void Scene::addExcitation(const std::string& name, std::function<void(SimTK::State&, bool)> setOn) {
    m_excitations.emplace_back(name, std::move(setOn));
}

void Scene::setExcitationsOn(SimTK::State& state, bool on) const {
    for (const auto& e : m_excitations) e.second(state, on);
}

void Scene::addSpeedRelation(const std::string& from, const std::string& to, double ratio) {
    m_speedRelations.push_back({from, to, ratio});
}

std::map<std::string, double> Scene::speedHints() const {
    std::map<std::string, double> hints = m_speedHints;
    // Spread along couplings until nothing changes (at most one pass per body).
    for (std::size_t pass = 0; pass <= m_bodies.size(); ++pass) {
        bool changed = false;
        for (const auto& r : m_speedRelations) {
            const bool hasFrom = hints.count(r.from) > 0, hasTo = hints.count(r.to) > 0;
            if (hasFrom && !hasTo) { hints[r.to] = hints[r.from] / r.ratio; changed = true; }
            if (hasTo && !hasFrom) { hints[r.from] = hints[r.to] * r.ratio; changed = true; }
        }
        if (!changed) break;
    }
    for (const auto& b : m_bodies) hints.emplace(b.name, 0.0);
    return hints;
}

const char* contributionKindName(Contribution::Kind kind) {
    using K = Contribution::Kind;
    switch (kind) {
        case K::Drive: return "drive";
        case K::Probe: return "probe";
        case K::EnergyFlow: return "energy flow";
        case K::SwitchEvent: return "switch event";
        case K::DerivedValue: return "derived value";
        case K::StartSequence: return "starting sequence";
        case K::StartHold: return "start hold";
        case K::RegularisationSpeed: return "regularisation speed";
        case K::Excitation: return "excitation";
        case K::KinetostaticUnknown: return "kinetostatic unknown";
        case K::LaggedValue: return "lagged value";
        case K::SteadyResidual: return "steady residual";
        case K::OrderExcitation: return "order excitation";
        case K::PrescribedTrajectory: return "prescribed trajectory";
        case K::SpeedRelation: return "speed relation";
    }
    return "?";
}

std::vector<const Contribution*> ElementRecord::of(Contribution::Kind kind) const {
    std::vector<const Contribution*> out;
    for (const auto& c : contributions)
        if (c.kind == kind) out.push_back(&c);
    return out;
}

/// Where each list stood when the open record began: the record is what
/// was appended since (every registration appends, so nothing is missed
/// and the element builders need no change).
struct Scene::RecordMarks {
    std::string element, type;
    std::size_t drives, probes, flows, events, derived, sequences, holds, regularisations, excitations, unknowns,
        lagged, residuals, orders, trajectories, relations;
};

void Scene::beginElement(const std::string& name, const std::string& type) {
    m_open = std::make_shared<RecordMarks>(RecordMarks{name, type, m_drives.size(), m_probes.size(),
                                                       m_energyFlows.size(), m_switchEvents.size(), m_derived.size(),
                                                       m_startSequences.size(), m_startHolds.size(),
                                                       m_regularisationSpeeds.size(), m_excitations.size(),
                                                       m_kinetostaticUnknowns.size(), m_laggedValues.size(),
                                                       m_steadyResiduals.size(), m_orderExcitations.size(),
                                                       m_trajectories.size(), m_speedRelations.size()});
}

namespace {
std::string probeRoleText(ProbeRole role) {
    switch (role) {
        case ProbeRole::Generic: return "";
        case ProbeRole::DriveTorque: return ", drive torque";
        case ProbeRole::ResistanceTorque: return ", resistance torque";
        case ProbeRole::ResistancePower: return ", resistance power";
        case ProbeRole::CouplingTorque: return ", coupling torque";
        case ProbeRole::BodySpeed: return ", body speed";
    }
    return "";
}
std::string flowKindText(EnergyFlow::Kind kind) {
    switch (kind) {
        case EnergyFlow::Kind::Source: return "source";
        case EnergyFlow::Kind::Load: return "load";
        case EnergyFlow::Kind::Dissipation: return "dissipation";
    }
    return "";
}
std::string eventKindText(Scene::SwitchEvent::Kind kind) {
    switch (kind) {
        case Scene::SwitchEvent::Kind::DriveOff: return "drive off";
        case Scene::SwitchEvent::Kind::LoadOn: return "load on";
        case Scene::SwitchEvent::Kind::StarterStep: return "starter step";
    }
    return "";
}
}  // namespace

void Scene::endElement(const std::string& defaultShaft) {
    if (!m_open) return;
    const RecordMarks m = *m_open;
    m_open.reset();
    using K = Contribution::Kind;
    ElementRecord r{m.element, m.type, {}};
    auto add = [&r](K kind, std::string name, std::string shaft, std::string detail) {
        r.contributions.push_back({kind, std::move(name), std::move(shaft), std::move(detail)});
    };
    for (std::size_t i = m.drives; i < m_drives.size(); ++i) {
        const Drive& d = m_drives[i];
        add(K::Drive, d.element, d.shaft,
            "speed hint " + formatNumber(d.speedHint) + " rad/s, switched off " +
                (std::isfinite(d.switchOffTime) ? "at " + formatNumber(d.switchOffTime) + " s" : std::string("never")) +
                ", starting sequence " + d.startingSequence);
    }
    for (std::size_t i = m.probes; i < m_probes.size(); ++i) {
        Probe& p = m_probes[i];
        if (p.shaft.empty()) p.shaft = defaultShaft;
        add(K::Probe, p.name, p.shaft, "[" + p.unit + "]" + probeRoleText(p.role));
    }
    for (std::size_t i = m.flows; i < m_energyFlows.size(); ++i)
        add(K::EnergyFlow, m_energyFlows[i].name, "", flowKindText(m_energyFlows[i].kind));
    for (std::size_t i = m.events; i < m_switchEvents.size(); ++i)
        add(K::SwitchEvent, m_switchEvents[i].what, "",
            eventKindText(m_switchEvents[i].kind) + " at " + formatNumber(m_switchEvents[i].time) + " s");
    for (std::size_t i = m.derived; i < m_derived.size(); ++i)
        add(K::DerivedValue, m_derived[i].name, "", formatNumber(m_derived[i].value) + " " + m_derived[i].unit);
    for (std::size_t i = m.sequences; i < m_startSequences.size(); ++i)
        add(K::StartSequence, m_startSequences[i].name, "", "");
    for (std::size_t i = m.holds; i < m_startHolds.size(); ++i) add(K::StartHold, m_startHolds[i].name, "", "");
    for (std::size_t i = m.regularisations; i < m_regularisationSpeeds.size(); ++i)
        add(K::RegularisationSpeed, m_regularisationSpeeds[i].key, "",
            formatNumber(m_regularisationSpeeds[i].speed) + " rad/s");
    for (std::size_t i = m.excitations; i < m_excitations.size(); ++i)
        add(K::Excitation, m_excitations[i].first, "", "");
    for (std::size_t i = m.unknowns; i < m_kinetostaticUnknowns.size(); ++i)
        add(K::KinetostaticUnknown, m_kinetostaticUnknowns[i].name, "", "");
    for (std::size_t i = m.lagged; i < m_laggedValues.size(); ++i)
        add(K::LaggedValue, m_laggedValues[i].name, "", m_laggedValues[i].eachStep ? "each step" : "");
    for (std::size_t i = m.residuals; i < m_steadyResiduals.size(); ++i)
        add(K::SteadyResidual, m_steadyResiduals[i].name, "", "");
    for (std::size_t i = m.orders; i < m_orderExcitations.size(); ++i)
        add(K::OrderExcitation, m_orderExcitations[i].name, m_orderExcitations[i].body,
            formatNumber(m_orderExcitations[i].eventsPerRevolution) + " per revolution");
    for (std::size_t i = m.trajectories; i < m_trajectories.size(); ++i)
        add(K::PrescribedTrajectory, m_trajectories[i].body, m_trajectories[i].body, "");
    for (std::size_t i = m.relations; i < m_speedRelations.size(); ++i)
        add(K::SpeedRelation, m_speedRelations[i].from + " / " + m_speedRelations[i].to, "",
            "ratio " + formatNumber(m_speedRelations[i].ratio));
    m_records.push_back(std::move(r));
}

const ElementRecord* Scene::findRecord(const std::string& name) const {
    for (const auto& r : m_records)
        if (r.element == name) return &r;
    return nullptr;
}

double pinSpeed(const SimTK::State& state, const SimTK::MobilizedBody& body) {
    return body.getOneU(state, SimTK::MobilizerUIndex(0));
}

std::vector<std::string> mobilityNames(const Scene& scene, const SimTK::State& state) {
    std::vector<std::string> names(state.getNU());
    for (const auto& b : scene.bodies()) {
        const int first = b.mobod.getFirstUIndex(state), n = b.mobod.getNumU(state);
        for (int i = 0; i < n; ++i)
            names.at(first + i) = n == 1 ? b.name : b.name + ".u" + std::to_string(i);
    }
    return names;
}

double pinAngle(const SimTK::State& state, const SimTK::MobilizedBody& body) {
    return body.getOneQ(state, SimTK::MobilizerQIndex(0));
}

double refreshLaggedValues(const Scene& scene, SimTK::State& state, bool eachStepOnly) {
    scene.system().realize(state, SimTK::Stage::Acceleration);
    // Read all before keeping any: keeping one invalidates the realization.
    std::vector<double> now;
    for (const auto& v : scene.laggedValues())
        if (v.eachStep || !eachStepOnly) now.push_back(v.current(state));
    double change = 0;
    std::size_t i = 0;
    for (const auto& v : scene.laggedValues())
        if (v.eachStep || !eachStepOnly) {
            const double c = v.keep(state, now[i++]);
            change = std::isnan(c) || std::isnan(change) ? NAN : std::max(change, c);
        }
    return change;
}

}  // namespace milldyn
