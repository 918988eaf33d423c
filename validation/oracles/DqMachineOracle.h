#pragma once
// DqMachineOracle: the start of a squirrel-cage induction machine written
// from the textbook alone (standard library only; no Simbody, no milldyn
// element), in a formulation different from milldyn's DqInductionMotor, so
// that the two can be compared over a whole transient.
//
// Source: Krause, Wasynczuk & Sudhoff, "Analysis of Electric Machinery and
// Drive Systems", ch. 6 ("Symmetrical induction machines"): the voltage
// equations in the arbitrary reference frame (eqs 6.5-1..6.5-8, here with
// the frame turning at the supply's ω_e), with the four winding currents
// as states (the "current form": λ = L·i inverted once, eq 6.5-16 ff.), the
// torque T_e = (3/2)(P/2)·L_M·(i_qs·i'_dr − i_ds·i'_qr) (eq 6.6-2's current
// form) and the rotor's equation J·dω_m/dt = T_e − T_L(ω_m) (eq 6.6-4):
// the "fifth-order model". Krause's transformation (eq 3.3-1 ff.) of the
// balanced supply v_as = √2·V·cos(ω_e·t) in a frame with θ(0) = 0 gives
// v_qs = √2·V, v_ds = 0: the same switch-on instant (phase a at its crest)
// as milldyn's stator-frame supply √2·V·e^(jω_e·t).
//
// milldyn's element instead integrates the four flux linkages in the
// stator-fixed frame and takes the torque as (3/2)·p·Im(conj(ψ_s)·i_s).
// Integrated here by the classic fixed-step fourth-order Runge–Kutta.

#include <functional>
#include <vector>

namespace milldyn::oracles {

/// The machine per phase of its winding (Krause's notation): resistances
/// [ohm], leakage and magnetising inductances [H], pole pairs P/2,
/// rms phase voltage [V], supply frequency [Hz].
struct DqMachine {
    double rs = 0, rr = 0, lls = 0, llr = 0, lm = 0;
    int polePairs = 1;
    double phaseVoltage = 0, frequency = 0;
};

/// How the supply's voltage is applied (the machine's own winding voltage
/// over rated): direct on line (1), star–delta (1/√3 until the switch,
/// then 1, without a phase shift), soft start (V0 + (1 − V0)·min(t/T, 1)).
struct DqSupply {
    enum class Kind { DirectOnLine, StarDelta, SoftStart };
    Kind kind = Kind::DirectOnLine;
    double switchTime = 0;      ///< star–delta [s]
    double initialVoltage = 1;  ///< soft start V0 [-]
    double rampTime = 0;        ///< soft start T [s]
    /// The voltage factor during a step that begins at `stepStart` [s], at
    /// `t` [s] inside it: a switch acts from the step that begins at it.
    double factor(double t, double stepStart) const;
};

/// One sample of the oracle's start.
struct DqSample {
    double time = 0;          ///< [s]
    double speed = 0;         ///< mechanical [rad/s]
    double torque = 0;        ///< electromagnetic, on the shaft [N*m]
    double statorCurrent = 0; ///< rms phase current √((i_qs² + i_ds²)/2) [A]
    double inputPower = 0;    ///< (3/2)(v_qs·i_qs + v_ds·i_ds) [W]
    double copperLoss = 0;    ///< (3/2)(r_s·|i_s|² + r_r·|i_r|²) [W]
    double fieldEnergy = 0;   ///< (3/4)·(i_qs·λ_qs + i_ds·λ_ds + i'_qr·λ'_qr + i'_dr·λ'_dr) [J]
};

/// Starts the machine unexcited (all currents 0) from rest at t = 0 on a
/// shaft of inertia J [kg*m^2] against a load torque T_L(ω) [N*m]
/// (opposing; a function of the mechanical speed), integrated with the
/// fixed step h [s] to `endTime` [s]; one sample every `sampleEvery` steps
/// (the first at t = 0). A star–delta switch time must be a whole number of
/// steps. Throws std::invalid_argument on a bad step or switch time.
std::vector<DqSample> dqMachineStart(const DqMachine& machine, const DqSupply& supply, double J,
                                     const std::function<double(double)>& loadTorque, double h, double endTime,
                                     int sampleEvery);

/// The machine held at slip s [-] (rotor at (1 − s)·ω_e/p) on a winding
/// voltage u(t)·√2·V that ramps at the constant rate du/dt [1/s], once the
/// switch-on transients have decayed. In the synchronous frame the machine
/// is then linear and time-invariant, Z(d/dt)·i = u(t)·v̂ with
///   Z(p) = [[R_s + (p + jω_e)·L_s, (p + jω_e)·L_M], [(p + js·ω_e)·L_M, R'_r + (p + js·ω_e)·L'_r]],
/// and a ramp's exact forced response is i(t) = u(t)·I_0 + (du/dt)·I_1 with
/// Z(0)·I_0 = v̂ (the T equivalent circuit) and Z(0)·I_1 = −L·I_0 (the
/// currents' lag behind the ramp), L = dZ/dp. du/dt = 0 gives the
/// equivalent circuit at voltage u·V: torque ∝ u².
struct DqHeldResponse {
    double torque = 0;         ///< (3/2)·p·L_M·Im(conj(i'_r)·i_s) [N*m]
    double statorCurrent = 0;  ///< rms phase current |i_s|/√2 [A]
};
DqHeldResponse dqHeldResponse(const DqMachine& machine, double slip, double u, double dudt);

/// Time [s] at which a sampled run first reaches `fraction` of its last
/// sample's speed, linearly interpolated between samples; NaN if never.
double dqTimeToFraction(const std::vector<DqSample>& run, double fraction);

}  // namespace milldyn::oracles
