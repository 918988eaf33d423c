#pragma once
// The roll-crusher 2-mass level (models/roll_crusher.yaml, fidelity 2-mass)
// written by hand for the baselines of bench/, rows in phase (the shipped
// staggered arrangement cancels every harmonic on one body, leaving a
// constant): state x = [q_m, q_r, w_m, w_r], motor on the linear branch,
// reducer ratio u as a TorsionalCoupling (twist q_m - u q_r), nine rows of
// PeriodicLoad on the rotor. Starts from steady running at the mean load.
//   J_m w_m' = M00 - b0 w_m - T,  J_r w_r' = u T - 9 (M tanh(w_r/ws) + sum_k b_k sin(k P1 t))
//   T = c (q_m - u q_r) + b (w_m - u w_r)

#include <cmath>

namespace roll {

constexpr double kPi = 3.14159265358979323846;
constexpr double Jm = 3.5, Jr = 639, u = 125, c = 716.54, b = 0.487;
constexpr double Mn = 893.2, wn = 588 * 2 * kPi / 60, wc = 600 * 2 * kPi / 60;
constexpr double M00 = Mn * wc / (wc - wn), b0 = Mn / (wc - wn);
constexpr double Mbar = 7440, P1 = 3.973, ws = 0.01;
constexpr double amp[4] = {4464, 2232, 1488, 1116};

inline double rowLoad(double wr, double t) {
    double m = Mbar * std::tanh(wr / ws);
    for (int k = 0; k < 4; ++k) m += amp[k] * std::sin((k + 1) * P1 * t);
    return 9 * m;
}

/// Steady running at the mean load: motor speed w with M00 - b0 w = 9 M tanh(w/(u ws))/u
/// (Newton), twist T/c; the motor angle is 0.
template <class State>
void steadyStart(State& x) {
    double w = (M00 - 9 * Mbar / u) / b0;
    for (int i = 0; i < 50; ++i) {
        const double th = std::tanh(w / (u * ws));
        const double f = M00 - b0 * w - 9 * Mbar * th / u;
        const double df = -b0 - 9 * Mbar * (1 - th * th) / (u * u * ws);
        w -= f / df;
    }
    const double T = M00 - b0 * w;
    x[0] = 0;
    x[1] = -(T / c) / u;
    x[2] = w;
    x[3] = w / u;
}

template <class State>
void rhs(const State& x, State& dx, double t) {
    const double T = c * (x[0] - u * x[1]) + b * (x[2] - u * x[3]);
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = (M00 - b0 * x[2] - T) / Jm;
    dx[3] = (u * T - rowLoad(x[3], t)) / Jr;
}

}  // namespace roll
