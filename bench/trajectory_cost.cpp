// What judging a transient from its integrated trajectory costs (issue 26
// item 2: verdicts, start_time and peaks from every accepted step, maxima
// and crossings located inside the steps, instead of from the output rows).
// Each model's transient is timed three ways in the same build, CPU time,
// median of REPEATS:
//   full   runAnalysis as shipped: Simulation::run's onStep at every step
//          end (speed trace, the drive torque's and every coupling torque's
//          and outputs.peaks' PeakTracker, sequence ends), then the summary
//   rows   the same scene, start state, integration, watch and table rows,
//          without onStep: what the analysis integrated and recorded before
//          the change (its summary then read the rows, a negligible cost)
//   steps  rows plus an empty onStep: Simulation's own share (each step end
//          realized to Acceleration and kept for trajectoryAt)
// One JSON line per model. No switch in the driver: the rows and steps runs
// drive Simulation directly, as the analysis does.
//   bench_trajectory [REPEATS] [MODEL.yaml ...]   (models under models/)

#include "clocks.h"

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/SteadyStart.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace milldyn;

/// The analysis's integration and rows without judging the trajectory
/// (driver/analyses/Transient.cpp's set-up, onStep left out or empty).
long rowsOnly(const ModelSpec& spec, bool emptyOnStep) {
    const ElementSpec& sc = spec.scenario;
    auto scene = buildScene(spec);
    const SimTK::State state = transientInitialState(*scene, spec);
    AnalysisResult result;
    SampleTable table(*scene, result);
    double switchTime = std::numeric_limits<double>::infinity();
    for (const auto& e : scene->switchEvents())
        if (e.kind == Scene::SwitchEvent::Kind::DriveOff) switchTime = std::min(switchTime, e.time);
    Simulation sim(*scene, spec.integrator);
    sim.initialize(state, sc.text("zero_dof") == "replay");
    auto onSample = [&](const SimTK::State& s) { table.record(s, sim.probeValues()); };
    Simulation::SampleFn onStep;
    if (emptyOnStep) onStep = [](const SimTK::State&) {};
    const double endTime = sc.number("end_time");
    const std::string runoutName = sc.text("runout_body");
    if (!runoutName.empty() && std::isfinite(switchTime) && switchTime < endTime) {
        const Simulation::Watch watch = speedWatch(scene->findBody(runoutName)->mobod, sc.number("stop_speed"),
                                                   switchTime, runoutName + " comes to rest");
        sim.run(endTime, spec.outputs.sampleInterval, onSample, &watch, onStep);
    } else {
        sim.run(endTime, spec.outputs.sampleInterval, onSample, nullptr, onStep);
    }
    return sim.statistics().steps;
}

template <class F>
double medianCpu(int repeats, F&& f) {
    std::vector<double> cpu;
    for (int k = 0; k < repeats; ++k) {
        bench::Stopwatch w;
        f();
        cpu.push_back(w.cpu());
    }
    return bench::median(cpu);
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
    std::vector<std::string> models;
    for (int i = 2; i < argc; ++i) models.push_back(argv[i]);
    if (models.empty())
        models = {"burr_mill_5p5kW_idle.yaml",       "burr_mill_5p5kW_loaded_start.yaml", "start_bench_dol.yaml",
                  "start_bench_star_delta.yaml",     "start_bench_soft_start.yaml",       "start_bench_catalogue.yaml",
                  "start_bench_clutch.yaml",         "start_bench_converter.yaml",        "start_bench_dq.yaml",
                  "start_bench_table.yaml"};
    if (repeats < 1) return 2;
    for (const std::string& m : models) {
        const ModelSpec spec = readModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/" + m, defaultModelReader(),
                                             {{"outputs.plots", "false"}});
        long fullSteps = 0, rowSteps = 0;
        const double full = medianCpu(repeats, [&] { fullSteps = runAnalysis(spec).statistics.steps; });
        const double rows = medianCpu(repeats, [&] { rowSteps = rowsOnly(spec, false); });
        const double steps = medianCpu(repeats, [&] { rowsOnly(spec, true); });
        std::printf("{\"model\": \"%s\", \"integrator\": \"%s\", \"steps\": %ld, \"steps_rows\": %ld, "
                    "\"full_cpu_s\": %.4g, \"rows_cpu_s\": %.4g, \"steps_cpu_s\": %.4g, \"full_over_rows\": %.3f, "
                    "\"steps_over_rows\": %.3f}\n",
                    m.c_str(), spec.integrator.name.c_str(), fullSteps, rowSteps, full, rows, steps, full / rows,
                    steps / rows);
        std::fflush(stdout);
    }
    return 0;
}
