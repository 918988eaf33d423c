// The error-cost front of one scene (issue #7, part 1), run on demand by
// bench/front.sh, never as a test. For every variant (a fidelity level, a
// journal-reaction mode, a max_step: any --set overrides), every
// integrator and every accuracy it runs the scene in process (no file
// output) and prints one CSV row: error against a reference run, wall
// time, steps, realizations.
//
//   bench_front MODEL --ref "path=value;..." --columns c1,c2 [--budget S]
//               [--set path=value]... [--variant "name:path=value;..."]...
//               [--integrators A,B] [--accuracies 1e-2,1e-3]
//
//               [--steady-end T1] [--repeat N]
//
// Trace error ("error"): for each compared column c, max_i |x_i - r_i| /
// max_i |r_i| over the samples both runs share (same times); the row's
// error is the largest over the columns (--columns; without it, none).
//
// What a designer reads (issue 20 item 11), each against the reference:
//  - peak_error: every summary peak (peak_drive_torque, peak.COUPLING),
//    |p - p_ref| / max(|p_ref|, F);
//  - ripple_error: every torque column (unit N*m), ripple = max - min over
//    the steady window, |R - R_ref| / max(R_ref, F);
//  - speed_error: steady_speed (or speed_at_end), |w - w_ref| /
//    max(|w_ref|, S), S = 1 % of the largest |speed| (rad/s column) of the
//    reference (a drive braked to rest ends near 0);
//  - time_error: start_time and runout_time, relative, a difference of up
//    to one sample interval not counted (they are sample times);
//  - energy: |energy_balance_relative| of the run itself.
// F, the torque floor, is 1 % of the largest |torque| of any torque column
// in the reference run. worst = the largest of these five.
// Steady window: the second half of [start_time of the reference (its
// first sample without one), T1], T1 = --steady-end (a switch-off time)
// or else the reference's last sample.
// Cost: process CPU time (bench/clocks.h, not wall: the machine is shared),
// the median over --repeat rounds (default 3) that alternate the points
// (round k runs every point once); realizations and steps are counted.
// Runs go from loose to tight accuracy; a run that passes the budget (CPU
// seconds) is stopped (status "budget") and that integrator's tighter
// accuracies are skipped (status "skipped").

#include "clocks.h"
#include "driver/Front.h"
#include "driver/analyses/Analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace milldyn;

struct OverBudget {};

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, sep);)
        if (!p.empty()) parts.push_back(p);
    return parts;
}

std::vector<Override> overridesOf(const std::string& text) {
    std::vector<Override> list;
    for (const auto& p : split(text, ';')) list.push_back(parseOverride(p));
    return list;
}

struct Run {
    std::string status = "ok";
    double cpu = 0;  ///< process CPU seconds
    AnalysisResult result;
};

Run runOnce(const std::string& model, const std::vector<Override>& overrides, double budget) {
    Run run;
    const bench::Stopwatch watch;
    auto elapsed = [&] { return watch.cpu(); };
    try {
        const ModelSpec spec = readModelFile(model, defaultModelReader(), overrides);
        run.result = runAnalysis(spec, [&](double, double) {
            if (budget > 0 && elapsed() > budget) throw OverBudget{};
        });
    } catch (const OverBudget&) {
        run.status = "budget";
    } catch (const std::exception& e) {
        run.status = "failed";
        std::cerr << "  failed: " << e.what() << "\n";
    }
    run.cpu = elapsed();
    return run;
}

double errorAgainst(const AnalysisResult& r, const AnalysisResult& ref, const std::vector<std::string>& columns) {
    double worst = 0;
    for (const auto& name : columns) {
        auto index = [&](const AnalysisResult& a) {
            for (std::size_t i = 0; i < a.columnNames.size(); ++i)
                if (a.columnNames[i] == name) return i;
            throw std::runtime_error("no column " + name);
        };
        const std::size_t ci = index(r), cr = index(ref);
        double scale = 0, diff = 0;
        std::size_t j = 0, matched = 0;
        for (const auto& row : ref.rows) scale = std::max(scale, std::abs(row[cr]));
        for (const auto& row : ref.rows) {
            while (j < r.rows.size() && r.rows[j][0] < row[0] - 1e-9) ++j;
            if (j >= r.rows.size()) break;
            if (std::abs(r.rows[j][0] - row[0]) > 1e-9) continue;
            const double d = std::abs(r.rows[j][ci] - row[cr]);
            diff = std::isfinite(d) ? std::max(diff, d) : INFINITY;
            ++matched;
        }
        if (matched + 1 < ref.rows.size()) return INFINITY;  // a run that stopped early
        worst = std::max(worst, diff / std::max(scale, 1e-300));
    }
    return worst;
}

// The errors of what a designer reads: driver/Front.h (one definition for
// this bench and `milldyn front`); the times keep one sample's allowance here.

using bench::median;

/// One output sample [s]: start and run-out times in this bench's tables
/// are compared with one sample's allowance (docs/speed-accuracy.md).
double sampleOf(const AnalysisResult& ref) { return ref.rows.size() > 1 ? ref.rows[1][0] - ref.rows[0][0] : 0.0; }

}  // namespace

struct Point {
    std::string variant, integrator;
    double accuracy = 0;
    std::vector<Override> overrides;
    std::string status;
    std::vector<double> cpu;
    RunStatistics stats;
    double error = 0;
    DesignerErrors designer;
};

int main(int argc, char** argv) {
    std::string model, refText, columnsText;
    double budget = 2;
    int repeat = 3;
    double steadyEnd = 0;
    std::vector<Override> base;
    std::vector<std::pair<std::string, std::vector<Override>>> variants;
    std::vector<std::string> integrators = integratorNames();
    std::vector<double> accuracies{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--ref") refText = next();
        else if (a == "--columns") columnsText = next();
        else if (a == "--budget") budget = std::atof(next().c_str());
        else if (a == "--repeat") repeat = std::max(1, std::atoi(next().c_str()));
        else if (a == "--steady-end") steadyEnd = std::atof(next().c_str());
        else if (a == "--set") base.push_back(parseOverride(next()));
        else if (a == "--variant") {
            const std::string v = next();
            const auto colon = v.find(':');
            variants.push_back({v.substr(0, colon), colon == std::string::npos ? std::vector<Override>{}
                                                                                : overridesOf(v.substr(colon + 1))});
        } else if (a == "--integrators") integrators = split(next(), ',');
        else if (a == "--accuracies") {
            accuracies.clear();
            for (const auto& x : split(next(), ',')) accuracies.push_back(std::atof(x.c_str()));
        } else model = a;
    }
    if (model.empty() || refText.empty()) {
        std::cerr << "usage: bench_front MODEL --ref OVERRIDES [--columns c1,c2] [--variant name:OVERRIDES]...\n";
        return 2;
    }
    if (variants.empty()) variants.push_back({"default", {}});
    const auto columns = split(columnsText, ',');

    std::vector<Override> refOverrides = base;
    for (const auto& o : overridesOf(refText)) refOverrides.push_back(o);
    const Run ref = runOnce(model, refOverrides, 0);
    if (ref.status != "ok") return 1;
    const SteadyWindow steady = steadyWindowOf(ref.result, steadyEnd);
    std::fprintf(stderr, "  reference %s %g: %.3g s CPU, steady window %g..%g s, torque floor %g N*m\n",
                 ref.result.statistics.integrator.c_str(), ref.result.statistics.accuracy, ref.cpu, steady.t0,
                 steady.t1, torqueFloorOf(ref.result));

    // Round 1: every point, loose to tight, skipping past the budget.
    std::vector<Point> points;
    for (const auto& variant : variants) {
        // A replayed run (no free degrees of freedom) uses no integrator:
        // one row for the variant, whatever the integrator and accuracy.
        bool replayed = false;
        for (const auto& integrator : integrators) {
            if (replayed) break;
            bool skip = false;
            for (double accuracy : accuracies) {
                Point p;
                p.variant = variant.first;
                p.integrator = integrator;
                p.accuracy = accuracy;
                if (skip) {
                    p.status = "skipped";
                    points.push_back(p);
                    continue;
                }
                p.overrides = base;
                p.overrides.insert(p.overrides.end(), variant.second.begin(), variant.second.end());
                char acc[32];
                std::snprintf(acc, sizeof acc, "%g", accuracy);
                p.overrides.push_back({"integrator.name", integrator});
                p.overrides.push_back({"integrator.accuracy", acc});
                const Run run = runOnce(model, p.overrides, budget);
                p.status = run.status;
                p.cpu.push_back(run.cpu);
                if (run.status == "ok") {
                    p.stats = run.result.statistics;
                    p.error = columns.empty() ? 0.0 : errorAgainst(run.result, ref.result, columns);
                    p.designer = designerErrors(run.result, ref.result, steady, sampleOf(ref.result));
                    if (p.stats.integrator == "replay") {
                        p.integrator = "replay";
                        p.accuracy = 0;
                        replayed = true;
                    }
                }
                skip = run.status == "budget";
                std::fprintf(stderr, "  %s %s %g: %s %.3g s worst %.3g\n", p.variant.c_str(), integrator.c_str(),
                             accuracy, p.status.c_str(), run.cpu, p.designer.worst());
                points.push_back(p);
                if (replayed) break;
            }
        }
    }
    // Rounds 2..repeat: the points again, in turn (CPU time median).
    for (int k = 1; k < repeat; ++k)
        for (auto& p : points)
            if (p.status == "ok" && p.cpu.front() < budget) p.cpu.push_back(runOnce(model, p.overrides, 0).cpu);

    std::printf("variant,integrator,accuracy,status,error,cpu_s,steps,realizations,step_attempts,"
                "peak_error,ripple_error,speed_error,time_error,energy,worst\n");
    const DesignerErrors refErrors = designerErrors(ref.result, ref.result, steady, 0);
    const auto& rs = ref.result.statistics;
    std::printf("reference,%s,%g,ok,0,%.6g,%ld,%ld,%ld,0,0,0,0,%.3g,%.3g\n", rs.integrator.c_str(), rs.accuracy,
                ref.cpu, rs.steps, rs.realizations, rs.stepAttempts, refErrors.energy, refErrors.energy);
    for (const auto& p : points) {
        if (p.status != "ok") {
            std::printf("%s,%s,%g,%s,,%s,,,,,,,,,\n", p.variant.c_str(), p.integrator.c_str(), p.accuracy,
                        p.status.c_str(), p.cpu.empty() ? "" : std::to_string(p.cpu.front()).c_str());
            continue;
        }
        const auto& d = p.designer;
        std::printf("%s,%s,%g,ok,%.3g,%.6g,%ld,%ld,%ld,%.3g,%.3g,%.3g,%.3g,%.3g,%.3g\n", p.variant.c_str(),
                    p.integrator.c_str(), p.accuracy, p.error, median(p.cpu), p.stats.steps, p.stats.realizations,
                    p.stats.stepAttempts, d.peak, d.ripple, d.speed, d.time, d.energy, d.worst());
    }
    return 0;
}
