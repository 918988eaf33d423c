// Issue 29 item 6: a wound rotor's start with stepped or liquid resistance
// splits the rotor circuit's heat between the rotor winding (R2) and the
// starter's external resistance ((r − 1)·R2), in the ratio of the two
// resistances at every instant; the two add up to the rotor circuit's heat.
//
// Closed form (static curve, linear law M_nat = c·(ωc − ω), c = Mn/(ωc − ωn)):
// with the rotor resistance r·R2 the torque at slip speed Δω = ωc − ω is the
// natural torque at Δω/r, M = c·Δω/r. A pure inertia J started from rest:
// J·dΔω/dt = −c·Δω/r, so Δω = ωc·e^(−t/τ), τ = J·r/c. The rotor circuit's
// heat rate is M·Δω = −J·Δω·dΔω/dt, so from Δω_a to Δω_b it takes
// ½·J·(Δω_a² − Δω_b²) whatever r (the classic ½·J·ωc² of a whole start);
// the external resistance takes (r − 1)/r of it while r is in circuit.
// Stepped: r1 until t1, then 1:
//   E_starter = (1 − 1/r1)·½·J·(ωc² − Δω1²),   Δω1 = ωc·e^(−t1/τ1)
//   E_total   = ½·J·(ωc² − Δω_T²),             Δω_T = Δω1·e^(−c·(T − t1)/J)
//   E_winding = E_total − E_starter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

namespace milldyn {
namespace {

std::string benchModel(const std::string& starter) {
    return "format_version: 1\n"
           "name: wound-rotor bench\n"
           "bodies:\n"
           "  - {name: shaft, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}\n"
           "elements:\n"
           "  - {type: InductionMotor, name: motor, body: shaft, law: linear, rated_torque: 100 N*m,\n"
           "     rated_speed: 1450 rpm, synchronous_speed: 1500 rpm, " + starter + "}\n"
           "scenario: {analysis: transient, initial_state: rest, end_time: 3 s, speed_body: shaft}\n"
           "integrator: {name: RungeKuttaMerson, accuracy: 1e-10}\n"
           "outputs: {sample_interval: 10 ms, plots: false}\n";
}

double result(const AnalysisResult& r, const std::string& name) {
    const ResultScalar* v = r.find(name);
    if (!v) throw std::runtime_error("no result " + name);
    return v->value;
}

TEST(StarterHeatSplit, SteppedResistanceSplitsAsTheClosedForm) {
    const AnalysisResult r = runAnalysis(readModelText(
        benchModel("starter: rotor_resistance, resistance_ratios: [4], switch_times: [1 s]"), "bench.yaml",
        defaultModelReader()));
    const double J = 2, wc = 1500 * M_PI / 30, c = 100 / (50 * M_PI / 30), r1 = 4, t1 = 1, T = 3;
    const double tau1 = J * r1 / c;
    const double dw1 = wc * std::exp(-t1 / tau1), dwT = dw1 * std::exp(-c * (T - t1) / J);
    const double starter = (1 - 1 / r1) * 0.5 * J * (wc * wc - dw1 * dw1);
    const double total = 0.5 * J * (wc * wc - dwT * dwT);
    EXPECT_NEAR(result(r, "energy.motor.starter_heat"), starter, 1e-6 * starter);
    EXPECT_NEAR(result(r, "energy.motor.rotor_heat"), total - starter, 1e-6 * total);
    EXPECT_NEAR(result(r, "energy.motor.starter_heat") + result(r, "energy.motor.rotor_heat"), total, 1e-6 * total);
    // The starter took a real share (not 0, not all): 3/4 of the first step's.
    EXPECT_GT(starter, 0.3 * total);
    EXPECT_LT(starter, 0.75 * total);

    // Every row: winding + starter = the rotor circuit's loss, in the ratio
    // 1 : (r − 1) — 1 : 3 before the switch, all in the winding after it.
    std::size_t before = 0, after = 0;
    for (std::size_t k = 0; k < r.rows.size(); ++k) {
        const double t = r.value(k, "time"), loss = r.value(k, "motor.rotor_loss");
        const double winding = r.value(k, "motor.rotor_winding_loss"), ext = r.value(k, "motor.starter_loss");
        EXPECT_NEAR(winding + ext, loss, 1e-12 * std::max(1.0, loss)) << t;
        if (t < t1 - 1e-9 && loss > 0) {
            EXPECT_NEAR(ext, 3 * winding, 1e-12 * loss) << t;
            EXPECT_EQ(r.value(k, "motor.rotor_resistance_ratio"), 4.0) << t;
            ++before;
        } else if (t > t1 + 1e-9) {
            EXPECT_EQ(ext, 0.0) << t;
            ++after;
        }
    }
    EXPECT_GT(before, 50u);
    EXPECT_GT(after, 50u);
}

TEST(StarterHeatSplit, LiquidResistanceSplitsInTheRampsRatioAtEveryRow) {
    // The liquid starter's ramp: r(t) = r0 + (1 − r0)·min(t/T_ramp, 1).
    const double r0 = 6, ramp = 2;
    const AnalysisResult r = runAnalysis(readModelText(
        benchModel("starter: liquid_resistance, initial_resistance_ratio: 6, ramp_time: 2 s"), "bench.yaml",
        defaultModelReader()));
    std::size_t checked = 0;
    for (std::size_t k = 0; k < r.rows.size(); ++k) {
        const double t = r.value(k, "time"), loss = r.value(k, "motor.rotor_loss");
        const double winding = r.value(k, "motor.rotor_winding_loss"), ext = r.value(k, "motor.starter_loss");
        const double ratio = r0 + (1 - r0) * std::min(t / ramp, 1.0);
        EXPECT_NEAR(winding + ext, loss, 1e-12 * std::max(1.0, loss)) << t;
        EXPECT_NEAR(winding, loss / ratio, 1e-9 * std::max(1.0, loss)) << t;
        EXPECT_NEAR(ext, loss * (ratio - 1) / ratio, 1e-9 * std::max(1.0, loss)) << t;
        checked += loss > 1.0;
    }
    EXPECT_GT(checked, 100u);
    // The energies add up to the rotor circuit's heat, ½·J·(ωc² − Δω_T²)
    // whatever the ramp (Δω_T from the run's end speed).
    const double J = 2, wc = 1500 * M_PI / 30;
    const double dwT = wc - r.value(r.rows.size() - 1, "shaft.speed");
    const double total = 0.5 * J * (wc * wc - dwT * dwT);
    EXPECT_NEAR(result(r, "energy.motor.starter_heat") + result(r, "energy.motor.rotor_heat"), total, 1e-6 * total);
    EXPECT_GT(result(r, "energy.motor.starter_heat"), 0.2 * total);
}

// The dq machine: the rotor circuit's loss 1.5·r·Rr·|i_r|² splits the same
// way, the external resistance's (r − 1)/r of it, at every row; r from the
// ramp's law (a liquid starter on MSL's AIM_SquirrelCage circuit).
TEST(StarterHeatSplit, DqMachineSplitsInTheRampsRatioAtEveryRow) {
    const double r0 = 5, ramp = 0.5;
    const AnalysisResult r = runModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/start_bench_dq.yaml",
                                          {{"elements.motor.starter", "liquid_resistance"},
                                           {"elements.motor.initial_resistance_ratio", "5"},
                                           {"elements.motor.ramp_time", "0.5 s"},
                                           {"scenario.end_time", "0.8 s"},
                                           {"outputs.sample_interval", "1 ms"},
                                           {"outputs.plots", "false"}});
    std::size_t checked = 0;
    for (std::size_t k = 0; k < r.rows.size(); ++k) {
        const double t = r.value(k, "time");
        const double ratio = r0 + (1 - r0) * std::min(t / ramp, 1.0);
        const double winding = r.value(k, "motor.rotor_winding_loss"), ext = r.value(k, "motor.starter_loss");
        EXPECT_NEAR(r.value(k, "motor.rotor_resistance_ratio"), ratio, 1e-12 * ratio) << t;
        EXPECT_NEAR(ext, (ratio - 1) * winding, 1e-9 * std::max(1.0, ext)) << t;
        checked += winding > 1.0;
    }
    EXPECT_GT(checked, 300u);
    EXPECT_GT(result(r, "energy.motor.starter_heat"), 0.0);
    EXPECT_GT(result(r, "energy.motor.copper_heat"), 0.0);
    // The split moves heat between two flows, never adds any: the balance closes.
    EXPECT_LT(std::abs(result(r, "energy_balance_relative")), 1e-3);
}

}  // namespace
}  // namespace milldyn
