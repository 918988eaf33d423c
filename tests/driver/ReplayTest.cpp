// A transient of a scene without free degrees of freedom is replayed, not
// integrated (Simulation::initialize, docs/speed-accuracy.md §3): the
// planetary gear start with rigid charges is such a scene (carrier
// prescribed, drums geared). These tests check the replay against an
// independent path (Simbody's integrators at a tight accuracy), the drive's
// closed-form motion against quadrature of its acceleration, the energy
// quadrature's order, and that scenes with free motion are still integrated.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "plugins/motors/CarrierDrive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";
const std::string kGear = kModels + "planetary_gear_100x200.yaml";

AnalysisResult runGearStart(const std::string& endTime, std::vector<Override> extra = {}) {
    std::vector<Override> sets = {
        {"use_scenario", "start"}, {"scenarios.start.end_time", endTime}, {"outputs.plots", "false"}};
    sets.insert(sets.end(), extra.begin(), extra.end());
    return runAnalysis(readModelFile(kGear, defaultModelReader(), sets));
}

bool hasNote(const AnalysisResult& r, const std::string& text) {
    for (const auto& n : r.notes)
        if (n.find(text) != std::string::npos) return true;
    return false;
}

/// Largest |a − b| over the shared samples of one column, over max |b|.
double relativeDifference(const AnalysisResult& a, const AnalysisResult& b, const std::string& column) {
    const std::size_t ca = a.findColumn(column), cb = b.findColumn(column);
    EXPECT_NE(ca, std::string::npos) << column;
    EXPECT_EQ(a.rows.size(), b.rows.size());
    double diff = 0, scale = 0;
    for (std::size_t i = 0; i < std::min(a.rows.size(), b.rows.size()); ++i) {
        EXPECT_NEAR(a.rows[i][0], b.rows[i][0], 1e-12);  // same sample times
        diff = std::max(diff, std::abs(a.rows[i][ca] - b.rows[i][cb]));
        scale = std::max(scale, std::abs(b.rows[i][cb]));
    }
    return diff / scale;
}

TEST(ReplayTest, CarrierDriveMotionIsTheIntegralOfItsAcceleration) {
    // Seed 000's start law (the gear model's values); the closed form of
    // calcAdvance against composite Simpson quadrature of ε(t) (error
    // ~(h/τ)^4/180 ~ 1e-11 relative with these panels).
    CarrierDriveParams p;
    p.exponential = true;
    p.steadySpeed = 78.54;
    p.accelerationTime = 4.6;
    p.timeConstant = 1;
    const CarrierDrive drive(p);
    // u(t) by Simpson on ε from t0, φ by Simpson on u.
    auto simpson = [](const std::function<double(double)>& f, double a, double b, int panels) {
        const double h = (b - a) / panels;
        double sum = f(a) + f(b);
        for (int i = 1; i < panels; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
        return sum * h / 3;
    };
    for (double t0 : {0.0, 0.7}) {
        const double u0 = t0 == 0 ? 0.0 : 3.0, t1 = t0 + 2.5;
        auto acceleration = [&](double t) { return drive.calcAcceleration(t); };
        auto speed = [&](double t) { return u0 + simpson(acceleration, t0, t, 200); };
        const double angle = simpson(speed, t0, t1, 400);
        const auto advance = drive.calcAdvance(t0, u0, t1);
        EXPECT_NEAR(advance.second, speed(t1), 1e-9 * std::abs(speed(t1)));
        EXPECT_NEAR(advance.first, angle, 1e-9 * std::abs(angle));
    }
    // The steady law holds the start speed.
    p.exponential = false;
    const CarrierDrive steady(p);
    const auto a = steady.calcAdvance(1.0, 5.0, 3.0);
    EXPECT_DOUBLE_EQ(a.second, 5.0);
    EXPECT_DOUBLE_EQ(a.first, 10.0);
}

TEST(ReplayTest, GearStartIsReplayedAndAgreesWithTightIntegration) {
    const AnalysisResult replay = runGearStart("0.5 s");
    EXPECT_EQ(replay.statistics.integrator, "replay");
    EXPECT_TRUE(hasNote(replay, "no free degrees of freedom"));
    // The same scene integrated by Simbody (RungeKuttaMerson 1e-10,
    // extrapolated journal loads): a different computation of the same
    // physics. Its journal loads lag the reaction by a fraction of a step;
    // docs/planetary_gear.md bounds that error of the friction torques by
    // 4e-5 at this accuracy; the drive torque, mesh force and reaction
    // carry it diluted by the inertia and gravity loads (friction is ~1 %
    // of the drive torque here), so 1e-6 of their peaks.
    const AnalysisResult integrated = runGearStart(
        "0.5 s", {{"scenarios.start.zero_dof", "integrate"}, {"integrator.accuracy", "1e-10"}});
    EXPECT_EQ(integrated.statistics.integrator, "RungeKuttaMerson");
    EXPECT_FALSE(hasNote(integrated, "no free degrees of freedom"));
    EXPECT_LT(relativeDifference(replay, integrated, "drum1.speed_rel_carrier"), 1e-12);  // both follow the drive's law
    EXPECT_LT(relativeDifference(replay, integrated, "drive.torque"), 1e-6);
    EXPECT_LT(relativeDifference(replay, integrated, "mesh1.tangential_force"), 1e-6);
    EXPECT_LT(relativeDifference(replay, integrated, "reaction_A.on_carrier_at_axis_magnitude"), 1e-6);
    EXPECT_LT(relativeDifference(replay, integrated, "friction_A.torque"), 4e-5);
    EXPECT_LT(relativeDifference(replay, integrated, "friction_B1.torque"), 4e-5);
    // No integration: a few realizations per placement (its own grid of
    // 4000 over the run, merged with the samples: issue 26 item 2).
    EXPECT_LT(replay.statistics.realizations, 10 * replay.statistics.steps);
}

TEST(ReplayTest, EnergyIntegralsDoNotDependOnTheSampling) {
    // The replay sums the energy meter's integrals by the trapezoid rule
    // over placements of its own (the run over 4000, merged with the
    // samples): halving the sample interval leaves the balance as it was
    // (it fell as h^2 with the sampling before issue 26 item 2).
    const double r2 = runGearStart("1 s", {{"outputs.sample_interval", "2 ms"}})
                          .find("energy_balance_residual")->value;
    const double r1 = runGearStart("1 s", {{"outputs.sample_interval", "1 ms"}})
                          .find("energy_balance_residual")->value;
    EXPECT_NE(r1, 0.0);
    EXPECT_NEAR(r2 / r1, 1.0, 0.2);
}

TEST(ReplayTest, AHeldChargeStartIsTheKinetostaticsOfEachInstant) {
    // Charges held at their lag: their wall torques are instant unknowns,
    // so the start is replayed, each sample solved as the kinetostatic
    // analysis solves one configuration. The same instant through that
    // analysis (the sample's carrier angle and speed, the law's time) must
    // give the same loads.
    const AnalysisResult start = runGearStart("1 s", {{"fidelity.level", "held_charge"}});
    ASSERT_EQ(start.statistics.integrator, "replay");
    for (const std::size_t row : {std::size_t(37), std::size_t(100)}) {
        const double t = start.value(row, "time");
        char angle[64], speed[64], time[64];
        std::snprintf(angle, sizeof angle, "%.17g rad", start.value(row, "carrier.angle"));
        std::snprintf(speed, sizeof speed, "%.17g rad/s", start.value(row, "carrier.speed"));
        std::snprintf(time, sizeof time, "%.17g s", t);
        const AnalysisResult instant = runAnalysis(readModelFile(
            kGear, defaultModelReader(),
            {{"fidelity.level", "held_charge"}, {"scenario.angle_from", angle}, {"scenario.carrier_speed", speed},
             {"scenario.time", time}, {"outputs.plots", "false"}}));
        for (const std::string column : {"drive.torque", "charge1.wall_torque", "friction_B1.torque",
                                         "reaction_A.on_carrier_at_axis_magnitude"}) {
            const double a = start.value(row, column), b = instant.value(0, column);
            EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(b))) << column << " at t = " << t;
        }
    }
    // Integrating it is refused with the reason (exit 2 from the driver).
    EXPECT_THROW(runGearStart("1 s", {{"fidelity.level", "held_charge"}, {"scenarios.start.zero_dof", "integrate"}}),
                 SpecError);
}

/// Why a transient of the model is integrated (empty: it is replayed).
std::string whyIntegrated(const std::string& model, const std::vector<Override>& sets) {
    const ModelSpec spec = readModelFile(model, defaultModelReader(), sets);
    const auto scene = buildScene(spec);
    return whyNoReplay(*scene, initialState(*scene, spec));
}

TEST(ReplayTest, ScenesWithFreeMotionAreIntegrated) {
    // Charges on their own pins, dragged by the wall: two free mobilities.
    EXPECT_EQ(whyIntegrated(kGear, {{"use_scenario", "start"}, {"fidelity.level", "dynamic_charge"}}),
              "integrated: 2 free degrees of freedom");
    const AnalysisResult dynamic =
        runGearStart("0.05 s", {{"fidelity.level", "dynamic_charge"}, {"integrator.accuracy", "1e-6"}});
    EXPECT_EQ(dynamic.statistics.integrator, "RungeKuttaMerson");
    EXPECT_FALSE(hasNote(dynamic, "free degrees of freedom"));  // the usual case: no note
    // The burr mill: a motor switched off at a scheduled time.
    EXPECT_EQ(whyIntegrated(kModels + "burr_mill_5p5kW_idle.yaml", {}), "integrated: the run has scheduled switchings");
    // The elastic belt: the belts' slip is a continuous state of their own.
    EXPECT_EQ(whyIntegrated(kModels + "planetary_belt_200x1000.yaml", {{"use_scenario", "start"}, {"fidelity.level", "elastic"}}),
              "integrated: elements have continuous states of their own");
    // The rigid-charge gear start replays.
    EXPECT_EQ(whyIntegrated(kGear, {{"use_scenario", "start"}}), "");
}

}  // namespace
}  // namespace milldyn
