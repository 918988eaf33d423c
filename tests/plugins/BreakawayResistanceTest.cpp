// Tests of BreakawayResistance (plugins/loads/BreakawayResistance.h): the
// law written out afresh, and breakaway passed or not against the closed
// form (a constant drive torque T passes iff T > M_s).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "plugins/loads/BreakawayResistance.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

using test::ShaftSystem;

BreakawayResistanceParams params() {
    BreakawayResistanceParams p;
    p.staticTorque = 5000;
    p.runningTorque = 1200;
    p.viscousCoefficient = 3;
    p.releaseSpeed = 0.2;
    p.smoothingSpeed = 0.002;
    return p;
}

TEST(BreakawayResistanceTest, LawIsStribeckWithTanhSign) {
    const BreakawayResistanceParams p = params();
    ShaftSystem rig;
    auto shaft = rig.addShaft(1.0);
    BreakawayResistance r(shaft, p);
    for (double w : {-3.0, -0.2, -0.01, 0.0, 0.001, 0.01, 0.1, 0.2, 0.5, 2.0, 30.0}) {
        const double expected =
            (p.runningTorque + (p.staticTorque - p.runningTorque) * std::exp(-(w / p.releaseSpeed) * (w / p.releaseSpeed))) *
                std::tanh(w / p.smoothingSpeed) +
            p.viscousCoefficient * w;
        EXPECT_NEAR(r.torqueAtSpeed(w), expected, 1e-12 * p.staticTorque) << "ω = " << w;
    }
    EXPECT_EQ(r.torqueAtSpeed(0.0), 0.0);  // no work on a standing shaft
    // released: the running law beyond a few release speeds
    EXPECT_NEAR(r.torqueAtSpeed(2.0), p.runningTorque + p.viscousCoefficient * 2.0, 1e-9 * p.staticTorque);
}

/// A shaft from rest under a constant drive torque T and the breakaway:
/// its speed after `t` seconds.
double speedAfter(double driveTorque, double t) {
    ShaftSystem rig;
    auto shaft = rig.addShaft(10.0);
    auto* r = new BreakawayResistance(shaft, params());
    SimTK::Force::Custom force(rig.forces(), r);
    SimTK::Force::MobilityConstantForce drive(rig.forces(), shaft, 0, driveTorque);
    SimTK::State s = rig.defaultState();
    std::vector<double> work;
    const SimTK::State end = test::integrateWithQuadrature(rig.system(), s, t, 20, {}, work);
    return test::shaftSpeed(end, shaft);
}

TEST(BreakawayResistanceTest, PassesIffDriveTorqueExceedsStaticTorque) {
    const BreakawayResistanceParams p = params();
    // Closed form: from rest the shaft breaks away iff T > M_s. The
    // regularised law peaks 2e^(−2a) + (1 − M_r/M_s)(a·ω_s/ω_r)² below M_s
    // (< 0.5 % here), so ±5 % of M_s sits clearly on either side.
    const double passed = speedAfter(1.05 * p.staticTorque, 2.0);
    const double held = speedAfter(0.95 * p.staticTorque, 2.0);
    EXPECT_GT(passed, 10 * p.releaseSpeed) << "1.05 M_s should break away";
    EXPECT_LT(held, p.releaseSpeed / 10) << "0.95 M_s should be held";
    // held: creeping where M_s·tanh(ω/ω_s) ≈ T, ω ≈ ω_s·atanh(0.95)
    EXPECT_NEAR(held, p.smoothingSpeed * std::atanh(0.95), 0.05 * p.smoothingSpeed * std::atanh(0.95));
}

TEST(BreakawayResistanceTest, StallReasonNamesTheBreakawayOnlyWhileHeld) {
    ShaftSystem rig;
    auto shaft = rig.addShaft(1.0);
    auto* r = new BreakawayResistance(shaft, params());
    SimTK::Force::Custom force(rig.forces(), r);
    SimTK::State s = rig.defaultState();
    test::setShaft(s, shaft, 0, 0.003);
    EXPECT_NE(r->stallReason("chamber", s).find("breakaway of chamber was not passed"), std::string::npos);
    test::setShaft(s, shaft, 0, 0.5);
    EXPECT_EQ(r->stallReason("chamber", s), "");
}

TEST(BreakawayResistanceTest, BadParametersAreRefusedNamingTheKey) {
    ShaftSystem rig;
    auto shaft = rig.addShaft(1.0);
    BreakawayResistanceParams p = params();
    p.staticTorque = 100;  // below running
    test::expectInvalidArgumentNaming("static_torque", [&] { BreakawayResistance r(shaft, p); });
    p = params();
    p.smoothingSpeed = p.releaseSpeed / 5;
    test::expectInvalidArgumentNaming("smoothing_speed", [&] { BreakawayResistance r(shaft, p); });
    p = params();
    p.releaseSpeed = 0;
    test::expectInvalidArgumentNaming("release_speed", [&] { BreakawayResistance r(shaft, p); });
}

}  // namespace
}  // namespace milldyn
