#pragma once
// BreakawayResistance: a resistance whose static torque at rest exceeds its
// running law and lets go once the shaft moves (a packed crusher chamber, a
// conveyor under load, a cold gearbox).

#include "plugins/scene/Schedule.h"

#include <Simbody.h>

#include <string>

namespace milldyn {

/// Parameters of a BreakawayResistance. All SI.
struct BreakawayResistanceParams {
    /// Breakaway (static) torque M_s [N*m], >= running_torque: what the
    /// drive must exceed to move the shaft from rest.
    double staticTorque = 0;
    /// Constant part of the running law M_r [N*m], >= 0.
    double runningTorque = 0;
    /// Viscous part of the running law b [N*m*s/rad], >= 0.
    double viscousCoefficient = 0;
    /// Release speed ω_r [rad/s], > 0: the excess M_s − M_r has fallen to
    /// 1/e of itself at |ω| = ω_r.
    double releaseSpeed = 0.1;
    /// Width ω_s of the sign regularisation at standstill [rad/s], > 0 and
    /// at most release_speed/10 (so the static torque is nearly reached
    /// before it releases).
    double smoothingSpeed = 0.001;
    /// f(t) multiplying the whole torque (Schedule.h); default f = 1.
    Schedule schedule;
};

/**
 * A Stribeck-like resistance opposing the rotation of one pin-jointed shaft.
 *
 * <pre>
 *   M(ω) = [M_r + (M_s − M_r)·exp(−(ω/ω_r)²)]·tanh(ω/ω_s) + b·ω     (> 0 opposes +ω)
 *   the shaft gets −f(t)·M as a mobility force, f the `schedule` (1 without
 *   one); absorbed power f·M·ω >= 0
 * </pre>
 *
 * Stribeck's curve with a Gaussian decay (the form Armstrong-Hélouvry's
 * survey gives, exponent 2) and tanh for the sign. At rest the torque
 * is 0 (it does no work on a standing shaft); a drive torque T below the
 * static torque leaves the shaft creeping at ω ≈ ω_s·atanh(T/M_s) ≪ ω_r:
 * held, the breakaway not passed. A drive torque above M_s at every speed
 * up to a few ω_r passes it. The regularised law peaks slightly below M_s:
 * at ω = a·ω_s the shortfall is about M_s·2e^(−2a) + (M_s − M_r)·(a·ω_s/ω_r)²,
 * least near a ≈ 3.5 for ω_s/ω_r = 0.01 (0.3 % of M_s, the defaults) and
 * a ≈ 2.3 for 0.1 (7 %); the element reports the peak it reaches
 * (NAME.peak_torque, 20000 points up to 3·ω_r). The breakaway threshold
 * stated to a user is M_s.
 * Dissipative; potential energy 0.
 */
class BreakawayResistance : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    BreakawayResistance(const SimTK::MobilizedBody& shaft, const BreakawayResistanceParams& params);

    /// M(ω) [N*m], before the schedule's factor.
    double torqueAtSpeed(double omega) const;
    /// f(t)·M(ω) [N*m].
    double calcTorque(const SimTK::State& state) const;
    /// True while the shaft turns slower than the release speed (the
    /// breakaway is not passed).
    bool isHeld(const SimTK::State& state) const;
    /// Why a start stalled, if it is this element's breakaway: "" when the
    /// shaft is past the release speed at `state`.
    std::string stallReason(const std::string& name, const SimTK::State& state) const;
    const BreakawayResistanceParams& params() const { return m_params; }
    const SimTK::MobilizedBody& shaft() const { return m_shaft; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody m_shaft;
    BreakawayResistanceParams m_params;
};

}  // namespace milldyn
