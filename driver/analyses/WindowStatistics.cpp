#include "driver/analyses/WindowStatistics.h"

#include "driver/analyses/Analysis.h"
#include "driver/analyses/Trajectory.h"
#include "plugins/scene/ElementSchema.h"
#include "plugins/scene/Format.h"
#include "plugins/scene/HarmonicForcing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace milldyn {

WindowStatistics::WindowStatistics(std::vector<Fn> quantities, double a, double b, PeriodRule rule)
    : m_f(std::move(quantities)), m_a(a), m_b(b), m_rule(std::move(rule)) {
    m_integral.assign(m_f.size(), 0.0);
    m_integral2.assign(m_f.size(), 0.0);
    m_maxRecords.resize(m_f.size());
    m_minRecords.resize(m_f.size());
}

std::vector<double> WindowStatistics::evaluate(const SimTK::State& s) const {
    std::vector<double> v(m_f.size());
    for (std::size_t i = 0; i < m_f.size(); ++i) v[i] = m_f[i](s);
    return v;
}

void WindowStatistics::addPoint(Simulation& sim, double t, std::vector<double> v) {
    const double inf = std::numeric_limits<double>::infinity();
    auto runMax = [&](std::size_t i) { return m_maxRecords[i].empty() ? -inf : m_maxRecords[i].back().v; };
    auto runMin = [&](std::size_t i) { return m_minRecords[i].empty() ? inf : m_minRecords[i].back().v; };
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (v[i] > runMax(i)) m_maxRecords[i].push_back({t, v[i]});
        if (v[i] < runMin(i)) m_minRecords[i].push_back({t, v[i]});
    }
    m_points.push_back({t, std::move(v)});
    if (m_points.size() > 3) m_points.erase(m_points.begin());
    if (m_points.size() < 3 || m_points[0].t < sim.trajectoryFrom()) return;
    const Point &p0 = m_points[0], &p1 = m_points[1], &p2 = m_points[2];
    for (std::size_t i = 0; i < m_f.size(); ++i)
        for (const double sign : {1.0, -1.0}) {
            // sign·f: a maximum of f, then a minimum of f as a maximum of −f.
            const double v0 = sign * p0.v[i], v1 = sign * p1.v[i], v2 = sign * p2.v[i];
            if (!(v1 >= v0 && v1 > v2)) continue;
            const double d01 = (v1 - v0) / (p1.t - p0.t), d12 = (v2 - v1) / (p2.t - p1.t);
            const double c2 = (d12 - d01) / (p2.t - p0.t);
            double estimate = v1;
            if (c2 < 0) {
                const double tv = 0.5 * (p0.t + p1.t) - d01 / (2 * c2);
                estimate = v0 + d01 * (tv - p0.t) + c2 * (tv - p0.t) * (tv - p1.t);
            }
            const double best = sign > 0 ? runMax(i) : -runMin(i);
            if (!(estimate > best)) continue;
            ++m_refinements;
            auto f = [&](double x) { return sign * m_f[i](sim.trajectoryAt(x)); };
            const auto [at, located] = goldenSectionMaximum(f, p0.t, p2.t);
            if (located > best) (sign > 0 ? m_maxRecords : m_minRecords)[i].push_back({at, sign * located});
        }
}

WindowStatistics::Boundary WindowStatistics::makeBoundary(double t, int index, const SimTK::State& at) const {
    Boundary bd;
    bd.t = t;
    bd.index = index;
    bd.integral = m_integral;
    bd.integral2 = m_integral2;
    bd.value = evaluate(at);
    bd.state = at;
    return bd;
}

void WindowStatistics::advance(Simulation& sim, double t, const SimTK::State* endState) {
    const double t0 = m_tLast, h = t - t0;
    if (h > 0) {
        // 3-point Gauss–Legendre on [t0, t]: nodes first (trajectoryAt's
        // state is replaced by the next call), then the end.
        static const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
        for (int k = 0; k < 3; ++k) {
            const double tk = t0 + 0.5 * h * (1 + x[k]);
            std::vector<double> v = evaluate(sim.trajectoryAt(tk));
            for (std::size_t i = 0; i < v.size(); ++i) {
                m_integral[i] += 0.5 * h * w[k] * v[i];
                m_integral2[i] += 0.5 * h * w[k] * v[i] * v[i];
            }
            addPoint(sim, tk, std::move(v));
        }
        addPoint(sim, t, evaluate(endState ? *endState : sim.trajectoryAt(t)));
    }
    m_tLast = t;
}

void WindowStatistics::step(Simulation& sim, const SimTK::State& s) {
    if (m_done) return;
    const double t = s.getTime();
    if (!m_started) {
        if (t < m_a) return;
        m_started = true;
        // The window starts at a on the trajectory (or at the run's start).
        if (!(m_a < t && m_a >= sim.trajectoryFrom())) m_a = t;
        // (A State's copy is not realized: evaluate on the original.)
        const SimTK::State& at = m_a == t ? s : sim.trajectoryAt(m_a);
        std::vector<double> first = evaluate(at);
        if (m_rule.kind == PeriodRule::Kind::Angle) m_thetaA = m_rule.angle(at);
        m_startState = at;
        m_direction = 0;
        m_tLast = m_a;
        addPoint(sim, m_a, std::move(first));
        if (m_a == t) return;
    } else if (t <= m_tLast) {
        // A restart at the same instant (a switching): the value after it
        // is a point; no extreme is interpolated across it.
        m_points.clear();
        addPoint(sim, t, evaluate(s));
        return;
    }
    const double tEnd = std::min(t, m_b);
    auto stateAt = [&](double x) -> const SimTK::State& { return x == t ? s : sim.trajectoryAt(x); };
    // Period boundaries up to tEnd: integrate to each, keep it.
    for (;;) {
        double tc = 0;
        if (m_rule.kind == PeriodRule::Kind::Time) {
            tc = m_a + m_nextIndex * m_rule.period;
            if (tc > tEnd) break;
        } else if (m_rule.kind == PeriodRule::Kind::Angle) {
            const double thetaEnd = m_rule.angle(stateAt(tEnd));
            if (m_direction == 0) m_direction = thetaEnd > m_thetaA ? 1 : thetaEnd < m_thetaA ? -1 : 0;
            const double target = m_nextIndex * 2 * SimTK::Pi;
            auto g = [&](double x) { return m_direction * (m_rule.angle(stateAt(x)) - m_thetaA) - target; };
            if (m_direction == 0 || !(g(tEnd) >= 0)) break;
            // Bisection on [m_tLast, tEnd]: g < 0 at m_tLast (the previous
            // boundary or step end had not reached it).
            double lo = m_tLast, hi = tEnd;
            for (int k = 0; k < 100 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++k) {
                const double mid = 0.5 * (lo + hi);
                (g(mid) >= 0 ? hi : lo) = mid;
            }
            tc = hi;
        } else {
            break;
        }
        advance(sim, tc, tc == t ? &s : nullptr);
        m_period = makeBoundary(tc, m_nextIndex++, stateAt(tc));
        m_periodIntegrals.emplace_back(tc, m_integral);
    }
    advance(sim, tEnd, tEnd == t ? &s : nullptr);
    if (t >= m_b) {
        m_end = makeBoundary(tEnd, 0, stateAt(tEnd));
        m_done = true;
    }
}

WindowStatistics::Values WindowStatistics::values(std::size_t i) const {
    const Boundary& e = boundary();
    Values v;
    const double span = e.t - m_a;
    v.mean = span > 0 ? e.integral[i] / span : e.value[i];
    v.rms = span > 0 ? std::sqrt(std::max(0.0, e.integral2[i] / span)) : std::abs(e.value[i]);
    v.max = v.min = e.value[i];
    v.tMax = v.tMin = e.t;
    // The running extremes' raises up to the window's end.
    for (const Record& r : m_maxRecords[i])
        if (r.t <= e.t && r.v > v.max) {
            v.max = r.v;
            v.tMax = r.t;
        }
    for (const Record& r : m_minRecords[i])
        if (r.t <= e.t && r.v < v.min) {
            v.min = r.v;
            v.tMin = r.t;
        }
    return v;
}

std::vector<WindowStatistics::PeriodMean> WindowStatistics::periodMeans(std::size_t i) const {
    std::vector<PeriodMean> out;
    double t0 = m_a, before = 0;
    for (const auto& [t, integral] : m_periodIntegrals) {
        if (t > t0) out.push_back({t0, t, (integral[i] - before) / (t - t0)});
        t0 = t;
        before = integral[i];
    }
    return out;
}

std::optional<NamedQuantity> findQuantity(const Scene& scene, const std::string& name) {
    for (const auto& b : scene.bodies())
        if (speedColumnName(scene, b) == name) {
            const SimTK::MobilizedBody mobod = b.mobod;
            return NamedQuantity{name, "rad/s", [mobod](const SimTK::State& s) { return pinSpeed(s, mobod); }, b.name};
        }
    for (const auto& p : scene.probes())
        if (p.name == name) {
            const Probe* probe = &p;
            return NamedQuantity{name, p.unit, [probe](const SimTK::State& s) { return probe->value(s); }, ""};
        }
    return std::nullopt;
}

WindowStatistics::PeriodRule statisticsPeriod(const Scene& scene, const ModelSpec& spec, std::string& why) {
    const OutputSpec& o = spec.outputs;
    using Kind = WindowStatistics::PeriodRule::Kind;
    WindowStatistics::PeriodRule rule;
    auto revolutionsOf = [&](const SceneBody& body) {
        rule.kind = Kind::Angle;
        rule.what = "revolutions of " + body.name;
        rule.body = body.name;
        const SimTK::MobilizedBody mobod = body.mobod;
        rule.angle = [mobod](const SimTK::State& s) { return pinAngle(s, mobod); };
    };
    if (o.statisticsPeriod == "hold") {
        why = "the hold window, not cut to whole periods (outputs.statistics_period: hold)";
        return rule;
    }
    if (o.statisticsPeriod == "time") {
        rule.kind = Kind::Time;
        rule.period = o.statisticsPeriodTime;
        rule.what = "periods of " + formatNumber(rule.period, 6) + " s";
        why = "outputs.statistics_period";
        return rule;
    }
    if (o.statisticsPeriod == "revolutions") {
        const SceneBody* body = scene.findBody(o.statisticsPeriodBody);
        if (!body) {
            std::vector<std::string> names;
            for (const auto& b : scene.bodies()) names.push_back(b.name);
            const std::string near = nearestName(o.statisticsPeriodBody, names);
            throw SpecError(o.statisticsPeriodWhere, "outputs.statistics_period",
                            "no body named '" + o.statisticsPeriodBody + "'" +
                                (near.empty() ? "" : " (did you mean '" + near + "'?)"));
        }
        revolutionsOf(*body);
        why = "outputs.statistics_period";
        return rule;
    }
    // auto: from the model's periodic loads, asked through HarmonicForcing
    // (no element type named here). A shaft-angle load (AngleLoad) repeats
    // every revolution of its shafts (whole events per revolution); a
    // time-clock load (PeriodicLoad) every 2π/P_1 of time.
    std::set<std::string> angleBodies;
    std::set<double> frequencies;
    std::string angleLoads, periodicLoads;
    for (const ElementSpec& e : spec.elements) {
        const HarmonicForcing* h = scene.findElement<HarmonicForcing>(e.name);
        if (!h) continue;
        if (h->forcingClock() == HarmonicForcing::Clock::ShaftAngle) {
            for (const SimTK::MobilizedBody& m : h->forcingBodies())
                for (const SceneBody& b : scene.bodies())
                    if (b.mobod.getMobilizedBodyIndex() == m.getMobilizedBodyIndex()) angleBodies.insert(b.name);
            angleLoads += (angleLoads.empty() ? "" : ", ") + e.name;
        } else {
            frequencies.insert(h->forcingOrder(1));
            periodicLoads += (periodicLoads.empty() ? "" : ", ") + e.name;
        }
    }
    if (angleBodies.size() == 1 && frequencies.empty()) {
        if (const SceneBody* body = scene.findBody(*angleBodies.begin())) {
            revolutionsOf(*body);
            why = "auto: the shaft-angle load " + angleLoads + " repeats every revolution of " + body->name;
            return rule;
        }
    }
    if (frequencies.size() == 1 && angleBodies.empty()) {
        rule.kind = Kind::Time;
        rule.period = 2 * SimTK::Pi / *frequencies.begin();
        rule.what = "periods 2π/P_1 of " + formatNumber(rule.period, 6) + " s";
        why = "auto: the time-clock load " + periodicLoads + "'s fundamental";
        return rule;
    }
    if (angleBodies.empty() && frequencies.empty())
        why = "no period: the model has no periodic load (no HarmonicForcing element: AngleLoad, PeriodicLoad) and outputs.statistics_period is "
              "auto; the hold window as it is";
    else
        why = "no period: the periodic loads (" + angleLoads + (angleLoads.empty() || periodicLoads.empty() ? "" : ", ") +
              periodicLoads + ") share no one period auto can tell (set outputs.statistics_period); the hold window "
              "as it is";
    return rule;
}

void addSteadyStatistics(const Scene& scene, const SceneBody& speedBody, const WindowStatistics& w,
                         std::size_t firstNamed, const std::vector<NamedQuantity>& named,
                         const WindowStatistics::PeriodRule& rule, const std::string& periodWhy,
                         const std::string& windowText, bool reached, const SimTK::State& steady,
                         const std::string& at, AnalysisResult& result) {
    auto fmt = [](double v) { return formatNumber(v, 4); };
    if (!reached) {
        if (!named.empty())
            result.notes.push_back("outputs.statistics: none given: the start did not complete, so the run has no "
                                   "steady window");
        return;
    }
    if (!w.valid()) {
        if (!named.empty())
            result.notes.push_back("outputs.statistics: none given: the run ended before the analysis window's end");
        return;
    }
    const bool whole = w.periods() > 0;
    const std::string hold = "the hold window, " + fmt(w.windowStart()) + " to " + fmt(w.windowEnd()) + " s";
    if (!whole && rule.kind != WindowStatistics::PeriodRule::Kind::None)
        result.notes.push_back("statistics over " + hold + ", not whole periods: it holds less than one of the " +
                               rule.what + " (" + periodWhy +
                               "); lengthen scenario.hold_time (the steady values are the last instant's)");
    else if (!whole && !named.empty())
        result.notes.push_back("outputs.statistics over " + hold + " (" + periodWhy + ")");
    const std::string over = whole ? windowText : hold;
    if (whole) {
        const std::string also = " (the steady values are means over whole periods)";
        result.results.push_back({"final.steady_speed", pinSpeed(steady, speedBody.mobod), "rad/s",
                                  "speed of " + speedBody.name + " " + at + also});
        result.results.push_back(
            {"final.power", sumProbes(scene, steady, ProbeRole::ResistancePower), "W",
             "power absorbed by the loads " + at + also});
        // final.resistance_torque and final.drive_torque: Transient's
        // addTorqueLines, on their shafts like the steady values.
    }
    auto fluctuation = [&](const std::string& body, const WindowStatistics::Values& v) {
        const std::string name = "speed_fluctuation." + body;
        if (result.find(name) || v.mean == 0) return;
        result.results.push_back({name, (v.max - v.min) / std::abs(v.mean), "1",
                                  "coefficient of speed fluctuation (ω_max − ω_min)/|ω_mean| of " + body + " over " +
                                      over + " (Shigley's C_s, with the time mean)"});
    };
    if (whole) fluctuation(speedBody.name, w.values(0));
    for (std::size_t j = 0; j < named.size(); ++j) {
        const NamedQuantity& q = named[j];
        const WindowStatistics::Values v = w.values(firstNamed + j);
        const std::string of = q.name + " over " + over;
        result.results.push_back({"mean." + q.name, v.mean, q.unit, "time mean of " + of});
        result.results.push_back({"min." + q.name, v.min, q.unit,
                                  "smallest " + of + " (at " + fmt(v.tMin) + " s, located inside the steps)"});
        result.results.push_back({"max." + q.name, v.max, q.unit,
                                  "largest " + of + " (at " + fmt(v.tMax) + " s, located inside the steps)"});
        result.results.push_back({"peak_to_peak." + q.name, v.max - v.min, q.unit, "max − min of " + of});
        result.results.push_back({"rms." + q.name, v.rms, q.unit, "root mean square of " + of});
        // A mean at 0 (to round-off of the extremes) leaves no ripple.
        if (std::abs(v.mean) > 1e-12 * std::max(std::abs(v.max), std::abs(v.min)))
            result.results.push_back(
                {"ripple." + q.name, (v.max - v.min) / std::abs(v.mean), "1", "(max − min)/|mean| of " + of});
        else
            result.notes.push_back("ripple." + q.name + " not given: its mean over " + over + " is 0");
        if (!q.body.empty()) fluctuation(q.body, v);
    }
}

}  // namespace milldyn
