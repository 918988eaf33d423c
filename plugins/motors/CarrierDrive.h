#pragma once
// CarrierDrive: a carrier (or any shaft) made to follow a prescribed start
// law, with the torque that takes read from Simbody.

#include "plugins/scene/Scene.h"

#include <utility>

namespace milldyn {

struct CarrierDriveParams {
    bool exponential = true;   ///< true: ε = ε0 e^(−t/τ) from rest; false: steady speed
    double steadySpeed = 0;    ///< ω_y [rad/s] >= 0
    double accelerationTime = 1;  ///< t_p [s] > 0: ω(t_p) = ω_y (exponential law)
    double timeConstant = 1;   ///< τ [s] > 0 (the paper's e^(−t): τ = 1 s)
};

/**
 * Seed 000's start (Fig. 6): the carrier's acceleration is prescribed,
 * <pre>
 *   ε(t) = ε0 e^(−t/τ),  ε0 = ω_y / (τ (1 − e^(−t_p/τ))),
 *   ω(t) = ε0 τ (1 − e^(−t/τ))  from rest,
 * </pre>
 * or a steady speed ω_y (ε = 0; the body's initial_speed sets the speed it
 * holds, the law only its zero acceleration). The prescription is at acceleration level
 * (a Simbody Motion::Custom), so the angle and speed stay state variables
 * that a kinetostatic analysis may set. The drive torque is what Simbody
 * computes the prescribed motion needs: T = −findMotionForces (the sign
 * checked in docs/simbody-notes.md), so it includes inertia, gravity,
 * friction and every reaction the model computes.
 */
class CarrierDrive : public SimTK::Motion::Custom::Implementation {
public:
    explicit CarrierDrive(const CarrierDriveParams& p);
    Implementation* clone() const override { return new CarrierDrive(*this); }

    const CarrierDriveParams& params() const { return m_p; }
    double calcInitialAcceleration() const;   ///< ε0 [rad/s^2]
    double calcAcceleration(double t) const;  ///< ε(t) [rad/s^2]
    double calcSpeed(double t) const;         ///< ω(t) [rad/s]
    /// The motion the law gives from a start at time t0 with speed u0
    /// (ε depends on time only, so it integrates in closed form):
    /// u(t) = u0 + V(t) − V(t0), Δφ = (u0 − V(t0))(t − t0) + P(t) − P(t0),
    /// V(t) = ε0 τ (1 − e^(−t/τ)), P(t) = ε0 τ (t − τ (1 − e^(−t/τ)));
    /// V = P = 0 for the steady law. Returns {Δφ [rad], u(t) [rad/s]}.
    std::pair<double, double> calcAdvance(double t0, double u0, double t) const;

    SimTK::Motion::Level getLevel(const SimTK::State&) const override { return SimTK::Motion::Acceleration; }
    void calcPrescribedAcceleration(const SimTK::State& s, int nu, SimTK::Real* udot) const override;

private:
    CarrierDriveParams m_p;
};

}  // namespace milldyn
