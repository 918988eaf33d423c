#pragma once
// Clutch: a friction clutch between two shafts (an air clutch of a mill
// drive) whose torque capacity follows its pressure from an engage time,
// sticking up to its static capacity and sliding at a lower kinetic one.

#include "plugins/scene/Schedule.h"
#include "plugins/scene/StartSequence.h"

#include <Simbody.h>

namespace milldyn {

/// The friction torque of a slipping pair [N*m]: capacity·tanh(slip/ω_reg),
/// opposing the slip speed [rad/s]. Regularised so that a locked pair holds
/// any torque below its capacity at a creep slip ω_reg·atanh(T/capacity).
/// Shared by Clutch and Brake.
double calcFrictionTorque(double capacity, double slipSpeed, double regularisationSpeed);

/// The same with a sliding torque below the sticking one [N*m]:
/// capacity·(κ + (1 − κ)·exp(−(slip/ω_s)²))·tanh(slip/ω_reg), κ = kinetic
/// fraction (0, 1], ω_s the Stribeck speed over which sticking gives way to
/// sliding. κ = 1 is calcFrictionTorque.
double calcStickSlipTorque(double capacity, double kineticFraction, double slipSpeed, double regularisationSpeed,
                           double stribeckSpeed);

/// Capacity ramp: 0 before `start`, rising linearly to 1 over `rampTime`
/// [s] (> 0), 1 after.
double rampFraction(double time, double start, double rampTime);

/// Parameters of a Clutch. All SI.
struct ClutchParams {
    /// Static (sticking) torque capacity when engaged M_max [N*m], > 0.
    double capacity = 0;
    /// Engagement starts at this time [s], >= 0.
    double engageTime = 0;
    /// The capacity rises from 0 to M_max over this time [s], > 0.
    double rampTime = 0;
    /// Slip-speed regularisation ω_reg [rad/s], > 0: the creep scale of a
    /// locked pair.
    double regularisationSpeed = 1e-3;
    /// Sliding (kinetic) torque when engaged M_k [N*m], in (0, M_max];
    /// 0 means M_max (no difference between sticking and sliding).
    double kineticCapacity = 0;
    /// Stribeck speed ω_s [rad/s], > ω_reg: the slip over which the
    /// sticking torque gives way to the sliding one.
    double stribeckSpeed = 0.05;
    /// The pressure curve r(t) multiplying both capacities; when not
    /// constant it replaces the ramp (engageTime, rampTime).
    Schedule schedule;
};

/**
 * Friction clutch between two pin-jointed shafts, 1:1 ("from" drives "to").
 *
 * <pre>
 *   slip speed        Δω = ω_from − ω_to                       [rad/s]
 *   pressure          r(t) = min(max((t − t_e)/T, 0), 1)       (air clutch: pressure ramp)
 *                     or r(t) = the `schedule` (a pressure curve, Schedule.h)
 *   capacities        M_c(t) = M_max·r(t) sticking,  M_k·r(t) sliding,  κ = M_k/M_max
 *   torque            T = M_c(t)·(κ + (1 − κ)·exp(−(Δω/ω_s)²))·tanh(Δω/ω_reg)   [N*m, transmitted]
 *   from-shaft gets −T, to-shaft gets +T
 *   slip heat         P = T·Δω >= 0                              (an EnergyFlow dissipation)
 * </pre>
 *
 * Locked (|Δω| of a few ω_reg) the pair transmits what the train needs up
 * to the sticking capacity M_c, at a creep slip ≈ ω_reg·atanh(T/M_c)
 * (1e-3 rad/s: a torque of 0.76·M_c creeps at 1e-3 rad/s and heats
 * T·1e-3 W). Asked for more, it breaks loose; sliding (|Δω| >> ω_s) it
 * transmits the kinetic capacity κ·M_c (Coulomb friction), and it locks
 * again when the speeds meet and the torque the train needs is below M_c.
 * The regularised law is a smooth stand-in for the stick/slip switch: its
 * errors against the ideal one are of order ω_s in slip speed. The locked
 * pair is stiff (M_c/ω_reg per shaft inertia): integrate with CPodes.
 * Checked by ClutchBrakeTest (stick → slip → stick on two inertias against
 * the closed form) and the start oracle (clutchSlipEnergy).
 */
class Clutch : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    Clutch(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& from, const SimTK::MobilizedBody& to,
           const ClutchParams& params);

    double calcSlipSpeed(const SimTK::State& state) const;  ///< Δω [rad/s]
    double calcCapacity(const SimTK::State& state) const;   ///< sticking M_c(t) [N*m] (M_max·r(∞) once engaged for good)
    /// The pressure fraction r at `time` [-].
    double pressureAt(double time) const;
    /// The transmitted torque at slip speed Δω with sticking capacity M_c [N*m].
    double torqueAt(double capacity, double slipSpeed) const;
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
    double m_kineticFraction = 1;  // κ = M_k/M_max
    mutable SimTK::DiscreteVariableIndex m_engagedIndex;  // bool: engaged for good (engage())
};

}  // namespace milldyn
