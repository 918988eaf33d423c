// SegmentCharge on any drum (issue 19 items 1, 2): the lag conventions, the
// torque-arm charge of a tumbling mill, the input errors of the new keys.
// Expected values come from validation/oracles/TumblingMillOracle (textbook
// closed forms), never from the model.

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "plugins/charges/SegmentCharge.h"
#include "validation/oracles/TumblingMillOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;
constexpr double kG = 9.81;

const std::string kMill = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata/charges/tumbling_mill.yaml";

std::string slurpModel() {
    std::ifstream in(kMill);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The test mill's text with `from` replaced by `to` (must occur).
std::string millText(const std::vector<std::pair<std::string, std::string>>& edits = {}) {
    std::string text = slurpModel();
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    return text;
}

ModelSpec readMill(const std::vector<std::pair<std::string, std::string>>& edits = {},
                   const std::vector<Override>& overrides = {}) {
    return readModelText(millText(edits), "tumbling_mill.yaml", defaultModelReader(), overrides);
}

double probe(const Scene& scene, const SimTK::State& s, const std::string& name) {
    for (const auto& p : scene.probes())
        if (p.name == name) return p.value(s);
    ADD_FAILURE() << "no probe " << name;
    return NAN;
}

oracles::CircularSegmentCharge oracleCharge(double fill) { return {1.5, 4.0, 4800.0, fill}; }

// The charge's derived values against the textbook segment (full central
// angle θ = 2γ, area R²(θ − sin θ)/2, centroid 4R sin³(θ/2)/(3(θ − sin θ)))
// and ω_c = sqrt(2g/D).
TEST(SegmentCharge, DerivedValuesMatchTheTextbookSegment) {
    auto scene = buildScene(readMill());
    auto derived = [&](const std::string& n) -> double {
        for (const auto& d : scene->derivedValues())
            if (d.name == n) return d.value;
        ADD_FAILURE() << "no derived value " << n;
        return NAN;
    };
    const auto c = oracleCharge(0.30);
    EXPECT_NEAR(derived("charge.mass"), oracles::segmentMass(c), 1e-12 * oracles::segmentMass(c));
    EXPECT_NEAR(derived("charge.centroid_radius"), oracles::segmentCentroidDistance(c), 1e-12);
    EXPECT_NEAR(2 * derived("charge.half_angle"), oracles::segmentCentralAngle(0.30), 1e-12);
    EXPECT_NEAR(derived("charge.fill"), 0.30, 1e-12);
    EXPECT_NEAR(derived("charge.critical_speed"), oracles::criticalSpeed(3.0, kG), 1e-14);
}

// Torque arm at speed: the load on the shell is m g r_c sin α, its power
// P = m g r_c sin α ω (the tanh smoothing is 1 to 1e-30 at 75 % of ω_c).
TEST(SegmentCharge, TorqueArmLoadIsTheWeightsMoment) {
    for (const double lag : {20.0, 40.0, 55.0}) {
        auto scene = buildScene(readMill({{"lag: 40 deg", "lag: " + std::to_string(lag) + " deg"}}));
        SimTK::State s = scene->system().realizeTopology();
        scene->system().realizeModel(s);
        const double omega = 0.75 * oracles::criticalSpeed(3.0, kG);
        scene->findBody("shell")->mobod.setOneU(s, SimTK::MobilizerUIndex(0), omega);
        scene->system().realize(s, SimTK::Stage::Acceleration);
        const double T = oracles::torqueArmTorque(oracleCharge(0.30), lag * kDeg, kG);
        EXPECT_NEAR(probe(*scene, s, "charge.torque"), T, 1e-12 * T) << lag;
        EXPECT_NEAR(probe(*scene, s, "charge.grinding_power"), T * omega, 1e-12 * T * omega) << lag;
        EXPECT_NEAR(probe(*scene, s, "charge.lag"), lag * kDeg, 1e-12) << lag;
        // Turning the other way, the load turns too (it opposes rotation).
        scene->findBody("shell")->mobod.setOneU(s, SimTK::MobilizerUIndex(0), -omega);
        scene->system().realize(s, SimTK::Stage::Acceleration);
        EXPECT_NEAR(probe(*scene, s, "charge.torque"), -T, 1e-12 * T) << lag;
        // At rest: no load (the smoothing), so a start from rest is well posed.
        scene->findBody("shell")->mobod.setOneU(s, SimTK::MobilizerUIndex(0), 0.0);
        scene->system().realize(s, SimTK::Stage::Acceleration);
        EXPECT_EQ(probe(*scene, s, "charge.torque"), 0.0);
    }
}

// The same physical lag gives the same outputs wherever the mill stands:
// a dynamic charge body released at 40° from the vertical, the mill at the
// origin, at (5 m, 0) and at (0, 5 m). Before issue 19 the lag was measured
// from the origin-to-axis line: not finite at the origin, +140° and −130°
// elsewhere.
TEST(SegmentCharge, SameLagWhereverTheMillStands) {
    std::vector<std::vector<double>> finals;
    for (const std::string at : {"[0 m, 0 m, 0 m]", "[5 m, 0 m, 0 m]", "[0 m, 5 m, 0 m]"}) {
        const ModelSpec spec = readMill({{"location: [0 m, 0 m, 0 m]", "location: " + at},
                                         {"motion: torque_arm", "motion: dynamic_lag"},
                                         {"lag: 40 deg", "initial_lag: 40 deg\n    wall_drag: 2.0e5 N*m*s/rad"},
                                         {"analysis: linearize", "analysis: transient\n  end_time: 0.5 s"}});
        auto scene = buildScene(spec);
        SimTK::State s = initialState(*scene, spec);
        scene->system().realize(s, SimTK::Stage::Acceleration);
        EXPECT_NEAR(probe(*scene, s, "charge.lag"), 40 * kDeg, 1e-13) << at;
        const AnalysisResult r = runAnalysis(spec);
        ASSERT_NE(r.find("energy_balance_relative"), nullptr);
        EXPECT_LT(std::abs(r.find("energy_balance_relative")->value), 1e-5) << at;
        const auto& last = r.rows.back();
        finals.push_back({last[r.findColumn("charge.lag")], last[r.findColumn("shell.speed")],
                          last[r.findColumn("charge.grinding_power")]});
    }
    for (std::size_t i = 1; i < finals.size(); ++i)
        for (std::size_t k = 0; k < finals[0].size(); ++k)
            EXPECT_NEAR(finals[i][k], finals[0][k], 1e-7 * (1 + std::abs(finals[0][k]))) << i << " " << k;
}

// `--set elements.charge.initial_lag=…` reaches the charge body's start.
TEST(SegmentCharge, InitialLagIsSettable) {
    const ModelSpec spec = readMill({{"motion: torque_arm", "motion: dynamic_lag"},
                                     {"lag: 40 deg", "wall_drag: 1.0e5 N*m*s/rad"}},
                                    {{"elements.charge.initial_lag", "25deg"}});
    auto scene = buildScene(spec);
    SimTK::State s = initialState(*scene, spec);
    scene->system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_NEAR(probe(*scene, s, "charge.lag"), 25 * kDeg, 1e-13);
}

void expectSpecError(const std::vector<std::pair<std::string, std::string>>& edits, const std::string& key,
                     const std::string& words) {
    try {
        buildScene(readMill(edits));
        ADD_FAILURE() << "no error for " << key;
    } catch (const SpecError& e) {
        EXPECT_NE(e.key().find(key), std::string::npos) << e.formatted();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.formatted();
        EXPECT_GT(e.where().line, 0) << e.formatted();
    }
}

TEST(SegmentCharge, KeysAModeDoesNotUseAreErrors) {
    // lag with dynamic_lag was silently ignored before issue 19.
    expectSpecError({{"motion: torque_arm", "motion: dynamic_lag\n    wall_drag: 1 N*m*s/rad"}}, "lag",
                    "not used with motion: dynamic_lag");
    expectSpecError({{"motion: torque_arm", "motion: held\n    wall_drag: 1 N*m*s/rad"}}, "wall_drag",
                    "not used with motion: held");
    expectSpecError({{"lag: 40 deg", "lag: 40 deg\n    initial_lag: 10 deg"}}, "initial_lag",
                    "not used with motion: torque_arm");
    expectSpecError({{"lag: 40 deg", "lag: 40 deg\n    lag_table_speed: [0.5, 0.8]\n    lag_table_lag: [30 deg, 40 deg]"}},
                    "lag", "not both");
    expectSpecError({{"lag: 40 deg", "lag_table_speed: [0.5, 0.8, 0.9]\n    lag_table_lag: [30 deg, 40 deg]"}}, "lag_table_lag",
                    "as many");
    expectSpecError({{"lag: 40 deg", "lag_table_speed: [0.8, 0.5]\n    lag_table_lag: [30 deg, 40 deg]"}},
                    "lag_table_speed", "increase");
    // The papers' convention needs a carrier; this shell turns on ground.
    expectSpecError({{"lag_from: vertical", "lag_from: carrier_radius"}}, "lag_from", "no carrier");
    // A torque-arm charge is a weight: no gravity, no load.
    expectSpecError({{"gravity: [0 m/s^2, -9.81 m/s^2, 0 m/s^2]", "gravity: [0 m/s^2, 0 m/s^2, 0 m/s^2]"}}, "motion",
                    "no gravity");
}

// The lag table: through its points, monotone between them (no overshoot),
// constant beyond its ends.
TEST(SegmentCharge, LagTableIsSmoothAndMonotone) {
    auto scene = buildScene(readMill(
        {{"lag: 40 deg", "lag_table_speed: [0.2, 0.5, 0.75, 0.9]\n    lag_table_lag: [20 deg, 35 deg, 40 deg, 41 deg]"}}));
    const auto* charge = scene->findElement<SegmentCharge>("charge");
    ASSERT_NE(charge, nullptr);
    const std::vector<double> x = {0.2, 0.5, 0.75, 0.9}, y = {20, 35, 40, 41};
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(charge->calcLagAtSpeedFraction(x[i]), y[i] * kDeg, 1e-14);
    EXPECT_NEAR(charge->calcLagAtSpeedFraction(0.05), 20 * kDeg, 1e-14);
    EXPECT_NEAR(charge->calcLagAtSpeedFraction(1.2), 41 * kDeg, 1e-14);
    double previous = charge->calcLagAtSpeedFraction(0.2);
    for (double phi = 0.2; phi <= 0.9; phi += 1e-3) {
        const double a = charge->calcLagAtSpeedFraction(phi);
        EXPECT_GE(a, previous - 1e-15) << phi;
        EXPECT_LE(a, 41 * kDeg + 1e-15) << phi;
        previous = a;
    }
    // C¹ at a knot: one-sided slopes agree.
    const double h = 1e-6, k = 0.5;
    const double left = (charge->calcLagAtSpeedFraction(k) - charge->calcLagAtSpeedFraction(k - h)) / h;
    const double right = (charge->calcLagAtSpeedFraction(k + h) - charge->calcLagAtSpeedFraction(k)) / h;
    EXPECT_NEAR(left, right, 1e-4 * std::abs(left));
}


oracles::KlossMotor testMotor() { return {3858.0, 1485 * kPi / 30, 1500 * kPi / 30, 2.2}; }

// The running speed of the mill driven by a Kloss motor, by hand: the
// torque-arm torque m g r_c sin α referred to the motor through i = 82,
// M_motor(ω) = M_charge/i solved in closed form on the stable branch.
TEST(TumblingMill, KlossRunningSpeedByHand) {
    for (const double lag : {30.0, 40.0}) {
        const ModelSpec spec = readMill({{"lag: 40 deg", "lag: " + std::to_string(lag) + " deg"}});
        auto scene = buildScene(spec);
        const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
        const double T = oracles::torqueArmTorque(oracleCharge(0.30), lag * kDeg, kG);
        const double expected = oracles::klossRunningSpeed(testMotor(), T / 82);
        EXPECT_NEAR(pinSpeed(steady, scene->findBody("motor_shaft")->mobod), expected, 1e-9 * expected) << lag;
        EXPECT_NEAR(pinSpeed(steady, scene->findBody("shell")->mobod), expected / 82, 1e-9 * expected / 82) << lag;
    }
}

// A start from rest with the torque-arm charge, integrated: a high-slip
// motor (rated 1350 rpm, λ = 2.5: 7.5 kN·m at standstill against the
// charge's 2.8 kN·m on the motor shaft) runs the mill up; the energy balance
// closes and the run ends at the hand-computed running speed.
TEST(TumblingMill, StartFromRestClosesTheEnergyBalance) {
    const ModelSpec spec = readMill({{"rated_speed: 1485 rpm", "rated_speed: 1350 rpm"},
                                     {"breakdown_ratio: 2.2", "breakdown_ratio: 2.5"},
                                     {"analysis: linearize", "analysis: transient\n  end_time: 6 s"}});
    const AnalysisResult r = runAnalysis(spec);
    ASSERT_NE(r.find("energy_balance_relative"), nullptr);
    EXPECT_LT(std::abs(r.find("energy_balance_relative")->value), 1e-5);
    const double T = oracles::torqueArmTorque(oracleCharge(0.30), 40 * kDeg, kG);
    const double expected = oracles::klossRunningSpeed({3858.0, 1350 * kPi / 30, 1500 * kPi / 30, 2.5}, T / 82);
    const double end = r.rows.back()[r.findColumn("motor_shaft.speed")];
    EXPECT_NEAR(end, expected, 1e-4 * expected);
    ASSERT_NE(r.find("energy_to_loads"), nullptr);
    EXPECT_GT(r.find("energy_to_loads")->value, 0);
}

// Bearing load: the torque-arm charge's weight reaches the shell's pin
// (its mass is on the shell's axis, the couple moves its line of action):
// at steady running the pin carries (m_shell + m) g straight up and no
// horizontal force, as statics of shell plus a charge at rest says.
TEST(SegmentCharge, TorqueArmWeightLoadsTheShellBearing) {
    const ModelSpec spec = readMill({{"scenario:", "  - {type: JointReaction, name: trunnion, body: shell}\nscenario:"}});
    auto scene = buildScene(spec);
    SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(steady, SimTK::Stage::Acceleration);
    const double weight = (60000 + oracles::segmentMass(oracleCharge(0.30))) * kG;
    EXPECT_NEAR(probe(*scene, steady, "trunnion.on_shell_at_axis_y_ground"), weight, 1e-9 * weight);
    EXPECT_NEAR(probe(*scene, steady, "trunnion.on_shell_at_axis_x_ground"), 0.0, 1e-9 * weight);
}

// A held charge body on a fixed axis (lag from the vertical), solved by
// kinetostatics at four shell angles: the wall torque that holds it is the
// same weight's moment m g r_c sin α the torque-arm law applies.
TEST(SegmentCharge, HeldOnAFixedAxisNeedsTheTorqueArmTorque) {
    const ModelSpec spec = readMill({{"motion: torque_arm", "motion: held"},
                                     {"analysis: linearize", "analysis: kinetostatic\n  carrier: shell\n"
                                                             "  carrier_speed: 1.9 rad/s\n  angle_points: 4"}});
    const AnalysisResult r = runAnalysis(spec);
    const double T = oracles::torqueArmTorque(oracleCharge(0.30), 40 * kDeg, kG);
    ASSERT_EQ(r.rows.size(), 4u);
    for (const auto& row : r.rows) {
        EXPECT_NEAR(row[r.findColumn("charge.wall_torque")], T, 1e-9 * T);
        EXPECT_NEAR(row[r.findColumn("charge.lag")], 40 * kDeg, 1e-12);
    }
}

// A drum on a coaxial body (a shell on a girth-gear body turning about the
// same fixed axis) is not carried: the lag is from the vertical by default,
// and the papers' convention is refused there too.
TEST(SegmentCharge, DrumOnACoaxialBodyHasAFixedAxis) {
    const std::vector<std::pair<std::string, std::string>> coaxial = {
        {"  - name: shell\n", "  - name: gear\n    inertia: 10 kg*m^2\n    joint: {type: pin, parent: ground}\n"
                              "  - name: shell\n"},
        {"joint: {type: pin, parent: ground, location: [0 m, 0 m, 0 m]}", "joint: {type: pin, parent: gear}"},
        {"    lag_from: vertical\n", ""},
        {"motion: torque_arm", "motion: dynamic_lag"},
        {"lag: 40 deg", "initial_lag: 40 deg\n    wall_drag: 1.0e5 N*m*s/rad"}};
    const ModelSpec spec = readMill(coaxial);
    auto scene = buildScene(spec);
    SimTK::State s = initialState(*scene, spec);
    scene->system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_NEAR(probe(*scene, s, "charge.lag"), 40 * kDeg, 1e-13);
    auto refused = coaxial;
    refused.push_back({"    motion: dynamic_lag", "    lag_from: carrier_radius\n    motion: dynamic_lag"});
    EXPECT_THROW(buildScene(readMill(refused)), SpecError);
}

// ---- linearize about the loaded running point (issue 19 item 5) ----

/// The test mill with a two-stage drive: motor → reducer (ratio 5) →
/// pinion → girth gear (ratio 16.4) → shell, the charge a torque arm.
std::string threeInertiaMill(const std::string& charge) {
    return millText({{"  - name: shell\n", "  - name: pinion\n    inertia: 8 kg*m^2\n    joint: {type: pin, parent: ground}\n"
                                         "  - name: shell\n"},
                     {"    name: drive\n    bodies: [motor_shaft, shell]\n    stiffness: 2.0e5 N*m/rad\n"
                      "    damping: 200 N*m*s/rad\n    ratio: 82\n",
                      "    name: reducer\n    bodies: [motor_shaft, pinion]\n    stiffness: 3.0e5 N*m/rad\n"
                      "    ratio: 5\n  - type: TorsionalCoupling\n    name: girth\n    bodies: [pinion, shell]\n"
                      "    stiffness: 4.0e6 N*m/rad\n    ratio: 16.4\n"},
                     {"    lag: 40 deg\n", charge},
                     {"analysis: linearize", "analysis: linearize\n  reference_shaft: motor_shaft"}});
}

// A 3-inertia geared chain at its loaded running point: the natural
// frequencies and the mode shapes referred to the motor shaft against the
// chain reduced by ratio² (oracle), the shell's inertia including the
// charge's J_Bz (sector less triangle).
TEST(TumblingMillLinearize, GearedChainAgainstRatioSquaredReduction) {
    const ModelSpec spec = readModelText(threeInertiaMill("    lag: 40 deg\n"), "mill3.yaml", defaultModelReader());
    const AnalysisResult r = runAnalysis(spec);
    const oracles::GearedChain chain{{30.0, 8.0, 150000.0 + oracles::segmentAxisInertia(oracleCharge(0.30))},
                                     {3.0e5, 4.0e6},
                                     {5.0, 16.4}};
    const std::vector<double> w = oracles::gearedChainFrequencies(chain);
    const auto shapes = oracles::gearedChainModeShapes(chain);
    ASSERT_EQ(r.columnNames, (std::vector<std::string>{"mode", "natural_frequency", "motor_shaft", "pinion", "shell"}));
    ASSERT_EQ(r.rows.size(), 3u);
    for (std::size_t m = 1; m < 3; ++m) {
        EXPECT_NEAR(r.rows[m][1] * 2 * kPi, w[m], 1e-8 * w[m]) << m;
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(r.rows[m][2 + k], shapes[m][k], 1e-7) << m << " " << k;
    }
    // The rigid rotation, referred: every shaft turns as the motor does.
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(r.rows[0][2 + k], 1.0, 1e-6) << k;
    // The loaded point: the motor at the slip the charge's torque gives.
    const double T = oracles::torqueArmTorque(oracleCharge(0.30), 40 * kDeg, kG);
    const double speed = oracles::klossRunningSpeed(testMotor(), T / 82);
    ASSERT_NE(r.find("operating_point.motor_shaft.speed"), nullptr);
    EXPECT_NEAR(r.find("operating_point.motor_shaft.speed")->value, speed, 1e-9 * speed);
    EXPECT_NEAR(r.find("operating_point.charge.lag")->value, 40 * kDeg, 1e-12);
}

// A lag that follows speed, linearized: the load's slope dM/dω =
// m g r_c cos α · (dα/dφ)/ω_c is a damping on the shell. A two-point table
// is a straight line (its Hermite slopes are the secant), so
// dα/dφ = Δα/Δφ; the girth coupling adds n²·b... here b = 0, so
// C(shell, shell) is the charge's alone.
TEST(TumblingMillLinearize, SpeedDependentLagIsADamping) {
    const ModelSpec spec = readModelText(
        threeInertiaMill("    lag_table_speed: [0.5, 0.9]\n    lag_table_lag: [30 deg, 50 deg]\n"), "mill3.yaml",
        defaultModelReader());
    auto scene = buildScene(spec);
    const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    const LinearModel lm = linearizeScene(*scene, steady);
    const double wc = oracles::criticalSpeed(3.0, kG);
    const double omega = pinSpeed(steady, scene->findBody("shell")->mobod);
    const double phi = omega / wc;
    const double slope = (50 - 30) * kDeg / (0.9 - 0.5);
    const double alpha = 30 * kDeg + (phi - 0.5) * slope;
    const auto c = oracleCharge(0.30);
    const double expected = oracles::segmentMass(c) * kG * oracles::segmentCentroidDistance(c) * std::cos(alpha) *
                            slope / wc;
    EXPECT_NEAR(lm.C(2, 2), expected, 1e-6 * expected);
    EXPECT_EQ(lm.dofNames[2], "shell");
    // And the running point: M(ω) = m g r_c sin α(φ)/82 on the motor.
    const double T = oracles::segmentMass(c) * kG * oracles::segmentCentroidDistance(c) * std::sin(alpha);
    EXPECT_NEAR(pinSpeed(steady, scene->findBody("motor_shaft")->mobod),
                oracles::klossRunningSpeed(testMotor(), T / 82), 1e-8 * 157);
}

// A dynamic charge body is linearized at its running lag, not hanging:
// steady, the wall drag c_w ω balances the weight's moment m g r_c sin α.
TEST(TumblingMillLinearize, DynamicChargeAtItsRunningLag) {
    const ModelSpec spec = readMill({{"motion: torque_arm", "motion: dynamic_lag"},
                                     {"lag: 40 deg", "wall_drag: 1.0e5 N*m*s/rad"},
                                     {"analysis: linearize", "analysis: linearize\n  reference_shaft: motor_shaft"}});
    const AnalysisResult r = runAnalysis(spec);
    const auto c = oracleCharge(0.30);
    const double omega = r.find("operating_point.shell.speed")->value;
    const double expected = std::asin(1.0e5 * omega / (oracles::segmentMass(c) * kG * oracles::segmentCentroidDistance(c)));
    EXPECT_GT(expected, 20 * kDeg);
    EXPECT_NEAR(r.find("operating_point.charge.lag")->value, expected, 1e-9);
    // Standing still in space: relative to the shell it turns back at ω.
    EXPECT_NEAR(r.find("operating_point.charge.speed")->value, -omega, 1e-9);
    EXPECT_EQ(r.columnNames, (std::vector<std::string>{"mode", "natural_frequency", "motor_shaft", "shell", "charge"}));
}

}  // namespace
}  // namespace milldyn
