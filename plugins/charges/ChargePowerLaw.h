#pragma once
// ChargePowerLaw: published correlations of the net power a tumbling mill's
// charge draws, as pure functions of the mill's size, fill and speed
// (no Simbody). SegmentCharge's `power_law` (motion: torque_arm) turns the
// power into the torque on the shell, T = P/ω.
//
// Speeds are fractions φ of the critical speed ω_c = sqrt(2 g/D), D the
// diameter inside the liners (ball radius neglected), as both correlations
// define it (Bond's and Morrell's N_c = 42.3/sqrt(D) rpm, D in m).
//
// Bond (1961; metric form as given by Rowland & Kjos 1980, Rowland 1982):
//   kWb = 4.879 D^0.3 (3.2 − 3 V_p) φ (1 − 0.1 / 2^(9 − 10 φ)) + S_s
// kW per metric tonne of balls (= W/kg), D [m] inside liners, V_p the
// fraction of the mill volume the ball charge fills (bulk, voids included),
// S_s the ball-size ("slide") factor [kW/t]. Bond's figure is the power at
// the mill's pinion shaft of a wet overflow ball mill. The speed factor
// φ (1 − 0.1·2^(10φ − 9)) peaks at φ = 0.94 and reaches zero at
// φ0 = 0.9 + log2(10)/10 = 1.2322; beyond, where the formula would go
// negative, the factor is taken as zero (an extrapolation: Bond's data are
// from mills run below critical speed).
//
// Morrell's C-model (Morrell 1996, "Power draw of wet tumbling mills and its
// relationship to charge dynamics", Parts 1 and 2, Trans. IMM C 105,
// C43–C53 and C54–C62; restated in Napier-Munn et al. 1996, JKMRC
// Monograph 2), net (charge-motion) power of the cylindrical section:
//   P_net = π g L N_m r_m / (3 (r_m − z r_i)) · [2 r_m³ − 3 z r_m² r_i + r_i³ (3z − 2)]
//             · ρ_c (sin θ_S − sin θ_T)
//         + L ρ_c (N_m r_m π / (r_m − z r_i))³ · [(r_m − z r_i)⁴ − r_i⁴ (z − 1)⁴]
//   z   = (1 − J)^0.4532
//   θ_T = 2.5307 (1.2796 − J)(1 − e^(−19.42 (φ_c − φ))) + π/2         (toe)
//   θ_S = π/2 − (θ_T − π/2)[(0.3386 + 0.1041 φ) + (1.54 − 2.5673 φ) J]  (shoulder)
//   φ_c = 0.35 (3.364 − J) when φ ≤ 0.35 (3.364 − J), else φ_c = φ     (centrifuging)
//   r_i = r_m sqrt(1 − 2π β J / (2π + θ_S − θ_T))                       (charge's inner surface)
//   β   = t_c/(t_f + t_c),  t_c = (2π − θ_T + θ_S)/(2π N̄),  N̄ = N_m/2
//   t_f = sqrt(2 r̄ (sin θ_S − sin θ_T)/g),  r̄ = (r_m/2)(1 + sqrt(1 − 2π J/(2π + θ_S − θ_T)))
// N_m [rev/s], r_m [m] inside liners, L [m], ρ_c [kg/m³] the charge's
// density, J the charge's volume fraction; angles [rad] from the
// horizontal. The slurry-pool term ρ_p (sin θ_T − sin θ_TO) of overflow
// mills is left out (θ_TO = θ_T: a grate-discharge mill, no pool), and the
// conical ends' term too (a cylindrical mill). Morrell's gross power is
// no-load + k·P_net, k = 1.26: the net power here is the charge's alone.
// Above φ_c = 0.35 (3.364 − J) (fully centrifuged: θ_T = θ_S = π/2) only
// the kinetic term remains; it keeps growing as φ³, outside the model's data.

namespace milldyn {
namespace charge_power {

/// Bond's speed factor φ (1 − 0.1/2^(9 − 10 φ)) [1], clipped at zero
/// beyond φ0 = 1.2322 (negative φ: the factor of |φ|).
double calcBondSpeedFactor(double phi);
/// Bond: net power per unit ball mass [W/kg] (= kW/t) at fraction of
/// critical φ, diameter D [m], ball-charge volume fraction V_p, ball-size
/// factor S_s [W/kg]; total clipped at zero.
double calcBondSpecificPower(double diameter, double fill, double phi, double ballSizeFactor);

/// Morrell's C-model angles and charge radius at (J, φ).
struct MorrellCharge {
    double toe = 0;          ///< θ_T [rad]
    double shoulder = 0;     ///< θ_S [rad]
    double innerRadius = 0;  ///< r_i [m]
    double z = 0;            ///< (1 − J)^0.4532
    bool valid = false;      ///< false where the model's charge does not exist (2πβJ ≥ 2π + θ_S − θ_T)
};
MorrellCharge calcMorrellCharge(double millRadius, double fill, double phi, double g);
/// Morrell: net power [W] of a cylindrical mill of radius r_m [m] inside
/// liners and length L [m], charge density ρ_c [kg/m³], fill J, fraction
/// of critical φ > 0, gravity g [m/s²]. NaN where the charge is not valid.
double calcMorrellNetPower(double millRadius, double length, double chargeDensity, double fill, double phi,
                           double g);

}  // namespace charge_power
}  // namespace milldyn
