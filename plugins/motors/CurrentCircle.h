#pragma once
// CurrentCircle: an induction motor's stator current against slip from its
// catalogue data (rated current and power factor, locked-rotor current),
// by the circle-diagram approximation. Plain C++ (no Simbody): the
// TorqueSpeedCurve holds one.

namespace milldyn {

/// Catalogue current data of an induction motor. All SI.
struct CurrentCircleParams {
    double ratedSlip = 0;          ///< sn [-], in (0, 1)
    double ratedCurrent = 0;       ///< I_N [A] (line current at rated load), > 0
    double ratedPowerFactor = 0;   ///< cos φ_N [-], in (0, 1)
    double lockedRotorRatio = 0;   ///< I_LR/I_N [-], > 1
};

/**
 * Stator (line) current of an induction motor against slip by the circle
 * diagram (Heyland/Ossanna): the approximate equivalent circuit with the
 * magnetising branch at the terminals and the stator resistance neglected
 * (Fitzgerald, Kingsley & Umans, "Electric Machinery", the polyphase
 * induction machine's approximate equivalent circuit; Kostenko &
 * Piotrovsky, "Electrical Machines", vol. 2, the circle diagram). Per unit
 * of the rated phase voltage and of I_N:
 * <pre>
 *   I(s)  = −j·Iμ + D·(ρ − j)/(1 + ρ²),   ρ = s_c/s      (s = 0: I = −j·Iμ)
 *   D = V/X_k (the circle's diameter), s_c = R2'/X_k, Iμ the magnetising current
 * </pre>
 * The current's locus is a circle through −j·Iμ (s = 0) of diameter D
 * on the −j axis. The three unknowns are fitted to the three catalogue
 * data: I(sn) = 1 at the power factor cos φ_N and |I(1)| = I_LR/I_N.
 * With u = s_c/sn the rated point gives D = c(1 + u²)/u and
 * Iμ = sin φ_N − c/u (c = cos φ_N); |I(1)| = I_LR/I_N is then one equation
 * in u, bisected on [c/sin φ_N (Iμ = 0), 1/sn (s_c = 1)]. Outside that
 * bracket no circle fits (the constructor throws with the attainable
 * range of I_LR/I_N printed).
 *
 * The fit reproduces its three data exactly; everything else is the
 * approximation's. With R2' and X_k constant, the circle gives its own
 * torque ratio M(1)/Mn = (ρ1/(1 + ρ1²))·((1 + u²)/u), ρ1 = u·sn (torque ∝
 * the rotor current's in-phase part at fixed ωc); catalogue motors with
 * deep bars or a double cage have a higher locked-rotor torque than that
 * (R2' is larger at standstill), so the current is fitted to the current
 * data, not to the torque curve, and calcLockedRotorTorqueRatio() tells
 * how far apart they are. Under a starter the current scales as the
 * InductionMotor says (k·V·I at the equivalent slip): at constant V/f the
 * current, like the torque, depends on the slip speed alone.
 */
class CurrentCircle {
public:
    /// Throws std::invalid_argument with the reason (a datum out of range,
    /// or no circle through the three data).
    explicit CurrentCircle(const CurrentCircleParams& params);
    /// Line current at slip s [A].
    double current(double slip) const;
    /// Magnetising (no-load) current Iμ [A].
    double magnetisingCurrent() const { return m_magnetising * m_params.ratedCurrent; }
    /// The circle's slip scale s_c = R2'/X_k [-].
    double circleSlip() const { return m_circleSlip; }
    /// Power factor at standstill of the fitted circle [-].
    double lockedRotorPowerFactor() const;
    /// The circle's own locked-rotor torque over rated torque [-].
    double calcLockedRotorTorqueRatio() const;

private:
    CurrentCircleParams m_params;
    double m_diameter = 0, m_magnetising = 0, m_circleSlip = 0;  // per unit of I_N; s_c
};

}  // namespace milldyn
