// Kinetostatic throughput (issue #7 §2: >= 50,000 configurations/s per
// core): the `turn` scenario of the planetary-gear models (one carrier turn
// at steady speed) with its angle count raised, at the fidelity levels
// rigid_charge and held_charge, single-threaded. For each: configurations
// per CPU second of milldyn's kinetostatic analysis (per wall second beside it), Simbody realizations per
// configuration (counted by the System), and the floor: the same system
// with the mechanism placed and realized to Stage::Acceleration once per
// configuration. One JSON line per model and level.
//   bench_kinetostatic [POINTS] [REPEATS]

#include "clocks.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace milldyn;

namespace {

/// Realization counts of a System (stages Velocity and Acceleration).
struct Counts {
    long velocity = 0, acceleration = 0;
};
Counts counts(const SimTK::System& system) {
    return {system.getNumRealizationsOfThisStage(SimTK::Stage::Velocity),
            system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration)};
}

}  // namespace

int main(int argc, char** argv) {
    const int points = argc > 1 ? std::atoi(argv[1]) : 20000;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    for (const char* model : {"planetary_gear_100x200", "planetary_gear_500x1000"})
        for (const char* level : {"rigid_charge", "held_charge"}) {
            const std::string path = std::string(MILLDYN_SOURCE_DIR) + "/models/" + model + ".yaml";
            const ModelSpec spec = readModelFile(path, defaultModelReader(),
                                                 {{"use_scenario", "turn"},
                                                  {"scenarios.turn.angle_points", std::to_string(points)},
                                                  {"fidelity.level", level},
                                                  {"outputs.plots", "false"}});
            // milldyn's analysis (building the scene included); the observer
            // sees every angle and reads the System's realization counters.
            std::vector<double> walls, cpus;
            Counts first, last;
            for (int r = 0; r < repeats; ++r) {
                bool seen = false;
                const bench::Stopwatch watch;
                runAnalysis(spec, {}, [&](const Scene& scene, const SimTK::State&, double) {
                    (seen ? last : first) = counts(scene.system());
                    seen = true;
                });
                walls.push_back(watch.wall());
                cpus.push_back(watch.cpu());
            }
            const double wall = bench::median(walls), cpu = bench::median(cpus);
            const double perConfig = points > 1 ? 1.0 / (points - 1) : 0.0;

            // The floor: the same system, mechanism placed (carrier angle and
            // speed, the elements' initializers) and one realization.
            const ElementSpec& sc = spec.scenario;
            std::vector<double> floorWalls, floorCpus, buildCpus;
            for (int r = 0; r < repeats; ++r) {
                const bench::Stopwatch building;
                auto scene = buildScene(spec);
                SimTK::State state = initialState(*scene, spec);
                buildCpus.push_back(building.cpu());
                state.setTime(sc.number("time"));
                const SimTK::MobilizedBody& carrier = scenarioBody(*scene, sc, "carrier").mobod;
                const double from = sc.number("angle_from"), to = sc.number("angle_to"),
                             speed = sc.number("carrier_speed");
                double sum = 0;  // keeps the realizations from being optimised away
                const bench::Stopwatch watch;
                for (int k = 0; k < points; ++k) {
                    carrier.setOneQ(state, SimTK::MobilizerQIndex(0), from + (to - from) * k / (points - 1));
                    carrier.setOneU(state, SimTK::MobilizerUIndex(0), speed);
                    for (const auto& init : scene->initializers()) init(state);
                    scene->system().realize(state, SimTK::Stage::Acceleration);
                    sum += state.getUDot()[0];
                }
                floorWalls.push_back(watch.wall());
                floorCpus.push_back(watch.cpu());
                if (sum != sum) std::fprintf(stderr, "non-finite accelerations\n");
            }
            const double floorWall = bench::median(floorWalls), floorCpu = bench::median(floorCpus);
            // Configurations/s per core: from the CPU time (the wall time,
            // which counts other processes' turns on a shared core, beside it).
            std::printf("{\"model\": \"%s\", \"level\": \"%s\", \"points\": %d, \"wall_s\": %.6e, \"cpu_s\": %.6e, "
                        "\"configurations_per_s\": %.4g, \"configurations_per_wall_s\": %.4g, "
                        "\"acceleration_realizations_per_configuration\": %.4g, "
                        "\"velocity_realizations_per_configuration\": %.4g, \"floor_wall_s\": %.6e, "
                        "\"floor_cpu_s\": %.6e, \"floor_configurations_per_s\": %.4g, \"scene_build_cpu_s\": %.4g}\n",
                        model, level, points, wall, cpu, points / cpu, points / wall,
                        (last.acceleration - first.acceleration) * perConfig,
                        (last.velocity - first.velocity) * perConfig, floorWall, floorCpu, points / floorCpu,
                        bench::median(buildCpus));
            std::fflush(stdout);
        }
    return 0;
}
