// Issue 31 item 1: every drive fills one complete facet (Scene::Drive:
// on/off, switch-off time, speed hint, starting sequence). The dq induction
// motor had none, so a coast-down would have left it running: switched off
// it opens its stator (no torque), and coastdown_identify identifies the
// load behind it.

#include "driver/Api.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "tests/driver/DqShaftModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

ModelSpec dqModel(const std::vector<Override>& overrides = {}) {
    return readModelText(kDqShaft, "dq.yaml", defaultModelReader(), overrides);
}

TEST(DriveFacet, TheDqMotorRegistersOne) {
    const auto scene = buildScene(dqModel());
    ASSERT_EQ(scene->drives().size(), 1u);
    const Scene::Drive& d = scene->drives()[0];
    EXPECT_EQ(d.element, "motor");
    EXPECT_EQ(d.shaft, "shaft");
    EXPECT_DOUBLE_EQ(d.speedHint, 2 * M_PI * 50 / 2);  // synchronous: 2π f / p
    EXPECT_TRUE(std::isinf(d.switchOffTime));
    EXPECT_EQ(d.startingSequence, "direct_on_line");
    EXPECT_DOUBLE_EQ(scene->speedHints().at("shaft"), 2 * M_PI * 50 / 2);
    // Never switched off: no DriveOff event.
    for (const auto& e : scene->switchEvents()) EXPECT_NE(e.kind, Scene::SwitchEvent::Kind::DriveOff) << e.what;
}

TEST(DriveFacet, TheScalarMotorAndThePrescribedDriveRegisterOne) {
    // burr_mill_3p2kW_idle.yaml: a Kloss motor switched off at 4 s, rated 1437 rpm.
    const auto burr = buildScene(readModel(kModels + "burr_mill_3p2kW_idle.yaml", {}));
    ASSERT_EQ(burr->drives().size(), 1u);
    EXPECT_EQ(burr->drives()[0].shaft, "motor_shaft");
    EXPECT_DOUBLE_EQ(burr->drives()[0].speedHint, 1437 * 2 * M_PI / 60);
    EXPECT_DOUBLE_EQ(burr->drives()[0].switchOffTime, 4.0);
    EXPECT_EQ(burr->drives()[0].startingSequence, "direct_on_line");
    int driveOff = 0;
    for (const auto& e : burr->switchEvents())
        if (e.kind == Scene::SwitchEvent::Kind::DriveOff) {
            ++driveOff;
            EXPECT_DOUBLE_EQ(e.time, 4.0);
            EXPECT_EQ(e.what, "motor switched off");
        }
    EXPECT_EQ(driveOff, 1);
    // planetary_gear_100x200.yaml: a CarrierDrive prescribing the carrier.
    const auto planetary = buildScene(readModel(kModels + "planetary_gear_100x200.yaml", {}));
    ASSERT_EQ(planetary->drives().size(), 1u);
    EXPECT_NE(planetary->drives()[0].startingSequence.find("prescribed"), std::string::npos);
    EXPECT_TRUE(std::isinf(planetary->drives()[0].switchOffTime));
    // It cannot be switched off: saying so, not leaving it running.
    SimTK::State s = planetary->system().getDefaultState();
    EXPECT_THROW(planetary->setDrivesOn(s, false), std::invalid_argument);
}

TEST(DriveFacet, AnIncompleteDriveIsRefusedWhenTheSceneIsBuilt) {
    auto scene = buildScene(dqModel());
    auto on = [](SimTK::State&, bool) {};
    EXPECT_THROW(scene->addDrive({"m", "shaft", NAN, INFINITY, on, "direct"}), std::invalid_argument);
    EXPECT_THROW(scene->addDrive({"m", "shaft", 1.0, NAN, on, "direct"}), std::invalid_argument);
    EXPECT_THROW(scene->addDrive({"m", "shaft", 1.0, INFINITY, nullptr, "direct"}), std::invalid_argument);
    EXPECT_THROW(scene->addDrive({"m", "", 1.0, INFINITY, on, "direct"}), std::invalid_argument);
    EXPECT_THROW(scene->addDrive({"m", "shaft", 1.0, INFINITY, on, ""}), std::invalid_argument);
    EXPECT_THROW(scene->addDrive({"", "shaft", 1.0, INFINITY, on, "direct"}), std::invalid_argument);
}

TEST(DriveFacet, DqMotorSwitchedOffOpensItsStatorAndTheLoadAloneDecelerates) {
    const AnalysisResult r = runAnalysis(dqModel({{"elements.motor.switch_off_time", "0.5 s"}}));
    const double J = 2, Mc = 100;
    double w1 = NAN, t1 = NAN;
    std::size_t after = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const double t = r.rows[i][0];
        // Before: the motor carries the load (steady running).
        if (t < 0.5) {
            EXPECT_NEAR(r.value(i, "motor.torque"), Mc, 1e-3 * Mc) << "t = " << t;
        }
        if (t <= 0.5) continue;
        ++after;
        // No stator current, no torque.
        EXPECT_EQ(r.value(i, "motor.torque"), 0.0) << "t = " << t;
        EXPECT_EQ(r.value(i, "motor.current"), 0.0) << "t = " << t;
        if (std::isnan(w1)) {
            w1 = r.value(i, "shaft.speed");
            t1 = t;
        } else if (r.value(i, "shaft.speed") > 1) {
            // J dω/dt = −Mc while the shaft turns far above the load's smoothing speed.
            EXPECT_NEAR(r.value(i, "shaft.speed"), w1 - Mc / J * (t - t1), 1e-6 * w1) << "t = " << t;
        }
    }
    EXPECT_GT(after, 900u);
}

TEST(DriveFacet, CoastdownIdentifiesTheLoadBehindADqMotor) {
    // A rigid shaft stopped by a constant Mc alone runs out in t_v = J·ω_y/Mc:
    // the identified Mc and the steady speed it gives must satisfy that
    // for the run-out time asked (a motor left running never stops).
    std::string text = kDqShaft;
    const std::string transient = "scenario: {analysis: transient, initial_state: steady, end_time: 1.5 s}";
    text.replace(text.find(transient), transient.size(),
                 "scenario: {analysis: coastdown_identify, resistance: load, runout_time: 2 s, runout_body: shaft}");
    const AnalysisResult r = runAnalysis(readModelText(text, "dq.yaml", defaultModelReader()));
    const ResultScalar* Mc = r.find("resistance_torque");
    const ResultScalar* wy = r.find("steady_speed");
    ASSERT_NE(Mc, nullptr);
    ASSERT_NE(wy, nullptr);
    const double J = 2, tv = 2;
    EXPECT_NEAR(Mc->value, J * wy->value / tv, 1e-4 * Mc->value) << Mc->value << " N*m, " << wy->value << " rad/s";
    EXPECT_GT(wy->value, 0.9 * 2 * M_PI * 25);  // near synchronous: the motor ran before it was switched off
}

TEST(DriveFacet, CoastdownRefusesADriveThatCannotBeSwitchedOff) {
    std::string text = kDqShaft;
    const std::string motor = text.substr(text.find("  - {type: DqInductionMotor"),
                                          text.find("  - {type: ResistanceTorque") - text.find("  - {type: DqInductionMotor"));
    text.replace(text.find(motor), motor.size(),
                 "  - {type: CarrierDrive, name: drive, body: shaft, law: steady, steady_speed: 10 rad/s}\n");
    const std::string transient = "scenario: {analysis: transient, initial_state: steady, end_time: 1.5 s}";
    text.replace(text.find(transient), transient.size(),
                 "scenario: {analysis: coastdown_identify, resistance: load, runout_time: 2 s, runout_body: shaft}");
    try {
        runAnalysis(readModelText(text, "carrier.yaml", defaultModelReader()));
        ADD_FAILURE() << "a coast-down behind a prescribed drive was run";
    } catch (const SpecError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot be switched off"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace milldyn
