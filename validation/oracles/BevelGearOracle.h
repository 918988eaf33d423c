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

}  // namespace milldyn::oracles
