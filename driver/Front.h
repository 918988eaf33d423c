#pragma once
// Front: the error-cost front of any model on demand (`milldyn front MODEL`,
// issue 29 item 8), and the errors of what a designer reads that both it and
// bench/front.cpp (the shipped models' fronts) measure. Plain C++ over
// AnalysisResult: no printing.
//
// The errors (docs/speed-accuracy.md §1), each of a run against a reference
// run of the same model at a tight accuracy:
//   peak    every summary torque peak (peak_drive_torque, peak.*, run_max.*,
//           run_min.*): |p − p_ref| / max(|p_ref|, F)
//   ripple  every torque column (unit N*m): R = max − min over the steady
//           window, |R − R_ref| / max(R_ref, F)
//   speed   steady_speed (or speed_at_end): |ω − ω_ref| / max(|ω_ref|, S)
//   time    start_time and runout_time: max(0, |t − t_ref| − allowance) / |t_ref|
//   energy  the run's own |energy_balance_relative|
// F (the torque floor) = 1 % of the largest |torque| of the reference's torque
// columns and peaks; S = 1 % of its largest |speed| (rad/s column). A
// quantity the reference has and the run lacks is an infinite error.
// Steady window: the second half of [the reference's start_time (its first
// sample without one), the earliest drive switch-off or its last sample].

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// The errors of what a designer reads (header), relative.
struct DesignerErrors {
    double peak = 0, ripple = 0, speed = 0, time = 0, energy = 0;
    double worst() const;
};

/// [t0, t1] of the steady window [s].
struct SteadyWindow {
    double t0 = 0, t1 = 0;
};

/// The steady window of `ref`; `steadyEnd` > 0 ends it there (a switch-off).
SteadyWindow steadyWindowOf(const AnalysisResult& ref, double steadyEnd);
/// F: 1 % of the largest |torque| of the reference [N*m].
double torqueFloorOf(const AnalysisResult& ref);
/// S: 1 % of the largest |speed| of the reference [rad/s].
double speedFloorOf(const AnalysisResult& ref);
/// Ripple max − min of column `c` over the rows inside `w`.
double rippleOf(const AnalysisResult& r, std::size_t c, const SteadyWindow& w);
/// The errors of `run` against `ref`. `timeAllowance` [s]: a start or
/// run-out time difference up to it is not counted (0: the times are
/// located crossings; bench/front.cpp keeps one sample for its tables).
DesignerErrors designerErrors(const AnalysisResult& run, const AnalysisResult& ref, const SteadyWindow& w,
                              double timeAllowance);

/// What `milldyn front` runs.
struct FrontOptions {
    std::vector<std::string> integrators{"RungeKuttaMerson", "RungeKutta3", "CPodes"};
    std::vector<double> accuracies{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
    std::string referenceIntegrator = "RungeKuttaMerson";
    double referenceAccuracy = 1e-10;
    /// CPU seconds a point may take; past it the point stops ("budget") and
    /// the integrator's tighter accuracies are skipped. <= 0: twice the
    /// reference's CPU time plus 1 s.
    double budget = 0;
    int repeat = 1;  ///< rounds; a point's CPU time is the median
    /// Presets: name and the largest worst error it may have; each is the
    /// cheapest point within its target.
    std::vector<std::pair<std::string, double>> targets{{"fast", 1e-2}, {"balanced", 1e-3}, {"accurate", 1e-5}};
};

/// One run of the front.
struct FrontPoint {
    std::string integrator;
    double accuracy = 0;
    std::string status;  ///< ok, budget, skipped, failed: REASON
    double cpuSeconds = 0;
    long steps = 0, realizations = 0;
    DesignerErrors errors;
    bool onFront = false;  ///< no other ok point is both cheaper and more accurate
};

struct FrontPreset {
    std::string name;
    double target = 0;
    int point = -1;  ///< index in points; -1: no point within the target
};

struct FrontResult {
    std::string model;
    FrontPoint reference;
    SteadyWindow window;
    double torqueFloor = 0, speedFloor = 0;  ///< [N*m], [rad/s]
    std::vector<FrontPoint> points;
    std::vector<FrontPreset> presets;
    std::vector<std::string> notes;
};

/// Runs `model` (with `overrides`) at the reference and at every integrator
/// and accuracy of `options`, loose to tight. Throws what reading the model
/// throws (SpecError), and AnalysisError when the reference run fails.
/// `log` (may be empty) gets one line per run.
FrontResult measureFront(const std::string& model, const std::vector<Override>& overrides, const FrontOptions& options,
                         const std::function<void(const std::string&)>& log = {});

/// `milldyn run --check-resolution`: runs `spec` again at a tenth of its
/// accuracy (same integrator) and adds a warning note to `result` for each
/// value a designer sizes by that moves by more than `tolerance`: every
/// torque peak (as the front's "peak"; relative to max(|p|, F), F the
/// run's torque floor), every `peak_to_peak.*` (the same floor), `ripple.*`
/// and `speed_fluctuation.*` (relative to the larger of the two values) —
/// the run's own accuracy does not resolve them. One note says what was
/// checked. A replayed run integrates nothing: a note says so. Returns the
/// number of values not resolved.
int checkResolution(const ModelSpec& spec, AnalysisResult& result, double tolerance = 0.01);

/// front.csv: one row per run, the reference first.
std::string frontCsv(const FrontResult& front);
/// The presets as a YAML file (`presets:` block) that the reader takes from
/// beside the model (MODEL.presets.yaml, docs/model-format.md "Presets").
std::string frontPresetsYaml(const FrontResult& front);
// presetsFileBeside (driver/ModelFile.h): where they go.

}  // namespace milldyn
