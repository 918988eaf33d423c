#include "plugins/charges/CircularSegment.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace milldyn {
namespace circular_segment {
namespace {

// Below this half-angle the factors come from their series in y = γ²
// (20 terms: the last is below 1e-17 of the first at γ = 1); above it the
// closed forms lose at most a few ulp.
constexpr double kSeriesBelow = 1.0;

// Taylor coefficients in y = γ², from the series of sin (sympy, exact
// rationals printed to 21 digits):
// (2γ − sin 2γ) / (4γ³/3)              = Σ a_k y^k
constexpr double kArea[] = {
    1.00000000000000000000, -0.200000000000000000000, 0.0190476190476190476190, -0.00105820105820105820106,
    0.0000384800384800384800385, -9.86667653334320000987e-7, 1.87936695873203809712e-8,
    -2.76377493931182073105e-10, 3.23248530913663243398e-12, -3.07855743727298327046e-14,
    2.43364224290354408732e-16, -1.62242816193569605821e-18, 9.24460491131450745421e-21,
    -4.55399256715000367202e-23, 1.95870648049462523528e-25, -7.41934272914630770939e-28,
    2.49389671567943116282e-30, -7.48917932636465814661e-33, 2.02137093829005617992e-35,
    -4.93017302021964921932e-38};
// (12γ − 4 sin 2γ − sin 4γ) / (16γ³)    = Σ n_k y^k
constexpr double kAxis[] = {
    1.00000000000000000000, -0.600000000000000000000, 0.209523809523809523810, -0.0455026455026455026455,
    0.00658008658008658008658, -0.000673894007227340560674, 0.0000513255116429719604323,
    -0.00000301887136621030178453, 1.41230515641488607673e-7, -5.38017933410138375295e-9,
    1.70124004354396539778e-10, -4.53663849368907912506e-12, 1.03399158702724527433e-13,
    -2.03742180081917831734e-15, 3.50524178827388713886e-17, -5.31097239905624384488e-19,
    7.14080322312794374802e-21, -8.57754140841377726018e-23, 9.26050354464404618302e-25,
    -9.03463760448147503372e-27};
// k_c / γ² = (n(y)/a(y) − (sin γ/γ)⁶/a(y)²) / γ²   = Σ j_k y^k
// (the y⁰ terms 1 − 1 cancel in the exact series, not in floating point)
constexpr double kCentral[] = {
    0.200000000000000000000, -0.0380952380952380952381, 0.00469841269841269841270,
    -0.000366769738198309626881, 0.0000155464993560231655470, -4.21880294896167912041e-7,
    1.60030465485981025530e-8, 1.03992722195315756474e-10, 2.87554229491839282555e-12,
    -1.27472865911924589878e-12, -1.26062396349633547539e-13, -6.72424735895278684497e-15,
    -8.84467176454795841199e-17, 2.17660128986817697842e-17, 2.56183735295093777628e-18,
    1.57132026830202400634e-19, 4.21966336282095646240e-21, -2.74944607306803294338e-22,
    -4.57586179510916986437e-23, -3.32993485485001893593e-24};

template <std::size_t N>
double horner(const double (&c)[N], double y) {
    double s = 0;
    for (std::size_t k = N; k-- > 0;) s = s * y + c[k];
    return s;
}

/// (2γ − sin 2γ) / (4γ³/3) for γ < kSeriesBelow.
double areaSeries(double g) { return horner(kArea, g * g); }

/// sin γ / γ, 1 at 0.
double sinc(double g) { return g == 0 ? 1.0 : std::sin(g) / g; }

void checkAngle(double g) {
    if (!(g >= 0 && g <= M_PI)) throw std::invalid_argument("circular segment: half-angle must be in [0, pi]");
}

}  // namespace

double calcAreaFactor(double g) {
    checkAngle(g);
    if (g < kSeriesBelow) return 4.0 / 3.0 * g * g * g * areaSeries(g);
    return 2 * g - std::sin(2 * g);
}

double calcCentroidFactor(double g) {
    checkAngle(g);
    if (g < kSeriesBelow) {
        const double s = sinc(g);
        return s * s * s / areaSeries(g);  // 4 γ³ sinc³ / (3 · 4γ³/3 · a)
    }
    const double s = std::sin(g);
    return 4 * s * s * s / (3 * (2 * g - std::sin(2 * g)));
}

double calcAxisInertiaFactor(double g) {
    checkAngle(g);
    if (g < kSeriesBelow) return horner(kAxis, g * g) / areaSeries(g);  // 16γ³ n / (12 · 4γ³/3 · a)
    return (12 * g - 4 * std::sin(2 * g) - std::sin(4 * g)) / (12 * (2 * g - std::sin(2 * g)));
}

double calcCentralInertiaFactor(double g) {
    checkAngle(g);
    if (g < kSeriesBelow) return g * g * horner(kCentral, g * g);
    const double c = calcCentroidFactor(g);
    return calcAxisInertiaFactor(g) - c * c;
}

double calcFillFraction(double g) { return calcAreaFactor(g) / (2 * M_PI); }

double calcHalfAngleForFill(double fill) {
    if (!(fill > 0 && fill <= 1)) throw std::invalid_argument("circular segment: fill must be in (0, 1]");
    if (fill == 1) return M_PI;
    // Above half full, γ is ill-conditioned in the fill (dγ/df = π / 2 sin²γ)
    // but π − γ is the half-angle of the empty segment, of fill 1 − f (exact
    // in floating point for f ≥ ½).
    if (fill > 0.5) return M_PI - calcHalfAngleForFill(1 - fill);
    const double target = 2 * M_PI * fill;  // 2γ − sin 2γ
    // Small fills: γ = (3 target / (4 a(γ)))^⅓ is a contraction (a ≈ 1 − γ²/5);
    // written with the series, it never forms γ³, which would underflow.
    double g = std::cbrt(0.75 * target);
    if (g < 0.1) {
        for (int i = 0; i < 60; ++i) {
            const double next = std::cbrt(0.75 * target / areaSeries(g));
            if (next == g) break;
            g = next;
        }
        return g;
    }
    // Otherwise Newton on F(γ) = 2γ − sin 2γ − target, F' = 4 sin²γ, kept
    // inside a bisection bracket (F' → 0 at π).
    double lo = 0, hi = M_PI;
    g = std::min(g, 3.0);
    for (int i = 0; i < 200; ++i) {
        const double f = calcAreaFactor(g) - target;
        if (f == 0) return g;
        (f < 0 ? lo : hi) = g;
        const double s = std::sin(g);
        double next = g - f / (4 * s * s);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - g) <= 1e-16 * g || hi - lo <= 1e-16 * g) return next;
        g = next;
    }
    return g;
}

}  // namespace circular_segment
}  // namespace milldyn
