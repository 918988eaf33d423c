// Tests of Schedule (plugins/scene/Schedule.h): each shape against its
// closed form written from the class comment, the model key's reader, and
// scheduled elements in runs against trajectories in closed form: a ramped
// load and a ramped torque source on one inertia, a bed-collapse step
// located by the integrator, and a clutch that sticks, slips and sticks
// again on two inertias (Clutch.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"
#include "plugins/scene/ElementSchema.h"
#include "plugins/scene/Schedule.h"
#include "plugins/transmissions/Clutch.h"

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Schedule, AbsentKeyIsTheConstantOne) {
    const Schedule s;
    EXPECT_TRUE(s.isConstant());
    EXPECT_EQ(s.factorAt(-3), 1.0);
    EXPECT_EQ(s.factorAt(1e6), 1.0);
    EXPECT_TRUE(s.breakpoints().empty());
}

TEST(Schedule, RampHoldsItsEndsAndIsLinearBetween) {
    // f = a + (b − a)(t − t0)/T on (t0, t0 + T): t0 = 5, T = 10, a = 0.2, b = 1.
    const Schedule s = Schedule::ramp(5, 10, 0.2, 1.0);
    EXPECT_EQ(s.factorAt(0), 0.2);
    EXPECT_EQ(s.factorAt(5), 0.2);
    EXPECT_NEAR(s.factorAt(7.5), 0.2 + 0.8 * 0.25, 1e-15);
    EXPECT_NEAR(s.factorAt(12), 0.2 + 0.8 * 0.7, 1e-15);
    EXPECT_EQ(s.factorAt(15), 1.0);
    EXPECT_EQ(s.factorAt(100), 1.0);
    EXPECT_EQ(s.breakpoints(), (std::vector<double>{5, 15}));
    EXPECT_EQ(s.settleTime(), 15.0);
    EXPECT_EQ(s.finalFactor(), 1.0);
    EXPECT_EQ(s.minimumFactor(), 0.2);
}

TEST(Schedule, StepRecoveryDropsAndRecoversLinearly) {
    // A 50 % drop at 20 s recovered in 0.4 s: f = 1 − 0.5·(1 − (t − 20)/0.4).
    const Schedule s = Schedule::stepRecovery(20, 0.5, 0.4);
    EXPECT_EQ(s.factorAt(19.999), 1.0);
    EXPECT_EQ(s.factorAt(20), 1.0);  // left-continuous: the step ending at 20 s sees 1
    EXPECT_NEAR(s.factorAt(20 + 1e-9), 0.5, 1e-8);
    EXPECT_NEAR(s.factorAt(20.1), 1 - 0.5 * 0.75, 1e-12);
    EXPECT_NEAR(s.factorAt(20.3), 1 - 0.5 * 0.25, 1e-12);
    EXPECT_EQ(s.factorAt(20.4), 1.0);
    EXPECT_EQ(s.breakpoints(), (std::vector<double>{20, 20.4}));
    EXPECT_EQ(s.minimumFactor(), 0.5);
    // A negative drop is a surge: 1 + 0.3 right after the step.
    EXPECT_NEAR(Schedule::stepRecovery(1, -0.3, 1).factorAt(1 + 1e-12), 1.3, 1e-11);
}

TEST(Schedule, SineStartsAtItsStartAndHoldsItsFirstValueBefore) {
    // f = m + A·sin(2π·fr·(t − t0) + φ): m = 1, A = 0.1, fr = 2 Hz, φ = π/6, t0 = 1.
    const Schedule s = Schedule::sine(1.0, 0.1, 2.0, kPi / 6, 1.0);
    EXPECT_NEAR(s.factorAt(0.0), 1 + 0.1 * 0.5, 1e-15);
    EXPECT_NEAR(s.factorAt(1.0), 1 + 0.1 * 0.5, 1e-15);
    for (double t : {1.1, 1.37, 2.0, 3.91})
        EXPECT_NEAR(s.factorAt(t), 1 + 0.1 * std::sin(2 * kPi * 2 * (t - 1) + kPi / 6), 1e-14) << t;
    EXPECT_EQ(s.breakpoints(), (std::vector<double>{1.0}));
    EXPECT_TRUE(std::isinf(s.settleTime()));
    EXPECT_NEAR(s.minimumFactor(), 0.9, 1e-15);
}

TEST(Schedule, TableInterpolatesLinearlyHoldsItsEndsAndJumpsAtRepeatedTimes) {
    // A clutch's pressure curve: 0 until 1 s, 30 % at 1.5 s, full at 3 s.
    const Schedule s = Schedule::table({1, 1.5, 3}, {0, 0.3, 1});
    EXPECT_EQ(s.factorAt(0), 0.0);
    EXPECT_NEAR(s.factorAt(1.25), 0.15, 1e-15);
    EXPECT_NEAR(s.factorAt(2.25), 0.3 + 0.7 * 0.5, 1e-15);
    EXPECT_EQ(s.factorAt(5), 1.0);
    EXPECT_EQ(s.breakpoints(), (std::vector<double>{1, 1.5, 3}));
    // Two rows at 2 s: a jump from 1 to 3, left-continuous (3 just after 2 s).
    const Schedule jump = Schedule::table({0, 2, 2, 4}, {1, 1, 3, 3});
    EXPECT_EQ(jump.factorAt(1.999999), 1.0);
    EXPECT_EQ(jump.factorAt(2.0), 1.0);
    EXPECT_EQ(jump.factorAt(2.000001), 3.0);
    EXPECT_EQ(jump.factorAt(9.0), 3.0);
    const Schedule last = Schedule::table({0, 1, 1}, {1, 1, 0});  // a jump at the last time
    EXPECT_EQ(last.factorAt(1.0), 1.0);
    EXPECT_EQ(last.factorAt(1.5), 0.0);
    EXPECT_EQ(jump.breakpoints(), (std::vector<double>{0, 2, 4}));
}

TEST(Schedule, RefusesWhatIsNotASchedule) {
    EXPECT_THROW(Schedule::ramp(0, 0), std::invalid_argument);              // no duration
    EXPECT_THROW(Schedule::ramp(-1, 1), std::invalid_argument);             // before t = 0
    EXPECT_THROW(Schedule::ramp(0, 1, 1, -0.5), std::invalid_argument);     // a reversed magnitude
    EXPECT_THROW(Schedule::stepRecovery(1, 1.5, 1), std::invalid_argument); // more than the whole
    EXPECT_THROW(Schedule::stepRecovery(1, 0.5, 0), std::invalid_argument);
    EXPECT_THROW(Schedule::sine(0.05, 0.1, 1), std::invalid_argument);      // dips below 0
    EXPECT_THROW(Schedule::sine(1, 0.1, 0), std::invalid_argument);
    EXPECT_THROW(Schedule::table({0, 1, 1, 1}, {0, 1, 2, 3}), std::invalid_argument);  // three rows at 1 s
    EXPECT_THROW(Schedule::table({0, 2, 1}, {0, 1, 2}), std::invalid_argument);        // time going back
    EXPECT_THROW(Schedule::decode("ramp", {0, 1, 0}), std::invalid_argument);
    EXPECT_THROW(Schedule::decode("ramp", {0, 1, 0, std::nan("")}), std::invalid_argument);
    EXPECT_THROW(Schedule::decode("wave", {}), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// The model key.

std::string oneShaft(const std::string& element, const std::string& scenario = "") {
    return "format_version: 1\n"
           "name: schedule test\n"
           "bodies:\n"
           "  - name: drum\n"
           "    inertia: 2 kg*m^2\n"
           "    joint: {type: pin, parent: ground}\n"
           "    initial_speed: 100 rad/s\n"
           "elements:\n" +
           element +
           (scenario.empty() ? "scenario:\n"
                               "  analysis: transient\n"
                               "  initial_state: file\n"
                               "  end_time: 3 s\n"
                               "  speed_body: drum\n"
                               "integrator:\n"
                               "  name: CPodes\n"
                               "  accuracy: 1e-8\n"
                               "outputs:\n"
                               "  sample_interval: 0.1 s\n"
                             : scenario);
}

SpecError readError(const std::string& text) {
    try {
        readModelText(text, "schedule.yaml", defaultModelReader());
    } catch (const SpecError& e) {
        return e;
    }
    ADD_FAILURE() << "no SpecError for:\n" << text;
    return SpecError({}, "", "");
}

TEST(ScheduleKey, ReadsEveryShapeInSIWithDefaults) {
    const ModelSpec spec = readModelText(oneShaft("  - type: ResistanceTorque\n"
                                                  "    name: load\n"
                                                  "    body: drum\n"
                                                  "    constant_torque: 10 N*m\n"
                                                  "    schedule: {ramp: {start: 500 ms, duration: 2 s}}\n"),
                                         "schedule.yaml", defaultModelReader());
    const ParamValue& v = spec.elements.at(0).params.at("schedule");
    EXPECT_EQ(v.text, "ramp");
    EXPECT_EQ(v.numbers, (std::vector<double>{0.5, 2.0, 0.0, 1.0}));  // start, duration, from, to
    const ModelSpec table = readModelText(oneShaft("  - type: ResistanceTorque\n"
                                                   "    name: load\n"
                                                   "    body: drum\n"
                                                   "    constant_torque: 10 N*m\n"
                                                   "    schedule:\n"
                                                   "      table: [[0 s, 1], [1 min, 50 %]]\n"),
                                          "schedule.yaml", defaultModelReader());
    EXPECT_EQ(table.elements.at(0).params.at("schedule").numbers, (std::vector<double>{0, 1, 60, 0.5}));
}

TEST(ScheduleKey, BadSchedulesAreOneLocatedError) {
    const std::string head = "  - type: ResistanceTorque\n    name: load\n    body: drum\n    constant_torque: 10 N*m\n";
    SpecError e = readError(oneShaft(head + "    schedule: {rmap: {duration: 2 s}}\n"));
    EXPECT_EQ(e.key(), "load.schedule.rmap");
    EXPECT_NE(std::string(e.what()).find("did you mean 'ramp'"), std::string::npos) << e.what();
    e = readError(oneShaft(head + "    schedule: {ramp: {start: 1 s}}\n"));
    EXPECT_EQ(e.key(), "load.schedule.ramp.duration");
    e = readError(oneShaft(head + "    schedule: {ramp: {duration: 2 rad}}\n"));
    EXPECT_EQ(e.key(), "load.schedule.ramp.duration");
    e = readError(oneShaft(head + "    schedule: {step_recovery: {at: 1 s, drop: 2, recovery_time: 0.4 s}}\n"));
    EXPECT_EQ(e.key(), "load.schedule.step_recovery");
    EXPECT_NE(std::string(e.what()).find("drop must be <= 1"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().line, 13);
    e = readError(oneShaft(head + "    schedule: {table: [[0 s, 1], [2 s]]}\n"));
    EXPECT_EQ(e.key(), "load.schedule.table");
    e = readError(oneShaft(head + "    schedule: 3\n"));
    EXPECT_EQ(e.key(), "load.schedule");
    e = readError(oneShaft(head + "    schedule: {ramp: {duration: 1 s}, sine: {amplitude: 0.1, frequency: 1 Hz}}\n"));
    EXPECT_EQ(e.key(), "load.schedule");
    // A brake's schedule is the whole application: not with the ramp keys.
    e = readError(oneShaft("  - type: Brake\n    name: b\n    body: drum\n    capacity: 1 N*m\n"
                           "    apply_time: 1 s\n    schedule: {ramp: {duration: 1 s}}\n"));
    EXPECT_EQ(e.key(), "b.apply_time");
}

// ---------------------------------------------------------------------------
// Runs against closed forms.

double valueAt(const AnalysisResult& r, const std::string& column, double t) {
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        if (std::abs(r.value(i, "time") - t) <= 1e-12) return r.value(i, column);
    ADD_FAILURE() << "no sample at t = " << t;
    return std::nan("");
}

/// ∫0^t f for the ramp (t0, T) from 0 to 1 [s].
double rampIntegral(double t, double t0, double T) {
    if (t <= t0) return 0;
    if (t <= t0 + T) return (t - t0) * (t - t0) / (2 * T);
    return T / 2 + (t - t0 - T);
}

TEST(ScheduledLoad, RampedLoadOnOneInertiaFollowsTheClosedFormSpeed) {
    // J·dω/dt = −M0·f(t) (ω > 0, far above the smoothing speed):
    // ω(t) = ω0 − (M0/J)·∫0^t f, f a ramp from 0 to 1 over [0.35, 1.35] s.
    const double J = 2, w0 = 100, M0 = 30, t0 = 0.35, T = 1.0;
    const AnalysisResult r = runAnalysis(readModelText(oneShaft("  - type: ResistanceTorque\n"
                                                                "    name: load\n"
                                                                "    body: drum\n"
                                                                "    constant_torque: 30 N*m\n"
                                                                "    smoothing_speed: 1e-3 rad/s\n"
                                                                "    schedule: {ramp: {start: 0.35 s, duration: 1 s}}\n"),
                                                       "schedule.yaml", defaultModelReader()));
    for (double t : {0.3, 0.8, 1.3, 2.0, 3.0})
        EXPECT_NEAR(valueAt(r, "drum.speed", t), w0 - M0 / J * rampIntegral(t, t0, T), 1e-6) << t;
    // Both kinks are step ends (samples at 0.35 and 1.35 s, off the 0.1 s grid).
    EXPECT_NEAR(valueAt(r, "load.torque", t0), 0.0, 1e-12);
    EXPECT_NEAR(valueAt(r, "load.torque", t0 + T), M0, 1e-9);
}

TEST(ScheduledLoad, RampedTorqueSourceOnOneInertiaFollowsTheClosedFormSpeed) {
    // J·dω/dt = M0·f(t), f the same ramp: ω(t) = ω0 + (M0/J)·∫0^t f.
    const double J = 2, w0 = 100, M0 = 30, t0 = 0.35, T = 1.0;
    const AnalysisResult r = runAnalysis(readModelText(oneShaft("  - type: AppliedTorque\n"
                                                                "    name: source\n"
                                                                "    body: drum\n"
                                                                "    torque: 30 N*m\n"
                                                                "    schedule: {ramp: {start: 0.35 s, duration: 1 s}}\n"),
                                                       "schedule.yaml", defaultModelReader()));
    for (double t : {0.3, 0.8, 1.3, 2.0, 3.0})
        EXPECT_NEAR(valueAt(r, "drum.speed", t), w0 + M0 / J * rampIntegral(t, t0, T), 1e-6) << t;
}

TEST(ScheduledLoad, ABedCollapseStepIsLocatedAndItsDeficitMatchesTheClosedForm) {
    // A 50 % drop at ts = 1.2345 s recovered in 0.4 s: the load's impulse
    // lacks d·M0·Tr/2, so after the recovery ω = ω0 − (M0/J)·(t − d·Tr/2).
    const double J = 2, w0 = 100, M0 = 30, ts = 1.2345, d = 0.5, Tr = 0.4;
    for (const char* sampling : {"0.1 s", "0.0371 s"}) {
        std::string text = oneShaft("  - type: ResistanceTorque\n"
                                    "    name: load\n"
                                    "    body: drum\n"
                                    "    constant_torque: 30 N*m\n"
                                    "    smoothing_speed: 1e-3 rad/s\n"
                                    "    schedule: {step_recovery: {at: 1.2345 s, drop: 0.5, recovery_time: 0.4 s}}\n");
        text.replace(text.find("0.1 s"), 5, sampling);
        const AnalysisResult r = runAnalysis(readModelText(text, "schedule.yaml", defaultModelReader()));
        // The step is a sample and a step end: the state just before the
        // switching, so the torque there is the full one (left-continuous).
        EXPECT_NEAR(valueAt(r, "load.torque", ts), M0, 1e-9) << sampling;
        EXPECT_NEAR(valueAt(r, "drum.speed", ts), w0 - M0 / J * ts, 1e-6) << sampling;
        EXPECT_NEAR(valueAt(r, "load.torque", ts + Tr), M0, 1e-9) << sampling;
        EXPECT_NEAR(valueAt(r, "drum.speed", ts + Tr), w0 - M0 / J * (ts + Tr - d * Tr / 2), 1e-6) << sampling;
        const std::size_t last = r.rows.size() - 1;
        EXPECT_NEAR(r.value(last, "time"), 3.0, 1e-12);
        EXPECT_NEAR(r.value(last, "drum.speed"), w0 - M0 / J * (3.0 - d * Tr / 2), 1e-6) << sampling;
    }
}

TEST(ScheduledLoad, ABreakawayResistanceFollowsItsScheduleAsTheClosedFormSays) {
    // Far above its release speed (100 rad/s against 0.1) the law is the
    // running torque M_r = 30 N*m (exp(−10⁶) = 0, tanh(10⁵) = 1): the same
    // bed collapse as above, ω = ω0 − (M_r/J)·(t − d·Tr/2) after it.
    const double J = 2, w0 = 100, Mr = 30, ts = 1.2345, d = 0.5, Tr = 0.4;
    const AnalysisResult r = runAnalysis(readModelText(
        oneShaft("  - type: BreakawayResistance\n"
                 "    name: load\n"
                 "    body: drum\n"
                 "    static_torque: 80 N*m\n"
                 "    running_torque: 30 N*m\n"
                 "    schedule: {step_recovery: {at: 1.2345 s, drop: 0.5, recovery_time: 0.4 s}}\n"),
        "schedule.yaml", defaultModelReader()));
    EXPECT_NEAR(valueAt(r, "drum.speed", ts), w0 - Mr / J * ts, 1e-6);
    EXPECT_NEAR(valueAt(r, "load.torque", ts + Tr), Mr, 1e-9);
    const std::size_t last = r.rows.size() - 1;
    EXPECT_NEAR(r.value(last, "drum.speed"), w0 - Mr / J * (3.0 - d * Tr / 2), 1e-6);
    // The torque at a sample inside the recovery, against f(t)·M_r.
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const double t = r.value(i, "time");
        if (t > ts + 1e-9 && t < ts + Tr - 1e-9) {
            EXPECT_NEAR(r.value(i, "load.torque"), Mr * (1 - d * (1 - (t - ts) / Tr)), 1e-9) << t;
        }
    }
}

TEST(ScheduledLoad, ARampedDiscDragFollowsTheClosedFormSpeed) {
    // Laminar disc drag T = c·ω^(3/2), c = 0.616·π·ρ·r⁴·k·√ν (seed 001
    // eq 1), times a ramp f from 0 to 1 over [0.35, 1.35] s:
    // J·dω/dt = −f(t)·c·ω^(3/2)  ⇒  ω^(−1/2) = ω0^(−1/2) + (c/(2J))·∫0^t f.
    const double J = 2, w0 = 100, t0 = 0.35, T = 1.0, rho = 1000, nu = 1e-6, r4 = std::pow(0.2, 4), k = 10;
    const double c = 0.616 * kPi * rho * r4 * k * std::sqrt(nu);
    const AnalysisResult r = runAnalysis(readModelText(oneShaft("  - type: DiscDrag\n"
                                                                "    name: drag\n"
                                                                "    body: drum\n"
                                                                "    medium_density: 1000 kg/m^3\n"
                                                                "    medium_viscosity: 1e-6 m^2/s\n"
                                                                "    disc_diameter: 0.4 m\n"
                                                                "    discs: 10\n"
                                                                "    schedule: {ramp: {start: 0.35 s, duration: 1 s}}\n"),
                                                       "schedule.yaml", defaultModelReader()));
    auto omega = [&](double t) {
        const double x = 1 / std::sqrt(w0) + c / (2 * J) * rampIntegral(t, t0, T);
        return 1 / (x * x);
    };
    ASSERT_LT(omega(3.0), w0 - 10);  // the drag is felt: a test that can fail
    for (double t : {0.3, 0.8, 1.3, 2.0, 3.0}) {
        EXPECT_NEAR(valueAt(r, "drum.speed", t), omega(t), 1e-6) << t;
        const double f = t <= t0 ? 0.0 : std::min(1.0, (t - t0) / T);
        const double w = valueAt(r, "drum.speed", t);
        EXPECT_NEAR(valueAt(r, "drag.torque", t), f * c * std::pow(w, 1.5), 1e-9) << t;
    }
}

TEST(ScheduledBrake, BrakeCapacityOnATableStopsTheDrumAsTheClosedFormSays) {
    // Brake capacity 40 N*m times a table 0 → 1 over [0.5, 1.0] s, then 1:
    // ω(t) = ω0 − (Mb/J)·∫f: 100 − 20·(t − 0.5)²/(2·0.5) on the ramp,
    // 100 − 20·(0.25 + (t − 1)) for t >= 1 s.
    const AnalysisResult r = runAnalysis(readModelText(oneShaft("  - type: Brake\n"
                                                                "    name: brake\n"
                                                                "    body: drum\n"
                                                                "    capacity: 40 N*m\n"
                                                                "    schedule: {table: [[0.5 s, 0], [1 s, 1]]}\n"),
                                                       "schedule.yaml", defaultModelReader()));
    EXPECT_NEAR(valueAt(r, "drum.speed", 0.5), 100.0, 1e-9);
    EXPECT_NEAR(valueAt(r, "drum.speed", 0.8), 100 - 20 * (0.3 * 0.3 / (2 * 0.5)), 1e-6);
    EXPECT_NEAR(valueAt(r, "drum.speed", 2.0), 100 - 20 * 1.25, 1e-6);
    EXPECT_NEAR(valueAt(r, "drum.speed", 3.0), 100 - 20 * 2.25, 1e-6);
}

// ---------------------------------------------------------------------------
// The clutch sticks, slips and sticks again.

TEST(ClutchStickSlip, SlidingTorqueIsBelowTheStickingOne) {
    // κ = 0.6: at slips far above ω_s the torque is 0.6·M_c; at 5·ω_reg
    // (= ω_s/2) M_c·(0.6 + 0.4·e^(−1/4))·tanh 5 = 91.14 N*m, and the
    // largest torque over the slip is above 0.95·M_c (the sticking one,
    // less the Stribeck fall and the tanh rise overlapping).
    const double Mc = 100, k = 0.6, wreg = 1e-3, ws = 0.01;
    EXPECT_NEAR(calcStickSlipTorque(Mc, k, 1.0, wreg, ws), 60.0, 1e-9);
    EXPECT_NEAR(calcStickSlipTorque(Mc, k, -1.0, wreg, ws), -60.0, 1e-9);
    EXPECT_NEAR(calcStickSlipTorque(Mc, k, 5 * wreg, wreg, ws), Mc * (0.6 + 0.4 * std::exp(-0.25)) * std::tanh(5.0),
                1e-12);
    double largest = 0;
    for (int i = 1; i <= 10000; ++i) largest = std::max(largest, calcStickSlipTorque(Mc, k, i * 1e-6, wreg, ws));
    EXPECT_GT(largest, 0.95 * Mc);
    EXPECT_LT(largest, Mc);
    EXPECT_EQ(calcStickSlipTorque(Mc, 1.0, 0.3, wreg, ws), calcFrictionTorque(Mc, 0.3, wreg));
}

TEST(ClutchStickSlip, TwoInertiasStickSlipAndLockWhereTheSpeedsMeet) {
    // J1 = J2 = 1 kg*m^2 from rest; the clutch sticks up to 100 N*m and
    // slides at 60 N*m. A torque source on J1: 100 N*m to 1 s, 300 N*m to
    // 1.5 s, then 0. Closed form (ideal stick/slip):
    //   0 – 1 s    locked (needs 50 < 100): both at 50 rad/s²; 50 rad/s at 1 s
    //   1 – 1.5 s  locked would need 150 > 100: slips; J1 at (300 − 60) = 240,
    //              J2 at 60 rad/s²: 170 and 80 rad/s at 1.5 s
    //   1.5 s on   J1 at −60, J2 at +60 rad/s²: the speeds meet at
    //              1.5 + 90/120 = 2.25 s at 125 rad/s; locked with 0 N*m after
    // The regularised law departs from the ideal one only while |Δω| < 3·ω_s
    // (0.03 rad/s), over 0.03/120 s at most, by at most M_c − M_k = 40 N*m:
    // speeds within 40·0.03/120 = 0.01 rad/s.
    const std::string text = "format_version: 1\n"
                             "name: stick slip\n"
                             "bodies:\n"
                             "  - {name: a, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}}\n"
                             "  - {name: b, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}}\n"
                             "elements:\n"
                             "  - type: AppliedTorque\n"
                             "    name: drive\n"
                             "    body: a\n"
                             "    torque: 100 N*m\n"
                             "    schedule: {table: [[0 s, 1], [1 s, 1], [1 s, 3], [1.5 s, 3], [1.5 s, 0]]}\n"
                             "  - type: Clutch\n"
                             "    name: clutch\n"
                             "    bodies: [a, b]\n"
                             "    capacity: 100 N*m\n"
                             "    kinetic_capacity: 60 N*m\n"
                             "    stribeck_speed: 0.01 rad/s\n"
                             "    schedule: {table: [[0 s, 1], [1 s, 1]]}\n"
                             "scenario:\n"
                             "  analysis: transient\n"
                             "  initial_state: file\n"
                             "  end_time: 3 s\n"
                             "  speed_body: b\n"
                             "integrator:\n"
                             "  name: CPodes\n"
                             "  accuracy: 1e-8\n"
                             "outputs:\n"
                             "  sample_interval: 5 ms\n";
    const AnalysisResult r = runAnalysis(readModelText(text, "stickslip.yaml", defaultModelReader()));
    const double tol = 0.01;
    struct Point { double t, a, b; };
    for (const Point& p : {Point{0.5, 25, 25}, Point{1.0, 50, 50}, Point{1.25, 110, 65}, Point{1.5, 170, 80},
                           Point{2.0, 140, 110}, Point{2.5, 125, 125}, Point{3.0, 125, 125}}) {
        EXPECT_NEAR(valueAt(r, "a.speed", p.t), p.a, tol) << p.t;
        EXPECT_NEAR(valueAt(r, "b.speed", p.t), p.b, tol) << p.t;
    }
    // Stuck before 1 s: creep only, ≈ ω_reg·atanh(50/100) = 5.5e-4 rad/s.
    // Sliding at the kinetic torque in between; locked again from 2.25 s.
    double lockTime = std::nan("");
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const double t = r.value(i, "time"), slip = r.value(i, "clutch.slip_speed");
        if (t > 0.05 && t < 0.99) {
            EXPECT_LT(std::abs(slip), 1e-3) << t;
        }
        if (t > 1.01 && t < 2.2) {
            EXPECT_NEAR(r.value(i, "clutch.torque"), 60.0, 1e-6) << t;
        }
        if (t > 1.5 && std::isnan(lockTime) && slip < 1e-2) lockTime = t;
        if (t > 2.3) {
            EXPECT_LT(std::abs(slip), 1e-3) << t;
        }
    }
    EXPECT_NEAR(lockTime, 2.25, 0.005);  // the 5 ms sampling
}

// ---------------------------------------------------------------------------
// A schedule started by an event (`after: {shaft, speed}`).

/// One inertia J = 2 kg*m^2 from rest, driven by 20 N*m: ω = 10 t, so it
/// passes 15 rad/s at t_c = 1.5 s exactly; a 10 N*m load on a ramp 0 → 1
/// over [0.25, 0.75] s of its clock, which starts there.
/// `text` with its one `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

std::string runUp(const std::string& speed, const std::string& interval) {
    return "format_version: 1\n"
           "name: triggered schedule\n"
           "bodies:\n"
           "  - {name: drum, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}\n"
           "elements:\n"
           "  - {type: AppliedTorque, name: drive, body: drum, torque: 20 N*m}\n"
           "  - type: ResistanceTorque\n"
           "    name: load\n"
           "    body: drum\n"
           "    constant_torque: 10 N*m\n"
           "    smoothing_speed: 1e-3 rad/s\n"
           "    schedule: {ramp: {start: 0.25 s, duration: 0.5 s}, after: {shaft: drum, speed: " + speed + "}}\n"
           "scenario: {analysis: transient, end_time: 3 s, speed_body: drum}\n"
           "integrator: {name: CPodes, accuracy: 1e-8}\n"
           "outputs: {sample_interval: " + interval + "}\n";
}

TEST(TriggeredSchedule, ARampAfterTheRunUpStartsWhereTheShaftPassesItsSpeed) {
    // ω(t) = 10 t − (10/2)·∫ f(τ − t_c) dτ, f the ramp on the clock τ − t_c.
    const double tc = 1.5;
    for (const char* interval : {"0.1 s", "0.0371 s"}) {
        SCOPED_TRACE(interval);
        const AnalysisResult r = runAnalysis(readModelText(runUp("15 rad/s", interval), "t.yaml", defaultModelReader()));
        const ResultScalar* start = nullptr;
        for (const auto& x : r.results)
            if (x.name == "load.schedule_start_time") start = &x;
        ASSERT_NE(start, nullptr);
        EXPECT_NEAR(start->value, tc, 1e-9);
        for (std::size_t i = 0; i < r.rows.size(); ++i) {
            const double t = r.value(i, "time");
            const double local = std::max(0.0, t - tc);
            const double w = 10 * t - 5 * rampIntegral(local, 0.25, 0.5);
            EXPECT_NEAR(r.value(i, "drum.speed"), w, 1e-6) << t;
            const double f = std::min(std::max((local - 0.25) / 0.5, 0.0), 1.0);
            EXPECT_NEAR(r.value(i, "load.torque"), 10 * f, 1e-6) << t;
            EXPECT_NEAR(r.value(i, "load.schedule_clock"), local, 1e-9) << t;
        }
        // The ramp's ends are on the trajectory (located events): the
        // closed form at 3 s has both kinks in it.
        EXPECT_NEAR(r.value(r.rows.size() - 1, "drum.speed"), 30 - 5 * rampIntegral(1.5, 0.25, 0.5), 1e-6);
    }
}

TEST(TriggeredSchedule, ATriggerThatNeverFiresSaysSoAndHoldsTheFactor) {
    const AnalysisResult r = runAnalysis(readModelText(runUp("100 rad/s", "0.1 s"), "t.yaml", defaultModelReader()));
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        EXPECT_NEAR(r.value(i, "drum.speed"), 10 * r.value(i, "time"), 1e-6);
        EXPECT_EQ(r.value(i, "load.torque"), 0.0);
    }
    bool said = false;
    for (const auto& n : r.notes) said = said || n.find("never started") != std::string::npos;
    EXPECT_TRUE(said);
    for (const auto& x : r.results) EXPECT_NE(x.name, "load.schedule_start_time");
}

TEST(TriggeredSchedule, BadTriggersAreOneLocatedError) {
    std::string text = runUp("15 rad/s", "0.1 s");
    SpecError e = readError(replaced(text, "after: {shaft: drum,", "after: {shaft: drun,"));
    EXPECT_EQ(e.key(), "load.schedule.after.shaft");
    e = readError(replaced(text, "speed: 15 rad/s", "speed: 15 s"));
    EXPECT_EQ(e.key(), "load.schedule.after.speed");
    e = readError(replaced(text, "speed: 15 rad/s}", "speed: 15 rad/s, at: 1 s}"));
    EXPECT_EQ(e.key(), "load.schedule.after.at");
}

}  // namespace
}  // namespace milldyn
