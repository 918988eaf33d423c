#include "driver/analyses/MotorReports.h"

#include "plugins/scene/DriveCapabilities.h"
#include "plugins/scene/Format.h"

#include <string>

namespace milldyn {

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
        if (scene.findElement<StaticTorqueSpeedCurve>(name)) {
            const DerivedValue* estimate = derived(name + ".dq_switch_on_peak_estimate");
            const DerivedValue* curve = derived(name + ".static_curve_peak");
            if (estimate && curve && estimate->value > curve->value)
                result.notes.push_back(
                    "peak torque: " + name + " runs on a static torque-speed curve (largest torque " +
                    formatNumber(curve->value, 4) + " N*m); the dq machine of the same data switched on line peaks at "
                    "about " + formatNumber(estimate->value, 4) + " N*m (" + formatNumber(estimate->value / curve->value, 3) +
                    " × it; fitted double cage, rotor held for the first 3 cycles): this run's peak torques are no "
                    "design load (DqInductionMotor with the datasheet runs the transient)");
        }
    }
}

}  // namespace milldyn
