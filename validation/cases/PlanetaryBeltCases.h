#pragma once
// What the planetary-belt cases (PlanetaryBeltCases.cpp, seed 002) share
// with their report section (PlanetaryBeltReport.cpp).

#include <string>
#include <vector>

namespace milldyn {

/// R_A(φ) of the Fig. 3 case over one carrier turn.
struct PlanetaryBeltTurnCurves {
    std::vector<double> angle;    ///< carrier angle φ [rad]
    std::vector<double> model;    ///< |R_A| of the multibody model [N]
    std::vector<double> rebuilt;  ///< |R_A| of the rebuilt oracle (14), steady charge [N]
    std::vector<double> paper;    ///< |R_A| of (15)-(18) as printed [N]
    std::vector<double> tight, slack;  ///< belt tensions of the model [N]
};
/// The Fig. 3 case (Ω = 30 rad/s, γ = 90°, k = 0.1, b = 1, c = 0.5, α = 50°)
/// at `points` angles over a turn, as the turn cases run it.
PlanetaryBeltTurnCurves calcPlanetaryBeltFig3Turn(int points);

/// One point of the maps (Figs 4-8): the map's tag (omega, gamma, k, b, c),
/// the mapped value, and the label that starts its rows' quantities.
struct PlanetaryBeltMapPoint {
    std::string map;
    double value = 0;
    std::string label;
};
std::vector<PlanetaryBeltMapPoint> planetaryBeltMapPoints();
/// The quantity of a map point's multibody R_A,max row.
std::string planetaryBeltMapQuantity(const PlanetaryBeltMapPoint& p);

}  // namespace milldyn
