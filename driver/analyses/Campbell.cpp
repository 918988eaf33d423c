// campbell: natural frequencies against running speed, the excitation
// lines, and where they cross.
//
// At each speed Ω of the reference shaft (its speed magnitude) in
// [speed_min, speed_max] the train is linearized about its operating point
// at that speed (linearizeScene, scenario.motor_model as in linearize), and
// its undamped elastic natural frequencies ω_m(Ω) (K v = ω² M v; modes
// numbered 1, 2, ... ascending at each speed, rigid-body modes are mode 0
// and not drawn: elasticModes) are set against the excitation lines f_L(Ω),
// all in rad/s (Hz beside):
//   shaft orders  f = o·|ω_s|, ω_s the speed of the line's shaft at that
//                 operating point (the train's own speed ratios, belt slip
//                 included), o events per revolution of that shaft:
//                   AngleLoad harmonic k of n cycles/rev: o = k·n
//                   (Scene::orderExcitations; harmonics of zero amplitude
//                   are not lines), gear mesh: o = z1 of gear 1,
//                   ShaftBelt passing: o = 2π·r1/L per revolution of the
//                   driver (belt speed r1·ω1 over the open belt's length
//                   L = r_s(π − 2β) + r_l(π + 2β) + 2·l·cos β, sin β =
//                   |r2 − r1|/l, l the centre distance),
//                   extra_orders: o per revolution of the reference shaft;
//   time lines    f = P_k, fixed (a PeriodicLoad's harmonics: a time clock);
//   supply        f = m·p·ω_c (m in supply_multiples, p pole pairs, ω_c the
//                 synchronous speed at that point: scaled with the supply);
//   twice slip    f = 2·p·|ω_c − |ω_motor||.
// Each line is also given per revolution of the reference shaft, f/Ω at
// the crossing (the order it is, referred through the speed ratios).
//
// A crossing of mode m with line L is a root of d(Ω) = ω_m(Ω) − f_L(Ω):
// bracketed by a sign change between neighbouring grid speeds and located
// by the Illinois method (regula falsi with halving of the stale end) on
// d, every evaluation a new operating point and linearization at that
// speed, until the bracket is 1e-9·Ω wide (or d = 0 to 1e-12·ω_m).
//
// The operating point at speed Ω (scenario.operating_point):
//   auto (default): supply_scaled when a motor is fed by a frequency
//     converter (starter: frequency_converter), else scaled_state.
//   supply_scaled: every motor's supply scaled by a factor a, as a
//     frequency converter runs it: an InductionMotor's torque–speed curve
//     scaled along the speed axis (every speed key × a: synchronous, rated,
//     pull-up, breakdown, table and switch speeds: the same torque at the
//     same relative slip), a DqInductionMotor's circuit fed at frequency ×
//     a and phase voltage × a (V/f constant); steady running about the mean
//     load solved for each a (solveSteadyState), a found by the secant
//     method so that the reference shaft runs at Ω (to 1e-10·Ω).
//   scaled_state: the model's own steady running with every speed × Ω/Ω0
//     (speed ratios, angles and twists kept; elements' own states set to
//     their steady running at those speeds), not re-solved: the loads and
//     motors are linearized where the rated supply would not hold them (an
//     induction motor's slope at a slip it would not run at). For a train
//     without a motor to scale, or to see the structure alone.

#include "driver/analyses/Campbell.h"

#include "driver/analyses/AnalysisRegistry.h"

#include "driver/SceneBuilder.h"
#include "driver/analyses/LinearModel.h"
#include "plugins/scene/DriveCapabilities.h"
#include "plugins/scene/Format.h"
#include "plugins/scene/HarmonicForcing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace milldyn {

namespace {

constexpr double kTwoPi = 2 * M_PI;
constexpr double kRpm = 60 / kTwoPi;  // rad/s → rpm

/// One excitation line.
struct Line {
    enum class Kind { Shaft, Time, Supply, TwiceSlip };
    std::string name;  ///< column stem
    Kind kind = Kind::Shaft;
    std::string body;  ///< Shaft: the shaft whose revolutions count; TwiceSlip: the motor's shaft
    double order = 0;  ///< Shaft: events per revolution of `body`; Supply: m·p; TwiceSlip: 2p
    double fixed = 0;  ///< Time: P_k [rad/s]; Supply, TwiceSlip: ω_c at a = 1 [rad/s]
    std::string what;  ///< in words, for the results' docs
};

/// A motor whose supply can be scaled (supply_scaled) and gives supply lines.
struct Motor {
    std::size_t element = 0;  ///< index into spec.elements
    std::string name, body;
    double polePairs = 0;
    double synchronous = 0;  ///< ω_c at rated supply [rad/s]
    std::vector<std::string> keys;  ///< its keys that scale with the supply frequency
};

/// The train at one speed.
struct Point {
    double speed = 0;  ///< |ω| of the reference shaft [rad/s]
    double scale = 1;  ///< supply scale a (supply_scaled)
    std::vector<double> modes;  ///< elastic natural frequencies, ascending [rad/s]
    std::vector<double> lines;  ///< each line's frequency [rad/s]
};

class CampbellModel {
public:
    CampbellModel(const ModelSpec& spec) : m_spec(spec), m_sc(spec.scenario) {
        m_motorModel = motorModelFromName(m_sc.text("motor_model"));
        m_base = buildScene(spec);
        // auto: a converter-fed motor's supply is scaled; a direct-on-line
        // machine passes the range only in its start, at its rated supply.
        const std::string rule = m_sc.text("operating_point");
        m_supplyScaled = rule == "supply_scaled";
        if (rule == "auto")
            for (const auto& d : m_base->drives())
                if (const auto* f = m_base->findElement<SupplyFedDrive>(d.element); f && f->converterFed())
                    m_supplyScaled = true;
        m_reference = referenceShaft();
        findMotors();
        if (m_supplyScaled && m_motors.empty())
            throw m_sc.error("operating_point", "supply_scaled: the model has no motor on an electrical supply "
                                                "(an induction motor) whose supply could be scaled; use "
                                                "operating_point: scaled_state");
        m_steady = solveSteadyState(*m_base, initialState(*m_base, spec));
        m_speed0 = std::abs(pinSpeed(m_steady, m_base->findBody(m_reference)->mobod));
        if (!(m_speed0 > 0))
            throw AnalysisError("campbell: " + m_reference + " stands still in steady running: no running speed to "
                                                             "scale");
        findLines();
    }

    const std::string& reference() const { return m_reference; }
    const Scene& scene() const { return *m_base; }
    double operatingSpeed() const { return m_speed0; }
    const std::vector<Line>& lines() const { return m_lines; }
    bool supplyScaled() const { return m_supplyScaled; }
    std::size_t evaluations() const { return m_evaluations; }

    /// The train at speed `speed` of the reference shaft; a failure names
    /// the speed.
    Point at(double speed) {
        try {
            return atSpeed(speed);
        } catch (const AnalysisError& e) {
            throw AnalysisError("campbell at " + formatNumber(speed) + " rad/s of " + m_reference + ": " + e.what());
        }
    }

private:
    Point atSpeed(double speed) {
        ++m_evaluations;
        if (!m_supplyScaled) {
            SimTK::State s = m_steady;
            const double f = speed / m_speed0;
            for (int i = 0; i < s.getNU(); ++i) s.updU()[i] *= f;
            for (const auto& init : m_base->steadyInitializers()) init(s);
            m_base->system().realize(s, SimTK::Stage::Acceleration);
            return evaluate(*m_base, s, 1.0);
        }
        // Secant on the supply scale a: the reference shaft's steady speed
        // Ω(a) = speed. Starts from a = speed/Ω0 (Ω(1) = Ω0).
        auto run = [&](double a, std::unique_ptr<Scene>& scene, SimTK::State& state) {
            ModelSpec scaled = scaledSpec(a);
            scene = buildScene(scaled);
            state = solveSteadyState(*scene, initialState(*scene, scaled));
            return std::abs(pinSpeed(state, scene->findBody(m_reference)->mobod));
        };
        std::unique_ptr<Scene> scene0, scene1;
        SimTK::State s0, s1;
        double a0 = speed / m_speed0;
        double w0 = run(a0, scene0, s0);
        const double tolerance = 1e-10 * speed;
        if (std::abs(w0 - speed) <= tolerance) return evaluate(*scene0, s0, a0);
        double a1 = a0 * speed / w0;
        double w1 = run(a1, scene1, s1);
        for (int i = 0; i < 30 && std::abs(w1 - speed) > tolerance; ++i) {
            if (w1 == w0) break;
            const double a2 = a1 + (speed - w1) * (a1 - a0) / (w1 - w0);
            a0 = a1, w0 = w1;
            std::swap(scene0, scene1);
            s0 = s1;
            a1 = a2;
            w1 = run(a1, scene1, s1);
        }
        if (!(std::abs(w1 - speed) <= 1e-8 * speed))
            throw AnalysisError("campbell: no supply scale runs " + m_reference + " at " + formatNumber(speed) +
                                " rad/s in steady running (reached " + formatNumber(w1) + " rad/s at scale " +
                                formatNumber(a1) + ")");
        return evaluate(*scene1, s1, a1);
    }

    const ModelSpec& m_spec;
    const ElementSpec& m_sc;
    bool m_supplyScaled = true;
    MotorModel m_motorModel = MotorModel::DqStates;
    std::unique_ptr<Scene> m_base;
    SimTK::State m_steady;
    std::string m_reference;
    double m_speed0 = 0;
    std::vector<Motor> m_motors;
    std::vector<Line> m_lines;
    std::size_t m_evaluations = 0;

    /// scenario.reference_shaft, else the first shaft-angle load's first
    /// body, else the first body.
    std::string referenceShaft() const {
        const std::string given = m_sc.text("reference_shaft");
        if (!given.empty()) {
            if (!m_base->findBody(given)) throw m_sc.error("reference_shaft", "'" + given + "' is not a body");
            return given;
        }
        for (const auto& e : m_spec.elements) {
            const HarmonicForcing* h = m_base->findElement<HarmonicForcing>(e.name);
            if (!h || h->forcingClock() != HarmonicForcing::Clock::ShaftAngle || h->forcingBodies().empty()) continue;
            for (const auto& b : m_base->bodies())
                if (b.mobod.getMobilizedBodyIndex() == h->forcingBodies()[0].getMobilizedBodyIndex()) return b.name;
        }
        return m_base->bodies().front().name;
    }

    /// The drives on an electrical supply (SupplyFedDrive), in the model's
    /// order: their pole pairs on scenario.supply_frequency, their rated
    /// synchronous speed and the keys a supply scale multiplies.
    void findMotors() {
        const double grid = m_sc.number("supply_frequency") * kTwoPi;  // [rad/s]
        for (std::size_t i = 0; i < m_spec.elements.size(); ++i) {
            const ElementSpec& e = m_spec.elements[i];
            const SupplyFedDrive* f = m_base->findElement<SupplyFedDrive>(e.name);
            if (!f) continue;
            double p = 0;
            try {
                p = f->polePairsOn(grid);
            } catch (const std::invalid_argument& why) {
                throw m_sc.error("supply_frequency", "'" + e.name + "': " + why.what() +
                                                         "; set supply_frequency to the supply it is rated for");
            }
            const std::vector<std::string> keys = f->supplyFrequencyKeys();
            if (m_supplyScaled)
                if (const std::string why = f->whySupplyNotScalable(); !why.empty()) {
                    std::string list;
                    for (const auto& k : keys) list += (list.empty() ? "" : " and ") + k;
                    throw m_sc.error("operating_point", "supply_scaled scales '" + e.name + "''s " + list + ": " +
                                                            why + ", or use operating_point: scaled_state");
                }
            m_motors.push_back({i, e.name, e.text("body"), p, f->ratedSynchronousSpeed(), keys});
        }
    }

    ModelSpec scaledSpec(double a) const {
        ModelSpec s = m_spec;
        for (const Motor& m : m_motors) {
            ElementSpec& e = s.elements[m.element];
            for (const std::string& key : m.keys) {
                auto it = e.params.find(key);
                if (it == e.params.end()) continue;
                it->second.number *= a;
                for (double& v : it->second.numbers) v *= a;
            }
        }
        return s;
    }

    void findLines() {
        const Scene& scene = *m_base;
        for (const auto& o : scene.orderExcitations())
            m_lines.push_back({o.name, Line::Kind::Shaft, o.body, o.eventsPerRevolution, 0,
                               formatNumber(o.eventsPerRevolution) + " per revolution of " + o.body});
        for (const auto& e : m_spec.elements) {
            const HarmonicForcing* h = scene.findElement<HarmonicForcing>(e.name);
            if (h && h->forcingClock() == HarmonicForcing::Clock::Time) {
                double largest = 0;
                for (int k = 1; k <= h->forcingHarmonicCount(); ++k)
                    largest = std::max(largest, h->forcingAmplitude(k));
                for (int k = 1; k <= h->forcingHarmonicCount(); ++k) {
                    if (!(h->forcingAmplitude(k) > 1e-6 * largest)) continue;
                    m_lines.push_back({e.name + ".harmonic_" + std::to_string(k), Line::Kind::Time, "", 0,
                                       h->forcingOrder(k),
                                       "harmonic " + std::to_string(k) + " of a time-clock load: fixed frequency"});
                }
            }
        }
        std::vector<double> multiples = m_sc.numbers("supply_multiples");
        if (multiples.empty()) multiples = {1.0};
        for (const Motor& m : m_motors) {
            for (double k : multiples)
                m_lines.push_back({m.name + (k == 1 ? std::string(".supply_frequency")
                                                    : ".supply_frequency_x" + formatNumber(k)),
                                   Line::Kind::Supply, m.body, k * m.polePairs, m.synchronous,
                                   formatNumber(k) + " x the supply frequency (" + formatNumber(m.polePairs) +
                                       " pole pairs)"});
            m_lines.push_back({m.name + ".twice_slip_frequency", Line::Kind::TwiceSlip, m.body, 2 * m.polePairs,
                               m.synchronous, "twice the slip frequency, 2p|ω_c − ω|"});
        }
        for (double o : m_sc.numbers("extra_orders"))
            m_lines.push_back({"extra_order_" + formatNumber(o), Line::Kind::Shaft, m_reference, o, 0,
                               formatNumber(o) + " per revolution of " + m_reference + " (extra_orders)"});
    }

    Point evaluate(const Scene& scene, const SimTK::State& state, double a) const {
        Point p;
        p.scale = a;
        p.speed = std::abs(pinSpeed(state, scene.findBody(m_reference)->mobod));
        const LinearModel lm = linearizeScene(scene, state, true, true, m_motorModel);
        for (int m : elasticModes(lm)) p.modes.push_back(lm.naturalFrequencies[m]);
        const double supply = m_supplyScaled ? a : 1.0;
        for (const Line& l : m_lines) {
            switch (l.kind) {
                case Line::Kind::Shaft:
                    p.lines.push_back(l.order * std::abs(pinSpeed(state, scene.findBody(l.body)->mobod)));
                    break;
                case Line::Kind::Time: p.lines.push_back(l.fixed); break;
                case Line::Kind::Supply: p.lines.push_back(l.order * supply * l.fixed); break;
                case Line::Kind::TwiceSlip:
                    p.lines.push_back(
                        l.order * std::abs(supply * l.fixed - std::abs(pinSpeed(state, scene.findBody(l.body)->mobod))));
                    break;
            }
        }
        return p;
    }
};

struct Crossing {
    int mode = 0;  ///< 1-based elastic mode number
    std::size_t line = 0;
    double speed = 0, frequency = 0;  ///< [rad/s], [rad/s]
    double margin = 0;                ///< to the nearest operating speed [%]
    double operating = 0;             ///< that operating speed [rad/s]
};

/// The keys of `scenario: {analysis: campbell}`.
ElementSchema campbellSchema() {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "campbell";
    s.doc = "Campbell diagram: elastic natural frequencies against the reference shaft's speed (linearized at each "
            "speed's operating point) with the excitation lines (load harmonics, gear-mesh and belt-passing orders, "
            "supply and twice slip frequency, fixed-frequency loads, extra orders) and every crossing in the range, "
            "located on the mode curve, with its margin to the operating speeds.";
    s.params = {
        P::body("reference_shaft", "shaft whose speed is the running speed (default: the first shaft-angle load's "
                                   "shaft, else the first body)")
            .optional(""),
        P::quantity("speed_min", "rad/s", "lowest running speed (0: 0.2 x the model's steady speed)")
            .optional(0.0)
            .atLeast(0),
        P::quantity("speed_max", "rad/s", "highest running speed (0: 1.2 x the model's steady speed)")
            .optional(0.0)
            .atLeast(0),
        P::quantity("points", "1", "speeds, evenly spaced, both ends included").optional(41.0).atLeast(2).atMost(
            10000),
        P::choice("operating_point", {"auto", "supply_scaled", "scaled_state"},
                  "supply_scaled: every motor's supply scaled (a converter drive) and steady running solved at each "
                  "speed; scaled_state: the model's steady running with every speed scaled, not re-solved (the "
                  "supply fixed: a direct-on-line start's view); auto: supply_scaled when a motor's starter is a "
                  "frequency_converter, else scaled_state")
            .optional("auto"),
        P::quantityList("operating_speeds", "rad/s", 0, 20,
                        "speeds of the reference shaft the margins are taken to (default: the model's steady speed)")
            .optional(0.0)
            .above(0),
        P::quantityList("extra_orders", "1", 0, 50, "further orders, events per revolution of the reference shaft")
            .optional(0.0)
            .above(0),
        P::quantityList("supply_multiples", "1", 0, 20,
                        "multiples of each motor's supply frequency drawn as lines (default: 1; a 6-pulse converter "
                        "adds 6, 12)")
            .optional(0.0)
            .above(0),
        P::quantity("supply_frequency", "Hz",
                    "supply frequency of InductionMotor elements at rated supply (their pole pairs are "
                    "supply_frequency/synchronous speed)")
            .optional(50.0)
            .above(0),
        motorModelParam(),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const double lo = e.number("speed_min"), hi = e.number("speed_max");
        if (hi > 0 && lo >= hi) throw e.error("speed_max", "must exceed speed_min");
    };
    return s;
}

}  // namespace

AnalysisKind campbellKind() {
    AnalysisKind kind;
    kind.schema = campbellSchema();
    kind.run = [](const ModelSpec& spec, const ProgressFn& progress, const SampleObserver&) {
        return runCampbell(spec, progress);
    };
    return kind;
}

AnalysisResult runCampbell(const ModelSpec& spec, const ProgressFn& progress) {
    const ElementSpec& sc = spec.scenario;
    CampbellModel model(spec);
    const double w0 = model.operatingSpeed();
    const double wMin = sc.number("speed_min") > 0 ? sc.number("speed_min") : 0.2 * w0;
    const double wMax = sc.number("speed_max") > 0 ? sc.number("speed_max") : 1.2 * w0;
    if (!(wMax > wMin))
        throw sc.error("speed_min", "the range " + formatNumber(wMin) + "-" + formatNumber(wMax) +
                                        " rad/s is empty (speed_max defaults to 1.2 x the steady speed " +
                                        formatNumber(w0) + " rad/s)");
    std::vector<double> operating = sc.numbers("operating_speeds");
    if (operating.empty()) operating = {w0};
    const int points = static_cast<int>(sc.number("points"));
    const std::vector<Line>& lines = model.lines();
    const std::string& ref = model.reference();

    std::vector<Point> grid;
    for (int i = 0; i < points; ++i) {
        const double w = i + 1 == points ? wMax : wMin + (wMax - wMin) * i / (points - 1);
        grid.push_back(model.at(w));
        if (grid.back().modes.size() != grid.front().modes.size())
            throw AnalysisError("campbell: " + std::to_string(grid.front().modes.size()) + " elastic modes at " +
                                formatNumber(grid.front().speed) + " rad/s of " + ref + " but " +
                                std::to_string(grid.back().modes.size()) + " at " + formatNumber(w) +
                                " rad/s: a mode turns rigid in the range; narrow it");
        if (progress) progress(i + 1, points);
    }
    const std::size_t nModes = grid.front().modes.size();

    AnalysisResult result;
    result.analysis = "campbell";
    result.tableName = "campbell";
    result.plotXLabel = "speed of " + ref + " [rpm]";
    result.derived = derivedResults(model.scene());
    result.columnNames = {"speed", "speed_rpm"};
    result.columnUnits = {"rad/s", "rpm"};
    if (model.supplyScaled()) {
        result.columnNames.push_back("supply_scale");
        result.columnUnits.push_back("1");
    }
    for (std::size_t m = 0; m < nModes; ++m) {
        const std::string k = std::to_string(m + 1);
        result.columnNames.insert(result.columnNames.end(),
                                  {"natural_frequency_" + k + "_hz", "natural_frequency_" + k + "_rad_per_s"});
        result.columnUnits.insert(result.columnUnits.end(), {"Hz", "rad/s"});
    }
    for (const Line& l : lines) {
        result.columnNames.insert(result.columnNames.end(), {l.name + "_hz", l.name + "_rad_per_s"});
        result.columnUnits.insert(result.columnUnits.end(), {"Hz", "rad/s"});
    }
    for (const Point& p : grid) {
        std::vector<double> row = {p.speed, p.speed * kRpm};
        if (model.supplyScaled()) row.push_back(p.scale);
        for (double w : p.modes) row.insert(row.end(), {w / kTwoPi, w});
        for (double f : p.lines) row.insert(row.end(), {f / kTwoPi, f});
        result.rows.push_back(row);
    }

    // Crossings: d(Ω) = ω_m(Ω) − f_L(Ω), located by Illinois between grid
    // speeds where d changes sign.
    std::vector<Crossing> crossings;
    auto difference = [&](const Point& p, std::size_t m, std::size_t l) { return p.modes[m] - p.lines[l]; };
    for (std::size_t l = 0; l < lines.size(); ++l) {
        for (std::size_t m = 0; m < nModes; ++m) {
            for (std::size_t i = 0; i < grid.size(); ++i) {
                // A root on a grid speed is exact there; between two grid
                // speeds where d changes sign it is located.
                const double fi = difference(grid[i], m, l);
                double root = grid[i].speed, at = grid[i].lines[l];
                if (fi != 0) {
                    if (i + 1 == grid.size()) continue;
                    double a = grid[i].speed, b = grid[i + 1].speed, fa = fi, fb = difference(grid[i + 1], m, l);
                    if (fb == 0 || (fa < 0) == (fb < 0)) continue;
                    int side = 0;
                    for (int it = 0; it < 200 && b - a > 1e-9 * b; ++it) {
                        double c = (a * fb - b * fa) / (fb - fa);
                        if (!(c > a && c < b)) c = 0.5 * (a + b);
                        const Point pc = model.at(c);
                        if (pc.modes.size() != nModes)
                            throw AnalysisError("campbell: the number of elastic modes changes at " +
                                                formatNumber(c) + " rad/s of " + ref);
                        const double fc = difference(pc, m, l);
                        root = c, at = pc.lines[l];
                        if (std::abs(fc) <= 1e-12 * pc.modes[m]) break;
                        if ((fc < 0) == (fa < 0)) {
                            a = c, fa = fc;
                            if (side == -1) fb *= 0.5;
                            side = -1;
                        } else {
                            b = c, fb = fc;
                            if (side == +1) fa *= 0.5;
                            side = +1;
                        }
                    }
                }
                Crossing x{int(m + 1), l, root, at, 0, 0};
                double best = std::numeric_limits<double>::infinity();
                for (double w : operating)
                    if (std::abs(root - w) < best) best = std::abs(root - w), x.operating = w;
                x.margin = (root - x.operating) / x.operating * 100;
                crossings.push_back(x);
            }
        }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
        return std::abs(x.margin) < std::abs(y.margin);
    });

    // campbell_crossings.csv: `order` is the line's index into lines (the
    // writer puts its name: Writers.cpp, campbell_crossings).
    DataTable table{"campbell_crossings",
                    {"mode", "order", "order_per_rev", "speed", "speed_rpm", "frequency_hz", "frequency_rad_per_s",
                     "nearest_operating_speed", "margin"},
                    {"1", "name", "1", "rad/s", "rpm", "Hz", "rad/s", "rad/s", "%"},
                    {}};
    int index = 0;
    for (const Crossing& x : crossings) {
        const Line& l = lines[x.line];
        table.rows.push_back({double(x.mode), double(x.line), x.frequency / x.speed, x.speed, x.speed * kRpm,
                              x.frequency / kTwoPi, x.frequency, x.operating, x.margin});
        const std::string tag = "crossing_" + std::to_string(++index);
        const std::string what = "mode " + std::to_string(x.mode) + " meets " + l.name + " (" + l.what + ")";
        result.results.push_back({tag + "_speed", x.speed, "rad/s", what + ": speed of " + ref});
        result.results.push_back({tag + "_speed_rpm", x.speed * kRpm, "rpm", "the same in rpm"});
        result.results.push_back({tag + "_frequency_hz", x.frequency / kTwoPi, "Hz", "frequency at the crossing"});
        result.results.push_back({tag + "_margin", x.margin, "%",
                                  "(crossing speed − nearest operating speed)/operating speed, " +
                                      formatNumber(x.operating) + " rad/s"});
        char text[400];
        std::snprintf(text, sizeof text,
                      "crossing %d: mode %d meets %s at %.5g rad/s (%.5g rpm) of %s, %.5g Hz: %+.3g %% from the "
                      "operating speed %.5g rpm",
                      index, x.mode, l.name.c_str(), x.speed, x.speed * kRpm, ref.c_str(), x.frequency / kTwoPi,
                      x.margin, x.operating * kRpm);
        result.notes.push_back(text);
    }
    result.extraTables.push_back(table);
    result.results.insert(result.results.begin(),
                          {{"operating_speed", w0, "rad/s", "steady speed of " + ref + " in the model as given"},
                           {"operating_speed_rpm", w0 * kRpm, "rpm", "the same in rpm"},
                           {"speed_min", wMin, "rad/s", "lowest speed of the diagram"},
                           {"speed_max", wMax, "rad/s", "highest speed of the diagram"},
                           {"elastic_modes", double(nModes), "1", "elastic modes (numbered 1.. ascending)"},
                           {"excitation_lines", double(lines.size()), "1", "excitation lines drawn"},
                           {"crossings", double(crossings.size()), "1",
                            "crossings of a mode with a line inside the speed range"}});
    // The natural frequencies at the operating speed (the grid point nearest it is not it: evaluated there).
    const Point here = model.at(w0);
    for (std::size_t m = 0; m < here.modes.size(); ++m) {
        const std::string k = std::to_string(m + 1);
        result.results.push_back({"natural_frequency_" + k + "_hz", here.modes[m] / kTwoPi, "Hz",
                                  "elastic mode " + k + " at the operating speed"});
        result.results.push_back({"natural_frequency_" + k + "_rad_per_s", here.modes[m], "rad/s", "the same in rad/s"});
    }
    result.results.push_back({"operating_points_evaluated", double(model.evaluations()), "1",
                              "linearizations: the grid, each crossing's trial speeds, the operating speed"});
    for (std::size_t o = 0; o < operating.size(); ++o)
        result.results.push_back({"operating_speed_" + std::to_string(o + 1) + "_rpm", operating[o] * kRpm, "rpm",
                                  "operating speed the margins are taken to"});
    char head[300];
    std::snprintf(head, sizeof head,
                  "campbell: %zu elastic mode(s) against %zu excitation line(s) over %.5g-%.5g rpm of %s (%s); "
                  "crossings located by the Illinois method on the mode curve (a new operating point at each trial "
                  "speed) to 1e-9 of the speed",
                  nModes, lines.size(), wMin * kRpm, wMax * kRpm, ref.c_str(),
                  model.supplyScaled() ? "supply scaled at each speed, steady running solved"
                                       : "steady running's state scaled to each speed");
    result.notes.insert(result.notes.begin(), head);
    if (crossings.empty()) result.notes.push_back("no crossing of a mode with an excitation line inside the range");
    return result;
}

}  // namespace milldyn
