#pragma once
// PlanetaryGearSet: one spur planetary stage — sun, n planets on pins on a
// carrier, ring — with any of sun, ring and carrier driven, free or fixed
// (an omitted member is fixed to ground), rigid (one holonomic constraint
// per mesh) or compliant (stiffness, damping and backlash per mesh) meshes,
// the mesh forces at the pitch points of both meshes of every planet, and
// the planets' load sharing with a stated carrier-pin position error.

#include "plugins/scene/Scene.h"
#include "plugins/transmissions/GearPair.h"

#include <vector>

namespace milldyn {

enum class PlanetaryLaw { Rigid, Compliant };

struct PlanetaryGearSetParams {
    double sunTeeth = 0, planetTeeth = 0, ringTeeth = 0;  ///< z_s, z_p, z_r (z_r = z_s + 2 z_p)
    double module = 0;         ///< m [m] > 0: pitch radius r = m z / 2
    double pressureAngle = 0;  ///< α [rad] in [0, π/2)
    PlanetaryLaw law = PlanetaryLaw::Rigid;
    double sunMeshStiffness = 0, sunMeshDamping = 0, sunBacklash = 0;     ///< [N/m], [N*s/m], [m]
    double ringMeshStiffness = 0, ringMeshDamping = 0, ringBacklash = 0;  ///< [N/m], [N*s/m], [m]
    /// e_k [m] per planet: the pin's position error along e_t (the tangent in
    /// the +z rotation sense at the planet's nominal place); compliant only.
    std::vector<double> pinPositionErrors;
    double axialPosition = 0;  ///< z [m] of the mesh plane in ground

    double sunRadius() const { return module * sunTeeth / 2; }
    double planetRadius() const { return module * planetTeeth / 2; }
    double ringRadius() const { return module * ringTeeth / 2; }
    /// Throws std::invalid_argument naming the bad value.
    void check() const;
};

/// Which member a mesh joins to the planet.
enum class PlanetaryMeshKind { Sun, Ring };

/**
 * The kinematics of one mesh of planet k. Angles: θ_G of the gear (sun or
 * ring) and θ_C of the carrier about the set's axis (z, absolute; 0 for a
 * member fixed to ground); q_k the planet's pin angle relative to the
 * carrier. Pitch radii r_s, r_p, r_r = r_s + 2 r_p.
 * <pre>
 *   sun mesh (external):   δ_s,k = r_s (θ_s − θ_C) + r_p q_k − e_k
 *   ring mesh (internal):  δ_r,k = r_r (θ_r − θ_C) − r_p q_k − e_k
 * </pre>
 * δ > 0: the gear's flank has advanced into the planet's along e_t (z × e_k,
 * e_k the unit vector from the axis to planet k's centre), so the gear
 * pushes the planet with F_t > 0 along +e_t. The two rolling conditions
 * δ_s = δ_r = 0 give Willis' equation (Müller, Die Umlaufgetriebe, eq 2.1):
 *   r_s (ω_s − ω_C) + r_r (ω_r − ω_C) = 0,  (ω_s − ω_C)/(ω_r − ω_C) = −z_r/z_s.
 * The mesh force acts at the pitch point of each gear (GearGeometry with the
 * gear as gear 1, the planet as gear 2): F_t along e_t, the separating force
 * |F_t| tan α radially (pushes the planet outwards from the sun, inwards
 * from the ring). Its generalized forces are −F_t ∂δ/∂(θ_G, θ_C, q_k): the
 * carrier is loaded through the planet's pin (Simbody's joint reaction).
 */
struct PlanetaryMesh {
    PlanetaryMeshKind kind;
    int planet = 0;          ///< index k
    double gearRadius = 0;   ///< r_s or r_r [m]
    double planetRadius = 0; ///< r_p [m]
    double pinError = 0;     ///< e_k [m]
    double sign() const { return kind == PlanetaryMeshKind::Sun ? 1.0 : -1.0; }
    GearGeometry geometry(double pressureAngle) const;
};

/// The members of a set: ground for a fixed one.
struct PlanetaryMembers {
    SimTK::MobilizedBody sun, ring, carrier;
    bool sunFixed = false, ringFixed = false, carrierFixed = false;
    std::vector<SimTK::MobilizedBody> planets;
    SimTK::Vec3 axis;  ///< a point of the set's axis in ground [m]
    const SimTK::MobilizedBody& gear(PlanetaryMeshKind k) const {
        return k == PlanetaryMeshKind::Sun ? sun : ring;
    }
    bool gearFixed(PlanetaryMeshKind k) const { return k == PlanetaryMeshKind::Sun ? sunFixed : ringFixed; }
    double angle(const SimTK::State& s, const SimTK::MobilizedBody& m, bool fixed) const;
    double speed(const SimTK::State& s, const SimTK::MobilizedBody& m, bool fixed) const;
    /// δ of a mesh [m] and its rate [m/s].
    double calcDeflection(const SimTK::State& s, const PlanetaryMesh& mesh) const;
    double calcDeflectionRate(const SimTK::State& s, const PlanetaryMesh& mesh) const;
    /// e_k (from the axis to planet k's centre, in the xy plane) at this state.
    SimTK::Vec3 calcRadialDirection(const SimTK::State& s, int planet) const;
};

/**
 * Compliant meshes, as GearPair's compliant law per mesh: δ_b = δ cos α,
 * F_b = k (δ_b ∓ j/2) + c δ̇_b when |δ_b| > j/2 (else 0), F_t = F_b cos α,
 * V = ½ k (|δ_b| − j/2)².
 */
class PlanetaryMeshForces : public SimTK::Force::Custom::Implementation {
public:
    PlanetaryMeshForces(const PlanetaryMembers& members, const std::vector<PlanetaryMesh>& meshes,
                        const PlanetaryGearSetParams& p);
    double calcTangentialForce(const SimTK::State& s, int mesh) const;  ///< F_t [N]
    double calcDampingPower(const SimTK::State& s) const;                ///< [W] >= 0
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;

private:
    PlanetaryMembers m_members;
    std::vector<PlanetaryMesh> m_meshes;
    PlanetaryGearSetParams m_p;
    double m_cosAlpha;
    double stiffness(const PlanetaryMesh& m) const;
    double damping(const PlanetaryMesh& m) const;
    double backlash(const PlanetaryMesh& m) const;
    double gap(const PlanetaryMesh& m, double deltaB) const;
};

/**
 * A rigid mesh: δ = 0 (no pin error) at position, velocity and acceleration
 * level; the multiplier λ is F_t, the force the gear exerts on the planet
 * along e_t. With both meshes of every planet rigid, the ring constraints of
 * n − 1 planets are redundant (the load split is statically indeterminate):
 * Simbody's least-squares multipliers share the load equally, which is the
 * perfect set; unequal sharing needs the compliant law.
 */
class PlanetaryMeshConstraint : public SimTK::Constraint::Custom::Implementation {
public:
    PlanetaryMeshConstraint(SimTK::SimbodyMatterSubsystem& matter, const PlanetaryMembers& members,
                            const PlanetaryMesh& mesh, double pressureAngle, double axialPosition);
    Implementation* clone() const override { return new PlanetaryMeshConstraint(*this); }

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
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;

private:
    PlanetaryMesh m_mesh;
    GearGeometry m_geometry;
    double m_axialPosition;
    SimTK::Vec3 m_axis;
    bool m_hasGear, m_hasCarrier;
    SimTK::ConstrainedMobilizerIndex m_gearMob, m_carrierMob, m_planetMob;
    SimTK::ConstrainedBodyIndex m_gearBody, m_planetBody;
    // Σ c·q over the constrained mobilizers, from q, q̇ or q̈ (template over the accessor).
    template <class Get> double combine(Get get) const;
};

}  // namespace milldyn
