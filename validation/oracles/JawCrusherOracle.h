#pragma once
// Closed forms for an angle-tied crushing load (issue 27): the Fourier
// coefficients of a half-sine pulse, its work per stroke, the flywheel's
// speed fluctuation by the textbook energy method and by a linear harmonic
// balance with the motor's slip slope, and the breakaway threshold of a
// drive through a belt. Written from the formulas below, independent of the
// Simbody model (own parameter structs; no Simbody, no ModelSpec).

#include <vector>

namespace milldyn::oracle {

/// g(ψ) = P·sin(π(ψ − ψ0)/w) for (ψ − ψ0) mod 2π in [0, w], else 0.
struct HalfSinePulse {
    double peak = 0;   ///< P [N*m]
    double start = 0;  ///< ψ0 [rad of the cycle]
    double width = 0;  ///< w [rad of the cycle], (0, 2π]
};

/// g(ψ) = mean + Σ_k (cosine[k−1]·cos kψ + sine[k−1]·sin kψ).
struct FourierSeries {
    double mean = 0;
    std::vector<double> cosine, sine;
};

/**
 * Fourier coefficients of a half-sine pulse, k = 1..harmonics. With
 * α = π/w and u = ψ − ψ0 (the pulse from u = 0):
 * <pre>
 *   a0  = P·w/π²
 *   c_k = (P/π)·α·(1 + cos kw)/(α² − k²),   s_k = (P/π)·α·sin kw/(α² − k²)      (k ≠ α)
 *   c_k = 0,                                s_k = P/2                            (k = α)
 *   shifted by ψ0:  a_k = c_k cos kψ0 − s_k sin kψ0,   b_k = c_k sin kψ0 + s_k cos kψ0
 * </pre>
 * (from ∫0^w sin αu·cos ku du = α(1 + cos kw)/(α² − k²) and
 * ∫0^w sin αu·sin ku du = α sin kw/(α² − k²), using αw = π).
 */
FourierSeries halfSinePulseSeries(const HalfSinePulse& pulse, int harmonics);

/// Σ_{k > K} (|c_k| + |s_k|) bound of the truncated series' error, from
/// |c_k|, |s_k| <= (P/π)·2α/(k² − α²) for k > α [N*m].
double halfSinePulseTailBound(const HalfSinePulse& pulse, int harmonics);

/// Crushing work of one pulse ∫ g dψ = 2·P·w/π [J per unit cycle angle];
/// per stroke on a shaft with n cycles per revolution: 2·P·w/(π·n) [J].
double halfSinePulseWorkPerStroke(const HalfSinePulse& pulse, int cyclesPerRevolution);

/// The flywheel check of a machine whose shaft carries a half-sine
/// crushing pulse n times per revolution, driven by a torque T_m.
struct FlywheelCheck {
    HalfSinePulse pulse;
    int cyclesPerRevolution = 1;
    double inertia = 0;     ///< J on the crusher shaft, everything referred to it [kg*m^2]
    double meanSpeed = 0;   ///< Ω [rad/s]
    /// Drive's slip slope referred to the crusher shaft c = −dT_m/dω
    /// [N*m*s/rad] (0: the textbook's constant drive torque).
    double driveSlope = 0;
};

/**
 * Textbook energy method (constant drive torque T_m = a0): over a stroke
 * E(u) = a0·u − (P·w/π)(1 − cos(πu/w)) on the pulse, linear after it;
 * extremes where g = a0, u1 = (w/π)·asin(a0/P), u2 = w − u1;
 * ΔE = (E(u1) − E(u2))/n [J] (shaft angle = ψ/n);
 * δ = (ω_max − ω_min)/Ω = ΔE/(J·Ω²).
 */
double flywheelEnergySwing(const FlywheelCheck& c);
double flywheelSpeedFluctuationTextbook(const FlywheelCheck& c);

/**
 * Linear harmonic balance about Ω with the drive's slope c:
 * J·Δω̇ + c·Δω = −(g(ψ) − a0), ψ = n·Ω·t;
 * Δω = Σ_k Re[−(a_k − i·b_k)·e^{ikψ}/(c + i·k·n·Ω·J)], δ = (max Δω − min Δω)/Ω
 * over `points` instants of a stroke, `harmonics` terms. With c = 0 and many
 * harmonics it tends to the energy method's δ.
 */
double flywheelSpeedFluctuationDamped(const FlywheelCheck& c, int harmonics, int points = 4096);

/// Breakaway from rest through a belt of ratio i = ω_motor/ω_shaft (rigid,
/// no loss): the drive passes the breakaway iff T_motor(0)·i > M_s. Returns
/// the largest static torque it passes, T_motor(0)·i [N*m].
double breakawayThreshold(double motorTorqueAtStandstill, double beltRatio);

}  // namespace milldyn::oracle
