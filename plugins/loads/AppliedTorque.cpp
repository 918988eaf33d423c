#include "plugins/loads/AppliedTorque.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

AppliedTorque::AppliedTorque(const SimTK::MobilizedBody& shaft, const AppliedTorqueParams& p)
    : m_shaft(shaft), m_params(p) {
    if (!std::isfinite(p.torque))
        throw std::invalid_argument("AppliedTorque: torque = " + std::to_string(p.torque) + " is invalid: must be finite");
}

void AppliedTorque::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                              SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcTorque(s), mobilityForces);
}

namespace {

void buildAppliedTorque(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    AppliedTorqueParams p;
    p.torque = spec.number("torque");
    p.schedule = Schedule::fromSpec(spec);
    auto* impl = new AppliedTorque(shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Time,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); },
                    "applied torque M0·f(t), + about the shaft's +z"});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source,
                         [impl, mobod](const SimTK::State& s) { return impl->calcTorque(s) * pinSpeed(s, mobod); },
                         "work of the torque source " + spec.name});
    scene.note("force " + spec.name + " (AppliedTorque)",
               "acts on body " + shaft->name + "; " + p.schedule.describe());
}

}  // namespace

void registerAppliedTorque(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "AppliedTorque";
    s.doc = "A torque source on a shaft: M0·f(t), signed (+ about +z), f the schedule; its work is a source.";
    s.params = {
        P::body("body", "shaft the torque acts on"),
        P::quantity("torque", "N*m", "M0, signed: + about the shaft's +z"),
        scheduleParam("schedule", "f(t) multiplying M0: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    registry.add({std::move(s), buildAppliedTorque});
}

}  // namespace milldyn
