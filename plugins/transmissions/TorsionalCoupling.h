#pragma once
// TorsionalCoupling: a torsional spring-damper between two shafts, with a
// speed ratio when they turn at different speeds (belt, reducer).

#include <Simbody.h>

namespace milldyn {

/// Parameters of a TorsionalCoupling. All SI.
struct TorsionalCouplingParams {
    /// Torsional stiffness c referred to the driving shaft [N*m/rad], >= 0.
    double stiffness = 0;
    /// Viscous damping b referred to the driving shaft [N*m*s/rad], >= 0.
    double damping = 0;
    /// Speed ratio n = ω_from/ω_to in steady running [-], > 0. A belt with
    /// u_p = 3.12 from motor to millstone has n = 3.12; a model already
    /// reduced to one shaft has n = 1.
    double ratio = 1;
};

/**
 * Spring-damper between two pin-jointed shafts ("from" drives "to").
 *
 * <pre>
 *   twist    Δ = q_from − n·q_to          [rad, on the from-shaft]
 *   torque   T = c·Δ + b·Δ̇                [N*m, transmitted]
 *   from-shaft gets −T, to-shaft gets +n·T (mobility forces)
 *   potential energy  V = ½·c·Δ²
 * </pre>
 *
 * With n = 1 this is seed 003's coupling c(φ1 − φ2) + b(φ̇1 − φ̇2) (eqs 1-2,
 * corrected signs) and seed 004's M_{i,i+1} = C(φ_i − φ_{i+1}) (eq 4).
 * Power balance: −T·ω_from + n·T·ω_to = −T·Δ̇, i.e. the spring stores and the
 * damper dissipates b·Δ̇², nothing else. Conservative when b = 0. With
 * n = 1 and b = 0 it equals Simbody's Force::LinearBushing restricted to
 * the pin rotation (TorsionalCouplingTest checks against
 * Force::MobilityLinearSpring for a shaft coupled to ground). Twist is
 * measured from the zero of both pin angles.
 */
class TorsionalCoupling : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    TorsionalCoupling(const SimTK::MobilizedBody& from, const SimTK::MobilizedBody& to,
                      const TorsionalCouplingParams& params);

    double calcTwist(const SimTK::State& state) const;      ///< Δ [rad]
    double calcTwistRate(const SimTK::State& state) const;  ///< Δ̇ [rad/s]
    double calcTorque(const SimTK::State& state) const;     ///< T [N*m]
    const TorsionalCouplingParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& state) const override;

private:
    SimTK::MobilizedBody m_from;
    SimTK::MobilizedBody m_to;
    TorsionalCouplingParams m_params;
};

}  // namespace milldyn
