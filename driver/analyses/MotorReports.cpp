#include "driver/analyses/MotorReports.h"

#include "plugins/scene/DriveCapabilities.h"
#include "plugins/scene/Format.h"

#include <string>

namespace milldyn {

namespace {

/// A start from rest was simulated (a start verdict, not steady running).
bool startedFromRest(const AnalysisResult& result) {
    return result.verdict == "completed" || result.verdict == "stalled" || result.verdict == "unfinished";
}

/**
 * What a start on a static torque-speed curve leaves out, per starter
 * (issue 28 item 3): a static curve has no electrical transient, so at
 * switch-on and at every switching of the starter the dq machine of the same
 * data peaks above it. `full` is the dq estimate of a full-voltage switch-on
 * (InductionMotor's addSwitchOnPeakEstimate; absent without the current
 * data), `atStarter` the same at the starter's switch-on voltage (star, a
 * soft start's initial voltage). A frequency converter ramps the
 * fundamental from standstill: no note.
 */
void addStaticCurveNote(const std::string& name, const std::string& starter, const DerivedValue* curve,
                        const DerivedValue* full, const DerivedValue* atStarter, AnalysisResult& result) {
    if (!curve || starter == "frequency_converter") return;
    const std::string head = "peak torque: " + name + " starts " + starter + " on a static torque-speed curve (largest "
                             "torque " + formatNumber(curve->value, 4) + " N*m), which has no electrical transient";
    const std::string noDesignLoad = ": this run's peak torques are no design load (DqInductionMotor with the "
                                     "datasheet and starter " + starter + " runs the transient)";
    const std::string noData = "; not estimated: rated_current, rated_power_factor, locked_rotor_current_ratio and "
                               "rated_efficiency give the dq machine's estimate";
    auto n = [](double v) { return formatNumber(v, 4) + " N*m"; };
    const std::string dqFull = full ? "the dq machine of the same data switched on at full voltage peaks at about " +
                                          n(full->value) + " (fitted double cage, rotor held for the first 3 cycles)"
                                    : std::string();
    if (starter == "direct_on_line") {
        if (!full)
            result.notes.push_back(head + noData + noDesignLoad);
        else if (full->value > curve->value)
            result.notes.push_back(head + "; " + dqFull + ", " + formatNumber(full->value / curve->value, 3) +
                                   " × the curve's" + noDesignLoad);
    } else if (starter == "star_delta") {
        result.notes.push_back(
            head + ": neither the switch-on in star" +
            (atStarter ? " (the dq machine: about " + n(atStarter->value) + ")" : std::string()) +
            " nor the reclosure in delta, which with the flux left out of phase can reach the full-voltage switch-on "
            "peak or more" + (full ? " (" + dqFull + ")" : noData) + noDesignLoad);
    } else if (starter == "soft_start") {
        if (!full)
            result.notes.push_back(head + noData + noDesignLoad);
        else if (full->value > curve->value)
            result.notes.push_back(head + " at its switch-on" +
                                   (atStarter ? " (the dq machine at the initial voltage: about " + n(atStarter->value) +
                                                    "; " + dqFull + ")"
                                              : "; " + dqFull) +
                                   noDesignLoad);
    } else {  // rotor_resistance, liquid_resistance: stepped or continuous added resistance
        result.notes.push_back(head + ": neither at switch-on nor at each change of the added rotor resistance" +
                               (full ? " (not estimated with the added resistance, which damps it; " + dqFull +
                                           " without it)"
                                     : noData) +
                               noDesignLoad);
    }
}

}  // namespace

// The drives in build order (Scene::drives()), asked what they can do
// (plugins/scene/DriveCapabilities.h): a supply impedance
// (SupplyVoltageDip: a DqInductionMotor with short_circuit_power), a static
// torque-speed curve (StaticTorqueSpeedCurve: an InductionMotor).
void addMotorReports(const Scene& scene, const SimTK::State& last, AnalysisResult& result) {
    auto derived = [&](const std::string& name) -> const DerivedValue* {
        for (const auto& d : scene.derivedValues())
            if (d.name == name) return &d;
        return nullptr;
    };
    for (const Scene::Drive& drive : scene.drives()) {
        const std::string& name = drive.element;
        if (const auto* supply = scene.findElement<SupplyVoltageDip>(name); supply && supply->hasSupplyImpedance()) {
            const double dip = supply->getPeakVoltageDip(last), limit = supply->voltageDipLimit();
            result.results.push_back({name + ".voltage_dip", dip, "1",
                                      "largest voltage dip 1 − |v|/|e| at " + name +
                                          "'s supply point over every accepted step (" +
                                          supply->supplyDescription() + ")"});
            if (dip > limit)
                result.notes.push_back("voltage dip: " + name + " dips its supply by " + formatNumber(100 * dip, 3) +
                                       " %, above its voltage_dip_limit " + formatNumber(100 * limit, 3) +
                                       " %: a gentler starter or a stiffer supply is needed");
        }
        if (scene.findElement<StaticTorqueSpeedCurve>(name) && startedFromRest(result))
            addStaticCurveNote(name, drive.startingSequence, derived(name + ".static_curve_peak"),
                               derived(name + ".dq_switch_on_peak_estimate"),
                               derived(name + ".dq_starter_switch_on_peak_estimate"), result);
    }
}

}  // namespace milldyn
