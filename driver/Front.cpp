#include "driver/Front.h"

#include "driver/Api.h"
#include "driver/SceneBuilder.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>

namespace milldyn {

double DesignerErrors::worst() const { return std::max({peak, ripple, speed, time, energy}); }

namespace {

bool isTorqueColumn(const AnalysisResult& r, std::size_t c) {
    return c < r.columnUnits.size() && r.columnUnits[c] == "N*m";
}

/// The summary's torque peaks: peak_drive_torque, peak.*, run_max.*, run_min.*.
bool isPeakTorque(const ResultScalar& s) {
    return s.unit == "N*m" && (s.name.rfind("peak", 0) == 0 || s.name.rfind("run_max.", 0) == 0 ||
                               s.name.rfind("run_min.", 0) == 0);
}

double relative(double x, double x0, double scale) {
    const double d = std::abs(x - x0) / std::max(scale, 1e-300);
    return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
}

double processCpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

struct OverBudget {};

}  // namespace

SteadyWindow steadyWindowOf(const AnalysisResult& ref, double steadyEnd) {
    const ResultScalar* start = ref.find("start_time");
    const double t0 = start ? start->value : (ref.rows.empty() ? 0.0 : ref.rows.front()[0]);
    double t1 = ref.rows.empty() ? 0.0 : ref.rows.back()[0];
    if (steadyEnd > 0) t1 = std::min(t1, steadyEnd - 1e-9);
    return {t0 + 0.5 * (t1 - t0), t1};
}

double torqueFloorOf(const AnalysisResult& ref) {
    double top = 0;
    for (std::size_t c = 1; c < ref.columnNames.size(); ++c)
        if (isTorqueColumn(ref, c))
            for (const auto& row : ref.rows) top = std::max(top, std::abs(row[c]));
    for (const auto& s : ref.results)
        if (isPeakTorque(s)) top = std::max(top, std::abs(s.value));
    return 0.01 * top;
}

double speedFloorOf(const AnalysisResult& ref) {
    double top = 0;
    for (std::size_t c = 1; c < ref.columnNames.size(); ++c)
        if (c < ref.columnUnits.size() && ref.columnUnits[c] == "rad/s")
            for (const auto& row : ref.rows) top = std::max(top, std::abs(row[c]));
    return 0.01 * top;
}

double rippleOf(const AnalysisResult& r, std::size_t c, const SteadyWindow& w) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& row : r.rows)
        if (row[0] >= w.t0 - 1e-12 && row[0] <= w.t1 + 1e-12) {
            lo = std::min(lo, row[c]);
            hi = std::max(hi, row[c]);
        }
    return hi >= lo ? hi - lo : 0.0;
}

DesignerErrors designerErrors(const AnalysisResult& r, const AnalysisResult& ref, const SteadyWindow& w,
                              double timeAllowance) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    DesignerErrors e;
    const double floor = torqueFloorOf(ref);
    const double speedScale = speedFloorOf(ref);
    for (const auto& s : ref.results) {
        const ResultScalar* mine = r.find(s.name);
        const bool peak = isPeakTorque(s);
        const bool speed = s.name == "steady_speed" || s.name == "speed_at_end";
        const bool time = s.name == "start_time" || s.name == "runout_time";
        if (!peak && !speed && !time) continue;
        if (!mine) {  // the run lost a quantity the reference has (a start that did not complete)
            (peak ? e.peak : speed ? e.speed : e.time) = kInf;
            continue;
        }
        if (peak) e.peak = std::max(e.peak, relative(mine->value, s.value, std::max(std::abs(s.value), floor)));
        if (speed) e.speed = std::max(e.speed, relative(mine->value, s.value, std::max(std::abs(s.value), speedScale)));
        if (time) {
            const double d = std::max(0.0, std::abs(mine->value - s.value) - timeAllowance * (1 + 1e-9));
            e.time = std::max(e.time, relative(d, 0.0, std::abs(s.value)));
        }
    }
    for (std::size_t c = 1; c < ref.columnNames.size(); ++c) {
        if (!isTorqueColumn(ref, c)) continue;
        const std::size_t mc = r.findColumn(ref.columnNames[c]);
        if (mc == std::string::npos) {
            e.ripple = kInf;
            continue;
        }
        const double r0 = rippleOf(ref, c, w);
        e.ripple = std::max(e.ripple, relative(rippleOf(r, mc, w), r0, std::max(r0, floor)));
    }
    if (const ResultScalar* b = r.find("energy_balance_relative")) e.energy = std::abs(b->value);
    if (!std::isfinite(e.energy)) e.energy = kInf;
    // A run that stopped before the steady window's end has no ripple to
    // compare (a run-out ends where each run finds its stop: the run-out
    // time compares that).
    if (r.rows.empty() || r.rows.back()[0] < w.t1 - 1e-9) e.ripple = kInf;
    return e;
}

namespace {

struct TimedRun {
    std::string status = "ok";
    double cpu = 0;
    AnalysisResult result;
};

TimedRun runTimed(const std::string& model, const std::vector<Override>& overrides, double budget) {
    TimedRun run;
    const double start = processCpuSeconds();
    try {
        const ModelSpec spec = readModel(model, overrides);
        run.result = runModel(spec, [&](double, double) {
                         if (budget > 0 && processCpuSeconds() - start > budget) throw OverBudget{};
                     }).result;
    } catch (const OverBudget&) {
        run.status = "budget";
    } catch (const SpecError&) {
        throw;  // the model itself is wrong: not a point of the front
    } catch (const std::exception& e) {
        run.status = std::string("failed: ") + e.what();
    }
    run.cpu = processCpuSeconds() - start;
    return run;
}

std::string accuracyText(double a) {
    std::ostringstream s;
    s << a;
    return s.str();
}

std::vector<Override> pointOverrides(const std::vector<Override>& base, const std::string& integrator, double accuracy) {
    std::vector<Override> o = base;
    o.push_back({"integrator.name", integrator});
    o.push_back({"integrator.accuracy", accuracyText(accuracy)});
    return o;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

FrontResult measureFront(const std::string& model, const std::vector<Override>& overrides, const FrontOptions& options,
                         const std::function<void(const std::string&)>& log) {
    FrontResult front;
    front.model = model;
    // The earliest drive switch-off ends the steady window (a run-out follows).
    double steadyEnd = 0;
    {
        const ModelSpec spec = readModel(model, overrides);
        // The scene is held here: a range-for over buildScene(spec)->drives()
        // would read the drives of a scene already destroyed (the temporary
        // lives only to the end of the range's initialiser before C++23).
        const auto scene = buildScene(spec);
        for (const auto& d : scene->drives())
            if (std::isfinite(d.switchOffTime) && d.switchOffTime > 0)
                steadyEnd = steadyEnd > 0 ? std::min(steadyEnd, d.switchOffTime) : d.switchOffTime;
    }
    const TimedRun ref =
        runTimed(model, pointOverrides(overrides, options.referenceIntegrator, options.referenceAccuracy), 0);
    if (ref.status != "ok")
        throw AnalysisError("front: the reference run (" + options.referenceIntegrator + " at " +
                            accuracyText(options.referenceAccuracy) + ") " + ref.status);
    const AnalysisResult& reference = ref.result;
    front.reference = {reference.statistics.integrator, reference.statistics.accuracy, "ok", ref.cpu,
                       reference.statistics.steps, reference.statistics.realizations, {}, false};
    front.reference.errors.energy = designerErrors(reference, reference, {}, 0).energy;
    front.window = steadyWindowOf(reference, steadyEnd);
    front.torqueFloor = torqueFloorOf(reference);
    front.speedFloor = speedFloorOf(reference);
    if (log)
        log("reference " + reference.statistics.integrator + " " + accuracyText(reference.statistics.accuracy) + ": " +
            formatNumber(ref.cpu, 3) + " s CPU, steady window " + formatNumber(front.window.t0, 6) + " to " +
            formatNumber(front.window.t1, 6) + " s, torque floor " + formatNumber(front.torqueFloor, 4) + " N*m");
    if (reference.statistics.integrator == "replay")
        front.notes.push_back("the model is replayed (nothing moves freely): no integrator or accuracy changes its "
                              "results, so there is no front; its presets are all the replay");

    const double budget = options.budget > 0 ? options.budget : 2 * ref.cpu + 1;
    std::vector<std::vector<double>> cpu;
    for (const std::string& integrator : options.integrators) {
        bool skip = reference.statistics.integrator == "replay";
        for (double accuracy : options.accuracies) {
            FrontPoint p;
            p.integrator = integrator;
            p.accuracy = accuracy;
            cpu.emplace_back();
            if (skip) {
                p.status = "skipped";
                front.points.push_back(p);
                continue;
            }
            const TimedRun run = runTimed(model, pointOverrides(overrides, integrator, accuracy), budget);
            p.status = run.status;
            p.cpuSeconds = run.cpu;
            cpu.back().push_back(run.cpu);
            if (run.status == "ok") {
                p.steps = run.result.statistics.steps;
                p.realizations = run.result.statistics.realizations;
                p.errors = designerErrors(run.result, reference, front.window, 0);
            }
            skip = run.status == "budget";
            if (log)
                log(integrator + " " + accuracyText(accuracy) + ": " + p.status + ", " + formatNumber(run.cpu, 3) +
                    " s CPU" + (run.status == "ok" ? ", worst error " + formatNumber(p.errors.worst(), 3) : ""));
            front.points.push_back(p);
        }
    }
    // Rounds 2..repeat, alternating the points: a CPU time is their median.
    for (int k = 1; k < options.repeat; ++k)
        for (std::size_t i = 0; i < front.points.size(); ++i)
            if (front.points[i].status == "ok")
                cpu[i].push_back(runTimed(model,
                                          pointOverrides(overrides, front.points[i].integrator, front.points[i].accuracy),
                                          0)
                                     .cpu);
    for (std::size_t i = 0; i < front.points.size(); ++i)
        if (!cpu[i].empty()) front.points[i].cpuSeconds = median(cpu[i]);

    // The front: sorted by CPU time, each point more accurate than every cheaper one.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < front.points.size(); ++i)
        if (front.points[i].status == "ok" && std::isfinite(front.points[i].errors.worst())) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return front.points[a].cpuSeconds < front.points[b].cpuSeconds; });
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i : order)
        if (front.points[i].errors.worst() < best) {
            best = front.points[i].errors.worst();
            front.points[i].onFront = true;
        }
    for (const auto& [name, target] : options.targets) {
        FrontPreset preset{name, target, -1};
        for (std::size_t i : order)
            if (front.points[i].errors.worst() <= target) {
                preset.point = static_cast<int>(i);
                break;
            }
        if (preset.point < 0 && reference.statistics.integrator != "replay")
            front.notes.push_back("preset " + name + ": no point within a worst error of " + formatNumber(target, 3) +
                                  " (tighten --accuracies or raise --budget)");
        front.presets.push_back(preset);
    }
    return front;
}

int checkResolution(const ModelSpec& spec, AnalysisResult& result, double tolerance) {
    if (result.statistics.integrator == "replay" || result.statistics.steps == 0) {
        result.notes.push_back("resolution: nothing checked (the run integrated nothing: replayed or solved at each "
                               "instant)");
        return 0;
    }
    ModelSpec finer = spec;
    finer.integrator.accuracy = spec.integrator.accuracy / 10;
    const AnalysisResult check = runAnalysis(finer);
    const double floor = torqueFloorOf(result);
    int unresolved = 0, checked = 0;
    std::vector<std::string> warnings;
    for (const auto& s : result.results) {
        const bool torque = isPeakTorque(s) || (s.name.rfind("peak_to_peak.", 0) == 0 && s.unit == "N*m");
        const bool relativeOnly = s.name.rfind("ripple.", 0) == 0 || s.name.rfind("speed_fluctuation.", 0) == 0;
        if (!torque && !relativeOnly) continue;
        ++checked;
        const ResultScalar* fine = check.find(s.name);
        const std::string at = formatNumber(spec.integrator.accuracy, 3);
        const std::string tighter = formatNumber(finer.integrator.accuracy, 3);
        if (!fine) {
            ++unresolved;
            warnings.push_back("warning: " + s.name + " = " + formatNumber(s.value, 6) + " " + s.unit +
                               " is not resolved: the run at accuracy " + tighter + " does not report it");
            continue;
        }
        const double scale = torque ? std::max(std::abs(fine->value), floor)
                                    : std::max(std::abs(s.value), std::abs(fine->value));
        const double change = std::abs(s.value - fine->value) / std::max(scale, 1e-300);
        if (!(change <= tolerance)) {
            ++unresolved;
            warnings.push_back("warning: " + s.name + " = " + formatNumber(s.value, 6) + " " + s.unit +
                               " is not resolved by accuracy " + at + ": " + formatNumber(fine->value, 6) + " " +
                               s.unit + " at " + tighter + " (a change of " + formatNumber(100 * change, 3) +
                               " %" + (torque ? " of max(|value|, the torque floor " + formatNumber(floor, 4) + " N*m)"
                                             : "") +
                               "); tighten integrator.accuracy (milldyn front measures the model's front)");
        }
    }
    result.notes.push_back("resolution: " + std::to_string(checked) + " peaks, peak-to-peak values and ripples " +
                           "checked against a run at accuracy " + formatNumber(finer.integrator.accuracy, 3) + ": " +
                           (unresolved ? std::to_string(unresolved) + " not resolved (warnings below)"
                                       : "each within " + formatNumber(100 * tolerance, 3) + " %"));
    for (auto& w : warnings) result.notes.push_back(std::move(w));
    return unresolved;
}

std::string frontCsv(const FrontResult& front) {
    std::ostringstream s;
    s << "integrator,accuracy,status,cpu_s,steps,realizations,peak_error,ripple_error,speed_error,time_error,energy,"
         "worst,front\n";
    auto row = [&](const FrontPoint& p, bool reference) {
        const std::string status = p.status.rfind("failed", 0) == 0 ? "failed" : p.status;
        s << p.integrator << "," << p.accuracy << "," << (reference ? "reference" : status) << ",";
        if (p.status != "ok") {
            s << (p.cpuSeconds > 0 ? formatNumber(p.cpuSeconds, 6) : "") << ",,,,,,,,,\n";
            return;
        }
        const DesignerErrors& e = p.errors;
        s << formatNumber(p.cpuSeconds, 6) << "," << p.steps << "," << p.realizations << "," << formatNumber(e.peak, 3)
          << "," << formatNumber(e.ripple, 3) << "," << formatNumber(e.speed, 3) << "," << formatNumber(e.time, 3) << ","
          << formatNumber(e.energy, 3) << "," << formatNumber(e.worst(), 3) << "," << (p.onFront ? 1 : 0) << "\n";
    };
    row(front.reference, true);
    for (const auto& p : front.points) row(p, false);
    return s.str();
}

std::string frontPresetsYaml(const FrontResult& front) {
    std::ostringstream s;
    s << "# Presets of " << front.model << ", written by `milldyn front` from its measured error-cost front\n"
      << "# (docs/speed-accuracy.md \"Your own model\"): each is the cheapest point whose worst error\n"
      << "# (peaks, ripple, steady speed, start and run-out times, energy balance) against\n"
      << "# " << front.reference.integrator << " at " << front.reference.accuracy
      << " is within its target. Read by milldyn beside the model when the model has no presets: block.\n"
      << "presets:\n";
    bool any = false;
    for (const auto& preset : front.presets) {
        if (preset.point < 0) continue;
        const FrontPoint& p = front.points[static_cast<std::size_t>(preset.point)];
        any = true;
        s << "  " << preset.name << ":\n"
          << "    why: \"" << p.integrator << " " << p.accuracy << ": worst error " << formatNumber(p.errors.worst(), 2)
          << " <= " << formatNumber(preset.target, 2) << ", " << formatNumber(p.cpuSeconds, 3)
          << " s CPU when measured (milldyn front)\"\n"
          << "    set: {integrator.name: " << p.integrator << ", integrator.accuracy: " << p.accuracy << "}\n";
    }
    if (!any) s << "  {}\n";
    return s.str();
}


}  // namespace milldyn
