#include "validation/oracles/StartOracle.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace milldyn::oracles {

double constantTorqueStartTime(double J, double omega, double M, double Mc) { return J * omega / (M - Mc); }

double klossBreakdownSlip(double sn, double lambda) { return sn * (lambda + std::sqrt(lambda * lambda - 1)); }

double klossTorque(double s, double Mk, double sk) { return 2 * Mk / (s / sk + sk / s); }

double klossSteadySlip(double Mc, double Mk, double sk) {
    const double q = Mk / Mc;
    return sk * (q - std::sqrt(q * q - 1));
}

double klossInertiaStartTime(double J, double wc, double Mk, double sk, double se) {
    // J·ωc·ds/dt = −M(s) ⇒ dt = J·ωc/(2·Mk)·(s/sk + sk/s)·(−ds), integrated from 1 to se.
    return J * wc / (2 * Mk) * ((1 - se * se) / (2 * sk) + sk * std::log(1 / se));
}

double modifiedKlossTorque(double s, double Mk, double sk, double a) {
    return Mk * 2 * (1 + a * sk) / (s / sk + sk / s + 2 * a * sk);
}

bool modifiedKlossFit(double sn, double lambda, double mu, double& sk, double& a) {
    if (!(mu < lambda) || !(lambda > 1) || !(sn > 0 && sn < 1)) return false;
    auto q = [&](double x) { return (mu * (x + 1 / x) - 2 * lambda) / (2 * (lambda - mu)); };
    auto residual = [&](double x) { return sn / x + x / sn - 2 * lambda - 2 * (lambda - 1) * q(x); };
    double lo = sn * (lambda + std::sqrt(lambda * lambda - 1)), hi = 1.0;
    if (!(lo < hi)) return false;
    const double rLo = residual(lo), rHi = residual(hi);
    if (rLo == 0) {
        hi = lo;
    } else {
        if (rLo * rHi > 0) return false;
        for (int i = 0; i < 300; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            ((residual(mid) > 0) == (rLo > 0) ? lo : hi) = mid;
        }
    }
    sk = 0.5 * (lo + hi);
    const double qs = q(sk);
    if (!(qs > -1e-9 && qs < 1)) return false;
    a = std::max(0.0, qs) / sk;
    return true;
}

double modifiedKlossInertiaStartTime(double J, double wc, double Mk, double sk, double a, double se) {
    const double q = a * sk;
    return J * wc / (2 * Mk * (1 + q)) * ((1 - se * se) / (2 * sk) + sk * std::log(1 / se) + 2 * q * (1 - se));
}

namespace {

/// The circle through the rated point, per unit of I_N: magnetising current
/// m, diameter D, slip scale s_c.
struct Circle {
    double m = 0, D = 0, sc = 0;
};

double circleMagnitude(const Circle& q, double slip) {
    if (slip == 0) return q.m;
    const double rho = q.sc / slip;
    return std::hypot(q.D * rho / (1 + rho * rho), q.m + q.D / (1 + rho * rho));
}

/// Fits the circle to the data (in m, see the header); false if none fits.
bool fitCircle(double sn, double c, double k, Circle& out) {
    const double sinPhi = std::sqrt(1 - c * c);
    auto circle = [&](double m) {
        const double w = sinPhi - m;
        return Circle{m, (c * c + w * w) / w, sn * c / w};
    };
    double lo = 0, hi = sinPhi - c * sn;
    if (!(circleMagnitude(circle(lo), 1.0) <= k && k <= circleMagnitude(circle(hi), 1.0))) return false;
    for (int i = 0; i < 300; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (circleMagnitude(circle(mid), 1.0) < k ? lo : hi) = mid;
    }
    out = circle(0.5 * (lo + hi));
    return true;
}

}  // namespace

double circleDiagramCurrent(double s, double sn, double IN, double c, double k) {
    Circle q;
    if (!fitCircle(sn, c, k, q)) return std::nan("");
    return IN * circleMagnitude(q, s);
}

double circleDiagramSlipAtCurrent(double current, double sn, double IN, double c, double k) {
    Circle q;
    if (!fitCircle(sn, c, k, q)) return std::nan("");
    // |I|² = m² + x·D·(D + 2m) with x = 1/(1 + ρ²), ρ = s_c/s.
    const double i = current / IN;
    const double x = (i * i - q.m * q.m) / (q.D * (q.D + 2 * q.m));
    if (!(x > 0 && x <= 1)) return std::nan("");
    return q.sc / std::sqrt(1 / x - 1);
}

double ratedStatorCopperLoss(double Mn, double wn, double wc, double eta, double P0) {
    const double ratedInput = Mn * wn / eta;     // P_n/η_n
    const double airGap = Mn * wc;               // rotor copper loss + shaft power
    return ratedInput - airGap - P0;
}

double electricalInputPower(double M, double wc, double statorCopperRated, double current, double ratedCurrent,
                            double P0) {
    const double r = current / ratedCurrent;
    return M * wc + statorCopperRated * r * r + P0;
}

double starDeltaCurrentRatio() {
    const double phaseCurrent = 1 / std::sqrt(3.0), deltaLineOverPhase = std::sqrt(3.0);
    return phaseCurrent / deltaLineOverPhase;
}

double starDeltaTorqueRatio() {
    const double phaseVoltage = 1 / std::sqrt(3.0);
    return phaseVoltage * phaseVoltage;
}

double reducedVoltageTorqueRatio(double v) { return v * v; }

double rotorHeatInertiaStart(double J, double wc, double we) { return J * (wc * we - 0.5 * we * we); }

double clutchSlipEnergy(double J1, double J2, double w0, double Mf, double Mc) {
    const double a = Mf / J1 + (Mf - Mc) / J2;
    return 0.5 * Mf * w0 * w0 / a;
}

double brakedSpeed(double J, double w0, double Mb, double Mc, double Tr, double t) {
    const double rampImpulse = t < Tr ? Mb * t * t / (2 * Tr) : Mb * (t - Tr / 2);
    return w0 - (Mc * t + rampImpulse) / J;
}

double pendulumTurningAngle(double J, double W, double a0, double w0) {
    return std::acos(std::cos(a0) - J * w0 * w0 / (2 * W));
}

double pendulumBottomSpeed(double J, double W, double aMax) { return std::sqrt(2 * W * (1 - std::cos(aMax)) / J); }

double chargeHoldingTorque(double W, double a) { return W * std::sin(a); }

double equivalentCircuitTorque(double s, double Rs, double Rr, double Lss, double Lrs, double Lm, int p, double V,
                               double f) {
    using C = std::complex<double>;
    const double w = 2 * M_PI * f;
    const C rotor(Rr / s, w * Lrs), main(0, w * Lm);
    const C Is = V / (C(Rs, w * Lss) + main * rotor / (main + rotor));
    const C Ir = Is * main / (main + rotor);
    return 3 * std::norm(Ir) * (Rr / s) / (w / p);
}

}  // namespace milldyn::oracles
