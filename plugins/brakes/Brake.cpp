#include "plugins/brakes/Brake.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/transmissions/Clutch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

Brake::Brake(const SimTK::MobilizedBody& shaft, const BrakeParams& p) : m_shaft(shaft), m_params(p) {
    auto bad = [](const std::string& name, double v, const std::string& rule) {
        throw std::invalid_argument("Brake: " + name + " = " + std::to_string(v) + " is invalid: " + rule);
    };
    if (!(std::isfinite(p.capacity) && p.capacity > 0)) bad("capacity", p.capacity, "must be finite and > 0");
    if (!(p.applyTime >= 0)) bad("apply_time", p.applyTime, "must be >= 0");
    if (!(std::isfinite(p.rampTime) && p.rampTime > 0)) bad("ramp_time", p.rampTime, "must be finite and > 0");
    if (!(std::isfinite(p.regularisationSpeed) && p.regularisationSpeed > 0))
        bad("regularisation_speed", p.regularisationSpeed, "must be finite and > 0");
}

double Brake::torqueAt(double omega, double t) const {
    if (m_params.mode == BrakeParams::Mode::Backstop)
        return -calcFrictionTorque(m_params.capacity, std::min(omega, 0.0), m_params.regularisationSpeed);
    if (!m_params.schedule.isConstant())
        return -calcFrictionTorque(m_params.capacity * m_params.schedule.factorAt(t), omega,
                                   m_params.regularisationSpeed);
    if (!std::isfinite(m_params.applyTime)) return 0;
    return -calcFrictionTorque(m_params.capacity * rampFraction(t, m_params.applyTime, m_params.rampTime), omega,
                               m_params.regularisationSpeed);
}

double Brake::calcTorque(const SimTK::State& s) const { return torqueAt(pinSpeed(s, m_shaft), s.getTime()); }

void Brake::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                      SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcTorque(s), mobilityForces);
}

namespace {

void buildBrake(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    BrakeParams p;
    p.mode = spec.text("mode") == "backstop" ? BrakeParams::Mode::Backstop : BrakeParams::Mode::Brake;
    p.capacity = spec.number("capacity");
    p.applyTime = spec.number("apply_time");
    p.rampTime = spec.number("ramp_time");
    p.regularisationSpeed = spec.number("regularisation_speed");
    p.schedule = Schedule::fromSpecUntriggered(spec);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    auto* impl = new Brake(shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    // The magnitude opposing rotation, like every load torque.
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return -impl->calcTorque(s); }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                         [impl, mobod](const SimTK::State& s) { return -impl->calcTorque(s) * pinSpeed(s, mobod); },
                         "friction heat of the " + spec.text("mode") + " " + spec.name});
    scene.note("force " + spec.name + " (Brake, " + spec.text("mode") + ")", "on body " + shaft->name);
}

}  // namespace

void registerBrake(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "Brake";
    s.doc = "Friction brake applied at a time over a ramp (run-out), or a backstop that holds a shaft against "
            "roll-back; friction heat reported.";
    s.params = {
        P::body("body", "shaft braked or held"),
        P::choice("mode", {"brake", "backstop"}, "brake: applied at apply_time; backstop: always, backwards only")
            .optional("brake"),
        P::quantity("capacity", "N*m", "brake torque, or the backstop's holding capacity").above(0),
        P::quantity("apply_time", "s", "brake: applied from this time (default never)")
            .optional(std::numeric_limits<double>::infinity())
            .atLeast(0),
        P::quantity("ramp_time", "s", "brake: torque ramp from 0 to full").optional(0.1).above(0),
        P::quantity("regularisation_speed", "rad/s", "speed regularisation ω_reg").optional(1e-3).above(0),
        scheduleParam("schedule", "brake: f(t) multiplying the capacity: {ramp|step_recovery|sine|table: ...} "
                                "(replaces apply_time and ramp_time)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.has("schedule"))
            for (const char* k : {"apply_time", "ramp_time"})
                if (e.has(k)) throw e.error(k, "not used with schedule (the schedule is the whole application)");
        if (e.text("mode") == "backstop" && e.has("schedule"))
            throw e.error("schedule", "not used with mode backstop (it holds whenever the shaft turns back)");
        if (e.text("mode") == "backstop")
            for (const char* k : {"apply_time", "ramp_time"})
                if (e.has(k)) throw e.error(k, "not used with mode backstop (it holds whenever the shaft turns back)");
    };
    registry.add({std::move(s), buildBrake});
}

}  // namespace milldyn
