#pragma once
// DqInductionMotor: a squirrel-cage induction motor as a dynamic space-phasor
// (dq) model, with its stator and rotor flux linkages as states, started
// direct on line, star–delta or by a soft starter.

#include "plugins/motors/Starter.h"

#include <Simbody.h>

#include <complex>

namespace milldyn {

/// Parameters of a DqInductionMotor, per phase of the equivalent star, SI.
struct DqInductionMotorParams {
    double statorResistance = 0;   ///< Rs [ohm], > 0
    double rotorResistance = 0;    ///< Rr' [ohm], > 0 (referred to the stator)
    double statorLeakage = 0;      ///< Lsσ [H], > 0
    double rotorLeakage = 0;       ///< Lrσ' [H], > 0
    double mainInductance = 0;     ///< Lm [H], > 0
    int polePairs = 1;             ///< p [-], >= 1
    double phaseVoltage = 0;       ///< V [V] rms phase voltage, > 0
    double frequency = 0;          ///< f [Hz] supply frequency, > 0
    /// direct_on_line, star_delta (switch by time only) or soft_start.
    StarterParams starter;
};

/**
 * Dynamic model of a squirrel-cage induction machine in space phasors
 * (amplitude-invariant, stator-fixed frame), the flux form of the classic
 * two-axis model (Krause, Wasynczuk & Sudhoff, "Analysis of Electric
 * Machinery", ch. 6; Leonhard, "Control of Electrical Drives", ch. 10;
 * the machine of Modelica MSL's AIM_SquirrelCage / IMC_DOL example):
 * <pre>
 *   v_s = u(t)·√2·V·e^(jω_s t),  ω_s = 2π f              (supply switched on at t = 0)
 *   u = 1                                                (direct on line)
 *   u = 1/√3 before the switch, 1 after                  (star–delta: V is the winding's
 *                                                         voltage in delta, the line voltage)
 *   u = V0 + (1 − V0)·min(t/T, 1)                         (soft start)
 *   dψ_s/dt = v_s − Rs·i_s
 *   dψ_r/dt = −Rr·i_r + j·p·ω·ψ_r                         (rotor at mechanical speed ω)
 *   ψ_s = Ls·i_s + Lm·i_r,  ψ_r = Lm·i_s + Lr·i_r,  Ls = Lsσ + Lm, Lr = Lrσ + Lm
 *   i_s = (Lr·ψ_s − Lm·ψ_r)/D,  i_r = (Ls·ψ_r − Lm·ψ_s)/D,  D = Ls·Lr − Lm²
 *   T = (3/2)·p·Im(conj(ψ_s)·i_s)                        (on the shaft, + drives)
 * </pre>
 * The four flux components are continuous states (Z), zero at t = 0 (the
 * machine switched on unexcited). In steady state at slip s the model is
 * the T equivalent circuit: T = 3·|I_r|²·(Rr/s)/(ω_s/p), checked by the
 * validation case start_dq_steady_torque against that closed form; a start
 * from rest shows the DC flux components' torque oscillation at the supply
 * frequency (start_dq_dol_oscillation).
 *
 * Starters (plugins/motors/Starter.h's supply: star–delta's torque factor
 * 1/3 is u² here, u = √(1/3)). The star–delta switch is a Scene switch event
 * at its time (the integrator restarts there; the fluxes are continuous,
 * the voltage jumps), closed-transition and without the 30° phase shift of
 * the delta's line-to-line voltage against star's phase voltage. The
 * element's `current` is the winding's (phase) current; with star–delta the
 * `line_current` is that current in star and √3 times it in delta (the
 * machine in its winding's own quantities, as Modelica MSL's IMC_YD example
 * feeds the same machine 57.7 V per winding in star and 100 V in delta;
 * its three-phase SwitchYD also carries the 30° step, not modelled here).
 * Validated against the oracle
 * validation/oracles/DqMachineOracle (a different formulation: currents in
 * a synchronously rotating frame, fixed-step RK4) over whole starts, and
 * held at a slip against the equivalent circuit times u² (start_dq_*).
 *
 * Energy: the terminal power (3/2)·Re(v_s·conj(i_s)) is the motor's input
 * (an EnergyFlow source); the copper losses (3/2)·(Rs|i_s|² + Rr|i_r|²)
 * are heat; the magnetic field's energy W = (3/4)·Re(conj(i_s)·ψ_s +
 * conj(i_r)·ψ_r) changes at (3/2)·Re(conj(i_s)·dψ_s/dt + conj(i_r)·dψ_r/dt),
 * reported as a source "NAME.field" of −dW/dt (negative while the field
 * builds up), so the balance closes. Iron, friction and stray losses,
 * saturation and skin effect are not modelled; the supply is ideal.
 */
class DqInductionMotor : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    DqInductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                     const DqInductionMotorParams& params);

    /// Stator and rotor flux linkages in this state [Wb].
    std::complex<double> getStatorFlux(const SimTK::State& state) const;
    std::complex<double> getRotorFlux(const SimTK::State& state) const;
    /// Stator and rotor current space phasors [A] (amplitude: peak phase current).
    std::complex<double> calcStatorCurrent(const SimTK::State& state) const;
    std::complex<double> calcRotorCurrent(const SimTK::State& state) const;
    /// The rated supply's voltage space phasor at time t [V] (u = 1).
    std::complex<double> calcSupplyVoltage(double time) const;
    /// The starter's voltage factor u [-] in this state (time and step).
    double calcVoltageFactor(const SimTK::State& state) const;
    /// The voltage on the windings, u·v_s [V].
    std::complex<double> calcTerminalVoltage(const SimTK::State& state) const;
    /// Line current [A rms]: the phase current, times √3 in delta after a
    /// star–delta switch.
    double calcLineCurrent(const SimTK::State& state) const;
    /// Where the starter's sequence stands in this state (Starter::progress):
    /// star until the switch, the soft start's ramp until it ends.
    StartSequenceState calcStarterProgress(const SimTK::State& state) const;
    /// Ends the starter's sequence in `state` for good (steady running): the
    /// supply is Starter::finalSupply (delta, full voltage) from then on.
    void finishStarter(SimTK::State& state) const;
    bool isStarterFinished(const SimTK::State& state) const;
    int getStarterStep(const SimTK::State& state) const;
    void setStarterStep(SimTK::State& state, int step) const;
    double calcTorque(const SimTK::State& state) const;           ///< [N*m]
    double calcInputPower(const SimTK::State& state) const;       ///< [W]
    double calcCopperLoss(const SimTK::State& state) const;       ///< [W]
    double calcFieldPower(const SimTK::State& state) const;       ///< dW/dt [W]
    const DqInductionMotorParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;
    void realizeAcceleration(const SimTK::State& state) const override;

private:
    struct Derivatives {
        std::complex<double> statorFlux, rotorFlux;
    };
    Derivatives calcFluxRates(const SimTK::State& state) const;

    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_shaft;
    DqInductionMotorParams m_params;
    Starter m_starter;
    double m_Ls = 0, m_Lr = 0, m_D = 0;
    mutable SimTK::ZIndex m_flux;  // ψsα, ψsβ, ψrα, ψrβ
    mutable SimTK::DiscreteVariableIndex m_stepIndex;  // starter step: 0, 1 after the star–delta switch
    mutable SimTK::DiscreteVariableIndex m_finishedIndex;  // bool: the starter's sequence ended (finishStarter)
};

}  // namespace milldyn
