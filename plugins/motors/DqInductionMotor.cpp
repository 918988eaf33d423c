#include "plugins/motors/DqInductionMotor.h"
#include "plugins/motors/StarterEvents.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace milldyn {

using Complex = std::complex<double>;

DqInductionMotor::DqInductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                                   const DqInductionMotorParams& p)
    : m_forces(forces), m_shaft(shaft), m_params(p), m_starter(p.starter) {
    auto positive = [](const char* name, double v) {
        if (!(std::isfinite(v) && v > 0))
            throw std::invalid_argument(std::string("DqInductionMotor: ") + name + " = " + std::to_string(v) +
                                        " is invalid: must be finite and > 0");
    };
    positive("stator_resistance", p.statorResistance);
    positive("rotor_resistance", p.rotorResistance);
    positive("stator_leakage_inductance", p.statorLeakage);
    positive("rotor_leakage_inductance", p.rotorLeakage);
    positive("main_inductance", p.mainInductance);
    positive("phase_voltage", p.phaseVoltage);
    positive("frequency", p.frequency);
    if (p.polePairs < 1) throw std::invalid_argument("DqInductionMotor: pole_pairs must be >= 1");
    using K = StarterParams::Kind;
    if (p.starter.kind != K::DirectOnLine && p.starter.kind != K::StarDelta && p.starter.kind != K::SoftStart)
        throw std::invalid_argument("DqInductionMotor: starter " + Starter::kindName(p.starter.kind) +
                                    " is not available (direct_on_line, star_delta, soft_start)");
    if (!p.starter.switchSpeeds.empty())
        throw std::invalid_argument("DqInductionMotor: star_delta switches by time only (switch_times)");
    m_Ls = p.statorLeakage + p.mainInductance;
    m_Lr = p.rotorLeakage + p.mainInductance;
    m_D = m_Ls * m_Lr - p.mainInductance * p.mainInductance;
}

Complex DqInductionMotor::getStatorFlux(const SimTK::State& s) const {
    const SimTK::Vector& z = m_forces.getZ(s);
    return {z[m_flux], z[m_flux + 1]};
}

Complex DqInductionMotor::getRotorFlux(const SimTK::State& s) const {
    const SimTK::Vector& z = m_forces.getZ(s);
    return {z[m_flux + 2], z[m_flux + 3]};
}

Complex DqInductionMotor::calcStatorCurrent(const SimTK::State& s) const {
    return (m_Lr * getStatorFlux(s) - m_params.mainInductance * getRotorFlux(s)) / m_D;
}

Complex DqInductionMotor::calcRotorCurrent(const SimTK::State& s) const {
    return (m_Ls * getRotorFlux(s) - m_params.mainInductance * getStatorFlux(s)) / m_D;
}

Complex DqInductionMotor::calcSupplyVoltage(double t) const {
    return std::polar(std::sqrt(2.0) * m_params.phaseVoltage, 2 * M_PI * m_params.frequency * t);
}

double DqInductionMotor::calcVoltageFactor(const SimTK::State& s) const {
    // Star–delta's torque factor 1/3 (Starter) is u² on the windings.
    const SupplyState u = m_starter.supply(s.getTime(), getStarterStep(s), isStarterFinished(s));
    return u.voltage * std::sqrt(u.connection);
}

Complex DqInductionMotor::calcTerminalVoltage(const SimTK::State& s) const {
    return calcVoltageFactor(s) * calcSupplyVoltage(s.getTime());
}

double DqInductionMotor::calcLineCurrent(const SimTK::State& s) const {
    const double phase = std::abs(calcStatorCurrent(s)) / std::sqrt(2.0);
    const bool delta = m_params.starter.kind == StarterParams::Kind::StarDelta && getStarterStep(s) > 0;
    return delta ? std::sqrt(3.0) * phase : phase;
}

StartSequenceState DqInductionMotor::calcStarterProgress(const SimTK::State& s) const {
    return m_starter.progress(s.getTime(), getStarterStep(s), isStarterFinished(s));
}

void DqInductionMotor::finishStarter(SimTK::State& s) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_finishedIndex)) = true;
    setStarterStep(s, m_starter.switchCount());
}

bool DqInductionMotor::isStarterFinished(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_finishedIndex));
}

int DqInductionMotor::getStarterStep(const SimTK::State& s) const {
    return SimTK::Value<int>::downcast(m_forces.getDiscreteVariable(s, m_stepIndex));
}

void DqInductionMotor::setStarterStep(SimTK::State& s, int step) const {
    SimTK::Value<int>::updDowncast(m_forces.updDiscreteVariable(s, m_stepIndex)) = step;
}

void DqInductionMotor::setSteadyFluxes(SimTK::State& s) const {
    const DqInductionMotorParams& p = m_params;
    const double ws = 2 * M_PI * p.frequency;
    const Complex k = (p.rotorResistance * p.mainInductance / m_D) /
                      Complex(p.rotorResistance * m_Ls / m_D, ws - p.polePairs * pinSpeed(s, m_shaft));
    const Complex statorFlux =
        calcTerminalVoltage(s) / (Complex(0, ws) + p.statorResistance * (m_Lr - p.mainInductance * k) / m_D);
    const Complex rotorFlux = k * statorFlux;
    SimTK::Vector& z = m_forces.updZ(s);
    z[m_flux] = statorFlux.real();
    z[m_flux + 1] = statorFlux.imag();
    z[m_flux + 2] = rotorFlux.real();
    z[m_flux + 3] = rotorFlux.imag();
}

double DqInductionMotor::calcTorque(const SimTK::State& s) const {
    return 1.5 * m_params.polePairs * std::imag(std::conj(getStatorFlux(s)) * calcStatorCurrent(s));
}

DqInductionMotor::Derivatives DqInductionMotor::calcFluxRates(const SimTK::State& s) const {
    const double electricalSpeed = m_params.polePairs * pinSpeed(s, m_shaft);
    return {calcTerminalVoltage(s) - m_params.statorResistance * calcStatorCurrent(s),
            -m_params.rotorResistance * calcRotorCurrent(s) + Complex(0, electricalSpeed) * getRotorFlux(s)};
}

double DqInductionMotor::calcInputPower(const SimTK::State& s) const {
    return 1.5 * std::real(calcTerminalVoltage(s) * std::conj(calcStatorCurrent(s)));
}

double DqInductionMotor::calcCopperLoss(const SimTK::State& s) const {
    return 1.5 * (m_params.statorResistance * std::norm(calcStatorCurrent(s)) +
                  m_params.rotorResistance * std::norm(calcRotorCurrent(s)));
}

double DqInductionMotor::calcFieldPower(const SimTK::State& s) const {
    const Derivatives d = calcFluxRates(s);
    return 1.5 * std::real(std::conj(calcStatorCurrent(s)) * d.statorFlux +
                           std::conj(calcRotorCurrent(s)) * d.rotorFlux);
}

void DqInductionMotor::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcTorque(s), mobilityForces);
}

void DqInductionMotor::realizeTopology(SimTK::State& s) const {
    m_flux = m_forces.allocateZ(s, SimTK::Vector(4, 0.0));
    // A switch changes the voltage, so the step invalidates Dynamics.
    m_stepIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<int>(0));
    m_finishedIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(false));
}

void DqInductionMotor::realizeAcceleration(const SimTK::State& s) const {
    const Derivatives d = calcFluxRates(s);
    SimTK::Vector& zdot = m_forces.updZDot(s);
    zdot[m_flux] = d.statorFlux.real();
    zdot[m_flux + 1] = d.statorFlux.imag();
    zdot[m_flux + 2] = d.rotorFlux.real();
    zdot[m_flux + 3] = d.rotorFlux.imag();
}

namespace {

using StarterKind = StarterParams::Kind;
const std::vector<StarterKind> kDqStarters = {StarterKind::DirectOnLine, StarterKind::StarDelta, StarterKind::SoftStart};

// The keys each starter uses; giving one to another starter is an error.
const std::vector<std::pair<std::string, std::vector<std::string>>> kDqStarterKeys = {
    {"star_delta", {"switch_times"}},
    {"soft_start", {"initial_voltage", "ramp_time"}},
};

void crossCheckDqInductionMotor(const ElementSpec& e) {
    const double p = e.number("pole_pairs");
    if (p != std::floor(p)) throw e.error("pole_pairs", "must be a whole number");
    const std::string starter = e.text("starter");
    for (const auto& [owner, keys] : kDqStarterKeys)
        for (const auto& k : keys)
            if (owner != starter && e.has(k))
                throw e.error(k, "not used with starter " + starter + " (only with starter " + owner + ")");
    if (starter == "star_delta" && e.numbers("switch_times").size() != 1)
        throw e.error("starter", "star_delta switches once: give one switch_times item");
    if (starter == "soft_start" && !(e.number("ramp_time") > 0))
        throw e.error(e.has("ramp_time") ? "ramp_time" : "starter", "a ramp of zero length: soft_start needs ramp_time > 0");
}

void buildDqInductionMotor(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    DqInductionMotorParams p;
    p.statorResistance = spec.number("stator_resistance");
    p.rotorResistance = spec.number("rotor_resistance");
    p.statorLeakage = spec.number("stator_leakage_inductance");
    p.rotorLeakage = spec.number("rotor_leakage_inductance");
    p.mainInductance = spec.number("main_inductance");
    p.polePairs = static_cast<int>(spec.number("pole_pairs"));
    p.phaseVoltage = spec.number("phase_voltage");
    p.frequency = spec.number("frequency");
    StarterParams& st = p.starter;
    for (auto k : kDqStarters)
        if (Starter::kindName(k) == spec.text("starter")) st.kind = k;
    st.switchTimes = spec.numbers("switch_times");
    st.initialVoltage = spec.number("initial_voltage");
    st.rampTime = spec.number("ramp_time");
    auto* impl = new DqInductionMotor(scene.forces(), shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    addStarterEvents(scene, spec.name, st, impl);
    // Steady running with the field built up (not switched on unexcited).
    scene.addSteadyInitializer([impl](SimTK::State& s) { impl->setSteadyFluxes(s); });
    scene.addSpeedHint(shaft->name, 2 * M_PI * p.frequency / p.polePairs);
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl, mobod](const SimTK::State& s) { return impl->calcTorque(s) * pinSpeed(s, mobod); }});
    scene.addProbe({spec.name + ".current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return std::abs(impl->calcStatorCurrent(s)) / std::sqrt(2.0); }});
    if (st.kind != StarterParams::Kind::DirectOnLine)
        scene.addProbe({spec.name + ".voltage", "1", ProbeRole::Generic, SimTK::Stage::Time,
                        [impl](const SimTK::State& s) { return impl->calcVoltageFactor(s); }});
    if (st.kind == StarterParams::Kind::StarDelta)
        scene.addProbe({spec.name + ".line_current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcLineCurrent(s); }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source, [impl](const SimTK::State& s) { return impl->calcInputPower(s); },
                         "electrical input of " + spec.name + " at its terminals"});
    scene.addEnergyFlow({spec.name + ".field", EnergyFlow::Kind::Source,
                         [impl](const SimTK::State& s) { return -impl->calcFieldPower(s); },
                         "magnetic field energy of " + spec.name + " released (negative: stored)"});
    scene.addEnergyFlow({spec.name + ".copper_heat", EnergyFlow::Kind::Dissipation,
                         [impl](const SimTK::State& s) { return impl->calcCopperLoss(s); },
                         "heat in the stator and rotor windings of " + spec.name});
    scene.note("force " + spec.name + " (DqInductionMotor, " + Starter::kindName(st.kind) + ")",
               "drives body " + shaft->name);
}

}  // namespace

void registerDqInductionMotor(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "DqInductionMotor";
    s.doc = "Squirrel-cage induction motor as a dynamic space-phasor (dq) model with stator and rotor flux "
            "states, started direct on line, star-delta or by a soft starter (Krause; Modelica MSL AIM_SquirrelCage).";
    std::vector<std::string> starters;
    for (StarterKind k : kDqStarters) starters.push_back(Starter::kindName(k));
    s.params = {
        P::body("body", "shaft the motor drives"),
        P::quantity("stator_resistance", "ohm", "Rs per phase").above(0),
        P::quantity("rotor_resistance", "ohm", "Rr' per phase, referred to the stator").above(0),
        P::quantity("stator_leakage_inductance", "H", "Lsσ per phase").above(0),
        P::quantity("rotor_leakage_inductance", "H", "Lrσ' per phase, referred to the stator").above(0),
        P::quantity("main_inductance", "H", "Lm per phase").above(0),
        P::quantity("pole_pairs", "1", "p").optional(2.0).atLeast(1).atMost(50),
        // At most 100 kV (the largest motors are 13.8 kV line): the coupled
        // electromechanical frequency grows with the voltage, and so does the
        // work; 1e9 V took 207 s for 0.05 s simulated (issue 26 item 7).
        P::quantity("phase_voltage", "V", "rms voltage on a phase winding (star_delta: on the winding in delta, the line voltage)").above(0).atMost(1e5),
        P::quantity("frequency", "Hz", "supply frequency f").optional(50.0).above(0),
        P::choice("starter", starters, "how the motor is started").optional("direct_on_line"),
        P::quantityList("switch_times", "s", 1, 1, "star_delta: time of the switch from star to delta")
            .optional(0.0)
            .above(0),
        P::quantity("initial_voltage", "1", "soft_start: initial voltage over rated").optional(0.3).above(0).atMost(1),
        P::quantity("ramp_time", "s", "soft_start: ramp length to full voltage").optional(0.0).atLeast(0),
    };
    s.crossCheck = crossCheckDqInductionMotor;
    registry.add({std::move(s), buildDqInductionMotor});
}

}  // namespace milldyn
