#pragma once
// GearPair: a spur or helical gear mesh between two shafts on pins on the
// same parent (pinion–girth gear, a reducer stage, a dual-pinion drive), rigid
// (a holonomic constraint) or compliant (mesh stiffness and damping along
// the line of action, optional backlash). GearGeometry is the one piece of
// mesh geometry (centre distance, pitch point, line of action, force
// components) that GearMesh (a planet on a fixed gear) uses too.

#include "plugins/scene/Scene.h"

#include <string>

namespace milldyn {

/**
 * The geometry of one mesh. Gear 1 and gear 2 have pitch radii r1, r2; in
 * an internal mesh gear 1 is the ring (r1 > r2) and gear 2 runs inside it.
 * <pre>
 *   centre distance   a = r1 + r2 (external),  a = r1 − r2 (internal)
 *   e12 = (c2 − c1)/|c2 − c1| in the plane normal to the axes (z),  e_t = z × e12
 *   pitch point       P = c1 + r1·e12            (both kinds)
 *   transverse pressure angle  tan α_t = tan α_n / cos β
 *   F_r = |F_t| tan α_n / cos β,   F_a = F_t tan β,   F_n = |F_t| / (cos α_n cos β)
 * </pre>
 * (the textbook helical-gear force triangle, e.g. Niemann–Winter, Shigley
 * §13-16: radial = tangential · tan α_n / cos β). F_t is the tangential
 * force gear 1 exerts on gear 2 along e_t; the radial force separates the
 * gears (pushes gear 2 along +e12 when external, −e12 when internal); the
 * axial force on gear 2 is +F_t tan β along z for a positive β (gear 1's
 * helix hand; gear 2 has the opposite hand in an external mesh).
 */
struct GearGeometry {
    double pitchRadius1 = 0;    ///< r1 [m] > 0 (the ring in an internal mesh)
    double pitchRadius2 = 0;    ///< r2 [m] > 0
    bool internal = false;      ///< false: external mesh; true: gear 2 inside ring 1
    double pressureAngle = 0;   ///< α_n [rad] in [0, π/2): normal pressure angle
    double helixAngle = 0;      ///< β [rad] in (−π/4, π/4): 0 for spur gears

    /// Throws std::invalid_argument naming a bad value (prefix `who`).
    void check(const std::string& who) const;
    /// a [m]: r1 + r2 or r1 − r2.
    double calcCentreDistance() const { return internal ? pitchRadius1 - pitchRadius2 : pitchRadius1 + pitchRadius2; }
    /// s = +1 external, −1 internal: rolling keeps r1·θ1 + s·r2·θ2 constant
    /// relative to the line of centres.
    double getRollingSign() const { return internal ? -1.0 : 1.0; }
    /// α_t [rad].
    double calcTransversePressureAngle() const;
    /// Relative tolerance on the centre distance: |a_pins − a| ≤ tol·a.
    static constexpr double kCentreDistanceTolerance = 1e-4;
    /// "" when `pinDistance` [m] fits the pitch radii, else the reason with both numbers.
    std::string checkCentreDistance(double pinDistance) const;

    /// Unit vector from centre 1 to centre 2 in the xy plane.
    static SimTK::Vec3 calcLineOfCentres(const SimTK::Vec3& c1, const SimTK::Vec3& c2);
    /// P on gear 1's pitch circle, c1 + r1·e12, and on gear 2's, c2 − s·r2·e12
    /// (z of c1, c2). The same point when the pins are exactly a apart;
    /// within the tolerance each gear takes the force on its own pitch
    /// circle, so the torques are exactly r1·F_t and r2·F_t.
    SimTK::Vec3 calcPitchPointOnGear1(const SimTK::Vec3& c1, const SimTK::Vec3& c2) const;
    SimTK::Vec3 calcPitchPointOnGear2(const SimTK::Vec3& c1, const SimTK::Vec3& c2) const;
    /// The force gear 1 exerts on gear 2 at P for tangential force Ft [N].
    SimTK::Vec3 calcForceOnGear2(double tangentialForce, const SimTK::Vec3& c1, const SimTK::Vec3& c2) const;
    double calcRadialForce(double tangentialForce) const;  ///< F_r >= 0 [N]
    double calcAxialForce(double tangentialForce) const;   ///< F_a [N], signed as F_t tan β
    double calcNormalForce(double tangentialForce) const;  ///< F_n >= 0 [N]
};

enum class GearPairLaw { Rigid, Compliant };

struct GearPairParams {
    GearGeometry geometry;
    GearPairLaw law = GearPairLaw::Rigid;
    double meshStiffness = 0;  ///< k [N/m] > 0 (compliant): along the transverse line of action
    double meshDamping = 0;    ///< c [N*s/m] >= 0 (compliant)
    double backlash = 0;       ///< j [m] >= 0 (compliant): play along the line of action
    double axialPosition = 0;  ///< z [m] of the mesh plane in the common parent's frame
    double teeth1 = 0;         ///< z1 (0: unknown)
    double teeth2 = 0;         ///< z2 (0: unknown)
};

/**
 * Both gears turn on pins on the same parent body (ground or a carrier),
 * so the line of centres is fixed in that parent and the rolling condition
 * is holonomic in the two pin angles q1, q2 (relative to the parent):
 * <pre>
 *   δ = r1·q1 + s·r2·q2          (s = +1 external, −1 internal)
 *   rigid:      δ = 0            (ω1/ω2 = −s·r2/r1)
 *   compliant:  δ_b = δ·cos α_t  (displacement along the transverse line of action)
 *               F_b = k·(δ_b ∓ j/2) + c·δ̇_b   when |δ_b| > j/2,  else 0
 *               F_t = F_b·cos α_t,   V = ½·k·(|δ_b| − j/2)²
 * </pre>
 * The mesh force (F_t, F_r, F_a of GearGeometry) is applied at the pitch
 * point P, in the mesh plane z = axial_position, to gear 2 and its opposite
 * to gear 1, so it loads both shafts' pins: the reactions (JointReaction,
 * ShaftBearings) see tangential, separating and axial force and the tilting
 * moments of their axial offsets. Only F_t does work (F_r passes through
 * both axes, F_a is along them), so the energy balance holds with |F_t| in
 * F_r. In the rigid law F_t is the constraint's multiplier. Mesh power:
 * F_t·r1·ω1 (gear 1 to gear 2); tooth-mesh frequency f_z = z1·|ω1|/(2π)
 * (relative to the parent). The initializer places gear 2 at δ = 0 from
 * gear 1 (angle and speed).
 */
class GearPairForce : public SimTK::Force::Custom::Implementation {
public:
    GearPairForce(const SimTK::MobilizedBody& gear1, const SimTK::MobilizedBody& gear2, const GearPairParams& p);
    const GearPairParams& params() const { return m_p; }
    double calcMeshDisplacement(const SimTK::State& s) const;  ///< δ [m]
    double calcTangentialForce(const SimTK::State& s) const;   ///< F_t [N]
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// Power the damping dissipates [W] >= 0 (0 out of contact).
    double calcDampingPower(const SimTK::State& s) const;

private:
    SimTK::MobilizedBody m_gear1, m_gear2;
    GearPairParams m_p;
    double m_cosAlphaT;
    double calcLineOfActionGap(double deltaB) const;  // δ_b beyond the backlash (0 inside it)
};

/**
 * The rolling condition of a gear mesh whose line of centres is fixed in
 * the frame the two angles are measured in: c1·q1 + c2·q2 = 0 in two pin
 * angles (a GearPair's r1 q1 ± r2 q2; a GearMesh's R q_carrier ∓ r q_planet),
 * at position, velocity and acceleration level. The mesh forces are the
 * derived class's (addInPositionConstraintForces).
 */
class RollingConstraint : public SimTK::Constraint::Custom::Implementation {
public:
    RollingConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& first,
                      const SimTK::MobilizedBody& second, double c1, double c2);

    void calcPositionErrors(const SimTK::State& s, const SimTK::Array_<SimTK::Transform, SimTK::ConstrainedBodyIndex>&,
                            const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& q,
                            SimTK::Array_<SimTK::Real>& perr) const override;
    void calcPositionDotErrors(const SimTK::State& s, const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>&,
                               const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qdot,
                               SimTK::Array_<SimTK::Real>& pverr) const override;
    void calcPositionDotDotErrors(const SimTK::State& s,
                                  const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>&,
                                  const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qdotdot,
                                  SimTK::Array_<SimTK::Real>& paerr) const override;

private:
    SimTK::ConstrainedMobilizerIndex m_mob1, m_mob2;
    double m_c1, m_c2;
};

class GearPairConstraint : public RollingConstraint {
public:
    GearPairConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& gear1,
                       const SimTK::MobilizedBody& gear2, const GearPairParams& p);
    Implementation* clone() const override { return new GearPairConstraint(*this); }
    /// F_t [N] from the multiplier, at Stage::Acceleration.
    double calcTangentialForce(const SimTK::State& s, const SimTK::Constraint& self) const;

    void addInPositionConstraintForces(const SimTK::State& s, const SimTK::Array_<SimTK::Real>& multipliers,
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;

private:
    GearPairParams m_p;
    SimTK::ConstrainedBodyIndex m_body1, m_body2;
    double m_z1 = 0, m_z2 = 0;  // the mesh plane in each gear's frame [m]
};

}  // namespace milldyn
