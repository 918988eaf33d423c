#pragma once
// GearMesh: a planet gear (a drum's gear) on a carrier, rolling on a fixed
// sun gear (external rolling) or inside a fixed ring (internal rolling),
// as a holonomic Simbody constraint whose force acts at the pitch point
// along the line of action.

#include "plugins/scene/Scene.h"
#include "plugins/transmissions/GearPair.h"

namespace milldyn {

struct GearMeshParams {
    double fixedPitchRadius = 0;  ///< R [m] > 0: fixed sun (external) or ring (internal) gear
    double planetPitchRadius = 0; ///< r [m] > 0: the drum's gear
    bool internal = false;        ///< false: planet outside the sun; true: inside the ring
    double pressureAngle = 0;     ///< [rad] in [0, π/2): 20° for standard gears
};

/**
 * The carrier turns about the fixed gear's axis (its pin origin); the planet
 * turns on a pin on the carrier at distance a = R + r (external) or R − r
 * (internal) from that axis. Rolling without slip at the pitch point P keeps
 * the gear phase (seed 000 eq 4, 15; internal rolling ω2 = ω1(R − r)/r):
 * <pre>
 *   external:  P = B − r e_out,  perr = R q1 − r q2        (ω2,abs = ω1 (R + r)/r)
 *   internal:  P = B + r e_out,  perr = R q1 + r q2        (ω2,abs = −ω1 (R − r)/r)
 * </pre>
 * q1 the carrier's angle, q2 the planet's angle relative to the carrier, B
 * the planet's axis, e_out = (B − A)/|B − A|. The velocity error is the
 * planet material point's velocity at P along e_t = z × e_out,
 * v_P·e_t = R u1 ∓ r u2 (its radial part is zero for every motion).
 *
 * Force: the multiplier λ is the tangential mesh force; the fixed gear pushes
 * the planet at P with F_t = −λ along e_t and, along the line of action, with
 * the separating force N = |F_t| tan(pressure angle) (seed 000 eqs 17–19),
 * away from the fixed gear. N passes through B and does no work for any
 * motion the pins allow (its generalized force is zero), so it changes no
 * acceleration; it loads the planet's bearing and so appears in Simbody's
 * mobilizer reaction at B and at the carrier's axis A, as in the paper.
 * Because |λ| is not linear in λ, that holds only because N is workless
 * here; a gear whose radial direction were free would need a contact model.
 * The mesh geometry (pitch point, line of action, force components) is
 * GearPair's GearGeometry with the fixed gear as gear 1 (the ring when
 * internal) and the planet as gear 2, spur (β = 0).
 */
class GearMesh : public RollingConstraint {
public:
    /// Throws std::invalid_argument naming a bad parameter.
    GearMesh(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& carrier,
             const SimTK::MobilizedBody& planet, const GearMeshParams& p);
    Implementation* clone() const override { return new GearMesh(*this); }

    const GearMeshParams& params() const { return m_p; }
    /// Planet angle relative to the carrier that meshes with carrier angle
    /// `carrierAngle` [rad] (phase 0 at q1 = 0), and the matching speed.
    double calcPlanetAngle(double carrierAngle) const;
    double calcPlanetSpeed(double carrierSpeed) const;

    /// Tangential force of the fixed gear on the planet along e_t [N]
    /// (positive: drives the planet's centre forward), at Stage::Acceleration.
    double calcTangentialForce(const SimTK::State& s, const SimTK::Constraint& self) const;
    /// Separating force N = |F_t| tan(pressure angle) [N], >= 0.
    double calcSeparatingForce(const SimTK::State& s, const SimTK::Constraint& self) const;

    void addInPositionConstraintForces(const SimTK::State& s, const SimTK::Array_<SimTK::Real>& multipliers,
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;

private:
    GearMeshParams m_p;
    GearGeometry m_geometry;  // gear 1 the fixed gear, gear 2 the planet
    double m_side;  // −1 external, +1 internal: P = B + side·r·e_out
    SimTK::ConstrainedBodyIndex m_groundBody, m_carrierBody, m_planetBody;
};

}  // namespace milldyn
