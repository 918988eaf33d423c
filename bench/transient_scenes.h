#pragma once
// The transient scenes of bench/ as milldyn runs them and as a bare Simbody
// system runs them (bench/milldyn_transient.cpp, bench/bare_simbody.cpp),
// and the timing and printing both share: one JSON line per integrator,
// read by bench/report.py.

#include "burr_equations.h"
#include "clocks.h"
#include "roll_equations.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bench {

using Vec4 = std::array<double, 4>;

/// One scene: how milldyn builds it from a model file, and the same
/// equations by hand (x = [q1, q2, w1, w2]) for the bare Simbody system.
struct TransientScene {
    std::string name;
    std::string modelFile;  ///< under models/
    std::vector<std::pair<std::string, std::string>> overrides;
    std::string column;            ///< milldyn's column of the compared speed
    int speedIndex;                ///< its index in x
    std::vector<double> times;     ///< comparison times [s]
    double endTime;                ///< [s]
    double sampleInterval;         ///< [s], as milldyn samples
    std::array<double, 2> inertia; ///< body inertias about the pins [kg*m^2]
    double odeintFirstStep;        ///< [s], the first step Odeint tries
    Vec4 (*start)();
    void (*rhs)(const Vec4&, Vec4&, double);
};

inline Vec4 burrStart() { return {0, 0, 0, 0}; }
inline Vec4 rollStart() {
    Vec4 x;
    roll::steadyStart(x);
    return x;
}

inline const std::vector<std::string>& integrators() {
    static const std::vector<std::string> names = {"CPodes", "RungeKuttaMerson", "RungeKuttaFeldberg", "RungeKutta3"};
    return names;
}

inline TransientScene findScene(const std::string& name) {
    if (name == "burr")
        // The 4 s start with the switch-off moved past the end.
        return {"burr",
                "burr_mill_5p5kW_idle.yaml",
                {{"scenario.end_time", "4 s"}, {"elements.motor.switch_off_time", "100 s"}},
                "millstone.speed",
                3,
                {0.5, 0.85, 4.0},
                4.0,
                0.05,
                {burr::J1, burr::J2},
                1e-4,
                burrStart,
                burr::rhs<Vec4>};
    if (name == "roll")
        // The 2-mass level, rows in phase (bench/roll_equations.h).
        return {"roll",
                "roll_crusher.yaml",
                {{"fidelity.level", "2-mass"}, {"elements.crushing.arrangement", "in_phase"}},
                "motor.speed",
                2,
                {2.5, 5.0, 10.0},
                10.0,
                0.05,
                {roll::Jm, roll::Jr},
                1e-3,
                rollStart,
                roll::rhs<Vec4>};
    throw std::invalid_argument("unknown scene '" + name + "' (burr or roll)");
}

/// What one run returns: the compared speed at the scene's times and the
/// number of realizations the integrator made (right-hand-side calls for
/// Odeint; negative: not counted).
struct RunOutcome {
    std::vector<double> values;
    long realizations = 0;
};

/// Runs `run` `repeats` times and prints the median wall and CPU times, the
/// realizations of a run and the CPU time per realization as one JSON line.
template <class Run>
void timeAndPrint(const std::string& method, const std::string& tolerance, int repeats, Run run) {
    std::vector<double> walls, cpus;
    RunOutcome outcome;
    for (int k = 0; k < repeats; ++k) {
        const Stopwatch watch;
        outcome = run();
        walls.push_back(watch.wall());
        cpus.push_back(watch.cpu());
    }
    const double wall = median(walls), cpu = median(cpus);
    if (outcome.values.size() != 3) throw std::runtime_error(method + ": a comparison time was not sampled");
    std::printf("{\"method\": \"%s\", \"tolerance\": %s, \"wall_s\": %.6e, \"cpu_s\": %.6e, ", method.c_str(),
                tolerance.c_str(), wall, cpu);
    if (outcome.realizations > 0)
        std::printf("\"realizations\": %ld, \"us_per_realization\": %.4g, ", outcome.realizations,
                    1e6 * cpu / outcome.realizations);
    std::printf("\"omega2\": [%.15g, %.15g, %.15g]}\n", outcome.values[0], outcome.values[1], outcome.values[2]);
    std::fflush(stdout);
}

/// The command line the transient bench programs share:
/// PROGRAM SCENE [TOL] [REPEATS] (what follows is the program's own).
struct BenchArgs {
    TransientScene scene;
    std::string tol = "1e-6";  ///< as typed, printed as given
    int repeats = 5;
};

/// Reads it, or prints `usage` and returns false (the program exits 2).
inline bool parseBenchArgs(int argc, char** argv, const char* usage, BenchArgs& out) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s\n", usage);
        return false;
    }
    out.scene = findScene(argv[1]);
    if (argc > 2) out.tol = argv[2];
    if (argc > 3) out.repeats = std::atoi(argv[3]);
    return true;
}

}  // namespace bench
