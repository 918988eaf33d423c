// Checks of validation/oracles/JawCrusherOracle against textbook special
// cases and against brute-force numerics written here.
#include "validation/oracles/JawCrusherOracle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(JawCrusherOracleTest, HalfWavePulseIsTheRectifiedSineSeries) {
    // w = π: P/π + (P/2) sin u − Σ_{k even} 2P/(π(k² − 1)) cos ku (a textbook series)
    const double P = 1000;
    const auto f = oracle::halfSinePulseSeries({P, 0.0, kPi}, 8);
    EXPECT_NEAR(f.mean, P / kPi, 1e-12 * P);
    EXPECT_NEAR(f.sine[0], P / 2, 1e-12 * P);
    EXPECT_NEAR(f.cosine[0], 0.0, 1e-12 * P);
    for (int k = 2; k <= 8; ++k) {
        const double expected = k % 2 == 0 ? -2 * P / (kPi * (k * k - 1)) : 0.0;
        EXPECT_NEAR(f.cosine[k - 1], expected, 1e-12 * P) << k;
        EXPECT_NEAR(f.sine[k - 1], 0.0, 1e-12 * P) << k;
    }
}

TEST(JawCrusherOracleTest, CoefficientsMatchBruteForceIntegrals) {
    const oracle::HalfSinePulse p{700, 1.1, 2.3};
    const auto f = oracle::halfSinePulseSeries(p, 6);
    const int N = 200000;
    for (int k = 1; k <= 6; ++k) {
        double c = 0, s = 0;
        for (int i = 0; i < N; ++i) {
            const double u = p.width * (i + 0.5) / N;
            const double g = p.peak * std::sin(kPi * u / p.width);
            c += g * std::cos(k * (u + p.start)) * p.width / N / kPi;
            s += g * std::sin(k * (u + p.start)) * p.width / N / kPi;
        }
        EXPECT_NEAR(f.cosine[k - 1], c, 1e-6 * p.peak) << k;
        EXPECT_NEAR(f.sine[k - 1], s, 1e-6 * p.peak) << k;
    }
    EXPECT_NEAR(oracle::halfSinePulseWorkPerStroke(p, 2), 2 * p.peak * p.width / kPi / 2, 1e-12 * p.peak);
}

TEST(JawCrusherOracleTest, UndampedHarmonicBalanceTendsToTheEnergyMethod) {
    oracle::FlywheelCheck c;
    c.pulse = {6000, 0, kPi};
    c.inertia = 870;
    c.meanSpeed = 26.5;
    const double textbook = oracle::flywheelSpeedFluctuationTextbook(c);
    EXPECT_NEAR(oracle::flywheelSpeedFluctuationDamped(c, 2000, 8192), textbook, 2e-3 * textbook);
    // ΔE of the half-wave pulse by hand: P·((u1 − u2)/π + 2 cos u1), u1 = asin(1/π), u2 = π − u1: 1.10220 P
    EXPECT_NEAR(oracle::flywheelEnergySwing(c) / 6000, 1.10220, 1e-5);
    // a damper only lowers it
    c.driveSlope = 8000;
    EXPECT_LT(oracle::flywheelSpeedFluctuationDamped(c, 200), textbook);
}

}  // namespace
}  // namespace milldyn
