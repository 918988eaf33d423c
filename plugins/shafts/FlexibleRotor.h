#pragma once
// FlexibleRotor: an overhung rotor shaft (bead mill, seed 001) as a chain of
// rigid shaft segments joined by bending and torsion springs, on two radial
// bearings, carrying discs on the overhang.

#include "plugins/loads/DiscDrag.h"

#include <Simbody.h>

#include <string>
#include <vector>

namespace milldyn {

/// Parameters of a FlexibleRotor. All SI. Positions are along the shaft
/// axis from the rear bearing A (at the drive body's origin).
struct FlexibleRotorParams {
    double shaftDiameter = 0;   ///< d [m] > 0
    double youngsModulus = 0;   ///< E [Pa] > 0
    double shearModulus = 0;    ///< G [Pa] > 0
    double shaftDensity = 0;    ///< [kg/m^3] > 0
    double span = 0;            ///< L_p, bearing A to bearing B [m] > 0
    double overhang = 0;        ///< a, bearing B to the shaft end [m] > 0
    /// Target number of rigid segments over L_p + a, >= 2: nodes are put at
    /// both bearings, the seal and every disc, and each interval between
    /// them is cut into round(length/h) equal pieces, h = (L_p + a)/segments
    /// (at least one), so the built count may differ a little.
    int segments = 0;
    int discs = 0;              ///< k >= 0
    double discDiameter = 0;    ///< D_d [m] > 0
    double discThickness = 0;   ///< [m] > 0
    double discDensity = 0;     ///< [kg/m^3] > 0
    double firstDiscOffset = 0; ///< first disc centre from bearing B [m] > 0
    double discPitch = 0;       ///< L_d, centre to centre [m] > 0
    double sealOffset = 0;      ///< L_y, seal from bearing B [m] > 0
    double discUnbalance = 0;   ///< m·e of each disc, along the segments' x [kg*m] >= 0
    double bearingStiffness = 0;  ///< radial (and, at A, axial) [N/m] > 0
    double bearingDamping = 0;    ///< radial viscous [N*s/m] >= 0
    double stiffnessDamping = 0;  ///< β: joint damping = β·joint stiffness [s] >= 0
};

/**
 * Lumped (Hencky) model of a uniform Euler–Bernoulli shaft with torsion.
 *
 * <pre>
 *   segments i of length h_i between nodes z_i (nodes at both bearings, the
 *   seal and every disc), rigid, each with its shaft mass μh_i (μ = ρπd²/4),
 *   transverse inertia μh_i(h_i²/12 + d²/16), polar μh_i·d²/8;
 *   joints at the inner nodes: Gimbal (body-fixed x-y-z angles q0..q2, u = q̇),
 *     bending springs  k_b = E·I/h̄  on q0, q1   (I = πd⁴/64)
 *     torsion spring   k_t = G·J/h̄  on q2       (J = πd⁴/32)
 *     h̄ = (h_{i−1} + h_i)/2, the length the node's curvature stands for;
 *   segment 0 on the drive body: Bushing (3 angles, 3 translations), only
 *     a torsion spring G·J/(h_0/2) on its z angle (bearing A is a simple
 *     support);
 *   bearings A (z = 0) and B (z = L_p): F = −k·Δ_radial − c·v_radial at the
 *     shaft centreline in ground, plus −k·Δ_axial at A (A locates axially);
 *   discs at nodes z_j = L_p + offset + j·pitch: m_d = ρ_d·π·D²/4·t, polar
 *     m_d D²/8, diametral m_d(3D²/4 + t²)/12, mass centre at e = unbalance/m_d
 *     off the axis; half of each disc on each segment meeting at its node
 *     (their mean rotation is the beam's slope there, to O(h²));
 *   gravity: the model's own (`gravity:` at the top of the model file, a
 *     Force::UniformGravity on every body); the deflection probes measure
 *     along ground −y, so give it as [0, −g, 0].
 * </pre>
 *
 * This is the Hencky bar chain: its nodal deflections are the central
 * finite differences of E·I·w'' = M, so it converges to the Euler–Bernoulli
 * beam as h → 0 with error O(h²) (docs/bead_mill.md measures it against
 * validation/oracles/BeadMillOracle). Nodes at the supports and loads
 * matter: a bearing or a disc inside a rigid segment spoils the order. Small deflections are assumed in the springs (linear in
 * the Euler angles); the spin itself is the drive body's pin angle, so it
 * may be any size. The shaft's rotary inertia (d²/16 term) is included, as
 * in a Rayleigh beam. Conservative when the damping keys are 0.
 */
class FlexibleRotor : public SimTK::Force::Custom::Implementation {
public:
    /// Builds the segment bodies on `drive` (a pin on ground, turning about
    /// its z axis: the rotor's spin). Throws std::invalid_argument naming a
    /// bad parameter.
    FlexibleRotor(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& drive,
                  const FlexibleRotorParams& params);

    const FlexibleRotorParams& params() const { return m_params; }
    const std::vector<SimTK::MobilizedBody>& segments() const { return m_segments; }
    double getLength() const { return m_params.span + m_params.overhang; }
    /// Node positions z_0 = 0 .. z_n = L_p + a [m] (n segments).
    const std::vector<double>& getNodes() const { return m_nodes; }
    int getNumSegments() const { return static_cast<int>(m_nodes.size()) - 1; }
    double getDiscMass() const;                               ///< [kg]
    double getDiscDiametralInertia() const;                   ///< about a diameter [kg*m^2]
    double getDiscPosition(int j) const;                      ///< z of disc j [m]
    double getSealPosition() const { return m_params.span + m_params.sealOffset; }
    /// The segment holding position z, and z's offset on it [m].
    int segmentAt(double z, double& local) const;

    /// Displacement of the shaft centreline at z from its undeformed place,
    /// in ground [m] (Stage::Position).
    SimTK::Vec3 calcDisplacement(const SimTK::State& state, double z) const;
    /// Component along ground −y (gravity's direction in the shipped
    /// models) [m]: the static deflection.
    double calcDeflection(const SimTK::State& state, double z) const;
    /// Component along ground x (the other bending plane) [m].
    double calcLateral(const SimTK::State& state, double z) const;
    /// Radial force on bearing A (0) or B (1) [N] (Stage::Velocity).
    double calcBearingForce(const SimTK::State& state, int bearing) const;

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& state) const override;
    /// Power dissipated by joint and bearing damping [W] (Stage::Velocity).
    double calcDissipation(const SimTK::State& state) const;

private:
    SimTK::Vec3 bearingStretch(const SimTK::State& s, int bearing, SimTK::Vec3& velocity) const;

    FlexibleRotorParams m_params;
    SimTK::MobilizedBody m_drive;
    std::vector<SimTK::MobilizedBody> m_segments;
    SimTK::Vec3 m_base;                     // bearing A in ground [m]
    std::vector<double> m_nodes;            // z of the nodes [m]
    std::vector<double> m_bending, m_torsion;  // joint i's springs [N*m/rad] (index 0: drive end)
};

}  // namespace milldyn
