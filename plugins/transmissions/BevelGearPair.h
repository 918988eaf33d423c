#pragma once
// BevelGearPair: a straight or spiral bevel mesh between two shafts whose
// axes intersect at the shaft angle Σ — the torsional ratio (rigid or
// compliant, as GearPair), and the tangential, axial and radial tooth forces
// on both shafts at the mean pitch point, signed.

#include "plugins/scene/Scene.h"

#include <string>

namespace milldyn {

enum class BevelLaw { Rigid, Compliant };

struct BevelGearParams {
    double pinionTeeth = 0, wheelTeeth = 0;  ///< z1, z2
    double meanPitchRadius = 0;  ///< r_m1 [m] > 0 of the pinion (r_m2 = r_m1 z2/z1)
    double shaftAngle = M_PI / 2;  ///< Σ [rad] in (0, π)
    double pressureAngle = 0;      ///< α_n [rad] in [0, π/2)
    double spiralAngle = 0;        ///< β_m [rad] in [0, π/2): 0 straight bevel
    int pinionHand = 1;            ///< +1 right-hand spiral, −1 left-hand (the wheel has the other)
    /// +1: the wheel's +z axis points away from the pitch cone apex, as the
    /// pinion's (ω2/ω1 = −z1/z2); −1: towards it (ω2/ω1 = +z1/z2).
    int wheelAxisSense = 1;
    BevelLaw law = BevelLaw::Rigid;
    double meshStiffness = 0, meshDamping = 0, backlash = 0;  ///< compliant [N/m], [N*s/m], [m]

    double wheelMeanPitchRadius() const { return meanPitchRadius * wheelTeeth / pinionTeeth; }
    /// δ1 [rad]: tan δ1 = sin Σ / (z2/z1 + cos Σ); δ2 = Σ − δ1.
    double pinionPitchAngle() const;
    double wheelPitchAngle() const { return shaftAngle - pinionPitchAngle(); }
    /// α_t at the mean point: tan α_t = tan α_n / cos β_m.
    double transversePressureAngle() const;
    /// Throws std::invalid_argument naming the bad value.
    void check() const;
};

/// The tooth force components on both gears for a tangential force F_t [N]
/// (positive: the mesh's torque on the pinion is −r_m1 F_t about its +z).
struct BevelForces {
    double tangential;    ///< F_t [N], signed as above
    double pinionAxial;   ///< on the pinion along its axis, + away from the cone apex [N]
    double pinionRadial;  ///< on the pinion, + towards its own axis (separating) [N]
    double wheelAxial;    ///< on the wheel, + away from the apex [N]
    double wheelRadial;   ///< on the wheel, + towards its own axis [N]
};

/**
 * Pinion forces at the mean point (Gleason's spiral-bevel formulas as in
 * Shigley, Mechanical Engineering Design, and Machinery's Handbook; with
 * β_m = 0 they are Shigley's straight-bevel eqs W_a = W_t tan α sin δ,
 * W_r = W_t tan α cos δ):
 * <pre>
 *   W_t = |F_t|
 *   W_a1 = W_t/cos β (tan α_n sin δ1 − σ sin β cos δ1)
 *   W_r1 = W_t/cos β (tan α_n cos δ1 + σ sin β sin δ1)
 * </pre>
 * σ = +1 (the textbook's upper signs) for a right-hand pinion driving
 * clockwise or a left-hand one driving counterclockwise, viewed from its
 * large end: the mesh torque on the pinion is then about +z (against a
 * clockwise, i.e. negative, rotation), so σ = hand · sign(−F_t) — the
 * spiral term follows the direction the tooth is loaded, whichever gear
 * drives. The wheel carries the opposite force; resolved on its axes
 * (both axes and the mean point in one plane, apex at the origin):
 * <pre>
 *   W_a2 = −W_a1 cos Σ + W_r1 sin Σ,    W_r2 = W_a1 sin Σ + W_r1 cos Σ
 * </pre>
 * (Σ = 90°: the wheel's thrust is the pinion's separating force and vice
 * versa; β = 0: W_a2 = W_t tan α sin δ2, W_r2 = W_t tan α cos δ2).
 */
BevelForces calcBevelForces(const BevelGearParams& p, double tangentialForce);

/**
 * What a bevel mesh puts on its two shafts besides the torque: the tooth
 * force at the mean point, which milldyn does not apply to the bodies (its
 * pins all turn about z and the intersecting axes are not drawn) and which a
 * ShaftBearings element with `mesh:` adds to its shaft's pin reaction by
 * statics. Both laws' elements implement it (Scene::findElement).
 */
class BevelShaftLoads {
public:
    virtual ~BevelShaftLoads() = default;
    virtual const BevelGearParams& bevelParams() const = 0;
    virtual SimTK::MobilizedBodyIndex pinionIndex() const = 0;
    virtual SimTK::MobilizedBodyIndex wheelIndex() const = 0;
    /// The tooth forces now (Stage::Acceleration for the rigid law).
    virtual BevelForces calcShaftForces(const SimTK::State& s) const = 0;
    /**
     * The tooth force on shaft `shaft` (the pinion or the wheel) in its pin's
     * frame, z the shaft's axis, with the mean point at angle θ from the
     * frame's x towards its y: e_r = (cos θ, sin θ, 0), e_θ = (−sin θ, cos θ, 0),
     * <pre>
     *   pinion:  F = W_a1 ẑ − W_r1 e_r − F_t e_θ
     *   wheel:   F = s W_a2 ẑ − W_r2 e_r − s F_t e_θ
     * </pre>
     * (the pinion's +z points away from the apex, the wheel's as s says; the
     * tangential parts give the torques −r_m1 F_t and −s r_m2 F_t about z).
     */
    SimTK::Vec3 calcShaftForce(const SimTK::State& s, SimTK::MobilizedBodyIndex shaft, double theta) const;
    /// The mean point's distance from the shaft's axis: r_m1 or r_m2 [m].
    double meanRadiusOn(SimTK::MobilizedBodyIndex shaft) const;
};

/**
 * Torsional law (pins about each shaft's own z, relative to a common
 * parent): δ = r_m1 q1 + s r_m2 q2, s the wheel's axis sense;
 * rigid δ = 0 (ω2/ω1 = −s z1/z2); compliant as GearPair's
 * (δ_b = δ cos α_t, F_b = k (δ_b ∓ j/2) + c δ̇_b, F_t = F_b cos α_t).
 * Torques: −r_m1 F_t on the pinion, −s r_m2 F_t on the wheel. The axial
 * and radial forces do no work about the axes; they are reported (for the
 * bearings) and not applied, since milldyn's pins all turn about z and the
 * intersecting axes are not drawn in space.
 */
class BevelMeshForce : public SimTK::Force::Custom::Implementation, public BevelShaftLoads {
public:
    BevelMeshForce(const SimTK::MobilizedBody& pinion, const SimTK::MobilizedBody& wheel, const BevelGearParams& p);
    double calcMeshDisplacement(const SimTK::State& s) const;  ///< δ [m]
    double calcMeshDisplacementRate(const SimTK::State& s) const;  ///< δ̇ [m/s]
    double calcTangentialForce(const SimTK::State& s) const;   ///< F_t [N]
    double calcDampingPower(const SimTK::State& s) const;      ///< [W] >= 0
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    const BevelGearParams& bevelParams() const override { return m_p; }
    SimTK::MobilizedBodyIndex pinionIndex() const override { return m_pinion.getMobilizedBodyIndex(); }
    SimTK::MobilizedBodyIndex wheelIndex() const override { return m_wheel.getMobilizedBodyIndex(); }
    BevelForces calcShaftForces(const SimTK::State& s) const override {
        return calcBevelForces(m_p, calcTangentialForce(s));
    }

private:
    SimTK::MobilizedBody m_pinion, m_wheel;
    BevelGearParams m_p;
    double m_cosAlphaT;
    double gap(double deltaB) const;
};

/// Rigid: r_m1 q1 + s r_m2 q2 = 0; the multiplier is F_t.
class BevelRollingConstraint : public SimTK::Constraint::Custom::Implementation {
public:
    BevelRollingConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& pinion,
                           const SimTK::MobilizedBody& wheel, double c1, double c2);
    Implementation* clone() const override { return new BevelRollingConstraint(*this); }
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
    void addInPositionConstraintForces(const SimTK::State& s, const SimTK::Array_<SimTK::Real>& multipliers,
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>&,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;

private:
    SimTK::ConstrainedMobilizerIndex m_mob1, m_mob2;
    double m_c1, m_c2;
};

/// The rigid law's BevelShaftLoads: a force element that applies nothing
/// (the constraint turns the gears) and reads F_t from the constraint's
/// multiplier, so ShaftBearings finds the rigid mesh as the compliant one.
class BevelRigidShaftLoads : public SimTK::Force::Custom::Implementation, public BevelShaftLoads {
public:
    BevelRigidShaftLoads(const SimTK::SimbodyMatterSubsystem& matter, SimTK::ConstraintIndex constraint,
                         const SimTK::MobilizedBody& pinion, const SimTK::MobilizedBody& wheel, const BevelGearParams& p)
        : m_matter(matter), m_constraint(constraint), m_pinion(pinion.getMobilizedBodyIndex()),
          m_wheel(wheel.getMobilizedBodyIndex()), m_p(p) {}
    void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    const BevelGearParams& bevelParams() const override { return m_p; }
    SimTK::MobilizedBodyIndex pinionIndex() const override { return m_pinion; }
    SimTK::MobilizedBodyIndex wheelIndex() const override { return m_wheel; }
    double calcTangentialForce(const SimTK::State& s) const {
        return m_matter.getConstraint(m_constraint).getMultipliersAsVector(s)[0];
    }
    BevelForces calcShaftForces(const SimTK::State& s) const override {
        return calcBevelForces(m_p, calcTangentialForce(s));
    }

private:
    const SimTK::SimbodyMatterSubsystem& m_matter;
    SimTK::ConstraintIndex m_constraint;
    SimTK::MobilizedBodyIndex m_pinion, m_wheel;
    BevelGearParams m_p;
};

}  // namespace milldyn
