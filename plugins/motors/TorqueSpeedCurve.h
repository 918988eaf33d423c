#pragma once
// TorqueSpeedCurve: an induction motor's natural torque (and, where the data
// give it, its current) against shaft speed at rated voltage and frequency,
// from a catalogue's points or a table, interpolated without overshoot.
// Plain C++ (no Simbody): the InductionMotor element holds one.

#include "plugins/motors/CurrentCircle.h"

#include <optional>
#include <vector>

namespace milldyn {

/**
 * Monotone piecewise-cubic Hermite interpolation (Fritsch & Carlson, "Monotone
 * piecewise cubic interpolation", SIAM J. Numer. Anal. 17 (1980) 238-246).
 *
 * <pre>
 *   secants  d_k = (y_{k+1} − y_k)/(x_{k+1} − x_k)
 *   tangents m_0 = d_0, m_n = d_{n−1}; m_k = (d_{k−1} + d_k)/2, or 0 where
 *            d_{k−1}·d_k <= 0 (a local extreme sits on a data point);
 *            on each interval with α = m_k/d_k, β = m_{k+1}/d_k and
 *            α² + β² > 9 both are scaled by 3/√(α² + β²)
 *   p(x) on [x_k, x_{k+1}]: the cubic Hermite through (x_k, y_k, m_k), (x_{k+1}, y_{k+1}, m_{k+1})
 * </pre>
 *
 * The interpolant is C¹, reproduces every point exactly and is monotone
 * wherever the data are, so it never overshoots between points: a
 * torque–speed curve's maximum is its breakdown point. Below x_0 it holds
 * y_0; above x_n it continues with the end tangent m_n.
 * Throws std::invalid_argument unless x has >= 2 finite, strictly increasing
 * values and y as many finite values.
 */
class MonotoneCubic {
public:
    MonotoneCubic() = default;
    MonotoneCubic(std::vector<double> x, std::vector<double> y);
    double operator()(double x) const;
    bool empty() const { return m_x.empty(); }

private:
    std::vector<double> m_x, m_y, m_m;
};

/// The torque–speed laws an InductionMotor can follow. All SI.
struct TorqueSpeedCurveParams {
    enum class Law { Linear, Kloss, KlossModified, Catalogue, Table };
    Law law = Law::Kloss;
    /// Rated (nameplate) torque Mn [N*m], > 0.
    double ratedTorque = 0;
    /// Rated speed ωn [rad/s], 0 < ωn < ωc.
    double ratedSpeed = 0;
    /// Synchronous speed ωc at rated frequency [rad/s], > 0.
    double synchronousSpeed = 0;
    /// Breakdown torque ratio λ = Mk/Mn [-], > 1 (Kloss, catalogue).
    double breakdownRatio = 2.2;
    /// Linear law only: printed M00 [N*m] and b0 [N*m*s/rad] (both > 0
    /// replace the nameplate formula).
    double linearStallTorque = 0;
    double linearSlope = 0;
    /// Catalogue, modified Kloss: locked-rotor (starting) torque ratio Mst/Mn [-] (> 0).
    double lockedRotorRatio = 0;
    /// Catalogue: pull-up (minimum) torque ratio Mmin/Mn [-] and its speed
    /// [rad/s]; a ratio of 0 leaves the point out.
    double pullUpRatio = 0;
    double pullUpSpeed = 0;
    /// Catalogue: breakdown speed [rad/s]; 0: the Kloss breakdown slip
    /// sk = sn·(λ + √(λ² − 1)) gives ωk = ωc·(1 − sk).
    double breakdownSpeed = 0;
    /// Table: speeds [rad/s] strictly increasing from >= 0 to <= ωc, torques
    /// [N*m] >= 0 at them, 0 at ωc; (ωc, 0) is appended when the last speed
    /// is below ωc.
    std::vector<double> tableSpeeds, tableTorques;
    /// Table: stator (line) currents [A] at the same speeds (optional).
    std::vector<double> tableCurrents;
    /// Other laws: catalogue current data for the circle diagram
    /// (CurrentCircle): rated current I_N [A], rated power factor [-] and
    /// locked-rotor current ratio I_LR/I_N [-]; all three, or 0 (no current).
    double ratedCurrent = 0;
    double ratedPowerFactor = 0;
    double lockedRotorCurrentRatio = 0;
};

/// The modified Kloss law's two constants, solved from the nameplate.
struct ModifiedKlossFit {
    /// Breakdown slip sk [-].
    double breakdownSlip = 0;
    /// Stator-resistance asymmetry a = R1/R2' [-] (a·sk = R1/√(R1² + Xk²) in [0, 1)).
    double asymmetry = 0;
};

/**
 * Solves the modified Kloss law M(s) = Mk·2(1 + a·sk)/(s/sk + sk/s + 2a·sk)
 * (see TorqueSpeedCurve) for sk and a from the rated slip sn, the breakdown
 * ratio λ = Mk/Mn and the starting torque ratio μ = M(1)/Mn.
 *
 * <pre>
 *   q = a·sk (physically R1/√(R1² + Xk²), so 0 <= q < 1)
 *   M(sn) = Mn:  sn/sk + sk/sn = 2λ + 2q(λ − 1)  =: 2C
 *                ⇒ sk(q) = sn·(C + √(C² − 1))     (stable branch, sk > sn)
 *   M(1) = μ·Mn: μ(q) = 2λ(1 + q)/(1/sk(q) + sk(q) + 2q)
 * </pre>
 *
 * sk(q) rises with q, and while sk <= 1 so does μ(q) (both the numerator
 * and 1/sk + sk move the same way): μ(q) = μ has one root on the bracket
 * [0, q_max], q_max = 1 or the q at which sk = 1 if smaller (a breakdown
 * beyond standstill has no starting torque below it), found by bisection
 * to the last bit. q = 0 is the classic Kloss law. Throws
 * std::invalid_argument with the reason (μ >= λ; μ outside [μ(0), μ(q_max)),
 * the attainable range printed) when no solution exists.
 */
ModifiedKlossFit fitModifiedKloss(double ratedSlip, double breakdownRatio, double startingRatio);

/**
 * Natural torque–speed curve of an induction motor (rated voltage, rated
 * frequency, rotor short-circuited, delta connection).
 *
 * <pre>
 *   slip s = (ωc − ω)/ωc, sn = (ωc − ωn)/ωc
 *   Linear (seed 003 eqs 3-4): M = M00 − b0·ω, M00 = Mn·ωc/(ωc − ωn), b0 = Mn/(ωc − ωn);
 *               printed M00 and b0 put its zero ω0 = M00/b0 near, not at, ωc
 *               (zeroTorqueSpeed: where the rotor has no slip for this law)
 *   Kloss:      M = 2·Mk·s·sk/(s² + sk²), Mk = λ·Mn, sk = sn·(λ + √(λ² − 1))   (M(ωn) = Mn)
 *   Modified Kloss (stator resistance kept; Chilikin, "Electric drive",
 *   ch. 3 "Characteristics of the induction motor", eq. for M with
 *   a = R1/R2'; Kopylov, "Electrical machines", same form):
 *               M = Mk·2(1 + a·sk)/(s/sk + sk/s + 2a·sk)
 *               = 2·Mk·(1 + q)·s·sk/(s² + sk² + 2q·s·sk),  q = a·sk,
 *               with sk and a from M(sn) = Mn and M(1) = Mst (fitModifiedKloss).
 *               Its maximum over s > 0 is Mk, at s = sk; on the generating
 *               side (s < 0) the breakdown torque is Mk·(1 + q)/(1 − q).
 *   Catalogue:  the monotone cubic (MonotoneCubic) through
 *               (0, Mst), (ω_pu, M_pu), (ωk, Mk), (ωn, Mn), (ωc, 0)
 *               — the points of IEC 60034-12 / NEMA MG 1 catalogues
 *   Table:      the monotone cubic through the given points (and (ωc, 0))
 * </pre>
 *
 * Below ω = 0 the catalogue and table curves hold the locked-rotor value;
 * above ωc they continue with the end tangent at ωc, which is <= 0 since
 * the last torque is 0 and the others >= 0 (generating; 0 if the table's
 * last two torques are 0). Every law keeps M·(ω0 − ω) >= 0 at every speed
 * (ω0 = zeroTorqueSpeed(), ωc but for the linear law):
 * the rotor heat is never negative (the monotone cubic stays between its
 * points' torques, all >= 0 below ωc). Current: the
 * table law's monotone cubic through its currents, or, for the other laws
 * given I_N, cos φ_N and I_LR/I_N, the circle diagram (CurrentCircle) at
 * the slip; otherwise none (NaN).
 * The constructor throws std::invalid_argument naming the parameter.
 */
class TorqueSpeedCurve {
public:
    explicit TorqueSpeedCurve(const TorqueSpeedCurveParams& params);

    /// Natural torque at shaft speed ω [rad/s] [N*m].
    double torque(double omega) const;
    /// Natural line current at shaft speed ω [A]; NaN if the data give none.
    double current(double omega) const;
    bool hasCurrent() const { return !m_current.empty() || m_circle.has_value(); }
    /// The circle diagram of the current, if the data give one.
    const std::optional<CurrentCircle>& currentCircle() const { return m_circle; }

    const TorqueSpeedCurveParams& params() const { return m_params; }
    double ratedSlip() const { return m_slipRated; }
    /// Breakdown slip sk [-] (Kloss and modified Kloss laws).
    double breakdownSlip() const { return m_slipBreakdown; }
    /// Modified Kloss: stator-resistance asymmetry a = R1/R2' [-] (0 otherwise).
    double asymmetry() const { return m_asymmetry; }
    double linearStallTorque() const { return m_M00; }
    double linearSlope() const { return m_b0; }
    /// The speed ω0 at which the natural torque is 0 [rad/s]: ωc, or M00/b0
    /// for the linear law.
    double zeroTorqueSpeed() const;
    /// The interpolation's points (catalogue and table laws): speeds [rad/s], torques [N*m].
    const std::vector<double>& pointSpeeds() const { return m_pointSpeeds; }
    const std::vector<double>& pointTorques() const { return m_pointTorques; }

private:
    TorqueSpeedCurveParams m_params;
    double m_M00 = 0, m_b0 = 0, m_slipRated = 0, m_slipBreakdown = 0, m_asymmetry = 0;
    std::vector<double> m_pointSpeeds, m_pointTorques;
    MonotoneCubic m_torque, m_current;
    std::optional<CurrentCircle> m_circle;
};

}  // namespace milldyn
