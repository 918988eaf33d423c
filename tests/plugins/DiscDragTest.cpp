// DiscDrag on its own: torques against hand-evaluated eq (1) and the
// turbulent law, the sign, the axis (the body's own z, whatever its
// orientation), the probes and energy flow a scene gets, and bad input.

#include "plugins/loads/DiscDrag.h"
#include "plugins/scene/Scene.h"
#include "tests/plugins/ShaftFixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRoundoff = 1e-12;

// DiscDrag applies a body torque (not a mobility force): on a shaft of polar
// moment J about its pin, J·u̇ is that torque (the fixture's contract).
constexpr double kJ = 0.01;  // [kg*m^2]
double torqueOf(test::ShaftSystem& sys, const SimTK::State& s, const SimTK::MobilizedBody& shaft) {
    return kJ * test::shaftAcceleration(sys.system(), s, shaft);
}

DiscDragParams water(DiscDragParams::Law law) {
    DiscDragParams p;
    p.law = law;
    p.density = 1000;
    p.viscosity = 1e-6;
    p.radius = 0.1;
    p.discs = 1;
    return p;
}

TEST(DiscDrag, LaminarTorqueByHandAndOpposingRotation) {
    // T = 0.616π·ρ·r⁴·k·√(ν·ω³); ρ = 1000, r = 0.1, ν = 1e-6, ω = 100:
    // ν·ω³ = 1, T = 0.616π·1000·1e-4 = 0.0616π N*m.
    test::ShaftSystem sys;
    auto shaft = sys.addShaft(kJ);
    auto* impl = new DiscDrag(shaft, water(DiscDragParams::Law::Laminar));
    SimTK::Force::Custom force(sys.forces(), impl);
    SimTK::State s = sys.defaultState();
    test::setShaft(s, shaft, 0, 100);
    const double T = 0.0616 * kPi;
    EXPECT_NEAR(torqueOf(sys, s, shaft), -T, T * kRoundoff);
    EXPECT_NEAR(impl->calcPower(s), T * 100, T * 100 * kRoundoff);
    EXPECT_NEAR(impl->calcReynolds(s), 100 * 0.01 / 1e-6, 1e-6);
    test::setShaft(s, shaft, 0, -100);
    EXPECT_NEAR(torqueOf(sys, s, shaft), T, T * kRoundoff);
    EXPECT_NEAR(impl->calcPower(s), T * 100, T * 100 * kRoundoff);  // taken from the shaft either way
    test::setShaft(s, shaft, 0, 0);
    EXPECT_EQ(torqueOf(sys, s, shaft), 0.0);
}

TEST(DiscDrag, TurbulentTorqueByHandScalesWithDiscCount) {
    // Re = 1e6: T = 0.073·1000·1e4·1e-5·10^-1.2 per disc.
    test::ShaftSystem sys;
    auto shaft = sys.addShaft(kJ);
    DiscDragParams p = water(DiscDragParams::Law::Turbulent);
    p.discs = 3;
    auto* impl = new DiscDrag(shaft, p);
    SimTK::Force::Custom force(sys.forces(), impl);
    SimTK::State s = sys.defaultState();
    test::setShaft(s, shaft, 0, 100);
    const double T = 3 * 0.073 * 100 * std::pow(10.0, -1.2);
    EXPECT_NEAR(torqueOf(sys, s, shaft), -T, T * kRoundoff);
}

TEST(DiscDrag, ActsAboutTheBodysOwnAxis) {
    // A pin whose axis is ground x (joint frame turned about y): the body's z
    // is ground x, and the drag torque must be along −x in ground.
    test::ShaftSystem sys;
    const SimTK::Body::Rigid body(SimTK::MassProperties(1, SimTK::Vec3(0), SimTK::Inertia(0.005, 0.005, 0.01)));
    const SimTK::Transform turned(SimTK::Rotation(kPi / 2, SimTK::YAxis), SimTK::Vec3(0));
    SimTK::MobilizedBody::Pin pin(sys.matter().updGround(), turned, body, SimTK::Transform());
    auto* impl = new DiscDrag(pin, water(DiscDragParams::Law::Laminar));
    SimTK::Force::Custom force(sys.forces(), impl);
    SimTK::State s = sys.defaultState();
    pin.setOneU(s, SimTK::MobilizerUIndex(0), 100);
    sys.system().realize(s, SimTK::Stage::Velocity);
    EXPECT_NEAR(impl->calcSpeed(s), 100, 1e-12);
    SimTK::Vector_<SimTK::SpatialVec> bodyForces(sys.matter().getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
    SimTK::Vector_<SimTK::Vec3> particleForces;
    SimTK::Vector mobilityForces(s.getNU(), 0.0);
    impl->calcForce(s, bodyForces, particleForces, mobilityForces);
    const SimTK::Vec3 torque = bodyForces[pin.getMobilizedBodyIndex()][0];
    const double T = 0.0616 * kPi;
    EXPECT_NEAR(torque[0], -T, T * kRoundoff);
    EXPECT_NEAR(torque[1], 0, T * kRoundoff);
    EXPECT_NEAR(torque[2], 0, T * kRoundoff);
}

TEST(DiscDrag, SceneGetsProbesAndALoadFlow) {
    Scene scene;
    const SimTK::Body::Rigid body(SimTK::MassProperties(1, SimTK::Vec3(0), SimTK::Inertia(0.005, 0.005, 0.01)));
    SimTK::MobilizedBody::Pin pin(scene.matter().updGround(), SimTK::Transform(), body, SimTK::Transform());
    scene.addBody("rotor", pin);
    addDiscDrag(scene, "drag", pin, water(DiscDragParams::Law::Laminar));
    scene.system().realizeTopology();
    SimTK::State s = scene.system().getDefaultState();
    pin.setOneU(s, SimTK::MobilizerUIndex(0), 100);
    scene.system().realize(s, SimTK::Stage::Velocity);
    const double T = 0.0616 * kPi;
    int found = 0;
    for (const auto& p : scene.probes()) {
        if (p.name == "drag.torque") {
            EXPECT_NEAR(p.value(s), T, T * kRoundoff);
            ++found;
        }
        if (p.name == "drag.power") {
            EXPECT_NEAR(p.value(s), 100 * T, 100 * T * kRoundoff);
            ++found;
        }
        if (p.name == "drag.reynolds") {
            EXPECT_NEAR(p.value(s), 1e6, 1e-6);  // 100·0.1²/1e-6
            ++found;
        }
    }
    EXPECT_EQ(found, 3);
    ASSERT_EQ(scene.energyFlows().size(), 1u);
    EXPECT_EQ(scene.energyFlows()[0].kind, EnergyFlow::Kind::Load);
    EXPECT_NEAR(scene.energyFlows()[0].power(s), 100 * T, 100 * T * kRoundoff);
}

TEST(DiscDrag, RejectsBadParameters) {
    test::ShaftSystem sys;
    auto shaft = sys.addShaft(0.01);
    for (int which = 0; which < 4; ++which) {
        DiscDragParams p = water(DiscDragParams::Law::Laminar);
        if (which == 0) p.density = 0;
        if (which == 1) p.viscosity = std::nan("");
        if (which == 2) p.radius = -0.1;
        if (which == 3) p.discs = 0;
        EXPECT_THROW(DiscDrag(shaft, p), std::invalid_argument) << which;
    }
}

}  // namespace
}  // namespace milldyn
