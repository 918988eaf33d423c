#include "plugins/motors/DqInductionMotor.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using Complex = std::complex<double>;

DqInductionMotor::DqInductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                                   const DqInductionMotorParams& p)
    : m_forces(forces), m_shaft(shaft), m_params(p) {
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

double DqInductionMotor::calcTorque(const SimTK::State& s) const {
    return 1.5 * m_params.polePairs * std::imag(std::conj(getStatorFlux(s)) * calcStatorCurrent(s));
}

DqInductionMotor::Derivatives DqInductionMotor::calcFluxRates(const SimTK::State& s) const {
    const double electricalSpeed = m_params.polePairs * pinSpeed(s, m_shaft);
    return {calcSupplyVoltage(s.getTime()) - m_params.statorResistance * calcStatorCurrent(s),
            -m_params.rotorResistance * calcRotorCurrent(s) + Complex(0, electricalSpeed) * getRotorFlux(s)};
}

double DqInductionMotor::calcInputPower(const SimTK::State& s) const {
    return 1.5 * std::real(calcSupplyVoltage(s.getTime()) * std::conj(calcStatorCurrent(s)));
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

void DqInductionMotor::realizeTopology(SimTK::State& s) const { m_flux = m_forces.allocateZ(s, SimTK::Vector(4, 0.0)); }

void DqInductionMotor::realizeAcceleration(const SimTK::State& s) const {
    const Derivatives d = calcFluxRates(s);
    SimTK::Vector& zdot = m_forces.updZDot(s);
    zdot[m_flux] = d.statorFlux.real();
    zdot[m_flux + 1] = d.statorFlux.imag();
    zdot[m_flux + 2] = d.rotorFlux.real();
    zdot[m_flux + 3] = d.rotorFlux.imag();
}

namespace {

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
    auto* impl = new DqInductionMotor(scene.forces(), shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    scene.addSpeedHint(shaft->name, 2 * M_PI * p.frequency / p.polePairs);
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl, mobod](const SimTK::State& s) { return impl->calcTorque(s) * pinSpeed(s, mobod); }});
    scene.addProbe({spec.name + ".current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return std::abs(impl->calcStatorCurrent(s)) / std::sqrt(2.0); }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source, [impl](const SimTK::State& s) { return impl->calcInputPower(s); },
                         "electrical input of " + spec.name + " at its terminals"});
    scene.addEnergyFlow({spec.name + ".field", EnergyFlow::Kind::Source,
                         [impl](const SimTK::State& s) { return -impl->calcFieldPower(s); },
                         "magnetic field energy of " + spec.name + " released (negative: stored)"});
    scene.addEnergyFlow({spec.name + ".copper_heat", EnergyFlow::Kind::Dissipation,
                         [impl](const SimTK::State& s) { return impl->calcCopperLoss(s); },
                         "heat in the stator and rotor windings of " + spec.name});
    scene.note("force " + spec.name + " (DqInductionMotor, direct on line)", "drives body " + shaft->name);
}

}  // namespace

void registerDqInductionMotor(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "DqInductionMotor";
    s.doc = "Squirrel-cage induction motor as a dynamic space-phasor (dq) model with stator and rotor flux "
            "states, started direct on line (Krause; Modelica MSL AIM_SquirrelCage).";
    s.params = {
        P::body("body", "shaft the motor drives"),
        P::quantity("stator_resistance", "ohm", "Rs per phase").above(0),
        P::quantity("rotor_resistance", "ohm", "Rr' per phase, referred to the stator").above(0),
        P::quantity("stator_leakage_inductance", "H", "Lsσ per phase").above(0),
        P::quantity("rotor_leakage_inductance", "H", "Lrσ' per phase, referred to the stator").above(0),
        P::quantity("main_inductance", "H", "Lm per phase").above(0),
        P::quantity("pole_pairs", "1", "p").optional(2.0).atLeast(1).atMost(50),
        P::quantity("phase_voltage", "V", "rms phase voltage of the equivalent star").above(0),
        P::quantity("frequency", "Hz", "supply frequency f").optional(50.0).above(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const double p = e.number("pole_pairs");
        if (p != std::floor(p)) throw e.error("pole_pairs", "must be a whole number");
    };
    registry.add({std::move(s), buildDqInductionMotor});
}

}  // namespace milldyn
