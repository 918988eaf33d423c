#pragma once
// Closed form of a planetary mill with n drums rolling inside a fixed ring
// (or outside a fixed sun), charges turning with their drums, no friction:
// rigid-body mechanics from first principles, std + Eigen only. Knows
// nothing of Simbody or of the plugin's element; its parameters are its own.

#include <Eigen/Dense>

#include <vector>

namespace planetary_layout {

struct LayoutParameters {
    bool internal = true;         ///< drums inside a fixed ring (true) or outside a fixed sun
    int drums = 2;                ///< n, evenly spaced
    double firstDrumAngle = 0;    ///< θ0 [rad] of drum 1 on the carrier
    double ringRadius = 0;        ///< R [m]: pitch radius of the fixed gear
    double planetRadius = 0;      ///< r [m]: pitch radius of a drum's gear
    double pressureAngle = 0;     ///< [rad]
    double carrierMass = 0;       ///< m1 [kg], centre on the carrier axis A
    double carrierInertia = 0;    ///< J1 [kg*m^2] about A
    double drumMass = 0;          ///< m_b [kg], centre on the drum axis B
    double drumInertia = 0;       ///< J_b [kg*m^2] about B
    double drumRadius = 0;        ///< inner radius [m] (the charge's circle)
    double drumLength = 0;        ///< inner length [m]
    double bulkDensity = 0;       ///< ρ [kg/m^3] of the charge
    double fillHalfAngle = 0;     ///< γ [rad]: the charge is a segment of half-angle γ
    double chargeDirection0 = 0;  ///< β0 [rad]: direction of B→centroid at carrier angle 0
    double gravity = 0;           ///< g [m/s^2], along −y
};

/// Loads on drum k (its unit: shell + charge).
struct DrumLoads {
    Eigen::Vector2d bearingForce;  ///< force of the carrier on the drum at B [N], ground axes
    double tangentialForce = 0;    ///< F_t of the fixed gear on the drum along e_t = z × e_out [N]
    double separatingForce = 0;    ///< N = |F_t| tan(pressure angle) [N]
};

struct LayoutLoads {
    double driveTorque = 0;         ///< T on the carrier [N*m]
    Eigen::Vector2d carrierForce;   ///< force of ground on the carrier at A [N], ground axes
    std::vector<DrumLoads> drums;
};

/**
 * Kinematics (rolling without slip at the pitch point P; B the drum axis,
 * e_out = (B − A)/|B − A|, e_t = z × e_out):
 * <pre>
 *   internal: a = R − r, P = B + r e_out;  external: a = R + r, P = B − r e_out
 *   v_P = ω1 a e_t + ω2 z × (P − B) = 0  ⇒  ω2 = −ω1 a/r (internal), +ω1 a/r (external)
 *   ψ = λ q1 with λ = ω2/ω1: the drum's absolute angle; the charge centroid
 *   is at B + l_c u, u at angle β0 + ψ
 * </pre>
 * Segment of half-angle γ, radius r_d, length l (sector minus triangle):
 * <pre>
 *   m_z = ρ l r_d² (2γ − sin 2γ)/2,   l_c = 2 r_d³ sin³γ ρ l / (3 m_z)
 *   J_Bz = ρ l r_d⁴ (γ/2 − sin γ cos³γ/2 − sin³γ cos γ/6)   about B
 * </pre>
 * Reduced inertia (2 KE / ω1²), per drum |v_c|² = ω1² |a e_t + λ l_c z × u|²:
 * <pre>
 *   J_pr = J1 + Σ_k [ (m_b + m_z) a² + λ² (J_b + J_Bz) + 2 a λ m_z l_c (e_out,k · u_k) ]
 * </pre>
 * Loads (free bodies; unit k of mass M = m_b + m_z, centre at ρ_u = m_z l_c u / M from B):
 * <pre>
 *   a_B = a (ε1 e_t − ω1² e_out),  ε2 = λ ε1,  a_c = a_B + ε2 z × ρ_u − ω2² ρ_u
 *   about B:  s r F_t = J_B ε2 + M (ρ_u × a_B)_z − M (ρ_u × g)_z     (s = +1 internal, −1 external)
 *   gear on drum: F_t e_t − s N e_out   (N pushes the drum away from the fixed gear)
 *   F_B = M a_c − M g − (F_t e_t − s N e_out)
 *   carrier (centre at A):  F_A = Σ F_B,k − m1 g,   T = J1 ε1 + Σ (b_k × F_B,k)_z
 * </pre>
 * Energy gives the torque a second way: T = J_pr ε1 + ½ J_pr'(q1) ω1² + V'(q1).
 */
class PlanetaryLayoutOracle {
public:
    explicit PlanetaryLayoutOracle(const LayoutParameters& p);

    double calcArm() const;              ///< a [m]
    double calcDrumRateRatio() const;    ///< λ = ω2,abs / ω1 [-]
    double calcChargeMass() const;       ///< m_z [kg]
    double calcCentroidDistance() const; ///< l_c [m]
    double calcChargeAxisInertia() const;///< J_Bz [kg*m^2]

    double calcReducedInertia(double carrierAngle) const;  ///< J_pr(q1) [kg*m^2]
    double calcPotentialEnergy(double carrierAngle) const; ///< V(q1) [J], zero at A's height
    LayoutLoads calcLoads(double carrierAngle, double carrierRate, double carrierAcceleration) const;

    /// ε0 of ε = ε0 e^(−t/τ) reaching ω_y at t_p [rad/s^2].
    static double calcInitialAcceleration(double steadySpeed, double accelerationTime, double timeConstant);

private:
    LayoutParameters m_p;
};

}  // namespace planetary_layout
