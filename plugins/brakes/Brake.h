#pragma once
// Brake: a friction brake (run-out) or a backstop (no roll-back) between a
// shaft and the ground.

#include "plugins/scene/Schedule.h"

#include <Simbody.h>

#include <limits>

namespace milldyn {

/// Parameters of a Brake. All SI.
struct BrakeParams {
    enum class Mode { Brake, Backstop };
    Mode mode = Mode::Brake;
    /// Brake torque when applied, or the backstop's holding capacity [N*m], > 0.
    double capacity = 0;
    /// Brake: applied from this time [s] (>= 0; +inf: never), over ramp_time.
    double applyTime = std::numeric_limits<double>::infinity();
    double rampTime = 0.1;
    /// Speed regularisation ω_reg [rad/s], > 0.
    double regularisationSpeed = 1e-3;
    /// Brake: f(t) multiplying the capacity; when not constant it replaces
    /// the ramp (applyTime, rampTime).
    Schedule schedule;
};

/**
 * Friction between one pin-jointed shaft and the ground (the stator).
 *
 * <pre>
 *   brake:    T = −M_b·r(t)·tanh(ω/ω_reg),  r(t) = min(max((t − t_a)/T_r, 0), 1)
 *             or r(t) = the `schedule` (Schedule.h), its breakpoints located
 *   backstop: T = −M_b·tanh(min(ω, 0)/ω_reg)   (free forwards, holds backwards)
 *   heat      P = −T·ω >= 0                     (an EnergyFlow dissipation)
 * </pre>
 * The friction law and the ramp are the Clutch's (calcFrictionTorque,
 * rampFraction) with the ground as the other side. A held shaft creeps at
 * ω_reg·atanh(T/M_b). Checked by BrakeTest and the start oracle (a braked
 * run-out of an inertia: t = J·ω0/(M_b + M_c)).
 */
class Brake : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    Brake(const SimTK::MobilizedBody& shaft, const BrakeParams& params);

    double calcTorque(const SimTK::State& state) const;  ///< T on the shaft [N*m]
    /// Torque at shaft speed ω [rad/s] and time t [s] [N*m].
    double torqueAt(double omega, double time) const;
    const BrakeParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody m_shaft;
    BrakeParams m_params;
};

}  // namespace milldyn
