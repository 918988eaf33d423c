// Issue 26 items 1, 2 and 6, issue 28 item 6: the verdicts, start_time
// and peaks of a transient come from the integrated trajectory (every step,
// maxima and crossings located inside the steps), hold for shafts turning
// either way, and do not depend on outputs.sample_interval; a steady start
// is steady at t = 0. Expected values come from statics and the models'
// own parameters (derived in the comments), or from the same run sampled
// finely (the sampling must not matter), never from today's output.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "driver/Cli.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/SteadyStart.h"

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

/// A pinion (motor shaft) driving a wheel through one external gear stage
/// (r = 0.2 m / 0.8 m: the wheel turns at −1/4 of the motor, ratio −4),
/// the load on the wheel. Linear motor: 1000 N*m at 1450 rpm, 0 at
/// 1500 rpm, so 30 kN*m at standstill = 120 kN*m on the wheel.
const char* kReversingTrain = R"(format_version: 1
name: negative-ratio train (one external gear stage)
bodies:
  - {name: pinion, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}
  - {name: wheel, inertia: 50 kg*m^2, joint: {type: pin, parent: ground, location: [1.0 m, 0 m, 0 m]}}
elements:
  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 1000 N*m,
     rated_speed: 1450 rpm, synchronous_speed: 1500 rpm}
  - {type: GearPair, name: mesh, bodies: [pinion, wheel], pitch_radii: [0.2 m, 0.8 m]}
  - {type: ResistanceTorque, name: load, body: wheel, constant_torque: 3000 N*m, smoothing_speed: 0.01 rad/s}
scenario: {analysis: transient, initial_state: rest, end_time: 1 s, speed_body: wheel}
outputs: {sample_interval: 5 ms, plots: false}
)";

std::string writeModel(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

AnalysisResult runTrain(const std::vector<Override>& overrides) {
    return runModelFile(writeModel("reversing_train.yaml", kReversingTrain), overrides);
}

double resultOf(const AnalysisResult& r, const std::string& name) {
    const ResultScalar* v = r.find(name);
    if (!v) ADD_FAILURE() << "no result " << name;
    return v ? v->value : NAN;
}

// The wheel's running speed is −(1500 rpm less the slip at its load)/4:
// load 3000/4 = 750 N*m on the pinion, slip 50·750/1000 = 37.5 rpm, so
// −(1462.5 rpm)/4 = −38.29 rad/s.
TEST(ReversingTrain, AStartCompletesAtTheSignedRunningSpeedWithItsStartTime) {
    const AnalysisResult r = runTrain({});
    EXPECT_EQ(r.verdict, "completed") << r.verdictText;
    const double running = -1462.5 * M_PI / 30 / 4;
    EXPECT_NEAR(resultOf(r, "steady_speed"), running, 1e-3 * std::abs(running));
    ASSERT_NE(r.find("start_time"), nullptr) << "a negative running speed still has a start time";
    EXPECT_GT(resultOf(r, "start_time"), 0);
    EXPECT_LT(resultOf(r, "start_time"), 0.5);
}

// 200 kN*m on the wheel is 50 kN*m on the pinion, above the motor's 30 kN*m
// at standstill: the wheel never turns (it creeps in the load's
// regularisation band). Held near zero is a stall, not a "completed" start.
TEST(ReversingTrain, ALoadAboveTheStandstillTorqueIsAStallNotACompletedStart) {
    const AnalysisResult r = runTrain({{"elements.load.constant_torque", "200000 N*m"}});
    EXPECT_EQ(r.verdict, "stalled") << r.verdictText;
    EXPECT_EQ(r.find("start_time"), nullptr);
    // ω_ref is the motor's rated 1450 rpm referred through −1/4: −37.96 rad/s.
    EXPECT_NE(r.verdictText.find("running speed -37.96 rad/s"), std::string::npos) << r.verdictText;
}

TEST(ReversingTrain, ARunEndedMidAccelerationIsUnfinished) {
    const AnalysisResult r = runTrain({{"scenario.end_time", "0.02 s"}});
    EXPECT_EQ(r.verdict, "unfinished") << r.verdictText;
    EXPECT_EQ(r.find("start_time"), nullptr);
}

TEST(ReversingTrain, SteadyRunningIsHeld) {
    const AnalysisResult r = runTrain({{"scenario.initial_state", "steady"}});
    EXPECT_EQ(r.verdict, "steady_held") << r.verdictText;
    EXPECT_NEAR(resultOf(r, "steady_speed"), -1462.5 * M_PI / 30 / 4, 1e-3 * 38.29);
}

// Switched off at 0.2 s from steady running the wheel (turning at
// −38.29 rad/s) runs out against 3000 N*m on 50 + 2·4² = 82 kg*m^2 referred
// to it: −36.6 rad/s², so it stops 38.29/36.59 = 1.047 s after switch-off.
TEST(ReversingTrain, ARunOutOfAShaftTurningBackwardsEndsAtItsStop) {
    const AnalysisResult r = runTrain({{"scenario.initial_state", "steady"},
                                       {"elements.motor.switch_off_time", "0.2 s"},
                                       {"scenario.runout_body", "wheel"},
                                       {"scenario.end_time", "3 s"}});
    EXPECT_EQ(r.verdict, "ran") << r.verdictText;
    const double omega = 1462.5 * M_PI / 30 / 4, decel = 3000.0 / (50 + 2 * 16);
    EXPECT_NEAR(resultOf(r, "runout_time"), omega / decel, 2e-3 * omega / decel);
}

// The run-out's stop is located on the integrated trajectory, not
// extrapolated from the step end before it. A drum (J = 1 kg*m^2) at
// 100 rad/s, its drive switched off at t = 0, against M0 + b·ω (M0 = 1 N*m,
// b = 1 N*m*s/rad): ω' = −(M0 + b·ω)/J, so it reaches the stop speed
// ω_s = 0.1 rad/s at t_s = (J/b)·ln((ω0 + M0/b)/(ω_s + M0/b)), and
// runout_time is t_s + ω_s/((M0 + b·ω_s)/J) (docs/model-format.md, stop_speed:
// extrapolated to zero with the deceleration there). Extrapolating from the
// last step end above ω_s instead was off by ~1e-3 of the time here (a
// linear extrapolation across a curved ω(t)).
TEST(RunOut, StopIsLocatedOnTheTrajectoryOfACurvedDeceleration) {
    const char* model = R"(format_version: 1
name: exponential run-out
bodies:
  - {name: drum, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}, initial_speed: 100 rad/s}
elements:
  - {type: InductionMotor, name: motor, body: drum, law: linear, rated_torque: 1 N*m, rated_speed: 900 rpm,
     synchronous_speed: 1000 rpm, switch_off_time: 0 s}
  - {type: ResistanceTorque, name: load, body: drum, constant_torque: 1 N*m, viscous_coefficient: 1 N*m*s/rad}
scenario: {analysis: transient, initial_state: file, end_time: 10 s, speed_body: drum, runout_body: drum}
integrator: {name: RungeKuttaMerson, accuracy: 1e-6}
outputs: {sample_interval: 1 s, plots: false}
)";
    const double J = 1, M0 = 1, b = 1, w0 = 100, ws = 0.1;
    const double expected = (J / b) * std::log((w0 + M0 / b) / (ws + M0 / b)) + ws / ((M0 + b * ws) / J);
    for (const char* interval : {"1 s", "0.01 s"}) {
        const AnalysisResult r =
            runModelFile(writeModel("exponential_runout.yaml", model), {{"outputs.sample_interval", interval}});
        EXPECT_NEAR(resultOf(r, "runout_time"), expected, 1e-5 * expected) << interval;
    }
}

TEST(ReversingTrain, ASweepRecordsTheStallAsStalled) {
    const std::string dir = ::testing::TempDir() + "/reversing_sweep";
    std::filesystem::remove_all(dir);
    std::ostringstream out, err;
    runCli({"sweep", writeModel("reversing_train_sweep.yaml", kReversingTrain), "--grid",
            "elements.load.constant_torque=3000 N*m:200000 N*m:2", "--jobs", "1", "--out", dir},
           out, err);
    std::ifstream table(dir + "/sweep.csv");
    std::string header, row0, row1;
    std::getline(table, header);
    std::getline(table, row0);
    std::getline(table, row1);
    EXPECT_NE(row0.find(",ok,"), std::string::npos) << row0;
    EXPECT_NE(row1.find(",stalled,"), std::string::npos) << row1;
}

// The same start sampled at three intervals gives one verdict, one
// start_time and the same peaks, to the integrator's accuracy.
struct Sampled {
    std::string verdict;
    std::vector<std::pair<std::string, double>> values;
};

Sampled runSampled(const std::string& model, std::vector<Override> overrides, const std::string& interval) {
    overrides.push_back({"outputs.sample_interval", interval});
    overrides.push_back({"outputs.plots", "false"});
    const AnalysisResult r = runModelFile(model, overrides);
    Sampled s{r.verdict, {}};
    for (const auto& v : r.results)
        if (v.name == "start_time" || v.name == "peak_drive_torque" || v.name.rfind("peak.", 0) == 0 ||
            v.name == "runout_time")
            s.values.emplace_back(v.name, v.value);
    return s;
}

void expectSameAtThreeIntervals(const std::string& model, const std::vector<Override>& overrides,
                                const std::vector<std::string>& intervals, double tolerance) {
    const Sampled fine = runSampled(model, overrides, intervals.front());
    for (std::size_t k = 1; k < intervals.size(); ++k) {
        SCOPED_TRACE(model + " at " + intervals[k]);
        const Sampled coarse = runSampled(model, overrides, intervals[k]);
        EXPECT_EQ(coarse.verdict, fine.verdict);
        ASSERT_EQ(coarse.values.size(), fine.values.size());
        for (std::size_t i = 0; i < fine.values.size(); ++i) {
            const double a = fine.values[i].second, b = coarse.values[i].second;
            // Times to the integration's accuracy in time (1e-4 s), loads relative.
            const double scale = fine.values[i].first == "start_time" || fine.values[i].first == "runout_time"
                                     ? 1.0
                                     : std::max(std::abs(a), 1e-9);
            EXPECT_NEAR(b, a, tolerance * scale) << fine.values[i].first;
        }
    }
}

// Issue 26 item 2's numbers, each wrong on main: the DOL bench cut at
// 2.5 s was "completed" at 0.5 s sampling (the hold window held one
// sample) and "unfinished" at 5 ms; at 1 s sampling peak_drive_torque was
// 95.19 against 243.5 N*m (Kloss's breakdown torque 2.5·97.4 = 243.5 N*m,
// passed on the way up); the burr mill's peak belt torque 63.51 against
// 71.90 N*m at 0.1 s.
TEST(SamplingIndependence, TheDolBenchCutAtTwoAndAHalfSecondsHasOneVerdict) {
    const std::string model = kModels + "start_bench_dol.yaml";
    const Sampled fine = runSampled(model, {{"scenario.end_time", "2.5 s"}}, "5 ms");
    const Sampled coarse = runSampled(model, {{"scenario.end_time", "2.5 s"}}, "0.5 s");
    EXPECT_EQ(fine.verdict, "unfinished");
    EXPECT_EQ(coarse.verdict, fine.verdict);
}

TEST(SamplingIndependence, ThePeakDriveTorqueIsTheBreakdownTorqueAtOneSecondSampling) {
    const AnalysisResult r = runModelFile(kModels + "start_bench_dol.yaml",
                                          {{"outputs.sample_interval", "1 s"}, {"outputs.plots", "false"}});
    EXPECT_NEAR(resultOf(r, "peak_drive_torque"), 2.5 * 97.4, 1e-4 * 243.5);
}

TEST(SamplingIndependence, TheBurrMillsPeakBeltTorqueDoesNotDependOnTheSampling) {
    expectSameAtThreeIntervals(kModels + "burr_mill_5p5kW_loaded_start.yaml", {}, {"2 ms", "0.1 s", "0.5 s"}, 1e-3);
}

// The demo (burr mill idle, CPodes, switched off at 4 s) is a completed
// start whatever the integrator. CPodes steps past the switch-off and
// interpolates back; before that interpolated stop was a trajectory point,
// the speed trace joined the last step end before 4 s to the state after
// the switching (the motor off, decelerating) and its cubic overshot by
// 182 rad/s inside the hold window: "start unfinished" on the demo.
TEST(SamplingIndependence, TheDemoStartIsCompletedOnEveryIntegrator) {
    for (const char* integrator : {"CPodes", "RungeKuttaMerson"}) {
        const AnalysisResult r = runModelFile(kModels + "burr_mill_5p5kW_idle.yaml",
                                              {{"integrator.name", integrator}, {"outputs.plots", "false"}});
        EXPECT_EQ(r.verdict, "completed") << integrator << ": " << r.verdictText;
    }
}

// start_time is the crossing instant, not the first sample past it: the
// same at 1 ms and at 0.25 s sampling to well under either interval.
TEST(SamplingIndependence, StartTimeIsInterpolatedToTheCrossing) {
    const std::string model = kModels + "start_bench_dol.yaml";
    const Sampled fine = runSampled(model, {}, "1 ms");
    const Sampled coarse = runSampled(model, {}, "0.25 s");
    ASSERT_EQ(fine.verdict, "completed");
    double a = NAN, b = NAN;
    for (const auto& v : fine.values)
        if (v.first == "start_time") a = v.second;
    for (const auto& v : coarse.values)
        if (v.first == "start_time") b = v.second;
    EXPECT_NEAR(a, b, 1e-4);
}

// Issue 26 item 6 saw the vertical roller mill's output-flange torque move
// with the sampling (±10 kN*m of ripple at 5 ms, 0.9 N*m at 0.5 ms; from a
// steady state that was not steady, since fixed). On this code the
// integrated trajectory does not depend on the rows: Simbody interpolates a
// report time inside a step and does not end a step there (interpolation
// allowed, the only hard stops are switchings), and scenes without
// constraints are sampled by the Simulation's own Hermite interpolation
// between step ends. Guarded here on both paths: the planetary motor start
// (planets rolling on the ring: GearMesh constraints, so Simbody's report
// times) on a Runge-Kutta integrator, the vertical roller mill from rest (a
// violent start; compliant meshes, own sampling) on RungeKuttaMerson and
// CPodes, and the burr mill's loaded start. Every column at every common
// time, 5 ms against 0.5 ms. (With Simbody's interpolation switched off, so
// that each row ends a step, the planetary case fails here.) Not here: CPodes
// on a scene with constraints, whose first step after each (re)start is
// sized from the report time (docs/reliability.md: still open).
TEST(SamplingIndependence, TheIntegratedTrajectoryDoesNotMoveWithTheRows) {
    struct Case {
        std::string model;
        std::vector<Override> overrides;
    };
    const std::vector<Case> cases = {
        {"vertical_roller_mill_4p2MW.yaml",
         {{"scenario.initial_state", "rest"}, {"scenario.end_time", "0.2 s"}, {"integrator.name", "RungeKuttaMerson"}}},
        {"vertical_roller_mill_4p2MW.yaml",
         {{"scenario.initial_state", "rest"}, {"scenario.end_time", "0.2 s"}, {"integrator.name", "CPodes"}}},
        {"burr_mill_5p5kW_loaded_start.yaml", {{"scenario.end_time", "0.5 s"}}},
        {"planetary_gear_500x1000_motor_start.yaml",
         {{"scenario.end_time", "0.5 s"}, {"integrator.name", "RungeKuttaMerson"}}},
    };
    for (const Case& c : cases) {
        auto run = [&](const std::string& interval) {
            std::vector<Override> o = c.overrides;
            o.push_back({"outputs.sample_interval", interval});
            o.push_back({"outputs.plots", "false"});
            return runModelFile(kModels + c.model, o);
        };
        const AnalysisResult coarse = run("5 ms"), fine = run("0.5 ms");
        SCOPED_TRACE(c.model + " " + c.overrides.back().value);
        ASSERT_EQ(coarse.columnNames, fine.columnNames);
        ASSERT_GE(coarse.rows.size(), 40u);
        EXPECT_EQ(coarse.statistics.steps, fine.statistics.steps);
        // The fine rows by time (ns): every coarse row's time is on both grids.
        std::map<long long, const std::vector<double>*> fineAt;
        for (const auto& row : fine.rows) fineAt[std::llround(row[0] * 1e9)] = &row;
        for (std::size_t j = 1; j < coarse.columnNames.size(); ++j) {
            double scale = 0, worst = 0;
            for (const auto& row : fine.rows) scale = std::max(scale, std::abs(row[j]));
            std::size_t compared = 0;
            for (const auto& a : coarse.rows) {
                const auto b = fineAt.find(std::llround(a[0] * 1e9));
                if (b == fineAt.end()) continue;
                worst = std::max(worst, std::abs(a[j] - (*b->second)[j]));
                ++compared;
            }
            EXPECT_EQ(compared, coarse.rows.size()) << coarse.columnNames[j];
            EXPECT_LE(worst, 1e-9 * scale + 1e-12) << coarse.columnNames[j];
        }
    }
}

// Each shipped start (and the other transient starts), shortened where the
// verdict allows, at three sample intervals. MILLDYN_SLOW=1 runs every
// model at its full length (ctest label slow).
TEST(SamplingIndependence, EveryShippedStartGivesOneVerdictAndPeaksAtThreeIntervals) {
    const bool slow = std::getenv("MILLDYN_SLOW") != nullptr;
    struct Case {
        std::string model;
        std::vector<Override> overrides;
    };
    std::vector<Case> cases = {
        {"start_bench_dol.yaml", {}},
        {"start_bench_star_delta.yaml", {}},
        {"start_bench_soft_start.yaml", {}},
        {"start_bench_catalogue.yaml", {}},
        {"start_bench_clutch.yaml", {}},
        {"start_bench_converter.yaml", {}},
        {"start_bench_dq.yaml", {}},
        {"start_bench_table.yaml", {}},
        {"burr_mill_5p5kW_loaded_start.yaml", {}},
    };
    if (slow)
        for (const char* m : {"start_bench_backstop.yaml", "start_bench_brake.yaml", "start_bench_converter_current.yaml",
                              "start_bench_dq_soft_start.yaml", "start_bench_dq_star_delta.yaml",
                              "start_bench_efficiency.yaml", "start_bench_kloss_modified.yaml",
                              "start_bench_live_charge_rollback.yaml", "start_bench_live_charge_trip.yaml",
                              "start_bench_rollback.yaml", "start_drum_converter.yaml", "start_drum_slip_ring.yaml",
                              "tumbling_ball_mill_3x4m_start_converter.yaml", "tumbling_ball_mill_3x4m_start_dol.yaml",
                              "tumbling_ball_mill_3x4m_start_slip_ring.yaml", "planetary_gear_500x1000_motor_start.yaml"})
            cases.push_back({m, {}});
    for (const auto& c : cases) expectSameAtThreeIntervals(kModels + c.model, c.overrides, {"1 ms", "0.1 s", "1 s"}, 2e-3);
}

// A replayed start (every mobility prescribed: nothing integrated) sums
// its energy integrals over placements of its own, not over the samples:
// at 0.5 s sampling the balance closes (it missed by 0.18 on main) and the
// integrals are those of 10 ms sampling.
TEST(SamplingIndependence, AReplayedStartsEnergyIntegralsDoNotDependOnTheSampling) {
    const std::string model = kModels + "planetary_gear_500x1000.yaml";
    auto run = [&](const std::string& interval) {
        return runModelFile(model, {{"use_scenario", "start"},
                                    {"outputs.sample_interval", interval},
                                    {"outputs.plots", "false"}});
    };
    const AnalysisResult fine = run("10 ms"), coarse = run("0.5 s");
    EXPECT_EQ(coarse.statistics.integrator, "replay");
    EXPECT_LT(std::abs(resultOf(coarse, "energy_balance_relative")), 1e-4);
    EXPECT_NEAR(resultOf(coarse, "energy_from_sources"), resultOf(fine, "energy_from_sources"),
                1e-5 * std::abs(resultOf(fine, "energy_from_sources")));
}

// Issue 26 item 6: a planet on a carrier that a motor drives through a
// ratio-10 coupling: at steady running the coupling carries the load's
// 5000 N*m / 10 = 500 N*m (statics), from t = 0 on.
const char* kPlanetOnCarrier = R"(format_version: 1
name: "repro: steady initial state with a planet on the carrier"
bodies:
  - name: sun
    inertia: 10 kg*m^2
    joint: {type: pin, parent: ground}
  - name: carrier
    inertia: 1000 kg*m^2
    joint: {type: pin, parent: ground}
  - name: planet
    inertia: 100 kg*m^2
    mass: 500 kg
    joint: {type: pin, parent: carrier, location: [1 m, 0 m, 0 m]}
elements:
  - {type: InductionMotor, name: motor, body: sun, rated_torque: 1000 N*m, rated_speed: 990 rpm, synchronous_speed: 1000 rpm}
  - {type: TorsionalCoupling, name: stage, bodies: [sun, carrier], ratio: 10, stiffness: 1e6 N*m/rad, damping: 100 N*m*s/rad}
  - {type: GearMesh, name: ring, carrier: carrier, planet: planet, fixed_pitch_radius: 2 m, planet_pitch_radius: 1 m, rolling: internal}
  - {type: ResistanceTorque, name: load, body: carrier, constant_torque: 5000 N*m}
scenario: {analysis: transient, initial_state: steady, end_time: 0.01 s}
outputs: {sample_interval: 1 ms, plots: false}
)";

TEST(SteadyStart, APlanetOnTheCarrierStartsAtTheStaticCouplingTorque) {
    const AnalysisResult r = runModelFile(writeModel("planet_on_carrier.yaml", kPlanetOnCarrier), {});
    EXPECT_EQ(r.verdict, "steady_held") << r.verdictText;
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        EXPECT_NEAR(r.value(i, "stage.torque"), 500, 1e-3) << "t = " << r.value(i, "time");
}

/// The planet model's solved steady state with the sun turned 1e-4 rad
/// ahead: the coupling's torque moves off its static 500 N*m by the
/// stiffness (1e6 N*m/rad) times that twist, so sun and carrier accelerate
/// (the sun at the order of 1e6·1e-4 N*m / 10 kg*m^2 = 10 rad/s^2, far
/// above 1e-6 of the running speed per second): what a steady solver that
/// left the coupling off its static twist would hand over.
struct PerturbedSteady {
    ModelSpec spec;
    std::unique_ptr<Scene> scene;
    SimTK::State solved, perturbed;
};
PerturbedSteady perturbedSteady(const std::vector<Override>& overrides) {
    PerturbedSteady p;
    p.spec = readModelFile(writeModel("planet_on_carrier.yaml", kPlanetOnCarrier), defaultModelReader(), overrides);
    p.scene = buildScene(p.spec);
    p.solved = solveSteadyState(*p.scene, initialState(*p.scene, p.spec));
    p.perturbed = p.solved;
    const SimTK::MobilizedBody sun = p.scene->findBody("sun")->mobod;
    sun.setOneQ(p.perturbed, SimTK::MobilizerQIndex(0), sun.getOneQ(p.solved, SimTK::MobilizerQIndex(0)) + 1e-4);
    p.scene->system().realize(p.perturbed, SimTK::Stage::Acceleration);
    return p;
}

// The check itself: the solved state passes, a state that is not steady
// is refused naming the body that accelerates and the elements on it.
TEST(SteadyStart, AStartThatIsNotSteadyIsRefusedNamingTheBodyAndItsElements) {
    const PerturbedSteady p = perturbedSteady({});
    EXPECT_NO_THROW(checkSteadyStart(*p.scene, p.spec, p.solved, p.solved));
    try {
        checkSteadyStart(*p.scene, p.spec, p.perturbed, p.perturbed);
        ADD_FAILURE() << "a twisted coupling passed as steady";
    } catch (const AnalysisError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("initial_state steady is not steady at t = 0 s: sun"), std::string::npos) << what;
        EXPECT_NE(what.find("element motor, stage on sun"), std::string::npos) << what;
        EXPECT_EQ(what.find("switching"), std::string::npos) << what;
    }
}

// A switching at t = 0 (the motor switched off: a coast-down from steady
// running) skipped the check on main, so whatever the solver handed over
// was integrated as steady running. Now the running the switching disturbs
// is checked: refused, naming the switching.
TEST(SteadyStart, ASwitchingAtTZeroNoLongerHidesAStartThatIsNotSteady) {
    const PerturbedSteady p = perturbedSteady({{"elements.motor.switch_off_time", "0 s"}});
    ASSERT_EQ(p.scene->switchEvents().size(), 1u);
    SimTK::State first = p.perturbed;  // the integration's start: the switching applied
    p.scene->switchEvents().front().apply(first);
    try {
        checkSteadyStart(*p.scene, p.spec, p.perturbed, first);
        ADD_FAILURE() << "not steady, but passed because of the switching at t = 0";
    } catch (const AnalysisError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not steady at t = 0 s: sun"), std::string::npos) << what;
        EXPECT_NE(what.find("before the switching at t = 0 (motor switched off)"), std::string::npos) << what;
        EXPECT_NE(what.find("element motor, stage on sun"), std::string::npos) << what;
    }
    // The solved state with the same switching passes: the coast-down the
    // switching starts is no fault of the steady running.
    SimTK::State coast = p.solved;
    p.scene->switchEvents().front().apply(coast);
    EXPECT_NO_THROW(checkSteadyStart(*p.scene, p.spec, p.solved, coast));
}

// The whole run with the switching at t = 0: the coast-down starts from
// the checked steady running, the coupling at its static 5000/10 = 500 N*m
// and the motor already off (0 N*m) in the first row.
TEST(SteadyStart, ACoastDownFromTZeroStartsFromTheStaticSteadyRunning) {
    const AnalysisResult r = runModelFile(writeModel("planet_on_carrier.yaml", kPlanetOnCarrier),
                                          {{"elements.motor.switch_off_time", "0 s"}});
    ASSERT_FALSE(r.rows.empty());
    EXPECT_NEAR(r.value(0, "time"), 0, 1e-15);
    EXPECT_NEAR(r.value(0, "stage.torque"), 500, 1e-3);
    EXPECT_NEAR(r.value(0, "motor.torque"), 0, 1e-9);
}

}  // namespace
}  // namespace milldyn
