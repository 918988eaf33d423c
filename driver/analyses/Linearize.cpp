// linearize: the linear model about steady running, its eigenvalues,
// natural frequencies and mode shapes.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/analyses/LinearModel.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace milldyn {

std::vector<int> modeNumbers(const LinearModel& lm) {
    std::vector<int> number(lm.naturalFrequencies.size(), 0);
    int k = 0;
    for (int m : elasticModes(lm)) number[m] = ++k;
    return number;
}

void addLinearModelOutputs(const LinearModel& lm, AnalysisResult& result) {
    const int n = static_cast<int>(lm.M.rows());
    auto matrix = [](const std::string& name, const std::string& unit, const Eigen::MatrixXd& m) {
        NamedMatrix out{name, unit, {}};
        out.rows.assign(m.rows(), std::vector<double>(m.cols(), 0.0));
        for (Eigen::Index i = 0; i < m.rows(); ++i)
            for (Eigen::Index j = 0; j < m.cols(); ++j) out.rows[i][j] = m(i, j);
        return out;
    };
    result.dofNames = lm.dofNames;
    result.matrices = {matrix("M", "kg*m^2", lm.M), matrix("C", "N*m*s/rad", lm.C), matrix("K", "N*m/rad", lm.K),
                       matrix("A", "1/s", lm.A)};

    auto eigenTable = [&](const std::string& name, const Eigen::VectorXcd& ev) {
        DataTable eig{name, {"index", "real", "imag", "frequency", "damping_ratio"}, {"1", "1/s", "rad/s", "Hz", "1"}, {}};
        for (Eigen::Index i = 0; i < ev.size(); ++i) {
            const auto l = ev[i];
            // The rigid rotation's eigenvalue is 0 up to differencing noise: no damping ratio.
            const bool rigid = isRigidEigenvalue(lm, l);
            eig.rows.push_back({double(i + 1), l.real(), l.imag(), std::abs(l.imag()) / (2 * M_PI),
                                rigid ? 0.0 : -l.real() / std::abs(l)});
        }
        return eig;
    };
    // The chosen motor model's (scenario.motor_model), then, with dq
    // machines, each model's for comparison.
    result.extraTables.push_back(eigenTable("eigenvalues", lm.eigenvalues));
    if (lm.Afull.size()) {
        // With the motors' electrical states (dq machines' fluxes).
        result.matrices.push_back(matrix("A_with_motor_states", "1/s", lm.Afull));
        result.matrices.push_back(matrix("A_frozen_flux", "1/s", lm.Afrozen));
        result.matrices.push_back(matrix("A_static_slope", "1/s", lm.Astatic));
        result.extraTables.push_back(eigenTable("eigenvalues_with_motor_states", lm.eigenvaluesFull));
        result.extraTables.push_back(eigenTable("eigenvalues_frozen_flux", lm.eigenvaluesFrozen));
        result.extraTables.push_back(eigenTable("eigenvalues_static_slope", lm.eigenvaluesStatic));
        result.extraTables.push_back(modeDampingTable(lm));
    }

    // Numbered as every output numbers modes (elasticModes): elastic 1, 2,
    // ... ascending, rigid-body modes 0.
    const std::vector<int> numbers = modeNumbers(lm);
    DataTable modes{"modes", {"mode", "natural_frequency", "natural_frequency_hz"}, {"1", "rad/s", "Hz"}, {}};
    for (int i = 0; i < n; ++i)
        modes.rows.push_back({double(numbers[i]), lm.naturalFrequencies[i], lm.naturalFrequencies[i] / (2 * M_PI)});
    result.extraTables.push_back(modes);
}

namespace {

/// Per mobility, the factor that refers its amplitude to `reference`: a body
/// on a pin on ground turning at u_k in the operating point is scaled by
/// u_ref/u_k (its speed ratio to the reference shaft: a geared body's angle
/// seen from that shaft); a body on another body (a charge on its drum, a
/// drum on its carrier) measures its angle relative to that body and takes
/// the body's factor; a body standing still in the operating point keeps 1.
std::vector<double> referralFactors(const Scene& scene, const SimTK::State& state, const SceneBody& reference,
                                    std::vector<std::string>& unreferred) {
    std::vector<double> factor(state.getNU(), 1.0);
    const double uRef = pinSpeed(state, reference.mobod);
    std::map<SimTK::MobilizedBodyIndex, double> ofBody;
    // Bodies are added parents first, so a parent's factor is known.
    for (const SceneBody& b : scene.bodies()) {
        const SimTK::MobilizedBody parent = b.mobod.getParentMobilizedBody();
        double f = 1;
        if (!parent.isGround()) {
            auto it = ofBody.find(parent.getMobilizedBodyIndex());
            f = it == ofBody.end() ? 1.0 : it->second;
        } else {
            const double u = pinSpeed(state, b.mobod);
            if (std::abs(u) > 1e-9 * std::abs(uRef) && std::abs(uRef) > 0) f = uRef / u;
            else if (b.name != reference.name) unreferred.push_back(b.name);
        }
        ofBody[b.mobod.getMobilizedBodyIndex()] = f;
        const int first = b.mobod.getFirstUIndex(state), nu = b.mobod.getNumU(state);
        for (int i = 0; i < nu; ++i) factor[first + i] = f;
    }
    return factor;
}

}  // namespace

AnalysisResult runLinearize(const ModelSpec& spec, const ProgressFn&) {
    auto scene = buildScene(spec);
    SimTK::State state = initialState(*scene, spec);
    if (spec.scenario.text("operating_point") == "steady") state = solveSteadyState(*scene, state);
    LinearModel lm = linearizeScene(*scene, state, true, true, motorModelFromName(spec.scenario.text("motor_model")));

    AnalysisResult result;
    result.derived = derivedResults(*scene);
    result.analysis = "linearize";
    const int n = static_cast<int>(lm.M.rows());              // modes: the independent coordinates
    const int nb = static_cast<int>(lm.modeShapes.rows());    // every mobility
    if (!lm.eliminated.empty()) {
        std::string kept, gone;
        for (int j : lm.independent) kept += (kept.empty() ? "" : ", ") + lm.bodyNames[j];
        for (int j : lm.eliminated) gone += (gone.empty() ? "" : ", ") + lm.bodyNames[j];
        result.notes.push_back("kinematic constraints reduced: independent coordinates " + kept + "; " + gone +
                               " follow from the constraints (u = N v); M, C, K, A are in the independent ones");
    }
    // Mode shapes referred to a shaft the file names (amplitudes of geared
    // bodies times their speed ratio to it), each scaled to max |entry| = 1.
    const std::string reference = spec.scenario.text("reference_shaft");
    if (!reference.empty()) {
        std::vector<std::string> unreferred;
        const std::vector<double> f = referralFactors(*scene, state, *scene->findBody(reference), unreferred);
        for (int m = 0; m < n; ++m) {
            for (int b = 0; b < nb; ++b) lm.modeShapes(b, m) *= f[b];
            Eigen::Index at = 0;
            lm.modeShapes.col(m).cwiseAbs().maxCoeff(&at);
            lm.modeShapes.col(m) /= lm.modeShapes(at, m);
        }
        result.notes.push_back("mode shapes referred to " + reference +
                               " (amplitude × speed ratio to it at the operating point)");
        for (const auto& b : unreferred)
            result.notes.push_back("mode shapes: " + b + " stands still at the operating point, amplitude not referred");
    } else {
        result.notes.push_back("mode shapes in each body's own angle (scenario.reference_shaft refers them to one shaft)");
    }
    // The main table: one row per mode, one column per mobility (every body,
    // the eliminated ones too), named by its body.
    result.tableName = "mode_shapes";
    result.plotXLabel = "mode";
    result.columnNames = {"mode", "natural_frequency"};
    result.columnUnits = {"1", "Hz"};
    for (const auto& name : lm.bodyNames) {
        result.columnNames.push_back(name);
        result.columnUnits.push_back("1");
    }
    const std::vector<int> numbers = modeNumbers(lm);
    for (int m = 0; m < n; ++m) {
        std::vector<double> row = {double(numbers[m]), lm.naturalFrequencies[m] / (2 * M_PI)};
        for (int b = 0; b < nb; ++b) row.push_back(lm.modeShapes(b, m));
        result.rows.push_back(row);
    }
    addLinearModelOutputs(lm, result);

    // Rigid rotation of the whole train is a zero-frequency mode; report the
    // elastic ones.
    // (and the differencing's round-off: a train with no stiffness at all
    // has only rigid modes).
    const double rigidBelow = rigidModeBound(lm);
    int elastic = 0;
    for (int m : elasticModes(lm)) {
        ++elastic;
        // The body that moves most in this mode names it.
        Eigen::Index at = 0;
        lm.modeShapes.col(m).cwiseAbs().maxCoeff(&at);
        const std::string number = std::to_string(elastic);
        result.results.push_back({"natural_frequency_" + number, lm.naturalFrequencies[m], "rad/s",
                                  "undamped elastic mode " + number + " (" +
                                      std::to_string(lm.naturalFrequencies[m] / (2 * M_PI)) + " Hz), largest at " +
                                      lm.bodyNames[at]});
        // The same in Hz, the unit in the name (natural_frequency_k keeps rad/s).
        result.results.push_back({"natural_frequency_" + number + "_hz", lm.naturalFrequencies[m] / (2 * M_PI), "Hz",
                                  "undamped elastic mode " + number + " in Hz (mode_shapes.csv row with mode " +
                                      number + ")"});
    }
    if (elastic < n)
        result.notes.push_back("modes numbered as in every output: elastic modes 1.." + std::to_string(elastic) +
                               " in ascending frequency; " + std::to_string(n - elastic) +
                               " rigid-body mode(s) (at most " + std::to_string(rigidBelow) +
                               " rad/s) are mode 0 in mode_shapes.csv and modes.csv");
    for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i) {
        const auto l = lm.eigenvalues[i];
        if (l.imag() < 0) continue;  // one of each conjugate pair
        const std::string tag = "eigenvalue_" + std::to_string(i + 1);
        result.results.push_back({tag + "_real", l.real(), "1/s", std::string("damped eigenvalue (motor_model ") + motorModelName(lm.motorModel) + "), real part"});
        if (l.imag() > 0) result.results.push_back({tag + "_imag", l.imag(), "rad/s", std::string("damped eigenvalue (motor_model ") + motorModelName(lm.motorModel) + "), imaginary part"});
    }
    // Which motor model each mode's damping comes from (per mode, all three side by side).
    for (const std::string& note : motorDampingNotes(*scene, lm)) result.notes.push_back(note);
    for (Eigen::Index i = 0; i < lm.eigenvaluesFull.size(); ++i) {
        const auto l = lm.eigenvaluesFull[i];
        if (l.imag() <= 0) continue;  // the oscillating ones, one of each pair
        const std::string tag = "eigenvalue_with_motor_states_" + std::to_string(i + 1);
        result.results.push_back({tag + "_real", l.real(), "1/s", "eigenvalue with the motors' flux states, real part"});
        result.results.push_back({tag + "_imag", l.imag(), "rad/s", "eigenvalue with the motors' flux states, imaginary part"});
        result.results.push_back({tag + "_damping_ratio", -l.real() / std::abs(l), "1",
                                  "damping ratio with the motors' flux states"});
    }
    if (elastic == 0)
        result.notes.push_back("no elastic mode: every natural frequency is at most " +
                               std::to_string(rigidBelow) + " rad/s, the differencing's round-off (rigid motion)");
    result.results.push_back({"degrees_of_freedom", double(n), "1", "independent coordinates of the linearized system (mobilities less constraints)"});
    // The operating point: every body's speed, and the probes that describe
    // a loaded running point (charge lags, load torques).
    for (const auto& b : scene->bodies())
        result.results.push_back({"operating_point." + b.name + ".speed", pinSpeed(state, b.mobod), "rad/s",
                                  "speed about its joint at the operating point"});
    scene->system().realize(state, SimTK::Stage::Acceleration);
    for (const auto& p : scene->probes()) {
        const bool lag = p.name.size() > 4 && p.name.compare(p.name.size() - 4, 4, ".lag") == 0;
        if (lag || p.role == ProbeRole::ResistanceTorque || p.role == ProbeRole::DriveTorque)
            result.results.push_back({"operating_point." + p.name, p.value(state), p.unit, "at the operating point"});
    }
    result.notes.push_back("operating point: " + spec.scenario.text("operating_point") + ", speed of " +
                           scene->bodies().front().name + " " +
                           std::to_string(pinSpeed(state, scene->bodies().front().mobod)) + " rad/s");
    return result;
}

AnalysisKind linearizeKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& linearize = kind.schema;
    linearize.type = "linearize";
    linearize.doc = "Mass, damping and stiffness matrices about steady running (numerical Jacobians), "
                    "eigenvalues, natural frequencies and mode shapes.";
    linearize.params = {
        P::choice("operating_point", {"steady", "file"},
                  "steady: solved steady running about the mean load; file: the bodies' initial_* keys")
            .optional("steady"),
        P::body("reference_shaft", "mode shapes referred to this shaft: amplitudes times the speed ratio to it "
                                   "(default: each body's own angle)")
            .optional(""),
        motorModelParam(),
    };
    kind.run = [](const ModelSpec& spec, const ProgressFn& progress, const SampleObserver&) {
        return runLinearize(spec, progress);
    };
    return kind;
}

}  // namespace milldyn
