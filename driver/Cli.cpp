#include "driver/Cli.h"

#include "driver/Front.h"
#include "plugins/scene/Format.h"

#include "driver/Api.h"
#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/PluginLoader.h"
#include "driver/SchemaReference.h"
#include "driver/Sweep.h"
#include "driver/SweepMpi.h"
#include "driver/outputs/SweepPlots.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/OutputSet.h"
#include "driver/outputs/Schematic.h"
#include "driver/outputs/Writers.h"
#include "plugins/scene/EngineTag.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace milldyn {
namespace {

const char* kUsage =
    "usage:\n"
    "  milldyn run MODEL.yaml [--out DIR] [--set path=value]... [--scenario NAME]\n"
    "                         [--integrator NAME] [--accuracy TOL] [--end-time T] [--quiet]\n"
    "                         [--preset fast|balanced|accurate]  (the model's presets:; --set and\n"
    "                         --integrator/--accuracy still win over the preset's choices)\n"
    "                         [--schematic [--schematic-at t1,t2,...]]   (2-D pictures, docs/schematic.md)\n"
    "                         [--check-resolution]  (again at accuracy/10: warns of peaks and ripples it moves)\n"
    "  milldyn info MODEL.yaml [--set path=value]... [--json]\n"
    "  milldyn validate [--filter TEXT] [--json] [--report DIR]\n"
    "  milldyn sweep MODEL.yaml (--grid path=a:b:n... | --lhs N --range path=a:b...) [--seed S]\n"
    "                           [--jobs N] [--shard i/N | --mpi] [--out DIR] [--set path=value]...\n"
    "                           [--integrator NAME] [--accuracy TOL] [--end-time T] [--no-plots]\n"
    "                           (--grid also path=a:b:n:log, path=v1,v2,..., 'p=...;q=...' tied)\n"
    "  mpirun -np N milldyn sweep ... --mpi      (each rank runs its slice; rank 0 writes the table)\n"
    "  milldyn merge DIR... --out DIR\n"
    "  milldyn front MODEL.yaml [--out DIR] [--set path=value]... [--integrators A,B] [--accuracies a,b]\n"
    "                           [--reference NAME:TOL] [--budget S] [--repeat N] [--write-presets]\n"
    "                           (error-cost front of any model; presets beside it: docs/speed-accuracy.md)\n"
    "  milldyn elements [TYPE] [--json]   every element type: keys, units, defaults, ranges\n"
    "  milldyn analyses [KIND]            every analysis (scenario.analysis) and its keys\n"
    "  milldyn schema                     JSON Schema of the model format (for YAML editors)\n"
    "  milldyn completion                 bash completion script\n"
    "  milldyn help [COMMAND] | COMMAND --help | --version\n"
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
    bool noPlots = false;  ///< sweep, merge: no sweep_*.png
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
    std::string topic;          ///< help COMMAND, elements TYPE, analyses KIND
    // front
    std::string integrators, accuracies, reference;  ///< comma lists; NAME:TOL
    double budget = 0;                               ///< CPU s per point (0: from the reference)
    std::size_t repeat = 1;
    bool writePresets = false;
    bool checkResolution = false;  ///< run --check-resolution
};

std::size_t parseCount(const std::string& option, const std::string& text, std::size_t max) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || text[0] == '-' || v > max)
        throw UsageError(option + " needs a whole number up to " + std::to_string(max) + ", got '" + text + "'");
    return static_cast<std::size_t>(v);
}

/// `--end-time 0.3` means seconds (the option names its unit); a written
/// unit ("300 ms") is passed on as is.
std::string secondsIfBare(const std::string& text) {
    const auto last = text.find_last_not_of(" \t");
    if (last != std::string::npos && (std::isdigit(static_cast<unsigned char>(text[last])) || text[last] == '.'))
        return text + " s";
    return text;
}

/// What a command line may say: the commands with their options. Built
/// anew for each parse; the options write into `a`.
struct CommandLine {
    CLI::App app{"milldyn: multibody simulation of the drive trains of grinding mills and crushers", "milldyn"};
    std::map<std::string, CLI::App*> commands;
    std::vector<std::string> sets, shard, lhs, seed, jobs, integrator, accuracy, endTime, scenario, preset;

    /// One value per occurrence, every occurrence kept (a vector option
    /// would otherwise swallow the model file after it).
    static CLI::Option* repeatable(CLI::Option* o) {
        return o->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    }

    explicit CommandLine(Arguments& a) {
        app.set_help_flag("-h,--help", "print this help");
        app.require_subcommand(0, 1);
        // As the hand parser before: an option given twice takes its last value.
        app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        auto command = [&](const std::string& name, const std::string& what) {
            CLI::App* c = app.add_subcommand(name, what);
            c->set_help_flag("-h,--help", "print the help of " + name);
            repeatable(c->add_option("--plugin", a.plugins, "load element types from a plugin library (repeatable)"))
                ->type_name("LIB.so");
            commands[name] = c;
            return c;
        };
        auto modelOptions = [&](CLI::App* c) {
            c->add_option("model", a.model, "the model file")->type_name("MODEL.yaml");
            repeatable(c->add_option("--set", sets, "override one value of the model file, with its unit (repeatable)"))
                ->type_name("path=value");
            repeatable(c->add_option("--scenario", scenario, "run the named scenario of scenarios:"))->type_name("NAME");
            repeatable(c->add_option("--preset", preset, "apply the model's named preset"))->type_name("NAME");
        };
        CLI::App* run = command("run", "run the model's analysis and write its tables, summary.json and plots");
        modelOptions(run);
        run->add_option("--out", a.outDir, "output directory (default out)")->type_name("DIR");
        repeatable(run->add_option("--integrator", integrator, "integrator (integrator.name)"))->type_name("NAME");
        repeatable(run->add_option("--accuracy", accuracy, "relative accuracy (integrator.accuracy)"))->type_name("TOL");
        repeatable(run->add_option("--end-time", endTime, "end time (scenario.end_time; seconds if no unit)"))->type_name("T");
        run->add_flag("--quiet", a.quiet, "print nothing on success");
        run->add_flag("--check-resolution", a.checkResolution,
                      "run again at a tenth of the accuracy and warn of peaks and ripples that move by more than 1 %");
        run->add_flag("--schematic", a.schematic, "2-D pictures of the machine (docs/schematic.md)");
        run->add_option("--schematic-at", a.schematicAt, "times or carrier angles of the pictures")
            ->type_name("t1,t2,...");
        CLI::App* info = command("info", "bodies, DOF, elements, derived values, what was built and why");
        modelOptions(info);
        info->add_flag("--json", a.json, "the same as JSON (derived values at full precision)");
        CLI::App* validate = command("validate", "compare the multibody model with the papers' oracles");
        validate->add_option("--filter", a.filter, "only cases whose name contains TEXT")->type_name("TEXT");
        validate->add_flag("--json", a.json, "rows as JSON");
        validate->add_option("--report", a.reportDir, "write report.html and report.md into DIR")->type_name("DIR");
        CLI::App* sweep = command("sweep", "run the model over a grid or a Latin hypercube of parameters");
        modelOptions(sweep);
        repeatable(sweep->add_option("--grid", a.grids,
                                     "axis of a full grid (repeatable): a:b:n, a:b:n:log or v1,v2,...; "
                                     "'p=...;q=...' ties paths to one axis"))
            ->type_name("path=a:b:n");
        repeatable(sweep->add_option("--lhs", lhs, "Latin hypercube of N points"))->type_name("N");
        repeatable(sweep->add_option("--range", a.ranges, "axis of the hypercube (repeatable)"))->type_name("path=a:b");
        repeatable(sweep->add_option("--seed", seed, "seed of the hypercube"))->type_name("S");
        repeatable(sweep->add_option("--jobs", jobs, "parallel runs (default: all cores)"))->type_name("N");
        repeatable(sweep->add_option("--shard", shard, "run slice i of N"))->type_name("i/N");
        repeatable(sweep->add_option("--integrator", integrator, "integrator of every point (integrator.name)"))->type_name("NAME");
        repeatable(sweep->add_option("--accuracy", accuracy, "relative accuracy of every point (integrator.accuracy)"))->type_name("TOL");
        repeatable(sweep->add_option("--end-time", endTime, "end time of every point (scenario.end_time; seconds if no unit)"))->type_name("T");
        sweep->add_flag("--mpi", a.mpi, "one slice per MPI rank");
        sweep->add_option("--out", a.outDir, "output directory")->type_name("DIR");
        sweep->add_flag("--quiet", a.quiet, "print nothing on success");
        sweep->add_flag("--no-plots", a.noPlots, "write no sweep_*.png (also outputs.plots: false in the model)");
        CLI::App* front = command("front", "error-cost front of the model: its results at every integrator and "
                                           "accuracy against a tight reference, and presets from it");
        modelOptions(front);
        front->add_option("--out", a.outDir, "output directory for front.csv (default front)")->type_name("DIR");
        front->add_option("--integrators", a.integrators, "integrators to try (default RungeKuttaMerson,RungeKutta3,CPodes)")
            ->type_name("A,B,...");
        front->add_option("--accuracies", a.accuracies, "accuracies to try (default 1e-3,...,1e-8)")->type_name("a,b,...");
        front->add_option("--reference", a.reference, "the reference run (default RungeKuttaMerson:1e-10)")
            ->type_name("NAME:TOL");
        front->add_option("--budget", a.budget, "CPU seconds a point may take (default 2x the reference + 1 s)")
            ->type_name("S");
        front->add_option("--repeat", a.repeat, "rounds; CPU time is the median (default 1)")->type_name("N");
        front->add_flag("--write-presets", a.writePresets,
                        "write fast/balanced/accurate beside the model (MODEL.presets.yaml)");
        CLI::App* merge = command("merge", "join the parts of a sharded sweep");
        merge->add_option("dirs", a.positional, "sweep directories")->type_name("DIR...");
        merge->add_flag("--no-plots", a.noPlots, "write no sweep_*.png");
        merge->add_option("--out", a.outDir, "output directory")->type_name("DIR");
        CLI::App* elements = command("elements", "every element type with its keys, units, defaults and ranges");
        elements->add_option("type", a.topic, "only this element type")->type_name("TYPE");
        elements->add_flag("--json", a.json, "as JSON");
        CLI::App* analyses = command("analyses", "every analysis (scenario.analysis) with its keys");
        analyses->add_option("kind", a.topic, "only this analysis")->type_name("KIND");
        command("schema", "print the JSON Schema of the model format (for YAML editors)");
        command("completion", "print a bash completion script");
        CLI::App* help = command("help", "print the help of milldyn or of one command");
        help->add_option("command", a.topic, "the command")->type_name("COMMAND");
    }
};

/// The first line of a CLI11 message, without its trailing "Run with --help".
std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    return line;
}

Arguments parseArguments(const std::vector<std::string>& args, std::string* helpText) {
    Arguments a;
    if (args.empty()) throw UsageError("no command given (milldyn help lists the commands)");
    CommandLine cl(a);
    if (args[0].empty() || args[0][0] != '-') {
        if (!cl.commands.count(args[0]))
            throw UsageError("unknown command '" + args[0] + "'" +
                             [&] {
                                 std::vector<std::string> names;
                                 for (const auto& c : cl.commands) names.push_back(c.first);
                                 const std::string near = nearestName(args[0], names);
                                 return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
                             }());
    }
    // An option of another command: say which command takes it.
    if (cl.commands.count(args[0])) {
        const CLI::App* given = cl.commands.at(args[0]);
        for (std::size_t i = 1; i < args.size(); ++i) {
            if (args[i].rfind("--", 0) != 0) continue;
            const std::string option = args[i].substr(0, args[i].find('='));
            if (given->get_option_no_throw(option)) continue;
            std::string owners;
            for (const auto& c : cl.commands)
                if (c.second->get_option_no_throw(option)) owners += (owners.empty() ? "" : " or ") + c.first;
            if (!owners.empty()) throw UsageError(option + " goes with " + owners);
        }
    }
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses from the back
    try {
        cl.app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        CLI::App* asked = nullptr;
        for (const auto& c : cl.commands)
            if (c.second->parsed()) asked = c.second;
        *helpText = asked ? asked->help() : std::string(kUsage) + "\n" + cl.app.help();
        a.command = "help";
        return a;
    } catch (const CLI::ParseError& e) {
        throw UsageError(firstLine(e.what()));
    }
    for (const auto& c : cl.commands)
        if (c.second->parsed()) a.command = c.first;
    if (a.command.empty()) throw UsageError("no command given (milldyn help lists the commands)");
    if (a.command == "help") {
        if (a.topic.empty()) {
            *helpText = std::string(kUsage) + "\n" + cl.app.help();
        } else {
            auto it = cl.commands.find(a.topic);
            if (it == cl.commands.end()) throw UsageError("help: unknown command '" + a.topic + "'");
            *helpText = it->second->help();
        }
        return a;
    }
    for (const auto& s : cl.sets) a.overrides.push_back(parseOverride(s));
    // The shorthand options, in the order of the hand parser before them:
    // they are settings like any --set (and win over the preset).
    for (const auto& v : cl.integrator) a.overrides.push_back({"integrator.name", v});
    for (const auto& v : cl.accuracy) a.overrides.push_back({"integrator.accuracy", v});
    for (const auto& v : cl.endTime) a.overrides.push_back({"scenario.end_time", secondsIfBare(v)});
    for (const auto& v : cl.scenario) a.overrides.push_back({"use_scenario", v});
    for (const auto& v : cl.preset) a.overrides.push_back({"preset", v});
    if (!cl.lhs.empty()) a.lhs = parseCount("--lhs", cl.lhs.back(), 1000000);
    if (!cl.seed.empty()) a.seed = parseCount("--seed", cl.seed.back(), 4294967295ULL);
    if (!cl.jobs.empty()) a.jobs = static_cast<unsigned>(parseCount("--jobs", cl.jobs.back(), 1024));
    if (!cl.shard.empty()) {
        const std::string v = cl.shard.back();
        const auto slash = v.find('/');
        if (slash == std::string::npos) throw UsageError("--shard needs i/N, got '" + v + "'");
        a.shardIndex = parseCount("--shard", v.substr(0, slash), 1000000);
        a.shardCount = parseCount("--shard", v.substr(slash + 1), 1000000);
        if (a.shardCount == 0 || a.shardIndex >= a.shardCount)
            throw UsageError("--shard i/N needs 0 <= i < N, got '" + v + "'");
        a.shardGiven = true;
    }
    if (!a.schematicAt.empty()) a.schematic = true;
    if (a.command == "front" && a.outDir == "out") a.outDir = "front";
    if ((a.command == "run" || a.command == "info" || a.command == "sweep" || a.command == "front") && a.model.empty())
        throw UsageError(a.command + " needs a model file");
    if (a.command == "merge" && a.positional.empty()) throw UsageError("merge needs sweep directories");
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

int commandRun(const Arguments& a, std::ostream& out, std::ostream& err) {
    const ModelSpec spec = readModel(a.model, a.overrides);
    const std::string noGravity = gravityWarning(spec, defaultModelReader());
    if (!noGravity.empty()) err << "milldyn: warning: " << noGravity << "\n";
    for (const auto& n : spec.readNotes) err << "milldyn: note: " << n << "\n";
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
                             " (no element of it draws itself; docs/schematic.md lists those that do)");
        observer = [&](const Scene& scene, const SimTK::State& s, double key) { recorder->observe(scene, s, key); };
    }
    RunOutcome run = runModel(spec, progress, observer);
    if (a.checkResolution) checkResolution(spec, run.result);
    const AnalysisResult& result = run.result;
    const RunInfo& info = run.info;
    if (showProgress) err << "\r" << std::string(40, ' ') << "\r";

    std::string warning;
    auto files = writeRunFiles(outputs.staging(), spec, run, warning);
    if (!warning.empty()) err << "milldyn: warning: " << warning << "\n";
    if (recorder) {
        std::string w;
        for (const auto& f : writeSchematics(outputs.staging(), spec.name, recorder->frames(), angles, w)) files.push_back(f);
        if (!w.empty()) err << "milldyn: warning: " << w << "\n";
    }
    files = outputs.commit(files);

    // A start that stalled is a machine that does not do what was asked:
    // its outputs are written, the verdict says why, exit 3. An unfinished
    // start (end_time too short) prints its verdict and no steady values,
    // and exits 0: the run did what it was told.
    const int code = runExitCode(result);  // one rule with the Python module (driver/Api.h)
    if (a.quiet) {
        if (code) err << "milldyn: " << result.verdictText << "\n";
        return code;
    }
    out << spec.name << "\n  analysis: " << result.analysis << "\n";
    if (!result.verdict.empty()) out << "  verdict: " << result.verdictText << "\n";
    for (const auto& r : result.results)
        out << "  " << r.name << std::string(std::max<std::size_t>(2, 26 - std::min<std::size_t>(26, r.name.size())), ' ')
            << describeValue(r.name, r.value, r.unit) << (r.referredTo.empty() ? "" : " on " + r.referredTo) << "\n";
    for (const auto& n : result.notes) out << "  note: " << n << "\n";
    if (result.statistics.steps > 0)
        out << "  integrator " << result.statistics.integrator << ", accuracy " << result.statistics.accuracy
            << ", " << result.statistics.steps << " steps, " << result.statistics.realizations << " realizations, ";
    else
        out << "  ";
    out << std::setprecision(3) << info.wallSeconds << " s wall\n  wrote";
    for (std::size_t i = 0; i < files.size(); ++i) out << (i ? ", " : " ") << files[i];
    out << "\n";
    return code;
}

int commandInfo(const Arguments& a, std::ostream& out) {
    const ModelInfo info = describeModel(readModel(a.model, a.overrides));
    if (a.json) {
        // The same facts for programs; numbers at full precision (JSON
        // doubles round-trip), derived values as in summary.json.
        nlohmann::ordered_json j;
        j["name"] = info.name;
        j["file"] = info.file;
        j["bodies"] = info.bodies;
        j["mobilities"] = info.mobilities;
        j["constraints"] = info.constraints;
        j["forces"] = info.forces;
        for (const auto& b : info.bodyList)
            j["body"][b.name] = {{"parent", b.parent}, {"inertia", {{"value", b.inertia}, {"unit", "kg*m^2"}}}};
        for (const auto& e : info.elements) j["elements"][e.name] = e.type;
        j["scenario"] = info.scenario;
        j["integrator"] = {{"name", info.integrator}, {"accuracy", info.accuracy}};
        if (!info.fidelity.empty()) j["fidelity"] = info.fidelity;
        j["warnings"] = info.warnings;
        j["notes"] = info.notes;
        j["derived"] = nlohmann::ordered_json::object();
        for (const auto& d : info.derived)
            j["derived"][d.name] = {{"value", d.value}, {"unit", d.unit}, {"description", d.doc}};
        j["built"] = nlohmann::ordered_json::array();
        for (const auto& n : info.built) j["built"].push_back({{"what", n.what}, {"why", n.why}});
        j["not_built"] = nlohmann::ordered_json::array();
        for (const auto& n : info.notBuilt) j["not_built"].push_back({{"what", n.what}, {"why", n.why}});
        j["outputs"] = nlohmann::ordered_json::object();
        for (const auto& p : info.outputs) j["outputs"][p.name] = p.unit;
        j["contributions"] = nlohmann::ordered_json::object();
        for (const auto& r : info.contributions) {
            nlohmann::ordered_json items = nlohmann::ordered_json::array();
            for (const auto& c : r.contributions)
                items.push_back({{"kind", contributionKindName(c.kind)},
                                 {"name", c.name},
                                 {"shaft", c.shaft},
                                 {"detail", c.detail}});
            j["contributions"][r.element] = {{"type", r.type}, {"items", items}};
        }
        out << j.dump(2) << "\n";
        return 0;
    }
    out << info.name << " (" << info.file << ")\n";
    for (const auto& w : info.warnings) out << "  warning: " << w << "\n";
    for (const auto& n : info.notes) out << "  note: " << n << "\n";
    out << "  bodies: " << info.bodies << ", mobilities (DOF): " << info.mobilities
        << ", constraints: " << info.constraints << ", forces: " << info.forces << "\n";
    for (const auto& b : info.bodyList)
        out << "  body " << b.name << ": pin on " << b.parent << ", inertia " << b.inertia << " kg*m^2\n";
    for (const auto& e : info.elements) out << "  element " << e.name << ": " << e.type << "\n";
    out << "  scenario: " << info.scenario << ", integrator " << info.integrator << " at accuracy " << info.accuracy;
    if (info.maxStep > 0) out << ", max_step " << info.maxStep << " s";
    if (!info.fidelity.empty()) out << ", fidelity " << info.fidelity;
    out << "\n";
    if (!info.presets.empty()) {
        out << "  presets:";
        for (const auto& p : info.presets) out << " " << p;
        out << "\n";
    }
    if (!info.preset.empty()) out << "  preset " << info.preset << ": " << info.presetWhy << "\n";
    if (!info.derived.empty()) {
        out << "  derived values:\n";
        for (const auto& d : info.derived) {
            std::ostringstream v;
            v << std::setprecision(17) << d.value;
            out << "    " << d.name << " = " << v.str() << " " << d.unit << " — " << d.doc << "\n";
        }
    }
    out << "  built:\n";
    for (const auto& n : info.built) out << "    " << n.what << " — " << n.why << "\n";
    if (!info.notBuilt.empty()) {
        out << "  not built:\n";
        for (const auto& n : info.notBuilt) out << "    " << n.what << " — " << n.why << "\n";
    }
    if (!info.contributions.empty()) {
        out << "  contributions (what each element registered):\n";
        for (const auto& r : info.contributions) {
            out << "    " << r.element << " (" << r.type << ")" << (r.contributions.empty() ? ": nothing" : "") << "\n";
            for (const auto& c : r.contributions)
                out << "      " << contributionKindName(c.kind) << " " << c.name
                    << (c.detail.empty() ? "" : " " + c.detail) << (c.shaft.empty() ? "" : ", on " + c.shaft) << "\n";
        }
    }
    out << "  time integration: " << info.timeIntegration << "\n";
    out << "  outputs:";
    for (const auto& p : info.outputs) out << " " << p.name << "[" << p.unit << "]";
    out << "\n";
    return 0;
}

/// The sweep's plots join its output files; what could not be drawn is a warning.
void addSweepPlots(bool plots, SweepLayout layout, const std::string& dir, SweepSummary& summary, std::ostream& err,
                   const std::vector<std::string>& select = {}) {
    if (!plots) return;
    std::string warning;
    const auto files = writeSweepPlots(dir, layout, warning, select);
    summary.files.insert(summary.files.end(), files.begin(), files.end());
    if (!warning.empty()) err << "milldyn: warning: " << warning << "\n";
}

int commandSweep(const Arguments& a, std::ostream& out, std::ostream& err) {
    SweepPlan plan;
    try {
        plan = makeSweepPlan(a.grids, a.ranges, a.lhs, a.seed);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    // A path swept twice or set and swept: refused before anything runs.
    checkSweepPaths(plan.axes, a.overrides);
    // The model and the grid's units are checked before hundreds of points
    // report the same error.
    const ModelSpec checked = checkSweepPlan(plan, a.model, a.overrides);
    const bool plots = checked.outputs.plots && !a.noPlots;

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
    const bool tied = std::any_of(plan.axes.begin(), plan.axes.end(), [](const SweepAxis& x) { return x.tiedToPrevious; });
    addSweepPlots(plots, !plan.cartesian || tied ? SweepLayout::Sample : a.shardCount > 1 ? SweepLayout::Infer : SweepLayout::Grid,
                  options.outDir, summary, err, checked.outputs.sweepPlots);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!a.quiet)
        out << "sweep of " << a.model << ": " << summary.total << " points (" << summary.run << " run, "
            << summary.resumed << " resumed), " << summary.failed << " not ok, " << options.jobs << " jobs, "
            << std::setprecision(3) << wall << " s wall\n  wrote " << summary.files.front() << "\n";
    if (!a.quiet && summary.files.size() > 1)
        out << "  wrote " << summary.files.size() - 1 << " plots (sweep_*.png)\n";
    if (summary.total > 0 && summary.errors == summary.total) {
        err << "milldyn: sweep failed: every one of its " << summary.total << " points failed (see the diagnostic column of "
            << summary.files.front() << ")\n";
        return 1;
    }
    return 0;
}

/// `milldyn front MODEL`: the model at every integrator and accuracy against
/// a tight reference (driver/Front.h), a table with the front marked,
/// front.csv, and with --write-presets MODEL.presets.yaml beside the model.
int commandFront(const Arguments& a, std::ostream& out, std::ostream& err) {
    auto list = [](const std::string& text) {
        std::vector<std::string> items;
        std::stringstream ss(text);
        for (std::string item; std::getline(ss, item, ',');)
            if (!item.empty()) items.push_back(item);
        return items;
    };
    auto integrator = [](const std::string& option, const std::string& name) {
        const auto& known = integratorNames();
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw UsageError(option + ": unknown integrator '" + name + "'" +
                             [&] {
                                 const std::string near = nearestName(name, known);
                                 return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
                             }());
        return name;
    };
    auto accuracy = [](const std::string& option, const std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(v > 0 && v < 1))
            throw UsageError(option + " needs accuracies between 0 and 1, got '" + text + "'");
        return v;
    };
    FrontOptions options;
    if (!a.integrators.empty()) {
        options.integrators.clear();
        for (const auto& n : list(a.integrators)) options.integrators.push_back(integrator("--integrators", n));
    }
    if (!a.accuracies.empty()) {
        options.accuracies.clear();
        for (const auto& t : list(a.accuracies)) options.accuracies.push_back(accuracy("--accuracies", t));
        std::sort(options.accuracies.rbegin(), options.accuracies.rend());  // loose to tight
    }
    if (!a.reference.empty()) {
        const auto colon = a.reference.find(':');
        if (colon == std::string::npos) throw UsageError("--reference needs NAME:TOL, got '" + a.reference + "'");
        options.referenceIntegrator = integrator("--reference", a.reference.substr(0, colon));
        options.referenceAccuracy = accuracy("--reference", a.reference.substr(colon + 1));
    }
    if (!(a.budget >= 0) || !std::isfinite(a.budget)) throw UsageError("--budget needs CPU seconds >= 0");
    options.budget = a.budget;
    if (a.repeat < 1 || a.repeat > 100) throw UsageError("--repeat needs a whole number from 1 to 100");
    options.repeat = static_cast<int>(a.repeat);
    for (const auto& p : options.accuracies)
        if (p <= options.referenceAccuracy)
            throw UsageError("--accuracies: " + formatNumber(p) + " is not looser than the reference's " +
                             formatNumber(options.referenceAccuracy));

    OutputSet outputs(a.outDir);  // all new files or the old set untouched
    const bool progress = !a.quiet && ::isatty(STDERR_FILENO);
    const FrontResult front = measureFront(a.model, a.overrides, options, [&](const std::string& line) {
        if (progress) err << "  " << line << "\n";
    });
    const std::string csv = outputs.staging() + "/front.csv";
    writeFileAtomically(csv, frontCsv(front));
    std::vector<std::string> files = outputs.commit({csv});
    std::string presetsFile;
    if (a.writePresets) {
        presetsFile = presetsFileBeside(a.model);
        writeFileAtomically(presetsFile, frontPresetsYaml(front));
        files.push_back(presetsFile);
    }
    if (a.quiet) return 0;
    out << "front of " << a.model << " against " << front.reference.integrator << " " << front.reference.accuracy
        << " (" << formatNumber(front.reference.cpuSeconds, 3) << " s CPU)\n"
        << "  errors: peaks and ripple against the torque floor " << formatNumber(front.torqueFloor, 4)
        << " N*m, steady window " << formatNumber(front.window.t0, 6) << " to " << formatNumber(front.window.t1, 6)
        << " s (docs/speed-accuracy.md)\n";
    out << "  integrator          accuracy  CPU [s]    peak     ripple   speed    time     energy   worst\n";
    for (const auto& p : front.points) {
        std::ostringstream line;
        line << "  " << (p.onFront ? "* " : "  ") << std::left << std::setw(18) << p.integrator << std::setw(10)
             << formatNumber(p.accuracy, 3);
        if (p.status != "ok") {
            line << p.status;
        } else {
            const DesignerErrors& e = p.errors;
            line << std::setw(11) << formatNumber(p.cpuSeconds, 3);
            for (double v : {e.peak, e.ripple, e.speed, e.time, e.energy, e.worst()})
                line << std::setw(9) << formatNumber(v, 2);
        }
        out << line.str() << "\n";
    }
    out << "  (* on the front: no cheaper point is as accurate)\n";
    for (const auto& preset : front.presets) {
        if (preset.point < 0) continue;
        const FrontPoint& p = front.points[static_cast<std::size_t>(preset.point)];
        out << "  preset " << preset.name << " (worst <= " << formatNumber(preset.target, 2) << "): " << p.integrator
            << " " << formatNumber(p.accuracy, 3) << ", worst " << formatNumber(p.errors.worst(), 2) << ", "
            << formatNumber(p.cpuSeconds, 3) << " s CPU\n";
    }
    for (const auto& n : front.notes) out << "  note: " << n << "\n";
    if (a.writePresets) {
        const ModelSpec spec = readModel(a.model, {});
        const bool beside = std::any_of(spec.readNotes.begin(), spec.readNotes.end(), [&](const std::string& n) {
            return n.find(presetsFile) != std::string::npos;
        });
        if (beside)
            out << "  presets: run with --preset NAME (read from " << presetsFile << ")\n";
        else
            out << "  note: " << a.model << " has its own presets: block, which wins over " << presetsFile
                << "; copy the presets into it or remove it\n";
    }
    out << "  wrote";
    for (std::size_t i = 0; i < files.size(); ++i) out << (i ? ", " : " ") << files[i];
    out << "\n";
    return 0;
}

int commandMerge(const Arguments& a, std::ostream& out, std::ostream& err) {
    SweepSummary summary = mergeSweeps(a.positional, a.outDir);
    addSweepPlots(!a.noPlots, SweepLayout::Infer, a.outDir, summary, err);
    out << "merged " << a.positional.size() << " sweep directories: " << summary.total << " points, "
        << summary.failed << " not ok\n  wrote " << summary.files.front() << "\n";
    if (summary.files.size() > 1) out << "  wrote " << summary.files.size() - 1 << " plots (sweep_*.png)\n";
    return 0;
}

int commandValidate(const Arguments& a, std::ostream& out, std::ostream& err) {
    const auto rows = validate(a.filter);
    if (a.json) {
        out << formatValidationJson(rows);
    } else {
        out << formatValidationTable(rows);
    }
    if (!a.reportDir.empty()) {
        std::string warning;
        const auto files = writeValidationReportFiles(a.reportDir, rows, warning);
        if (!warning.empty()) err << "milldyn: warning: " << warning << "\n";
        (a.json ? err : out) << "wrote " << files.size() << " report files: " << a.reportDir << "/report.html, "
            << a.reportDir << "/report.md\n";
    }
    for (const auto& r : rows)
        if (r.status == "fail") return 1;
    return 0;
}

int commandElements(const Arguments& a, std::ostream& out) {
    const ModelFileReader reader = defaultModelReader();
    if (!a.json) {
        out << formatElementReference(reader, a.topic);
        return 0;
    }
    formatElementReference(reader, a.topic);  // the unknown-type diagnostic
    const nlohmann::json schema = modelJsonSchema(reader);
    nlohmann::json types = nlohmann::json::object();
    for (const auto& variant : schema["properties"]["elements"]["items"]["allOf"]) {
        const std::string type = variant["if"]["properties"]["type"]["const"];
        if (a.topic.empty() || a.topic == type) types[type] = variant["then"];
    }
    out << types.dump(2) << "\n";
    return 0;
}

int commandAnalyses(const Arguments& a, std::ostream& out) {
    out << formatAnalysisReference(defaultModelReader(), a.topic);
    return 0;
}

int commandSchema(std::ostream& out) {
    out << modelJsonSchema(defaultModelReader()).dump(2) << "\n";
    return 0;
}

int commandCompletion(std::ostream& out) {
    out << bashCompletionScript(defaultModelReader());
    return 0;
}

}  // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    try {
        if (!args.empty() && args[0] == "--version") {
            out << "milldyn " << milldynVersion() << "\n" << kSimbodyEngine << "\n";
            return 0;
        }
        std::string helpText;
        const Arguments a = parseArguments(args, &helpText);
        if (a.command == "help") {
            out << helpText;
            return 0;
        }
        for (const auto& p : a.plugins) loadPlugin(p);
        if (a.command == "run") return commandRun(a, out, err);
        if (a.command == "info") return commandInfo(a, out);
        if (a.command == "validate") return commandValidate(a, out, err);
        if (a.command == "sweep") return commandSweep(a, out, err);
        if (a.command == "merge") return commandMerge(a, out, err);
        if (a.command == "front") return commandFront(a, out, err);
        if (a.command == "elements") return commandElements(a, out);
        if (a.command == "analyses") return commandAnalyses(a, out);
        if (a.command == "schema") return commandSchema(out);
        if (a.command == "completion") return commandCompletion(out);
        throw UsageError("unknown command '" + a.command + "'");
    } catch (const UsageError& e) {
        err << "milldyn: error: " << e.what() << " (milldyn help lists the commands and options)\n";
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
