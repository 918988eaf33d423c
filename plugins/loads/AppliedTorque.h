#pragma once
// AppliedTorque: a torque source on one shaft, given as a torque and a
// schedule (a hydraulic drive, a test rig's load motor, a torque step).

#include "plugins/scene/Schedule.h"

#include <Simbody.h>

namespace milldyn {

/// Parameters of an AppliedTorque. All SI.
struct AppliedTorqueParams {
    /// M0 [N*m], signed: + turns the shaft in its + sense (about +z).
    double torque = 0;
    /// f(t) multiplying M0 (constant 1 by default).
    Schedule schedule;
};

/**
 * A torque source on a pin-jointed shaft, independent of its speed.
 *
 * <pre>
 *   the shaft gets M(t) = M0·f(t) as a mobility force (+ about +z)
 *   power into the shaft P = M(t)·ω (an EnergyFlow source; < 0 when it brakes)
 * </pre>
 *
 * A drive given as its torque (no machine behind it): a step, a ramp or a
 * table in time through `schedule`, whose breakpoints the integrator stops
 * at. Not conservative; potential energy 0. Checked by ScheduleTest (a
 * ramped torque on one inertia against ω(t) in closed form).
 */
class AppliedTorque : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    AppliedTorque(const SimTK::MobilizedBody& shaft, const AppliedTorqueParams& params);

    /// M(t) [N*m].
    double torqueAt(double time) const { return m_params.torque * m_params.schedule.factorAt(time); }
    /// M0·f at the schedule's clock in `state` (its time, or since its trigger).
    double calcTorque(const SimTK::State& state) const { return m_params.torque * m_params.schedule.factorAt(state); }
    const AppliedTorqueParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody m_shaft;
    AppliedTorqueParams m_params;
};

}  // namespace milldyn
