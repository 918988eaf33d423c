#include "driver/Cli.h"

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/PluginLoader.h"
#include "driver/Sweep.h"
#include "driver/SweepMpi.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/OutputSet.h"
#include "driver/outputs/Schematic.h"
#include "driver/outputs/Writers.h"
#include "plugins/scene/ElementRegistry.h"
#include "validation/cases/ValidationCases.h"
#include "validation/report/ReportWriter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace milldyn {
namespace {

constexpr const char* kVersion = "0.1.0";

const char* kUsage =
    "usage:\n"
    "  milldyn run MODEL.yaml [--out DIR] [--set path=value]... [--scenario NAME]\n"
    "                         [--integrator NAME] [--accuracy TOL] [--end-time T] [--quiet]\n"
    "                         [--preset fast|balanced|accurate]  (the model's presets:; --set and\n"
    "                         --integrator/--accuracy still win over the preset's choices)\n"
    "                         [--schematic [--schematic-at t1,t2,...]]   (2-D pictures, docs/schematic.md)\n"
    "  milldyn info MODEL.yaml [--set path=value]...\n"
    "  milldyn validate [--filter TEXT] [--json] [--report DIR]\n"
    "  milldyn sweep MODEL.yaml (--grid path=a:b:n... | --lhs N --range path=a:b...) [--seed S]\n"
    "                           [--jobs N] [--shard i/N | --mpi] [--out DIR] [--set path=value]...\n"
    "  mpirun -np N milldyn sweep ... --mpi      (each rank runs its slice; rank 0 writes the table)\n"
    "  milldyn merge DIR... --out DIR\n"
    "  milldyn --version | --help\n"
    "  any command: --plugin LIB.so (repeatable) loads element types from a plugin library\n";

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Arguments {
    std::string command;
    std::string model;
    std::string outDir = "out";
    std::vector<Override> overrides;
    std::string filter;
    std::string reportDir;  ///< validate --report: where report.html/.md go
    bool json = false;
    bool quiet = false;
    std::vector<std::string> positional;  ///< after the model (merge: directories)
    std::vector<std::string> plugins;     ///< --plugin libraries, loaded first
    std::vector<std::string> grids, ranges;
    std::size_t lhs = 0;
    unsigned long seed = 1;
    unsigned jobs = 0;  ///< 0: all cores
    std::size_t shardIndex = 0, shardCount = 1;
    bool shardGiven = false;
    bool mpi = false;  ///< sweep --mpi: one slice per MPI rank
    bool schematic = false;     ///< run --schematic: SVG/PNG pictures of the machine
    std::string schematicAt;    ///< --schematic-at: times or carrier angles
};

std::size_t parseCount(const std::string& option, const std::string& text, std::size_t max) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || text[0] == '-' || v > max)
        throw UsageError(option + " needs a whole number up to " + std::to_string(max) + ", got '" + text + "'");
    return static_cast<std::size_t>(v);
}

Arguments parseArguments(const std::vector<std::string>& args) {
    Arguments a;
    if (args.empty()) throw UsageError("no command given");
    a.command = args[0];
    auto value = [&](std::size_t& i) -> const std::string& {
        if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
        return args[++i];
    };
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--out") a.outDir = value(i);
        else if (arg == "--set") a.overrides.push_back(parseOverride(value(i)));
        else if (arg == "--integrator") a.overrides.push_back({"integrator.name", value(i)});
        else if (arg == "--accuracy") a.overrides.push_back({"integrator.accuracy", value(i)});
        else if (arg == "--end-time") a.overrides.push_back({"scenario.end_time", value(i)});
        else if (arg == "--scenario") a.overrides.push_back({"use_scenario", value(i)});
        else if (arg == "--preset") a.overrides.push_back({"preset", value(i)});
        else if (arg == "--filter") a.filter = value(i);
        else if (arg == "--report") a.reportDir = value(i);
        else if (arg == "--grid") a.grids.push_back(value(i));
        else if (arg == "--plugin") a.plugins.push_back(value(i));
        else if (arg == "--range") a.ranges.push_back(value(i));
        else if (arg == "--lhs") a.lhs = parseCount(arg, value(i), 1000000);
        else if (arg == "--seed") a.seed = parseCount(arg, value(i), 4294967295ULL);
        else if (arg == "--jobs") a.jobs = static_cast<unsigned>(parseCount(arg, value(i), 1024));
        else if (arg == "--shard") {
            const std::string v = value(i);
            const auto slash = v.find('/');
            if (slash == std::string::npos) throw UsageError("--shard needs i/N, got '" + v + "'");
            a.shardIndex = parseCount("--shard", v.substr(0, slash), 1000000);
            a.shardCount = parseCount("--shard", v.substr(slash + 1), 1000000);
            if (a.shardCount == 0 || a.shardIndex >= a.shardCount)
                throw UsageError("--shard i/N needs 0 <= i < N, got '" + v + "'");
            a.shardGiven = true;
        }
        else if (arg == "--mpi") a.mpi = true;
        else if (arg == "--schematic") a.schematic = true;
        else if (arg == "--schematic-at") { a.schematicAt = value(i); a.schematic = true; }
        else if (arg == "--json") a.json = true;
        else if (arg == "--quiet") a.quiet = true;
        else if (!arg.empty() && arg[0] == '-') throw UsageError("unknown option " + arg);
        else if (a.model.empty()) a.model = arg;
        else if (a.command == "merge") a.positional.push_back(arg);
        else throw UsageError("unexpected argument " + arg);
    }
    if ((a.command == "run" || a.command == "info" || a.command == "sweep") && a.model.empty())
        throw UsageError(a.command + " needs a model file");
    if (!a.reportDir.empty() && a.command != "validate") throw UsageError("--report goes with validate");
    if (a.schematic && a.command != "run") throw UsageError("--schematic goes with run");
    if (a.command == "merge") {
        if (a.model.empty()) throw UsageError("merge needs sweep directories");
        a.positional.insert(a.positional.begin(), a.model);
    }
    return a;
}

std::string describeValue(const std::string& name, double v, const std::string& unit) {
    std::ostringstream s;
    s << std::setprecision(6) << v << ' ' << unit;
    // rpm for shaft speeds; a frequency in rad/s gets Hz instead.
    if (unit == "rad/s" && name.find("speed") != std::string::npos)
        s << " (" << std::setprecision(5) << v * 60 / (2 * M_PI) << " rpm)";
    else if (unit == "rad/s")
        s << " (" << std::setprecision(5) << v / (2 * M_PI) << " Hz)";
    if (unit == "W" && std::abs(v) >= 1000) s << " (" << std::setprecision(4) << v / 1000 << " kW)";
    return s.str();
}

std::string hostName() {
    char buf[256] = {0};
    if (::gethostname(buf, sizeof buf - 1) != 0) return "unknown";
    return buf;
}

int commandRun(const Arguments& a, std::ostream& out, std::ostream& err) {
    const ModelSpec spec = readModelFile(a.model, defaultModelReader(), a.overrides);
    OutputSet outputs(a.outDir);  // all new files or the old set untouched (docs/reliability.md)
    const bool showProgress = !a.quiet && ::isatty(STDERR_FILENO);
    auto lastReport = std::chrono::steady_clock::now();
    ProgressFn progress;
    if (showProgress)
        progress = [&](double t, double end) {
            const auto now = std::chrono::steady_clock::now();
            if (now - lastReport < std::chrono::milliseconds(500)) return;
            lastReport = now;
            err << "\r  simulated " << std::setprecision(4) << t << " of " << end << " s   " << std::flush;
        };
    // --schematic: check before the run that there is something to draw.
    std::unique_ptr<SchematicRecorder> recorder;
    bool angles = false;
    SampleObserver observer;
    if (a.schematic) {
        try {
            recorder = std::make_unique<SchematicRecorder>(parseSchematicInstants(spec, a.schematicAt, angles));
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        if (!sceneHasSketches(*buildScene(spec)))
            throw UsageError("--schematic: nothing to draw in " + a.model +
                             " (no element of it draws itself; GearMesh, SegmentCharge, BeltDrive and JointReaction do)");
        observer = [&](const Scene& scene, const SimTK::State& s, double key) { recorder->observe(scene, s, key); };
    }
    const auto start = std::chrono::steady_clock::now();
    AnalysisResult result = runAnalysis(spec, progress, observer);
    // What the preset picked, in the printed summary and summary.json.
    if (!spec.preset.empty()) {
        std::ostringstream picked;
        picked << "preset " << spec.preset << ": " << spec.integrator.name << " " << spec.integrator.accuracy;
        if (spec.integrator.maxStep > 0) picked << ", max_step " << spec.integrator.maxStep << " s";
        if (!spec.fidelity.empty()) picked << ", fidelity " << spec.fidelity;
        picked << " (" << spec.presetWhy << ")";
        result.notes.insert(result.notes.begin(), picked.str());
    }
    if (showProgress) err << "\r" << std::string(40, ' ') << "\r";
    RunInfo info;
    info.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    info.host = hostName();
    info.version = kVersion;
    for (const auto& r : result.results)
        if (!std::isfinite(r.value))
            throw AnalysisError("result " + r.name + " is not finite (the analysis diverged)");

    std::string warning;
    auto files = writeResultFiles(outputs.staging(), spec, result, info, warning);
    if (!warning.empty()) err << "milldyn: warning: " << warning << "\n";
    if (recorder) {
        std::string w;
        for (const auto& f : writeSchematics(outputs.staging(), spec.name, recorder->frames(), angles, w)) files.push_back(f);
        if (!w.empty()) err << "milldyn: warning: " << w << "\n";
    }
    files = outputs.commit(files);

    if (a.quiet) return 0;
    out << spec.name << "\n  analysis: " << result.analysis << "\n";
    for (const auto& r : result.results)
        out << "  " << r.name << std::string(std::max<std::size_t>(2, 26 - std::min<std::size_t>(26, r.name.size())), ' ')
            << describeValue(r.name, r.value, r.unit) << "\n";
    for (const auto& n : result.notes) out << "  note: " << n << "\n";
    if (result.statistics.steps > 0)
        out << "  integrator " << result.statistics.integrator << ", accuracy " << result.statistics.accuracy
            << ", " << result.statistics.steps << " steps, " << result.statistics.realizations << " realizations, ";
    else
        out << "  ";
    out << std::setprecision(3) << info.wallSeconds << " s wall\n  wrote";
    for (std::size_t i = 0; i < files.size(); ++i) out << (i ? ", " : " ") << files[i];
    out << "\n";
    return 0;
}

int commandInfo(const Arguments& a, std::ostream& out) {
    const ModelSpec spec = readModelFile(a.model, defaultModelReader(), a.overrides);
    auto scene = buildScene(spec);
    const SimTK::State state = scene->system().getDefaultState();
    out << spec.name << " (" << spec.file << ")\n";
    out << "  bodies: " << scene->bodies().size() << ", mobilities (DOF): " << state.getNU()
        << ", constraints: " << scene->matter().getNumConstraints()
        << ", forces: " << scene->forces().getNumForces() << "\n";
    for (const auto& b : spec.bodies)
        out << "  body " << b.name << ": pin on " << b.joint.parent << ", inertia " << b.inertia << " kg*m^2\n";
    for (const auto& e : spec.elements) out << "  element " << e.name << ": " << e.type << "\n";
    out << "  scenario: " << spec.scenario.type << ", integrator " << spec.integrator.name << " at accuracy "
        << spec.integrator.accuracy;
    if (spec.integrator.maxStep > 0) out << ", max_step " << spec.integrator.maxStep << " s";
    if (!spec.fidelity.empty()) out << ", fidelity " << spec.fidelity;
    out << "\n";
    if (!spec.presetNames.empty()) {
        out << "  presets:";
        for (const auto& p : spec.presetNames) out << " " << p;
        out << "\n";
    }
    if (!spec.preset.empty()) out << "  preset " << spec.preset << ": " << spec.presetWhy << "\n";
    if (!scene->derivedValues().empty()) {
        out << "  derived values:\n";
        for (const auto& d : scene->derivedValues()) {
            std::ostringstream v;
            v << std::setprecision(17) << d.value;
            out << "    " << d.name << " = " << v.str() << " " << d.unit << " — " << d.doc << "\n";
        }
    }
    out << "  built:\n";
    for (const auto& n : scene->notes()) out << "    " << n.what << " — " << n.why << "\n";
    if (!spec.notBuilt.empty() || !scene->omitted().empty()) {
        out << "  not built:\n";
        for (const auto& n : spec.notBuilt) out << "    " << n.what << " — " << n.why << "\n";
        for (const auto& n : scene->omitted()) out << "    " << n.what << " — " << n.why << "\n";
    }
    if (spec.scenario.type == "transient") {
        const std::string why = whyNoReplay(*scene, initialState(*scene, spec));
        out << "  time integration: "
            << (spec.scenario.text("zero_dof") == "integrate" ? "integrated (zero_dof: integrate)"
                : why.empty() ? "none: no free degrees of freedom, the run is replayed at the samples"
                              : why)
            << "\n";
    } else if (spec.scenario.type == "coastdown_identify") {
        out << "  time integration: integrated (run-outs after a switch-off)\n";
    } else if (spec.scenario.type == "frequency_response") {
        out << "  time integration: only the optional time-domain check of the linear response\n";
    } else {
        out << "  time integration: none (" << spec.scenario.type << " analysis)\n";
    }
    out << "  outputs:";
    for (const auto& p : scene->probes()) out << " " << p.name << "[" << p.unit << "]";
    out << "\n";
    return 0;
}

int commandSweep(const Arguments& a, std::ostream& out, std::ostream& err) {
    if (a.grids.empty() == (a.lhs == 0))
        throw UsageError("sweep needs --grid path=a:b:n ... or --lhs N with --range path=a:b ...");
    if (a.lhs > 0 && a.ranges.empty()) throw UsageError("--lhs needs at least one --range path=a:b");
    if (!a.grids.empty() && !a.ranges.empty()) throw UsageError("--range goes with --lhs, not with --grid");
    std::vector<SweepAxis> axes;
    for (const auto& g : a.grids) axes.push_back(parseGrid(g));
    for (const auto& r : a.ranges) axes.push_back(parseRange(r));
    const SweepPlan plan = a.lhs > 0 ? makeLatinHypercube(axes, a.lhs, a.seed) : makeGrid(axes);
    // The model must read before hundreds of points report the same error.
    readModelFile(a.model, defaultModelReader(), a.overrides);

    SweepOptions options;
    options.model = a.model;
    options.baseOverrides = a.overrides;
    options.jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
    options.shardIndex = a.shardIndex;
    options.shardCount = a.shardCount;
    options.outDir = a.outDir;
    const bool showProgress = !a.quiet && ::isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    auto progress = [&](std::size_t done, std::size_t total, std::size_t failed) {
        if (!showProgress) return;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double eta = done > 0 ? elapsed * double(total - done) / double(done) : 0;
        err << "\r  " << done << "/" << total << " points, " << failed << " failed, ETA " << std::setprecision(3)
            << eta << " s   " << std::flush;
    };
    SweepSummary summary;
    if (a.mpi) {
        if (a.shardGiven) throw UsageError("--mpi gives each rank its slice: leave out --shard");
        // Ranks are processes: one thread each unless --jobs says otherwise.
        options.jobs = a.jobs > 0 ? a.jobs : 1;
        const MpiSweepResult r = runSweepMpi(plan, options, progress);
        if (r.rank != 0) return 0;  // rank 0 reports for all
        summary = r.summary;
        options.jobs *= static_cast<unsigned>(r.size);
    } else {
        // N ranks of one sweep without --mpi would all run every point into one directory.
        if (launchedAsMpiRank() && !a.shardGiven)
            throw UsageError("started as one of several MPI ranks: add --mpi (or run one process per --shard)");
        summary = runSweep(plan, options, progress);
    }
    if (showProgress) err << "\r" << std::string(50, ' ') << "\r";
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!a.quiet)
        out << "sweep of " << a.model << ": " << summary.total << " points (" << summary.run << " run, "
            << summary.resumed << " resumed), " << summary.failed << " not ok, " << options.jobs << " jobs, "
            << std::setprecision(3) << wall << " s wall\n  wrote " << summary.files.front() << "\n";
    if (summary.total > 0 && summary.failed == summary.total) {
        err << "milldyn: sweep failed: every one of its " << summary.total << " points failed (see the diagnostic column of "
            << summary.files.front() << ")\n";
        return 1;
    }
    return 0;
}

int commandMerge(const Arguments& a, std::ostream& out) {
    const SweepSummary summary = mergeSweeps(a.positional, a.outDir);
    out << "merged " << a.positional.size() << " sweep directories: " << summary.total << " points, "
        << summary.failed << " not ok\n  wrote " << summary.files.front() << "\n";
    return 0;
}

int commandValidate(const Arguments& a, std::ostream& out, std::ostream& err) {
    const auto rows = runValidationCases(a.filter);
    if (a.json) {
        out << formatValidationJson(rows);
    } else {
        out << formatValidationTable(rows);
    }
    if (!a.reportDir.empty()) {
        std::string warning;
        const auto files = writeValidationReport(a.reportDir, rows, reportSections(), warning);
        if (!warning.empty()) err << "milldyn: warning: " << warning << "\n";
        (a.json ? err : out) << "wrote " << files.size() << " report files: " << a.reportDir << "/report.html, "
            << a.reportDir << "/report.md\n";
    }
    for (const auto& r : rows)
        if (r.status == "fail") return 1;
    return 0;
}

}  // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    try {
        if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
            out << kUsage;
            return 0;
        }
        if (!args.empty() && args[0] == "--version") {
            out << "milldyn " << kVersion << "\n";
            return 0;
        }
        const Arguments a = parseArguments(args);
        for (const auto& p : a.plugins) loadPlugin(p);
        if (a.command == "run") return commandRun(a, out, err);
        if (a.command == "info") return commandInfo(a, out);
        if (a.command == "validate") return commandValidate(a, out, err);
        if (a.command == "sweep") return commandSweep(a, out, err);
        if (a.command == "merge") return commandMerge(a, out);
        throw UsageError("unknown command '" + a.command + "'");
    } catch (const UsageError& e) {
        err << "milldyn: error: " << e.what() << "\n" << kUsage;
        return 2;
    } catch (const SpecError& e) {
        err << e.formatted() << "\n";
        return 2;
    } catch (const AnalysisError& e) {
        err << "milldyn: analysis failed: " << e.what() << "\n";
        return 1;
    } catch (const OutputError& e) {
        err << "milldyn: output failed: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        err << "milldyn: internal error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace milldyn
