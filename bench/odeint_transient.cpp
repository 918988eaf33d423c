// Baseline: a transient scene of bench/transient_scenes.h integrated by
// Boost.Odeint (dopri5 and rosenbrock4) at a given relative tolerance
// (absolute: 1e-3 of it); one JSON line per method: wall and CPU times (medians of
// repeats), right-hand-side calls of dopri5, the compared speed.
//   bench_odeint SCENE [TOL] [REPEATS] [dopri5]      SCENE: burr | roll
// "dopri5" as the last argument: dopri5 only (the reference at 1e-12;
// rosenbrock4 at 1e-12 takes minutes on the roll crusher).

#include "transient_scenes.h"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <cstdlib>

namespace odeint = boost::numeric::odeint;
using bench::Vec4;

namespace {

/// The right-hand side is a template argument, so Odeint calls it as
/// directly as a hand-written program would (no function pointer).
template <void (*Rhs)(const Vec4&, Vec4&, double)>
void run(const bench::TransientScene& scene, const std::string& tolText, int repeats, bool dopri5Only) {
    const double tol = std::atof(tolText.c_str());
    const double firstStep = scene.odeintFirstStep;

    bench::timeAndPrint("odeint_dopri5", tolText, repeats, [&] {
        bench::RunOutcome out;
        auto counted = [&](const Vec4& x, Vec4& dx, double t) {
            ++out.realizations;
            Rhs(x, dx, t);
        };
        Vec4 x = scene.start();
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::runge_kutta_dopri5<Vec4>());
        for (double target : scene.times) {
            odeint::integrate_adaptive(stepper, counted, x, t, target, firstStep);
            t = target;
            out.values.push_back(x[scene.speedIndex]);
        }
        return out;
    });
    if (dopri5Only) return;

    // Rosenbrock needs the Jacobian (by differences, ∂f/∂t too); ublas
    // vectors and matrices.
    using V = boost::numeric::ublas::vector<double>;
    using M = boost::numeric::ublas::matrix<double>;
    auto f = [](const V& x, V& dx, double t) {
        Vec4 a = {x[0], x[1], x[2], x[3]}, da;
        Rhs(a, da, t);
        for (int i = 0; i < 4; ++i) dx[i] = da[i];
    };
    auto jacobian = [&f](const V& x, M& J, double t, V& dfdt) {
        const double h = 1e-7;
        V f0(4), f1(4), xp = x;
        f(x, f0, t);
        for (int j = 0; j < 4; ++j) {
            xp = x;
            xp[j] += h * std::max(1.0, std::abs(x[j]));
            f(xp, f1, t);
            for (int i = 0; i < 4; ++i) J(i, j) = (f1[i] - f0[i]) / (xp[j] - x[j]);
        }
        f(x, f1, t + h);
        for (int i = 0; i < 4; ++i) dfdt[i] = (f1[i] - f0[i]) / h;
    };
    bench::timeAndPrint("odeint_rosenbrock4", tolText, repeats, [&] {
        bench::RunOutcome out;
        out.realizations = -1;  // not counted
        const Vec4 x0 = scene.start();
        V x(4);
        for (int i = 0; i < 4; ++i) x[i] = x0[i];
        double t = 0;
        auto stepper = odeint::make_dense_output(tol * 1e-3, tol, odeint::rosenbrock4<double>());
        for (double target : scene.times) {
            odeint::integrate_adaptive(stepper, std::make_pair(f, jacobian), x, t, target, firstStep);
            t = target;
            out.values.push_back(x[scene.speedIndex]);
        }
        return out;
    });
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, "bench_odeint burr|roll [TOL] [REPEATS] [dopri5]", args)) return 2;
    const bench::TransientScene& scene = args.scene;
    const std::string& tol = args.tol;
    const int repeats = args.repeats;
    const bool dopri5Only = argc > 4 && std::string(argv[4]) == "dopri5";
    if (scene.name == "burr") run<burr::rhs<Vec4>>(scene, tol, repeats, dopri5Only);
    else run<roll::rhs<Vec4>>(scene, tol, repeats, dopri5Only);
    return 0;
}
