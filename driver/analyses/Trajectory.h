#pragma once
// What a transient judges from the integrated trajectory itself (every
// accepted step of Simulation::run's onStep), never from the output rows:
// a shaft's speed as the integrator's own interpolant between its step ends
// (SpeedTrace: crossings, extremes, values at any instant) and the largest
// |value| of quantities with their maxima located inside the steps
// (PeakTracker). outputs.sample_interval only chooses the CSV rows.

#include "driver/Simulation.h"

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace milldyn {

/**
 * One shaft's speed ω(t) over a run: ω and dω/dt at every step end, joined
 * by the cubic Hermite interpolant the integrator itself uses between them
 * (so a crossing or an extreme is as accurate as the integration, whatever
 * the sampling). A switching adds a second point at the same time (ω is
 * continuous, dω/dt jumps); no segment spans it.
 */
class SpeedTrace {
public:
    void add(double t, double omega, double omegaDot);
    bool empty() const { return m_t.empty(); }
    double startTime() const { return m_t.front(); }
    double endTime() const { return m_t.back(); }
    /// ω at t (clamped to the trace); at a switching, the value before it.
    double at(double t) const;
    /// The smallest and largest ω over [a, b] (the interpolant's extremes).
    std::pair<double, double> range(double a, double b) const;
    /// The first instant at which direction·ω reaches direction·level
    /// (direction ±1), or nullopt.
    std::optional<double> firstReach(double level, double direction) const;

private:
    std::vector<double> m_t, m_w, m_wd;
    double segment(std::size_t i, double t) const;  // Hermite on [m_t[i], m_t[i+1]]
};

/// The maximum of f over [a, b] by golden-section search (40 reductions at
/// most, to 1e-12 of b): {where, f there}. f is a quantity on the
/// trajectory between two step ends, assumed unimodal there.
std::pair<double, double> goldenSectionMaximum(const std::function<double(double)>& f, double a, double b);

/**
 * The largest |f(state)| of one quantity over the trajectory (or, by
 * Measure, its largest or smallest value: the same search on f or −f). Fed every
 * step end in order; where the step-end values have a local maximum of |f|
 * whose parabola through the three step ends could exceed the peak so far,
 * the maximum is located on the trajectory between the neighbouring step
 * ends (golden-section search over Simulation::trajectoryAt), so a peak
 * inside a step is not lost. A restart (a switching) is not interpolated
 * across: the values just before and just after it are both step ends.
 */
class PeakTracker {
public:
    using Fn = std::function<double(const SimTK::State&)>;
    /// What is maximised: |f| (the peak's magnitude), f itself (the largest
    /// value, run_max) or −f (the negated smallest value, run_min).
    enum class Measure { Magnitude, Largest, Smallest };
    explicit PeakTracker(Fn f, Measure measure = Measure::Magnitude) : m_f(std::move(f)), m_measure(measure) {}
    /// A step end: `s` realized to Acceleration, as onStep gives it.
    void step(Simulation& sim, const SimTK::State& s);
    /// Magnitude: the largest |f| (0 before any step); Largest: the largest
    /// f; Smallest: the smallest f (±infinity before any step).
    double peak() const { return m_measure == Measure::Smallest ? -m_peak : m_peak; }
    double peakTime() const { return m_peakTime; }
    long refinements() const { return m_refinements; }

private:
    Fn m_f;
    Measure m_measure;
    double measured(const SimTK::State& s) const {
        const double v = m_f(s);
        return m_measure == Measure::Magnitude ? std::abs(v) : m_measure == Measure::Largest ? v : -v;
    }
    double m_peak = m_measure == Measure::Magnitude ? 0.0 : -std::numeric_limits<double>::infinity();
    double m_peakTime = 0;
    long m_refinements = 0;
    // The last two step ends' times and measured values.
    double m_t[2] = {0, 0}, m_v[2] = {0, 0};
    int m_count = 0;
};

}  // namespace milldyn
