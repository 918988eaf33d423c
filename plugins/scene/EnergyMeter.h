#pragma once
// EnergyMeter: integrates every energy flow the scene's elements declare,
// so a run can close its energy balance.

#include "plugins/scene/Scene.h"

namespace milldyn {

/**
 * Applies no force. Allocates one auxiliary state z_i per EnergyFlow of the
 * scene and sets ż_i = P_i (its power), so the integrator carries the work
 * integrals W_i = ∫ P_i dt at its own accuracy — no quadrature over
 * samples. With them
 * <pre>
 *   ΔKE + ΔPE = W_sources − W_loads − W_dissipated       (exact, per run)
 * </pre>
 * and the residual of that identity measures the integration error. Built
 * by the SceneBuilder after every element, so it sees all their flows.
 */
class EnergyMeter : public SimTK::Force::Custom::Implementation {
public:
    EnergyMeter(const SimTK::GeneralForceSubsystem& forces, std::vector<EnergyFlow> flows);

    /// Work done by flow i since the start of the run [J].
    double work(const SimTK::State& state, std::size_t i) const;
    const std::vector<EnergyFlow>& flows() const { return m_flows; }

    void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;
    void realizeAcceleration(const SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    std::vector<EnergyFlow> m_flows;
    mutable SimTK::ZIndex m_first;
};

}  // namespace milldyn
