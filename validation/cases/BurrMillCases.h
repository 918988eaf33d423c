#pragma once
// What the burr-mill cases (BurrMillCases.cpp) share with their report
// section (BurrMillReport.cpp).

#include <cstddef>
#include <string>
#include <vector>

namespace milldyn {

/// The case name of Table 1 row `i` (0..5, as printed: 5.5 kW idle first).
std::string burrMillTable1CaseName(std::size_t i);

/// A coast-down of the multibody model (linear motor branch switched off at
/// t = 0 from steady running, the printed idle Mc) next to eqs (10)-(12).
struct BurrMillCoastdownCurves {
    std::vector<double> t;                         ///< [s]
    std::vector<double> omega1, omega2;            ///< multibody [rad/s]
    std::vector<double> omega1Oracle, omega2Oracle;///< eqs (10), (11) [rad/s]
    std::vector<double> meanLine;                  ///< eq (12) [rad/s]
    double Mc = 0;                                 ///< [N*m]
    double b = 0;                                  ///< belt damping [N*m*s/rad]
};
/// The coast-down of the motor of `kW` (5.5 or 3.2) sampled at `intervals`
/// equal steps up to 0.9 of the millstone's first stop (as the case does).
BurrMillCoastdownCurves simulateBurrMillCoastdown(double kW, int intervals);

}  // namespace milldyn
