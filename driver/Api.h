#pragma once
// Api: what the command line (driver/Cli.cpp) and the Python module
// (python/bindings.cpp) both do with a model — read it, describe it, run it,
// write its files, plan a sweep — and what they list (element types,
// analyses) and validate, in one place, so neither has a second
// implementation nor reaches into the registry or the validation cases.
// Plain C++ (no printing, no Python): the callers present the results.
// Built as the library milldyn_api over milldyn_driver_lib and
// milldyn_validation_cases (CMakeLists.txt).

#include "driver/ModelFile.h"
#include "driver/ModelSpec.h"
#include "driver/Sweep.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/Writers.h"
#include "validation/cases/ValidationCases.h"

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn {

/// milldyn's version ("0.1.0"): `milldyn --version`, summary.json, the module.
const char* milldynVersion();

/// Reads and checks a model file with the overrides (`--set`, `--scenario`
/// as {"use_scenario", name}, `--preset` as {"preset", name}). Throws SpecError.
ModelSpec readModel(const std::string& path, const std::vector<Override>& overrides);

/// A run's result with the facts that differ between runs.
struct RunOutcome {
    AnalysisResult result;
    RunInfo info;  ///< wall time, host, version
};

/// Runs the model's scenario as `milldyn run` does: the analysis, the preset's
/// choices as the first note, and a refusal (AnalysisError) when a result is
/// not finite. Writes nothing.
RunOutcome runModel(const ModelSpec& spec, const ProgressFn& progress = {}, const SampleObserver& observer = {});

/// What a run's verdict (AnalysisResult::verdict) says about what was asked:
/// one rule for `milldyn run`'s exit code, a sweep point's status and the
/// Python module's Result.verdict (its warning and on_failure).
///   Done:       no verdict (the analysis judges no start), "completed",
///               "steady_held", "ran"
///   Unfinished: "unfinished": a start, a run-out or a starting sequence
///               not finished by end_time (no start time or steady values)
///   Stalled:    "stalled": the drive cannot take the load past a speed
enum class VerdictKind { Done, Unfinished, Stalled };
VerdictKind verdictKind(const std::string& verdict);
/// "done", "unfinished", "stalled".
const char* verdictKindName(VerdictKind kind);
/// `milldyn run`'s exit code for a run that produced its result: 3 for a
/// stalled start (its outputs are written), 0 otherwise (an unfinished start
/// prints its verdict and exits 0: the run did what it was told).
int runExitCode(const AnalysisResult& result);

/// Thrown out of a run that was asked to stop (CancelFlag).
class RunCancelled : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A flag another thread sets to stop a run at its next sample; checked by
/// the progress function cancellableProgress() makes.
struct CancelFlag {
    std::atomic<bool> cancelled{false};
    std::atomic<double> simulated{0.0};  ///< the last progress: simulated time (or step) reached
    std::atomic<double> end{0.0};        ///< ... of this many
};

/// A progress function that records the progress in `flag`, throws
/// RunCancelled when the flag is set, then calls `next` (may be empty).
ProgressFn cancellableProgress(CancelFlag& flag, ProgressFn next = {});

/// Writes the files of `milldyn run` into `dir` (created if needed):
/// the tables, summary.json, plots. Returns the paths; `warning` says what
/// could not be plotted. Throws OutputError.
std::vector<std::string> writeRunFiles(const std::string& dir, const ModelSpec& spec, const RunOutcome& run,
                                       std::string& warning);

/// What `milldyn info` shows about a model, as data.
struct ModelInfo {
    std::string name, file;
    int bodies = 0, mobilities = 0, constraints = 0, forces = 0;
    struct Body {
        std::string name, parent;
        double inertia = 0;  ///< [kg*m^2]
    };
    std::vector<Body> bodyList;
    struct Element {
        std::string name, type;
    };
    std::vector<Element> elements;
    std::string scenario, integrator, fidelity;
    double accuracy = 0;
    double maxStep = 0;  ///< [s]; 0: the integrator's choice
    std::vector<std::string> presets;
    std::string preset, presetWhy;
    std::vector<ResultScalar> derived;
    std::vector<ModelSpec::Omitted> built, notBuilt;  ///< what, why
    std::string timeIntegration;
    struct Output {
        std::string name, unit;
    };
    std::vector<Output> outputs;
    std::vector<std::string> warnings;  ///< e.g. elements that need gravity in a model without it
    std::vector<std::string> notes;     ///< what the reader did (an analysis switched by --set, keys dropped)
    /// What each element registered with the scene (Scene::elementRecords),
    /// in build order.
    std::vector<ElementRecord> contributions;
};
/// Builds the scene (throws SpecError like a run would) and describes it.
ModelInfo describeModel(const ModelSpec& spec);

/// The sweep plan of `milldyn sweep`: either grids ("path=a:b:n") or a Latin
/// hypercube of n points over ranges ("path=a:b") with a seed. Throws
/// std::invalid_argument for a wrong combination, SpecError for a bad text.
SweepPlan makeSweepPlan(const std::vector<std::string>& grids, const std::vector<std::string>& ranges,
                        std::size_t lhs, unsigned long seed);
/// Reads the model with the base overrides and checks the plan's values
/// against it before any point runs: a unitless nonzero value on a
/// dimensional key is refused up front (SpecError located at the --grid or
/// --range option, "did you mean 1490 rpm ...?"), as --set refuses it,
/// instead of failing at every point. Returns the base model.
ModelSpec checkSweepPlan(const SweepPlan& plan, const std::string& model, const std::vector<Override>& base);

/// Every element type's schema, built-in and loaded plugins', in the order
/// `milldyn elements` lists them (the registry's).
std::vector<const ElementSchema*> elementSchemas();
/// Every analysis's schema (`scenario.analysis`), in the order `milldyn
/// analyses` lists them.
std::vector<const ElementSchema*> analysisSchemas();
/// True for a key whose value is a schedule ({ramp|step_recovery|sine|table}).
bool isScheduleKey(const ParamSchema& p);

/// The validation cases whose name contains `filter` ("" for all), plugins'
/// case groups included: the rows `milldyn validate` prints.
std::vector<ValidationRow> validate(const std::string& filter);
/// Writes `milldyn validate --report`'s report.html and report.md of `rows`
/// into `dir`, with every machine's report section. Returns the paths;
/// `warning` says what could not be drawn. Throws OutputError.
std::vector<std::string> writeValidationReportFiles(const std::string& dir, const std::vector<ValidationRow>& rows,
                                                    std::string& warning);

}  // namespace milldyn
