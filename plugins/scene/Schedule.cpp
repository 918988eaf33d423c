#include "plugins/scene/Schedule.h"

#include "plugins/scene/Format.h"
#include "plugins/scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace milldyn {

using namespace SimTK;

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

const std::vector<std::string> kShapeNames = {"ramp", "step_recovery", "sine", "table"};

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument(what); }

std::string num(double v) { return formatNumber(v); }

}  // namespace

// ------------------------------------------------ a schedule's trigger (item 4)

/// Where a triggered schedule keeps the instant its clock started: a
/// discrete variable of the force subsystem (NaN until the trigger fires),
/// allocated by ScheduleClockForce when the system's topology is realized.
class ScheduleClock {
public:
    const GeneralForceSubsystem* forces = nullptr;
    mutable DiscreteVariableIndex index;
    double startTime(const State& s) const {
        if (!forces || !index.isValid()) return std::numeric_limits<double>::quiet_NaN();
        return Value<double>::downcast(forces->getDiscreteVariable(s, index));
    }
    void setStartTime(State& s, double t) const {
        Value<double>::updDowncast(forces->updDiscreteVariable(s, index)) = t;
    }
};

namespace {

/// Applies nothing: owns the clock's discrete variable.
class ScheduleClockForce : public Force::Custom::Implementation {
public:
    explicit ScheduleClockForce(std::shared_ptr<ScheduleClock> clock) : m_clock(std::move(clock)) {}
    void realizeTopology(State& s) const override {
        m_clock->index = m_clock->forces->allocateDiscreteVariable(
            s, Stage::Dynamics, new Value<double>(std::numeric_limits<double>::quiet_NaN()));
    }
    void calcForce(const State&, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector&) const override {}
    Real calcPotentialEnergy(const State&) const override { return 0; }

private:
    std::shared_ptr<ScheduleClock> m_clock;
};

/// The crossing as a located Simbody event, as StarterSpeedTrigger: the
/// witness ω − ω_t rises through zero where the shaft passes ω_t (+1 once
/// fired); the clock starts at the step end just past it (the lagged value).
class ScheduleSpeedTrigger : public TriggeredEventHandler {
public:
    ScheduleSpeedTrigger(std::shared_ptr<ScheduleClock> clock, const MobilizedBody& shaft, double speed)
        : TriggeredEventHandler(Stage::Velocity), m_clock(std::move(clock)), m_shaft(shaft), m_speed(speed) {
        getTriggerInfo().setTriggerOnRisingSignTransition(true);
        getTriggerInfo().setTriggerOnFallingSignTransition(false);
        getTriggerInfo().setRequiredLocalizationTimeWindow(kWindow);
    }
    Real getValue(const State& s) const override {
        if (!std::isnan(m_clock->startTime(s))) return 1;
        return pinSpeed(s, m_shaft) - m_speed;
    }
    void handleEvent(State& s, Real, bool& shouldTerminate) const override {
        if (std::isnan(m_clock->startTime(s)) && pinSpeed(s, m_shaft) >= m_speed) m_clock->setStartTime(s, s.getTime());
        shouldTerminate = false;
    }
    static constexpr double kWindow = 1e-6;

private:
    std::shared_ptr<ScheduleClock> m_clock;
    MobilizedBody m_shaft;
    double m_speed;
};

/// A breakpoint of a triggered schedule (its kink at t_start + b), located
/// as an event: the witness t − t_start − b rises through zero (−1 until
/// the clock starts), so a step ends on it as on an untriggered one's.
class ScheduleBreakpointTrigger : public TriggeredEventHandler {
public:
    ScheduleBreakpointTrigger(std::shared_ptr<ScheduleClock> clock, double at)
        : TriggeredEventHandler(Stage::Dynamics), m_clock(std::move(clock)), m_at(at) {
        getTriggerInfo().setTriggerOnRisingSignTransition(true);
        getTriggerInfo().setTriggerOnFallingSignTransition(false);
        getTriggerInfo().setRequiredLocalizationTimeWindow(1e-9);
    }
    Real getValue(const State& s) const override {
        const double t0 = m_clock->startTime(s);
        return std::isnan(t0) ? -1.0 : s.getTime() - t0 - m_at;
    }
    void handleEvent(State&, Real, bool& shouldTerminate) const override { shouldTerminate = false; }

private:
    std::shared_ptr<ScheduleClock> m_clock;
    double m_at;
};

}  // namespace

const std::vector<std::string>& Schedule::shapeNames() { return kShapeNames; }

const std::vector<Schedule::Key>& Schedule::keysOf(const std::string& shape) {
    static const std::vector<Key> ramp = {
        {"start", "s", false, 0.0}, {"duration", "s", true, 0.0}, {"from", "1", false, 0.0}, {"to", "1", false, 1.0}};
    static const std::vector<Key> step = {
        {"at", "s", true, 0.0}, {"drop", "1", true, 0.0}, {"recovery_time", "s", true, 0.0}};
    static const std::vector<Key> sine = {{"mean", "1", false, 1.0},
                                          {"amplitude", "1", true, 0.0},
                                          {"frequency", "Hz", true, 0.0},
                                          {"phase", "rad", false, 0.0},
                                          {"start", "s", false, 0.0}};
    static const std::vector<Key> none;
    if (shape == "ramp") return ramp;
    if (shape == "step_recovery") return step;
    if (shape == "sine") return sine;
    return none;
}

Schedule Schedule::decode(const std::string& shape, const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) bad(shape + ": every number must be finite");
    Schedule s;
    if (shape.empty() || shape == "constant") {
        if (!v.empty()) bad("constant: takes no numbers");
        return s;
    }
    s.m_v = v;
    if (shape == "ramp") {
        if (v.size() != 4) bad("ramp: expected 4 numbers (start, duration, from, to)");
        s.m_shape = Shape::Ramp;
        if (!(v[0] >= 0)) bad("ramp.start must be >= 0 s, got " + num(v[0]) + " s");
        if (!(v[1] > 0)) bad("ramp.duration must be > 0 s, got " + num(v[1]) + " s");
    } else if (shape == "step_recovery") {
        if (v.size() != 3) bad("step_recovery: expected 3 numbers (at, drop, recovery_time)");
        s.m_shape = Shape::StepRecovery;
        if (!(v[0] >= 0)) bad("step_recovery.at must be >= 0 s, got " + num(v[0]) + " s");
        if (!(v[1] <= 1)) bad("step_recovery.drop must be <= 1 (the whole magnitude), got " + num(v[1]));
        if (!(v[2] > 0)) bad("step_recovery.recovery_time must be > 0 s, got " + num(v[2]) + " s");
    } else if (shape == "sine") {
        if (v.size() != 5) bad("sine: expected 5 numbers (mean, amplitude, frequency, phase, start)");
        s.m_shape = Shape::Sine;
        if (!(v[2] > 0)) bad("sine.frequency must be > 0 Hz, got " + num(v[2]) + " Hz");
        if (!(v[4] >= 0)) bad("sine.start must be >= 0 s, got " + num(v[4]) + " s");
    } else if (shape == "table") {
        if (v.size() < 4 || v.size() % 2 != 0) bad("table: expected at least 2 rows [time, factor]");
        s.m_shape = Shape::Table;
        // Two rows at one time are a jump (the later row holds from that
        // time on); three are ambiguous.
        for (std::size_t i = 2; i < v.size(); i += 2) {
            const bool jump = v[i] == v[i - 2] && !(i >= 4 && v[i - 4] == v[i]);
            if (!(v[i] > v[i - 2] || jump))
                bad("table: times must increase (two equal times make a jump), row " + std::to_string(i / 2 + 1) +
                    " has " + num(v[i]) + " s after " + num(v[i - 2]) + " s");
        }
        if (!(v[0] >= 0)) bad("table: times must be >= 0 s, got " + num(v[0]) + " s");
    } else {
        bad("unknown schedule '" + shape + "'");
    }
    if (!(s.minimumFactor() >= 0))
        bad(shape + ": the factor must stay >= 0 (it scales a magnitude or a capacity), its least value is " +
            num(s.minimumFactor()));
    return s;
}

Schedule Schedule::fromSpec(const ElementSpec& spec, const std::string& key) {
    if (!spec.has(key)) return Schedule();
    try {
        Schedule s = decode(spec.text(key), spec.numbers(key));
        const std::vector<std::string>& after = spec.names(key);
        if (!after.empty()) s.setTrigger({after[0], spec.number(key)});
        return s;
    } catch (const std::invalid_argument& e) {
        throw spec.error(key, e.what());
    }
}

Schedule Schedule::fromSpecUntriggered(const ElementSpec& spec, const std::string& key) {
    Schedule s = fromSpec(spec, key);
    if (s.hasTrigger())
        throw spec.error(key, "after: starts a load's or a torque source's schedule at an event; a capacity's "
                              "schedule runs on the simulated time (give its times from t = 0)");
    return s;
}

Schedule Schedule::ramp(double start, double duration, double from, double to) {
    return decode("ramp", {start, duration, from, to});
}
Schedule Schedule::stepRecovery(double at, double drop, double recoveryTime) {
    return decode("step_recovery", {at, drop, recoveryTime});
}
Schedule Schedule::sine(double mean, double amplitude, double frequencyHz, double phase, double start) {
    return decode("sine", {mean, amplitude, frequencyHz, phase, start});
}
Schedule Schedule::table(const std::vector<double>& times, const std::vector<double>& factors) {
    if (times.size() != factors.size()) bad("table: as many times as factors");
    std::vector<double> v;
    for (std::size_t i = 0; i < times.size(); ++i) {
        v.push_back(times[i]);
        v.push_back(factors[i]);
    }
    return decode("table", v);
}

const std::string& Schedule::shapeName() const {
    static const std::string constant = "constant";
    switch (m_shape) {
        case Shape::Constant: return constant;
        case Shape::Ramp: return kShapeNames[0];
        case Shape::StepRecovery: return kShapeNames[1];
        case Shape::Sine: return kShapeNames[2];
        case Shape::Table: return kShapeNames[3];
    }
    return constant;
}

double Schedule::factorAt(double t) const {
    const std::vector<double>& v = m_v;
    switch (m_shape) {
        case Shape::Constant: return 1;
        case Shape::Ramp: {
            const double x = std::min(std::max((t - v[0]) / v[1], 0.0), 1.0);
            return v[2] + (v[3] - v[2]) * x;
        }
        case Shape::StepRecovery: {
            // Left-continuous at the step: the step ending on it sees the
            // value before, the integrator's restart from it the value after.
            if (t <= v[0] || t >= v[0] + v[2]) return 1;
            return 1 - v[1] * (1 - (t - v[0]) / v[2]);
        }
        case Shape::Sine: return v[0] + v[1] * std::sin(kTwoPi * v[2] * (std::max(t, v[4]) - v[4]) + v[3]);
        case Shape::Table: {
            const std::size_t rows = v.size() / 2;
            if (t <= v[0]) return v[1];
            if (t > v[2 * (rows - 1)]) return v[2 * rows - 1];
            // First row at or after t (rows are few: a linear search); at a
            // jump's time the earlier row holds (left-continuous, as a step).
            std::size_t i = 1;
            while (v[2 * i] < t) ++i;
            const double t0 = v[2 * i - 2], f0 = v[2 * i - 1], t1 = v[2 * i], f1 = v[2 * i + 1];
            return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
        }
    }
    return 1;
}

std::vector<double> Schedule::breakpoints() const {
    const std::vector<double>& v = m_v;
    switch (m_shape) {
        case Shape::Constant: return {};
        case Shape::Ramp: return {v[0], v[0] + v[1]};
        case Shape::StepRecovery: return {v[0], v[0] + v[2]};
        case Shape::Sine: return {v[4]};
        case Shape::Table: {
            std::vector<double> times;
            for (std::size_t i = 0; i < v.size(); i += 2)
                if (times.empty() || times.back() != v[i]) times.push_back(v[i]);
            return times;
        }
    }
    return {};
}

double Schedule::settleTime() const {
    if (m_shape == Shape::Constant) return 0;
    if (m_shape == Shape::Sine) return std::numeric_limits<double>::infinity();
    return breakpoints().back();
}

double Schedule::finalFactor() const {
    switch (m_shape) {
        case Shape::Constant: return 1;
        case Shape::Ramp: return m_v[3];
        case Shape::StepRecovery: return 1;
        case Shape::Sine: return m_v[0];
        case Shape::Table: return m_v.back();
    }
    return 1;
}

double Schedule::minimumFactor() const {
    const std::vector<double>& v = m_v;
    switch (m_shape) {
        case Shape::Constant: return 1;
        case Shape::Ramp: return std::min(v[2], v[3]);
        case Shape::StepRecovery: return std::min(1.0, 1 - v[1]);
        case Shape::Sine: return v[0] - std::abs(v[1]);
        case Shape::Table: {
            double least = v[1];
            for (std::size_t i = 1; i < v.size(); i += 2) least = std::min(least, v[i]);
            return least;
        }
    }
    return 1;
}

std::string Schedule::describe() const {
    const std::vector<double>& v = m_v;
    switch (m_shape) {
        case Shape::Constant: return "constant (factor 1)";
        case Shape::Ramp:
            return "ramp from " + num(v[2]) + " to " + num(v[3]) + " over " + num(v[1]) + " s from " + num(v[0]) + " s";
        case Shape::StepRecovery:
            return "step at " + num(v[0]) + " s to " + num(1 - v[1]) + ", recovered linearly to 1 in " + num(v[2]) +
                   " s";
        case Shape::Sine:
            return "sine " + num(v[0]) + " + " + num(v[1]) + "·sin(2π·" + num(v[2]) + " Hz·(t − " + num(v[4]) +
                   " s) + " + num(v[3]) + " rad)";
        case Shape::Table: return "table of " + std::to_string(v.size() / 2) + " rows, linear between them";
    }
    return "";
}

ParamSchema scheduleParam(std::string key, std::string doc) {
    ParamSchema p = ParamSchema::text(std::move(key), std::move(doc));
    p.unit = "schedule";
    p.required = false;
    return p;
}

bool isScheduleParam(const ParamSchema& p) { return p.kind == ParamKind::Text && p.unit == "schedule"; }

void Schedule::setTrigger(const Trigger& trigger) {
    if (trigger.shaft.empty()) bad("after.shaft: name a body");
    if (!std::isfinite(trigger.speed)) bad("after.speed must be finite");
    m_trigger = trigger;
    m_clock = std::make_shared<ScheduleClock>();
}

double Schedule::clockAt(const SimTK::State& s) const {
    if (!m_clock) return s.getTime();
    const double t0 = m_clock->startTime(s);
    return std::isnan(t0) ? 0.0 : s.getTime() - t0;
}

double Schedule::factorAt(const SimTK::State& s) const { return factorAt(clockAt(s)); }

void addScheduleBreakpoints(Scene& scene, const Schedule& schedule, const std::string& what) {
    if (!schedule.hasTrigger()) {
        for (double t : schedule.breakpoints())
            if (t > 0)
                scene.addSwitchEvent({Scene::SwitchEvent::Kind::LoadOn, t,
                                      what + " schedule breakpoint at " + formatNumber(t) + " s",
                                      [](SimTK::State&) {}});
        return;
    }
    const Schedule::Trigger& trigger = schedule.trigger();
    const SceneBody* body = scene.findBody(trigger.shaft);
    if (!body) throw std::invalid_argument("schedule.after.shaft: no body named '" + trigger.shaft + "'");
    std::shared_ptr<ScheduleClock> clock = schedule.m_clock;
    clock->forces = &scene.forces();
    Force::Custom force(scene.forces(), new ScheduleClockForce(clock));
    const MobilizedBody shaft = body->mobod;
    const double speed = trigger.speed;
    scene.system().addEventHandler(new ScheduleSpeedTrigger(clock, shaft, speed));
    for (double b : schedule.breakpoints())
        if (b > 0) scene.system().addEventHandler(new ScheduleBreakpointTrigger(clock, b));
    // The clock starts at the step end at or just past the crossing (within
    // the event's window); the start time is the crossing itself, back from
    // there along the shaft's acceleration (ω − ω_t)/ω̇ <= the window.
    scene.addLaggedValue({what + ".schedule_start", true,
                          [clock, shaft, speed](const State& s) {
                              const double kept = clock->startTime(s);
                              if (!std::isnan(kept)) return kept;
                              const double w = pinSpeed(s, shaft);
                              if (!(w >= speed)) return std::numeric_limits<double>::quiet_NaN();
                              const double a = shaft.getOneUDot(s, MobilizerUIndex(0));
                              const double back = a > 0 ? (w - speed) / a : 0.0;
                              return back <= 1e-3 ? s.getTime() - back : s.getTime();
                          },
                          [clock](State& s, double v) {
                              if (std::isnan(v) || !std::isnan(clock->startTime(s))) return 0.0;
                              clock->setStartTime(s, v);
                              return 1.0;
                          }});
    scene.addProbe({what + ".schedule_clock", "s", ProbeRole::Generic, Stage::Dynamics,
                    [schedule](const State& s) { return schedule.clockAt(s); },
                    "time on the schedule's clock: since " + trigger.shaft + " first reached " +
                        formatNumber(speed) + " rad/s, 0 before"});
    scene.note("schedule of " + what, "its clock starts when " + trigger.shaft + " first rises through " +
                                          formatNumber(speed) + " rad/s (a located event); " + schedule.describe() +
                                          ", times from that instant");
}

}  // namespace milldyn
