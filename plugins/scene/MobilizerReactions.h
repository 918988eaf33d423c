#pragma once
// MobilizerReactions: Simbody's mobilizer reaction forces of a state,
// computed once per realization and shared by every element that needs a
// joint reaction (journal friction, joint-reaction outputs).

#include <Simbody.h>

namespace milldyn {

/**
 * calcMobilizerReactionForces costs a pass over the whole tree; three
 * journals and three reaction outputs used to make six passes per
 * evaluation. This element keeps the result in a lazy cache entry of the
 * matter subsystem that depends on its Acceleration stage: any change of
 * q, u, time, a force or a discrete variable invalidates that stage and
 * with it the entry, so a value is never stale, and it is computed at most
 * once per realization.
 *
 * Needs a state realized to Stage::Acceleration (the matter's accelerations;
 * inside a force's realizeAcceleration they already are). Applies no force.
 * Built once per Scene (Scene::mobilizerReactions()).
 */
class MobilizerReactions : public SimTK::Force::Custom::Implementation {
public:
    explicit MobilizerReactions(const SimTK::SimbodyMatterSubsystem& matter) : m_matter(matter) {}

    /// Reactions of every mobilized body, indexed by MobilizedBodyIndex, in
    /// ground axes: [moment, force] of the parent on the body at the
    /// mobilizer's M-frame origin [N*m, N].
    const SimTK::Vector_<SimTK::SpatialVec>& get(const SimTK::State& s) const;
    /// The force part for one body [N], ground axes.
    SimTK::Vec3 getForce(const SimTK::State& s, const SimTK::MobilizedBody& body) const {
        return get(s)[body.getMobilizedBodyIndex()][1];
    }

    void realizeTopology(SimTK::State& s) const override;
    void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    const SimTK::SimbodyMatterSubsystem& m_matter;
    mutable SimTK::CacheEntryIndex m_entry;
};

}  // namespace milldyn
