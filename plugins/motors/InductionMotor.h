#pragma once
// InductionMotor: the torque of an asynchronous motor on its shaft as a
// function of shaft speed.

#include "plugins/motors/Starter.h"
#include "plugins/motors/TorqueSpeedCurve.h"
#include "plugins/scene/DriveCapabilities.h"

#include <Simbody.h>

#include <limits>
#include <string>

namespace milldyn {

/// Parameters of an InductionMotor: its natural torque–speed law
/// (TorqueSpeedCurveParams), its starter and a switch-off time. All SI.
struct InductionMotorParams : TorqueSpeedCurveParams {
    StarterParams starter;
    /// Rated efficiency η_n = P_n/P_in,n [-] in (0, 1); 0: not given (the
    /// motor's input is then its air-gap power, no stator-side losses).
    double ratedEfficiency = 0;
    /// No-load loss P_0 [W] at rated voltage and frequency (iron plus
    /// friction and windage, the no-load test's input less its stator
    /// copper loss), >= 0; required with ratedEfficiency.
    double noLoadLoss = 0;
    /// Time at which the supply is switched off [s]; +inf: never.
    double switchOffTime = std::numeric_limits<double>::infinity();
};

/// Frequency converter: the slip speed [rad/s] at which `curve`'s natural
/// torque reaches min(torqueLimit [N*m], its breakdown torque) on the
/// stable branch (between synchronous speed and breakdown), by bisection.
double calcHoldSlipSpeed(const TorqueSpeedCurve& curve, double torqueLimit);
/// Frequency converter: the slip speed [rad/s] at which `curve`'s natural
/// line current reaches currentLimit [A] on the stable branch (the
/// breakdown slip speed if it stays below), by the same bisection; at
/// constant V/f the current is a function of the slip speed alone. Throws
/// std::invalid_argument when the curve has no current or the limit is not
/// above the current at synchronous speed (the magnetising current).
double calcCurrentHoldSlipSpeed(const TorqueSpeedCurve& curve, double currentLimit);

/// Stator copper loss at the rated point [W]: P_Cu1,n = Mn·ωn/η_n − Mn·ωc − P_0
/// (rated efficiency η_n [-], no-load loss P_0 [W]); <= 0 means the data
/// leave none (refused).
double calcRatedStatorCopperLoss(const TorqueSpeedCurveParams& curve, double ratedEfficiency, double noLoadLoss);
/// Why the rated point leaves no stator copper loss, with its numbers.
std::string describeRatedLosses(const TorqueSpeedCurveParams& curve, double ratedEfficiency, double noLoadLoss);

/**
 * Drive torque of an induction motor on one pin-jointed shaft: a natural
 * torque–speed law (TorqueSpeedCurve: linear, Kloss, catalogue points or a
 * table) under the supply state of its Starter.
 *
 * <pre>
 *   supply (Starter): voltage V (over rated), frequency f (over rated, V/f
 *   constant), rotor resistance ratio r = R/R_rotor, connection factor k (1/3 in star)
 *   slip speed      Δω = f·ωc − ω
 *   equivalent speed on the natural curve  ω_eq = ωc − Δω/r
 *   M(ω, t) = k·V²·M_nat(ω_eq),  clipped to |M| <= M_lim (converter)
 *   I(ω, t) = k·V·I_nat(ω_eq)    (line current; table law with currents)
 * </pre>
 * The torque depends on the slip speed alone at constant V/f (the stator
 * resistance neglected, as in the Kloss law), so a converter shifts the
 * curve by ωc·(1 − f); torque at slip s with rotor resistance r·R_rotor is
 * the natural torque at slip s/r (the rotor circuit sees R_rotor/s), so
 * for Kloss sk ∝ R with the breakdown torque unchanged.
 *
 * Power: the air-gap power P_ag = M·f·ωc crosses to the rotor; the rotor
 * circuit (and its starting resistance) turns P_ag − M·ω = M·Δω into heat
 * (a dissipation "NAME.rotor_heat"), so a direct-on-line start of a pure
 * inertia J to ωc dissipates ½·J·ωc² in the rotor whatever the curve.
 * Every law has M·(ω0 − ω) >= 0 with M(ω0) = 0 (TorqueSpeedCurve), so the
 * heat is never negative. A linear law with printed M00, b0 has its zero at
 * ω0 = M00/b0, not ωc: its slip speed is counted from there,
 * Δω_r = Δω + r·(ω0 − ωc), P_ag = M·(ω + Δω_r), heat M·Δω_r = r·M²/(k·V²·b0).
 * Without a rated efficiency the air-gap power is the motor's input (an
 * EnergyFlow source). With one (η_n, and the no-load loss P_0) the
 * electrical input is the source and the stator-side losses a second
 * dissipation "NAME.stator_heat":
 * <pre>
 *   rated:   P_n = Mn·ωn,  P_in,n = P_n/η_n,  P_δn = Mn·ωc,
 *            P_Cu1,n = P_in,n − P_δn − P_0            (> 0, else refused)
 *   stator copper, with current data (circle diagram or a table's currents):
 *            P_Cu1 = P_Cu1,n·k·(V·I_nat(ω_eq)/I_n)²     (phase current squared:
 *            k = 1/3 in star, V the voltage; I_n the data's current at ωn)
 *   without current data (magnetising current neglected, I1 ≈ I2'):
 *            P_Cu1 = P_Cu1,n·(M·Δω/r)/(Mn·(ωc − ωn))   (the heat in the rotor's
 *            own resistance over its rated value: ∝ I2'², any slip)
 *   no-load: P_0·k·(V·f)²  (iron loss ∝ terminal voltage², as MSL's core loss
 *            with no hysteresis part: V² at rated f; f² under V/f; the friction
 *            and windage in P_0 scaled alike, an approximation)
 *   P_el = P_ag + P_Cu1 + P_0·k·(V·f)²,  all 0 when switched off
 * </pre>
 * The torque law is the shaft's torque, so the friction and windage
 * share of P_0 is booked on the input side: the model's efficiency at the
 * rated point is η_n exactly (derived value NAME.rated_efficiency_model).
 * Switched off: M = 0 (the builder schedules that as a Scene
 * switch event at switch_off_time). Starter steps are a discrete state:
 * switched at a time (a Scene switch event the integrator restarts at) or
 * at a speed (a kept value refreshed after each accepted step: the switch
 * lands at the end of the first step past the speed, and the integrator
 * restarts there).
 *
 * Frequency converter, torque limit (ramp hold): the converter never lets
 * the slip speed exceed Δω_h, the slip speed at which the natural torque
 * reaches min(M_lim, M_max) on the stable branch (M_max the curve's
 * breakdown torque; without a torque_limit the hold is at breakdown), and
 * its ramp generator pauses while it is so limited:
 * <pre>
 *   f_lim(ω) = (ω + Δω_h)/ωc                       (slip speed Δω_h: torque M_lim)
 *   ramping:  f = max(0, min(f_r + R·(t − t_r), 1, f_lim(ω))),  R = (1 − f0)/T
 *   held:     f = max(0, min(1, f_lim(ω)))          (the ramp paused; f follows the rotor)
 *   hold      when ramping and f_r + R·(t − t_r) > f_lim(ω)   (the ramp ran into the limit)
 *   release   when held and dω/dt >= R·ωc (the rotor would keep up with the
 *             ramp) or f_lim(ω) >= 1; the ramp restarts from the present
 *             frequency: f_r = f, t_r = t
 * </pre>
 * (f_r, t_r) = (f0, 0) at switch-on. Hold and release are a discrete state
 * checked after every accepted step (a Scene lagged value); f is
 * continuous across both, so the integrator restarts without a jump.
 * While held the slip speed is Δω_h and the torque exactly M_lim: a drive
 * at its torque limit accelerates an inertia J against a load Mc at
 * (M_lim − Mc)/J, and its slip never exceeds the breakdown slip (checked
 * by the validation case start_converter_torque_limit).
 *
 * Frequency converter, current limit: with current data a current_limit
 * I_lim gives a second hold slip speed, where the natural current
 * I_nat(ωc − Δω) reaches I_lim (calcCurrentHoldSlipSpeed; at constant
 * V/f the current depends on the slip speed alone); Δω_h is the smaller
 * of the two, so while held the current is I_lim and the torque the
 * natural torque at that slip speed, M(I_lim) (validation case
 * start_converter_current_limit).
 *
 * The shaft gets +M as a mobility force about its pin axis; the reaction on
 * the stator (ground) is not modelled. The linear branch reaches ≈ 28·Mn at
 * standstill for the MMP-50 motors: it is valid only near ωc, so a start
 * from rest should use Kloss, a catalogue curve or a table. Checked by
 * InductionMotorTest and StarterTest against the closed forms above, and by
 * the start oracle (validation/oracles/StartOracle.h).
 */
class InductionMotor : public SimTK::Force::Custom::Implementation,
                       public StaticTorqueSpeedCurve,
                       public SupplyFedDrive {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    InductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                   const InductionMotorParams& params);

    /// Natural torque (rated supply, DOL) at shaft speed ω [rad/s] [N*m].
    double torqueAtSpeed(double omega) const override { return m_curve.torque(omega); }
    /// SupplyFedDrive: p = supply/ω_c, refused unless within 2 % of a whole number.
    double polePairsOn(double supply) const override;
    double ratedSynchronousSpeed() const override { return m_params.synchronousSpeed; }
    /// Every speed of the law and of the starter.
    std::vector<std::string> supplyFrequencyKeys() const override {
        return {"synchronous_speed", "rated_speed", "pull_up_speed", "breakdown_speed", "curve_speeds", "switch_speeds"};
    }
    std::string whySupplyNotScalable() const override { return ""; }
    bool converterFed() const override { return isConverter(); }
    /// Torque at shaft speed ω [rad/s] under a supply state [N*m].
    double torqueAtSpeed(double omega, const SupplyState& supply) const;
    /// Line current at ω under a supply state [A] (NaN without current data).
    double currentAtSpeed(double omega, const SupplyState& supply) const;
    /// The supply in this state (time and starter step).
    SupplyState supply(const SimTK::State& state) const;
    /// Torque the motor applies in this state (0 when off) [N*m].
    double calcTorque(const SimTK::State& state) const;
    /// Slip speed f·ωc − ω in this state [rad/s].
    double calcSlipSpeed(const SimTK::State& state) const;
    /// Line current in this state (0 when off) [A].
    double calcCurrent(const SimTK::State& state) const;
    bool isOn(const SimTK::State& state) const;
    void setOn(SimTK::State& state, bool on) const;
    int getStarterStep(const SimTK::State& state) const;
    void setStarterStep(SimTK::State& state, int step) const;
    /// Frequency converter: slip speed Δω_h the ramp holds at [rad/s].
    double holdSlipSpeed() const { return m_holdSlipSpeed; }
    /// Frequency converter: whether Δω_h is the current limit's (not the torque limit's).
    bool holdsAtCurrentLimit() const { return m_holdByCurrent; }

    /// Whether the rated efficiency is given (stator-side losses modelled).
    bool hasLosses() const { return m_params.ratedEfficiency > 0; }
    /// Stator copper loss at the rated point P_Cu1,n [W] (0 without losses).
    double ratedStatorCopperLoss() const { return m_statorCopperRated; }
    /// Rotor slip speed f·ωc − ω + r·(ω0 − ωc) at ω [rad/s] under a supply
    /// [rad/s] (ω0 = curve().zeroTorqueSpeed(); ωc but for a printed linear law).
    double rotorSlipSpeed(double omega, const SupplyState& supply) const;
    /// Air-gap power M·(ω + rotorSlipSpeed) (M·f·ωc when ω0 = ωc) at ω [rad/s] under a supply [W].
    double airGapPowerAtSpeed(double omega, const SupplyState& supply) const;
    /// Rotor heat M·rotorSlipSpeed in this state (0 when off) [W], never negative.
    double calcRotorHeat(const SimTK::State& state) const;
    /// Stator copper loss P_Cu1 at ω under a supply [W] (0 without losses).
    double statorCopperLossAtSpeed(double omega, const SupplyState& supply) const;
    /// No-load (iron, friction and windage) loss under a supply [W].
    double noLoadLossAt(const SupplyState& supply) const;
    /// Electrical input P_ag + P_Cu1 + P_0,supply at ω under a supply [W].
    double electricalPowerAtSpeed(double omega, const SupplyState& supply) const;
    /// Stator-side losses (copper and no-load) in this state (0 when off) [W].
    double calcStatorLoss(const SimTK::State& state) const;
    /// Electrical input in this state (the air-gap power without losses; 0 when off) [W].
    double calcElectricalPower(const SimTK::State& state) const;
    /// Frequency converter: whether the ramp is held at the torque limit.
    bool isRampHeld(const SimTK::State& state) const;
    /// Frequency converter: the hold state (1 held, 0 ramping) the state
    /// (realized to Acceleration) asks for, by the rules above.
    double calcRampHold(const SimTK::State& state) const;
    /// Frequency converter: sets the hold state; a release restarts the
    /// ramp from the present frequency. Returns 1 if it changed, else 0.
    double setRampHold(SimTK::State& state, double held) const;

    /// Where the starter's sequence stands in this state (Starter::progress).
    StartSequenceState calcStarterProgress(const SimTK::State& state) const;
    /// Ends the starter's sequence in `state` for good (steady running): the
    /// supply is Starter::finalSupply from then on, whatever the time.
    void finishStarter(SimTK::State& state) const;
    bool isStarterFinished(const SimTK::State& state) const;

    /// Linear-law coefficients in use: M00 [N*m], b0 [N*m*s/rad].
    double linearStallTorque() const { return m_curve.linearStallTorque(); }
    double linearSlope() const { return m_curve.linearSlope(); }
    const InductionMotorParams& params() const { return m_params; }
    const TorqueSpeedCurve& curve() const { return m_curve; }
    const Starter& starter() const { return m_starter; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_shaft;
    InductionMotorParams m_params;
    TorqueSpeedCurve m_curve;
    Starter m_starter;
    double m_holdSlipSpeed = 0;
    bool m_holdByCurrent = false;
    double m_statorCopperRated = 0;  // P_Cu1,n [W]
    double m_ratedCurrent = 0;       // the data's current at ωn [A] (NaN without current)
    bool isConverter() const { return m_params.starter.kind == StarterParams::Kind::FrequencyConverter; }
    double converterFrequency(const SimTK::State& state) const;
    // Allocated once per system in realizeTopology().
    mutable SimTK::DiscreteVariableIndex m_onIndex;
    mutable SimTK::DiscreteVariableIndex m_stepIndex;
    mutable SimTK::DiscreteVariableIndex m_rampIndex;  // Vec3(held, f_r, t_r)
    mutable SimTK::DiscreteVariableIndex m_finishedIndex;  // bool: the starter's sequence ended (finishStarter)
};

}  // namespace milldyn
