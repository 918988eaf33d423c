#include "plugins/transmissions/Clutch.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

double calcFrictionTorque(double capacity, double slipSpeed, double regularisationSpeed) {
    return capacity * std::tanh(slipSpeed / regularisationSpeed);
}

double calcStickSlipTorque(double capacity, double kineticFraction, double slipSpeed, double regularisationSpeed,
                           double stribeckSpeed) {
    if (kineticFraction >= 1) return calcFrictionTorque(capacity, slipSpeed, regularisationSpeed);
    const double x = slipSpeed / stribeckSpeed;
    return capacity * (kineticFraction + (1 - kineticFraction) * std::exp(-x * x)) *
           std::tanh(slipSpeed / regularisationSpeed);
}

double rampFraction(double time, double start, double rampTime) {
    return std::min(std::max((time - start) / rampTime, 0.0), 1.0);
}

Clutch::Clutch(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& from,
               const SimTK::MobilizedBody& to, const ClutchParams& p)
    : m_forces(forces), m_from(from), m_to(to), m_params(p) {
    auto bad = [](const std::string& name, double v, const std::string& rule) {
        throw std::invalid_argument("Clutch: " + name + " = " + std::to_string(v) + " is invalid: " + rule);
    };
    if (!(std::isfinite(p.capacity) && p.capacity > 0)) bad("capacity", p.capacity, "must be finite and > 0");
    if (!(std::isfinite(p.engageTime) && p.engageTime >= 0)) bad("engage_time", p.engageTime, "must be finite and >= 0");
    if (p.schedule.isConstant() && !(std::isfinite(p.rampTime) && p.rampTime > 0))
        bad("ramp_time", p.rampTime, "must be finite and > 0");
    if (!(std::isfinite(p.regularisationSpeed) && p.regularisationSpeed > 0))
        bad("regularisation_speed", p.regularisationSpeed, "must be finite and > 0");
    if (!(std::isfinite(p.kineticCapacity) && p.kineticCapacity >= 0 && p.kineticCapacity <= p.capacity))
        bad("kinetic_capacity", p.kineticCapacity, "must be in (0, capacity] (0: the capacity)");
    if (!(std::isfinite(p.stribeckSpeed) && p.stribeckSpeed > p.regularisationSpeed))
        bad("stribeck_speed", p.stribeckSpeed, "must be finite and > regularisation_speed");
    if (!(p.schedule.isConstant() || std::isfinite(p.schedule.settleTime())))
        bad("schedule", 0, "a clutch's pressure must settle (ramp, step_recovery or table, not sine)");
    m_kineticFraction = p.kineticCapacity > 0 ? p.kineticCapacity / p.capacity : 1.0;
}

double Clutch::pressureAt(double t) const {
    if (!m_params.schedule.isConstant()) return m_params.schedule.factorAt(t);
    return rampFraction(t, m_params.engageTime, m_params.rampTime);
}

double Clutch::torqueAt(double capacity, double slip) const {
    return calcStickSlipTorque(capacity, m_kineticFraction, slip, m_params.regularisationSpeed,
                               m_params.stribeckSpeed);
}

double Clutch::calcSlipSpeed(const SimTK::State& s) const { return pinSpeed(s, m_from) - pinSpeed(s, m_to); }

double Clutch::calcCapacity(const SimTK::State& s) const {
    if (isEngaged(s)) return m_params.capacity * m_params.schedule.finalFactor();
    return m_params.capacity * pressureAt(s.getTime());
}

void Clutch::realizeTopology(SimTK::State& state) const {
    m_engagedIndex = m_forces.allocateDiscreteVariable(state, SimTK::Stage::Dynamics, new SimTK::Value<bool>(false));
}

void Clutch::engage(SimTK::State& state) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(state, m_engagedIndex)) = true;
}

bool Clutch::isEngaged(const SimTK::State& state) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(state, m_engagedIndex));
}

double Clutch::calcTorque(const SimTK::State& s) const {
    return torqueAt(calcCapacity(s), calcSlipSpeed(s));
}

StartSequenceState Clutch::calcEngagement(const SimTK::State& s) const {
    // Engaged: the pressure has reached its final value (1 for the ramp).
    const double finalFactor = m_params.schedule.finalFactor();
    const bool settled = isEngaged(s) || s.getTime() >= (m_params.schedule.isConstant()
                                                             ? m_params.engageTime + m_params.rampTime
                                                             : m_params.schedule.settleTime());
    const double engaged = settled || !(finalFactor > 0)
                               ? (settled ? 1.0 : 0.0)
                               : std::min(calcCapacity(s) / (m_params.capacity * finalFactor), 1.0 - 1e-12);
    const double slip = calcSlipSpeed(s);
    const double lockSlip = std::max(10 * m_params.regularisationSpeed, 0.01 * std::abs(pinSpeed(s, m_from)));
    StartSequenceState q;
    q.finished = engaged >= 1 && std::abs(slip) <= lockSlip;
    q.waitsOnShaft = engaged >= 1 && !q.finished;
    const std::string fullAt = formatNumber(m_params.schedule.isConstant() ? m_params.engageTime + m_params.rampTime
                                                                           : m_params.schedule.settleTime());
    q.text = engaged < 1 ? "clutch engaging: capacity " + formatNumber(100 * engaged, 3) + " % of " +
                               formatNumber(m_params.capacity * finalFactor) + " N*m, full at " + fullAt + " s"
             : q.finished ? "clutch engaged and locked (slip " + formatNumber(slip, 3) + " rad/s)"
                          : "clutch fully engaged but slipping at " + formatNumber(slip, 4) + " rad/s (locked: within " +
                                formatNumber(lockSlip, 3) + " rad/s)";
    return q;
}

void Clutch::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                       SimTK::Vector& mobilityForces) const {
    const double T = calcTorque(s);
    m_from.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -T, mobilityForces);
    m_to.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), T, mobilityForces);
}

namespace {

void buildClutch(const ElementSpec& spec, Scene& scene) {
    const auto& names = spec.names("bodies");
    const SceneBody* from = scene.findBody(names.at(0));
    const SceneBody* to = scene.findBody(names.at(1));
    ClutchParams p;
    p.capacity = spec.number("capacity");
    p.engageTime = spec.number("engage_time");
    p.rampTime = spec.number("ramp_time");
    p.regularisationSpeed = spec.number("regularisation_speed");
    p.kineticCapacity = spec.number("kinetic_capacity");
    p.stribeckSpeed = spec.number("stribeck_speed");
    p.schedule = Schedule::fromSpecUntriggered(spec);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    auto* impl = new Clutch(scene.forces(), from->mobod, to->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::CouplingTorque, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".slip_speed", "rad/s", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcSlipSpeed(s); }});
    scene.addProbe({spec.name + ".capacity", "N*m", ProbeRole::Generic, SimTK::Stage::Time,
                    [impl](const SimTK::State& s) { return impl->calcCapacity(s); },
                    "sticking capacity M_max·r(t) at the pressure of the moment"});
    // No steady residual on the slip: a locked pair creeps at
    // ω_reg·atanh(T/M_c) to carry its torque, which the shafts' balance
    // (zero acceleration) already fixes.
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                         [impl](const SimTK::State& s) { return impl->calcTorque(s) * impl->calcSlipSpeed(s); },
                         "slip heat of the clutch " + spec.name});
    scene.addSpeedRelation(from->name, to->name, 1.0);
    scene.addStartSequence({spec.name, [impl](const SimTK::State& s) { return impl->calcEngagement(s); },
                            [impl](SimTK::State& s) { impl->engage(s); }});
    scene.note("force " + spec.name + " (Clutch)", "couples " + from->name + " to " + to->name + " by friction");
}

}  // namespace

void registerClutch(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "Clutch";
    s.doc = "Friction clutch between two shafts (1:1) engaging over a ramp or a pressure schedule, sticking up to "
            "M_max and sliding at M_k: T = M_c(t)·(κ + (1 − κ)·exp(−(Δω/ω_s)²))·tanh(Δω/ω_reg); slip heat.";
    s.params = {
        P::bodyPair("bodies", "[from, to]: the driving shaft first"),
        P::quantity("capacity", "N*m", "torque capacity when engaged").above(0),
        P::quantity("engage_time", "s", "engagement starts").optional(0.0).atLeast(0),
        P::quantity("ramp_time", "s", "capacity ramp from 0 to full (required without schedule)").optional(0.0).above(0),
        P::quantity("regularisation_speed", "rad/s", "slip-speed regularisation ω_reg: the creep scale when locked")
            .optional(1e-3).above(0),
        P::quantity("kinetic_capacity", "N*m", "sliding torque M_k at full pressure, <= capacity (default: capacity)")
            .optional(0.0).above(0),
        P::quantity("stribeck_speed", "rad/s", "slip ω_s over which sticking gives way to sliding, > ω_reg")
            .optional(0.05).above(0),
        scheduleParam("schedule", "pressure curve r(t) multiplying both capacities: {ramp|step_recovery|table: ...} "
                                "(replaces engage_time and ramp_time)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const auto& n = e.names("bodies");
        if (n.size() == 2 && n[0] == n[1])
            throw e.error("bodies", "a clutch needs two different bodies, got '" + n[0] + "' twice");
        if (e.has("schedule")) {
            for (const char* k : {"engage_time", "ramp_time"})
                if (e.has(k)) throw e.error(k, "not used with schedule (the schedule is the whole pressure curve)");
            if (e.text("schedule") == "sine")
                throw e.error("schedule", "a clutch's pressure must settle: ramp, step_recovery or table, not sine");
        } else if (!e.has("ramp_time")) {
            throw e.error("ramp_time", "missing required key 'ramp_time' (or give a schedule)");
        }
        if (e.has("kinetic_capacity") && e.number("kinetic_capacity") > e.number("capacity"))
            throw e.error("kinetic_capacity", "must be <= capacity (sliding never holds more than sticking), got " +
                                                  formatNumber(e.number("kinetic_capacity")) + " N*m > " +
                                                  formatNumber(e.number("capacity")) + " N*m");
        if (e.number("stribeck_speed") <= e.number("regularisation_speed"))
            throw e.error("stribeck_speed", "must be > regularisation_speed (" +
                                                formatNumber(e.number("regularisation_speed")) + " rad/s)");
    };
    registry.add({std::move(s), buildClutch});
}

}  // namespace milldyn
