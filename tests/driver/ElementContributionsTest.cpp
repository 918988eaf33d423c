// Issue 31 items 1 and 4: what each element registered with the scene
// (Scene::elementRecords, listed by `milldyn info`), and the capabilities
// generic code reads instead of element type names (ElementSchema).

#include "driver/Api.h"
#include "driver/Cli.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "plugins/scene/ElementRegistry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

const Contribution* findContribution(const ElementRecord& r, Contribution::Kind kind, const std::string& name) {
    for (const Contribution* c : r.of(kind))
        if (c->name == name) return c;
    return nullptr;
}

// burr_mill_3p2kW_idle.yaml: motor (Kloss, on motor_shaft, switched off at
// 4 s), belt (TorsionalCoupling motor_shaft → millstone, ratio 1), grinding
// (ResistanceTorque on millstone, smoothing 0.01 rad/s). The entries
// expected are read from each element's builder.
TEST(ElementContributions, TheBurrMillsElementsRecordWhatTheyRegistered) {
    const ModelInfo info = describeModel(readModel(kModels + "burr_mill_3p2kW_idle.yaml", {}));
    ASSERT_EQ(info.contributions.size(), 3u);
    const ElementRecord& motor = info.contributions[0];
    const ElementRecord& belt = info.contributions[1];
    const ElementRecord& grinding = info.contributions[2];
    EXPECT_EQ(motor.element, "motor");
    EXPECT_EQ(motor.type, "InductionMotor");
    EXPECT_EQ(belt.type, "TorsionalCoupling");
    EXPECT_EQ(grinding.type, "ResistanceTorque");
    using K = Contribution::Kind;

    // The motor: its drive facet, its torque probe on its shaft, its
    // switch-off event, its energy source.
    ASSERT_EQ(motor.of(K::Drive).size(), 1u);
    EXPECT_EQ(motor.of(K::Drive)[0]->shaft, "motor_shaft");
    EXPECT_NE(motor.of(K::Drive)[0]->detail.find("switched off at 4 s"), std::string::npos)
        << motor.of(K::Drive)[0]->detail;
    const Contribution* torque = findContribution(motor, K::Probe, "motor.torque");
    ASSERT_NE(torque, nullptr);
    EXPECT_EQ(torque->shaft, "motor_shaft");
    EXPECT_EQ(torque->detail, "[N*m], drive torque");
    const Contribution* off = findContribution(motor, K::SwitchEvent, "motor switched off");
    ASSERT_NE(off, nullptr);
    EXPECT_EQ(off->detail, "drive off at 4 s");
    EXPECT_NE(findContribution(motor, K::EnergyFlow, "motor"), nullptr);
    EXPECT_TRUE(motor.of(K::StartSequence).empty());  // direct on line: no sequence to finish
    EXPECT_TRUE(motor.of(K::RegularisationSpeed).empty());

    // The belt: its coupling torque, its twist rate held at zero in steady
    // running, its speed relation.
    const Contribution* coupling = findContribution(belt, K::Probe, "belt.torque");
    ASSERT_NE(coupling, nullptr);
    EXPECT_EQ(coupling->detail, "[N*m], coupling torque");
    EXPECT_EQ(coupling->shaft, "motor_shaft, millstone");  // it acts on both
    EXPECT_NE(findContribution(belt, K::SteadyResidual, "belt.twist_rate"), nullptr);
    ASSERT_EQ(belt.of(K::SpeedRelation).size(), 1u);
    EXPECT_EQ(belt.of(K::SpeedRelation)[0]->name, "motor_shaft / millstone");
    EXPECT_EQ(belt.of(K::SpeedRelation)[0]->detail, "ratio 1");
    EXPECT_TRUE(belt.of(K::Drive).empty());

    // The load: its resistance torque on the millstone, its load flow, its
    // regularisation speed from the file.
    const Contribution* load = findContribution(grinding, K::Probe, "grinding.torque");
    ASSERT_NE(load, nullptr);
    EXPECT_EQ(load->shaft, "millstone");
    EXPECT_EQ(load->detail, "[N*m], resistance torque");
    const Contribution* flow = findContribution(grinding, K::EnergyFlow, "grinding");
    ASSERT_NE(flow, nullptr);
    EXPECT_EQ(flow->detail, "load");
    ASSERT_EQ(grinding.of(K::RegularisationSpeed).size(), 1u);
    EXPECT_EQ(grinding.of(K::RegularisationSpeed)[0]->name, "smoothing_speed");
    EXPECT_EQ(grinding.of(K::RegularisationSpeed)[0]->detail, "0.01 rad/s");
}

// The loaded jaw-crusher restart: a breakaway holds the start back (a
// start hold), the crushing law is an excitation the steady state switches
// off, and a star-delta starter's sequence is the motor's.
TEST(ElementContributions, StartHoldsExcitationsAndStarterSequencesAreRecorded) {
    const auto scene = buildScene(readModel(kModels + "jaw_crusher_900x600_loaded_restart.yaml", {}));
    using K = Contribution::Kind;
    const ElementRecord* chamber = scene->findRecord("packed_chamber");
    ASSERT_NE(chamber, nullptr);
    EXPECT_EQ(chamber->type, "BreakawayResistance");
    ASSERT_EQ(chamber->of(K::StartHold).size(), 1u);
    EXPECT_EQ(chamber->of(K::StartHold)[0]->name, "packed_chamber");
    ASSERT_EQ(chamber->of(K::RegularisationSpeed).size(), 1u);
    EXPECT_EQ(chamber->of(K::RegularisationSpeed)[0]->detail, "0.002 rad/s");
    EXPECT_NE(findContribution(*chamber, K::DerivedValue, "packed_chamber.breakaway_excess"), nullptr);
    const ElementRecord* crushing = scene->findRecord("crushing");
    ASSERT_NE(crushing, nullptr);
    ASSERT_EQ(crushing->of(K::Excitation).size(), 1u);
    EXPECT_EQ(findContribution(*crushing, K::Probe, "crushing.torque")->shaft, "eccentric_shaft");
    EXPECT_FALSE(crushing->of(K::OrderExcitation).empty());
    // The scene's own lists hold the same: one start hold, from the chamber.
    ASSERT_EQ(scene->startHolds().size(), 1u);
    EXPECT_EQ(scene->startHolds()[0].name, "packed_chamber");

    const auto starDelta = buildScene(readModel(kModels + "start_bench_star_delta.yaml", {}));
    const ElementRecord* motor = starDelta->findRecord("motor");
    ASSERT_NE(motor, nullptr);
    ASSERT_EQ(motor->of(K::StartSequence).size(), 1u);
    EXPECT_NE(motor->of(K::Drive)[0]->detail.find("starting sequence star_delta"), std::string::npos);
    EXPECT_NE(findContribution(*motor, K::SwitchEvent, "motor star_delta step 1"), nullptr);
    EXPECT_EQ(findContribution(*motor, K::SwitchEvent, "motor star_delta step 1")->detail, "starter step at 2 s");
}

TEST(ElementContributions, InfoListsThemPerElement) {
    std::ostringstream out, err;
    ASSERT_EQ(runCli({"info", kModels + "burr_mill_3p2kW_idle.yaml"}, out, err), 0) << err.str();
    const std::string text = out.str();
    EXPECT_NE(text.find("  contributions (what each element registered):\n"), std::string::npos) << text;
    EXPECT_NE(text.find("    motor (InductionMotor)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("      probe motor.torque [N*m], drive torque, on motor_shaft\n"), std::string::npos) << text;
    EXPECT_NE(text.find("      regularisation speed smoothing_speed 0.01 rad/s\n"), std::string::npos) << text;
    // The motor's lines come before the belt's header, the grinding's after it.
    EXPECT_LT(text.find("probe motor.torque"), text.find("    belt (TorsionalCoupling)"));
    EXPECT_GT(text.find("probe grinding.torque"), text.find("    grinding (ResistanceTorque)"));

    std::ostringstream jout, jerr;
    ASSERT_EQ(runCli({"info", kModels + "burr_mill_3p2kW_idle.yaml", "--json"}, jout, jerr), 0) << jerr.str();
    const nlohmann::json j = nlohmann::json::parse(jout.str());
    const auto& items = j["contributions"]["grinding"]["items"];
    EXPECT_EQ(j["contributions"]["grinding"]["type"], "ResistanceTorque");
    bool found = false;
    for (const auto& c : items)
        if (c["kind"] == "probe" && c["name"] == "grinding.torque") {
            found = true;
            EXPECT_EQ(c["shaft"], "millstone");
        }
    EXPECT_TRUE(found) << items.dump();
}

// Item 4: the capabilities the generic checks read, declared by the types.
TEST(ElementCapabilities, StopSpeedIsCheckedAgainstEveryRegularisedLoad) {
    // A PeriodicLoad's smoothing speed bounds stop_speed like a
    // ResistanceTorque's (checkStopSpeed knew only the latter).
    for (const std::string type : {"ResistanceTorque", "PeriodicLoad", "AngleLoad", "BreakawayResistance"}) {
        const ElementType* t = ElementRegistry::instance().find(type);
        ASSERT_NE(t, nullptr) << type;
        EXPECT_EQ(t->schema.regularisationSpeedKey, "smoothing_speed") << type;
    }
    const std::string text = R"(format_version: 1
name: periodic load run-out
bodies:
  - {name: shaft, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: PeriodicLoad, name: crushing, bodies: [shaft], rows: 1, mean_torque: 100 N*m, amplitudes: [50 N*m],
     fundamental_frequency: 10 rad/s, smoothing_speed: 0.1 rad/s}
scenario: {analysis: transient, initial_state: file, end_time: 1 s, stop_speed: 0.2 rad/s, runout_body: shaft}
)";
    try {
        runAnalysis(readModelText(text, "p.yaml", defaultModelReader()));
        ADD_FAILURE() << "a stop_speed inside the PeriodicLoad's regularisation was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.stop_speed");
        EXPECT_NE(std::string(e.what()).find("smoothing_speed of crushing"), std::string::npos) << e.what();
    }
}

TEST(ElementCapabilities, CoastdownIdentificationNamesTheTypesWithAnAdjustableResistance) {
    std::string text = R"(format_version: 1
name: coast-down against a breakaway
bodies:
  - {name: shaft, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: InductionMotor, name: motor, body: shaft, law: kloss, rated_torque: 97.4 N*m, rated_speed: 1470 rpm,
     synchronous_speed: 1500 rpm, breakdown_ratio: 2.5}
  - {type: BreakawayResistance, name: chamber, body: shaft, static_torque: 50 N*m, running_torque: 20 N*m,
     release_speed: 1 rad/s}
scenario: {analysis: coastdown_identify, resistance: chamber, runout_time: 2 s, runout_body: shaft}
)";
    try {
        runAnalysis(readModelText(text, "c.yaml", defaultModelReader()));
        ADD_FAILURE() << "a BreakawayResistance was accepted as the adjustable resistance";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.resistance");
        EXPECT_NE(std::string(e.what()).find("types with one: ResistanceTorque"), std::string::npos) << e.what();
    }
}

TEST(ElementCapabilities, AHeldChargeOutsideKinetostaticsIsRefusedFromItsSchema) {
    const ElementType* t = ElementRegistry::instance().find("SegmentCharge");
    ASSERT_NE(t, nullptr);
    ASSERT_EQ(t->schema.analysisNeeds.size(), 2u);
    EXPECT_EQ(t->schema.analysisNeeds[0].value, "held");
    EXPECT_EQ(t->schema.analysisNeeds[0].kind, ElementSchema::AnalysisNeed::Kind::EachInstant);
    EXPECT_EQ(t->schema.analysisNeeds[1].value, "frozen");
    EXPECT_EQ(t->schema.analysisNeeds[1].kind, ElementSchema::AnalysisNeed::Kind::StepHistory);
    const std::string text = R"(format_version: 1
name: held charge linearized
gravity: [0 m/s^2, -9.81 m/s^2, 0 m/s^2]
bodies:
  - {name: drum, inertia: 100 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: InductionMotor, name: motor, body: drum, law: kloss, rated_torque: 9740 N*m, rated_speed: 14.7 rad/s,
     synchronous_speed: 15 rad/s, breakdown_ratio: 2.5}
  - {type: SegmentCharge, name: charge, drum: drum, drum_radius: 1 m, length: 1 m, bulk_density: 4800 kg/m^3,
     motion: held, lag: 45 deg}
scenario: {analysis: linearize}
)";
    try {
        runAnalysis(readModelText(text, "h.yaml", defaultModelReader()));
        ADD_FAILURE() << "a held charge was linearized";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "charge.motion");
        EXPECT_EQ(e.where().line, 10);  // where `motion: held` is written
        EXPECT_NE(std::string(e.what()).find("analysis 'linearize' cannot solve it"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace milldyn
