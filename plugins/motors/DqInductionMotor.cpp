#include "plugins/motors/DqInductionMotor.h"
#include "plugins/motors/CageCircuitFit.h"
#include "plugins/motors/StarterEvents.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cctype>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace milldyn {

using Complex = std::complex<double>;

namespace {

CageCircuit circuitOf(const DqInductionMotorParams& p) {
    CageCircuit c;
    c.statorResistance = p.statorResistance;
    c.statorLeakage = p.statorLeakage;
    c.mainInductance = p.mainInductance;
    c.rotorResistances = {p.rotorResistance};
    c.rotorLeakages = {p.rotorLeakage};
    if (p.rotorResistance2 > 0) {
        c.rotorResistances.push_back(p.rotorResistance2);
        c.rotorLeakages.push_back(p.rotorLeakage2);
    }
    return c;
}

/// The slip speed [rad/s, electrical] in (0, breakdown] at which an
/// increasing function of it reaches `limit`; the breakdown slip speed if
/// it stays below.
double bisectSlip(const std::function<double(double)>& value, double limit, double breakdownSlipSpeed) {
    if (!(value(breakdownSlipSpeed) > limit)) return breakdownSlipSpeed;
    double lo = 0, hi = breakdownSlipSpeed;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (value(mid) < limit ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace

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
    if (p.rotorResistance2 != 0 || p.rotorLeakage2 != 0) {
        positive("rotor_resistance_2", p.rotorResistance2);
        positive("rotor_leakage_inductance_2", p.rotorLeakage2);
        m_nr = 2;
    }
    using K = StarterParams::Kind;
    if (!p.starter.switchSpeeds.empty() && p.openTransitionTime > 0)
        throw std::invalid_argument("DqInductionMotor: an open star-delta transition switches by time only");
    if (m_nr == 2 && (p.starter.kind == K::RotorResistance || p.starter.kind == K::LiquidResistance))
        throw std::invalid_argument("DqInductionMotor: a " + Starter::kindName(p.starter.kind) +
                                    " starter needs a slip-ring rotor (one rotor circuit), not a double cage");
    if (!(std::isfinite(p.openTransitionTime) && p.openTransitionTime >= 0))
        throw std::invalid_argument("DqInductionMotor: open_transition_time must be finite and >= 0");
    if (!std::isfinite(p.deltaPhaseShift)) throw std::invalid_argument("DqInductionMotor: delta_phase_shift must be finite");
    if (!(p.voltageBoost >= 0 && p.voltageBoost < 1))
        throw std::invalid_argument("DqInductionMotor: voltage_boost must lie in [0, 1)");
    positive("limit_time_constant", p.limitTimeConstant);
    if (!(std::isfinite(p.interruptionTime) && p.interruptionTime >= 0 && std::isfinite(p.interruptionDuration) &&
          p.interruptionDuration >= 0))
        throw std::invalid_argument("DqInductionMotor: interruption_time and interruption_duration must be finite and >= 0");
    if (!(p.shortCircuitPower > 0)) throw std::invalid_argument("DqInductionMotor: short_circuit_power must be > 0");
    positive("source_x_r", p.sourceXR);

    const int n = 1 + m_nr;
    Eigen::MatrixXd L = Eigen::MatrixXd::Constant(n, n, p.mainInductance);
    L(0, 0) += p.statorLeakage;
    L(1, 1) += p.rotorLeakage;
    if (m_nr == 2) L(2, 2) += p.rotorLeakage2;
    const Eigen::MatrixXd G = L.inverse();
    const Eigen::MatrixXd Grr = L.bottomRightCorner(m_nr, m_nr).inverse();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m_L[i][j] = L(i, j), m_G[i][j] = G(i, j);
    for (int i = 0; i < m_nr; ++i)
        for (int j = 0; j < m_nr; ++j) m_Grr[i][j] = Grr(i, j);

    const double ws = 2 * M_PI * p.frequency;
    if (std::isfinite(p.shortCircuitPower)) {
        const double Z = 3 * p.phaseVoltage * p.phaseVoltage / p.shortCircuitPower;
        m_Rk = Z / std::sqrt(1 + p.sourceXR * p.sourceXR);
        m_Lk = p.sourceXR * m_Rk / ws;
    }
    if (isConverter()) {
        // The rated circuit (f = 1) at a slip speed Δω: torque and current.
        const CageCircuit c = circuitOf(p);
        const auto at = [&](double slipSpeed) {
            return cageSteadyState(c, p.phaseVoltage, p.frequency, p.polePairs, slipSpeed / ws);
        };
        const double breakdown = cageBreakdown(c, p.phaseVoltage, p.frequency, p.polePairs).slip * ws;
        m_holdSlip = breakdown;
        if (std::isfinite(p.starter.torqueLimit))
            m_holdSlip = bisectSlip([&](double d) { return at(d).torque; }, p.starter.torqueLimit, breakdown);
        if (std::isfinite(p.starter.currentLimit)) {
            const double noLoad = at(0).current;
            if (!(p.starter.currentLimit > noLoad))
                throw std::invalid_argument("DqInductionMotor: current_limit = " + formatNumber(p.starter.currentLimit) +
                                            " A is not above the magnetising current " + formatNumber(noLoad) +
                                            " A: the motor cannot run within it");
            const double byCurrent = bisectSlip([&](double d) { return at(d).current; }, p.starter.currentLimit, breakdown);
            m_holdByCurrent = byCurrent < m_holdSlip;
            m_holdSlip = std::min(m_holdSlip, byCurrent);
        }
    }
}

Complex DqInductionMotor::flux(const SimTK::State& s, int k) const {
    const SimTK::Vector& z = m_forces.getZ(s);
    return {z[m_flux + 2 * k], z[m_flux + 2 * k + 1]};
}

std::string DqInductionMotor::electricalStateName(int k) const {
    static const char* const kFlux[] = {"psi_s_alpha", "psi_s_beta", "psi_r1_alpha", "psi_r1_beta",
                                        "psi_r2_alpha", "psi_r2_beta"};
    return kFlux[k];
}

std::string DqInductionMotor::supplyDescription() const {
    return "S_k = " + formatNumber(m_params.shortCircuitPower / 1e6, 4) + " MVA, X/R = " +
           formatNumber(m_params.sourceXR, 3);
}

int DqInductionMotor::firstFluxIndex(const SimTK::State& s) const {
    return int(s.getZStart(m_forces.getMySubsystemIndex())) + int(m_flux);
}

Complex DqInductionMotor::getStatorFlux(const SimTK::State& s) const { return flux(s, 0); }

Complex DqInductionMotor::getRotorFlux(const SimTK::State& s, int cage) const { return flux(s, 1 + cage); }

double DqInductionMotor::supplyAngle(const SimTK::State& s) const {
    if (isConverter() && !isStarterFinished(s)) return m_forces.getZ(s)[m_flux + 2 + 2 * m_nr];
    const double ws = 2 * M_PI * m_params.frequency;
    const bool delta = m_params.starter.kind == StarterParams::Kind::StarDelta && getStarterStep(s) > 0;
    return ws * s.getTime() + (delta ? m_params.deltaPhaseShift : 0.0);
}

double DqInductionMotor::calcSupplyFrequency(const SimTK::State& s) const {
    if (!isConverter() || isStarterFinished(s)) return 1;
    return std::min(1.0, std::max(0.0, m_forces.getZ(s)[m_flux + 3 + 2 * m_nr]));
}

double DqInductionMotor::calcRotorResistanceRatio(const SimTK::State& s) const {
    return m_starter.supply(s.getTime(), getStarterStep(s), isStarterFinished(s)).resistance;
}

double DqInductionMotor::converterLimitFrequency(const SimTK::State& s) const {
    const double ws = 2 * M_PI * m_params.frequency;
    return (m_params.polePairs * pinSpeed(s, m_shaft) + m_holdSlip) / ws;
}

DqInductionMotor::Electrical DqInductionMotor::calcElectrical(const SimTK::State& s) const {
    const DqInductionMotorParams& p = m_params;
    Electrical el;
    const int n = 1 + m_nr;
    Complex psi[3];
    for (int k = 0; k < n; ++k) psi[k] = flux(s, k);
    const double wr = p.polePairs * pinSpeed(s, m_shaft);
    const SupplyState sup = m_starter.supply(s.getTime(), getStarterStep(s), isStarterFinished(s));
    el.r = sup.resistance;
    el.f = calcSupplyFrequency(s);
    el.u = isConverter() ? p.voltageBoost + (1 - p.voltageBoost) * el.f : sup.voltage * std::sqrt(sup.connection);
    el.open = isStatorOpen(s) || !isOn(s);
    const double R[3] = {p.statorResistance, el.r * p.rotorResistance, p.rotorResistance2};
    if (el.open) {
        el.current[0] = 0;
        for (int k = 0; k < m_nr; ++k) {
            el.current[1 + k] = 0;
            for (int j = 0; j < m_nr; ++j) el.current[1 + k] += m_Grr[k][j] * psi[1 + j];
        }
    } else {
        for (int k = 0; k < n; ++k) {
            el.current[k] = 0;
            for (int j = 0; j < n; ++j) el.current[k] += m_G[k][j] * psi[j];
        }
    }
    for (int k = 1; k < n; ++k) el.fluxRate[k] = -R[k] * el.current[k] + Complex(0, wr) * psi[k];
    if (el.open) {
        // ψ_s = Lm·Σ i_r with i_r = Γ_rr·ψ_r.
        el.fluxRate[0] = 0;
        for (int k = 0; k < m_nr; ++k)
            for (int j = 0; j < m_nr; ++j) el.fluxRate[0] += p.mainInductance * m_Grr[k][j] * el.fluxRate[1 + j];
        el.winding = el.fluxRate[0];
        el.emf = 0;
        return el;
    }
    el.emf = el.u * std::polar(std::sqrt(2.0) * p.phaseVoltage, supplyAngle(s));
    const double u2 = isConverter() ? 0.0 : el.u * el.u;
    Complex rotorPart = 0;
    for (int k = 1; k < n; ++k) rotorPart += m_G[0][k] * el.fluxRate[k];
    el.fluxRate[0] = (el.emf - (p.statorResistance + u2 * m_Rk) * el.current[0] - u2 * m_Lk * rotorPart) /
                     (1 + u2 * m_Lk * m_G[0][0]);
    el.winding = el.fluxRate[0] + p.statorResistance * el.current[0];
    return el;
}

Complex DqInductionMotor::calcStatorCurrent(const SimTK::State& s) const { return calcElectrical(s).current[0]; }

Complex DqInductionMotor::calcRotorCurrent(const SimTK::State& s, int cage) const {
    return calcElectrical(s).current[1 + cage];
}

Complex DqInductionMotor::calcSupplyVoltage(double t) const {
    return std::polar(std::sqrt(2.0) * m_params.phaseVoltage, 2 * M_PI * m_params.frequency * t);
}

double DqInductionMotor::calcVoltageFactor(const SimTK::State& s) const {
    // Star–delta's torque factor 1/3 (Starter) is u² on the windings.
    if (isConverter()) return m_params.voltageBoost + (1 - m_params.voltageBoost) * calcSupplyFrequency(s);
    const SupplyState u = m_starter.supply(s.getTime(), getStarterStep(s), isStarterFinished(s));
    return u.voltage * std::sqrt(u.connection);
}

Complex DqInductionMotor::calcTerminalVoltage(const SimTK::State& s) const { return calcElectrical(s).winding; }

namespace {
/// The converter's grid current amplitude: its input at unit power factor.
double gridCurrent(double power, double emfAmplitude) { return std::max(power, 0.0) / (1.5 * emfAmplitude); }
}  // namespace

double DqInductionMotor::calcLineCurrent(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    if (el.open) return 0;
    if (isConverter()) {
        const double P = 1.5 * std::real(el.winding * std::conj(el.current[0]));
        return gridCurrent(P, std::sqrt(2.0) * m_params.phaseVoltage) / std::sqrt(2.0);
    }
    const double phase = std::abs(el.current[0]) / std::sqrt(2.0);
    const bool delta = m_params.starter.kind == StarterParams::Kind::StarDelta && getStarterStep(s) > 0;
    return delta ? std::sqrt(3.0) * phase : phase;
}

double DqInductionMotor::calcVoltageDip(const SimTK::State& s) const {
    if (!(m_Rk > 0)) return 0;
    const Electrical el = calcElectrical(s);
    if (el.open) return 0;
    const double e = std::sqrt(2.0) * m_params.phaseVoltage;
    if (isConverter()) {
        const double P = 1.5 * std::real(el.winding * std::conj(el.current[0]));
        const Complex Zk(m_Rk, 2 * M_PI * m_params.frequency * m_Lk);
        return 1 - std::abs(1.0 - Zk * gridCurrent(P, e) / e);
    }
    return 1 - std::abs(el.winding / el.u) / e;
}

double DqInductionMotor::getPeakVoltageDip(const SimTK::State& s) const {
    return SimTK::Value<double>::downcast(m_forces.getDiscreteVariable(s, m_dipIndex));
}

double DqInductionMotor::keepPeakVoltageDip(SimTK::State& s, double dip) const {
    double& kept = SimTK::Value<double>::updDowncast(m_forces.updDiscreteVariable(s, m_dipIndex));
    if (!(dip > kept)) return 0;
    kept = dip;
    return 0;  // a record, not a consistency condition: no restart
}

bool DqInductionMotor::isStatorOpen(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_openIndex));
}

bool DqInductionMotor::isOn(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_onIndex));
}

void DqInductionMotor::setOn(SimTK::State& s, bool on) const {
    if (!on && isOn(s) && !isStatorOpen(s)) openStatorFluxes(s);
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_onIndex)) = on;
}

void DqInductionMotor::setStatorOpen(SimTK::State& s, bool open) const {
    if (open && !isStatorOpen(s) && isOn(s)) openStatorFluxes(s);
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_openIndex)) = open;
}

void DqInductionMotor::openStatorFluxes(SimTK::State& s) const {
    // i_s → 0 with the rotor's flux linkages continuous: ψ_s = Lm·Σ i_r.
    Complex statorFlux = 0;
    for (int k = 0; k < m_nr; ++k)
        for (int j = 0; j < m_nr; ++j) statorFlux += m_params.mainInductance * m_Grr[k][j] * flux(s, 1 + j);
    SimTK::Vector& z = m_forces.updZ(s);
    z[m_flux] = statorFlux.real();
    z[m_flux + 1] = statorFlux.imag();
}

StartSequenceState DqInductionMotor::calcStarterProgress(const SimTK::State& s) const {
    if (!isConverter()) return m_starter.progress(s.getTime(), getStarterStep(s), isStarterFinished(s));
    const double f = calcSupplyFrequency(s);
    const bool held = !isStarterFinished(s) && f < 1 &&
                      (converterLimitFrequency(s) - f) / m_params.limitTimeConstant < m_starter.rampRate();
    return m_starter.progress(s.getTime(), getStarterStep(s), isStarterFinished(s), f, held, m_holdByCurrent);
}

void DqInductionMotor::finishStarter(SimTK::State& s) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_finishedIndex)) = true;
    setStarterStep(s, m_starter.switchCount());
    if (isConverter()) m_forces.updZ(s)[m_flux + 3 + 2 * m_nr] = 1;
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
    const int n = 1 + m_nr;
    const double ws = 2 * M_PI * p.frequency * calcSupplyFrequency(s);
    const double slipSpeed = ws - p.polePairs * pinSpeed(s, m_shaft);
    const double u = calcVoltageFactor(s), u2 = isConverter() ? 0.0 : u * u;
    const double r = calcRotorResistanceRatio(s);
    const double R[3] = {p.statorResistance + u2 * m_Rk, r * p.rotorResistance, p.rotorResistance2};
    // Z(jω)·I = [u·ê; 0; 0] in the synchronous frame (rotor rows at the slip speed).
    Eigen::MatrixXcd Z(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double w = i == 0 ? ws : slipSpeed;
            const double L = m_L[i][j] + (i == 0 && j == 0 ? u2 * m_Lk : 0.0);
            Z(i, j) = Complex(i == j ? R[i] : 0.0, w * L);
        }
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(n);
    rhs(0) = std::polar(u * std::sqrt(2.0) * p.phaseVoltage, supplyAngle(s));
    const Eigen::VectorXcd I = Z.fullPivLu().solve(rhs);
    SimTK::Vector& z = m_forces.updZ(s);
    for (int i = 0; i < n; ++i) {
        Complex psi = 0;
        for (int j = 0; j < n; ++j) psi += m_L[i][j] * I(j);
        z[m_flux + 2 * i] = psi.real();
        z[m_flux + 2 * i + 1] = psi.imag();
    }
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_openIndex)) = false;
}

double DqInductionMotor::calcTorque(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    if (el.open) return 0;
    return 1.5 * m_params.polePairs * std::imag(std::conj(getStatorFlux(s)) * el.current[0]);
}

double DqInductionMotor::calcInputPower(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    return 1.5 * std::real(el.winding * std::conj(el.current[0]));
}

double DqInductionMotor::calcCopperLoss(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    const double R[3] = {m_params.statorResistance, el.r * m_params.rotorResistance, m_params.rotorResistance2};
    double loss = 0;
    for (int k = 0; k <= m_nr; ++k) loss += R[k] * std::norm(el.current[k]);
    return 1.5 * loss;
}

double DqInductionMotor::calcFieldPower(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    double w = 0;
    for (int k = 0; k <= m_nr; ++k) w += std::real(std::conj(el.current[k]) * el.fluxRate[k]);
    return 1.5 * w;
}

void DqInductionMotor::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcTorque(s), mobilityForces);
}

void DqInductionMotor::realizeTopology(SimTK::State& s) const {
    SimTK::Vector z0(2 + 2 * m_nr + (isConverter() ? 2 : 0), 0.0);
    if (isConverter()) z0[3 + 2 * m_nr] = m_params.starter.initialFrequency;
    m_flux = m_forces.allocateZ(s, z0);
    // A switch changes the voltage, so the step invalidates Dynamics.
    m_stepIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<int>(0));
    m_finishedIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(false));
    m_openIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(false));
    m_onIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(true));
    // A record only (read by a probe): changing it invalidates nothing the motion needs.
    m_dipIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Report, new SimTK::Value<double>(0.0));
}

void DqInductionMotor::realizeAcceleration(const SimTK::State& s) const {
    const Electrical el = calcElectrical(s);
    SimTK::Vector& zdot = m_forces.updZDot(s);
    for (int k = 0; k <= m_nr; ++k) {
        zdot[m_flux + 2 * k] = el.fluxRate[k].real();
        zdot[m_flux + 2 * k + 1] = el.fluxRate[k].imag();
    }
    if (isConverter()) {
        const double ws = 2 * M_PI * m_params.frequency;
        double rate = 0;
        if (!isStarterFinished(s)) {
            const double f = m_forces.getZ(s)[m_flux + 3 + 2 * m_nr];
            rate = std::min(m_starter.rampRate(), (converterLimitFrequency(s) - f) / m_params.limitTimeConstant);
            if ((f >= 1 && rate > 0) || (f <= 0 && rate < 0)) rate = 0;
        }
        zdot[m_flux + 2 + 2 * m_nr] = ws * el.f;
        zdot[m_flux + 3 + 2 * m_nr] = rate;
    }
}

namespace {

using StarterKind = StarterParams::Kind;
const std::vector<StarterKind> kDqStarters = {StarterKind::DirectOnLine,       StarterKind::StarDelta,
                                              StarterKind::SoftStart,          StarterKind::FrequencyConverter,
                                              StarterKind::RotorResistance,    StarterKind::LiquidResistance};

// The keys each starter uses; giving one to another starter is an error.
const std::vector<std::pair<std::string, std::vector<std::string>>> kDqStarterKeys = {
    {"star_delta", {"open_transition_time", "delta_phase_shift"}},
    {"soft_start", {"initial_voltage"}},
    {"frequency_converter", {"initial_frequency", "torque_limit", "current_limit", "voltage_boost", "limit_time_constant"}},
    {"rotor_resistance", {"resistance_ratios"}},
    {"liquid_resistance", {"initial_resistance_ratio"}},
};

const std::vector<std::string> kCircuitKeys = {"stator_resistance", "rotor_resistance", "stator_leakage_inductance",
                                               "rotor_leakage_inductance", "main_inductance"};
const std::vector<std::string> kDatasheetKeys = {"rated_power",        "rated_speed",      "rated_voltage",
                                                 "rated_current",      "rated_power_factor", "rated_efficiency",
                                                 "locked_rotor_ratio", "breakdown_ratio",  "locked_rotor_current_ratio"};

bool fromDatasheet(const ElementSpec& e) { return e.has("rated_power"); }

MotorDatasheet datasheetOf(const ElementSpec& e) {
    MotorDatasheet d;
    d.ratedPower = e.number("rated_power");
    d.ratedSpeed = e.number("rated_speed");
    d.lineVoltage = e.number("rated_voltage");
    d.ratedCurrent = e.number("rated_current");
    d.powerFactor = e.number("rated_power_factor");
    d.efficiency = e.number("rated_efficiency");
    d.lockedRotorTorqueRatio = e.has("locked_rotor_ratio") ? e.number("locked_rotor_ratio") : 0;  // 0: not given
    d.breakdownTorqueRatio = e.number("breakdown_ratio");
    d.lockedRotorCurrentRatio = e.has("locked_rotor_current_ratio") ? e.number("locked_rotor_current_ratio") : 0;
    d.frequency = e.number("frequency");
    d.polePairs = e.has("pole_pairs") ? static_cast<int>(e.number("pole_pairs")) : 0;
    if (e.has("curve_speeds")) d.curveSpeeds = e.numbers("curve_speeds");
    if (e.has("curve_torques")) d.curveTorques = e.numbers("curve_torques");
    if (e.has("curve_currents")) d.curveCurrents = e.numbers("curve_currents");
    return d;
}

int cagesOf(const ElementSpec& e) {
    // A datasheet gets a double cage unless told: a single cage rarely
    // gives the catalogue's Ma and Mk together.
    if (!e.has("cage")) return fromDatasheet(e) ? 2 : 1;
    return e.text("cage") == "double" ? 2 : 1;
}

/// The fit of the element's datasheet; throws the located error of an
/// impossible datasheet or of a fit that misses a point by more than
/// fit_tolerance.
CageFitResult fitOf(const ElementSpec& e) {
    const MotorDatasheet d = datasheetOf(e);
    const DatasheetProblem problem = checkDatasheet(d);
    if (!problem.key.empty()) throw e.error(problem.key, problem.reason);
    const int cages = cagesOf(e);
    const CageFitResult fit = fitCageCircuitCached(d, cages);  // once per datasheet in the process
    const double tolerance = e.number("fit_tolerance");
    if (fit.worstResidual > tolerance) {
        const FitPoint& w = fit.points[fit.worstPoint];
        std::string all;
        for (const FitPoint& pt : fit.points)
            all += (all.empty() ? "" : ", ") + pt.name.substr(0, pt.name.find(" (")) + " " +
                   formatNumber(100 * pt.residual, 3) + " %";
        // One rotor circuit ties Ma and Ia to Mk and the rated point: say
        // what they are for this motor (the fit without them), so a
        // slip-ring motor's datasheet can leave them out or give these.
        std::string single;
        if (cages == 1 && (d.lockedRotorTorqueRatio > 0 || d.lockedRotorCurrentRatio > 0)) {
            MotorDatasheet ring = d;
            ring.lockedRotorTorqueRatio = ring.lockedRotorCurrentRatio = 0;
            if (checkDatasheet(ring).key.empty()) {
                const CageFitResult f1 = fitCageCircuitCached(ring, 1);
                if (f1.worstResidual <= tolerance) {
                    const CagePoint locked = cageSteadyState(f1.circuit, f1.phaseVoltage, d.frequency, f1.polePairs, 1.0);
                    single = "; one rotor circuit with this rated point and Mk has Ma/Mn = " +
                             formatNumber(locked.torque * d.ratedSpeed / d.ratedPower, 3) + " and Ia/In = " +
                             formatNumber(locked.current / d.ratedCurrent, 3) +
                             " (a slip-ring motor with its rings shorted: give these or leave "
                             "locked_rotor_ratio and locked_rotor_current_ratio out)";
                }
            }
            single += "; a cage motor with these starting values: use cage: double";
        }
        throw e.error(w.key, "no " + std::string(cages == 1 ? "single" : "double") + "-cage circuit fits this datasheet within fit_tolerance " +
                                 formatNumber(tolerance) + ": the best misses the " + w.name + " (" +
                                 formatNumber(w.data, 5) + " " + w.unit + ") by " + formatNumber(100 * w.residual, 3) +
                                 " % (residuals: " + all + ")" + single);
    }
    return fit;
}

void crossCheckDqInductionMotor(const ElementSpec& e) {
    const double p = e.number("pole_pairs");
    if (p != std::floor(p)) throw e.error("pole_pairs", "must be a whole number");
    const std::string starter = e.text("starter");
    for (const auto& [owner, keys] : kDqStarterKeys)
        for (const auto& k : keys)
            if (owner != starter && e.has(k))
                throw e.error(k, "not used with starter " + starter + " (only with starter " + owner + ")");
    const bool stepped = starter == "star_delta" || starter == "rotor_resistance";
    for (const char* k : {"switch_times", "switch_speeds"})
        if (!stepped && e.has(k))
            throw e.error(k, "not used with starter " + starter + " (only with star_delta and rotor_resistance)");
    if (e.has("switch_times") && e.has("switch_speeds"))
        throw e.error("switch_speeds", "give switch_times or switch_speeds, not both");
    // The switches by time (switch_times) or by shaft speed (switch_speeds).
    const std::size_t switches = e.numbers("switch_times").size() + e.numbers("switch_speeds").size();
    const char* switchKey = e.has("switch_speeds") ? "switch_speeds" : "switch_times";
    if (e.has("switch_speeds") && e.number("open_transition_time") > 0)
        throw e.error("switch_speeds", "an open transition (open_transition_time > 0) switches by time only: give "
                                       "switch_times, or a closed transition");
    const bool ramped = starter == "soft_start" || starter == "frequency_converter" || starter == "liquid_resistance";
    if (!ramped && e.has("ramp_time"))
        throw e.error("ramp_time", "not used with starter " + starter +
                                       " (only with soft_start, frequency_converter and liquid_resistance)");
    if (starter == "star_delta" && switches != 1)
        throw e.error(e.has(switchKey) ? switchKey : "starter",
                      "star_delta switches once: give one switch_times or one switch_speeds item");
    if (starter == "rotor_resistance" && switches != e.numbers("resistance_ratios").size())
        throw e.error(e.has("resistance_ratios") ? "resistance_ratios" : "starter",
                      std::string("rotor_resistance needs one resistance_ratios item per ") + switchKey + " item");
    if (e.has("switch_speeds")) {
        const auto& v = e.numbers("switch_speeds");
        for (std::size_t i = 1; i < v.size(); ++i)
            if (!(v[i] > v[i - 1])) throw e.error("switch_speeds", "must increase from one switching to the next");
    }
    if (ramped && !(e.number("ramp_time") > 0))
        throw e.error(e.has("ramp_time") ? "ramp_time" : "starter",
                      "a ramp of zero length: " + starter + " needs ramp_time > 0");
    if (e.has("interruption_duration") != e.has("interruption_time"))
        throw e.error(e.has("interruption_time") ? "interruption_time" : "interruption_duration",
                      "a supply interruption needs both interruption_time and interruption_duration");
    if (e.has("source_x_r") && !e.has("short_circuit_power"))
        throw e.error("source_x_r", "the source's X/R needs its short_circuit_power");
    if (e.has("voltage_dip_limit") && !e.has("short_circuit_power"))
        throw e.error("voltage_dip_limit", "a stiff supply does not dip: give short_circuit_power");
    if (e.has("rotor_resistance_2") != e.has("rotor_leakage_inductance_2"))
        throw e.error(e.has("rotor_resistance_2") ? "rotor_resistance_2" : "rotor_leakage_inductance_2",
                      "the second cage needs both rotor_resistance_2 and rotor_leakage_inductance_2");
    if (e.has("rotor_resistance_2") && e.has("cage") && e.text("cage") == "single")
        throw e.error("cage", "single contradicts the second cage's rotor_resistance_2");
    // Circuit parameters or a datasheet, not both.
    const bool datasheet = fromDatasheet(e);
    for (const auto& k : datasheet ? kCircuitKeys : kDatasheetKeys)
        if (e.has(k))
            throw e.error(k, datasheet ? "a circuit parameter with a datasheet (rated_power): give one or the other"
                                       : "a datasheet value without rated_power: give the whole datasheet or the circuit");
    for (const auto& k : datasheet ? kDatasheetKeys : kCircuitKeys) {
        // A slip-ring motor's datasheet (cage: single) may leave out the
        // shorted-ring starting values: one rotor circuit ties them to Mk
        // and the rated point, and the fit reports what they are.
        const bool startingValue = k == "locked_rotor_ratio" || k == "locked_rotor_current_ratio";
        if (!e.has(k) && !(datasheet && startingValue && cagesOf(e) == 1))
            throw e.error(datasheet ? "rated_power" : "stator_resistance",
                          std::string(datasheet ? "a datasheet" : "the circuit") + " needs " + k +
                              (datasheet && startingValue ? " (a double cage's starting value; cage: single may omit it)" : ""));
    }
    if (datasheet) {
        if (e.has("phase_voltage")) throw e.error("phase_voltage", "with a datasheet the voltage is rated_voltage (line)");
        if (e.has("rotor_resistance_2")) throw e.error("rotor_resistance_2", "a circuit parameter with a datasheet");
        // A published curve: curve_speeds with their torques, currents or both.
        for (const char* k : {"curve_torques", "curve_currents"}) {
            if (e.has(k) && !e.has("curve_speeds")) throw e.error(k, "needs curve_speeds (the speeds of its points)");
            if (e.has(k) && e.numbers(k).size() != e.numbers("curve_speeds").size())
                throw e.error(k, std::string("give one ") + (k[6] == 't' ? "torque" : "current") +
                                     " per curve_speeds item (" + std::to_string(e.numbers("curve_speeds").size()) +
                                     ")");
        }
        if (e.has("curve_speeds") && !e.has("curve_torques") && !e.has("curve_currents"))
            throw e.error("curve_speeds", "give the curve's curve_torques, curve_currents or both");
        if (cagesOf(e) == 2 && (starter == "rotor_resistance" || starter == "liquid_resistance"))
            throw e.error("cage", "a " + starter + " starter needs a slip-ring rotor: cage: single");
        fitOf(e);
    } else {
        if (!e.has("phase_voltage")) throw e.error("stator_resistance", "the circuit needs phase_voltage");
        for (const char* k : {"cage", "fit_tolerance", "curve_speeds", "curve_torques", "curve_currents"})
            if (e.has(k)) throw e.error(k, "only with a datasheet (rated_power)");
    }
}

void buildDqInductionMotor(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    DqInductionMotorParams p;
    p.frequency = spec.number("frequency");
    const std::string starterName = spec.text("starter");
    if (fromDatasheet(spec)) {
        const CageFitResult fit = fitOf(spec);
        // The fit is the equivalent star; star_delta's windings are in delta:
        // on V_n each, with 3× the star's impedances.
        const double k = starterName == "star_delta" ? 3.0 : 1.0;
        p.phaseVoltage = starterName == "star_delta" ? spec.number("rated_voltage") : fit.phaseVoltage;
        p.statorResistance = k * fit.circuit.statorResistance;
        p.statorLeakage = k * fit.circuit.statorLeakage;
        p.mainInductance = k * fit.circuit.mainInductance;
        p.rotorResistance = k * fit.circuit.rotorResistances[0];
        p.rotorLeakage = k * fit.circuit.rotorLeakages[0];
        if (fit.circuit.rotorResistances.size() > 1) {
            p.rotorResistance2 = k * fit.circuit.rotorResistances[1];
            p.rotorLeakage2 = k * fit.circuit.rotorLeakages[1];
        }
        p.polePairs = fit.polePairs;
        p.fittedToDatasheet = true;
        const std::string per = starterName == "star_delta" ? " (per winding in delta)" : " (per phase of the equivalent star)";
        scene.addDerivedValue({spec.name + ".stator_resistance", p.statorResistance, "ohm", "fitted Rs" + per});
        scene.addDerivedValue({spec.name + ".stator_leakage_inductance", p.statorLeakage, "H", "fitted Lsσ" + per});
        scene.addDerivedValue({spec.name + ".main_inductance", p.mainInductance, "H", "fitted Lm" + per});
        const bool two = p.rotorResistance2 > 0;
        scene.addDerivedValue({spec.name + ".rotor_resistance", p.rotorResistance, "ohm",
                               std::string("fitted Rr'") + (two ? " of the starting (outer) cage" : "") + per});
        scene.addDerivedValue({spec.name + ".rotor_leakage_inductance", p.rotorLeakage, "H",
                               std::string("fitted Lrσ'") + (two ? " of the starting (outer) cage" : "") + per});
        if (two) {
            scene.addDerivedValue({spec.name + ".rotor_resistance_2", p.rotorResistance2, "ohm",
                                   "fitted Rr,2' of the running (inner) cage" + per});
            scene.addDerivedValue({spec.name + ".rotor_leakage_inductance_2", p.rotorLeakage2, "H",
                                   "fitted Lrσ,2' of the running (inner) cage" + per});
        }
        scene.addDerivedValue({spec.name + ".pole_pairs", double(p.polePairs), "1", "pole pairs"});
        scene.addDerivedValue({spec.name + ".phase_voltage", p.phaseVoltage, "V", "winding voltage" + per});
        if (!spec.has("locked_rotor_ratio") || !spec.has("locked_rotor_current_ratio")) {
            // Not in the datasheet (a slip-ring motor): the fitted circuit's.
            const CagePoint locked = cageSteadyState(fit.circuit, fit.phaseVoltage, p.frequency, fit.polePairs, 1.0);
            const double Mn = spec.number("rated_power") / spec.number("rated_speed");
            scene.addDerivedValue({spec.name + ".circuit_locked_rotor_ratio", locked.torque / Mn, "1",
                                   "Ma/Mn of the fitted circuit (rotor short-circuited)"});
            scene.addDerivedValue({spec.name + ".circuit_locked_rotor_current_ratio",
                                   locked.current / spec.number("rated_current"), "1",
                                   "Ia/In of the fitted circuit (rotor short-circuited)"});
        }
        for (const FitPoint& pt : fit.points) {
            std::string id = pt.name.substr(0, pt.name.find(" ("));
            for (char& c : id)
                if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
            scene.addDerivedValue({spec.name + ".fit." + id, pt.residual, "1",
                                   "fit residual (circuit − datasheet)/datasheet of the " + pt.name + ": datasheet " +
                                       formatNumber(pt.data, 6) + " " + pt.unit + ", circuit " +
                                       formatNumber(pt.model, 6) + " " + pt.unit});
        }
    } else {
        p.statorResistance = spec.number("stator_resistance");
        p.rotorResistance = spec.number("rotor_resistance");
        p.statorLeakage = spec.number("stator_leakage_inductance");
        p.rotorLeakage = spec.number("rotor_leakage_inductance");
        p.rotorResistance2 = spec.number("rotor_resistance_2");
        p.rotorLeakage2 = spec.number("rotor_leakage_inductance_2");
        p.mainInductance = spec.number("main_inductance");
        p.polePairs = static_cast<int>(spec.number("pole_pairs"));
        p.phaseVoltage = spec.number("phase_voltage");
    }
    StarterParams& st = p.starter;
    for (auto k : kDqStarters)
        if (Starter::kindName(k) == starterName) st.kind = k;
    st.switchTimes = spec.numbers("switch_times");
    st.switchSpeeds = spec.numbers("switch_speeds");
    st.resistanceRatios = spec.numbers("resistance_ratios");
    st.initialVoltage = spec.number("initial_voltage");
    st.initialFrequency = spec.number("initial_frequency");
    st.initialResistanceRatio = spec.number("initial_resistance_ratio");
    st.rampTime = spec.number("ramp_time");
    st.torqueLimit = spec.number("torque_limit");
    st.currentLimit = spec.number("current_limit");
    p.openTransitionTime = spec.number("open_transition_time");
    p.deltaPhaseShift = spec.number("delta_phase_shift");
    p.voltageBoost = spec.number("voltage_boost");
    p.limitTimeConstant = spec.number("limit_time_constant");
    p.interruptionTime = spec.number("interruption_time");
    p.interruptionDuration = spec.number("interruption_duration");
    p.shortCircuitPower = spec.number("short_circuit_power");
    p.sourceXR = spec.number("source_x_r");
    p.voltageDipLimit = spec.number("voltage_dip_limit");
    // With an open transition delta closes t_o after star opens.
    StarterParams closing = st;
    if (st.kind == StarterKind::StarDelta)
        for (double& t : closing.switchTimes) t += p.openTransitionTime;
    DqInductionMotorParams built = p;
    built.starter = closing;
    auto* impl = new DqInductionMotor(scene.forces(), shaft->mobod, built);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    addStarterEvents(scene, spec.name, closing, impl);
    // A switch at a speed (as InductionMotor's; closed transitions only:
    // an open one is timed).
    addStarterSpeedSwitching(scene, spec.name, mobod, st.switchSpeeds, impl);
    // Stator open intervals: an open star–delta transition, a supply interruption.
    auto openInterval = [&](double from, double length, const std::string& what) {
        scene.addSwitchEvent({Scene::SwitchEvent::Kind::StarterStep, from, spec.name + " " + what + " opens",
                              [impl](SimTK::State& s) { impl->setStatorOpen(s, true); }});
        scene.addSwitchEvent({Scene::SwitchEvent::Kind::StarterStep, from + length, spec.name + " " + what + " closes",
                              [impl](SimTK::State& s) { impl->setStatorOpen(s, false); }});
    };
    if (st.kind == StarterKind::StarDelta && p.openTransitionTime > 0)
        openInterval(st.switchTimes.front(), p.openTransitionTime, "star-delta open transition");
    if (p.interruptionDuration > 0) openInterval(p.interruptionTime, p.interruptionDuration, "supply interruption");
    // Steady running with the field built up (not switched on unexcited).
    scene.addSteadyInitializer([impl](SimTK::State& s) { impl->setSteadyFluxes(s); });
    // The drive facet: on/off, switch-off, speed hint (synchronous), starter.
    scene.addDrive({spec.name, shaft->name, 2 * M_PI * p.frequency / p.polePairs, spec.number("switch_off_time"),
                    [impl](SimTK::State& s, bool on) { impl->setOn(s, on); }, Starter::kindName(st.kind)});
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl, mobod](const SimTK::State& s) { return impl->calcTorque(s) * pinSpeed(s, mobod); }});
    scene.addProbe({spec.name + ".current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return std::abs(impl->calcStatorCurrent(s)) / std::sqrt(2.0); }});
    if (st.kind != StarterKind::DirectOnLine && st.kind != StarterKind::RotorResistance &&
        st.kind != StarterKind::LiquidResistance)
        scene.addProbe({spec.name + ".voltage", "1", ProbeRole::Generic, SimTK::Stage::Time,
                        [impl](const SimTK::State& s) { return impl->calcVoltageFactor(s); }});
    if (st.kind == StarterKind::FrequencyConverter)
        scene.addProbe({spec.name + ".frequency", "1", ProbeRole::Generic, SimTK::Stage::Time,
                        [impl](const SimTK::State& s) { return impl->calcSupplyFrequency(s); }});
    if (st.kind == StarterKind::RotorResistance || st.kind == StarterKind::LiquidResistance)
        scene.addProbe({spec.name + ".rotor_resistance_ratio", "1", ProbeRole::Generic, SimTK::Stage::Time,
                        [impl](const SimTK::State& s) { return impl->calcRotorResistanceRatio(s); }});
    const bool source = std::isfinite(p.shortCircuitPower);
    if (st.kind != StarterKind::DirectOnLine || source)
        scene.addProbe({spec.name + ".line_current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcLineCurrent(s); }});
    if (source) {
        scene.addProbe({spec.name + ".voltage_dip", "1", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcVoltageDip(s); },
                        "1 − |v|/|e| at the supply point (through the source impedance)"});
        scene.addProbe({spec.name + ".peak_voltage_dip", "1", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->getPeakVoltageDip(s); },
                        "largest voltage_dip over the accepted steps so far"});
        scene.addLaggedValue({spec.name + ".peak_voltage_dip", true,
                              [impl](const SimTK::State& s) { return impl->calcVoltageDip(s); },
                              [impl](SimTK::State& s, double dip) { return impl->keepPeakVoltageDip(s, dip); }});
        const double Z = 3 * p.phaseVoltage * p.phaseVoltage / p.shortCircuitPower;
        scene.addDerivedValue({spec.name + ".source_impedance", Z, "ohm",
                               "|Z_k| = 3·V²/S_k at the winding's rated voltage V"});
    }
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source, [impl](const SimTK::State& s) { return impl->calcInputPower(s); },
                         "electrical input of " + spec.name + " at its terminals"});
    scene.addEnergyFlow({spec.name + ".field", EnergyFlow::Kind::Source,
                         [impl](const SimTK::State& s) { return -impl->calcFieldPower(s); },
                         "magnetic field energy of " + spec.name + " released (negative: stored)"});
    // A wound rotor's starter (issue 29 item 6): the rotor circuit's loss
    // 1.5·r·Rr·|i_r|² splits in the ratio of its resistances, the winding's
    // Rr : the external (r − 1)·Rr; the starter's share is a flow of its own.
    if (st.kind == StarterKind::RotorResistance || st.kind == StarterKind::LiquidResistance) {
        const double Rr = p.rotorResistance;
        auto external = [impl, Rr](const SimTK::State& s) {
            return 1.5 * (impl->calcRotorResistanceRatio(s) - 1) * Rr * std::norm(impl->calcRotorCurrent(s, 0));
        };
        scene.addEnergyFlow({spec.name + ".copper_heat", EnergyFlow::Kind::Dissipation,
                             [impl, external](const SimTK::State& s) { return impl->calcCopperLoss(s) - external(s); },
                             "heat in the stator and rotor windings of " + spec.name +
                                 " (the starter's external rotor resistance: starter_heat)"});
        scene.addEnergyFlow({spec.name + ".starter_heat", EnergyFlow::Kind::Dissipation, external,
                             "heat in the starter's external rotor resistance of " + spec.name +
                                 ": 1.5·(r − 1)·Rr·|i_r|²"});
        scene.addProbe({spec.name + ".rotor_winding_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl, Rr](const SimTK::State& s) { return 1.5 * Rr * std::norm(impl->calcRotorCurrent(s, 0)); },
                        "heat rate in the rotor winding: 1.5·Rr·|i_r|²"});
        scene.addProbe({spec.name + ".starter_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics, external,
                        "heat rate in the starter's external rotor resistance: 1.5·(r − 1)·Rr·|i_r|²"});
    } else {
        scene.addEnergyFlow({spec.name + ".copper_heat", EnergyFlow::Kind::Dissipation,
                             [impl](const SimTK::State& s) { return impl->calcCopperLoss(s); },
                             "heat in the stator and rotor windings of " + spec.name});
    }
    if (st.kind == StarterKind::FrequencyConverter)
        scene.addDerivedValue({spec.name + ".hold_slip_speed", impl->holdSlipSpeed(), "rad/s",
                               "converter: electrical slip speed its limits hold (rated circuit, f = 1)"});
    scene.note("force " + spec.name + " (DqInductionMotor, " + Starter::kindName(st.kind) +
                   (p.rotorResistance2 > 0 ? ", double cage" : "") + (fromDatasheet(spec) ? ", fitted to its datasheet" : "") + ")",
               "drives body " + shaft->name);
}

}  // namespace

void registerDqInductionMotor(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "DqInductionMotor";
    s.doc = "Induction motor as a dynamic space-phasor (dq) model with stator and rotor flux states, single or double "
            "cage, from its circuit or fitted to its datasheet, with every starter, supply interruptions and a source "
            "impedance (Krause; Modelica MSL AIM_SquirrelCage).";
    std::vector<std::string> starters;
    for (StarterKind k : kDqStarters) starters.push_back(Starter::kindName(k));
    const double never = std::numeric_limits<double>::infinity();
    s.params = {
        P::body("body", "shaft the motor drives"),
        P::quantity("stator_resistance", "ohm", "circuit: Rs per phase").optional(0.0).above(0),
        P::quantity("rotor_resistance", "ohm", "circuit: Rr' per phase, referred to the stator (double cage: the "
                                               "starting cage's)").optional(0.0).above(0),
        P::quantity("stator_leakage_inductance", "H", "circuit: Lsσ per phase").optional(0.0).above(0),
        P::quantity("rotor_leakage_inductance", "H", "circuit: Lrσ' per phase, referred to the stator").optional(0.0).above(0),
        P::quantity("rotor_resistance_2", "ohm", "circuit, double cage: the second cage's Rr,2'").optional(0.0).above(0),
        P::quantity("rotor_leakage_inductance_2", "H", "circuit, double cage: the second cage's Lrσ,2'").optional(0.0).above(0),
        P::quantity("main_inductance", "H", "circuit: Lm per phase").optional(0.0).above(0),
        P::quantity("pole_pairs", "1", "p (datasheet: from rated_speed)").optional(2.0).atLeast(1).atMost(50),
        // At most 100 kV (the largest motors are 13.8 kV line): the coupled
        // electromechanical frequency grows with the voltage, and so does the
        // work; 1e9 V took 207 s for 0.05 s simulated (issue 26 item 7).
        P::quantity("phase_voltage", "V", "circuit: rms voltage on a phase winding (star_delta: on the winding in delta, "
                                          "the line voltage)").optional(0.0).above(0).atMost(1e5),
        P::quantity("frequency", "Hz", "supply frequency f").optional(50.0).above(0),
        P::quantity("rated_power", "W", "datasheet: rated shaft power P_n").optional(0.0).above(0),
        P::quantity("rated_speed", "rad/s", "datasheet: rated speed").optional(0.0).above(0),
        P::quantity("rated_voltage", "V", "datasheet: rated line voltage").optional(0.0).above(0),
        P::quantity("rated_current", "A", "datasheet: rated line current I_n").optional(0.0).above(0),
        P::quantity("rated_power_factor", "1", "datasheet: cos φ_n").optional(0.0).above(0).below(1),
        P::quantity("rated_efficiency", "1", "datasheet: η_n").optional(0.0).above(0).below(1),
        P::quantity("locked_rotor_ratio", "1", "datasheet: Ma/Mn (cage: single may omit it)").optional(0.0).above(0).atMost(10),
        P::quantity("breakdown_ratio", "1", "datasheet: Mk/Mn").optional(0.0).above(0).atMost(10),
        P::quantity("locked_rotor_current_ratio", "1", "datasheet: Ia/In (cage: single may omit it)").optional(0.0).above(1).atMost(20),
        P::quantityList("curve_speeds", "rad/s", 1, 50, "datasheet: speeds of a published torque or current curve").optional(0.0).atLeast(0),
        P::quantityList("curve_torques", "N*m", 1, 50, "datasheet: the published torques at curve_speeds").optional(0.0).above(0),
        P::quantityList("curve_currents", "A", 1, 50, "datasheet: the published line currents (rms) at curve_speeds")
            .optional(0.0)
            .above(0),
        P::choice("cage", {"single", "double"}, "datasheet: the circuit fitted (default double)").optional("double"),
        P::quantity("fit_tolerance", "1", "datasheet: largest relative residual of the fit accepted").optional(0.05).above(0),
        P::choice("starter", starters, "how the motor is started").optional("direct_on_line"),
        P::quantityList("switch_times", "s", 1, 20, "star_delta (one), rotor_resistance: switching times")
            .optional(0.0)
            .above(0),
        P::quantityList("switch_speeds", "rad/s", 1, 20,
                        "star_delta (one), rotor_resistance: switching shaft speeds (instead of switch_times)")
            .optional(0.0)
            .above(0),
        P::quantity("open_transition_time", "s", "star_delta: dead time with the stator open (0: closed transition)")
            .optional(0.0)
            .atLeast(0),
        P::quantity("delta_phase_shift", "rad", "star_delta: phase of the delta winding voltage against star's")
            .optional(M_PI / 6),
        P::quantity("initial_voltage", "1", "soft_start: initial voltage over rated").optional(0.3).above(0).atMost(1),
        P::quantity("ramp_time", "s", "soft_start, frequency_converter, liquid_resistance: ramp length").optional(0.0).atLeast(0),
        P::quantity("initial_frequency", "1", "frequency_converter: initial frequency over rated").optional(0.0).atLeast(0).below(1),
        P::quantity("voltage_boost", "1", "frequency_converter: voltage at zero frequency over rated (V/f boost)")
            .optional(0.0)
            .atLeast(0)
            .below(1),
        P::quantity("torque_limit", "N*m", "frequency_converter: torque limit (slip hold; default breakdown)").optional(never).above(0),
        P::quantity("current_limit", "A", "frequency_converter: current limit (slip hold; default none)").optional(never).above(0),
        P::quantity("limit_time_constant", "s", "frequency_converter: time constant of its limit controller")
            .optional(0.02)
            .above(0),
        P::quantityList("resistance_ratios", "1", 1, 20, "rotor_resistance: R/R_rotor of each step, decreasing")
            .optional(0.0)
            .above(1),
        P::quantity("initial_resistance_ratio", "1", "liquid_resistance: initial R/R_rotor").optional(10.0).atLeast(1),
        P::quantity("interruption_time", "s", "supply interruption: when the stator opens").optional(0.0).atLeast(0),
        P::quantity("interruption_duration", "s", "supply interruption: how long it stays open").optional(0.0).above(0),
        P::quantity("short_circuit_power", "W", "the source's short-circuit power S_k [VA] (default: stiff)").optional(never).above(0),
        P::quantity("source_x_r", "1", "the source's X/R").optional(10.0).above(0),
        P::quantity("voltage_dip_limit", "1", "largest voltage dip accepted at the supply point").optional(never).above(0).below(1),
        P::quantity("switch_off_time", "s", "supply switched off (stator opened) at this time (default never)")
            .optional(never)
            .atLeast(0),
    };
    s.crossCheck = crossCheckDqInductionMotor;
    registry.add({std::move(s), buildDqInductionMotor});
}

}  // namespace milldyn
