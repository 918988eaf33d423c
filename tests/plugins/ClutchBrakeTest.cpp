// Tests of Clutch (plugins/transmissions/Clutch.h) and Brake
// (plugins/brakes/Brake.h): torques by hand from the class comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "driver/analyses/Analysis.h"
#include "driver/ModelFile.h"
#include "plugins/brakes/Brake.h"
#include "plugins/transmissions/Clutch.h"
#include "tests/plugins/ShaftFixture.h"
#include "validation/cases/ValidationCases.h"
#include "validation/oracles/TumblingMillOracle.h"

namespace milldyn {
namespace {

TEST(Clutch, SlippingTransmitsItsRampedCapacityFromFastToSlow) {
    test::ShaftSystem sys;
    auto a = sys.addShaft(2.0), b = sys.addShaft(1.0);
    ClutchParams p;
    p.capacity = 300;
    p.engageTime = 1;
    p.rampTime = 2;
    auto* c = new Clutch(sys.forces(), a, b, p);
    SimTK::Force::Custom force(sys.forces(), c);
    SimTK::State s = sys.defaultState();
    test::setShaft(s, a, 0, 100);
    test::setShaft(s, b, 0, 0);
    s.setTime(0.5);
    sys.system().realize(s, SimTK::Stage::Dynamics);
    EXPECT_EQ(c->calcTorque(s), 0.0);  // not yet engaging
    s.setTime(2.0);                    // half way up the ramp: 150 N*m
    sys.system().realize(s, SimTK::Stage::Acceleration);
    EXPECT_NEAR(c->calcTorque(s), 150.0, 1e-9);  // tanh(1e5) = 1
    EXPECT_NEAR(a.getOneUDot(s, SimTK::MobilizerUIndex(0)), -150.0 / 2, 1e-9);
    EXPECT_NEAR(b.getOneUDot(s, SimTK::MobilizerUIndex(0)), 150.0 / 1, 1e-9);
    p.rampTime = 0;  // a ramp of zero length
    EXPECT_THROW(Clutch(sys.forces(), a, b, p), std::invalid_argument);
}

TEST(Brake, BrakeOpposesRotationAndBackstopHoldsOnlyBackwards) {
    test::ShaftSystem sys;
    auto a = sys.addShaft(1.0);
    BrakeParams p;
    p.capacity = 100;
    p.applyTime = 1;
    p.rampTime = 0.5;
    const Brake brake(a, p);
    EXPECT_EQ(brake.torqueAt(10, 0.5), 0.0);
    EXPECT_NEAR(brake.torqueAt(10, 1.25), -50.0, 1e-9);
    EXPECT_NEAR(brake.torqueAt(-10, 2.0), 100.0, 1e-9);
    p.mode = BrakeParams::Mode::Backstop;
    const Brake backstop(a, p);
    EXPECT_EQ(backstop.torqueAt(10, 0.0), 0.0);
    EXPECT_NEAR(backstop.torqueAt(-10, 0.0), 100.0, 1e-9);
    // Creep: a held load of 76 N*m turns back at ω_reg·atanh(0.76) = 1e-3·0.9962 rad/s.
    EXPECT_NEAR(backstop.torqueAt(-1e-3 * std::atanh(0.76), 0.0), 76.0, 1e-9);
}

// The frozen-charge drum after its inching drive trips at 1 s: without a
// backstop the charge rolls it back and it swings (the speed changes sign
// again and again); with one it never turns back faster than the backstop's
// creep and the backstop carries the charge's moment.
TEST(Backstop, AFrozenChargeRollsTheDrumBackUnlessABackstopHoldsIt) {
    const AnalysisResult free = runModelFile(modelsDirectory() + "/start_bench_rollback.yaml", {});
    int reversals = 0;
    double slowest = 0;
    for (std::size_t i = 1; i < free.rows.size(); ++i) {
        const double w0 = free.value(i - 1, "drum.speed"), w1 = free.value(i, "drum.speed");
        if (free.value(i, "time") > 1 && (w0 > 0) != (w1 > 0)) ++reversals;
        slowest = std::min(slowest, w1);
    }
    EXPECT_GE(reversals, 4);    // ~2.7 s swings over the 7 s after the trip
    EXPECT_LT(slowest, -1.0);   // rolls back at more than 1 rad/s through the bottom
    const AnalysisResult held = runModelFile(modelsDirectory() + "/start_bench_backstop.yaml", {});
    double heldSlowest = 0;
    for (std::size_t i = 0; i < held.rows.size(); ++i) heldSlowest = std::min(heldSlowest, held.value(i, "drum.speed"));
    // Creep of the regularised backstop: 1e-3·atanh(T/60 kN*m) rad/s, T < 30 kN*m (the charge's W).
    EXPECT_GT(heldSlowest, -1e-3 * std::atanh(0.5));
    // m·g·r_c·sin α at the held angle; m, r_c of the 20 % segment (2 m x 1.5 m, 4650 kg/m^3) in closed form.
    const oracles::CircularSegmentCharge seg{1.0, 1.5, 4650, 0.2};
    const double W = oracles::segmentMass(seg) * 9.81 * oracles::segmentCentroidDistance(seg);
    // Over the last second (single samples scatter by ~6e-6: the backstop's
    // torque answers the speed with the gain 6e7 N*m*s/rad).
    double T = 0, statics = 0;
    for (std::size_t i = held.rows.size() - 1000; i < held.rows.size(); ++i) {
        T += -held.value(i, "backstop.torque") / 1000;
        statics += W * std::sin(M_PI / 6 + held.value(i, "drum.angle")) / 1000;
    }
    EXPECT_GT(T, 0.5 * W * std::sin(M_PI / 6));  // it carries the charge
    EXPECT_NEAR(T, statics, 1e-6 * T);
}

}  // namespace
}  // namespace milldyn
