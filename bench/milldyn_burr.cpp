// milldyn on the burr-mill start, in process (no file output): the same
// scene as bench/burr_equations.h, built from models/burr_mill_5p5kW_idle.yaml
// with the switch-off moved past the end. Prints one JSON line per integrator.

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
    const std::string model = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";
    for (const char* integrator : {"CPodes", "RungeKuttaMerson", "RungeKuttaFeldberg", "RungeKutta3"}) {
        const ModelSpec spec = readModelFile(model, defaultModelReader(),
                                             {{"scenario.end_time", "4 s"},
                                              {"elements.motor.switch_off_time", "100 s"},
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
            if (r.columnNames[i] == "millstone.speed") col = i;
        std::vector<double> at;
        for (double t : {0.5, 0.85, 4.0})
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
