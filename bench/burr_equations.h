#pragma once
// The MMP-50 burr-mill start (5.5 kW motor, idle) written by hand: the
// equations milldyn builds from models/burr_mill_5p5kW_idle.yaml, for the
// baselines of bench/. State x = [φ1, φ2, ω1, ω2].
//   J1 ω̇1 = M_Kloss(ω1) − T,  J2 ω̇2 = T − Mc·tanh(ω2/ωs),
//   T = c(φ1 − φ2) + b(ω1 − ω2)

#include <cmath>

namespace burr {

constexpr double kPi = 3.14159265358979323846;
constexpr double J1 = 190.7e-4, J2 = 982.4e-4, c = 537, b = 0.293;
constexpr double Mn = 36.3, wn = 1446 * 2 * kPi / 60, wc = 1500 * 2 * kPi / 60, lambda = 2.2;
constexpr double Mc = 16.2, ws = 0.01;
inline double slipBreakdown() { return (wc - wn) / wc * (lambda + std::sqrt(lambda * lambda - 1)); }

template <class State>
void rhs(const State& x, State& dx, double) {
    static const double sk = slipBreakdown();
    const double s = (wc - x[2]) / wc;
    const double M = 2 * lambda * Mn * s * sk / (s * s + sk * sk);
    const double T = c * (x[0] - x[1]) + b * (x[2] - x[3]);
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = (M - T) / J1;
    dx[3] = (T - Mc * std::tanh(x[3] / ws)) / J2;
}

}  // namespace burr
