#include "plugins/bearings/JournalFriction.h"

#include "plugins/scene/ElementRegistry.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn {

using namespace SimTK;

namespace {

/// The journals of each scene (keyed by its shared reaction cache), so one
/// can compute the frictionless reaction with all of them off. Journals
/// leave on destruction; sweeps build scenes on several threads.
std::mutex g_journalsMutex;
std::map<const MobilizerReactions*, std::vector<const JournalFriction*>>& journalsOfScene() {
    static std::map<const MobilizerReactions*, std::vector<const JournalFriction*>> all;
    return all;
}

}  // namespace

JournalFriction::JournalFriction(const SimbodyMatterSubsystem& matter, const MobilizerReactions& reactions,
                                 const MobilizedBody& body, const JournalFrictionParams& p)
    : m_matter(matter), m_reactions(reactions), m_body(body), m_p(p) {
    auto bad = [](const std::string& what) { throw std::invalid_argument("JournalFriction: " + what); };
    if (!(p.frictionCoefficient >= 0 && p.frictionCoefficient <= 1)) bad("friction_coefficient must be in [0, 1]");
    if (!(p.journalDiameter >= 0) || !std::isfinite(p.journalDiameter)) bad("journal_diameter must be >= 0 m");
    if (!(p.smoothingSpeed > 0) || !std::isfinite(p.smoothingSpeed)) bad("smoothing_speed must be > 0 rad/s");
    std::lock_guard<std::mutex> lock(g_journalsMutex);
    journalsOfScene()[&m_reactions].push_back(this);
}

JournalFriction::~JournalFriction() {
    std::lock_guard<std::mutex> lock(g_journalsMutex);
    auto it = journalsOfScene().find(&m_reactions);
    if (it == journalsOfScene().end()) return;
    auto& list = it->second;
    list.erase(std::remove(list.begin(), list.end(), this), list.end());
    if (list.empty()) journalsOfScene().erase(it);
}

std::pair<double, double> JournalFriction::calcFrictionless(const State& s) const {
    std::vector<const JournalFriction*> journals;
    {
        std::lock_guard<std::mutex> lock(g_journalsMutex);
        journals = journalsOfScene()[&m_reactions];
    }
    State off = s;
    for (const JournalFriction* j : journals)
        Value<Vec4>::updDowncast(j->m_matter.updDiscreteVariable(off, j->m_keptLoad)) = Vec4(0);
    m_matter.getSystem().realize(off, Stage::Acceleration);
    return {calcReaction(off), m_body.getOneUDot(off, MobilizerUIndex(0))};
}

double JournalFriction::keepDirection(State& s, double direction) const {
    double& kept = Value<double>::updDowncast(m_matter.updDiscreteVariable(s, m_direction));
    const double changed = kept == direction ? 0.0 : 1.0;
    kept = direction;
    return changed;
}

void JournalFriction::realizeTopology(State& s) const {
    // [R_n, t_n, R_(n-1), t_(n-1)]: the reactions at the last two step ends.
    m_keptLoad = m_matter.allocateAutoUpdateDiscreteVariable(s, Stage::Dynamics, new Value<Vec4>(Vec4(0)),
                                                             Stage::Acceleration);
    m_direction = m_matter.allocateDiscreteVariable(s, Stage::Dynamics, new Value<double>(0.0));
}

double JournalFriction::calcReaction(const State& s) const {
    return m_reactions.getForce(s, m_body).norm();
}

const Vec4& JournalFriction::history(const State& s) const {
    return Value<Vec4>::downcast(m_matter.getDiscreteVariable(s, m_keptLoad));
}

double JournalFriction::getLoad(const State& s) const {
    const Vec4& h = history(s);
    if (m_p.coupling != ReactionCoupling::Extrapolated || !(h[1] > h[3])) return h[0];
    // Linear in time through the last two step ends: continuous within the
    // step, so the integrator's error control sees the load change.
    return std::max(0.0, h[0] + (s.getTime() - h[1]) * (h[0] - h[2]) / (h[1] - h[3]));
}

double JournalFriction::calcFrictionTorque(double load, const JournalFrictionParams& p, double u) {
    return load * p.frictionCoefficient * p.journalDiameter / 2 * std::tanh(u / p.smoothingSpeed);
}

double JournalFriction::calcTorque(const State& s) const {
    const double u = m_body.getOneU(s, MobilizerUIndex(0));
    if (m_p.breakaway && u == 0)  // at rest: full friction against the kept breakaway direction
        return getLoad(s) * m_p.frictionCoefficient * m_p.journalDiameter / 2 *
               Value<double>::downcast(m_matter.getDiscreteVariable(s, m_direction));
    return calcFrictionTorque(getLoad(s), m_p, u);
}

double JournalFriction::calcPower(const State& s) const {
    return calcTorque(s) * m_body.getOneU(s, MobilizerUIndex(0));
}

double JournalFriction::keepLoad(State& s, double now) const {
    const double kept = getLoad(s);
    const double t = s.getTime();
    Value<Vec4>::updDowncast(m_matter.updDiscreteVariable(s, m_keptLoad)) = Vec4(now, t, now, t);
    return std::abs(now - kept) / std::max(now, 1e-300);
}

void JournalFriction::calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const {
    m_body.applyOneMobilityForce(s, MobilizerUIndex(0), -calcTorque(s), mobilityForces);
}

void JournalFriction::realizeAcceleration(const State& s) const {
    // Keep this step's reaction for the next (swapped in by the integrator
    // when the step is accepted).
    const Vec4& h = history(s);
    // First order: the frictionless reaction needs a realization of its
    // own, so it is refreshed between steps (eachStep), not here.
    Value<Vec4>::updDowncast(m_matter.updDiscreteVarUpdateValue(s, m_keptLoad)) =
        m_p.coupling == ReactionCoupling::FirstOrder ? h : Vec4(calcReaction(s), s.getTime(), h[0], h[1]);
    m_matter.markDiscreteVarUpdateValueRealized(s, m_keptLoad);
}

std::vector<ParamSchema> reactionCouplingParams() {
    using P = ParamSchema;
    return {
        P::choice("coupling", {"consistent", "first_order"},
                  "consistent: the load is the reaction of the model with its friction (the journal's own "
                  "friction included); first_order: the reaction with every journal's friction off (seed 000 "
                  "eq 21, the paper's convention)")
            .optional(std::string("consistent")),
        P::choice("reaction", {"lagged", "iterated", "extrapolated", "first_order"},
                  "how the consistent load is obtained: the reaction of the last step, made consistent each "
                  "step, or extrapolated from the last two; first_order: alias of coupling: first_order")
            .optional(std::string("lagged")),
    };
}

ReactionCoupling readReactionCoupling(const ElementSpec& spec) {
    const std::string& coupling = spec.text("coupling");
    const std::string& reaction = spec.text("reaction");
    const bool couplingGiven = spec.params.at("coupling").given;
    // coupling: first_order leaves `reaction:` unused (a shipped model's
    // `reaction: extrapolated` stays valid when --set switches the coupling).
    if (reaction == "first_order" && couplingGiven && coupling != "first_order")
        throw spec.error("coupling", "'" + coupling + "' contradicts reaction: first_order (an alias of coupling: "
                                     "first_order); drop one of the two keys");
    if (coupling == "first_order" || reaction == "first_order") return ReactionCoupling::FirstOrder;
    return reaction == "iterated"       ? ReactionCoupling::Iterated
           : reaction == "extrapolated" ? ReactionCoupling::Extrapolated
                                        : ReactionCoupling::Lagged;
}

std::string describeReactionCoupling(ReactionCoupling c) {
    switch (c) {
        case ReactionCoupling::Lagged: return "consistent (lagged)";
        case ReactionCoupling::Iterated: return "consistent (iterated)";
        case ReactionCoupling::Extrapolated: return "consistent (extrapolated)";
        case ReactionCoupling::FirstOrder: return "first_order";
    }
    return "?";
}

void addKeptLoad(Scene& scene, const std::string& name, JournalFriction* impl) {
    const ReactionCoupling c = impl->params().coupling;
    const bool firstOrder = c == ReactionCoupling::FirstOrder;
    scene.addLaggedValue({name + ".load", c == ReactionCoupling::Iterated || firstOrder,
                          [impl, firstOrder](const State& s) {
                              return firstOrder ? impl->calcFrictionless(s).first : impl->calcReaction(s);
                          },
                          [impl](State& s, double load) { return impl->keepLoad(s, load); }});
    if (impl->params().breakaway)
        scene.addLaggedValue({name + ".breakaway_direction", false,
                              [impl](const State& s) {
                                  const double a = impl->calcFrictionless(s).second;
                                  return a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0;
                              },
                              [impl](State& s, double d) { return impl->keepDirection(s, d); }});
}

namespace {

void buildJournalFriction(const ElementSpec& spec, Scene& scene) {
    const SceneBody* body = scene.findBody(spec.text("body"));
    JournalFrictionParams p;
    p.frictionCoefficient = spec.number("friction_coefficient");
    p.journalDiameter = spec.number("journal_diameter");
    p.smoothingSpeed = spec.number("smoothing_speed");
    p.coupling = readReactionCoupling(spec);
    p.breakaway = spec.text("at_rest") == "breakaway";
    auto* impl = new JournalFriction(scene.matter(), scene.mobilizerReactions(), body->mobod, p);
    Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    // The torque the journal takes from its shaft, + about +z (the shaft gets
    // −calcTorque): signed like every load's, so the summary's
    // resistance_torque sums it rightly on a shaft turning −z.
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::ResistanceTorque, Stage::Velocity,
                    [impl](const State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".load", "N", ProbeRole::Generic, Stage::Velocity,
                    [impl](const State& s) { return impl->getLoad(s); }});
    scene.addProbe({spec.name + ".reaction", "N", ProbeRole::Generic, Stage::Acceleration,
                    [impl](const State& s) { return impl->calcReaction(s); }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                         [impl](const State& s) { return impl->calcPower(s); }});
    addKeptLoad(scene, spec.name, impl);
    scene.note("force " + spec.name + " (JournalFriction, " + describeReactionCoupling(p.coupling) + ")",
               "journal of " + body->name + " on its parent, load from Simbody's reaction");
}

}  // namespace

void registerJournalFriction(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "JournalFriction";
    s.needsGravity = true;
    s.doc = "Journal-bearing friction M = |R| f d/2 from the reaction the model computes (seed 000 eq 21).";
    s.params = {
        P::body("body", "body whose pin (to its parent) is the journal"),
        P::quantity("friction_coefficient", "1", "f").atLeast(0).atMost(1),
        P::quantity("journal_diameter", "m", "d").atLeast(0),
        P::quantity("smoothing_speed", "rad/s", "ω_s of tanh(u/ω_s) near zero relative speed").optional(1e-3).above(0),
        P::choice("at_rest", {"smooth", "breakaway"},
                  "at zero relative speed: tanh(0) = 0, or full friction against the motion beginning")
            .optional(std::string("smooth")),
    };
    for (ParamSchema& k : reactionCouplingParams()) s.params.push_back(std::move(k));
    s.crossCheck = [](const ElementSpec& e) { readReactionCoupling(e); };
    registry.add({std::move(s), buildJournalFriction});
}

}  // namespace milldyn
