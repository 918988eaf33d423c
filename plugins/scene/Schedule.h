#pragma once
// Schedule: a dimensionless factor f(t) that multiplies a magnitude (a
// load's torque, a clutch's or brake's capacity) over time, read from one
// model key (`schedule: {ramp: {...}}`). Plain data: no Simbody, no YAML.

#include "plugins/scene/ElementSchema.h"

#include <memory>
#include <string>
#include <vector>

namespace SimTK {
class State;
}

namespace milldyn {

class Scene;
class ScheduleClock;

/**
 * A time law f(t) >= 0 multiplying an element's magnitude. One of
 *
 * <pre>
 *   constant       f = 1                                   (no `schedule` key)
 *   ramp           f = a                         t <= t0
 *                  f = a + (b − a)·(t − t0)/T    t0 < t < t0 + T
 *                  f = b                         t >= t0 + T
 *                  {start: t0, duration: T > 0, from: a (0), to: b (1)}
 *   step_recovery  f = 1                         t <= ts
 *                  f = 1 − d·(1 − (t − ts)/Tr)   ts < t < ts + Tr   (a drop d, recovered linearly)
 *                  f = 1                         t >= ts + Tr
 *                  {at: ts, drop: d <= 1 (d < 0: a surge), recovery_time: Tr > 0}
 *   sine           f = m + A·sin(2π·fr·(t − t0) + φ)       t >= t0 (held at its t0 value before)
 *                  {mean: m (1), amplitude: A, frequency: fr [Hz] > 0, phase: φ [rad] (0), start: t0 (0)}
 *   table          f linear between rows (t_i, f_i), held at the first and
 *                  last values outside; t_i increasing, >= 2 rows; two rows
 *                  at one time are a jump (the later row holds after it)
 * </pre>
 *
 * Breakpoints are the times where f or its slope jumps (a ramp's two ends,
 * the step and the end of its recovery, a table's rows, a sine's start):
 * addScheduleBreakpoints makes the integrator stop there, so a result never
 * depends on where a step happened to straddle a kink. f must be >= 0 at
 * every time (a magnitude or a capacity is never reversed by its schedule).
 * A jump (the step, a table's repeated time) is left-continuous: the
 * integrator's step ending on the breakpoint sees the value before it, and
 * its restart from there the value after (a right-continuous jump would put
 * the new value into the end derivative of the step before, and the
 * output's interpolation inside that step would bend towards it).
 *
 * A start trigger (`after: {shaft: NAME, speed: ω_t}`, issue 32 item 4)
 * makes the schedule's clock τ start when that shaft's pin speed first rises
 * through ω_t: f = f(τ), τ = t − t_c after the crossing t_c, τ = 0 before
 * (f held at its value at τ = 0). The crossing is a located Simbody event
 * (as a starter's switch speed, StarterEvents.h), t_c taken back from the
 * step end just past it along the shaft's acceleration, and the
 * breakpoints are events at t_c + b: neither depends on the output's
 * sampling. A shaft already at or above ω_t when the run starts starts the
 * clock then.
 */
class Schedule {
public:
    enum class Shape { Constant, Ramp, StepRecovery, Sine, Table };

    Schedule() = default;
    /// The shape names the model key accepts, in the order documented.
    static const std::vector<std::string>& shapeNames();
    /// A key of a shape's map, in the order decode() takes the numbers.
    struct Key {
        std::string name;
        std::string unit;  ///< SI unit ("s", "1", "Hz", "rad")
        bool required;
        double defaultValue;
    };
    /// The keys of a shape written as a map (ramp, step_recovery, sine);
    /// empty for table (rows [t, f]) and unknown shapes.
    static const std::vector<Key>& keysOf(const std::string& shape);
    /// From a shape name and its numbers in SI, in the order encode() writes
    /// them ("" or "constant": f = 1). Throws std::invalid_argument with a
    /// reason naming the key at fault ("ramp.duration must be > 0").
    static Schedule decode(const std::string& shape, const std::vector<double>& numbers);
    /// The element key `key` of `spec` (absent: constant). Throws SpecError
    /// located at the key.
    static Schedule fromSpec(const ElementSpec& spec, const std::string& key = "schedule");
    /// As fromSpec, refusing a start trigger (a capacity on the simulated
    /// time: Brake, Clutch), located at the key.
    static Schedule fromSpecUntriggered(const ElementSpec& spec, const std::string& key = "schedule");

    static Schedule ramp(double start, double duration, double from = 0, double to = 1);
    static Schedule stepRecovery(double at, double drop, double recoveryTime);
    static Schedule sine(double mean, double amplitude, double frequencyHz, double phase = 0, double start = 0);
    static Schedule table(const std::vector<double>& times, const std::vector<double>& factors);

    Shape shape() const { return m_shape; }
    const std::string& shapeName() const;
    bool isConstant() const { return m_shape == Shape::Constant; }
    /// f(t) [-].
    double factorAt(double time) const;
    /// Times where f or df/dt jumps, increasing [s].
    std::vector<double> breakpoints() const;
    /// The time from which f no longer changes (last breakpoint; a sine
    /// never settles: +inf) [s].
    double settleTime() const;
    /// f after settleTime (a sine: its mean) [-].
    double finalFactor() const;
    /// The smallest value f takes [-].
    double minimumFactor() const;
    /// One line: "ramp from 0 to 1 over 10 s from 5 s".
    std::string describe() const;

    /// The start trigger: the clock starts when `shaft` first rises through `speed` [rad/s].
    struct Trigger {
        std::string shaft;
        double speed = 0;
    };
    /// Throws std::invalid_argument for an empty shaft or a speed not finite.
    void setTrigger(const Trigger& trigger);
    bool hasTrigger() const { return !m_trigger.shaft.empty(); }
    const Trigger& trigger() const { return m_trigger; }
    /// The schedule's clock in `s` [s]: its time, or with a trigger the time
    /// since it fired (0 before). Copies share the trigger's state.
    double clockAt(const SimTK::State& s) const;
    /// f at the schedule's clock in `s` [-]: what an element applies.
    double factorAt(const SimTK::State& s) const;

private:
    Shape m_shape = Shape::Constant;
    std::vector<double> m_v;  // the shape's numbers, as decode() takes them
    Trigger m_trigger;
    std::shared_ptr<ScheduleClock> m_clock;  // with a trigger: where its start time lives (addScheduleBreakpoints)
    friend void addScheduleBreakpoints(Scene& scene, const Schedule& schedule, const std::string& what);
};

/// The model key of a schedule: a ParamSchema of kind Text marked by its
/// unit "schedule" (optional; absent: f = 1). The reader reads its map into
/// the shape's name (ParamValue::text) and numbers in SI
/// (ParamValue::numbers), as Schedule::decode takes them.
ParamSchema scheduleParam(std::string key, std::string doc);
/// Whether `p` is a schedule key (scheduleParam).
bool isScheduleParam(const ParamSchema& p);

/// Makes the integrator stop at each breakpoint of `schedule` after t = 0
/// (a scheduled switching of kind LoadOn that changes nothing: the step
/// ends on the kink and the integrator restarts from it), named "`what`
/// schedule breakpoint at T s". With a trigger: registers its clock (a
/// discrete variable), the crossing and the breakpoints as located events,
/// the start as a kept value `what.schedule_start` and the probe
/// `what.schedule_clock` [s]. Throws std::invalid_argument for a trigger
/// shaft the scene does not have.
void addScheduleBreakpoints(Scene& scene, const Schedule& schedule, const std::string& what);

}  // namespace milldyn
