// Closed-form oracle for gear meshes, shafts on two bearings and geared
// torsional chains (issue 19: the tumbling mill's girth-gear drive).
//
// Textbook statics and linear vibration only; it knows nothing of Simbody
// nor of ModelSpec, takes its own parameter structs, and states every
// result as the textbook writes it (so it cannot share a bug with the
// model it judges).
#pragma once

#include <array>
#include <vector>

namespace milldyn::oracles {

/// Forces in a helical (spur: β = 0) gear mesh transmitting torque T on a
/// gear of pitch radius r (Shigley, Mechanical Engineering Design §13-16;
/// Niemann–Winter, Maschinenelemente II §21):
/// <pre>
///   W_t = T / r,   W_r = W_t tan φ_n / cos ψ,   W_a = W_t tan ψ,
///   W   = W_t / (cos φ_n cos ψ)
/// </pre>
struct HelicalMeshForces {
    double tangential;  ///< W_t [N] (sign of T)
    double radial;      ///< W_r [N] >= 0
    double axial;       ///< W_a [N] (sign of T·ψ)
    double normal;      ///< W [N] >= 0
};
HelicalMeshForces helicalMeshForces(double torque, double pitchRadius, double normalPressureAngle,
                                    double helixAngle);

/// A load on a rigid shaft whose axis is z: a force (Fx, Fy, Fz) applied at
/// the point (x, y, z) relative to the axis (x, y: its offset from the
/// axis, which makes an axial force tilt the shaft).
struct ShaftLoad {
    double x = 0, y = 0, z = 0;     ///< [m]
    double fx = 0, fy = 0, fz = 0;  ///< [N]
};

/// The two radial support forces of a rigid shaft on simple supports at
/// z = zA and z = zB (a beam on two supports): moments about each support
/// of every load, in the xz and the yz plane,
/// <pre>
///   R_B = −Σ [F_j (z_j − z_A) + couple_j] / (z_B − z_A),   R_A = −Σ F_j − R_B
/// </pre>
/// with couple_j the moment of F_z,j about the support line through its
/// offset (F_z x_j in the xz plane, F_z y_j in the yz plane).
/// Returns {R_Ax, R_Ay, R_Bx, R_By} [N]: forces the supports exert on the shaft.
std::array<double, 4> twoSupportReactions(const std::vector<ShaftLoad>& loads, double zA, double zB);

/// (The natural frequencies of a geared chain reduced by ratio² are
/// TumblingMillOracle's gearedChainFrequencies.)
///
/// Torsional stiffness of a gear mesh on gear 1's shaft: a mesh stiffness k
/// [N/m] along the transverse line of action (the base circle's tangent)
/// acts at the base radius r_b1 = r1 cos α_t: k_t = k r_b1².
double meshTorsionalStiffness(double meshStiffness, double pitchRadius1, double normalPressureAngle,
                              double helixAngle);

}  // namespace milldyn::oracles
