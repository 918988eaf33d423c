#include "driver/Api.h"

#include "driver/SceneBuilder.h"
#include "driver/Units.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/outputs/AtomicFile.h"
#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Schedule.h"
#include "validation/report/ReportSection.h"
#include "validation/report/ReportWriter.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace milldyn {
namespace {

std::string hostName() {
    char buf[256] = {0};
    if (::gethostname(buf, sizeof buf - 1) != 0) return "unknown";
    return buf;
}

}  // namespace

const char* milldynVersion() { return "0.1.0"; }

ModelSpec readModel(const std::string& path, const std::vector<Override>& overrides) {
    return readModelFile(path, defaultModelReader(), overrides);
}

VerdictKind verdictKind(const std::string& verdict) {
    if (verdict == "stalled") return VerdictKind::Stalled;
    if (verdict == "unfinished") return VerdictKind::Unfinished;
    return VerdictKind::Done;
}

const char* verdictKindName(VerdictKind kind) {
    switch (kind) {
        case VerdictKind::Done: return "done";
        case VerdictKind::Unfinished: return "unfinished";
        case VerdictKind::Stalled: return "stalled";
    }
    return "?";
}

int runExitCode(const AnalysisResult& result) { return verdictKind(result.verdict) == VerdictKind::Stalled ? 3 : 0; }

RunOutcome runModel(const ModelSpec& spec, const ProgressFn& progress, const SampleObserver& observer) {
    RunOutcome run;
    const auto start = std::chrono::steady_clock::now();
    run.result = runAnalysis(spec, progress, observer);
    // What the preset picked, in the printed summary and summary.json.
    if (!spec.preset.empty()) {
        std::ostringstream picked;
        picked << "preset " << spec.preset << ": " << spec.integrator.name << " " << spec.integrator.accuracy;
        if (spec.integrator.maxStep > 0) picked << ", max_step " << spec.integrator.maxStep << " s";
        if (!spec.fidelity.empty()) picked << ", fidelity " << spec.fidelity;
        picked << " (" << spec.presetWhy << ")";
        run.result.notes.insert(run.result.notes.begin(), picked.str());
    }
    run.info.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.info.host = hostName();
    run.info.version = milldynVersion();
    for (const auto& r : run.result.results)
        if (!std::isfinite(r.value))
            throw AnalysisError("result " + r.name + " is not finite (the analysis diverged)");
    return run;
}

ProgressFn cancellableProgress(CancelFlag& flag, ProgressFn next) {
    return [&flag, next = std::move(next)](double t, double end) {
        flag.simulated = t;
        flag.end = end;
        if (flag.cancelled) {
            std::ostringstream s;
            s << "run cancelled at " << t << " of " << end;
            throw RunCancelled(s.str());
        }
        if (next) next(t, end);
    };
}

std::vector<std::string> writeRunFiles(const std::string& dir, const ModelSpec& spec, const RunOutcome& run,
                                       std::string& warning) {
    ensureDirectory(dir);
    return writeResultFiles(dir, spec, run.result, run.info, warning);
}

ModelInfo describeModel(const ModelSpec& spec) {
    auto scene = buildScene(spec);
    const SimTK::State state = scene->system().getDefaultState();
    ModelInfo info;
    info.name = spec.name;
    info.file = spec.file;
    info.bodies = static_cast<int>(scene->bodies().size());
    info.mobilities = state.getNU();
    info.constraints = scene->matter().getNumConstraints();
    info.forces = scene->forces().getNumForces();
    for (const auto& b : spec.bodies) info.bodyList.push_back({b.name, b.joint.parent, b.inertia});
    for (const auto& e : spec.elements) info.elements.push_back({e.name, e.type});
    info.scenario = spec.scenario.type;
    info.integrator = spec.integrator.name;
    info.accuracy = spec.integrator.accuracy;
    info.maxStep = spec.integrator.maxStep;
    info.fidelity = spec.fidelity;
    info.presets = spec.presetNames;
    info.preset = spec.preset;
    info.presetWhy = spec.presetWhy;
    info.derived = derivedResults(*scene);
    for (const auto& n : scene->notes()) info.built.push_back({n.what, n.why});
    info.notBuilt = spec.notBuilt;
    for (const auto& n : scene->omitted()) info.notBuilt.push_back({n.what, n.why});
    const AnalysisKind* kind = findAnalysisKind(spec.scenario.type);
    info.timeIntegration = kind && kind->timeIntegration ? kind->timeIntegration(spec, *scene)
                                                         : "none (" + spec.scenario.type + " analysis)";
    for (const auto& p : scene->probes()) info.outputs.push_back({p.name, p.unit});
    info.contributions = scene->elementRecords();
    const std::string noGravity = gravityWarning(spec, defaultModelReader());
    if (!noGravity.empty()) info.warnings.push_back(noGravity);
    info.notes = spec.readNotes;
    return info;
}

SweepPlan makeSweepPlan(const std::vector<std::string>& grids, const std::vector<std::string>& ranges,
                        std::size_t lhs, unsigned long seed) {
    if (grids.empty() == (lhs == 0))
        throw std::invalid_argument("sweep needs --grid path=a:b:n ... or --lhs N with --range path=a:b ...");
    if (lhs > 0 && ranges.empty()) throw std::invalid_argument("--lhs needs at least one --range path=a:b");
    if (!grids.empty() && !ranges.empty()) throw std::invalid_argument("--range goes with --lhs, not with --grid");
    std::vector<SweepAxis> axes;
    for (const auto& g : grids)
        for (auto& axis : parseGridAxes(g)) axes.push_back(std::move(axis));
    for (const auto& r : ranges)
        for (auto& axis : parseRangeAxes(r)) axes.push_back(std::move(axis));
    return lhs > 0 ? makeLatinHypercube(axes, lhs, seed) : makeGrid(axes);
}

ModelSpec checkSweepPlan(const SweepPlan& plan, const std::string& model, const std::vector<Override>& base) {
    ModelSpec spec = readModel(model, base);
    const std::string option = plan.cartesian ? "--grid" : "--range";
    for (std::size_t a = 0; a < plan.axes.size(); ++a) {
        const SweepAxis& axis = plan.axes[a];
        if (!axis.unit.empty() || axis.bareNumberIsSI) continue;
        // The largest value: a bare 0 needs no unit, any other does.
        double v = 0;
        for (double x : axis.values)
            if (std::abs(x) > std::abs(v)) v = x;
        if (v == 0) continue;
        std::vector<Override> one = base;
        one.push_back(plan.overrides(0)[a]);
        std::ostringstream text;
        text << std::setprecision(17) << v;
        one.back().value = text.str();
        try {
            readModel(model, one);
        } catch (const SpecError& e) {
            // Only the missing unit is refused for the whole sweep; any
            // other error of this value stays the error of its points.
            if (std::string(e.what()).find(units::kBareNumberNeedsUnit) != std::string::npos)
                throw SpecError({"<" + option + " " + axis.path + "=...>", 1, 1}, axis.path, e.what());
        }
    }
    return spec;
}

std::vector<const ElementSchema*> elementSchemas() {
    const auto& registry = ElementRegistry::instance();
    std::vector<const ElementSchema*> out;
    for (const auto& name : registry.typeNames()) out.push_back(&registry.find(name)->schema);
    return out;
}

std::vector<const ElementSchema*> analysisSchemas() {
    std::vector<const ElementSchema*> out;
    for (const auto& kind : analysisKinds()) out.push_back(findAnalysisSchema(kind));
    return out;
}

bool isScheduleKey(const ParamSchema& p) { return isScheduleParam(p); }

std::vector<ValidationRow> validate(const std::string& filter) { return runValidationCases(filter); }

std::vector<std::string> writeValidationReportFiles(const std::string& dir, const std::vector<ValidationRow>& rows,
                                                    std::string& warning) {
    return writeValidationReport(dir, rows, reportSections(), warning);
}

}  // namespace milldyn
