// Baseline: the burr-mill start integrated by Boost.Odeint (dopri5 and
// rosenbrock4) at a given relative tolerance; prints one JSON line per
// method: wall time (median of repeats) and ω2 at the comparison times.

#include "burr_equations.h"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace odeint = boost::numeric::odeint;
using Vec = std::array<double, 4>;
const std::vector<double> kTimes = {0.5, 0.85, 4.0};

template <class Run>
// `calls`, if given, counts right-hand-side evaluations over all repeats.
void timeIt(const char* name, double tol, int repeats, Run run, const long* calls = nullptr) {
    std::vector<double> walls, values;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        values = run();
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(walls.begin(), walls.end());
    std::printf("{\"method\": \"%s\", \"tolerance\": %g, \"wall_s\": %.6e, ", name, tol, walls[walls.size() / 2]);
    if (calls) std::printf("\"realizations\": %ld, ", *calls / repeats);
    std::printf("\"omega2\": [%.15g, %.15g, %.15g]}\n", values[0], values[1], values[2]);
}

int main(int argc, char** argv) {
    const double tol = argc > 1 ? std::atof(argv[1]) : 1e-6;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
    long calls = 0;
    auto counted = [&calls](const Vec& x, Vec& dx, double t) {
        ++calls;
        burr::rhs<Vec>(x, dx, t);
    };
    timeIt("odeint_dopri5", tol, repeats, [tol, &counted] {
        Vec x = {0, 0, 0, 0};
        std::vector<double> out;
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::runge_kutta_dopri5<Vec>());
        for (double target : kTimes) {
            odeint::integrate_adaptive(stepper, counted, x, t, target, 1e-4);
            t = target;
            out.push_back(x[3]);
        }
        return out;
    }, &calls);
    // Rosenbrock needs the Jacobian; ublas vectors and matrices.
    using V = boost::numeric::ublas::vector<double>;
    using M = boost::numeric::ublas::matrix<double>;
    auto system = [](const V& x, V& dx, double t) { burr::rhs<V>(x, dx, t); };
    auto jacobian = [](const V& x, M& J, double, V& dfdt) {
        const double h = 1e-7;
        V f0(4), f1(4), xp = x;
        burr::rhs<V>(x, f0, 0);
        for (int j = 0; j < 4; ++j) {
            xp = x;
            xp[j] += h * std::max(1.0, std::abs(x[j]));
            burr::rhs<V>(xp, f1, 0);
            for (int i = 0; i < 4; ++i) J(i, j) = (f1[i] - f0[i]) / (xp[j] - x[j]);
        }
        for (int i = 0; i < 4; ++i) dfdt[i] = 0;
    };
    timeIt("odeint_rosenbrock4", tol, repeats, [&] {
        V x(4);
        for (int i = 0; i < 4; ++i) x[i] = 0;
        std::vector<double> out;
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::rosenbrock4<double>());
        for (double target : kTimes) {
            odeint::integrate_adaptive(stepper, std::make_pair(system, jacobian), x, t, target, 1e-4);
            t = target;
            out.push_back(x[3]);
        }
        return out;
    });
    return 0;
}
