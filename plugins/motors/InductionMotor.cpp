#include "plugins/motors/InductionMotor.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {
namespace {

[[noreturn]] void badParameter(const std::string& name, double value, const std::string& rule) {
    throw std::invalid_argument("InductionMotor: " + name + " = " + std::to_string(value) +
                                " is invalid: " + rule);
}

}  // namespace

InductionMotor::InductionMotor(const SimTK::GeneralForceSubsystem& forces,
                               const SimTK::MobilizedBody& shaft, const InductionMotorParams& p)
    : m_forces(forces), m_shaft(shaft), m_params(p) {
    auto finite = [](double v) { return std::isfinite(v); };
    if (!(finite(p.ratedTorque) && p.ratedTorque > 0)) badParameter("rated_torque", p.ratedTorque, "must be finite and > 0");
    if (!(finite(p.synchronousSpeed) && p.synchronousSpeed > 0))
        badParameter("synchronous_speed", p.synchronousSpeed, "must be finite and > 0");
    if (!(p.ratedSpeed > 0 && p.ratedSpeed < p.synchronousSpeed))
        badParameter("rated_speed", p.ratedSpeed, "must lie in (0, synchronous_speed)");
    if (!finite(p.breakdownRatio)) badParameter("breakdown_ratio", p.breakdownRatio, "must be finite");
    if (p.law == InductionMotorParams::Law::Kloss && !(p.breakdownRatio > 1))
        badParameter("breakdown_ratio", p.breakdownRatio, "must be > 1 for the Kloss law");
    if (!(finite(p.linearStallTorque) && p.linearStallTorque >= 0))
        badParameter("linear_stall_torque", p.linearStallTorque, "must be finite and >= 0");
    if (!(finite(p.linearSlope) && p.linearSlope >= 0)) badParameter("linear_slope", p.linearSlope, "must be finite and >= 0");
    if (std::isnan(p.switchOffTime)) badParameter("switch_off_time", p.switchOffTime, "is NaN");

    const double slipSpeed = p.synchronousSpeed - p.ratedSpeed;
    if (p.linearStallTorque > 0 && p.linearSlope > 0) {
        m_M00 = p.linearStallTorque;
        m_b0 = p.linearSlope;
    } else {
        m_M00 = p.ratedTorque * p.synchronousSpeed / slipSpeed;  // eq (4)
        m_b0 = p.ratedTorque / slipSpeed;                         // eq (4)
    }
    m_slipRated = slipSpeed / p.synchronousSpeed;
    const double lambda = p.breakdownRatio;
    m_slipBreakdown = m_slipRated * (lambda + std::sqrt(std::max(0.0, lambda * lambda - 1)));
}

double InductionMotor::torqueAtSpeed(double omega) const {
    if (m_params.law == InductionMotorParams::Law::Linear) return m_M00 - m_b0 * omega;  // eq (3)
    const double s = (m_params.synchronousSpeed - omega) / m_params.synchronousSpeed;
    const double sk = m_slipBreakdown;
    const double Mk = m_params.breakdownRatio * m_params.ratedTorque;
    // 2Mk/(s/sk + sk/s) written without the division by s, so s = 0 is fine.
    return 2 * Mk * s * sk / (s * s + sk * sk);
}

bool InductionMotor::isOn(const SimTK::State& state) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(state, m_onIndex));
}

void InductionMotor::setOn(SimTK::State& state, bool on) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(state, m_onIndex)) = on;
}

double InductionMotor::calcTorque(const SimTK::State& state) const {
    if (!isOn(state)) return 0;
    return torqueAtSpeed(m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)));
}

void InductionMotor::calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>&,
                               SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(state, SimTK::MobilizerUIndex(0), calcTorque(state),
                                  mobilityForces);
}

void InductionMotor::realizeTopology(SimTK::State& state) const {
    // A switch-off changes forces, so the variable invalidates Dynamics.
    m_onIndex = m_forces.allocateDiscreteVariable(state, SimTK::Stage::Dynamics,
                                                  new SimTK::Value<bool>(true));
}

namespace {

void buildInductionMotor(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    InductionMotorParams p;
    p.law = spec.text("law") == "linear" ? InductionMotorParams::Law::Linear
                                         : InductionMotorParams::Law::Kloss;
    p.ratedTorque = spec.number("rated_torque");
    p.ratedSpeed = spec.number("rated_speed");
    p.synchronousSpeed = spec.number("synchronous_speed");
    p.breakdownRatio = spec.number("breakdown_ratio");
    p.linearStallTorque = spec.number("linear_stall_torque");
    p.linearSlope = spec.number("linear_slope");
    p.switchOffTime = spec.number("switch_off_time");

    auto* impl = new InductionMotor(scene.forces(), shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);  // Simbody owns impl
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    scene.addSwitchable(spec.name, [impl](SimTK::State& s, bool on) { impl->setOn(s, on); });
    if (std::isfinite(p.switchOffTime))
        scene.addSwitchEvent({Scene::SwitchEvent::Kind::DriveOff, p.switchOffTime, spec.name + " switched off",
                              [impl](SimTK::State& s) { impl->setOn(s, false); }});
    // Slightly below synchronous: where every motor law has its stable branch.
    scene.addSpeedHint(shaft->name, p.ratedSpeed);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl, mobod](const SimTK::State& s) {
                        return impl->calcTorque(s) * pinSpeed(s, mobod);
                    }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source, [impl, mobod](const SimTK::State& s) {
                             return impl->calcTorque(s) * pinSpeed(s, mobod);
                         }});
    scene.note("force " + spec.name + " (InductionMotor, " + spec.text("law") + ")",
               "drives body " + shaft->name);
}

}  // namespace

void registerInductionMotor(ElementRegistry& registry) {
    ElementSchema s;
    s.type = "InductionMotor";
    s.doc = "Asynchronous motor torque on a shaft: linear working branch (seed 003 eqs 3-4) or "
            "Kloss curve; optional switch-off time.";
    using P = ParamSchema;
    const double never = std::numeric_limits<double>::infinity();
    s.params = {
        P::body("body", "shaft the motor drives"),
        P::choice("law", {"kloss", "linear"}, "torque-speed law").optional("kloss"),
        P::quantity("rated_torque", "N*m", "nameplate torque Mn").above(0),
        P::quantity("rated_speed", "rad/s", "nameplate speed ωn, below synchronous").above(0),
        P::quantity("synchronous_speed", "rad/s", "synchronous speed ωc").above(0),
        P::quantity("breakdown_ratio", "1", "Kloss: breakdown over rated torque λ")
            .optional(2.2).above(1).atMost(10),
        P::quantity("linear_stall_torque", "N*m", "linear law: printed M00 (0: eq 4)")
            .optional(0.0).atLeast(0),
        P::quantity("linear_slope", "N*m*s/rad", "linear law: printed b0 (0: eq 4)")
            .optional(0.0).atLeast(0),
        P::quantity("switch_off_time", "s", "supply switched off at this time (default never)")
            .optional(never).atLeast(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.number("rated_speed") >= e.number("synchronous_speed"))
            throw e.error("rated_speed", "rated speed must be below the synchronous speed (" +
                                             std::to_string(e.number("rated_speed")) +
                                             " rad/s >= " +
                                             std::to_string(e.number("synchronous_speed")) +
                                             " rad/s)");
        if (e.has("linear_stall_torque") != e.has("linear_slope"))
            throw e.error(e.has("linear_slope") ? "linear_slope" : "linear_stall_torque",
                          "give both linear_stall_torque and linear_slope, or neither");
    };
    registry.add({std::move(s), buildInductionMotor});
}

}  // namespace milldyn
