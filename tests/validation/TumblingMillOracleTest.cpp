// The tumbling-mill oracle against independent computations: the segment's
// area, centroid and polar moment by quadrature over the cross-section, the
// Kloss running speed by substituting it back into the torque law, the
// geared chain against the 2-mass formula with the ratio² reduction.

#include "validation/oracles/TumblingMillOracle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Midpoint quadrature over the segment below the chord y = −R cos(θ/2)…
// i.e. the points of the disc with y < −R cos(θ/2) (the segment hangs).
struct Quadrature {
    double area = 0, firstMoment = 0, polar = 0;
};
Quadrature integrate(double R, double theta, int n) {
    Quadrature q;
    const double chord = -R * std::cos(theta / 2);
    const double h = 2 * R / n;
    for (int i = 0; i < n; ++i) {
        const double y = -R + (i + 0.5) * h;
        if (y >= chord) break;
        const double half = std::sqrt(R * R - y * y);
        // Exact in x for each strip: ∫ dx = 2·half, ∫ x² dx = 2·half³/3.
        q.area += 2 * half * h;
        q.firstMoment += -y * 2 * half * h;
        q.polar += (y * y * 2 * half + 2 * half * half * half / 3) * h;
    }
    return q;
}

TEST(TumblingMillOracle, SegmentAgainstQuadrature) {
    for (const double fill : {0.1, 0.3, 0.5, 0.7}) {
        const CircularSegmentCharge c{1.5, 4.0, 4800.0, fill};
        const double theta = segmentCentralAngle(fill);
        EXPECT_NEAR(theta - std::sin(theta), 2 * kPi * fill, 1e-13) << fill;
        const Quadrature q = integrate(1.5, theta, 400000);
        EXPECT_NEAR(segmentArea(c), q.area, 1e-5 * q.area) << fill;
        EXPECT_NEAR(segmentCentroidDistance(c), q.firstMoment / q.area, 1e-5) << fill;
        EXPECT_NEAR(segmentAxisInertia(c), 4800.0 * 4.0 * q.polar, 1e-5 * 4800.0 * 4.0 * q.polar) << fill;
        EXPECT_NEAR(segmentMass(c), 4800.0 * 4.0 * q.area, 1e-5 * 4800.0 * 4.0 * q.area) << fill;
    }
    // Half full: the half disc, centroid 4R/(3π), polar moment ρL πR⁴/4.
    const CircularSegmentCharge half{1.5, 4.0, 4800.0, 0.5};
    EXPECT_NEAR(segmentCentroidDistance(half), 4 * 1.5 / (3 * kPi), 1e-14);
    EXPECT_NEAR(segmentAxisInertia(half), 4800.0 * 4.0 * kPi * std::pow(1.5, 4) / 4, 1e-9);
}

TEST(TumblingMillOracle, TorqueArmAndCriticalSpeed) {
    const CircularSegmentCharge c{1.5, 4.0, 4800.0, 0.3};
    EXPECT_NEAR(torqueArmTorque(c, kPi / 2, 9.81), segmentMass(c) * 9.81 * segmentCentroidDistance(c), 1e-9);
    EXPECT_EQ(torqueArmTorque(c, 0, 9.81), 0.0);
    EXPECT_NEAR(criticalSpeed(3.0, 9.81), std::sqrt(9.81 / 1.5), 1e-15);
}

TEST(TumblingMillOracle, KlossRunningSpeedSolvesTheTorqueLaw) {
    const KlossMotor m{3858.0, 1485 * kPi / 30, 1500 * kPi / 30, 2.2};
    const double sn = (m.synchronousSpeed - m.ratedSpeed) / m.synchronousSpeed;
    const double sk = sn * (2.2 + std::sqrt(2.2 * 2.2 - 1));
    auto torque = [&](double w) {
        const double s = (m.synchronousSpeed - w) / m.synchronousSpeed;
        return 2 * 2.2 * m.ratedTorque / (s / sk + sk / s);
    };
    for (const double T : {500.0, 2826.0, 3858.0, 8000.0}) {
        const double w = klossRunningSpeed(m, T);
        EXPECT_NEAR(torque(w), T, 1e-9 * T) << T;
        EXPECT_GT(w, m.synchronousSpeed * (1 - sk)) << "stable branch " << T;
    }
    EXPECT_NEAR(klossRunningSpeed(m, m.ratedTorque), m.ratedSpeed, 1e-9 * m.ratedSpeed);
    EXPECT_THROW(klossRunningSpeed(m, 2.3 * m.ratedTorque), std::domain_error);
}

TEST(TumblingMillOracle, TwoMassChainIsTheRatioSquaredFormula) {
    const double Ja = 30, Jb = 2.0e5, c = 2.0e5, n = 82;
    const auto w = gearedChainFrequencies({{Ja, Jb}, {c}, {n}});
    ASSERT_EQ(w.size(), 2u);
    EXPECT_LT(w[0], 1e-6);
    const double expected = std::sqrt(c * (Ja + Jb / (n * n)) / (Ja * Jb / (n * n)));
    EXPECT_NEAR(w[1], expected, 1e-10 * expected);
    const auto shapes = gearedChainModeShapes({{Ja, Jb}, {c}, {n}});
    // Elastic mode in referred angles: Ja θa + (Jb/n²) θb = 0.
    EXPECT_NEAR(Ja * shapes[1][0] + Jb / (n * n) * shapes[1][1], 0, 1e-9 * Ja);
}

}  // namespace
}  // namespace milldyn::oracles
