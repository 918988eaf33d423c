// Tests of Clutch (plugins/transmissions/Clutch.h) and Brake
// (plugins/brakes/Brake.h): torques by hand from the class comments.
#include <gtest/gtest.h>

#include <cmath>

#include "plugins/brakes/Brake.h"
#include "plugins/transmissions/Clutch.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

TEST(Clutch, SlippingTransmitsItsRampedCapacityFromFastToSlow) {
    test::ShaftSystem sys;
    auto a = sys.addShaft(2.0), b = sys.addShaft(1.0);
    ClutchParams p;
    p.capacity = 300;
    p.engageTime = 1;
    p.rampTime = 2;
    auto* c = new Clutch(a, b, p);
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
    EXPECT_THROW(Clutch(a, b, p), std::invalid_argument);
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

}  // namespace
}  // namespace milldyn
