#pragma once
// CageCircuitFit: the steady-state T equivalent circuit of a single- or
// double-cage induction machine, and a fit of its parameters to catalogue
// (datasheet) values. Plain C++ (no Simbody): DqInductionMotor builds its
// machine from a fit's circuit.

#include <string>
#include <vector>

namespace milldyn {

/// The machine per phase of its equivalent star, SI: stator resistance and
/// leakage, main inductance, and one resistance and leakage per rotor cage
/// (referred to the stator; 1 or 2 cages, the cages coupled only through Lm).
struct CageCircuit {
    double statorResistance = 0;  ///< Rs [ohm]
    double statorLeakage = 0;     ///< Lsσ [H]
    double mainInductance = 0;    ///< Lm [H]
    std::vector<double> rotorResistances;  ///< Rr,k' [ohm]
    std::vector<double> rotorLeakages;     ///< Lrσ,k' [H]
};

/// The circuit's steady state at one slip on a phase voltage.
struct CagePoint {
    double torque = 0;       ///< air-gap torque 3·Σ|I_r,k|²·R_k/s / (ω_s/p) [N*m]
    double current = 0;      ///< stator (line) current, rms [A]
    double powerFactor = 0;  ///< P/(3·V·I) [-]
    double inputPower = 0;   ///< 3·Re(V·conj(I_s)) [W]
};

/// Steady state at slip s (≠ 0 for the torque) on the rms phase voltage V
/// [V] at frequency f [Hz] with p pole pairs: the complex equations
///   V = (Rs + jω(Lsσ+Lm))·I_s + jωLm·ΣI_r
///   0 = (R_k + j·s·ω·(Lrσ,k+Lm))·I_r,k + j·s·ω·Lm·(I_s + Σ_{j≠k} I_r,j)
CagePoint cageSteadyState(const CageCircuit& circuit, double phaseVoltage, double frequency, int polePairs,
                          double slip);
/// Largest torque over slip in (0, 1] and its slip (scan and golden section).
struct CageBreakdown {
    double torque = 0, slip = 0;
};
CageBreakdown cageBreakdown(const CageCircuit& circuit, double phaseVoltage, double frequency, int polePairs);

/// The largest |air-gap torque| [N*m] of the circuit switched on line
/// unexcited with the rotor held at rest for `cycles` supply cycles: the
/// dq equations (DqInductionMotor's, stator frame) at ω = 0 integrated by
/// fixed-step RK4 (400 steps a cycle). For a drive whose inertia keeps the
/// rotor near rest over the first cycles this is the switch-on peak a
/// static torque–speed curve leaves out (the DC flux's torque at the
/// supply frequency); the start's own peak is at most this plus the
/// speed's effect over those cycles.
double cageSwitchOnPeakTorque(const CageCircuit& circuit, double phaseVoltage, double frequency, int polePairs,
                              double cycles);

/// Catalogue data of a motor (IEC datasheet), SI.
struct MotorDatasheet {
    double ratedPower = 0;       ///< P_n shaft [W]
    double ratedSpeed = 0;       ///< ω_n [rad/s]
    double lineVoltage = 0;      ///< V_n line-to-line, rms [V]
    double ratedCurrent = 0;     ///< I_n line, rms [A]
    double powerFactor = 0;      ///< cos φ_n [-]
    double efficiency = 0;       ///< η_n [-]
    /// Ma/Mn [-]; 0: not given (a single cage only: a slip-ring motor's
    /// datasheet rarely gives its shorted-ring starting values, which one
    /// rotor circuit ties to Mk and the rated point).
    double lockedRotorTorqueRatio = 0;
    double breakdownTorqueRatio = 0;     ///< Mk/Mn [-]
    double lockedRotorCurrentRatio = 0;  ///< Ia/In [-]; 0: not given (as Ma/Mn)
    double frequency = 50;       ///< [Hz]
    int polePairs = 0;           ///< p; 0: the largest p with synchronous speed above ω_n
    /// Optional published curve: speeds [rad/s] with the torques [N*m]
    /// and/or the line currents [A rms] there (each empty or one per speed).
    std::vector<double> curveSpeeds, curveTorques, curveCurrents;
};

/// One fitted point: the datasheet's value, the circuit's, and the relative
/// residual (model − data)/data.
struct FitPoint {
    std::string name;  ///< "rated torque Mn", "breakdown torque Mk", ...
    std::string key;   ///< the datasheet key it comes from
    double data = 0, model = 0, residual = 0;
    std::string unit;
};

struct CageFitResult {
    CageCircuit circuit;
    int polePairs = 0;
    double phaseVoltage = 0;  ///< V_n/√3 [V]
    std::vector<FitPoint> points;
    double worstResidual = 0;           ///< max |residual|
    std::size_t worstPoint = 0;         ///< index into points
};

/// Why a datasheet is impossible, with the key to blame; empty key: none.
struct DatasheetProblem {
    std::string key, reason;
};
/// Physical impossibilities checked before any fit (rated speed not below
/// synchronous, breakdown below the rated or starting torque, an air-gap
/// power above the apparent input at the rated point or at standstill), and
/// of a published curve: a driving torque at or above synchronous speed, a
/// torque above Mk, an air-gap power T·ω_s above the apparent input √3·V·I
/// at a point with both, a standstill point more than 10 % from Ma or Ia.
DatasheetProblem checkDatasheet(const MotorDatasheet& data);

/**
 * Fits a `cages`-cage circuit (1 or 2) to the datasheet by Levenberg–
 * Marquardt on the logarithms of the parameters (all stay > 0), from
 * several starting points, minimising the sum of squared relative residuals
 * of: Mn = P_n/ω_n at the rated slip, I_n and cos φ_n there, η_n = P_n/P_in
 * (the circuit's input: iron, friction and stray losses are booked as
 * stator copper), Ma and Ia at standstill (when given), Mk the largest
 * torque, and each point of a published torque or current curve (the
 * circuit's torque and line current at the point's slip). Single cage:
 * Lsσ = Lrσ' (the usual
 * split). Double cage (cage 1 the starting, outer cage, cage 2 the
 * running, inner one): all seven parameters free; the data determine six
 * (η_n follows from P_n, I_n and cos φ_n), and the damped steps take the
 * solution nearest the per-unit starting point. Throws std::invalid_argument on a bad datasheet
 * (checkDatasheet's reason).
 */
CageFitResult fitCageCircuit(const MotorDatasheet& data, int cages);

/// fitCageCircuit, computed once per (datasheet, cages) in the process: a
/// scene build fits each DOL InductionMotor with full data and each
/// datasheet DqInductionMotor (a few seconds each), so a sweep would refit
/// at every point. Keyed by every field of the datasheet, bit for bit;
/// thread-safe (sweeps build scenes on several threads): the first caller
/// of a key fits, concurrent callers of the same key wait for its result,
/// other keys fit in parallel. A datasheet the fit refuses throws each
/// time (not cached).
CageFitResult fitCageCircuitCached(const MotorDatasheet& data, int cages);
/// How many fits fitCageCircuit has run in this process (for tests of the cache).
long cageFitCount();

}  // namespace milldyn
