// Issue 31 item 4. The drive capabilities (plugins/scene/DriveCapabilities.h)
// answer what the linear model and the motor reports asked of two motor
// types by name: a dq machine's fluxes and supply, a static curve.

#include "driver/Api.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "tests/driver/DqShaftModel.h"
#include "driver/analyses/LinearModel.h"
#include "plugins/scene/DriveCapabilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(DriveCapabilities, TheDqMachineDeclaresItsFluxesAndItsSupply) {
    const auto scene = buildScene(readModelText(kDqShaft, "dq.yaml", defaultModelReader(), {}));
    const auto* states = scene->findElement<ElectricalStates>("motor");
    ASSERT_NE(states, nullptr);
    // Single cage: stator and rotor flux, α and β each, in the frame of 2π·50 Hz.
    ASSERT_EQ(states->electricalStateCount(), 4);
    EXPECT_EQ(states->electricalStateName(0), "psi_s_alpha");
    EXPECT_EQ(states->electricalStateName(1), "psi_s_beta");
    EXPECT_EQ(states->electricalStateName(2), "psi_r1_alpha");
    EXPECT_EQ(states->electricalStateName(3), "psi_r1_beta");
    EXPECT_DOUBLE_EQ(states->electricalFrameSpeed(), 2 * M_PI * 50);
    EXPECT_EQ(dqMachineNames(*scene), (std::vector<std::string>{"motor"}));
    // No short_circuit_power: a stiff supply, nothing dips.
    const auto* supply = scene->findElement<SupplyVoltageDip>("motor");
    ASSERT_NE(supply, nullptr);
    EXPECT_FALSE(supply->hasSupplyImpedance());
    EXPECT_TRUE(std::isinf(supply->voltageDipLimit()));
    EXPECT_EQ(scene->findElement<StaticTorqueSpeedCurve>("motor"), nullptr);
    // The load is no drive of any kind.
    EXPECT_EQ(scene->findElement<ElectricalStates>("load"), nullptr);
}

TEST(DriveCapabilities, ADqMachineOnASupplyImpedanceReportsItsLargestDip) {
    // S_k = 200 kVA, X/R 5 under the 100 V machine, a start from rest; a
    // 1 % limit the start must exceed.
    const ModelSpec spec = readModelText(kDqShaft, "dq.yaml", defaultModelReader(),
                                         {{"elements.motor.short_circuit_power", "200000 W"},
                                          {"elements.motor.source_x_r", "5"},
                                          {"elements.motor.voltage_dip_limit", "0.01"},
                                          {"scenario.initial_state", "rest"},
                                          {"scenario.end_time", "0.2 s"},
                                          {"integrator.accuracy", "1e-6"}});
    const AnalysisResult r = runAnalysis(spec);
    const ResultScalar* dip = r.find("motor.voltage_dip");
    ASSERT_NE(dip, nullptr);
    EXPECT_TRUE(contains(dip->doc, "(S_k = 0.2 MVA, X/R = 5)")) << dip->doc;
    // Kept over every accepted step: at least the largest sampled dip.
    double sampled = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i) sampled = std::max(sampled, r.value(i, "motor.voltage_dip"));
    EXPECT_GT(sampled, 0.01);
    EXPECT_GE(dip->value, sampled);
    bool noted = false;
    for (const auto& n : r.notes) noted = noted || contains(n, "voltage dip: motor dips its supply by");
    EXPECT_TRUE(noted);
}

TEST(DriveCapabilities, TheKlossMotorIsAStaticCurveThroughItsRatedPoint) {
    // The burr mill: an InductionMotor on a Kloss curve, linearized.
    ModelSpec spec = readModel(kModels + "burr_mill_3p2kW_idle.yaml", {});
    spec.scenario = defaultScenario("linearize");
    const auto scene = buildScene(spec);
    const auto* curve = scene->findElement<StaticTorqueSpeedCurve>("motor");
    ASSERT_NE(curve, nullptr);
    EXPECT_EQ(scene->findElement<ElectricalStates>("motor"), nullptr);
    EXPECT_EQ(scene->findElement<SupplyVoltageDip>("motor"), nullptr);
    EXPECT_TRUE(dqMachineNames(*scene).empty());
    // Kloss passes through the rated point (21.3 N*m at 1437 rpm) and gives
    // no torque at synchronous speed (1500 rpm).
    EXPECT_NEAR(curve->torqueAtSpeed(1437 * 2 * M_PI / 60), 21.3, 1e-9 * 21.3);
    EXPECT_NEAR(curve->torqueAtSpeed(1500 * 2 * M_PI / 60), 0.0, 1e-9 * 21.3);
    // The linear model's note names it as the static slope, with its type.
    const AnalysisResult r = runAnalysis(spec);
    bool named = false;
    for (const auto& n : r.notes)
        named = named || contains(n, "motor (InductionMotor) as the static torque-speed slope at the operating point, "
                                     "in every motor model");
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace milldyn
