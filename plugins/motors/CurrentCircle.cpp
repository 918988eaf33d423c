#include "plugins/motors/CurrentCircle.h"
#include "plugins/scene/Format.h"

#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn {
namespace {

std::string number(double v) { return formatNumber(v); }

/// Per-unit current at slip s on a circle (diameter d, magnetising m, slip scale sc).
std::complex<double> circleCurrent(double s, double d, double m, double sc) {
    // D·(ρ − j)/(1 + ρ²) with ρ = sc/s, times s²/s²: finite at s = 0.
    const double den = s * s + sc * sc;
    return {d * sc * s / den, -m - d * s * s / den};
}

}  // namespace

CurrentCircle::CurrentCircle(const CurrentCircleParams& p) : m_params(p) {
    const double sn = p.ratedSlip, c = p.ratedPowerFactor, k = p.lockedRotorRatio;
    if (!(std::isfinite(sn) && sn > 0 && sn < 1)) throw std::invalid_argument("rated slip must lie in (0, 1)");
    if (!(std::isfinite(p.ratedCurrent) && p.ratedCurrent > 0))
        throw std::invalid_argument("rated current must be finite and > 0");
    if (!(std::isfinite(c) && c > 0 && c < 1)) throw std::invalid_argument("rated power factor must lie in (0, 1)");
    if (!(std::isfinite(k) && k > 1))
        throw std::invalid_argument("locked-rotor current must exceed the rated current (ratio > 1)");
    const double sigma = std::sqrt(1 - c * c);
    auto lockedRotor = [&](double u) {
        const double d = c * (1 + u * u) / u;
        return std::abs(circleCurrent(1.0, d, sigma - c / u, u * sn));
    };
    double lo = c / sigma, hi = 1 / sn;
    const double kLow = lo < hi ? lockedRotor(lo) : NAN, kHigh = lo < hi ? lockedRotor(hi) : NAN;
    if (!(kLow <= k && k <= kHigh))
        throw std::invalid_argument("no circle diagram through these data: with rated slip " + number(sn) +
                                    " and power factor " + number(c) + " the locked-rotor current ratio must lie in [" +
                                    number(kLow) + ", " + number(kHigh) + "] (magnetising current >= 0, circle slip <= 1)");
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (lockedRotor(mid) < k ? lo : hi) = mid;
    }
    const double u = std::abs(lockedRotor(lo) - k) <= std::abs(lockedRotor(hi) - k) ? lo : hi;
    m_diameter = c * (1 + u * u) / u;
    m_magnetising = sigma - c / u;
    m_circleSlip = u * sn;
}

double CurrentCircle::current(double s) const {
    return std::abs(circleCurrent(s, m_diameter, m_magnetising, m_circleSlip)) * m_params.ratedCurrent;
}

double CurrentCircle::lockedRotorPowerFactor() const {
    const std::complex<double> i = circleCurrent(1.0, m_diameter, m_magnetising, m_circleSlip);
    return i.real() / std::abs(i);
}

double CurrentCircle::calcLockedRotorTorqueRatio() const {
    // Torque ∝ the air-gap power = the in-phase part of the rotor current.
    const double u = m_circleSlip / m_params.ratedSlip, r1 = m_circleSlip;
    return (r1 / (1 + r1 * r1)) * ((1 + u * u) / u);
}

}  // namespace milldyn
