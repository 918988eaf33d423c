// milldyn on the roll-crusher 2-mass run, rows in phase, in process (no file
// output): the scene of bench/roll_equations.h, from models/roll_crusher.yaml. Prints one JSON line per integrator.

#include "driver/analyses/Analysis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace milldyn;
    const std::string tol = argc > 1 ? argv[1] : "1e-6";
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
    const std::string model = std::string(MILLDYN_SOURCE_DIR) + "/models/roll_crusher.yaml";
    for (const char* integrator : {"CPodes", "RungeKuttaMerson", "RungeKuttaFeldberg", "RungeKutta3"}) {
        const ModelSpec spec = readModelFile(model, defaultModelReader(),
                                             {{"fidelity.level", "2-mass"},
                                              {"elements.crushing.arrangement", "in_phase"},
                                              {"outputs.sample_interval", "0.05 s"},
                                              {"outputs.plots", "false"},
                                              {"integrator.name", integrator},
                                              {"integrator.accuracy", tol}});
        std::vector<double> walls;
        AnalysisResult r;
        for (int k = 0; k < repeats; ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            r = runAnalysis(spec);
            walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        std::sort(walls.begin(), walls.end());
        std::size_t col = 0;
        for (std::size_t i = 0; i < r.columnNames.size(); ++i)
            if (r.columnNames[i] == "motor.speed") col = i;
        std::vector<double> at;
        for (double t : {2.5, 5.0, 10.0})
            for (const auto& row : r.rows)
                if (std::abs(row[0] - t) < 1e-9) {
                    at.push_back(row[col]);
                    break;
                }
        std::printf("{\"method\": \"milldyn_%s\", \"tolerance\": %s, \"wall_s\": %.6e, \"realizations\": %ld, "
                    "\"omega2\": [%.15g, %.15g, %.15g]}\n",
                    integrator, tol.c_str(), walls[walls.size() / 2], r.statistics.realizations, at.at(0), at.at(1),
                    at.at(2));
    }
    return 0;
}
