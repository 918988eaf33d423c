#pragma once
// SegmentCharge: the grinding charge of a drum (balls and material) as its
// own body, a circular segment of the drum's cross-section.

#include "plugins/scene/Scene.h"

#include <vector>

namespace milldyn {

/// How the charge moves relative to its drum.
enum class ChargeMotionMode {
    WithDrum,    ///< rigid with the drum (seed 000's J_pr (1), (5), (22))
    Held,        ///< held at the lag α in the carrier frame by a wall torque
                 ///< the kinetostatic analysis solves for (the papers' lag)
    DynamicLag,  ///< on its own pin, dragged by the wall: the lag follows
    TorqueArm,   ///< no body: held at a lag that is a condition, its weight's
                 ///< moment m·g·r_c·sin α loads the shell (tumbling mills)
    Frozen,      ///< no body: a packed block lifted with the shell until it
                 ///< breaks loose at the release angle and falls (issue 27)
};

/// What sets a torque-arm charge's load (plugins/charges/ChargePowerLaw.h).
enum class ChargePowerLaw {
    Lag,      ///< the weight's moment at the lag (constant or a table against φ)
    Bond,     ///< Bond's ball-mill power equation (1961; Rowland's metric form)
    MorrellC, ///< Morrell's C-model net power (1996)
};

/// What the lag α is measured from.
enum class LagReference {
    Vertical,       ///< from the downward vertical (gravity), positive in the
                    ///< +z sense, the sense of a positive drum speed
    CarrierRadius,  ///< from the tangent e_t in the carrier frame, u = sin α e_out + cos α e_t (seed 000 eq 22)
};

struct SegmentChargeParams {
    double drumRadius = 0;   ///< r [m] > 0: inner radius of the drum
    double length = 0;       ///< l [m] > 0: inner length of the drum
    double bulkDensity = 0;  ///< ρ [kg/m^3] > 0: balls + material + voids
    double halfAngle = 0;    ///< γ [rad] in (0, π]: segment of central angle 2γ
    ChargeMotionMode motion = ChargeMotionMode::WithDrum;
    double lag = 0;          ///< α [rad]: held position, u = sin α e_out + cos α e_t
    double initialDirection = -M_PI / 2;  ///< [rad] of B→c from +x at t = 0 (−90°: hanging)
    double wallDrag = 0;     ///< c_w [N*m*s/rad] >= 0: wall drag, DynamicLag
    LagReference lagFrom = LagReference::CarrierRadius;
    /// [m/s^2] the gravity the scene applies (the vertical, the torque arm's
    /// weight and the critical speed); zero when the model has none.
    SimTK::Vec3 gravity = SimTK::Vec3(0);
    /// TorqueArm: lag against the fraction of critical speed φ = |ω|/ω_c
    /// (both empty: the constant `lag`); φ strictly increasing [1], lags [rad].
    std::vector<double> lagTableSpeed, lagTableLag;
    double smoothingSpeed = 0;  ///< ω_ε [rad/s] > 0: TorqueArm lag · tanh(ω/ω_ε)
    ChargePowerLaw powerLaw = ChargePowerLaw::Lag;  ///< TorqueArm: what sets the load
    double ballSizeFactor = 0;      ///< S_s [W/kg] (= kW/t), Bond's ball-size term
    /// φ_s [1] > 0: below this fraction of critical speed a correlation's
    /// torque is held at its value at φ_s (the start rule; no P/ω at ω = 0).
    double startSpeedFraction = 0.5;
    double releaseAngle = 0;  ///< θ_r [rad] in (0, π): Frozen, where the packed block breaks loose
    double safeAngle = 0;     ///< θ_s [rad] in (0, π): Frozen, the protection's trip angle
    double frozenInitialLag = 0;  ///< θ_0 [rad]: Frozen, the block's lag at t = 0
};

/**
 * The charge fills a circular segment of half-angle γ of the drum's
 * cross-section (seed 000 eqs 3, 6, 13; seed 002 eq 12):
 * <pre>
 *   m_z  = ρ l r² (2γ − sin 2γ)/2                        fill = (2γ − sin 2γ)/(2π)
 *   l_c  = 4 r sin³γ / (3 (2γ − sin 2γ))                  (4r/(3π) at γ = π/2)
 *   J_Bz = m_z r² (12γ − 4 sin 2γ − sin 4γ)/(12 (2γ − sin 2γ))   about the drum axis
 * </pre>
 * The body sits on the drum's axis B (a weld to the drum, or a pin on the
 * drum), its mass centre at l_c from B. Its lag α is measured in the
 * convention `lag_from` names (below): from the carrier radius as in seed
 * 000 (22), u = sin α e_out + cos α e_t, e_out pointing from the carrier
 * axis A to B, e_t = z × e_out; or from the downward vertical.
 *
 * - WithDrum: welded to the drum, turning with it (the papers' J_pr).
 * - Held: on a pin on the drum; the wall applies a torque T_w (drum on
 *   charge) that a kinetostatic analysis solves for so that the charge does
 *   not move in the carrier frame (ground, for a drum on a fixed axis). Its power T_w·(ω_drum − ω_charge) is the
 *   power the wall spends sliding under the charge (grinding). Not a
 *   time-simulation model: T_w is an unknown of one instant.
 * - DynamicLag: on a free pin on the drum with the wall drag
 *   T = c_w (ω_drum − ω_charge); gravity and the carrier's centrifugal field
 *   restore it, and the lag settles where cos α = c_w ω_r/(m_z l_c ω1²(R ± r))
 *   without gravity. T·(ω_drum − ω_charge) is the grinding power (a Load).
 *   Steady running (solveSteadyState, linearize) has the charge standing
 *   still in the carrier frame, at its running lag.
 * - TorqueArm (tumbling mills, the torque-arm model of mill power: the
 *   charge's weight times its centroid's horizontal offset from the axis):
 *   the charge is no body; it stays at the lag α from the downward
 *   vertical while the shell turns under it. Its
 *   mass and its inertia about the axis J_Bz are added to the shell's (the
 *   charge circulates with the shell, so the motor accelerates it and the
 *   bearings carry its weight through the shell's pin); its weight's line of
 *   action, shifted from the axis to the centroid, adds the couple
 * <pre>
 *   M = (r_c u(α_ε)) × (m g) · e_z = −m·|g|·r_c·sin α_ε      (gravity −y)
 *   α_ε = α(φ)·tanh(ω/ω_ε),  φ = |ω|/ω_c,  ω_c = sqrt(|g|/r) = sqrt(2|g|/D)
 *   P = −M·ω = m·|g|·r_c·sin α_ε·ω                            (grinding power)
 * </pre>
 *   ω the shell's absolute speed about z. α(φ) is the constant `lag`, or a
 *   table of lag against φ interpolated by a monotone cubic (Fritsch–Carlson:
 *   C¹, no overshoot), constant beyond its ends. The tanh makes the load
 *   odd and smooth in ω: a start from rest is well posed (zero load at rest,
 *   96 % of it at ω = 2ω_ε); the breakaway torque of a charge lifted rigidly
 *   before it slumps is not modelled. ω_c omits the ball radius (the
 *   sqrt(g/(R − r_ball)) form needs the ball size, which this element does
 *   not take). With `power_law` a published correlation (Bond 1961 in
 *   Rowland's metric form; Morrell's 1996 C-model net power:
 *   plugins/charges/ChargePowerLaw.h has the equations) sets the load:
 * <pre>
 *   M = −T(φ_h)·tanh(ω/ω_ε),  T(φ) = P(φ)/(φ ω_c),  φ_h = max(|ω|/ω_c, φ_s)
 * </pre>
 *   so that M ω = −P(φ) running and the start is continuous, zero at rest
 *   (φ_s = start_speed_fraction: below it the torque is held). The lag
 *   output is then the equivalent asin(T/(m |g| r_c)). Lag laws take lags
 *   in [0, 90°] only. Hogg–Fuerstenau is not implemented (its published
 *   form could not be checked here).
 * - Frozen (a packed charge, issue 27): no body; mass and J_Bz on the
 *   shell's axis; the block turns with the shell, its lag θ = θ_0 + the
 *   shell's turn since t = 0:
 * <pre>
 *   M = −m |g| r_c sin θ  while packed,  0 once released
 *   released: a located event, the witness θ_r − θ falling through zero
 *   (Simbody's event localization: the peak is m |g| r_c sin θ_r to it)
 *   fall energy m |g| r_c (1 − cos θ_r), checked against safe_angle θ_s
 * </pre>
 *
 * Lag conventions (docs/charges.md has the picture): `Vertical` measures α
 * from the downward vertical (the gravity direction in the xy-plane; −y
 * without gravity), positive in the +z sense (the sense of a positive drum
 * speed: a drum turning +z lifts its charge to positive α), so a mill gives
 * the same lag wherever its axis stands; `CarrierRadius` is the papers' α
 * (seed 000 eq 22), defined only when the drum's axis moves on a carrier.
 */
class SegmentCharge : public SimTK::Force::Custom::Implementation {
public:
    SegmentCharge(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& carrier,
                  const SimTK::MobilizedBody& drum, const SegmentChargeParams& p);

    /// Mass, centroid distance and inertia about the axis of a segment.
    static double calcFillFraction(double halfAngle);
    static double calcHalfAngleForFill(double fill);
    double calcMass() const;
    double calcCentroidDistance() const;
    double calcAxisInertia() const;

    void setBody(const SimTK::MobilizedBody& charge) { m_charge = charge; }
    const SegmentChargeParams& params() const { return m_p; }

    /// Critical speed ω_c = sqrt(|g|/r) [rad/s] (0 without gravity).
    double calcCriticalSpeed() const;
    /// Lag α(φ) at the fraction of critical speed φ (TorqueArm) [rad].
    double calcLagAtSpeedFraction(double phi) const;
    /// The TorqueArm lag at absolute shell speed ω [rad/s], smoothing included.
    double calcTorqueArmLag(double omega) const;
    /// The TorqueArm couple on the shell [N*m] at shell speed ω [rad/s].
    double calcTorqueArmTorque(double omega) const;
    /// A correlation's net power [W] at fraction of critical φ >= 0 (Bond,
    /// MorrellC; the lag law: m g r_c sin α(φ) ω).
    double calcLawPower(double phi) const;
    /// The load's magnitude [N*m] at φ before the smoothing: P(φ)/(φ ω_c),
    /// held at its φ_s value below φ_s for a correlation.
    double calcLawTorque(double phi) const;
    /// Fraction of critical speed of the drum, ω/ω_c (signed) [1].
    double calcFractionOfCritical(const SimTK::State& s) const;
    /// The weight's largest moment m |g| r_c [N*m] (the lag at 90°).
    double calcUnbalanceMoment() const;

    /// Frozen: the packed block's lag θ from the downward vertical [rad]
    /// (θ_0 + the drum's turn since t = 0), whether it has been released,
    /// and the largest lag reached while packed (at the integrator's step
    /// ends; θ_r exactly at the release).
    double calcFrozenLag(const SimTK::State& s) const;
    bool isReleased(const SimTK::State& s) const;
    double getAngleReached(const SimTK::State& s) const;
    /// Frozen: the couple on the shell [N*m]: −m |g| r_c sin θ while packed,
    /// 0 once released (the fallen charge lies at the bottom).
    double calcFrozenTorque(const SimTK::State& s) const;
    /// Frozen: the release's event witness θ_r − θ while packed, −1 once
    /// released (it falls through zero at the release angle) [rad].
    double calcReleaseWitness(const SimTK::State& s) const;
    /// Frozen: the latch (released, angle reached) from state `s` at an
    /// accepted step end; returns 1 if it changed, else 0.
    double updateFrozenLatch(SimTK::State& s) const;
    /// Frozen: the value the latch should take at `s` (1 released, 0 not).
    double calcFrozenLatch(const SimTK::State& s) const;
    void setFrozenStart(SimTK::State& s) const;
    /// Absolute speed of the drum about z [rad/s] (Stage::Velocity).
    double calcDrumSpeed(const SimTK::State& s) const;

    /// Direction of the downward vertical from +x [rad] (gravity's, −90° without).
    double calcDownAngle() const;
    /// Angle of B→c from the ground's +x [rad], at Stage::Position.
    double calcDirection(const SimTK::State& s) const;
    /// Lag α in the element's convention [rad], in (−π, π].
    double calcLag(const SimTK::State& s) const;
    /// Wall torque on the charge (drum on charge) [N*m], at Stage::Velocity;
    /// TorqueArm: the load torque on the shell, opposite.
    double calcWallTorque(const SimTK::State& s) const;
    /// ω_drum − ω_charge [rad/s].
    double calcSlipSpeed(const SimTK::State& s) const;
    /// Held: the kept wall torque and its setter.
    double getHeldTorque(const SimTK::State& s) const;
    void setHeldTorque(SimTK::State& s, double torque) const;
    /// Angle of the charge relative to the drum that puts its centroid at
    /// direction `direction` [rad] from +x, in state `s` (Position).
    double calcRelativeAngleFor(const SimTK::State& s, double direction) const;
    /// Direction from +x [rad] of the lag α in state `s` (Position).
    double calcDirectionOfLag(const SimTK::State& s, double lag) const;

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& s) const override;

private:
    const SimTK::SimbodyMatterSubsystem& m_matter;
    SimTK::MobilizedBody m_carrier, m_drum, m_charge;
    SegmentChargeParams m_p;
    mutable SimTK::DiscreteVariableIndex m_heldTorque;
    /// Frozen: the drum's angle at which the block hangs (θ = 0), the
    /// released latch (0/1) and the largest lag reached while packed.
    mutable SimTK::DiscreteVariableIndex m_hangAngle, m_released, m_angleReached;
};

}  // namespace milldyn
