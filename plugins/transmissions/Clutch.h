#pragma once
// Clutch: a friction clutch between two shafts (an air clutch of a mill
// drive) whose torque capacity is ramped up from an engage time.

#include "plugins/scene/StartSequence.h"

#include <Simbody.h>

namespace milldyn {

/// The friction torque of a slipping pair [N*m]: capacity·tanh(slip/ω_reg),
/// opposing the slip speed [rad/s]. Regularised so that a locked pair holds
/// any torque below its capacity at a creep slip ω_reg·atanh(T/capacity).
/// Shared by Clutch and Brake.
double calcFrictionTorque(double capacity, double slipSpeed, double regularisationSpeed);

/// Capacity ramp: 0 before `start`, rising linearly to 1 over `rampTime`
/// [s] (> 0), 1 after.
double rampFraction(double time, double start, double rampTime);

/// Parameters of a Clutch. All SI.
struct ClutchParams {
    /// Torque capacity when engaged M_max [N*m], > 0.
    double capacity = 0;
    /// Engagement starts at this time [s], >= 0.
    double engageTime = 0;
    /// The capacity rises from 0 to M_max over this time [s], > 0.
    double rampTime = 0;
    /// Slip-speed regularisation ω_reg [rad/s], > 0.
    double regularisationSpeed = 1e-3;
};

/**
 * Friction clutch between two pin-jointed shafts, 1:1 ("from" drives "to").
 *
 * <pre>
 *   slip speed        Δω = ω_from − ω_to                       [rad/s]
 *   capacity          M_c(t) = M_max·min(max((t − t_e)/T, 0), 1) (air clutch: pressure ramp)
 *   torque            T = M_c(t)·tanh(Δω/ω_reg)                 [N*m, transmitted]
 *   from-shaft gets −T, to-shaft gets +T
 *   slip heat         P = T·Δω >= 0                              (an EnergyFlow dissipation)
 * </pre>
 *
 * While slipping (|Δω| >> ω_reg) the torque is the capacity (Coulomb
 * friction); once the shafts lock it transmits what the load needs up to
 * the capacity, at a creep slip ω_reg·atanh(T/M_c) (1e-3 rad/s: a torque
 * of 0.76·M_c creeps at 1e-3 rad/s and heats T·1e-3 W). The locked pair is
 * stiff (M_c/ω_reg per shaft inertia): integrate with CPodes. Checked by
 * ClutchTest and the start oracle (clutchSlipEnergy).
 */
class Clutch : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    Clutch(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& from, const SimTK::MobilizedBody& to,
           const ClutchParams& params);

    double calcSlipSpeed(const SimTK::State& state) const;  ///< Δω [rad/s]
    double calcCapacity(const SimTK::State& state) const;   ///< M_c(t) [N*m] (M_max once engaged for good)
    double calcTorque(const SimTK::State& state) const;     ///< T [N*m]
    /// The engagement as a starting sequence: finished once the capacity is
    /// full and the pair is locked, |Δω| <= max(10·ω_reg, 1 % of |ω_from|);
    /// fully engaged but slipping, it waits on the driven shaft.
    StartSequenceState calcEngagement(const SimTK::State& state) const;
    /// Engages the clutch for good in `state` (steady running: the machine
    /// after its start): capacity M_max whatever the time.
    void engage(SimTK::State& state) const;
    bool isEngaged(const SimTK::State& state) const;
    const ClutchParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_from, m_to;
    ClutchParams m_params;
    mutable SimTK::DiscreteVariableIndex m_engagedIndex;  // bool: engaged for good (engage())
};

}  // namespace milldyn
