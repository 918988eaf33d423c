#pragma once
// DiscDrag: the torque that turning discs in a bead mill's grinding medium
// (beads, material, liquid) take from their shaft (seed 001, eq 1).

#include "plugins/scene/Schedule.h"

#include <Simbody.h>

namespace milldyn {

/// Parameters of a DiscDrag. All SI.
struct DiscDragParams {
    enum class Law { Laminar, Turbulent };
    Law law = Law::Laminar;
    /// Density of the medium ρ_c [kg/m^3], > 0.
    double density = 0;
    /// Kinematic viscosity of the medium ν [m^2/s], > 0.
    double viscosity = 0;
    /// Disc radius r_d [m], > 0.
    double radius = 0;
    /// Number of identical discs k on this body [-], >= 1.
    int discs = 1;
    /// f(t) multiplying the torque (a medium filled in, a chamber drained;
    /// Schedule.h); default f = 1.
    Schedule schedule;
};

/**
 * Drag torque of k discs turning about the body's z axis in fluid at rest,
 * each wetted on both faces.
 *
 * <pre>
 *   Re = |ω|·r²/ν                                   (regime check)
 *   laminar (eq 1, von Kármán):  N = 0.616·π·ρ_c·ω²·r⁴·k·√(ν·|ω|)   [W]
 *                                T = N/|ω| = 0.616·π·ρ_c·r⁴·k·√(ν·|ω|³)
 *   turbulent (Schlichting, C_M = 0.146·Re^(-1/5), both faces):
 *                                T = 0.073·ρ_c·ω²·r⁵·Re^(-1/5)·k
 *   the torque opposes ω: applied as −f(t)·T·sign(ω) about the body's z axis,
 *   f the `schedule` (1 without one)
 * </pre>
 *
 * ω is the body's angular velocity component along its own z axis, so the
 * element works on a pin-jointed shaft and on any segment of a flexible
 * rotor alike. Both laws vanish with ω like |ω|^1.5 or |ω|^1.8: the torque is
 * continuously differentiable through standstill and needs no smoothing.
 * The laminar law holds for Re below about 3e5 (the `reynolds` probe tells);
 * eq (1) assumes the medium at rest far from the disc, which a filled
 * chamber only approximates (docs/bead_mill.md).
 */
class DiscDrag : public SimTK::Force::Custom::Implementation {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    DiscDrag(const SimTK::MobilizedBody& body, const DiscDragParams& params);

    /// ω about the body's z axis [rad/s] (Stage::Velocity).
    double calcSpeed(const SimTK::State& state) const;
    /// Re = |ω| r²/ν [-].
    double calcReynolds(const SimTK::State& state) const;
    /// Magnitude of the drag torque T(|ω|) [N*m], >= 0.
    double calcTorque(const SimTK::State& state) const;
    /// Power taken from the shaft T·|ω| [W], >= 0.
    double calcPower(const SimTK::State& state) const;
    /// T for a given |ω| [N*m] (no state needed).
    double calcTorqueAtSpeed(double omega) const;
    const DiscDragParams& params() const { return m_params; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody m_body;
    DiscDragParams m_params;
};

class Scene;
struct ElementSpec;
/// Adds a DiscDrag on `body` to a scene with its probes (NAME.torque,
/// NAME.power, NAME.reynolds) and its energy flow (a Load). Shared by the
/// DiscDrag element and the FlexibleRotor's discs.
const DiscDrag* addDiscDrag(Scene& scene, const std::string& name, const SimTK::MobilizedBody& body,
                            const DiscDragParams& params);

}  // namespace milldyn
