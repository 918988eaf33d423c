// Oracle for the tumbling-mill charge's power correlations and the frozen
// charge (issue 27), written from the published equations, independent of
// SegmentCharge and plugins/charges/ChargePowerLaw (its own parameter
// structs, standard library only):
//  - Bond's ball-mill power equation in the metric form of Rowland & Kjos
//    (1980) and Rowland (1982): kW per tonne of balls
//      kWb = 4.879 D^0.3 (3.2 − 3 V_p) C_s (1 − 0.1 / 2^(9 − 10 C_s)) + S_s,
//    the ball mass V_p (π D²/4) L ρ_b; no clipping (the formula as printed).
//  - Morrell's C-model (Morrell 1996, Trans. IMM C 105, Parts 1–2) net
//    power of a cylindrical mill without a slurry pool (θ_TO = θ_T).
//  - The frozen (packed) charge as a rigid block: its static unbalance
//    moment m g r_c sin θ at lag θ and the energy of its fall from θ_r,
//    m g r_c (1 − cos θ_r).
#pragma once

namespace milldyn::oracles {

struct BondBallMill {
    double diameter;          ///< D [m] inside the liners
    double length;            ///< L [m]
    double ballBulkDensity;   ///< ρ_b [kg/m^3] of the ball charge (voids included)
    double ballFill;          ///< V_p [1]: fraction of the mill volume the balls fill
    double ballSizeFactor;    ///< S_s [kW/t]
};
/// Bond's power per tonne of balls [kW/t] at fraction of critical speed C_s.
double bondKilowattsPerTonne(const BondBallMill& mill, double fractionOfCritical);
/// Bond's mill power [W]: kWb × ball mass in tonnes × 1000.
double bondPower(const BondBallMill& mill, double fractionOfCritical);

struct MorrellMill {
    double diameter;       ///< D [m] inside the liners
    double length;         ///< L [m]
    double chargeDensity;  ///< ρ_c [kg/m^3]
    double chargeFill;     ///< J_t [1]
};
/// Morrell's net power [W] (potential + kinetic terms) at fraction of
/// critical φ (critical speed 42.3/sqrt(D) rpm), gravity g [m/s^2].
double morrellNetPower(const MorrellMill& mill, double fractionOfCritical, double g);

/// Frozen charge: a rigid block of mass m [kg] whose centroid is r_c [m]
/// from the axis, at lag θ [rad] from the downward vertical.
double frozenUnbalanceTorque(double mass, double centroidRadius, double lag, double g);
/// Energy of the block's fall from release angle θ_r to hanging [J].
double frozenFallEnergy(double mass, double centroidRadius, double releaseAngle, double g);

}  // namespace milldyn::oracles
