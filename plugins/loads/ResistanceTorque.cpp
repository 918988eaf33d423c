#include "plugins/loads/ResistanceTorque.h"

#include "plugins/loads/LoadTorqueOutputs.h"
#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

ResistanceTorque::ResistanceTorque(const SimTK::GeneralForceSubsystem& forces,
                                   const SimTK::MobilizedBody& shaft, const ResistanceTorqueParams& p)
    : m_forces(forces), m_shaft(shaft), m_params(p) {
    auto check = [](bool ok, const std::string& name, double v, const std::string& rule) {
        if (!ok)
            throw std::invalid_argument("ResistanceTorque: " + name + " = " + std::to_string(v) +
                                        " is invalid: " + rule);
    };
    auto finite = [](double v) { return std::isfinite(v); };
    check(finite(p.constantTorque) && p.constantTorque >= 0, "constant_torque", p.constantTorque, "must be >= 0");
    check(finite(p.viscousCoefficient) && p.viscousCoefficient >= 0, "viscous_coefficient",
          p.viscousCoefficient, "must be >= 0");
    check(finite(p.feedRate) && p.feedRate >= 0, "feed_rate", p.feedRate, "must be >= 0");
    check(finite(p.feedCoefficient) && p.feedCoefficient >= 0, "feed_coefficient", p.feedCoefficient,
          "must be >= 0");
    check(finite(p.feedExponent) && p.feedExponent > 0, "feed_exponent", p.feedExponent, "must be > 0");
    check(finite(p.reductionRatio) && p.reductionRatio > 0, "reduction_ratio", p.reductionRatio, "must be > 0");
    check(finite(p.smoothingSpeed) && p.smoothingSpeed > 0, "smoothing_speed", p.smoothingSpeed, "must be > 0");
    check(finite(p.feedStartTime) && p.feedStartTime >= 0, "feed_start_time", p.feedStartTime, "must be >= 0");

    m_idle = p.constantTorque;
    if (p.law == ResistanceTorqueParams::Law::Feed) {
        const double qPerMinute = p.feedRate * 60.0;  // eq (16) takes q in kg/min
        m_feedPart = p.feedCoefficient * std::pow(qPerMinute, p.feedExponent) / p.reductionRatio;
    }
}

double ResistanceTorque::torqueAtSpeed(double omega, bool feeding) const {
    const double constant = m_idle + (feeding ? m_feedPart : 0.0);
    return constant * std::tanh(omega / m_params.smoothingSpeed) + m_params.viscousCoefficient * omega;
}

bool ResistanceTorque::isFeeding(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_feedingIndex));
}

void ResistanceTorque::setFeeding(SimTK::State& s, bool feeding) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_feedingIndex)) = feeding;
}

void ResistanceTorque::realizeTopology(SimTK::State& s) const {
    m_feedingIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics,
                                                       new SimTK::Value<bool>(m_params.feedStartTime <= 0));
}

double ResistanceTorque::calcTorque(const SimTK::State& s) const {
    return m_params.schedule.factorAt(s) *
           torqueAtSpeed(m_shaft.getOneU(s, SimTK::MobilizerUIndex(0)), isFeeding(s));
}

void ResistanceTorque::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -calcTorque(s), mobilityForces);
}

namespace {

void buildResistanceTorque(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    ResistanceTorqueParams p;
    p.law = spec.text("law") == "feed" ? ResistanceTorqueParams::Law::Feed
                                       : ResistanceTorqueParams::Law::SpeedLinear;
    p.constantTorque = spec.number("constant_torque");
    p.viscousCoefficient = spec.number("viscous_coefficient");
    p.feedRate = spec.number("feed_rate");
    p.feedCoefficient = spec.number("feed_coefficient");
    p.feedExponent = spec.number("feed_exponent");
    p.reductionRatio = spec.number("reduction_ratio");
    p.smoothingSpeed = spec.number("smoothing_speed");
    p.feedStartTime = spec.number("feed_start_time");
    p.schedule = Schedule::fromSpec(spec);
    auto* impl = new ResistanceTorque(scene.forces(), shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    addShaftLoadTorqueOutputs(scene, spec.name, shaft->mobod,
                              [impl](const SimTK::State& s) { return impl->calcTorque(s); });
    if (p.feedStartTime > 0)
        scene.addSwitchEvent({Scene::SwitchEvent::Kind::LoadOn, p.feedStartTime, spec.name + " feed opened",
                              [impl](SimTK::State& s) { impl->setFeeding(s, true); }});
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    scene.note("force " + spec.name + " (ResistanceTorque, " + spec.text("law") + ")",
               "loads body " + shaft->name +
                   (p.schedule.isConstant() ? "" : "; torque times the schedule: " + p.schedule.describe()));
}

}  // namespace

void registerResistanceTorque(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "ResistanceTorque";
    s.doc = "Load torque opposing rotation: M0 + b2·ω (seed 003 eq 17) or the feed law a·q^m "
            "(eq 16), smoothed near standstill.";
    s.params = {
        P::body("body", "shaft the load acts on"),
        P::choice("law", {"speed_linear", "feed"}, "resistance law").optional("speed_linear"),
        P::quantity("constant_torque", "N*m", "constant part M0 (feed law: idle part)").optional(0.0).atLeast(0),
        P::quantity("viscous_coefficient", "N*m*s/rad", "viscous part b2").optional(0.0).atLeast(0),
        P::quantity("feed_rate", "kg/s", "feed q (e.g. '130 kg/h')").optional(0.0).atLeast(0),
        P::quantity("feed_coefficient", "N*m", "a: organ torque at q = 1 kg/min").optional(0.0).atLeast(0),
        P::quantity("feed_exponent", "1", "m in a·q^m").optional(1.0).above(0).atMost(10),
        P::quantity("reduction_ratio", "1", "organ-to-shaft speed ratio u").optional(1.0).above(0),
        P::quantity("smoothing_speed", "rad/s", "regularisation width ωs near standstill")
            .optional(0.01).above(0),
        P::quantity("feed_start_time", "s", "feed law: the feed opens at this time (mill started empty)")
            .optional(0.0).atLeast(0),
        scheduleParam("schedule", "f(t) multiplying the torque: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    s.regularisationSpeedKey = "smoothing_speed";
    s.adjustableResistanceKey = "constant_torque";
    registry.add({std::move(s), buildResistanceTorque});
}

}  // namespace milldyn
