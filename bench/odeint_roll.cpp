// Baseline: the roll-crusher 2-mass run (rows in phase) integrated by Boost.Odeint (dopri5 and
// rosenbrock4) at a given relative tolerance; prints one JSON line per
// method: wall time (median of repeats) and the motor speed at the
// comparison times (bench/roll_equations.h).

#include "roll_equations.h"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace odeint = boost::numeric::odeint;
using Vec = std::array<double, 4>;
const std::vector<double> kTimes = {2.5, 5.0, 10.0};

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
    // "dopri5" as the third argument: the reference only (rosenbrock4 at
    // 1e-12 takes minutes here).
    const bool dopri5Only = argc > 3 && std::string(argv[3]) == "dopri5";
    long calls = 0;
    auto counted = [&calls](const Vec& x, Vec& dx, double t) {
        ++calls;
        roll::rhs<Vec>(x, dx, t);
    };
    timeIt("odeint_dopri5", tol, repeats, [tol, &counted] {
        Vec x;
        roll::steadyStart(x);
        std::vector<double> out;
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::runge_kutta_dopri5<Vec>());
        for (double target : kTimes) {
            odeint::integrate_adaptive(stepper, counted, x, t, target, 1e-3);
            t = target;
            out.push_back(x[2]);
        }
        return out;
    }, &calls);
    if (dopri5Only) return 0;
    // Rosenbrock needs the Jacobian; ublas vectors and matrices.
    using V = boost::numeric::ublas::vector<double>;
    using M = boost::numeric::ublas::matrix<double>;
    auto system = [](const V& x, V& dx, double t) { roll::rhs<V>(x, dx, t); };
    auto jacobian = [](const V& x, M& J, double t, V& dfdt) {
        const double h = 1e-7;
        V f0(4), f1(4), xp = x;
        roll::rhs<V>(x, f0, t);
        for (int j = 0; j < 4; ++j) {
            xp = x;
            xp[j] += h * std::max(1.0, std::abs(x[j]));
            roll::rhs<V>(xp, f1, t);
            for (int i = 0; i < 4; ++i) J(i, j) = (f1[i] - f0[i]) / (xp[j] - x[j]);
        }
        roll::rhs<V>(x, f1, t + h);
        for (int i = 0; i < 4; ++i) dfdt[i] = (f1[i] - f0[i]) / h;
    };
    timeIt("odeint_rosenbrock4", tol, repeats, [&] {
        V x(4);
        roll::steadyStart(x);
        std::vector<double> out;
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::rosenbrock4<double>());
        for (double target : kTimes) {
            odeint::integrate_adaptive(stepper, std::make_pair(system, jacobian), x, t, target, 1e-3);
            t = target;
            out.push_back(x[2]);
        }
        return out;
    });
    return 0;
}
