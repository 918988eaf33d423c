#pragma once
// DqInductionMotor: an induction motor as a dynamic space-phasor (dq) model,
// with its stator and rotor flux linkages as states, single or double cage,
// from circuit parameters or fitted to a datasheet, with every starter,
// supply interruptions and a source impedance.

#include "plugins/motors/Starter.h"
#include "plugins/scene/DriveCapabilities.h"

#include <Simbody.h>

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace milldyn {

/// Parameters of a DqInductionMotor, per phase of the equivalent star (or of
/// the winding, star_delta), SI.
struct DqInductionMotorParams {
    double statorResistance = 0;   ///< Rs [ohm], > 0
    double rotorResistance = 0;    ///< Rr' [ohm], > 0 (referred to the stator; cage 1)
    double statorLeakage = 0;      ///< Lsσ [H], > 0
    double rotorLeakage = 0;       ///< Lrσ' [H], > 0 (cage 1)
    /// Double cage: the second cage's Rr,2' [ohm] and Lrσ,2' [H]; 0: single cage.
    double rotorResistance2 = 0, rotorLeakage2 = 0;
    double mainInductance = 0;     ///< Lm [H], > 0
    int polePairs = 1;             ///< p [-], >= 1
    /// The circuit was fitted to a datasheet at its rated supply (scaling
    /// frequency and phase_voltage then does not scale the fitted motor).
    bool fittedToDatasheet = false;
    double phaseVoltage = 0;       ///< V [V] rms phase voltage, > 0
    double frequency = 0;          ///< f [Hz] supply frequency, > 0
    /// Every starter of InductionMotor (Starter.h): star_delta and
    /// rotor_resistance switch by time or by shaft speed (an open
    /// star–delta transition by time only).
    StarterParams starter;
    /// star_delta: the open-transition dead time [s] (>= 0; 0: closed
    /// transition) and the phase of the delta's winding voltage against the
    /// star's [rad] (the line-to-line voltage leads the phase voltage by π/6).
    double openTransitionTime = 0, deltaPhaseShift = M_PI / 6;
    /// frequency_converter: voltage at zero frequency over rated [-] in
    /// [0, 1) (V/f with boost: u = b + (1 − b)·f), and the time constant of
    /// its slip (torque/current) limit controller [s] (> 0).
    double voltageBoost = 0, limitTimeConstant = 0.02;
    /// A supply interruption: the stator open from interruptionTime [s] for
    /// interruptionDuration [s] (0: none); the supply returns in phase with
    /// the grid, which ran on.
    double interruptionTime = 0, interruptionDuration = 0;
    /// The source: short-circuit power S_k [VA] at the motor's supply (+inf:
    /// stiff) and its X/R [-] (> 0).
    double shortCircuitPower = std::numeric_limits<double>::infinity(), sourceXR = 10;
    /// The largest supply voltage dip a start may cause [-] (+inf: none);
    /// a transient notes a start that exceeds it.
    double voltageDipLimit = std::numeric_limits<double>::infinity();
};

/**
 * Dynamic model of a squirrel-cage (single or double cage) or slip-ring
 * induction machine in space phasors (amplitude-invariant, stator-fixed
 * frame), the flux form of the classic two-axis model (Krause, Wasynczuk &
 * Sudhoff, "Analysis of Electric Machinery", ch. 6; Leonhard, "Control of
 * Electrical Drives", ch. 10; the machine of Modelica MSL's
 * AIM_SquirrelCage / IMC_DOL example), with one rotor circuit per cage:
 * <pre>
 *   e = √2·V·e^(jθ),  θ = ω_s·t (+ δ in delta after a star–delta switch),  ω_s = 2π f
 *   dψ_s/dt = v_s − Rs·i_s,   v_s = u·e − u²·(R_k·i_s + L_k·di_s/dt)    (through the source)
 *   dψ_r,k/dt = −r·Rr,k·i_r,k + j·p·ω·ψ_r,k                   (rotor at mechanical speed ω)
 *   [ψ_s; ψ_r,1; ψ_r,2] = L·[i_s; i_r,1; i_r,2],  L = [[Ls, Lm, Lm], [Lm, Lr1, Lm], [Lm, Lm, Lr2]]
 *   Ls = Lsσ + Lm,  Lr,k = Lrσ,k + Lm;   T = (3/2)·p·Im(conj(ψ_s)·i_s)   (on the shaft, + drives)
 * </pre>
 * The source (S_k, X/R at the rated winding voltage V): Z_k = 3·V²/S_k,
 * R_k = Z_k/√(1 + (X/R)²), L_k = (X/R)·R_k/ω_s; seen through the starter
 * it is u²·Z_k (star: the winding's V/√3, a third; soft start: the
 * fundamental's u), so di_s/dt is solved with the flux rates:
 * (1 + u²·L_k·Γ_ss)·dψ_s/dt = u·e − (Rs + u²R_k)·i_s − u²·L_k·Σ_k Γ_s,rk·dψ_r,k/dt,
 * Γ = L⁻¹. The voltage at the supply point is v_pcc = v_s/u; its dip is
 * 1 − |v_pcc|/|e| (NAME.voltage_dip, its largest value over every
 * accepted step NAME.peak_voltage_dip).
 *
 * Starters (u, r, θ from plugins/motors/Starter's supply):
 * <pre>
 *   direct on line    u = 1
 *   star–delta        u = 1/√3 in star, 1 in delta (V: the winding's voltage in delta), θ += δ in delta
 *                     (δ = π/6: the line-to-line voltage leads the phase voltage); with an
 *                     open transition the stator is open for t_o before delta closes
 *   soft start        u = V0 + (1 − V0)·min(t/T, 1)   (phase control, fundamental)
 *   rotor resistance  r = R/R_rotor of the step (single cage: resistance added to the slip rings)
 *   liquid resistance r = r0 + (1 − r0)·min(t/T, 1)
 *   converter         θ' = ω_s·f,  u = b + (1 − b)·f           (V/f with boost b, fundamental)
 *                     f' = min(R, (f_lim(ω) − f)/τ) (0 once f >= 1),  f_lim = (p·ω + Δω_h)/ω_s
 * </pre>
 * The converter's Δω_h is the electrical slip speed at which the rated
 * circuit's (f = 1) torque reaches the torque limit, or its current the
 * current limit (the smaller), on the stable branch: the frequency never
 * runs ahead of the rotor by more, and the ramp pauses (resumes from the
 * present f) while it is held; its input is on the grid at unit power
 * factor (i_grid ∥ e, |i_grid| = P/(1.5·|e|)), so its dip is
 * 1 − |1 − Z_k·i_grid/e|.
 *
 * Stator open (an open star–delta transition, a supply interruption, the
 * motor switched off: switch_off_time, a coast-down's switch at t = 0): i_s = 0,
 * so ψ_s jumps to Lm·Σi_r at the opening (the rotor's flux linkages are
 * continuous; the stator's field energy goes into the switch's arc) and the
 * rotor currents decay with the rotor's time constant while the flux turns
 * with the rotor: dψ_r/dt = −R·Γ_rr·ψ_r + j·p·ω·ψ_r, ψ_s = Lm·Σ_k (Γ_rr·ψ_r)_k.
 * The supply returns at θ (the grid ran on): the reclosure is out of phase
 * with the residual flux by (ω_s − p·ω)·t_o plus δ.
 *
 * The flux components are continuous states (Z), zero at t = 0 (switched
 * on unexcited); the converter adds θ and f. In steady state at slip s
 * the model is the T equivalent circuit (CageCircuitFit's
 * cageSteadyState). Validated against validation/oracles/DqMachineOracle
 * (currents in a synchronously rotating frame, fixed-step RK4) over whole
 * starts, and held at a slip against the equivalent circuit (start_dq_*).
 *
 * Energy: the terminal power (3/2)·Re(v_s·conj(i_s)) is the motor's input
 * (an EnergyFlow source); the copper losses (3/2)·(Rs|i_s|² + Σ r·Rr,k|i_r,k|²)
 * are heat; the magnetic field's energy changes at (3/2)·Re(Σ conj(i)·dψ/dt),
 * reported as a source "NAME.field" of −dW/dt. The field energy lost in an
 * opening's arc is not a flow (the balance is off by it). Iron, friction
 * and stray losses, saturation and skin effect are not modelled.
 */
class DqInductionMotor : public SimTK::Force::Custom::Implementation,
                         public ElectricalStates,
                         public SupplyVoltageDip,
                         public SupplyFedDrive {
public:
    /// SupplyFedDrive: its own pole pairs and supply frequency.
    double polePairsOn(double) const override { return m_params.polePairs; }
    double ratedSynchronousSpeed() const override {
        return 2 * SimTK::Pi * m_params.frequency / m_params.polePairs;
    }
    std::vector<std::string> supplyFrequencyKeys() const override { return {"frequency", "phase_voltage"}; }
    std::string whySupplyNotScalable() const override {
        return m_params.fittedToDatasheet ? "its circuit is fitted to a datasheet at its rated supply: give its "
                                            "circuit (frequency, phase_voltage and the impedances)"
                                          : "";
    }
    bool converterFed() const override {
        return m_params.starter.kind == StarterParams::Kind::FrequencyConverter;
    }

    /// Throws std::invalid_argument naming the parameter that is out of range.
    DqInductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                     const DqInductionMotorParams& params);

    /// Number of rotor circuits (cages): 1 or 2.
    int rotorCount() const { return m_nr; }
    /// Stator and (first cage's) rotor flux linkages in this state [Wb].
    std::complex<double> getStatorFlux(const SimTK::State& state) const;
    std::complex<double> getRotorFlux(const SimTK::State& state, int cage = 0) const;
    /// Stator and rotor current space phasors [A] (amplitude: peak phase current).
    std::complex<double> calcStatorCurrent(const SimTK::State& state) const;
    std::complex<double> calcRotorCurrent(const SimTK::State& state, int cage = 0) const;
    /// The source's emf space phasor at time t [V] (rated supply, u = 1,
    /// θ = ω_s·t).
    std::complex<double> calcSupplyVoltage(double time) const;
    /// The starter's voltage factor u [-] in this state.
    double calcVoltageFactor(const SimTK::State& state) const;
    /// The voltage on the windings v_s [V] (through the source impedance).
    std::complex<double> calcTerminalVoltage(const SimTK::State& state) const;
    /// Line current [A rms] at the supply: the phase current, times √3 in
    /// delta after a star–delta switch; the converter's grid current.
    double calcLineCurrent(const SimTK::State& state) const;
    /// Voltage dip at the supply point 1 − |v_pcc|/|e| [-].
    double calcVoltageDip(const SimTK::State& state) const;
    /// Largest dip over the accepted steps so far [-].
    double getPeakVoltageDip(const SimTK::State& state) const override;
    /// Frequency converter: output frequency over rated f [-] (1 otherwise).
    double calcSupplyFrequency(const SimTK::State& state) const;
    /// Rotor resistance ratio r [-] of the starter in this state.
    double calcRotorResistanceRatio(const SimTK::State& state) const;
    bool isStatorOpen(const SimTK::State& state) const;
    /// Opens (ψ_s to Lm·Σi_r) or closes the stator.
    void setStatorOpen(SimTK::State& state, bool open) const;
    /// Switched on (supplied) or off (switch_off_time, a coast-down's
    /// switch at t = 0): off, the stator is open as in an interruption,
    /// for good (an interruption's reclosure does not close it).
    bool isOn(const SimTK::State& state) const;
    void setOn(SimTK::State& state, bool on) const;
    StartSequenceState calcStarterProgress(const SimTK::State& state) const;
    /// Ends the starter's sequence in `state` for good (steady running).
    void finishStarter(SimTK::State& state) const;
    bool isStarterFinished(const SimTK::State& state) const;
    int getStarterStep(const SimTK::State& state) const;
    void setStarterStep(SimTK::State& state, int step) const;
    /// Sets the fluxes to their steady running at the shaft speed ω and the
    /// time in `state`: the T circuit's phasors, Z(jω_s)·I = [u·ê; 0; 0],
    /// Ψ = L·I, ψ = Ψ·e^(jθ).
    void setSteadyFluxes(SimTK::State& state) const;
    /// Refreshes the kept largest dip (a lagged value, each accepted step);
    /// returns 1 if it grew.
    double keepPeakVoltageDip(SimTK::State& state, double dip) const;
    double calcTorque(const SimTK::State& state) const;           ///< [N*m]
    double calcInputPower(const SimTK::State& state) const;       ///< [W]
    double calcCopperLoss(const SimTK::State& state) const;       ///< [W]
    double calcFieldPower(const SimTK::State& state) const;       ///< dW/dt [W]
    /// Index in the State's z of the first flux component (ψsα), and their
    /// number (the fluxes a linearization includes, in the frame turning at
    /// ω_s = 2π·f, where steady running is an equilibrium).
    int firstFluxIndex(const SimTK::State& state) const;
    int fluxStateCount() const { return 2 + 2 * m_nr; }
    bool hasSource() const { return m_Rk > 0; }

    // ElectricalStates (a linear model's motor_model): the fluxes.
    int firstElectricalState(const SimTK::State& state) const override { return firstFluxIndex(state); }
    int electricalStateCount() const override { return fluxStateCount(); }
    std::string electricalStateName(int k) const override;
    double electricalFrameSpeed() const override { return 2 * M_PI * m_params.frequency; }
    // SupplyVoltageDip (a transient's motor reports): the source impedance.
    bool hasSupplyImpedance() const override { return hasSource(); }
    double voltageDipLimit() const override { return m_params.voltageDipLimit; }
    std::string supplyDescription() const override;
    /// Frequency converter: the hold slip speed Δω_h [rad/s electrical].
    double holdSlipSpeed() const { return m_holdSlip; }
    const DqInductionMotorParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;
    void realizeAcceleration(const SimTK::State& state) const override;

private:
    /// Everything one evaluation needs: currents, flux rates, voltages.
    struct Electrical {
        std::complex<double> current[3];  // i_s, i_r,1, i_r,2
        std::complex<double> fluxRate[3];
        std::complex<double> winding;     // v_s
        std::complex<double> emf;         // u·e (the starter's output before the source's drop)
        double u = 1, r = 1, f = 1;
        bool open = false;
    };
    Electrical calcElectrical(const SimTK::State& state) const;
    /// The flux jump of an opening: ψ_s = Lm·Σ_k (Γ_rr·ψ_r)_k (i_s = 0).
    void openStatorFluxes(SimTK::State& state) const;
    std::complex<double> flux(const SimTK::State& state, int k) const;
    double supplyAngle(const SimTK::State& state) const;
    bool isConverter() const { return m_params.starter.kind == StarterParams::Kind::FrequencyConverter; }
    double converterLimitFrequency(const SimTK::State& state) const;

    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_shaft;
    DqInductionMotorParams m_params;
    Starter m_starter;
    int m_nr = 1;
    double m_L[3][3] = {}, m_G[3][3] = {};  // L and Γ = L⁻¹
    double m_Grr[2][2] = {};                // the rotor block's inverse (stator open)
    double m_Rk = 0, m_Lk = 0;               // source resistance and inductance at V
    double m_holdSlip = std::numeric_limits<double>::infinity();
    bool m_holdByCurrent = false;
    mutable SimTK::ZIndex m_flux;  // ψsα, ψsβ, ψr1α, ψr1β[, ψr2α, ψr2β][, θ, f]
    mutable SimTK::DiscreteVariableIndex m_stepIndex;      // starter step
    mutable SimTK::DiscreteVariableIndex m_finishedIndex;  // bool: the starter's sequence ended
    mutable SimTK::DiscreteVariableIndex m_onIndex;        // bool: switched on (false: off, stator open)
    mutable SimTK::DiscreteVariableIndex m_openIndex;      // bool: stator open
    mutable SimTK::DiscreteVariableIndex m_dipIndex;       // double: largest dip so far
};

}  // namespace milldyn
