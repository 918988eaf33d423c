// Transient analysis: integrate the scene from its initial state, switch
// drives off when scheduled, and summarise steady running and run-out.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace milldyn {

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
            if (role == ProbeRole::CouplingTorque) peakCoupling[i] = std::max(peakCoupling[i], std::abs(values[i]));
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
    result.results.push_back({"steady_speed", omega, "rad/s", "speed of " + speedBody.name + " " + at});
    result.results.push_back({"resistance_torque", sumProbes(*scene, steady, ProbeRole::ResistanceTorque), "N*m",
                              "sum of load torques " + at});
    result.results.push_back({"power", sumProbes(*scene, steady, ProbeRole::ResistancePower), "W",
                              "power absorbed by the loads " + at});
    result.results.push_back({"drive_torque", sumProbes(*scene, steady, ProbeRole::DriveTorque), "N*m",
                              "sum of drive torques " + at});
    result.results.push_back({"peak_drive_torque", peakDrive, "N*m", "largest drive torque of the run"});
    // Couplings sit on shafts of different speeds: one peak each.
    for (std::size_t i = 0; i < scene->probes().size(); ++i)
        if (scene->probes()[i].role == ProbeRole::CouplingTorque) {
            const std::string name = scene->probes()[i].name;
            result.results.push_back({"peak." + name, peakCoupling[i], "N*m",
                                      "largest |" + name + "| of the run (on its from-shaft)"});
        }
    if (start == "rest" && omega > 0) {
        const std::size_t col = table.column(speedColumnName(*scene, speedBody));
        for (const auto& row : result.rows)
            if (row[col] >= 0.95 * omega) {
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
    addDefaultPlots(result);
    return result;
}

}  // namespace milldyn
