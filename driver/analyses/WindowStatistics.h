#pragma once
// Steady-operation statistics of a transient (issue 29 item 1): the mean,
// RMS, minimum and maximum of any quantity over whole periods of the steady
// window, from the integrated trajectory itself (every accepted step of
// Simulation::run's onStep, the integrator's interpolant inside the steps
// through Simulation::trajectoryAt), never from the output rows.

#include "driver/ModelSpec.h"
#include "driver/analyses/Analysis.h"
#include "driver/Simulation.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace milldyn {

/**
 * Statistics of quantities f_i(state) over a window [a, e] of one run, e
 * the last period boundary at or before b (or b itself without a period):
 *
 * <pre>
 *   mean_i = (1/(e − a)) ∫_a^e f_i dt            rms_i = sqrt((1/(e − a)) ∫_a^e f_i² dt)
 *   min_i, max_i: the extremes of f_i on [a, e], located inside the steps
 *   peak_to_peak_i = max_i − min_i             ripple_i = (max_i − min_i)/|mean_i|
 *   speed fluctuation δ = (ω_max − ω_min)/ω_mean   (Shigley, "Flywheels")
 * </pre>
 *
 * The integrals: every accepted step [t_k, t_k+1] (clipped to the window,
 * split at a period boundary) by 3-point Gauss–Legendre quadrature on the
 * trajectory (trajectoryAt at the nodes): exact for f polynomial of degree
 * 5 in t, error h⁷·f⁽⁶⁾/2016000 per step of length h where f is smooth —
 * far below the integrator's own error at the steps it accepts; a kink of
 * f inside a step (a pulse's edge) costs O(h²·|Δf'|) there.
 *
 * The extremes, as PeakTracker does it: every node and step end is a point;
 * where three consecutive points have a local maximum (minimum) that the
 * parabola through them says could exceed the extreme so far, the extreme
 * is located on the trajectory between the outer two by golden-section
 * search (within the last two steps, where trajectoryAt reaches). A
 * switching restarts the points (no interpolation across it).
 *
 * Period boundaries: Time: a + k·T; Angle: where direction·(θ(t) − θ(a))
 * reaches k·2π (θ a body's pin angle, direction the sign of its turning at
 * a), located by bisection on the trajectory. The window ends at the last
 * boundary reached by b; with none (no period, or the window holds less
 * than one) it ends at b.
 */
class WindowStatistics {
public:
    using Fn = std::function<double(const SimTK::State&)>;
    struct PeriodRule {
        enum class Kind { None, Time, Angle } kind = Kind::None;
        double period = 0;  ///< Time: T [s]
        Fn angle;           ///< Angle: the pin angle θ [rad] whose whole turns are the periods
        std::string body;   ///< Angle: the body whose revolutions they are
        std::string what;   ///< "revolutions of B", "periods of 0.2 s" (after "whole")
    };
    /// One whole period [t0, t1] of the window and a quantity's mean over it.
    struct PeriodMean {
        double t0 = 0, t1 = 0, mean = 0;
    };
    struct Values {
        double mean = 0, rms = 0, min = 0, max = 0, tMin = 0, tMax = 0;
    };

    /// The window [a, b]; a before the run's start is the start.
    WindowStatistics(std::vector<Fn> quantities, double a, double b, PeriodRule rule);

    /// A step end (onStep's state, realized to Acceleration), in order.
    void step(Simulation& sim, const SimTK::State& s);

    /// The window was reached and closed (the run got to b).
    bool valid() const { return m_end.has_value(); }
    /// Whole periods: the number cut (0: none fitted or no period).
    int periods() const { return m_period ? m_period->index : 0; }
    double windowStart() const { return m_a; }
    double windowEnd() const { return boundary().t; }
    /// The states at the window's start and end (on the trajectory).
    const SimTK::State& startState() const { return m_startState; }
    const SimTK::State& endState() const { return boundary().state; }
    Values values(std::size_t i) const;
    /// Quantity i's mean over each whole period of the window, in order
    /// (empty without whole periods): (∫ over the period)/(its length).
    std::vector<PeriodMean> periodMeans(std::size_t i) const;
    long refinements() const { return m_refinements; }

private:
    struct Boundary {
        double t = 0;
        int index = 0;
        std::vector<double> integral, integral2, value;  // ∫f, ∫f² from a; f at t
        SimTK::State state;
    };
    struct Point {
        double t = 0;
        std::vector<double> v;
    };
    struct Record {
        double t, v;
    };

    std::vector<Fn> m_f;
    double m_a, m_b;
    PeriodRule m_rule;
    bool m_started = false, m_done = false;
    double m_tLast = 0;       // the integrals run from a to here
    double m_thetaA = 0, m_direction = 1;
    int m_nextIndex = 1;
    std::vector<double> m_integral, m_integral2;
    std::vector<Point> m_points;  // the last (up to) three points since a restart
    std::vector<std::vector<Record>> m_maxRecords, m_minRecords;  // raises of the running extremes
    SimTK::State m_startState;
    std::optional<Boundary> m_period, m_end;
    std::vector<std::pair<double, std::vector<double>>> m_periodIntegrals;  // every period boundary: t, ∫f from a
    long m_refinements = 0;

    const Boundary& boundary() const { return m_period ? *m_period : *m_end; }
    std::vector<double> evaluate(const SimTK::State& s) const;
    /// Integrates [m_tLast, t] (inside the current step) and adds its points.
    void advance(Simulation& sim, double t, const SimTK::State* endState);
    void addPoint(Simulation& sim, double t, std::vector<double> v);
    /// The integrals so far and the quantities at `at`, the state at t.
    Boundary makeBoundary(double t, int index, const SimTK::State& at) const;
};

/// A quantity a transient can give statistics or a peak of: a probe by its
/// name, or a body's speed by its column name (speedColumnName).
struct NamedQuantity {
    std::string name, unit;
    WindowStatistics::Fn f;
    std::string body;  ///< the body, for a speed; empty for a probe
};
std::optional<NamedQuantity> findQuantity(const Scene& scene, const std::string& name);

/// How outputs.statistics_period cuts this model's steady window, and why
/// in words (`why`: "auto: the AngleLoad X repeats every revolution of B",
/// or why there is no period). Throws SpecError for a `revolutions of` body
/// the scene does not have.
WindowStatistics::PeriodRule statisticsPeriod(const Scene& scene, const ModelSpec& spec, std::string& why);

/**
 * Adds a transient's steady-operation statistics to its result (the window
 * `w` was fed quantities 0..3 = speed_body's speed, the sums of the load
 * torques, load powers and drive torques, then `named` from index
 * `firstNamed`): with whole periods, final.steady_speed, final.
 * resistance_torque, final.power, final.drive_torque (the last instant
 * before switch-off, `at` says which) and speed_fluctuation.SPEED_BODY;
 * for each outputs.statistics name X: mean.X, min.X, max.X,
 * peak_to_peak.X, rms.X, ripple.X and, for a body's speed,
 * speed_fluctuation.BODY. Notes say over what window, or why none.
 */
void addSteadyStatistics(const Scene& scene, const SceneBody& speedBody, const WindowStatistics& w,
                         std::size_t firstNamed, const std::vector<NamedQuantity>& named,
                         const WindowStatistics::PeriodRule& rule, const std::string& periodWhy,
                         const std::string& windowText, bool reached, const SimTK::State& steady,
                         const std::string& at, AnalysisResult& result);

}  // namespace milldyn
