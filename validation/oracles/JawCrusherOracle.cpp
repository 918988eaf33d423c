#include "validation/oracles/JawCrusherOracle.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace milldyn::oracle {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

FourierSeries halfSinePulseSeries(const HalfSinePulse& p, int harmonics) {
    FourierSeries f;
    const double P = p.peak, w = p.width, alpha = kPi / w;
    f.mean = P * w / (kPi * kPi);
    for (int k = 1; k <= harmonics; ++k) {
        double c, s;
        if (std::abs(alpha - k) < 1e-12) {
            c = 0;
            s = P / 2;
        } else {
            const double d = alpha * alpha - double(k) * k;
            c = P / kPi * alpha * (1 + std::cos(k * w)) / d;
            s = P / kPi * alpha * std::sin(k * w) / d;
        }
        f.cosine.push_back(c * std::cos(k * p.start) - s * std::sin(k * p.start));
        f.sine.push_back(c * std::sin(k * p.start) + s * std::cos(k * p.start));
    }
    return f;
}

double halfSinePulseTailBound(const HalfSinePulse& p, int harmonics) {
    const double alpha = kPi / p.width;
    double sum = 0;
    // Terms beyond 10^7 add less than (P/π)·4α/10^7.
    for (int k = harmonics + 1; k <= 10000000; ++k) {
        if (k <= alpha) continue;
        sum += 2 * (p.peak / kPi) * 2 * alpha / (double(k) * k - alpha * alpha);
    }
    return sum + p.peak / kPi * 4 * alpha / 1e7;
}

double halfSinePulseWorkPerStroke(const HalfSinePulse& p, int n) { return 2 * p.peak * p.width / (kPi * n); }

double flywheelEnergySwing(const FlywheelCheck& c) {
    const double P = c.pulse.peak, w = c.pulse.width;
    const double a0 = P * w / (kPi * kPi);
    auto E = [&](double u) { return a0 * u - P * w / kPi * (1 - std::cos(kPi * u / w)); };
    const double u1 = w / kPi * std::asin(std::min(1.0, a0 / P));
    const double u2 = w - u1;
    return (E(u1) - E(u2)) / c.cyclesPerRevolution;
}

double flywheelSpeedFluctuationTextbook(const FlywheelCheck& c) {
    return flywheelEnergySwing(c) / (c.inertia * c.meanSpeed * c.meanSpeed);
}

double flywheelSpeedFluctuationDamped(const FlywheelCheck& c, int harmonics, int points) {
    const FourierSeries f = halfSinePulseSeries(c.pulse, harmonics);
    const double nu = c.cyclesPerRevolution * c.meanSpeed;
    double lo = 0, hi = 0;
    for (int i = 0; i < points; ++i) {
        const double psi = 2 * kPi * i / points;
        double dw = 0;
        for (int k = 1; k <= harmonics; ++k) {
            const std::complex<double> amp(f.cosine[k - 1], -f.sine[k - 1]);
            const std::complex<double> z = -amp * std::exp(std::complex<double>(0, k * psi)) /
                                           std::complex<double>(c.driveSlope, k * nu * c.inertia);
            dw += z.real();
        }
        lo = i == 0 ? dw : std::min(lo, dw);
        hi = i == 0 ? dw : std::max(hi, dw);
    }
    return (hi - lo) / c.meanSpeed;
}

double breakawayThreshold(double motorTorqueAtStandstill, double beltRatio) {
    return motorTorqueAtStandstill * beltRatio;
}

}  // namespace milldyn::oracle
