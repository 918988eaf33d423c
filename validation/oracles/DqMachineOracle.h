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

#include <complex>
#include <functional>
#include <limits>
#include <utility>
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


/// The extended machine and supply of dqMachineRun (issue 28): a second
/// rotor cage, a slip-ring rotor's added resistance, the stator opened for
/// intervals (an open star–delta transition, a supply interruption), the
/// supply's phase steps, a V/f converter's frequency ramp and a source
/// impedance. Written from the same textbook equations in the
/// synchronously rotating frame, the frame now turning with the supply's
/// angle θ(t) (Krause's arbitrary frame, eq 6.5-1 ff., ω = dθ/dt), with
/// the winding currents as states.
struct DqMachineExtended {
    DqMachine base;
    double rr2 = 0, llr2 = 0;  ///< second cage [ohm], [H]; 0: single cage
    /// Source impedance at the rated winding voltage [ohm], [H]; seen
    /// through the starter's voltage factor u as u²·(R, L), added in series
    /// with the stator (its inductance to L_s: the currents stay the states).
    double sourceR = 0, sourceL = 0;
};

struct DqSupplyExtended {
    /// Voltage factor u(t) on the windings (star 1/√3, soft start ramp,
    /// converter boost + (1 − boost)·f), given by the caller as a function
    /// of time (steps switch at a step boundary).
    std::function<double(double)> voltage = [](double) { return 1.0; };
    /// Supply frequency over rated f(t) [-] (converter); θ(t) = ω_e·∫f dt.
    std::function<double(double)> frequency = [](double) { return 1.0; };
    /// Phase added to θ from `phaseStepTime` on [rad] (delta's +π/6).
    double phaseStep = 0, phaseStepTime = std::numeric_limits<double>::infinity();
    /// Rotor resistance multiplier of the first cage r(t) [-].
    std::function<double(double)> rotorResistanceRatio = [](double) { return 1.0; };
    /// Stator open over [from, to) intervals [s] (step boundaries).
    std::vector<std::pair<double, double>> openIntervals;
};

struct DqSampleExtended {
    DqSample base;
    double voltageDip = 0;  ///< 1 − |v_pcc|/|e| (0 without a source) [-]
};

/// As dqMachineStart, for the extended machine and supply: from rest,
/// unexcited, fixed-step RK4 of step h (every switch on a step boundary).
std::vector<DqSampleExtended> dqMachineRun(const DqMachineExtended& machine, const DqSupplyExtended& supply, double J,
                                           const std::function<double(double)>& loadTorque, double h, double endTime,
                                           int sampleEvery);

/// Steady state of the extended machine (double cage) at slip s, rated
/// voltage: the T circuit's torque and rms stator current, from the same
/// equations with d/dt = 0 in the synchronous frame.
DqHeldResponse dqHeldResponseExtended(const DqMachineExtended& machine, double slip);

/// The machine driving a belt (or any torsional spring–damper of ratio n =
/// ω_motor/ω_driven) to a loaded flywheel, linearized about its steady
/// running: Krause's fifth-order model in currents (synchronous frame, where
/// steady running is an equilibrium) with the chain
///   J1·dω1/dt = T_e − k·φ − c·(ω1 − n·ω2),  dφ/dt = ω1 − n·ω2,
///   J2·dω2/dt = n·(k·φ + c·(ω1 − n·ω2)) − T_L        (φ = θ1 − n·θ2),
/// the Jacobian by central differences of these rates at the equilibrium
/// (the slip where T_e = T_L/n on the stable branch, by bisection), its
/// seven eigenvalues by Eigen, sorted by |imag| then real.
struct DqBeltChain {
    DqMachine machine;
    double motorInertia = 0, flywheelInertia = 0;  ///< J1, J2 [kg*m^2]
    double stiffness = 0, damping = 0, ratio = 1;  ///< k [N*m/rad], c [N*m*s/rad] on the motor shaft, n [-]
    double loadTorque = 0;                         ///< T_L on the flywheel [N*m], constant
};
std::vector<std::complex<double>> dqBeltChainEigenvalues(const DqBeltChain& chain);
/// Same chain with the machine as its static torque–speed slope at the
/// operating point (the T circuit's dT/dω): three eigenvalues.
std::vector<std::complex<double>> staticBeltChainEigenvalues(const DqBeltChain& chain);
/// The same linearized chain's steady harmonic response: the complex
/// amplitude of the belt torque k·φ + c·(ω1 − n·ω2) [N*m] when a torque
/// Re(torque·e^{iPt}) [N*m] acts on the flywheel (in its direction of
/// rotation) at P [rad/s]: (iP·I − A)·x̂ = b, b = torque/J2 in ω2's row.
/// staticSlope: the three-state chain with the T circuit's slope.
std::complex<double> dqBeltChainBeltResponse(const DqBeltChain& chain, double P, std::complex<double> torque,
                                             bool staticSlope = false);

/// Time [s] at which a sampled run first reaches `fraction` of its last
/// sample's speed, linearly interpolated between samples; NaN if never.
double dqTimeToFraction(const std::vector<DqSample>& run, double fraction);

}  // namespace milldyn::oracles
