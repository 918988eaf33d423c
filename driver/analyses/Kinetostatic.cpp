// kinetostatic: loads at prescribed configurations, no time integration.
// For each carrier angle the state is set (angle, speed, the instant of the
// drive's law), the elements place what they drive (gears, charges), and
// one realization gives the drive torque and the reactions. The unknowns
// of one instant are solved first: held charges' wall torques and journals'
// kept reactions (InstantSolver: quasi-Newton, one realization per
// iteration, starting from the earlier angles' solutions).

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace milldyn {

namespace {

/// Places every element's part of the state from the carrier's angle and
/// speed (gears, charges).
void placeMechanism(const Scene& scene, const SimTK::MobilizedBody& carrier, SimTK::State& s, double angle,
                    double speed) {
    carrier.setOneQ(s, SimTK::MobilizerQIndex(0), angle);
    carrier.setOneU(s, SimTK::MobilizerUIndex(0), speed);
    for (const auto& init : scene.initializers()) init(s);
}

}  // namespace

AnalysisResult runKinetostatic(const ModelSpec& spec, const ProgressFn& progress, const SampleObserver& observer) {
    const ElementSpec& sc = spec.scenario;
    auto scene = buildScene(spec);
    const SceneBody& carrier = scenarioBody(*scene, sc, "carrier");
    const double from = sc.number("angle_from"), to = sc.number("angle_to");
    const int points = static_cast<int>(sc.number("angle_points"));
    const double speed = sc.number("carrier_speed"), tolerance = sc.number("tolerance");

    AnalysisResult result;
    result.derived = derivedResults(*scene);
    result.analysis = "kinetostatic";
    result.tableName = "kinetostatics";
    result.plotXLabel = "carrier angle [rad]";
    result.columnNames = {"carrier_angle", "reduced_inertia"};
    result.columnUnits = {"rad", "kg*m^2"};
    result.columnLabels = {"", ""};
    for (const auto& p : scene->probes()) {
        result.columnNames.push_back(p.name);
        result.columnUnits.push_back(p.unit);
        result.columnLabels.push_back(p.label);
    }

    SimTK::State state = initialState(*scene, spec);
    state.setTime(sc.number("time"));
    // Realizations to Acceleration, counted by the System itself.
    const SimTK::System& system = scene->system();
    const int realizedBefore = system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration);
    // J_pr = 2 KE at unit carrier speed, every part moving as the elements
    // say (charges with their drums or held in the carrier frame), in a
    // State of its own that takes each configuration's q and u: copying a
    // whole State per angle cost 5 % of the analysis' instructions.
    SimTK::State unit = state;
    // One solver for all angles: each angle starts from the last ones'
    // solutions extrapolated, with the Jacobian the earlier angles left.
    InstantSolver instant(*scene);
    for (int k = 0; k < points; ++k) {
        const double angle = points == 1 ? from : from + (to - from) * k / (points - 1);
        placeMechanism(*scene, carrier.mobod, state, angle, speed);
        instant.solve(state, tolerance);
        unit.setTime(state.getTime());
        unit.updQ() = state.getQ();
        unit.updU() = state.getU();
        placeMechanism(*scene, carrier.mobod, unit, angle, 1.0);
        scene->system().realize(unit, SimTK::Stage::Velocity);
        std::vector<double> row = {angle, 2 * scene->system().calcKineticEnergy(unit)};
        for (const auto& p : scene->probes()) row.push_back(p.value(state));
        for (double v : row)
            if (!std::isfinite(v))
                throw AnalysisError("kinetostatic: a non-finite output at carrier angle " + std::to_string(angle) +
                                    " rad");
        result.rows.push_back(std::move(row));
        if (observer) observer(*scene, state, angle);  // realized by the solver
        if (progress) progress(k + 1, points);
    }
    result.statistics.realizations =
        system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration) - realizedBefore;

    result.results.push_back({"reduced_inertia", result.rows.front()[1], "kg*m^2",
                              "J_pr = 2 KE / ω1² at the first angle"});
    std::vector<std::size_t> torqueColumns, reactionColumns;
    for (std::size_t i = 0; i < scene->probes().size(); ++i) {
        const Probe& p = scene->probes()[i];
        const std::size_t c = result.findColumn(p.name);
        double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0, atMax = 0;
        for (const auto& row : result.rows) {
            if (row[c] > hi) { hi = row[c]; atMax = row[0]; }
            lo = std::min(lo, row[c]);
            sum += row[c];
        }
        if (p.role == ProbeRole::DriveTorque) {
            torqueColumns.push_back(c);
            result.results.push_back({p.name + ".first", result.rows.front()[c], p.unit, "at the first angle"});
            result.results.push_back({p.name + ".max", hi, p.unit, "largest over the angles"});
            result.results.push_back({p.name + ".min", lo, p.unit, "smallest over the angles"});
            result.results.push_back({p.name + ".mean", sum / result.rows.size(), p.unit, "mean over the angles"});
        } else if (p.unit == "N" && p.name.size() > 10 && p.name.substr(p.name.size() - 10) == "_magnitude") {
            reactionColumns.push_back(c);
            result.results.push_back({p.name + ".first", result.rows.front()[c], p.unit, "at the first angle"});
            result.results.push_back({p.name + ".max", hi, p.unit, "largest over the angles"});
            result.results.push_back({p.name + ".angle_of_max", atMax, "rad", "carrier angle of the largest"});
        } else if (p.unit == "N*m") {
            torqueColumns.push_back(c);
            result.results.push_back({p.name + ".first", result.rows.front()[c], p.unit, "at the first angle"});
        }
    }
    result.plots.push_back({"drive_torque", torqueColumns});
    result.plots.push_back({"reactions", reactionColumns});
    result.notes.push_back("carrier " + carrier.name + " at " + std::to_string(speed) + " rad/s, t = " +
                           std::to_string(sc.number("time")) + " s of the drive law; " +
                           std::to_string(points) + " angles, no time integration");
    return result;
}

AnalysisKind kinetostaticKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& kin = kind.schema;
    kin.type = "kinetostatic";
    kin.doc = "Loads at prescribed carrier angles: one realization each, no time integration.";
    kin.params = {
        P::body("carrier", "body whose angle is swept (default: the first)").optional(""),
        P::quantity("angle_from", "rad", "first carrier angle").optional(0.0),
        P::quantity("angle_to", "rad", "last carrier angle").optional(2 * M_PI),
        P::quantity("angle_points", "1", "angles, evenly spaced, both ends included").optional(37.0).atLeast(1).atMost(
            100000),
        P::quantity("carrier_speed", "rad/s", "carrier speed ω1").optional(0.0),
        P::quantity("time", "s", "instant of the drive laws (ε(t) of a CarrierDrive)").optional(0.0).atLeast(0),
        P::quantity("tolerance", "1", "relative tolerance of wall torques and journal reactions")
            .optional(1e-12)
            .above(0)
            .below(1),
    };
    kind.run = runKinetostatic;
    kind.solvesEachInstant = true;
    // The carrier angles swept: the pictures' default angles are the first
    // and three more a quarter of the range apart (one with one angle).
    kind.schematicSpan = [](const ElementSpec& sc) {
        SchematicSpan span;
        span.angles = true;
        const double first = sc.number("angle_from"), last = sc.number("angle_to");
        span.from = std::min(first, last);
        span.to = std::max(first, last);
        if (sc.number("angle_points") <= 1) span.defaults = {first};
        else
            for (int k = 0; k < 4; ++k) span.defaults.push_back(first + (last - first) * k / 4);
        return span;
    };
    return kind;
}

}  // namespace milldyn
