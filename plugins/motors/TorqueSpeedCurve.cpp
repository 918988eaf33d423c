#include "plugins/motors/TorqueSpeedCurve.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn {
namespace {

[[noreturn]] void badParameter(const std::string& name, double value, const std::string& rule) {
    throw std::invalid_argument("InductionMotor: " + name + " = " + std::to_string(value) +
                                " is invalid: " + rule);
}

}  // namespace

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y) : m_x(std::move(x)), m_y(std::move(y)) {
    const std::size_t n = m_x.size();
    if (n < 2 || m_y.size() != n) throw std::invalid_argument("MonotoneCubic: need >= 2 points, as many x as y");
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(m_x[k]) || !std::isfinite(m_y[k])) throw std::invalid_argument("MonotoneCubic: point not finite");
        if (k > 0 && !(m_x[k] > m_x[k - 1])) throw std::invalid_argument("MonotoneCubic: x not strictly increasing");
    }
    std::vector<double> d(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) d[k] = (m_y[k + 1] - m_y[k]) / (m_x[k + 1] - m_x[k]);
    m_m.assign(n, 0.0);
    m_m[0] = d[0];
    m_m[n - 1] = d[n - 2];
    for (std::size_t k = 1; k + 1 < n; ++k) m_m[k] = d[k - 1] * d[k] <= 0 ? 0.0 : 0.5 * (d[k - 1] + d[k]);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (d[k] == 0) {
            m_m[k] = m_m[k + 1] = 0;
            continue;
        }
        const double a = m_m[k] / d[k], b = m_m[k + 1] / d[k];
        const double r = a * a + b * b;
        if (r > 9) {
            const double tau = 3 / std::sqrt(r);
            m_m[k] = tau * a * d[k];
            m_m[k + 1] = tau * b * d[k];
        }
    }
}

double MonotoneCubic::operator()(double x) const {
    const std::size_t n = m_x.size();
    if (x <= m_x[0]) return m_y[0];
    if (x >= m_x[n - 1]) return m_y[n - 1] + m_m[n - 1] * (x - m_x[n - 1]);
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(m_x.begin(), m_x.end(), x) - m_x.begin()) - 1;
    const double h = m_x[k + 1] - m_x[k];
    const double t = (x - m_x[k]) / h;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * m_y[k] + (t3 - 2 * t2 + t) * h * m_m[k] + (-2 * t3 + 3 * t2) * m_y[k + 1] +
           (t3 - t2) * h * m_m[k + 1];
}

namespace {

std::string number(double v) { return formatNumber(v); }

}  // namespace

ModifiedKlossFit fitModifiedKloss(double sn, double lambda, double mu) {
    if (!(std::isfinite(sn) && sn > 0 && sn < 1)) throw std::invalid_argument("rated slip must lie in (0, 1)");
    if (!(std::isfinite(lambda) && lambda > 1)) throw std::invalid_argument("breakdown ratio must be > 1");
    if (!(std::isfinite(mu) && mu > 0)) throw std::invalid_argument("starting torque ratio must be finite and > 0");
    if (!(mu < lambda))
        throw std::invalid_argument("starting torque above the breakdown torque (" + number(mu) +
                                    " >= breakdown ratio " + number(lambda) + ")");
    auto slipOf = [&](double q) {
        const double C = lambda + q * (lambda - 1);
        return sn * (C + std::sqrt(C * C - 1));
    };
    auto ratioOf = [&](double q) {
        const double sk = slipOf(q);
        return 2 * lambda * (1 + q) / (1 / sk + sk + 2 * q);
    };
    // q at which sk(q) = 1: C = (sn + 1/sn)/2.
    const double qUnitSlip = (0.5 * (sn + 1 / sn) - lambda) / (lambda - 1);
    if (!(qUnitSlip > 0))
        throw std::invalid_argument("the Kloss breakdown slip of this rated slip and breakdown ratio is beyond "
                                    "standstill (sk >= 1): no starting torque below breakdown");
    const double qMax = std::min(1.0, qUnitSlip);
    const double muLow = ratioOf(0), muHigh = ratioOf(qMax);
    // μ within rounding of the classic Kloss value is that value (q = 0).
    if (!(mu >= muLow * (1 - 1e-12) && mu < muHigh))
        throw std::invalid_argument("no modified Kloss curve through these data: with rated slip " + number(sn) +
                                    " and breakdown ratio " + number(lambda) +
                                    " the starting torque ratio must lie in [" + number(muLow) + ", " +
                                    number(muHigh) + ") (stator resistance 0 to R1/√(R1² + Xk²) → 1)");
    double lo = 0, hi = qMax;  // ratioOf(lo) <= mu < ratioOf(hi)
    for (int i = 0; i < 200 && hi - lo > 0; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (ratioOf(mid) <= mu ? lo : hi) = mid;
    }
    const double q = std::abs(ratioOf(lo) - mu) <= std::abs(ratioOf(hi) - mu) ? lo : hi;
    ModifiedKlossFit fit;
    fit.breakdownSlip = slipOf(q);
    fit.asymmetry = q / fit.breakdownSlip;
    return fit;
}

TorqueSpeedCurve::TorqueSpeedCurve(const TorqueSpeedCurveParams& p) : m_params(p) {
    using Law = TorqueSpeedCurveParams::Law;
    auto finite = [](double v) { return std::isfinite(v); };
    if (!(finite(p.ratedTorque) && p.ratedTorque > 0)) badParameter("rated_torque", p.ratedTorque, "must be finite and > 0");
    if (!(finite(p.synchronousSpeed) && p.synchronousSpeed > 0))
        badParameter("synchronous_speed", p.synchronousSpeed, "must be finite and > 0");
    if (!(p.ratedSpeed > 0 && p.ratedSpeed < p.synchronousSpeed))
        badParameter("rated_speed", p.ratedSpeed, "must lie in (0, synchronous_speed)");
    if (!finite(p.breakdownRatio)) badParameter("breakdown_ratio", p.breakdownRatio, "must be finite");
    if ((p.law == Law::Kloss || p.law == Law::KlossModified || p.law == Law::Catalogue) && !(p.breakdownRatio > 1))
        badParameter("breakdown_ratio", p.breakdownRatio, "must be > 1 (breakdown torque above rated)");
    if (!(finite(p.linearStallTorque) && p.linearStallTorque >= 0))
        badParameter("linear_stall_torque", p.linearStallTorque, "must be finite and >= 0");
    if (!(finite(p.linearSlope) && p.linearSlope >= 0)) badParameter("linear_slope", p.linearSlope, "must be finite and >= 0");

    const double wc = p.synchronousSpeed, Mn = p.ratedTorque;
    const double slipSpeed = wc - p.ratedSpeed;
    if (p.linearStallTorque > 0 && p.linearSlope > 0) {
        m_M00 = p.linearStallTorque;
        m_b0 = p.linearSlope;

    } else {
        m_M00 = Mn * wc / slipSpeed;  // eq (4)
        m_b0 = Mn / slipSpeed;        // eq (4)
    }
    m_slipRated = slipSpeed / wc;
    const double lambda = p.breakdownRatio;
    m_slipBreakdown = m_slipRated * (lambda + std::sqrt(std::max(0.0, lambda * lambda - 1)));

    if (p.law == Law::KlossModified) {
        try {
            const ModifiedKlossFit fit = fitModifiedKloss(m_slipRated, lambda, p.lockedRotorRatio);
            m_slipBreakdown = fit.breakdownSlip;
            m_asymmetry = fit.asymmetry;
        } catch (const std::invalid_argument& e) {
            badParameter("locked_rotor_ratio", p.lockedRotorRatio, e.what());
        }
    } else if (p.law == Law::Catalogue) {
        const double wk = p.breakdownSpeed > 0 ? p.breakdownSpeed : wc * (1 - m_slipBreakdown);
        if (!(p.lockedRotorRatio > 0 && finite(p.lockedRotorRatio)))
            badParameter("locked_rotor_ratio", p.lockedRotorRatio, "must be finite and > 0");
        if (!(wk > 0 && wk < p.ratedSpeed))
            badParameter("breakdown_speed", wk, "must lie in (0, rated_speed)");
        m_pointSpeeds = {0.0};
        m_pointTorques = {p.lockedRotorRatio * Mn};
        if (p.pullUpRatio > 0) {
            if (!(p.pullUpSpeed > 0 && p.pullUpSpeed < wk))
                badParameter("pull_up_speed", p.pullUpSpeed, "must lie in (0, breakdown speed)");
            if (!(p.pullUpRatio <= p.lockedRotorRatio && p.pullUpRatio <= lambda))
                badParameter("pull_up_ratio", p.pullUpRatio, "must not exceed the locked-rotor or breakdown ratio");
            m_pointSpeeds.push_back(p.pullUpSpeed);
            m_pointTorques.push_back(p.pullUpRatio * Mn);
        }
        if (!(p.lockedRotorRatio <= lambda))
            badParameter("locked_rotor_ratio", p.lockedRotorRatio, "must not exceed the breakdown ratio");
        m_pointSpeeds.insert(m_pointSpeeds.end(), {wk, p.ratedSpeed, wc});
        m_pointTorques.insert(m_pointTorques.end(), {lambda * Mn, Mn, 0.0});
        m_torque = MonotoneCubic(m_pointSpeeds, m_pointTorques);
    } else if (p.law == Law::Table) {
        const std::size_t n = p.tableSpeeds.size();
        if (n < 2 || p.tableTorques.size() != n)
            badParameter("curve_torques", static_cast<double>(p.tableTorques.size()),
                         "give as many torques as speeds (at least 2)");
        if (!p.tableCurrents.empty() && p.tableCurrents.size() != n)
            badParameter("curve_currents", static_cast<double>(p.tableCurrents.size()), "give as many currents as speeds");
        for (std::size_t k = 0; k < n; ++k) {
            if (!finite(p.tableSpeeds[k]) || !finite(p.tableTorques[k]))
                badParameter("curve_speeds", p.tableSpeeds[k], "points must be finite");
            if (k > 0 && !(p.tableSpeeds[k] > p.tableSpeeds[k - 1]))
                badParameter("curve_speeds", p.tableSpeeds[k], "speeds must increase strictly");
        }
        if (p.tableSpeeds.front() < 0) badParameter("curve_speeds", p.tableSpeeds.front(), "must be >= 0");
        // Below ωc a motor drives (M >= 0, rotor heat M·(ωc − ω) >= 0); at ωc
        // it has no slip, no rotor current and no torque.
        for (double M : p.tableTorques)
            if (M < 0) badParameter("curve_torques", M, "torques below synchronous speed must be >= 0");
        if (p.tableSpeeds.back() == wc && p.tableTorques.back() != 0)
            badParameter("curve_torques", p.tableTorques.back(), "the torque at synchronous speed must be 0");
        if (p.tableSpeeds.back() > wc) badParameter("curve_speeds", p.tableSpeeds.back(), "must not exceed synchronous_speed");
        m_pointSpeeds = p.tableSpeeds;
        m_pointTorques = p.tableTorques;
        std::vector<double> currents = p.tableCurrents;
        if (p.tableSpeeds.back() < wc) {
            m_pointSpeeds.push_back(wc);
            m_pointTorques.push_back(0.0);
            if (!currents.empty()) currents.push_back(currents.back());  // no-load current ≈ the last given
        }
        m_torque = MonotoneCubic(m_pointSpeeds, m_pointTorques);
        if (!currents.empty()) m_current = MonotoneCubic(m_pointSpeeds, currents);
    }
    const bool anyCurrent = p.ratedCurrent != 0 || p.ratedPowerFactor != 0 || p.lockedRotorCurrentRatio != 0;
    if (anyCurrent) {
        if (p.law == Law::Table)
            badParameter("rated_current", p.ratedCurrent, "the table law takes its currents from curve_currents");
        try {
            m_circle = CurrentCircle({m_slipRated, p.ratedCurrent, p.ratedPowerFactor, p.lockedRotorCurrentRatio});
        } catch (const std::invalid_argument& e) {
            badParameter("locked_rotor_current_ratio", p.lockedRotorCurrentRatio, e.what());
        }
    }
}

double TorqueSpeedCurve::torque(double omega) const {
    using Law = TorqueSpeedCurveParams::Law;
    switch (m_params.law) {
        case Law::Linear: return m_M00 - m_b0 * omega;  // eq (3)
        case Law::Kloss: {
            const double s = (m_params.synchronousSpeed - omega) / m_params.synchronousSpeed;
            const double sk = m_slipBreakdown;
            const double Mk = m_params.breakdownRatio * m_params.ratedTorque;
            // 2Mk/(s/sk + sk/s) written without the division by s, so s = 0 is fine.
            return 2 * Mk * s * sk / (s * s + sk * sk);
        }
        case Law::KlossModified: {
            const double s = (m_params.synchronousSpeed - omega) / m_params.synchronousSpeed;
            const double sk = m_slipBreakdown, q = m_asymmetry * sk;
            const double Mk = m_params.breakdownRatio * m_params.ratedTorque;
            // Mk·2(1 + q)/(s/sk + sk/s + 2q) times s·sk over s·sk: finite at s = 0.
            return 2 * Mk * (1 + q) * s * sk / (s * s + sk * sk + 2 * q * s * sk);
        }
        case Law::Catalogue:
        case Law::Table: return m_torque(omega);
    }
    return 0;
}

double TorqueSpeedCurve::zeroTorqueSpeed() const {
    return m_params.law == TorqueSpeedCurveParams::Law::Linear ? m_M00 / m_b0 : m_params.synchronousSpeed;
}

double TorqueSpeedCurve::current(double omega) const {
    if (m_circle) return m_circle->current((m_params.synchronousSpeed - omega) / m_params.synchronousSpeed);
    return m_current.empty() ? std::nan("") : m_current(std::max(omega, 0.0));
}

}  // namespace milldyn
