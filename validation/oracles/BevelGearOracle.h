// Closed-form oracle for bevel gear forces (issue 32): the textbook
// formulas at the mean point, no Simbody, own parameter struct.
//  - straight bevel: Shigley, Mechanical Engineering Design, §13-15:
//    W_t = T/r_m, W_r = W_t tan φ cos γ, W_a = W_t tan φ sin γ (γ the
//    gear's pitch angle; both thrusts away from the apex, both radial forces
//    towards the gear's own axis);
//  - spiral bevel: the Gleason formulas (as given in Shigley's earlier
//    editions and in Machinery's Handbook, "Bevel gearing, tooth loads"):
//    driving member
//      W_a = W_t/cos ψ (tan φ_n sin γ ∓ sin ψ cos γ)
//      W_r = W_t/cos ψ (tan φ_n cos γ ± sin ψ sin γ)
//    driven member
//      W_a = W_t/cos ψ (tan φ_n sin Γ ± sin ψ cos Γ)
//      W_r = W_t/cos ψ (tan φ_n cos Γ ∓ sin ψ sin Γ)
//    upper signs for a driving member with a right-hand spiral turning
//    clockwise, or a left-hand one turning counterclockwise, viewed from
//    its large end; a positive thrust points away from the cone apex, a
//    positive separating force away from the mating gear (towards the
//    gear's own axis);
//  - pitch angles for a shaft angle Σ: tan γ = sin Σ/(N_G/N_P + cos Σ), Γ = Σ − γ.
#pragma once

namespace milldyn::oracles {

struct BevelPairModel {
    double pinionTeeth = 0, gearTeeth = 0;
    double pinionMeanRadius = 0;  ///< r_m [m]
    double shaftAngle = 0;        ///< Σ [rad]
    double normalPressureAngle = 0;  ///< φ_n [rad]
    double spiralAngle = 0;       ///< ψ [rad], 0 straight
    bool pinionRightHand = true;
    bool pinionClockwiseFromLargeEnd = false;  ///< the driving pinion's sense
};

struct BevelLoads {
    double tangential = 0;                  ///< W_t [N] >= 0
    double pinionThrust = 0, pinionSeparating = 0;  ///< [N], signs as above
    double gearThrust = 0, gearSeparating = 0;      ///< [N]
    double pinionPitchAngle = 0, gearPitchAngle = 0;  ///< γ, Γ [rad]
    double speedRatio = 0;  ///< ω_P/ω_G magnitude: N_G/N_P
};

/// The pinion drives with torque |T| [N m].
BevelLoads bevelLoads(const BevelPairModel& m, double pinionTorque);

/// A gear shaft on two bearings A and B (a straddle- or overhung-mounted
/// bevel gear), its axis the x of a right-handed frame (x, y, z): the mean
/// point at x_m, at distance r from the axis along +y.
struct BevelShaftModel {
    double bearingA = 0, bearingB = 0;  ///< x_A, x_B [m], A != B
    double meshPosition = 0;            ///< x_m [m]
    double meanRadius = 0;              ///< r [m]
    double apexSide = 1;  ///< +1: "away from the apex" is +x; −1: −x
    /// +1: the mesh's tangential force on this gear points along +z (the
    /// gear is driven and turns +x-wise, or drives and turns −x-wise); −1: −z.
    double tangentialSense = 1;
};

/// The bearings' forces on the shaft: y components in the plane of the
/// axis and the mean point (+y: towards the mean point), z components
/// tangential.
struct BevelShaftReactions {
    double Ay = 0, Az = 0, By = 0, Bz = 0;  ///< [N]
    double radialA = 0, radialB = 0;        ///< |(Ay, Az)|, |(By, Bz)| [N]
    double thrust = 0;                      ///< on the shaft along +x, all at the locating bearing [N]
};

/**
 * Statics of the shaft as in Shigley, Mechanical Engineering Design,
 * Example 13-8 (bearing forces on a bevel gear shaft, one bearing taking the
 * thrust): the tooth force at (x_m, r, 0) is
 * (apexSide·W_a, −W_r, tangentialSense·W_t) — the thrust away from the apex,
 * the separating force towards the gear's own axis; moments about A:
 * <pre>
 *   xy plane:  (x_B − x_A) B_y − (x_m − x_A) W_r − r·apexSide·W_a = 0,   A_y = W_r − B_y
 *   xz plane:  (x_B − x_A) B_z + (x_m − x_A) W_tz = 0,                   A_z = −W_tz − B_z
 *   thrust:    −apexSide·W_a
 * </pre>
 * (the xy-plane moment of the thrust W_a at height r is −r·apexSide·W_a about +z).
 */
BevelShaftReactions bevelShaftReactions(const BevelShaftModel& m, double thrust, double separating, double tangential);

}  // namespace milldyn::oracles
