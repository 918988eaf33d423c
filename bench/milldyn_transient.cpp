// milldyn on a transient scene of bench/transient_scenes.h, in process (no
// file output), with each Simbody integrator; one JSON line per integrator.
//   bench_milldyn SCENE [TOL] [REPEATS]      SCENE: burr | roll

#include "transient_scenes.h"

#include "driver/analyses/Analysis.h"

#include <cmath>
#include <cstdlib>

int main(int argc, char** argv) {
    using namespace milldyn;
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, "bench_milldyn burr|roll [TOL] [REPEATS]", args)) return 2;
    const bench::TransientScene& scene = args.scene;
    const std::string& tol = args.tol;
    const int repeats = args.repeats;
    const std::string model = std::string(MILLDYN_SOURCE_DIR) + "/models/" + scene.modelFile;
    char sample[32];
    std::snprintf(sample, sizeof sample, "%.17g s", scene.sampleInterval);
    for (const std::string& integrator : bench::integrators()) {
        std::vector<Override> overrides = {{"outputs.sample_interval", sample},
                                           {"outputs.plots", "false"},
                                           {"integrator.name", integrator},
                                           {"integrator.accuracy", tol}};
        for (const auto& [key, value] : scene.overrides) overrides.push_back({key, value});
        const ModelSpec spec = readModelFile(model, defaultModelReader(), overrides);
        bench::timeAndPrint("milldyn_" + integrator, tol, repeats, [&] {
            const AnalysisResult r = runAnalysis(spec);
            const std::size_t col = r.findColumn(scene.column);
            bench::RunOutcome out;
            out.realizations = r.statistics.realizations;
            for (double t : scene.times)
                for (const auto& row : r.rows)
                    if (std::abs(row[0] - t) < 1e-9) {
                        out.values.push_back(row.at(col));
                        break;
                    }
            return out;
        });
    }
    return 0;
}
