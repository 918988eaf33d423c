#pragma once
// SegmentCharge: the grinding charge of a drum (balls and material) as its
// own body, a circular segment of the drum's cross-section.

#include "plugins/scene/Scene.h"

namespace milldyn {

/// How the charge moves relative to its drum.
enum class ChargeMotionMode {
    WithDrum,    ///< rigid with the drum (seed 000's J_pr (1), (5), (22))
    Held,        ///< held at the lag α in the carrier frame by a wall torque
                 ///< the kinetostatic analysis solves for (the papers' lag)
    DynamicLag,  ///< on its own pin, dragged by the wall: the lag follows
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
 * carrier frame as in seed 000 (22): the centroid direction is
 * u = sin α e_out + cos α e_t, e_out pointing from the carrier axis A to B,
 * e_t = z × e_out.
 *
 * - WithDrum: welded to the drum, turning with it (the papers' J_pr).
 * - Held: on a pin on the drum; the wall applies a torque T_w (drum on
 *   charge) that a kinetostatic analysis solves for so that the charge does
 *   not move in the carrier frame. Its power T_w·(ω_drum − ω_charge) is the
 *   power the wall spends sliding under the charge (grinding). Not a
 *   time-simulation model: T_w is an unknown of one instant.
 * - DynamicLag: on a free pin on the drum with the wall drag
 *   T = c_w (ω_drum − ω_charge); gravity and the carrier's centrifugal field
 *   restore it, and the lag settles where cos α = c_w ω_r/(m_z l_c ω1²(R ± r))
 *   without gravity. T·(ω_drum − ω_charge) is the grinding power (a Load).
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

    /// Angle of B→c from the ground's +x [rad], at Stage::Position.
    double calcDirection(const SimTK::State& s) const;
    /// Lag α in the carrier frame [rad], in (−π, π].
    double calcLag(const SimTK::State& s) const;
    /// Wall torque on the charge (drum on charge) [N*m], at Stage::Velocity.
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
};

}  // namespace milldyn
