#include "plugins/scene/Scene.h"

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
