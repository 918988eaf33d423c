#include "driver/analyses/Trajectory.h"

#include <algorithm>
#include <cmath>

namespace milldyn {

void SpeedTrace::add(double t, double omega, double omegaDot) {
    m_t.push_back(t);
    m_w.push_back(omega);
    m_wd.push_back(omegaDot);
}

double SpeedTrace::segment(std::size_t i, double t) const {
    const double h = m_t[i + 1] - m_t[i];
    if (!(h > 0)) return m_w[i];
    const double s = (t - m_t[i]) / h, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * m_w[i] + (s3 - 2 * s2 + s) * h * m_wd[i] + (3 * s2 - 2 * s3) * m_w[i + 1] +
           (s3 - s2) * h * m_wd[i + 1];
}

double SpeedTrace::at(double t) const {
    if (m_t.empty()) return 0;
    if (t <= m_t.front()) return m_w.front();
    if (t >= m_t.back()) {
        // The value before a switching at the very end: the first point at that time.
        std::size_t i = m_t.size() - 1;
        while (i > 0 && m_t[i - 1] == m_t.back()) --i;
        return m_w[i];
    }
    const std::size_t i = static_cast<std::size_t>(std::lower_bound(m_t.begin(), m_t.end(), t) - m_t.begin());
    if (m_t[i] == t) return m_w[i];
    return segment(i - 1, t);
}

std::pair<double, double> SpeedTrace::range(double a, double b) const {
    double lo = at(a), hi = lo;
    auto take = [&](double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    };
    take(at(b));
    for (std::size_t i = 0; i + 1 < m_t.size(); ++i) {
        const double t0 = m_t[i], t1 = m_t[i + 1];
        if (t1 < a || t0 > b || !(t1 > t0)) continue;
        if (t0 >= a && t0 <= b) take(m_w[i]);
        if (t1 >= a && t1 <= b) take(m_w[i + 1]);
        // Interior extremes: the roots of the cubic's derivative in s.
        const double h = t1 - t0, w0 = m_w[i], w1 = m_w[i + 1], d0 = h * m_wd[i], d1 = h * m_wd[i + 1];
        // w(s) = (2s³−3s²+1)w0 + (s³−2s²+s)d0 + (3s²−2s³)w1 + (s³−s²)d1
        // w'(s) = A s² + B s + C
        const double A = 6 * w0 + 3 * d0 - 6 * w1 + 3 * d1, B = -6 * w0 - 4 * d0 + 6 * w1 - 2 * d1, C = d0;
        double roots[2];
        int n = 0;
        if (std::abs(A) < 1e-300) {
            if (std::abs(B) > 1e-300) roots[n++] = -C / B;
        } else {
            const double disc = B * B - 4 * A * C;
            if (disc >= 0) {
                const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
                roots[n++] = q / A;
                if (q != 0) roots[n++] = C / q;
            }
        }
        for (int k = 0; k < n; ++k) {
            const double t = t0 + roots[k] * h;
            if (roots[k] > 0 && roots[k] < 1 && t >= a && t <= b) take(segment(i, t));
        }
    }
    return {lo, hi};
}

std::optional<double> SpeedTrace::firstReach(double level, double direction) const {
    if (m_t.empty()) return std::nullopt;
    auto g = [&](double w) { return direction * (w - level); };
    if (g(m_w[0]) >= 0) return m_t[0];
    for (std::size_t i = 0; i + 1 < m_t.size(); ++i) {
        if (!(m_t[i + 1] > m_t[i])) continue;
        // A segment reaching the level: at its end, or at an interior
        // maximum of g (the interpolant may overshoot between step ends).
        double b = m_t[i + 1];
        if (!(g(m_w[i + 1]) >= 0)) {
            const auto r = range(m_t[i], m_t[i + 1]);
            const double best = direction > 0 ? r.second : r.first;
            if (!(g(best) >= 0)) continue;
            // Bracket the first reach: the interior extreme's time by a scan.
            const int n = 64;
            double tb = m_t[i + 1];
            for (int k = 1; k <= n; ++k) {
                const double t = m_t[i] + (m_t[i + 1] - m_t[i]) * k / n;
                if (g(segment(i, t)) >= 0) {
                    tb = t;
                    break;
                }
            }
            b = tb;
        }
        // Bisection on [a, b]: g(a) < 0 <= g(b), to round-off.
        double a = m_t[i];
        for (int k = 0; k < 200 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++k) {
            const double c = 0.5 * (a + b);
            if (g(segment(i, c)) >= 0)
                b = c;
            else
                a = c;
        }
        return b;
    }
    return std::nullopt;
}

std::pair<double, double> goldenSectionMaximum(const std::function<double(double)>& f, double a, double b) {
    const double r = 0.5 * (3 - std::sqrt(5.0));
    double x1 = a + r * (b - a), x2 = b - r * (b - a), f1 = f(x1), f2 = f(x2);
    for (int k = 0; k < 40 && b - a > 1e-12 * std::max(1.0, std::abs(b)); ++k) {
        if (f1 >= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = a + r * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = b - r * (b - a);
            f2 = f(x2);
        }
    }
    return f1 >= f2 ? std::make_pair(x1, f1) : std::make_pair(x2, f2);
}

void PeakTracker::step(Simulation& sim, const SimTK::State& s) {
    const double t = s.getTime(), v = measured(s);
    if (m_count > 0 && t <= m_t[m_count - 1]) m_count = 0;  // a restart at the same instant: no interpolation across it
    if (m_count == 2 && m_v[1] >= m_v[0] && m_v[1] > v) {
        // A local maximum of the step-end values at m_t[1]: the parabola
        // through the three points bounds what lies between them.
        const double t0 = m_t[0], t1 = m_t[1], t2 = t, v0 = m_v[0], v1 = m_v[1], v2 = v;
        const double d01 = (v1 - v0) / (t1 - t0), d12 = (v2 - v1) / (t2 - t1), c2 = (d12 - d01) / (t2 - t0);
        double estimate = v1;
        if (c2 < 0) {
            const double tv = 0.5 * (t0 + t1) - d01 / (2 * c2);  // vertex of v0 + d01 (t−t0) + c2 (t−t0)(t−t1)
            estimate = v0 + d01 * (tv - t0) + c2 * (tv - t0) * (tv - t1);
        }
        // Refine when the located maximum could raise the peak (with a
        // margin: the parabola is only an estimate of the interpolant).
        if (estimate > m_peak && t0 >= sim.trajectoryFrom()) {
            ++m_refinements;
            auto f = [&](double x) { return measured(sim.trajectoryAt(x)); };
            const auto [bestAt, best] = goldenSectionMaximum(f, t0, t2);
            if (best > m_peak) {
                m_peak = best;
                m_peakTime = bestAt;
            }
        }
    }
    if (v > m_peak) {
        m_peak = v;
        m_peakTime = t;
    }
    if (m_count == 2) {
        m_t[0] = m_t[1];
        m_v[0] = m_v[1];
        m_t[1] = t;
        m_v[1] = v;
    } else {
        m_t[m_count] = t;
        m_v[m_count] = v;
        ++m_count;
    }
}

}  // namespace milldyn
