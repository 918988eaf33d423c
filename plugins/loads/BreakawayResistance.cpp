#include "plugins/loads/BreakawayResistance.h"

#include "plugins/loads/LoadTorqueOutputs.h"
#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

BreakawayResistance::BreakawayResistance(const SimTK::MobilizedBody& shaft, const BreakawayResistanceParams& p)
    : m_shaft(shaft), m_params(p) {
    auto check = [](bool ok, const std::string& name, double v, const std::string& rule) {
        if (!ok)
            throw std::invalid_argument("BreakawayResistance: " + name + " = " + std::to_string(v) +
                                        " is invalid: " + rule);
    };
    auto finite = [](double v) { return std::isfinite(v); };
    check(finite(p.runningTorque) && p.runningTorque >= 0, "running_torque", p.runningTorque, "must be >= 0");
    check(finite(p.staticTorque) && p.staticTorque >= p.runningTorque, "static_torque", p.staticTorque,
          "must be >= running_torque");
    check(finite(p.viscousCoefficient) && p.viscousCoefficient >= 0, "viscous_coefficient", p.viscousCoefficient,
          "must be >= 0");
    check(finite(p.releaseSpeed) && p.releaseSpeed > 0, "release_speed", p.releaseSpeed, "must be > 0");
    check(finite(p.smoothingSpeed) && p.smoothingSpeed > 0 && p.smoothingSpeed <= p.releaseSpeed / 10,
          "smoothing_speed", p.smoothingSpeed, "must be > 0 and <= release_speed/10");
}

double BreakawayResistance::torqueAtSpeed(double omega) const {
    const BreakawayResistanceParams& p = m_params;
    const double x = omega / p.releaseSpeed;
    const double level = p.runningTorque + (p.staticTorque - p.runningTorque) * std::exp(-x * x);
    return level * std::tanh(omega / p.smoothingSpeed) + p.viscousCoefficient * omega;
}

double BreakawayResistance::calcTorque(const SimTK::State& s) const {
    return m_params.schedule.factorAt(s) * torqueAtSpeed(m_shaft.getOneU(s, SimTK::MobilizerUIndex(0)));
}

bool BreakawayResistance::isHeld(const SimTK::State& s) const {
    return std::abs(m_shaft.getOneU(s, SimTK::MobilizerUIndex(0))) < m_params.releaseSpeed;
}

std::string BreakawayResistance::stallReason(const std::string& name, const SimTK::State& s) const {
    if (!isHeld(s) || !(m_params.staticTorque > m_params.runningTorque)) return "";
    const double w = m_shaft.getOneU(s, SimTK::MobilizerUIndex(0));
    const double f = m_params.schedule.factorAt(s);
    return "the breakaway of " + name + " was not passed: its static torque " +
           formatNumber(f * m_params.staticTorque) + " N*m" +
           (m_params.schedule.isConstant() ? std::string() : " (" + formatNumber(f) + " x M_s, its schedule)") +
           " held the shaft at " + formatNumber(w) + " rad/s, below its release speed " +
           formatNumber(m_params.releaseSpeed) + " rad/s";
}

void BreakawayResistance::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                    SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -calcTorque(s), mobilityForces);
}

namespace {

void buildBreakawayResistance(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    BreakawayResistanceParams p;
    p.staticTorque = spec.number("static_torque");
    p.runningTorque = spec.number("running_torque");
    p.viscousCoefficient = spec.number("viscous_coefficient");
    p.releaseSpeed = spec.number("release_speed");
    p.smoothingSpeed = spec.number("smoothing_speed");
    p.schedule = Schedule::fromSpec(spec);
    auto* impl = new BreakawayResistance(shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const std::string name = spec.name;
    scene.addStartHold({name, [impl, name](const SimTK::State& s) { return impl->stallReason(name, s); }});
    addShaftLoadTorqueOutputs(scene, spec.name, shaft->mobod,
                              [impl](const SimTK::State& s) { return impl->calcTorque(s); });
    scene.addDerivedValue({spec.name + ".breakaway_excess", p.staticTorque - p.runningTorque, "N*m",
                           "static torque above the running law's constant part, M_s − M_r"});
    double peak = 0;
    for (int i = 1; i <= 20000; ++i) peak = std::max(peak, impl->torqueAtSpeed(3 * p.releaseSpeed * i / 20000));
    scene.addDerivedValue({spec.name + ".peak_torque", peak, "N*m",
                           "largest torque of the regularised law over 0..3·ω_r (20000 points): the breakaway the "
                           "drive actually meets, slightly below M_s (before a schedule's factor)"});
    scene.note("force " + spec.name + " (BreakawayResistance, static " + formatNumber(p.staticTorque) + " N*m)",
               "loads body " + shaft->name + "; releases above " + formatNumber(p.releaseSpeed) + " rad/s" +
                   (p.schedule.isConstant() ? "" : "; torque times the schedule: " + p.schedule.describe()));
    addScheduleBreakpoints(scene, p.schedule, spec.name);
}

}  // namespace

void registerBreakawayResistance(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "BreakawayResistance";
    s.doc = "Stribeck-like resistance: static torque M_s at rest releasing to the running law M_r + b·ω "
            "once the shaft moves, [M_r + (M_s − M_r)·exp(−(ω/ω_r)²)]·tanh(ω/ω_s) + b·ω.";
    s.params = {
        P::body("body", "shaft the resistance acts on"),
        P::quantity("static_torque", "N*m", "M_s: breakaway torque the drive must exceed from rest").atLeast(0),
        P::quantity("running_torque", "N*m", "M_r: constant part of the running law").optional(0.0).atLeast(0),
        P::quantity("viscous_coefficient", "N*m*s/rad", "b: viscous part of the running law")
            .optional(0.0).atLeast(0),
        P::quantity("release_speed", "rad/s", "ω_r: the excess falls to 1/e at this speed").optional(0.1).above(0),
        P::quantity("smoothing_speed", "rad/s", "ω_s: sign regularisation at standstill, <= release_speed/10")
            .optional(0.001).above(0),
        scheduleParam("schedule", "f(t) multiplying the whole torque: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.number("static_torque") < e.number("running_torque"))
            throw e.error("static_torque", "must be >= running_torque (" + formatNumber(e.number("running_torque")) +
                                               " N*m)");
        if (e.number("smoothing_speed") > e.number("release_speed") / 10)
            throw e.error("smoothing_speed", "must be <= release_speed/10 (" +
                                                 formatNumber(e.number("release_speed") / 10) +
                                                 " rad/s): the static torque must be reached before it releases");
    };
    s.regularisationSpeedKey = "smoothing_speed";
    registry.add({std::move(s), buildBreakawayResistance});
}

}  // namespace milldyn
