#include "plugins/transmissions/TorsionalCoupling.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

TorsionalCoupling::TorsionalCoupling(const SimTK::MobilizedBody& from,
                                     const SimTK::MobilizedBody& to,
                                     const TorsionalCouplingParams& p)
    : m_from(from), m_to(to), m_params(p) {
    auto bad = [](const std::string& name, double v, const std::string& rule) {
        throw std::invalid_argument("TorsionalCoupling: " + name + " = " + std::to_string(v) +
                                    " is invalid: " + rule);
    };
    if (!(p.stiffness >= 0) || !std::isfinite(p.stiffness)) bad("stiffness", p.stiffness, "must be finite and >= 0");
    if (!(p.damping >= 0) || !std::isfinite(p.damping)) bad("damping", p.damping, "must be finite and >= 0");
    if (!(p.ratio > 0) || !std::isfinite(p.ratio)) bad("ratio", p.ratio, "must be finite and > 0");
    if (from.getMobilizedBodyIndex() == to.getMobilizedBodyIndex())
        throw std::invalid_argument("TorsionalCoupling: bodies: a coupling needs two different shafts");
}

double TorsionalCoupling::calcTwist(const SimTK::State& s) const {
    const SimTK::MobilizerQIndex q0(0);
    return m_from.getOneQ(s, q0) - m_params.ratio * m_to.getOneQ(s, q0);
}

double TorsionalCoupling::calcTwistRate(const SimTK::State& s) const {
    const SimTK::MobilizerUIndex u0(0);
    return m_from.getOneU(s, u0) - m_params.ratio * m_to.getOneU(s, u0);
}

double TorsionalCoupling::calcTorque(const SimTK::State& s) const {
    return m_params.stiffness * calcTwist(s) + m_params.damping * calcTwistRate(s);
}

void TorsionalCoupling::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                  SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    const double T = calcTorque(s);
    const SimTK::MobilizerUIndex u0(0);
    m_from.applyOneMobilityForce(s, u0, -T, mobilityForces);
    m_to.applyOneMobilityForce(s, u0, m_params.ratio * T, mobilityForces);
}

SimTK::Real TorsionalCoupling::calcPotentialEnergy(const SimTK::State& s) const {
    const double twist = calcTwist(s);
    return 0.5 * m_params.stiffness * twist * twist;
}

namespace {

void buildTorsionalCoupling(const ElementSpec& spec, Scene& scene) {
    const auto& names = spec.names("bodies");
    const SceneBody* from = scene.findBody(names.at(0));
    const SceneBody* to = scene.findBody(names.at(1));
    TorsionalCouplingParams p;
    p.stiffness = spec.number("stiffness");
    p.damping = spec.number("damping");
    p.ratio = spec.number("ratio");
    auto* impl = new TorsionalCoupling(from->mobod, to->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::CouplingTorque, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".twist", "rad", ProbeRole::Generic, SimTK::Stage::Position,
                    [impl](const SimTK::State& s) { return impl->calcTwist(s); }});
    scene.addSteadyResidual({spec.name + ".twist_rate",
                             [impl](const SimTK::State& s) { return impl->calcTwistRate(s); }});
    if (p.damping > 0)
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation, [impl](const SimTK::State& s) {
                                 const double rate = impl->calcTwistRate(s);
                                 return impl->params().damping * rate * rate;
                             }});
    scene.addSpeedRelation(from->name, to->name, p.ratio);
    scene.note("force " + spec.name + " (TorsionalCoupling)",
               "couples " + from->name + " to " + to->name);
}

}  // namespace

void registerTorsionalCoupling(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "TorsionalCoupling";
    s.doc = "Torsional spring-damper between two shafts with a speed ratio (belt, reducer, shaft).";
    s.params = {
        P::bodyPair("bodies", "[from, to]: the driving shaft first"),
        P::quantity("stiffness", "N*m/rad", "torsional stiffness c on the from-shaft").atLeast(0),
        P::quantity("damping", "N*m*s/rad", "viscous damping b on the from-shaft").optional(0.0).atLeast(0),
        P::quantity("ratio", "1", "speed ratio ω_from/ω_to").optional(1.0).above(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const auto& n = e.names("bodies");
        if (n.size() == 2 && n[0] == n[1])
            throw e.error("bodies", "a coupling needs two different bodies, got '" + n[0] + "' twice");
    };
    registry.add({std::move(s), buildTorsionalCoupling});
}

}  // namespace milldyn
