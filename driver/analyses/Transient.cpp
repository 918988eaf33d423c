// Transient analysis: integrate the scene from its initial state, switch
// drives off when scheduled, and summarise steady running and run-out.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {

namespace {
/// |energy_balance_relative| above which a transient is refused as diverged.
constexpr double kEnergyBalanceLimit = 1e-2;
}  // namespace
namespace {

std::string probeNames(const Scene& scene, ProbeRole role) {
    std::string out;
    for (const auto& p : scene.probes())
        if (p.role == role) out += (out.empty() ? "" : ", ") + p.name;
    return out.empty() ? "none" : out;
}

std::string fmt(double v) {
    std::ostringstream o;
    o << std::setprecision(4) << v;
    return o.str();
}

/**
 * The start verdict over the samples up to the first switch-off (the start
 * window); returns whether the speed was held (also for a run that does not
 * start from rest, which gets no verdict). The reference speed ω_ref is the drives' rated speed referred
 * to speed_body (Scene::speedHints; the final speed if no drive hints one).
 * The speed is *held* when every sample of the last hold_time of the
 * window lies within start_tolerance·ω_ref of the window's last speed ω_e,
 * and its mean drift over that time, continued for another hold_time,
 * would not leave that band.
 *   completed:  held and ω_e >= stall_fraction·ω_ref
 *   stalled:    held and ω_e <  stall_fraction·ω_ref, and not still gaining
 *               speed over the second half of the run at >= a tenth of its
 *               mean rate since the start (the
 *               drive cannot take the load past this speed; the torques
 *               there are given)
 *   unfinished: not held (still accelerating, or oscillating) when the
 *               window ended
 */
bool judgeStart(const Scene& scene, const ModelSpec& spec, const SceneBody& body, std::size_t col, double switchTime,
                bool fromRest, AnalysisResult& result) {
    const ElementSpec& sc = spec.scenario;
    std::vector<const std::vector<double>*> window;
    for (const auto& row : result.rows)
        if (row[0] <= switchTime) window.push_back(&row);
    if (window.empty()) return false;
    const double tEnd = window.back()->at(0), wEnd = window.back()->at(col);
    const auto hints = scene.speedHints();
    const auto hint = hints.find(body.name);
    const bool hinted = hint != hints.end() && hint->second > 0;
    const double wRef = hinted ? hint->second : std::abs(wEnd);
    const double tol = sc.number("start_tolerance");
    const double hold = sc.number("hold_time") > 0 ? sc.number("hold_time") : 0.1 * (tEnd - window.front()->at(0));
    const double band = tol * wRef;
    bool held = window.front()->at(0) <= tEnd - hold && wRef > 0;
    double worst = 0;
    for (const auto* row : window)
        if (row->at(0) >= tEnd - hold) worst = std::max(worst, std::abs(row->at(col) - wEnd));
    // Held also means not drifting out: at the window's mean rate the speed
    // must stay in the band for another hold window.
    const double tWindow = std::max(tEnd - hold, window.front()->at(0));
    double wWindow = wEnd;
    for (const auto* row : window)
        if (row->at(0) >= tWindow) {
            wWindow = row->at(col);
            break;
        }
    const double drift = hold > 0 ? std::abs(wEnd - wWindow) / hold : 0;
    const double elapsed = tEnd - window.front()->at(0);
    held = held && worst <= band && drift * hold <= band;
    // A stall is an equilibrium: below the started speed a shaft that
    // gained speed over the second half of the run at >= a tenth of its mean
    // rate since the start is not stalled but slow (its start is
    // unfinished). Half the run, not the hold window: a belt mode rings
    // through a short window.
    const double meanRate = elapsed > 0 ? std::abs(wEnd - window.front()->at(col)) / elapsed : 0;
    const double tMid = window.front()->at(0) + 0.5 * elapsed;
    double wMid = wEnd, tMidSample = tEnd;
    for (const auto* row : window)
        if (row->at(0) >= tMid) {
            wMid = row->at(col);
            tMidSample = row->at(0);
            break;
        }
    const bool stillRising = tEnd > tMidSample && (wEnd - wMid) / (tEnd - tMidSample) > 0.1 * meanRate;
    if (!fromRest) return held;  // no start to judge: only whether the end is steady
    const double fraction = sc.number("stall_fraction");
    const std::string ref = hinted ? "the drives' running speed " + fmt(wRef) + " rad/s referred to " + body.name
                                   : "its final speed (no drive hints a rated speed)";
    const std::string holdText = "within ±" + fmt(band) + " rad/s (" + fmt(tol * 100) + " % of ω_ref) for the last " +
                                 fmt(hold) + " s before " + (tEnd >= switchTime ? "switch-off" : "the end");
    const double wRpm = wEnd * 30 / SimTK::Pi;
    if (held && std::abs(wEnd) >= fraction * wRef) {
        result.verdict = "completed";
        result.verdictText = "start completed: " + body.name + " held " + fmt(wEnd) + " rad/s (" + fmt(wRpm) + " rpm) " +
                             holdText + ", >= " + fmt(fraction * 100) + " % of ω_ref, " + ref;
    } else if (held && !stillRising) {
        result.verdict = "stalled";
        // Drive and load torques at the last sample of the window.
        std::string drive, load;
        for (std::size_t i = 0; i < scene.probes().size(); ++i) {
            const Probe& p = scene.probes()[i];
            const double v = window.back()->at(1 + 2 * scene.bodies().size() + i);
            if (p.role == ProbeRole::DriveTorque) drive += (drive.empty() ? "" : ", ") + p.name + " = " + fmt(v) + " N*m";
            if (p.role == ProbeRole::ResistanceTorque)
                load += (load.empty() ? "" : ", ") + p.name + " = " + fmt(v) + " N*m";
        }
        result.verdictText = "start stalled: " + body.name + " held " + fmt(wEnd) + " rad/s (" + fmt(wRpm) + " rpm, " +
                             fmt(100 * wEnd / wRef) + " % of " + ref + ") " + holdText + ", below the " +
                             fmt(fraction * 100) + " % that counts as started; there the drive torque is " +
                             (drive.empty() ? "none" : drive) + " against the load torque " +
                             (load.empty() ? "none" : load) +
                             " (each on its own shaft): the drive cannot take the load past this speed";
    } else {
        result.verdict = "unfinished";
        result.verdictText = "start unfinished: " + body.name + " was at " + fmt(wEnd) + " rad/s (" + fmt(wRpm) +
                             " rpm) at " + fmt(tEnd) + " s and not held " + holdText + " (it moved by up to " +
                             fmt(worst) + " rad/s): no start time or steady values are given; lengthen end_time";
    }
    result.results.push_back({"start_completed", result.verdict == "completed" ? 1.0 : 0.0, "1",
                              "1 if the start completed (see verdict), else 0"});
    return held;
}

}  // namespace

AnalysisResult runTransient(const ModelSpec& spec, const ProgressFn& progress, const SampleObserver& observer) {
    const ElementSpec& sc = spec.scenario;
    checkStopSpeed(spec);
    auto scene = buildScene(spec);
    SimTK::State state = initialState(*scene, spec);
    const std::string start = sc.text("initial_state");
    if (start == "rest")
        for (const auto& b : scene->bodies()) b.mobod.setOneU(state, SimTK::MobilizerUIndex(0), 0.0);
    if (start == "steady") state = solveSteadyState(*scene, state);

    AnalysisResult result;
    result.derived = derivedResults(*scene);
    result.analysis = "transient";
    SampleTable table(*scene, result);
    const SceneBody& speedBody = scenarioBody(*scene, sc, "speed_body");
    const double endTime = sc.number("end_time");

    double switchTime = std::numeric_limits<double>::infinity();
    for (const auto& e : scene->switchEvents())
        if (e.kind == Scene::SwitchEvent::Kind::DriveOff) switchTime = std::min(switchTime, e.time);

    Simulation sim(*scene, spec.integrator);
    sim.initialize(state, sc.text("zero_dof") == "replay");
    // A held charge's wall torque is an instant unknown: only a replayed run
    // solves it at every sample.
    for (const auto& e : spec.elements)
        if (e.type == "SegmentCharge" && e.text("motion") == "held" && !sim.isReplay())
            throw e.error("motion", "a held charge is a condition of each instant: a transient with one must have no "
                                    "free degree of freedom and be replayed (" +
                                        (sc.text("zero_dof") == "integrate" ? std::string("zero_dof is integrate")
                                                                            : sim.replayReason()) +
                                        "); use motion: with_drum or dynamic_lag");
    const SimTK::State first = sim.state();

    // Summary at the last sample before the first switch-off: steady running.
    // Samples fall on multiples of the interval and on the switch, so that
    // sample is within one interval of it; only those are copied (a State
    // copy costs more than an integration step), the end is sim.lastSample().
    SimTK::State steady = state;
    bool steadyCopied = false;
    const double copyFrom = switchTime - 1.5 * spec.outputs.sampleInterval;
    double peakDrive = 0;
    std::vector<double> peakCoupling(scene->probes().size(), 0.0);
    // outputs.peaks: their largest |value| and their value at the end.
    std::vector<bool> peakWanted(scene->probes().size(), false);
    for (std::size_t i = 0; i < scene->probes().size(); ++i)
        peakWanted[i] = std::find(spec.outputs.peaks.begin(), spec.outputs.peaks.end(), scene->probes()[i].name) !=
                        spec.outputs.peaks.end();
    auto onSample = [&](const SimTK::State& s) {
        const std::vector<double>& values = sim.probeValues();
        table.record(s, values);
        if (observer) {
            SimTK::State drawn = s;
            scene->system().realize(drawn, SimTK::Stage::Acceleration);
            observer(*scene, drawn, s.getTime());
        }
        if (s.getTime() <= switchTime && s.getTime() > copyFrom) {
            steady = s;
            steadyCopied = true;
        }
        double drive = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const ProbeRole role = scene->probes()[i].role;
            if (role == ProbeRole::DriveTorque) drive += values[i];
            if (role == ProbeRole::CouplingTorque || peakWanted[i])
                peakCoupling[i] = std::max(peakCoupling[i], std::abs(values[i]));
        }
        peakDrive = std::max(peakDrive, std::abs(drive));
        if (progress) progress(s.getTime(), endTime);
    };

    std::optional<double> stopTime;
    const std::string runoutName = sc.text("runout_body");
    if (!runoutName.empty() && std::isfinite(switchTime) && switchTime < endTime) {
        const Simulation::Watch watch = speedWatch(scene->findBody(runoutName)->mobod, sc.number("stop_speed"),
                                                   switchTime, runoutName + " comes to rest");
        stopTime = sim.run(endTime, spec.outputs.sampleInterval, onSample, &watch);
    } else {
        sim.run(endTime, spec.outputs.sampleInterval, onSample);
    }
    result.statistics = sim.statistics();
    if (!sim.replayNote().empty()) result.notes.push_back(sim.replayNote());
    const SimTK::State last = sim.lastSample();
    if (!steadyCopied && !(switchTime < sim.lastSample().getTime())) steady = last;

    scene->system().realize(steady, SimTK::Stage::Acceleration);
    const double omega = pinSpeed(steady, speedBody.mobod);
    const bool switched = switchTime < endTime;
    const std::string at = switched ? "just before switch-off" : "at the end of the run";

    // The start verdict (from rest only): over the samples before switch-off.
    const std::size_t speedCol = table.column(speedColumnName(*scene, speedBody));
    if (start == "rest") judgeStart(*scene, spec, speedBody, speedCol, switchTime, true, result);
    // A start that did not complete has no steady values. (A run from a
    // given or steady state keeps the names: what it ends in is the user's
    // question, e.g. a braked run-out's end speed.)
    const bool reached = start != "rest" || result.verdict == "completed";
    // A start that did not complete has no steady values: its numbers are
    // what the shafts did at the end of the start window.
    const std::string suffix = reached ? "" : "_at_end";
    result.results.push_back({reached ? "steady_speed" : "speed_at_end", omega, "rad/s",
                              "speed of " + speedBody.name + " " + at});
    result.results.push_back({"resistance_torque" + suffix, sumProbes(*scene, steady, ProbeRole::ResistanceTorque),
                              "N*m", "sum of load torques " + at + ", each on its own shaft (" +
                                         probeNames(*scene, ProbeRole::ResistanceTorque) + ")"});
    result.results.push_back({"power" + suffix, sumProbes(*scene, steady, ProbeRole::ResistancePower), "W",
                              "power absorbed by the loads " + at});
    result.results.push_back({"drive_torque" + suffix, sumProbes(*scene, steady, ProbeRole::DriveTorque), "N*m",
                              "sum of drive torques " + at + ", each on its own shaft (" +
                                  probeNames(*scene, ProbeRole::DriveTorque) + ")"});
    result.results.push_back({"peak_drive_torque", peakDrive, "N*m",
                              "largest drive torque of the run (" + probeNames(*scene, ProbeRole::DriveTorque) + ")"});
    // Couplings sit on shafts of different speeds: one peak each.
    for (std::size_t i = 0; i < scene->probes().size(); ++i)
        if (scene->probes()[i].role == ProbeRole::CouplingTorque) {
            const std::string name = scene->probes()[i].name;
            result.results.push_back({"peak." + name, peakCoupling[i], "N*m",
                                      "largest |" + name + "| of the run (on its from-shaft)"});
        }
    for (const std::string& name : spec.outputs.peaks)
        for (std::size_t i = 0; i < scene->probes().size(); ++i) {
            const Probe& p = scene->probes()[i];
            if (p.name != name || p.role == ProbeRole::CouplingTorque) continue;
            result.results.push_back({"peak." + name, peakCoupling[i], p.unit,
                                      "largest |" + name + "| of the run (outputs.peaks)"});
            result.results.push_back(
                {"final." + name, p.value(steady), p.unit, name + " " + at + " (outputs.peaks)"});
        }
    if (start == "rest" && omega > 0 && reached) {
        for (const auto& row : result.rows)
            if (row[speedCol] >= 0.95 * omega) {
                result.results.push_back({"start_time", row[0], "s",
                                          "first sample at 95 % of the steady speed of " + speedBody.name});
                break;
            }
    }
    if (stopTime) {
        result.results.push_back({"runout_time", *stopTime - switchTime, "s",
                                  "from switch-off to the first stop of " + runoutName});
        result.notes.push_back("run ended when " + runoutName + " came to rest");
    } else if (!runoutName.empty() && std::isfinite(switchTime)) {
        result.notes.push_back(runoutName + " did not come to rest before end_time");
    }

    addEnergyBalance(*scene, first, last, result);
    // A balance that misses by more than 1 % of the run's largest energy is
    // no result: the integration diverged or stepped too coarsely, even when
    // every sample stayed finite (a run-out stop can end the run first).
    const ResultScalar* balance = result.find("energy_balance_relative");
    if (balance && std::abs(balance->value) > kEnergyBalanceLimit) {
        std::ostringstream why;
        why << "transient: the energy balance does not close at t = " << last.getTime() << " s (residual "
            << balance->value << " of the run's largest energy, limit " << kEnergyBalanceLimit << "; integrator "
            << spec.integrator.name << ", accuracy " << spec.integrator.accuracy;
        if (spec.integrator.maxStep > 0) why << ", max_step " << spec.integrator.maxStep << " s";
        why << "): the integration diverged or is too coarse; tighten integrator.accuracy or max_step";
        throw AnalysisError(why.str());
    }
    addDefaultPlots(result);
    return result;
}

}  // namespace milldyn
