#pragma once
// InductionMotor: the torque of an asynchronous motor on its shaft as a
// function of shaft speed.

#include <Simbody.h>

#include <limits>

namespace milldyn {

/// Parameters of an InductionMotor. All SI.
struct InductionMotorParams {
    enum class Law { Linear, Kloss };
    Law law = Law::Kloss;
    /// Rated (nameplate) torque Mn [N*m], > 0.
    double ratedTorque = 0;
    /// Rated speed ωn [rad/s], 0 < ωn < ωc.
    double ratedSpeed = 0;
    /// Synchronous speed ωc [rad/s], > 0.
    double synchronousSpeed = 0;
    /// Breakdown torque ratio λ = Mk/Mn [-], > 1. Kloss law only.
    double breakdownRatio = 2.2;
    /// Linear law only: the paper's printed M00 [N*m] and b0 [N*m*s/rad].
    /// When both are > 0 they replace the nameplate formula (3)-(4); seed
    /// 003 prints 1010 N*m / 6.428 N*m*s for a motor whose nameplate gives
    /// 1008 / 6.42, and Table 1 was computed with the printed pair.
    double linearStallTorque = 0;
    double linearSlope = 0;
    /// Time at which the supply is switched off [s]; +inf: never.
    double switchOffTime = std::numeric_limits<double>::infinity();
};

/**
 * Drive torque of an induction motor on one pin-jointed shaft.
 *
 * <pre>
 *   Linear working branch, seed 003 eqs (3)-(4), seed 004 eqs (1), (15):
 *     M(ω) = M00 − b0·ω,   M00 = Mn·ωc/(ωc − ωn),   b0 = Mn/(ωc − ωn)
 *   Kloss curve (start from rest):
 *     s = (ωc − ω)/ωc,  sn = (ωc − ωn)/ωc,  sk = sn·(λ + √(λ² − 1)),
 *     M(ω) = 2·Mk·s·sk/(s² + sk²),  Mk = λ·Mn        (M(ωn) = Mn exactly)
 *   Switched off: M = 0 (setOn(state, false); the registry's builder
 *   schedules that as a Scene switch event at switch_off_time).
 * </pre>
 *
 * The shaft gets +M as a mobility force about its pin axis; the reaction on
 * the stator (ground) is not modelled. Not conservative (an energy source);
 * potential energy is 0. The linear branch reaches ≈ 28·Mn at standstill
 * for the MMP-50 motors: it is valid only near ωc, so a start from rest
 * should use Kloss. The on/off state is a discrete state variable, so a
 * switch-off is an event the integrator restarts at, not a discontinuity
 * inside a step. Checked by InductionMotorTest against the closed forms
 * above, and by the burr-mill oracle (validation/oracles/BurrMillOracle.h).
 */
class InductionMotor : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    InductionMotor(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& shaft,
                   const InductionMotorParams& params);

    /// Torque at shaft speed ω [rad/s] with the supply on [N*m].
    double torqueAtSpeed(double omega) const;
    /// Torque the motor applies in this state (0 when off) [N*m].
    double calcTorque(const SimTK::State& state) const;
    bool isOn(const SimTK::State& state) const;
    void setOn(SimTK::State& state, bool on) const;

    /// Linear-law coefficients in use: M00 [N*m], b0 [N*m*s/rad].
    double linearStallTorque() const { return m_M00; }
    double linearSlope() const { return m_b0; }
    const InductionMotorParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_shaft;
    InductionMotorParams m_params;
    double m_M00 = 0;
    double m_b0 = 0;
    double m_slipRated = 0;
    double m_slipBreakdown = 0;
    // Allocated once per system in realizeTopology().
    mutable SimTK::DiscreteVariableIndex m_onIndex;
};

}  // namespace milldyn
