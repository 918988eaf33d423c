// PlanetaryMotorStartOracle::calcRunningLoads (validation/oracles/
// PlanetaryGearStartOracle.h): the journal loads of the running mill with the
// belt's pull on A, checked against closed forms written here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "validation/oracles/PlanetaryGearStartOracle.h"

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The fixed point converges geometrically with ratio k·s/r2 ~ 1e-4.
constexpr double kFixedPointRelTol = 1e-12;

PlanetaryGearParameters mill(double f, double g) {
    PlanetaryGearParameters p;  // docs/planetary_gear.md's 500 x 1000 mm mill
    p.drumRadius = 0.25;
    p.drumLength = 1.0;
    p.wallThickness = 0.005;
    p.shellDensity = 7850;
    p.chargeDensity = 4800;
    p.sunRadius = 0.5;
    p.carrierMass = 250;
    p.carrierJournalDiameter = 0.125;
    p.drumJournalDiameter = 0.1;
    p.frictionCoefficient = f;
    p.carrierFriction = CarrierFrictionReading::kTotalLoadHalfD;
    p.gravity = g;
    return p;
}

CatalogueMotor motor() {
    CatalogueMotor m;
    m.ratedTorque = 1300;
    m.ratedSpeed = 1485 * kPi / 30;
    m.synchronousSpeed = 1500 * kPi / 30;
    m.lockedRotorRatio = 2.0;
    m.breakdownRatio = 2.5;
    return m;
}

VBelt belt(double pretension) {
    VBelt b;
    b.driverRadius = 0.1575;
    b.drivenRadius = 0.69615;
    b.centreDistance = 1.6;
    b.pretension = pretension;
    b.frictionCoefficient = 0.512;
    return b;  // motor straight below A
}

TEST(PlanetaryMotorStartOracle, RunningLoadsAtRestWithoutGravityAreTheBeltPullAndItsFriction) {
    // ω = 0, g = 0: the mill loads nothing, A carries the belt's pull
    // P = 2T0·cos β·u + (M/r2)·sin β·n alone, and M = k|P|, k = f·d_A/2:
    // M = k·2T0·cos β/√(1 − (k·sin β/r2)²).
    const double f = 0.01, T0 = 11200;
    const PlanetaryMotorStartOracle o(mill(f, 0), motor(), belt(T0), 3.5);
    const VBelt b = belt(T0);
    const double s = (b.drivenRadius - b.driverRadius) / b.centreDistance, cb = std::sqrt(1 - s * s);
    const double k = f * 0.125 / 2;
    const double M = k * 2 * T0 * cb / std::sqrt(1 - std::pow(k * s / b.drivenRadius, 2));
    const PlanetaryRunningLoads L = o.calcRunningLoads(0.0, 0.3);
    EXPECT_NEAR(L.driveTorque, M, kFixedPointRelTol * M);
    // u = (0, −1) (motor below), n = z × u = (1, 0); the ground takes −P.
    EXPECT_NEAR(L.journalA.x(), -M / b.drivenRadius * s, kFixedPointRelTol * 2 * T0);
    EXPECT_NEAR(L.journalA.y(), 2 * T0 * cb, kFixedPointRelTol * 2 * T0);
    EXPECT_EQ(L.journalB1.norm(), 0.0);
    EXPECT_EQ(L.journalB2.norm(), 0.0);
}

TEST(PlanetaryMotorStartOracle, RunningLoadsWithoutBeltAreTheMillsSteadyKinetostatics) {
    // T0 = 0, f = 0: A's load is the mill's own less the belt's cross pull
    // (M/r2)·sin β·n that carries the mill's torque M; the charges rigid with their
    // drums sit at −π/2 + κφ; the frictionless torque averages to zero over a
    // turn (a conservative exchange, PlanetaryGearOracle.h) though it swings.
    const PlanetaryGearParameters p = mill(0, 9.80665);
    const PlanetaryGearOracle gear(p);
    const PlanetaryMotorStartOracle o(p, motor(), belt(0), 3.5);
    const double w = 35.1, phi = 0.7, kappa = gear.calcSpeedRatio();
    PlanetaryGearMotionState st;
    st.carrierAngle = phi;
    st.carrierRate = w;
    st.chargeDirection = {{-kPi / 2 + kappa * phi, -kPi / 2 + kappa * phi}};
    const PlanetaryGearLoads ref = gear.calcLoads(st, ChargeMotion::kRotatesWithDrum);
    const PlanetaryRunningLoads L = o.calcRunningLoads(w, phi);
    const VBelt b = belt(0);
    const double s = (b.drivenRadius - b.driverRadius) / b.centreDistance;
    const Eigen::Vector2d cross(ref.driveTorque / b.drivenRadius * s, 0.0);  // n = (1, 0)
    EXPECT_EQ(L.driveTorque, ref.driveTorque);
    EXPECT_NEAR((L.journalA - (ref.carrierBearingForce - cross)).norm(), 0.0, 1e-12 * ref.carrierBearingForce.norm());
    EXPECT_EQ((L.journalB1 - ref.drums[0].bearingForce).norm(), 0.0);
    EXPECT_EQ((L.journalB2 - ref.drums[1].bearingForce).norm(), 0.0);
    double swing = 0;
    for (int j = 0; j < 36; ++j) swing = std::max(swing, std::abs(o.calcRunningLoads(w, 2 * kPi * j / 36).driveTorque));
    ASSERT_GT(swing, 1e3);
    EXPECT_LT(std::abs(o.calcCarrierLoadTorque(w)), 1e-9 * swing);
}

}  // namespace
}  // namespace milldyn::oracles
