// Samples between step ends are interpolated by the Simulation (cubic
// Hermite from the two step ends, the discrete variables of the step's end)
// when the scene has no constraints: checked here on a motion with a closed
// form. A shaft spinning down under a constant load, the feed opening at
// 1 s (a switching: discrete variable and integrator restart): ω is
// piecewise linear and θ piecewise quadratic, which a cubic interpolant
// reproduces exactly, so every sample must match to round-off however long
// the integrator's steps are (constant torque: its error estimate is ~0
// and its steps grow to the run's length).

#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace milldyn {
namespace {

const char* kSpinDown = R"(format_version: 1
name: spin-down under a constant load, feed opening at 1 s
bodies:
  - {name: shaft, inertia: 2 kg*m^2, initial_speed: 100 rad/s, joint: {type: pin}}
elements:
  - {type: ResistanceTorque, name: load, body: shaft, law: feed, constant_torque: 10 N*m,
     feed_rate: 1 kg/min, feed_coefficient: 20 N*m, feed_exponent: 1, feed_start_time: 1 s}
scenario: {analysis: transient, end_time: 2 s, initial_state: file}
integrator: {name: RungeKuttaMerson, accuracy: 1e-6}
outputs: {sample_interval: 1 ms, plots: false}
)";

TEST(SamplingTest, InterpolatedSamplesReproduceAPiecewiseQuadraticMotion) {
    // Runge-Kutta steps of order >= 2 integrate this motion exactly: only
    // round-off is left. CPodes starts at order 1 (backward Euler, not exact
    // for a quadratic): its own error, within its accuracy 1e-6, is allowed.
    for (const std::string integrator : {"RungeKuttaMerson", "RungeKutta3", "CPodes"}) {
        SCOPED_TRACE(integrator);
        const double tolerance = integrator == "CPodes" ? 1e-6 : 1e-9;
        const ModelSpec spec = readModelText(kSpinDown, "spin_down.yaml", defaultModelReader(),
                                             {{"integrator.name", integrator}});
        const AnalysisResult r = runAnalysis(spec);
        ASSERT_EQ(r.rows.size(), 2001u);
        // Fewer steps than samples: most samples are interpolated.
        EXPECT_LT(r.statistics.steps, 200);
        // J = 2 kg*m^2: 10 N*m before the feed (-5 rad/s^2), 10 + 20*1 after (-15 rad/s^2).
        for (std::size_t i = 0; i < r.rows.size(); ++i) {
            const double t = r.value(i, "time");
            // The switching instant's sample is the state just before it.
            const double omega = t <= 1 ? 100 - 5 * t : 95 - 15 * (t - 1);
            const double theta = t <= 1 ? 100 * t - 2.5 * t * t : 97.5 + 95 * (t - 1) - 7.5 * (t - 1) * (t - 1);
            EXPECT_NEAR(r.value(i, "shaft.speed"), omega, tolerance * 100) << "t = " << t;
            EXPECT_NEAR(r.value(i, "shaft.angle"), theta, tolerance * 200) << "t = " << t;
            EXPECT_NEAR(r.value(i, "load.torque"), t <= 1 ? 10 : 30, tolerance * 30) << "t = " << t;
        }
    }
}

}  // namespace
}  // namespace milldyn
