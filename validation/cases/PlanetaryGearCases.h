#pragma once
// What the planetary-gear cases (PlanetaryGearCases.cpp, seed 000) share
// with their report section (PlanetaryGearReport.cpp): the instants and row
// names of the Fig. 10 cases, and the oracle's curves with the cases'
// parameters.

#include "validation/oracles/PlanetaryGearOracle.h"

#include <string>
#include <vector>

namespace milldyn {

/// The two sizes of the cases: 0 = 100 x 200 mm, 1 = 500 x 1000 mm.
std::string planetaryGearSizeTag(int size);
/// The oracle's parameters of one size (docs/planetary_gear.md's free
/// parameters; the carrier friction read as the whole load on d_A/2).
oracles::PlanetaryGearParameters planetaryGearOracleParameters(int size, double friction);
/// The steady carrier speed of one size (750 rpm for the small mill, the
/// large at equal centrifugal factor) [rad/s].
double planetaryGearSteadyRate(int size);

/// Reading (a) of Fig. 10: the acceleration times t_p [s] of the cases and
/// the quantities of their rows (initial torque, and its ratio to t_p → ∞).
std::vector<double> planetaryGearFig10AccelerationTimes();
std::string planetaryGearFig10TorqueQuantity(double accelerationTime);
std::string planetaryGearFig10RatioQuantity(double accelerationTime);
/// Reading (b): the instants t [s] of the start-history rows, and their quantity.
std::vector<double> planetaryGearStartHistoryTimes();
std::string planetaryGearStartHistoryQuantity(double time);

/// Oracle curves of one size with the cases' parameters (frictionless).
struct PlanetaryGearCurves {
    std::vector<double> accelerationTime;  ///< t_p [s]
    std::vector<double> torqueRatio;       ///< M(t_p)/M(∞) of (20), reading (a) [-]
    std::vector<double> time;              ///< t [s] of the start with t_p = 4.6 s
    std::vector<double> torqueFull;        ///< full kinetostatics at (φ, ω, ε)(t) [N*m]
    std::vector<double> torquePaper;       ///< the paper's J_pr ε(t) [N*m]
    std::vector<double> lagDeg;            ///< held-charge lag α [deg]
    std::vector<double> holdingTorque;     ///< steady charge-holding drive torque at ω_y, φ = 0 [N*m]
    double steadyRate = 0;                 ///< ω_y [rad/s]
};
/// `points` samples per curve: t_p over [0.25, 6] s, t over [0, 5] s, α over [0, 90] deg.
PlanetaryGearCurves calcPlanetaryGearCurves(int size, int points);

/// The multibody start (t_p = 4.6 s, no friction) of one size: drive
/// torque [N*m] every `interval` [s] up to 5 s, as the start-history case
/// runs it.
void simulatePlanetaryGearStart(int size, double interval, std::vector<double>& time, std::vector<double>& torque);

}  // namespace milldyn
