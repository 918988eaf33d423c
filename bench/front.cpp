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
// Error: for each compared column c, max_i |x_i - r_i| / max_i |r_i| over
// the samples both runs share (same times); the row's error is the
// largest over the columns. Runs go from loose to tight accuracy; a run
// that passes the budget (wall seconds) is stopped (status "budget") and
// that integrator's tighter accuracies are skipped (status "skipped").

#include "driver/analyses/Analysis.h"

#include <algorithm>
#include <chrono>
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
    double wall = 0;
    AnalysisResult result;
};

Run runOnce(const std::string& model, const std::vector<Override>& overrides, double budget) {
    Run run;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
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
    run.wall = elapsed();
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

}  // namespace

int main(int argc, char** argv) {
    std::string model, refText, columnsText;
    double budget = 2;
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
    if (model.empty() || refText.empty() || columnsText.empty()) {
        std::cerr << "usage: bench_front MODEL --ref OVERRIDES --columns c1,c2 [--variant name:OVERRIDES]...\n";
        return 2;
    }
    if (variants.empty()) variants.push_back({"default", {}});
    const auto columns = split(columnsText, ',');

    std::vector<Override> refOverrides = base;
    for (const auto& o : overridesOf(refText)) refOverrides.push_back(o);
    const Run ref = runOnce(model, refOverrides, 0);
    if (ref.status != "ok") return 1;
    std::printf("variant,integrator,accuracy,status,error,wall_s,steps,realizations,step_attempts\n");
    std::printf("reference,%s,%g,ok,0,%.6g,%ld,%ld,%ld\n", ref.result.statistics.integrator.c_str(),
                ref.result.statistics.accuracy, ref.wall, ref.result.statistics.steps,
                ref.result.statistics.realizations, ref.result.statistics.stepAttempts);
    std::fflush(stdout);

    for (const auto& variant : variants) {
        // A replayed run (no free degrees of freedom) uses no integrator:
        // one row for the variant, whatever the integrator and accuracy.
        bool replayed = false;
        for (const auto& integrator : integrators) {
            if (replayed) break;
            bool skip = false;
            for (double accuracy : accuracies) {
                if (skip) {
                    std::printf("%s,%s,%g,skipped,,,,,\n", variant.first.c_str(), integrator.c_str(), accuracy);
                    continue;
                }
                std::vector<Override> o = base;
                o.insert(o.end(), variant.second.begin(), variant.second.end());
                char acc[32];
                std::snprintf(acc, sizeof acc, "%g", accuracy);
                o.push_back({"integrator.name", integrator});
                o.push_back({"integrator.accuracy", acc});
                Run run = runOnce(model, o, budget);
                // Short runs: best of three (the machine is shared).
                for (int k = 0; k < 2 && run.status == "ok" && run.wall < 0.2; ++k) {
                    Run again = runOnce(model, o, budget);
                    if (again.status == "ok" && again.wall < run.wall) run.wall = again.wall;
                }
                if (run.status != "ok") {
                    std::printf("%s,%s,%g,%s,,%.6g,,,\n", variant.first.c_str(), integrator.c_str(), accuracy,
                                run.status.c_str(), run.wall);
                    skip = run.status == "budget";
                } else if (run.result.statistics.integrator == "replay") {
                    const auto& s = run.result.statistics;
                    std::printf("%s,replay,0,ok,%.6g,%.6g,%ld,%ld,%ld\n", variant.first.c_str(),
                                errorAgainst(run.result, ref.result, columns), run.wall, s.steps, s.realizations,
                                s.stepAttempts);
                    replayed = true;
                    break;
                } else {
                    const auto& s = run.result.statistics;
                    std::printf("%s,%s,%g,ok,%.6g,%.6g,%ld,%ld,%ld\n", variant.first.c_str(), integrator.c_str(),
                                accuracy, errorAgainst(run.result, ref.result, columns), run.wall, s.steps,
                                s.realizations, s.stepAttempts);
                }
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
