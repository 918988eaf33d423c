#include "plugins/motors/InductionMotor.h"

#include "plugins/motors/CageCircuitFit.h"
#include "plugins/motors/StarterEvents.h"
#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <utility>
#include <vector>
#include <stdexcept>
#include <string>

namespace milldyn {

InductionMotor::InductionMotor(const SimTK::GeneralForceSubsystem& forces,
                               const SimTK::MobilizedBody& shaft, const InductionMotorParams& p)
    : m_forces(forces), m_shaft(shaft), m_params(p), m_curve(p), m_starter(p.starter) {
    if (std::isnan(p.switchOffTime))
        throw std::invalid_argument("InductionMotor: switch_off_time is NaN");
    if (isConverter()) {
        m_holdSlipSpeed = calcHoldSlipSpeed(m_curve, p.starter.torqueLimit);
        if (std::isfinite(p.starter.currentLimit)) {
            const double currentHold = calcCurrentHoldSlipSpeed(m_curve, p.starter.currentLimit);
            m_holdByCurrent = currentHold < m_holdSlipSpeed;
            m_holdSlipSpeed = std::min(m_holdSlipSpeed, currentHold);
        }
    }
    m_ratedCurrent = m_curve.current(p.ratedSpeed);
    if (p.ratedEfficiency != 0) {
        if (!(p.ratedEfficiency > 0 && p.ratedEfficiency < 1))
            throw std::invalid_argument("InductionMotor: rated_efficiency must lie in (0, 1)");
        if (!(std::isfinite(p.noLoadLoss) && p.noLoadLoss >= 0))
            throw std::invalid_argument("InductionMotor: no_load_loss must be finite and >= 0");
        m_statorCopperRated = calcRatedStatorCopperLoss(p, p.ratedEfficiency, p.noLoadLoss);
        if (!(m_statorCopperRated > 0))
            throw std::invalid_argument("InductionMotor: rated_efficiency: " +
                                        describeRatedLosses(p, p.ratedEfficiency, p.noLoadLoss));
    }
}

double calcRatedStatorCopperLoss(const TorqueSpeedCurveParams& p, double ratedEfficiency, double noLoadLoss) {
    return p.ratedTorque * p.ratedSpeed / ratedEfficiency - p.ratedTorque * p.synchronousSpeed - noLoadLoss;
}

std::string describeRatedLosses(const TorqueSpeedCurveParams& p, double ratedEfficiency, double noLoadLoss) {
    const double Pn = p.ratedTorque * p.ratedSpeed, Pin = Pn / ratedEfficiency;
    const double Pag = p.ratedTorque * p.synchronousSpeed;
    return "no stator copper loss is left at the rated point: P_in,n = P_n/η_n = " + formatNumber(Pn) + " W / " +
           formatNumber(ratedEfficiency) + " = " + formatNumber(Pin) + " W, less the air-gap power Mn·ωc = " +
           formatNumber(Pag) + " W (rotor copper loss " + formatNumber(Pag - Pn) + " W) and the no-load loss " +
           formatNumber(noLoadLoss) + " W, leaves P_Cu1,n = " + formatNumber(Pin - Pag - noLoadLoss) +
           " W (must be > 0: the efficiency or the no-load loss is too high for this rated slip)";
}

namespace {

/// The slip speed on the stable branch (synchronous to breakdown) at which
/// an increasing function of the slip speed reaches `limit`, by bisection;
/// the breakdown slip speed if it stays below there, 0 if above at 0.
double bisectStableBranch(const TorqueSpeedCurve& curve, const std::function<double(double)>& valueAt, double limit) {
    using Law = TorqueSpeedCurveParams::Law;
    const TorqueSpeedCurveParams& p = curve.params();
    const double wc = p.synchronousSpeed;
    double slipSpeedBreakdown = wc;  // linear law: torque rises with slip all the way
    if (p.law == Law::Kloss || p.law == Law::KlossModified) {
        slipSpeedBreakdown = curve.breakdownSlip() * wc;
    } else if (!curve.pointSpeeds().empty()) {
        const auto& T = curve.pointTorques();
        const auto k = static_cast<std::size_t>(std::max_element(T.begin(), T.end()) - T.begin());
        slipSpeedBreakdown = wc - curve.pointSpeeds()[k];
    }
    if (!(valueAt(slipSpeedBreakdown) > limit)) return slipSpeedBreakdown;
    if (!(valueAt(0) < limit)) return 0;
    double lo = 0, hi = slipSpeedBreakdown;  // value(lo) < limit < value(hi)
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (valueAt(mid) < limit ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace

double calcHoldSlipSpeed(const TorqueSpeedCurve& curve, double torqueLimit) {
    const double wc = curve.params().synchronousSpeed;
    return bisectStableBranch(curve, [&](double slipSpeed) { return curve.torque(wc - slipSpeed); }, torqueLimit);
}

double calcCurrentHoldSlipSpeed(const TorqueSpeedCurve& curve, double currentLimit) {
    const double wc = curve.params().synchronousSpeed;
    if (!curve.hasCurrent())
        throw std::invalid_argument("InductionMotor: current_limit needs the motor's current data (rated_current, "
                                    "rated_power_factor and locked_rotor_current_ratio, or a table's curve_currents)");
    const double noLoad = curve.current(wc);
    if (!(currentLimit > noLoad))
        throw std::invalid_argument("InductionMotor: current_limit = " + formatNumber(currentLimit) +
                                    " A is not above the no-load (magnetising) current " + formatNumber(noLoad) +
                                    " A: the motor cannot run at all within it");
    return bisectStableBranch(curve, [&](double slipSpeed) { return curve.current(wc - slipSpeed); }, currentLimit);
}

double InductionMotor::torqueAtSpeed(double omega, const SupplyState& u) const {
    const double wc = m_params.synchronousSpeed;
    const double slipSpeed = u.frequency * wc - omega;
    const double M = u.connection * u.voltage * u.voltage * m_curve.torque(wc - slipSpeed / u.resistance);
    return std::max(-u.torqueLimit, std::min(u.torqueLimit, M));
}

double InductionMotor::currentAtSpeed(double omega, const SupplyState& u) const {
    const double wc = m_params.synchronousSpeed;
    const double slipSpeed = u.frequency * wc - omega;
    return u.connection * u.voltage * m_curve.current(wc - slipSpeed / u.resistance);
}

SupplyState InductionMotor::supply(const SimTK::State& state) const {
    SupplyState u = m_starter.supply(state.getTime(), getStarterStep(state), isStarterFinished(state));
    if (isConverter()) u.frequency = converterFrequency(state);
    return u;
}

double InductionMotor::converterFrequency(const SimTK::State& state) const {
    const SimTK::Vec3& r = SimTK::Value<SimTK::Vec3>::downcast(m_forces.getDiscreteVariable(state, m_rampIndex));
    const double wc = m_params.synchronousSpeed;
    const double fLimit = (m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)) + m_holdSlipSpeed) / wc;
    const double fRamp = r[0] > 0.5 ? 1.0 : m_starter.rampFrequency(state.getTime(), r[1], r[2]);
    return std::max(0.0, std::min(fRamp, fLimit));
}

bool InductionMotor::isRampHeld(const SimTK::State& state) const {
    if (!isConverter()) return false;
    const SimTK::Vec3& r = SimTK::Value<SimTK::Vec3>::downcast(m_forces.getDiscreteVariable(state, m_rampIndex));
    return r[0] > 0.5;
}

double InductionMotor::calcRampHold(const SimTK::State& state) const {
    if (!isConverter()) return 0;
    const SimTK::Vec3& r = SimTK::Value<SimTK::Vec3>::downcast(m_forces.getDiscreteVariable(state, m_rampIndex));
    const double wc = m_params.synchronousSpeed;
    const double fLimit = (m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)) + m_holdSlipSpeed) / wc;
    if (r[0] > 0.5) {
        const bool keepsUp = m_shaft.getOneUDot(state, SimTK::MobilizerUIndex(0)) >= m_starter.rampRate() * wc;
        return keepsUp || fLimit >= 1 ? 0.0 : 1.0;
    }
    return m_starter.rampFrequency(state.getTime(), r[1], r[2]) > fLimit ? 1.0 : 0.0;
}

double InductionMotor::setRampHold(SimTK::State& state, double held) const {
    if (!isConverter() || (held > 0.5) == isRampHeld(state)) return 0;
    // A release restarts the ramp from the frequency the hold has reached.
    const double f = converterFrequency(state);
    SimTK::Value<SimTK::Vec3>::updDowncast(m_forces.updDiscreteVariable(state, m_rampIndex)) =
        held > 0.5 ? SimTK::Vec3(1, f, state.getTime()) : SimTK::Vec3(0, f, state.getTime());
    return 1;
}

double InductionMotor::rotorSlipSpeed(double omega, const SupplyState& u) const {
    // f·ωc − ω, measured from where the torque is 0: for a linear law whose
    // printed zero ω0 = M00/b0 is not ωc that is r·(ω0 − ωc) further.
    const double wc = m_params.synchronousSpeed;
    return u.frequency * wc - omega + u.resistance * (m_curve.zeroTorqueSpeed() - wc);
}

double InductionMotor::airGapPowerAtSpeed(double omega, const SupplyState& u) const {
    const double wc = m_params.synchronousSpeed;
    return torqueAtSpeed(omega, u) * (u.frequency * wc + u.resistance * (m_curve.zeroTorqueSpeed() - wc));
}

double InductionMotor::calcRotorHeat(const SimTK::State& state) const {
    if (!isOn(state)) return 0;
    const double omega = m_shaft.getOneU(state, SimTK::MobilizerUIndex(0));
    const SupplyState u = supply(state);
    return torqueAtSpeed(omega, u) * rotorSlipSpeed(omega, u);
}

double InductionMotor::statorCopperLossAtSpeed(double omega, const SupplyState& u) const {
    if (!hasLosses()) return 0;
    const double wc = m_params.synchronousSpeed;
    const double slipSpeed = u.frequency * wc - omega;
    if (m_curve.hasCurrent()) {
        // The phase current over its rated value: k·V·I_nat is the line
        // current, and in star (k = 1/3) the phase current is √k of delta's.
        const double phase = u.voltage * m_curve.current(wc - slipSpeed / u.resistance) / m_ratedCurrent;
        return m_statorCopperRated * u.connection * phase * phase;
    }
    // No current data: I1 ≈ I2', so P_Cu1 ∝ the heat in the rotor's own resistance.
    const double rotorOwnHeat = torqueAtSpeed(omega, u) * rotorSlipSpeed(omega, u) / u.resistance;
    return m_statorCopperRated * rotorOwnHeat / (m_params.ratedTorque * (wc - m_params.ratedSpeed));
}

double InductionMotor::noLoadLossAt(const SupplyState& u) const {
    if (!hasLosses()) return 0;
    // Terminal voltage over rated: V (the flux ratio) times f under V/f.
    const double terminal = u.voltage * u.frequency;
    return m_params.noLoadLoss * u.connection * terminal * terminal;
}

double InductionMotor::electricalPowerAtSpeed(double omega, const SupplyState& u) const {
    return airGapPowerAtSpeed(omega, u) + statorCopperLossAtSpeed(omega, u) + noLoadLossAt(u);
}

double InductionMotor::calcStatorLoss(const SimTK::State& state) const {
    if (!isOn(state) || !hasLosses()) return 0;
    const SupplyState u = supply(state);
    return statorCopperLossAtSpeed(m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)), u) + noLoadLossAt(u);
}

double InductionMotor::calcElectricalPower(const SimTK::State& state) const {
    if (!isOn(state)) return 0;
    return electricalPowerAtSpeed(m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)), supply(state));
}

double InductionMotor::calcSlipSpeed(const SimTK::State& state) const {
    return supply(state).frequency * m_params.synchronousSpeed - m_shaft.getOneU(state, SimTK::MobilizerUIndex(0));
}

double InductionMotor::calcCurrent(const SimTK::State& state) const {
    if (!isOn(state)) return 0;
    return currentAtSpeed(m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)), supply(state));
}

StartSequenceState InductionMotor::calcStarterProgress(const SimTK::State& state) const {
    return m_starter.progress(state.getTime(), getStarterStep(state), isStarterFinished(state),
                              isConverter() ? converterFrequency(state) : 1.0, isRampHeld(state), m_holdByCurrent);
}

void InductionMotor::finishStarter(SimTK::State& state) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(state, m_finishedIndex)) = true;
    setStarterStep(state, m_starter.switchCount());
    // The converter's ramp at rated frequency (still held to its torque limit).
    SimTK::Value<SimTK::Vec3>::updDowncast(m_forces.updDiscreteVariable(state, m_rampIndex)) =
        SimTK::Vec3(0, 1, state.getTime());
}

bool InductionMotor::isStarterFinished(const SimTK::State& state) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(state, m_finishedIndex));
}

int InductionMotor::getStarterStep(const SimTK::State& state) const {
    return SimTK::Value<int>::downcast(m_forces.getDiscreteVariable(state, m_stepIndex));
}

void InductionMotor::setStarterStep(SimTK::State& state, int step) const {
    SimTK::Value<int>::updDowncast(m_forces.updDiscreteVariable(state, m_stepIndex)) = step;
}

bool InductionMotor::isOn(const SimTK::State& state) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(state, m_onIndex));
}

void InductionMotor::setOn(SimTK::State& state, bool on) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(state, m_onIndex)) = on;
}

double InductionMotor::polePairsOn(double supply) const {
    // The law knows only its synchronous speed: p from the supply.
    const double wc = m_params.synchronousSpeed;
    const double p = supply / wc;
    if (!(std::abs(p - std::round(p)) <= 0.02 * p) || std::round(p) < 1)
        throw std::invalid_argument("synchronous speed " + formatNumber(wc * 30 / SimTK::Pi) + " rpm is not " +
                                    formatNumber(supply / (2 * SimTK::Pi)) +
                                    " Hz over a whole number of pole pairs");
    return std::round(p);
}

double InductionMotor::calcTorque(const SimTK::State& state) const {
    if (!isOn(state)) return 0;
    return torqueAtSpeed(m_shaft.getOneU(state, SimTK::MobilizerUIndex(0)), supply(state));
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
    m_stepIndex = m_forces.allocateDiscreteVariable(state, SimTK::Stage::Dynamics, new SimTK::Value<int>(0));
    m_rampIndex = m_forces.allocateDiscreteVariable(
        state, SimTK::Stage::Dynamics, new SimTK::Value<SimTK::Vec3>(SimTK::Vec3(0, m_params.starter.initialFrequency, 0)));
    m_finishedIndex = m_forces.allocateDiscreteVariable(state, SimTK::Stage::Dynamics, new SimTK::Value<bool>(false));
}

namespace {

using Law = TorqueSpeedCurveParams::Law;
using StarterKind = StarterParams::Kind;

const std::vector<std::pair<std::string, Law>> kLaws = {
    {"kloss", Law::Kloss}, {"linear", Law::Linear}, {"catalogue", Law::Catalogue}, {"table", Law::Table},
    {"kloss_modified", Law::KlossModified}};
const std::vector<StarterKind> kStarters = {StarterKind::DirectOnLine,       StarterKind::StarDelta,
                                            StarterKind::SoftStart,          StarterKind::FrequencyConverter,
                                            StarterKind::RotorResistance,    StarterKind::LiquidResistance};

Law lawOf(const std::string& word) {
    for (const auto& [name, law] : kLaws)
        if (name == word) return law;
    return Law::Kloss;
}

StarterKind starterOf(const std::string& word) {
    for (StarterKind k : kStarters)
        if (Starter::kindName(k) == word) return k;
    return StarterKind::DirectOnLine;
}

// The keys only some laws or starters use: giving one to another is an error
// (the linear law's printed M00/b0 stay allowed with any law, as before:
// the burr-mill files carry them for a --set law=linear).
const std::map<std::string, std::vector<std::string>> kLawKeys = {
    {"catalogue", {"locked_rotor_ratio", "pull_up_ratio", "pull_up_speed", "breakdown_speed"}},
    {"kloss_modified", {"locked_rotor_ratio"}},
    {"table", {"curve_speeds", "curve_torques", "curve_currents"}},
};
const std::map<std::string, std::vector<std::string>> kStarterKeys = {
    {"star_delta", {"switch_times", "switch_speeds"}},
    {"soft_start", {"initial_voltage", "ramp_time"}},
    {"frequency_converter", {"initial_frequency", "ramp_time", "torque_limit", "current_limit"}},
    {"rotor_resistance", {"switch_times", "switch_speeds", "resistance_ratios"}},
    {"liquid_resistance", {"initial_resistance_ratio", "ramp_time"}},
};

void rejectKeysOfOthers(const ElementSpec& e, const std::string& chosenKey,
                        const std::map<std::string, std::vector<std::string>>& keysOf) {
    const std::string& chosen = e.text(chosenKey);
    for (const auto& [owner, keys] : keysOf) {
        if (owner == chosen) continue;
        for (const auto& k : keys) {
            const auto mine = keysOf.find(chosen);
            const bool alsoMine = mine != keysOf.end() &&
                                  std::find(mine->second.begin(), mine->second.end(), k) != mine->second.end();
            if (e.has(k) && !alsoMine)
                throw e.error(k, "not used with " + chosenKey + " " + chosen + " (only with " + chosenKey + " " + owner +
                                     ")");
        }
    }
}

std::string num(double v) { return formatNumber(v); }

void checkIncreasing(const ElementSpec& e, const std::string& key, const std::string& what) {
    const std::vector<double>& v = e.numbers(key);
    for (std::size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1]))
            throw e.error(key, what + " must increase strictly: item " + std::to_string(i + 1) + " (" + num(v[i]) +
                                   ") is not above item " + std::to_string(i) + " (" + num(v[i - 1]) + ")");
}

InductionMotorParams motorParamsOf(const ElementSpec& spec) {
    InductionMotorParams p;
    p.law = lawOf(spec.text("law"));
    p.ratedTorque = spec.number("rated_torque");
    p.ratedSpeed = spec.number("rated_speed");
    p.synchronousSpeed = spec.number("synchronous_speed");
    p.breakdownRatio = spec.number("breakdown_ratio");
    p.linearStallTorque = spec.number("linear_stall_torque");
    p.linearSlope = spec.number("linear_slope");
    p.lockedRotorRatio = spec.number("locked_rotor_ratio");
    p.pullUpRatio = spec.number("pull_up_ratio");
    p.pullUpSpeed = spec.number("pull_up_speed");
    p.breakdownSpeed = spec.number("breakdown_speed");
    p.tableSpeeds = spec.numbers("curve_speeds");
    p.tableTorques = spec.numbers("curve_torques");
    p.tableCurrents = spec.numbers("curve_currents");
    p.ratedCurrent = spec.number("rated_current");
    p.ratedPowerFactor = spec.number("rated_power_factor");
    p.lockedRotorCurrentRatio = spec.number("locked_rotor_current_ratio");
    p.switchOffTime = spec.number("switch_off_time");
    p.ratedEfficiency = spec.number("rated_efficiency");
    p.noLoadLoss = spec.number("no_load_loss");
    StarterParams& st = p.starter;
    st.kind = starterOf(spec.text("starter"));
    st.switchTimes = spec.numbers("switch_times");
    st.switchSpeeds = spec.numbers("switch_speeds");
    st.resistanceRatios = spec.numbers("resistance_ratios");
    st.initialVoltage = spec.number("initial_voltage");
    st.initialFrequency = spec.number("initial_frequency");
    st.initialResistanceRatio = spec.number("initial_resistance_ratio");
    st.rampTime = spec.number("ramp_time");
    st.torqueLimit = spec.number("torque_limit");
    st.currentLimit = spec.number("current_limit");

    return p;
}

void crossCheckInductionMotor(const ElementSpec& e) {
    const double wn = e.number("rated_speed"), wc = e.number("synchronous_speed");
    if (wn >= wc)
        throw e.error("rated_speed", "rated speed must be below the synchronous speed (" + std::to_string(wn) +
                                         " rad/s >= " + std::to_string(wc) + " rad/s)");
    if (e.has("linear_stall_torque") != e.has("linear_slope"))
        throw e.error(e.has("linear_slope") ? "linear_slope" : "linear_stall_torque",
                      "give both linear_stall_torque and linear_slope, or neither");
    rejectKeysOfOthers(e, "law", kLawKeys);
    rejectKeysOfOthers(e, "starter", kStarterKeys);
    const std::string law = e.text("law");
    const std::vector<std::string> currentKeys = {"rated_current", "rated_power_factor", "locked_rotor_current_ratio"};
    for (const auto& k : currentKeys) {
        if (!e.has(k)) continue;
        if (law == "table") throw e.error(k, "not used with law table (its currents are curve_currents)");
        for (const auto& other : currentKeys)
            if (!e.has(other))
                throw e.error(k, "the circle diagram of the current needs rated_current, rated_power_factor and "
                                 "locked_rotor_current_ratio together (" + other + " is missing)");
    }
    if (e.has("locked_rotor_current_ratio")) {
        try {
            CurrentCircle({(e.number("synchronous_speed") - e.number("rated_speed")) / e.number("synchronous_speed"),
                           e.number("rated_current"), e.number("rated_power_factor"),
                           e.number("locked_rotor_current_ratio")});
        } catch (const std::invalid_argument& x) {
            throw e.error("locked_rotor_current_ratio", x.what());
        }
    }
    if (law == "catalogue") {
        if (!e.has("locked_rotor_ratio")) throw e.error("law", "the catalogue law needs locked_rotor_ratio");
        const double lambda = e.number("breakdown_ratio");
        const double sn = (wc - wn) / wc;
        const double wk = e.has("breakdown_speed") ? e.number("breakdown_speed")
                                                   : wc * (1 - sn * (lambda + std::sqrt(lambda * lambda - 1)));
        if (!(wk < wn))
            throw e.error(e.has("breakdown_speed") ? "breakdown_speed" : "breakdown_ratio",
                          "the breakdown speed (" + num(wk) + " rad/s) must be below the rated speed (" + num(wn) +
                              " rad/s)");
        if (!(wk > 0))
            throw e.error("breakdown_ratio", "the Kloss breakdown slip of this ratio puts the breakdown speed at " +
                                                 num(wk) + " rad/s; give breakdown_speed");
        if (e.number("locked_rotor_ratio") > lambda)
            throw e.error("locked_rotor_ratio", "locked-rotor torque above the breakdown torque (" +
                                                    num(e.number("locked_rotor_ratio")) + " > " + num(lambda) + ")");
        if (e.has("pull_up_ratio") != e.has("pull_up_speed"))
            throw e.error(e.has("pull_up_ratio") ? "pull_up_ratio" : "pull_up_speed",
                          "give both pull_up_ratio and pull_up_speed, or neither");
        if (e.has("pull_up_speed")) {
            if (!(e.number("pull_up_speed") < wk))
                throw e.error("pull_up_speed", "the pull-up point must lie below the breakdown speed (" + num(wk) +
                                                   " rad/s)");
            if (e.number("pull_up_ratio") > std::min(lambda, e.number("locked_rotor_ratio")))
                throw e.error("pull_up_ratio", "the pull-up torque is the curve's minimum below breakdown: it "
                                               "cannot exceed the locked-rotor or breakdown ratio");
        }
    }
    if (law == "kloss_modified") {
        if (!e.has("locked_rotor_ratio"))
            throw e.error("law", "the kloss_modified law needs locked_rotor_ratio (the starting torque over rated)");
        try {
            fitModifiedKloss((wc - wn) / wc, e.number("breakdown_ratio"), e.number("locked_rotor_ratio"));
        } catch (const std::invalid_argument& x) {
            throw e.error("locked_rotor_ratio", x.what());
        }
    }
    if (law == "table") {
        if (!e.has("curve_speeds") || !e.has("curve_torques"))
            throw e.error("law", "the table law needs curve_speeds and curve_torques");
        checkIncreasing(e, "curve_speeds", "torque-speed points");
        const std::size_t n = e.numbers("curve_speeds").size();
        for (const char* k : {"curve_torques", "curve_currents"})
            if (e.has(k) && e.numbers(k).size() != n)
                throw e.error(k, "give one value per speed in curve_speeds (" + std::to_string(n) + "), got " +
                                     std::to_string(e.numbers(k).size()));
        if (e.numbers("curve_speeds").back() > wc)
            throw e.error("curve_speeds", "speeds must not exceed the synchronous speed (" + num(wc) + " rad/s)");
        // A motor drives below synchronous speed and has no torque at it
        // (no slip, no rotor current): the rotor heat M·(ωc − ω) is never
        // negative, and above ωc the curve generates (docs/elements/InductionMotor.md).
        const std::vector<double>& torques = e.numbers("curve_torques");
        for (std::size_t k = 0; k < torques.size(); ++k)
            if (torques[k] < 0)
                throw e.error("curve_torques", "item " + std::to_string(k + 1) + " is " + num(torques[k]) +
                                                   " N*m: torques below synchronous speed must be >= 0 N*m");
        if (e.numbers("curve_speeds").back() == wc && torques.back() != 0)
            throw e.error("curve_torques", "the last point is at synchronous speed, where the torque must be 0 N*m "
                                           "(got " + num(torques.back()) + " N*m): end the table there with 0, "
                                           "or below it (the point (synchronous_speed, 0) is then added)");
    }
    const std::string starter = e.text("starter");
    if (e.has("switch_times") && e.has("switch_speeds"))
        throw e.error("switch_speeds", "give switch_times or switch_speeds, not both");
    for (const char* k : {"switch_times", "switch_speeds"})
        if (e.has(k)) checkIncreasing(e, k, "switchings");
    const std::size_t switches = e.numbers("switch_times").size() + e.numbers("switch_speeds").size();
    if (starter == "star_delta" && switches != 1)
        throw e.error("starter", "star_delta switches once: give one switch_times or one switch_speeds item");
    if (starter == "rotor_resistance") {
        if (!e.has("resistance_ratios")) throw e.error("starter", "rotor_resistance needs resistance_ratios");
        if (switches != e.numbers("resistance_ratios").size())
            throw e.error("resistance_ratios", "give one switching per resistance step (" +
                                                   std::to_string(e.numbers("resistance_ratios").size()) +
                                                   " steps, " + std::to_string(switches) + " switchings)");
        const std::vector<double>& r = e.numbers("resistance_ratios");
        for (std::size_t i = 1; i < r.size(); ++i)
            if (!(r[i] < r[i - 1]))
                throw e.error("resistance_ratios", "resistance steps must decrease: item " + std::to_string(i + 1) +
                                                       " (" + num(r[i]) + ") is not below item " + std::to_string(i));
    }
    if ((starter == "soft_start" || starter == "frequency_converter" || starter == "liquid_resistance") &&
        !(e.number("ramp_time") > 0))
        throw e.error(e.has("ramp_time") ? "ramp_time" : "starter",
                      "a ramp of zero length: " + starter + " needs ramp_time > 0");
    if (e.has("rated_efficiency") != e.has("no_load_loss"))
        throw e.error(e.has("rated_efficiency") ? "rated_efficiency" : "no_load_loss",
                      "give rated_efficiency and no_load_loss together (the no-load test's loss splits the rated "
                      "losses into those that scale with the current and those that do not; state 0 W if unknown)");
    const InductionMotorParams p = motorParamsOf(e);
    if (e.has("rated_efficiency") && !(calcRatedStatorCopperLoss(p, p.ratedEfficiency, p.noLoadLoss) > 0))
        throw e.error("rated_efficiency", describeRatedLosses(p, p.ratedEfficiency, p.noLoadLoss));
    if (e.has("current_limit")) {
        if (!e.has("rated_current") && !e.has("curve_currents"))
            throw e.error("current_limit", "a current limit needs the motor's current data (rated_current, "
                                           "rated_power_factor and locked_rotor_current_ratio, or a table's "
                                           "curve_currents)");
        try {
            calcCurrentHoldSlipSpeed(TorqueSpeedCurve(p), p.starter.currentLimit);
        } catch (const std::invalid_argument& x) {
            const std::string why = x.what(), prefix = "InductionMotor: ";
            throw e.error("current_limit", why.rfind(prefix, 0) == 0 ? why.substr(prefix.size()) : why);
        }
    }
}

/// A static curve has no electrical transient: at switch-on, and at every
/// switching of a starter (star→delta, resistance steps), the dq machine of
/// the same data peaks above it. With the datasheet's current data and
/// efficiency, the dq machine fitted to the same data (double cage,
/// CageCircuitFit) estimates the full-voltage switch-on peak with the rotor
/// held for three cycles, for every starter: it is what a direct-on-line
/// start, an open-transition reclosure that finds the flux out of phase, or
/// a reclosure after an interruption can reach. The peak of a switch-on at a
/// voltage u·V_n is u² times it (the machine is linear in the voltage, its
/// torque quadratic): star (u = 1/√3) and a soft start's initial voltage.
/// Derived values only; the run's notes (MotorReports) say per starter what
/// the static curve leaves out.
void addSwitchOnPeakEstimate(const ElementSpec& spec, Scene& scene, const InductionMotor& motor) {
    const InductionMotorParams& p = motor.params();
    const TorqueSpeedCurve& c = motor.curve();
    if (p.law == TorqueSpeedCurveParams::Law::Linear) return;
    const double Mn = p.ratedTorque, wc = p.synchronousSpeed;
    double staticMax = 0;
    for (int i = 0; i <= 2000; ++i) staticMax = std::max(staticMax, c.torque(wc * i / 2000));
    scene.addDerivedValue({spec.name + ".static_curve_peak", staticMax, "N*m",
                           "largest torque of the static torque-speed curve (rated supply)"});
    if (!(p.ratedCurrent > 0 && p.ratedPowerFactor > 0 && p.lockedRotorCurrentRatio > 0 && p.ratedEfficiency > 0))
        return;  // no estimate: the run's notes say which data would give one
    // Per-unit torques do not depend on the voltage level: V_n such that
    // the data's input √3·V·I·cos φ is P_n/η; f from ωc with the nearest p at 50 Hz.
    MotorDatasheet d;
    d.ratedPower = Mn * p.ratedSpeed;
    d.ratedSpeed = p.ratedSpeed;
    d.ratedCurrent = p.ratedCurrent;
    d.powerFactor = p.ratedPowerFactor;
    d.efficiency = p.ratedEfficiency;
    d.lineVoltage = d.ratedPower / (p.ratedEfficiency * std::sqrt(3.0) * p.ratedCurrent * p.ratedPowerFactor);
    d.lockedRotorTorqueRatio = c.torque(0) / Mn;
    d.breakdownTorqueRatio = staticMax / Mn;
    d.lockedRotorCurrentRatio = p.lockedRotorCurrentRatio;
    d.polePairs = std::max(1, static_cast<int>(std::lround(2 * M_PI * 50 / wc)));
    d.frequency = d.polePairs * wc / (2 * M_PI);
    if (!checkDatasheet(d).key.empty()) return;
    const CageFitResult fit = fitCageCircuitCached(d, 2);  // once per datasheet in the process
    if (fit.worstResidual > 0.05) {
        scene.note("force " + spec.name + " switch-on peak",
                   "not estimated: no double-cage circuit fits its data within 5 %");
        return;
    }
    const double peak = cageSwitchOnPeakTorque(fit.circuit, fit.phaseVoltage, d.frequency, d.polePairs, 3.0);
    scene.addDerivedValue({spec.name + ".dq_switch_on_peak_estimate", peak, "N*m",
                           "switch-on peak air-gap torque at full voltage of the dq machine fitted to the same data "
                           "(double cage, CageCircuitFit), rotor held for the first 3 cycles: an estimate, not this "
                           "run's"});
    const StarterParams& st = p.starter;
    double u = 1;  // the voltage the starter switches on at, per unit
    if (st.kind == StarterParams::Kind::StarDelta) u = 1 / std::sqrt(3.0);
    if (st.kind == StarterParams::Kind::SoftStart) u = st.initialVoltage;
    if (u < 1)
        scene.addDerivedValue({spec.name + ".dq_starter_switch_on_peak_estimate", u * u * peak, "N*m",
                               "the same estimate at the starter's switch-on voltage " + formatNumber(u, 4) +
                                   "·V_n (× u²; " +
                                   (st.kind == StarterParams::Kind::StarDelta ? std::string("star")
                                                                              : std::string("soft start's initial "
                                                                                            "voltage")) +
                                   ")"});
}

void buildInductionMotor(const ElementSpec& spec, Scene& scene) {
    const SceneBody* shaft = scene.findBody(spec.text("body"));
    const InductionMotorParams p = motorParamsOf(spec);
    const StarterParams& st = p.starter;
    auto* impl = new InductionMotor(scene.forces(), shaft->mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);  // Simbody owns impl
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    // The drive facet: on/off, switch-off, speed hint (slightly below
    // synchronous: where every motor law has its stable branch), starter.
    scene.addDrive({spec.name, shaft->name, p.ratedSpeed, p.switchOffTime,
                    [impl](SimTK::State& s, bool on) { impl->setOn(s, on); }, Starter::kindName(st.kind)});
    addStarterEvents(scene, spec.name, st, impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    addStarterSpeedSwitching(scene, spec.name, mobod, st.switchSpeeds, impl);
    if (st.kind == StarterKind::FrequencyConverter) {
        // The ramp's hold at the torque limit, decided after each accepted step.
        scene.addLaggedValue({spec.name + ".converter_hold", true,
                              [impl](const SimTK::State& s) { return impl->calcRampHold(s); },
                              [impl](SimTK::State& s, double v) { return impl->setRampHold(s, v); }});
        scene.addProbe({spec.name + ".frequency", "1", ProbeRole::Generic, SimTK::Stage::Velocity,
                        [impl](const SimTK::State& s) { return impl->supply(s).frequency; }});
        const double wc = p.synchronousSpeed;
        scene.addDerivedValue({spec.name + ".hold_slip", impl->holdSlipSpeed() / wc, "1",
                               impl->holdsAtCurrentLimit()
                                   ? "converter: slip at which the ramp holds, natural current = current_limit"
                                   : "converter: slip at which the ramp holds, natural torque = min(torque_limit, "
                                     "breakdown)"});
        scene.addDerivedValue({spec.name + ".hold_torque", impl->torqueAtSpeed(wc - impl->holdSlipSpeed()), "N*m",
                               "converter: the torque the ramp holds at"});
        if (impl->curve().hasCurrent())
            scene.addDerivedValue({spec.name + ".hold_current", impl->curve().current(wc - impl->holdSlipSpeed()), "A",
                                   "converter: the line current the ramp holds at"});
    }
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcTorque(s); }});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl, mobod](const SimTK::State& s) { return impl->calcTorque(s) * pinSpeed(s, mobod); }});
    scene.addProbe({spec.name + ".rotor_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                    [impl](const SimTK::State& s) { return impl->calcRotorHeat(s); }});
    if (impl->curve().hasCurrent())
        scene.addProbe({spec.name + ".current", "A", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcCurrent(s); }});
    else
        scene.note("output " + spec.name + ".current",
                   "not available: the motor's data give no current (rated_current, rated_power_factor and "
                   "locked_rotor_current_ratio, or a table's curve_currents)");
    if (const auto& circle = impl->curve().currentCircle()) {
        scene.addDerivedValue({spec.name + ".no_load_current", circle->magnetisingCurrent(), "A",
                               "circle diagram: magnetising current Iμ (current at s = 0)"});
        scene.addDerivedValue({spec.name + ".circle_slip", circle->circleSlip(), "1",
                               "circle diagram: s_c = R2'/X_k fitted to I_N, cos φ_N, I_LR"});
        scene.addDerivedValue({spec.name + ".locked_rotor_power_factor", circle->lockedRotorPowerFactor(), "1",
                               "circle diagram: power factor at standstill"});
        scene.addDerivedValue({spec.name + ".circle_locked_rotor_torque_ratio", circle->calcLockedRotorTorqueRatio(), "1",
                               "circle diagram's own M(1)/Mn (constant R2'); the torque law's is locked_rotor_ratio"});
    }
    if (impl->hasLosses()) {
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source,
                             [impl](const SimTK::State& s) { return impl->calcElectricalPower(s); },
                             "electrical input of " + spec.name +
                                 ": air-gap power + stator copper loss + no-load loss (from rated_efficiency)"});
        scene.addEnergyFlow({spec.name + ".stator_heat", EnergyFlow::Kind::Dissipation,
                             [impl](const SimTK::State& s) { return impl->calcStatorLoss(s); },
                             "heat in the stator of " + spec.name +
                                 ": stator copper loss + no-load loss (iron, friction, windage)"});
        scene.addProbe({spec.name + ".electrical_power", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcElectricalPower(s); }});
        scene.addProbe({spec.name + ".stator_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->calcStatorLoss(s); }});
        const SupplyState rated;  // direct on line, rated voltage and frequency
        const double wn = p.ratedSpeed;
        scene.addDerivedValue({spec.name + ".rated_stator_copper_loss", impl->ratedStatorCopperLoss(), "W",
                               "P_Cu1,n = Mn·ωn/η_n − Mn·ωc − P_0"});
        scene.addDerivedValue({spec.name + ".rated_input_power", p.ratedTorque * wn / p.ratedEfficiency, "W",
                               "P_in,n = Mn·ωn/η_n"});
        scene.addDerivedValue({spec.name + ".rated_efficiency_model",
                               impl->torqueAtSpeed(wn, rated) * wn / impl->electricalPowerAtSpeed(wn, rated), "1",
                               "check: the model's M·ω/P_el at the rated speed on the natural curve (= rated_efficiency)"});
        if (!impl->curve().hasCurrent())
            scene.note("force " + spec.name + " stator copper loss",
                       "no current data: P_Cu1 scaled as the heat in the rotor's own resistance, "
                       "P_Cu1,n·(M·Δω/r)/(Mn·(ωc − ωn)) (magnetising current neglected, I1 ≈ I2')");
    } else {
        const double wc = p.synchronousSpeed;
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source,
                             [impl, wc](const SimTK::State& s) {
                                 return impl->calcTorque(s) * impl->supply(s).frequency * wc;
                             },
                             "air-gap power of " + spec.name +
                                 " (electrical input less stator losses, not modelled: no rated_efficiency)"});
        scene.note("output " + spec.name + ".electrical_power",
                   "not available: give rated_efficiency and no_load_loss for the electrical input and stator losses");
    }
    // A wound rotor's starter (rotor or liquid resistance, issue 29 item 6):
    // the rotor circuit's heat M·Δω_r = 3·I2²·r·R2 splits in the ratio of
    // its resistances, R2 : (r − 1)·R2 — the rotor winding's share 1/r, the
    // external resistance's (r − 1)/r at every instant.
    const bool woundRotor = st.kind == StarterKind::RotorResistance || st.kind == StarterKind::LiquidResistance;
    if (woundRotor) {
        auto winding = [impl](const SimTK::State& s) { return impl->calcRotorHeat(s) / impl->supply(s).resistance; };
        auto external = [impl](const SimTK::State& s) {
            return impl->calcRotorHeat(s) * (1 - 1 / impl->supply(s).resistance);
        };
        scene.addEnergyFlow({spec.name + ".rotor_heat", EnergyFlow::Kind::Dissipation, winding,
                             "heat in the rotor winding of " + spec.name +
                                 " (its own resistance R2: M·(f·ωc − ω)/r; the starter's share is starter_heat)"});
        scene.addEnergyFlow({spec.name + ".starter_heat", EnergyFlow::Kind::Dissipation, external,
                             "heat in the starter's external rotor resistance of " + spec.name +
                                 " ((r − 1)·R2: M·(f·ωc − ω)·(r − 1)/r)"});
        scene.addProbe({spec.name + ".rotor_winding_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics, winding,
                        "heat rate in the rotor winding (R2), rotor_loss/r"});
        scene.addProbe({spec.name + ".starter_loss", "W", ProbeRole::Generic, SimTK::Stage::Dynamics, external,
                        "heat rate in the starter's external rotor resistance, rotor_loss·(r − 1)/r"});
        scene.addProbe({spec.name + ".rotor_resistance_ratio", "1", ProbeRole::Generic, SimTK::Stage::Dynamics,
                        [impl](const SimTK::State& s) { return impl->supply(s).resistance; },
                        "r = (R2 + R_ext)/R2, the starter's rotor resistance over the rotor's own"});
    } else {
        scene.addEnergyFlow({spec.name + ".rotor_heat", EnergyFlow::Kind::Dissipation,
                             [impl](const SimTK::State& s) { return impl->calcRotorHeat(s); },
                             "heat in the rotor circuit of " + spec.name + ": M·(f·ωc − ω)"});
    }

    const TorqueSpeedCurve& c = impl->curve();
    scene.addDerivedValue({spec.name + ".rated_slip", c.ratedSlip(), "1", "sn = (ωc − ωn)/ωc"});
    // Every law: the papers print M00 and b0 of the working branch (seed 003 eq 4) whatever curve runs.
    scene.addDerivedValue({spec.name + ".linear_stall_torque", c.linearStallTorque(), "N*m",
                           "M00 of the linear law M = M00 − b0·ω (seed 003 eq 4 or as printed)"});
    scene.addDerivedValue({spec.name + ".linear_slope", c.linearSlope(), "N*m*s/rad", "b0 of the linear law"});
    if (p.law == Law::Kloss)
        scene.addDerivedValue({spec.name + ".breakdown_slip", c.breakdownSlip(), "1", "Kloss sk = sn·(λ + √(λ² − 1))"});
    if (p.law == Law::KlossModified) {
        scene.addDerivedValue({spec.name + ".breakdown_slip", c.breakdownSlip(), "1",
                               "modified Kloss sk, from M(sn) = Mn and M(1) = Mst"});
        scene.addDerivedValue({spec.name + ".stator_resistance_ratio", c.asymmetry(), "1",
                               "modified Kloss a = R1/R2', from M(sn) = Mn and M(1) = Mst"});
        scene.addDerivedValue({spec.name + ".locked_rotor_torque", c.torque(0), "N*m", "curve torque at standstill"});
    }
    if (!c.pointSpeeds().empty()) {
        // The monotone cubic's maximum lies on a data point (no overshoot).
        const auto& T = c.pointTorques();
        const std::size_t k = static_cast<std::size_t>(std::max_element(T.begin(), T.end()) - T.begin());
        scene.addDerivedValue({spec.name + ".locked_rotor_torque", c.torque(0), "N*m", "curve torque at standstill"});
        scene.addDerivedValue({spec.name + ".breakdown_torque", T[k], "N*m", "largest torque of the curve"});
        scene.addDerivedValue({spec.name + ".breakdown_speed", c.pointSpeeds()[k], "rad/s",
                               "speed of the largest torque"});
    }
    addSwitchOnPeakEstimate(spec, scene, *impl);
    scene.note("force " + spec.name + " (InductionMotor, " + spec.text("law") + ", " + Starter::kindName(st.kind) + ")",
               "drives body " + shaft->name);
}

}  // namespace

void registerInductionMotor(ElementRegistry& registry) {
    ElementSchema s;
    s.type = "InductionMotor";
    s.doc = "Asynchronous motor torque on a shaft: linear working branch (seed 003 eqs 3-4), Kloss curve, "
            "modified Kloss curve with a stated starting torque, catalogue points or a torque-speed table (monotone cubic); starters direct-on-line, star-delta, "
            "soft start, frequency converter, slip-ring rotor resistance steps or liquid resistance; optional "
            "switch-off time.";
    using P = ParamSchema;
    const double never = std::numeric_limits<double>::infinity();
    std::vector<std::string> laws, starters;
    for (const auto& l : kLaws) laws.push_back(l.first);
    for (StarterKind k : kStarters) starters.push_back(Starter::kindName(k));
    s.params = {
        P::body("body", "shaft the motor drives"),
        P::choice("law", laws, "torque-speed law").optional("kloss"),
        P::quantity("rated_torque", "N*m", "nameplate torque Mn").above(0),
        P::quantity("rated_speed", "rad/s", "nameplate speed ωn, below synchronous").above(0),
        P::quantity("synchronous_speed", "rad/s", "synchronous speed ωc").above(0),
        P::quantity("breakdown_ratio", "1", "Kloss, kloss_modified, catalogue: breakdown over rated torque λ")
            .optional(2.2).above(1).atMost(10),
        P::quantity("linear_stall_torque", "N*m", "linear law: printed M00 (0: eq 4)").optional(0.0).atLeast(0),
        P::quantity("linear_slope", "N*m*s/rad", "linear law: printed b0 (0: eq 4)").optional(0.0).atLeast(0),
        P::quantity("locked_rotor_ratio", "1", "catalogue, kloss_modified: locked-rotor (starting) over rated torque").optional(0.0).above(0).atMost(10),
        P::quantity("pull_up_ratio", "1", "catalogue: pull-up (minimum) over rated torque").optional(0.0).above(0).atMost(10),
        P::quantity("pull_up_speed", "rad/s", "catalogue: speed of the pull-up torque").optional(0.0).above(0),
        P::quantity("breakdown_speed", "rad/s", "catalogue: speed of the breakdown torque (default from Kloss sk)")
            .optional(0.0).above(0),
        P::quantityList("curve_speeds", "rad/s", 2, 200, "table: speeds, strictly increasing").optional(0.0).atLeast(0),
        P::quantityList("curve_torques", "N*m", 2, 200, "table: torques at curve_speeds").optional(0.0),
        P::quantityList("curve_currents", "A", 2, 200, "table: line currents at curve_speeds").optional(0.0).atLeast(0),
        P::quantity("rated_current", "A", "not table: nameplate line current I_N (circle diagram)").optional(0.0).above(0),
        P::quantity("rated_power_factor", "1", "not table: nameplate power factor cos φ_N").optional(0.0).above(0).below(1),
        P::quantity("locked_rotor_current_ratio", "1", "not table: I_LR/I_N").optional(0.0).above(1).atMost(20),
        P::choice("starter", starters, "how the motor is started").optional("direct_on_line"),
        P::quantityList("switch_times", "s", 1, 20, "star_delta, rotor_resistance: switching times").optional(0.0).above(0),
        P::quantityList("switch_speeds", "rad/s", 1, 20, "star_delta, rotor_resistance: switching shaft speeds")
            .optional(0.0)
            .above(0),
        P::quantityList("resistance_ratios", "1", 1, 20, "rotor_resistance: R/R_rotor of each step, decreasing")
            .optional(0.0)
            .above(1),
        P::quantity("initial_voltage", "1", "soft_start: initial voltage over rated").optional(0.3).above(0).atMost(1),
        P::quantity("initial_frequency", "1", "frequency_converter: initial frequency over rated")
            .optional(0.0)
            .atLeast(0)
            .below(1),
        P::quantity("initial_resistance_ratio", "1", "liquid_resistance: initial R/R_rotor").optional(10.0).atLeast(1),
        P::quantity("ramp_time", "s", "soft_start, frequency_converter, liquid_resistance: ramp length")
            .optional(0.0)
            .atLeast(0),
        P::quantity("torque_limit", "N*m", "frequency_converter: torque limit (default none)").optional(never).above(0),
        P::quantity("current_limit", "A", "frequency_converter: line current limit, needs current data (default none)")
            .optional(never)
            .above(0),
        P::quantity("rated_efficiency", "1", "rated efficiency P_n/P_in,n; with no_load_loss: electrical input and "
                                             "stator losses (default: none, input = air-gap power)")
            .optional(0.0)
            .above(0)
            .below(1),
        P::quantity("no_load_loss", "W", "with rated_efficiency: no-load loss P_0 at rated supply (iron, friction, "
                                         "windage; the no-load test)")
            .optional(0.0)
            .atLeast(0),
        P::quantity("switch_off_time", "s", "supply switched off at this time (default never)")
            .optional(never)
            .atLeast(0),
    };
    s.crossCheck = crossCheckInductionMotor;
    registry.add({std::move(s), buildInductionMotor});
}

}  // namespace milldyn
