// Closed-form oracle for a spur planetary stage (issue 32): Willis'
// kinematics, the static mesh and planet-bearing forces with the load
// shared by compliant planets whose carrier pins are out of place, and the
// natural frequencies of the purely torsional planetary model.
//
// Textbook models only (no Simbody, no ModelSpec; own parameter structs):
//  - Willis' equation, H. W. Müller, Die Umlaufgetriebe (1971) eq (2.1):
//    (ω_s − ω_c)/(ω_r − ω_c) = i_0 = −z_r/z_s;
//  - statics of the planet (moment and force about its pin) and of the sun;
//  - the rotational planetary model of Lin & Parker, "Analytical
//    characterization of the unique properties of planetary gear free
//    vibration", J. Vib. Acoust. 121 (1999) 316-321, with the translational
//    degrees of freedom suppressed: mesh deflections along the line of
//    action δ_sn = u_s + u_n − u_c cos α, δ_rn = u_r − u_n − u_c cos α with
//    u_j = r_j cos α θ_j for sun, ring and planets (base radii) and
//    u_c = (r_s + r_p) θ_c, planet rotations absolute (written here in the
//    angles), and the planet mode of multiplicity n − 1 in which sun, ring
//    and carrier are at rest.
#pragma once

#include <vector>

namespace milldyn::oracles {

/// Willis: the third speed from two (ring fixed: ω_r = 0, and so on).
double willisCarrierSpeed(double sunTeeth, double ringTeeth, double sunSpeed, double ringSpeed);
double willisSunSpeed(double sunTeeth, double ringTeeth, double ringSpeed, double carrierSpeed);
double willisRingSpeed(double sunTeeth, double ringTeeth, double sunSpeed, double carrierSpeed);

struct PlanetaryStageModel {
    double sunTeeth = 0, planetTeeth = 0, ringTeeth = 0;
    double module = 0;         ///< [m]
    double pressureAngle = 0;  ///< α [rad]
    int planets = 0;           ///< n
    double sunMeshStiffness = 0, ringMeshStiffness = 0;  ///< along the line of action [N/m]
    double sunInertia = 0, ringInertia = 0, carrierInertia = 0;  ///< about the axis [kg m^2]
    double planetInertia = 0;  ///< about its own axis [kg m^2]
    double planetMass = 0;     ///< [kg]
};

/// Static forces with torque T_s [N m] on the sun (about +z) reacted by the
/// ring and the carrier, each planet's pin at tangential position error e_k
/// [m] (compliant meshes, no backlash, every mesh in contact):
/// <pre>
///   F_k = T_s/(n r_s) − 2 k_t (e_k − ē),   k_t = cos²α k_s k_r/(k_s + k_r)
/// </pre>
/// (planet moment balance F_sun,k = F_ring,k, the meshes in series, Σ r_s F_k = T_s).
struct PlanetaryStatics {
    std::vector<double> meshForce;     ///< F_k [N]: tangential, sun on planet = ring on planet
    std::vector<double> bearingForce;  ///< 2 F_k [N]: carrier's force on planet k, against e_t
    double sunTorque = 0;      ///< torque of the meshes on the sun, −r_s Σ F_k [N m]
    double ringTorque = 0;     ///< −r_r Σ F_k [N m]
    double carrierTorque = 0;  ///< (r_s + r_r) Σ F_k [N m]
    double loadSharingFactor = 0;  ///< n max F_k / Σ F_k
};
/// Rigid meshes: pass empty errors (equal sharing). Throws std::domain_error
/// if a mesh would lose contact (F_k <= 0).
PlanetaryStatics planetaryStatics(const PlanetaryStageModel& m, double sunTorque,
                                  const std::vector<double>& pinErrors);

/// Undamped natural frequencies [rad/s] of the torsional model with the
/// member `fixed` ('s', 'r' or 'c') held, ascending, rigid-body modes
/// (ω below 1e-6 of the largest) removed.
std::vector<double> torsionalPlanetaryFrequencies(const PlanetaryStageModel& m, char fixed);

/// Lin & Parker's planet mode: ω² = (k_s + k_r) cos²α r_p² / J_p.
double planetModeFrequency(const PlanetaryStageModel& m);

/// Tooth-mesh frequency [Hz]: z_r |ω_r − ω_c| / 2π.
double planetaryMeshFrequency(double ringTeeth, double ringSpeed, double carrierSpeed);

}  // namespace milldyn::oracles
