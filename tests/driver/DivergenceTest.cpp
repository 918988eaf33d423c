// A diverging analysis stops with a diagnostic naming the element or body
// and the simulated time: never a NaN in the output, never a hang.

#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace milldyn {
namespace {

// A 1e9 N*m/rad coupling between 0.01 kg*m^2 shafts (ω ≈ 4.5e5 rad/s)
// integrated by fixed-step semi-explicit Euler at 10 ms: ω·h ≈ 4500, far
// outside its stability limit (ω·h < 2), so the motion grows by orders of
// magnitude each step and overflows within a few dozen steps.
const char* kUnstable = R"(format_version: 1
name: unstable
bodies:
  - {name: a, inertia: 0.01 kg*m^2, joint: {type: pin}, initial_angle: 0.001 rad}
  - {name: b, inertia: 0.01 kg*m^2, joint: {type: pin}}
elements:
  - {type: TorsionalCoupling, name: shaft, bodies: [a, b], stiffness: 1e9 N*m/rad}
scenario: {analysis: transient, initial_state: file, end_time: 5 s}
integrator: {name: SemiExplicitEuler, max_step: 10 ms}
outputs: {sample_interval: 10 ms, plots: false}
)";

TEST(DivergenceTest, UnstableIntegrationStopsNamingTheElementAndTheTime) {
    const ModelSpec spec = readModelText(kUnstable, "unstable.yaml", defaultModelReader());
    try {
        runAnalysis(spec);
        FAIL() << "a diverging run finished";
    } catch (const AnalysisError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not finite"), std::string::npos) << what;
        EXPECT_NE(what.find("t = "), std::string::npos) << what;
        const bool namesSomething = what.find("element shaft") != std::string::npos ||
                                    what.find("body a") != std::string::npos ||
                                    what.find("body b") != std::string::npos ||
                                    what.find("integrator") != std::string::npos;
        EXPECT_TRUE(namesSomething) << what;
    }
}

TEST(DivergenceTest, TheSameModelIsStableWithAnErrorControlledIntegrator) {
    // Stable means bounded and conservative: the undamped pair, released at
    // rest with a twist of 1 mrad, swings between ±1 mrad for good (period
    // 2π/√(k(1/J_a + 1/J_b)) = 14 µs, ~70 periods in 1 ms, sampled every
    // 1 µs) and its energy balance closes.
    ModelSpec spec = readModelText(kUnstable, "unstable.yaml", defaultModelReader(),
                                   {{"outputs.sample_interval", "1e-6 s"}});
    spec.integrator.name = "RungeKuttaMerson";
    spec.integrator.maxStep = 0;
    spec.scenario.params["end_time"].number = 1e-3;
    const AnalysisResult r = runAnalysis(spec);
    ASSERT_GT(r.rows.size(), 900u);
    double largest = 0, lateLargest = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        for (double v : r.rows[i]) ASSERT_TRUE(std::isfinite(v));
        const double twist = std::abs(r.value(i, "shaft.twist"));
        largest = std::max(largest, twist);
        if (r.rows[i][0] > 0.9e-3) lateLargest = std::max(lateLargest, twist);
    }
    EXPECT_LE(largest, 1e-3 * (1 + 1e-4));   // never beyond the initial twist
    EXPECT_GE(lateLargest, 0.9e-3);          // still swinging at the end (1 µs samples: ≥ cos(π/14))
    const ResultScalar* balance = r.find("energy_balance_relative");
    ASSERT_NE(balance, nullptr);
    EXPECT_LT(std::abs(balance->value), 1e-4);
}

// The burr demo on fixed-step semi-explicit Euler at 50 ms (the belt mode's
// ω·h ≈ 9, beyond the stability limit 2): the run-out stop ended the run
// before any sample overflowed, and it printed steady_speed −2e153 rad/s with
// exit 0. A run whose energy balance misses by more than 1 % is refused.
TEST(DivergenceTest, ARunWhoseEnergyBalanceDoesNotCloseIsNoResult) {
    const ModelSpec spec = readModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml",
                                         defaultModelReader(),
                                         {{"integrator.name", "SemiExplicitEuler"},
                                          {"integrator.max_step", "50 ms"},
                                          {"outputs.plots", "false"}});
    try {
        const AnalysisResult r = runAnalysis(spec);
        const ResultScalar* speed = r.find("steady_speed");
        FAIL() << "a diverged run gave results, steady_speed " << (speed ? speed->value : 0.0);
    } catch (const AnalysisError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("energy balance does not close"), std::string::npos) << what;
        EXPECT_NE(what.find("SemiExplicitEuler"), std::string::npos) << what;
        EXPECT_NE(what.find("t = "), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace milldyn
