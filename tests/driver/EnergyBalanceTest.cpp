// Every shipped scene closes its energy balance: the work of the drives
// minus the loads' and the dampers' equals the change of kinetic and
// potential energy, up to the integration error.

#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace milldyn {
namespace {

// The work integrals are auxiliary states of the integration (EnergyMeter),
// controlled at the model's accuracy (1e-6 in every shipped model) per
// step; their global error over a run stays within a few times that. Ten
// times the accuracy leaves room for that accumulation, not for a missing
// energy flow (which shows at the size of the flow, 1e-4 and more).
constexpr double kBalanceTolerancePerAccuracy = 10;

TEST(EnergyBalanceTest, EveryShippedTimeSimulationClosesItsEnergyBalance) {
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(MILLDYN_SOURCE_DIR) + "/models")) {
        if (entry.path().extension() != ".yaml") continue;
        const ModelSpec spec = readModelFile(entry.path().string(), defaultModelReader(), {{"outputs.plots", "false"}});
        if (spec.scenario.type != "transient" && spec.scenario.type != "coastdown_identify") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const AnalysisResult r = runAnalysis(spec);
        const ResultScalar* relative = r.find("energy_balance_relative");
        ASSERT_NE(relative, nullptr);
        EXPECT_LE(std::abs(relative->value), kBalanceTolerancePerAccuracy * spec.integrator.accuracy);
        // Something actually flowed: the balance is not 0 = 0 (a coast-down
        // has no source, its loads take the kinetic energy; a clutch
        // engaging an unpowered flywheel only dissipates).
        EXPECT_GT(r.find("energy_from_sources")->value + r.find("energy_to_loads")->value +
                      r.find("energy_dissipated")->value,
                  0.0);
        ++checked;
    }
    EXPECT_GE(checked, 9);  // six burr-mill scenes, two identifications, the crusher
}

TEST(EnergyBalanceTest, MissingFlowWouldShow) {
    // The balance is not trivially satisfied: drop the load's work from it
    // (the residual then equals that work) and it fails by its full size.
    const ModelSpec spec = readModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml",
                                         defaultModelReader(), {{"outputs.plots", "false"}});
    const AnalysisResult r = runAnalysis(spec);
    const double withoutLoad = r.find("energy_balance_residual")->value - r.find("energy_to_loads")->value;
    EXPECT_GT(std::abs(withoutLoad), 1e3 * std::abs(r.find("energy_balance_residual")->value));
}

}  // namespace
}  // namespace milldyn
