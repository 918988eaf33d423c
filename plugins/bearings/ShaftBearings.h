#pragma once
// ShaftBearings: a shaft on two bearings at axial positions (a mill's two
// trunnions, a pinion's two bearings): each bearing's radial load split
// from the pin's reaction by statics, and journal friction per bearing.

#include "plugins/bearings/JournalFriction.h"

#include <array>

namespace milldyn {

class BevelShaftLoads;

struct ShaftBearingsParams {
    double position1 = 0;  ///< z1 [m] of bearing 1 in the shaft's frame (along its axis)
    double position2 = 0;  ///< z2 [m] != z1
    int thrustBearing = 1;  ///< 1 or 2: the locating bearing, which takes the whole thrust
    JournalFrictionParams friction;  ///< f, d, ω_s, coupling: the same for both bearings
};

/// A bevel mesh on the shaft (`mesh:`): its tooth force at the mean point,
/// which Simbody does not see, is added to the pin's reaction by statics.
struct ShaftBearingsMesh {
    const BevelShaftLoads* mesh = nullptr;  ///< Simbody owns it
    double position = 0;  ///< z_m [m]: the mean point's axial position in the shaft's frame
    double angle = 0;     ///< θ [rad]: direction of the mean point from the axis, pin frame, from x towards y
};

/**
 * The shaft is rigid and its pin (Simbody's mobilizer) carries force F and
 * moment M about the pin origin O (the body origin, z = 0), ground axes,
 * from Simbody's mobilizer reaction. Two radial supports at z1 ≠ z2 on the
 * axis are statically determinate (a beam on two supports):
 * <pre>
 *   F1 + F2 = F_xy,    z1·ẑ×F1 + z2·ẑ×F2 = M_xy
 *   ⇒  F2 = ((M_y, −M_x) − z1·F_xy) / (z2 − z1),   F1 = F_xy − F2
 * </pre>
 * The axial part F_z is the thrust, taken whole by the locating bearing
 * (`thrust_bearing: bearing_1 | bearing_2`; the other floats): reported as
 * the force of the housing on the shaft along the shaft's +z.
 *
 * With a bevel mesh (`mesh:`) the tooth force F at the mean point
 * P = (r_m cos θ, r_m sin θ, z_m) (pin frame; BevelShaftLoads::calcShaftForce)
 * is not in Simbody's reaction (milldyn turns the gears by torques about z
 * only), so it is added as the housing must carry it, rotated to ground axes:
 * <pre>
 *   F ← F − F_mesh,    M ← M − P × F_mesh     (M_z, the torque, unused)
 * </pre>
 * — the textbook shaft statics (Shigley, Mechanical Engineering Design,
 * §13-15, Example 13-8: bevel shaft bearing forces, one bearing taking the
 * thrust). More than two supports on a rigid shaft are statically
 * indeterminate: the element refuses them (the split would depend on the
 * supports' stiffness and alignment, which the model does not know).
 *
 * Friction (seed 000 eq 21 per bearing, JournalFriction's law):
 * M_i = |F_i|·f·d/2·tanh(u/ω_s); the torque applied is JournalFriction's
 * with the load |F1| + |F2| (kept from the last step the same way,
 * `coupling: consistent` with `reaction: lagged | iterated | extrapolated`,
 * or `coupling: first_order`: |F1| + |F2| of the frictionless mechanism,
 * seed 000 eq 21's convention), so the bearing torques add up to it when
 * the load is converged (consistent coupling). u is the shaft's speed relative
 * to its parent.
 */
class ShaftBearings : public JournalFriction {
public:
    ShaftBearings(const SimTK::SimbodyMatterSubsystem& matter, const MobilizerReactions& reactions,
                  const SimTK::MobilizedBody& body, const ShaftBearingsParams& p, const ShaftBearingsMesh& mesh = {});
    /// The two bearings' forces on the shaft [N], ground axes (z = 0), at Stage::Acceleration.
    std::array<SimTK::Vec3, 2> calcBearingForces(const SimTK::State& s) const;
    /// Thrust F_z [N] (force of the parent along the axis), with the mesh's.
    double calcAxialLoad(const SimTK::State& s) const;
    /// The pin's reaction with the mesh's tooth force: {moment about the
    /// pin origin, force}, ground axes [N*m, N].
    SimTK::SpatialVec calcShaftReaction(const SimTK::State& s) const;
    /// |F1| + |F2| [N]: the load the friction is computed from.
    double calcReaction(const SimTK::State& s) const override;
    /// Bearing i's friction torque from its current load [N*m].
    double calcBearingTorque(const SimTK::State& s, int i) const;
    const ShaftBearingsParams& shaftParams() const { return m_sp; }

private:
    const MobilizerReactions& m_allReactions;
    SimTK::MobilizedBody m_shaft;
    ShaftBearingsParams m_sp;
    ShaftBearingsMesh m_mesh;
};

}  // namespace milldyn
