#pragma once
// ResistanceTorque: the load a working organ (millstone, drum, rotor) puts
// on its shaft.

#include "plugins/scene/Schedule.h"

#include <Simbody.h>

namespace milldyn {

/// Parameters of a ResistanceTorque. All SI.
struct ResistanceTorqueParams {
    enum class Law { SpeedLinear, Feed };
    Law law = Law::SpeedLinear;
    /// Constant part M0 of the resistance [N*m], >= 0 (eq 17). For the feed
    /// law: the idle resistance the feed adds to.
    double constantTorque = 0;
    /// Viscous part b2 [N*m*s/rad], >= 0 (eq 17).
    double viscousCoefficient = 0;
    /// Feed law (eq 16): feed q [kg/s] >= 0, coefficient a [N*m at q = 1
    /// kg/min] >= 0 (the paper's a = 4.8 with q in kg/min), exponent m > 0.
    double feedRate = 0;
    double feedCoefficient = 0;
    double feedExponent = 1;
    /// Speed ratio u from the working organ to the shaft the torque is
    /// applied to [-], > 0: the organ's torque is divided by u (seed 003
    /// reduces the millstone torque to the motor shaft through u_p = 3.12).
    double reductionRatio = 1;
    /// Width ωs of the regularisation near standstill [rad/s], > 0.
    double smoothingSpeed = 0.01;
    /// Feed law: time the feed is opened [s], >= 0; before it only the
    /// idle part acts (a mill is started empty).
    double feedStartTime = 0;
    /// f(t) multiplying the whole torque (roller lowering, a bed collapse);
    /// constant 1 by default.
    Schedule schedule;
};

/**
 * A load torque opposing the rotation of one pin-jointed shaft.
 *
 * <pre>
 *   speed_linear (seed 003 eq 17):  Mc(ω) = M0·tanh(ω/ωs) + b2·ω
 *   feed         (seed 003 eq 16):  Mc(ω) = (M0 + a·q^m/u)·tanh(ω/ωs) + b2·ω
 *                                    q in kg/min inside the power law
 *   the shaft gets −Mc as a mobility force; absorbed power Mc·ω >= 0
 *   before feed_start_time the feed term is absent (discrete state, so the
 *   opening of the feed is an integrator restart, not a jump inside a step)
 *   scheduled:  the shaft gets −f(t)·Mc(ω), f the `schedule` (Schedule.h),
 *               whose breakpoints the integrator stops at
 * </pre>
 *
 * A Coulomb-like constant torque has no value at ω = 0; tanh(ω/ωs) makes it
 * smooth, so the shaft comes to rest instead of reversing (|ω| ≪ ωs: the
 * torque is a stiff viscous one, M0/ωs). Away from standstill (ω > 10·ωs)
 * the difference from the constant is below 2·e^(−20)·M0 ≈ 4.2e-9·M0. Dissipative, never a
 * source; potential energy is 0. With M0 = 0 it reduces to a linear
 * viscous damper to ground (Simbody's Force::MobilityLinearDamper), which
 * ResistanceTorqueTest checks.
 */
class ResistanceTorque : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    ResistanceTorque(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                     const ResistanceTorqueParams& params);

    /// The torque magnitude at shaft speed ω [rad/s] with the feed on or
    /// off (positive when ω > 0), before the schedule's factor [N*m].
    double torqueAtSpeed(double omega, bool feeding = true) const;
    /// The constant part the law gives away from standstill, feeding [N*m].
    double constantPart() const { return m_idle + m_feedPart; }
    double calcTorque(const SimTK::State& state) const;
    const ResistanceTorqueParams& params() const { return m_params; }
    bool isFeeding(const SimTK::State& state) const;
    void setFeeding(SimTK::State& state, bool feeding) const;

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_shaft;
    ResistanceTorqueParams m_params;
    double m_idle = 0;
    double m_feedPart = 0;
    mutable SimTK::DiscreteVariableIndex m_feedingIndex;
};

}  // namespace milldyn
