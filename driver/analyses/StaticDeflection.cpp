// static_deflection: the equilibrium of the model at rest under its constant
// loads (gravity, preloads), every probe there, and the deflection line of
// each FlexibleRotor.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/analyses/LinearModel.h"
#include "plugins/shafts/FlexibleRotor.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace milldyn {

AnalysisResult runStaticDeflection(const ModelSpec& spec, const ProgressFn&) {
    auto scene = buildScene(spec);
    SimTK::State state = initialState(*scene, spec);
    state.updU() = 0;
    // With a spin speed the coordinates of a FlexibleRotor turn with the
    // shaft, so a synchronous whirl is an equilibrium in them.
    const double spin = spec.scenario.number("spin_speed");
    const SceneBody& spinBody = scenarioBody(*scene, spec.scenario, "spin_body");
    if (spin != 0) spinBody.mobod.setOneU(state, SimTK::MobilizerUIndex(0), spin);
    scene->setExcitationsOn(state, false);
    const SimTK::System& system = scene->system();
    const int n = state.getNU();

    // Newton on the accelerations at rest: K·Δq = M·u̇(q). K has a null space
    // where nothing holds the bodies (the free spin of a shaft); the
    // minimum-norm solution leaves those coordinates where they are.
    auto accelerations = [&](SimTK::State& s) {
        system.realize(s, SimTK::Stage::Acceleration);
        Eigen::VectorXd a(n);
        for (int i = 0; i < n; ++i) a[i] = s.getUDot()[i];
        return a;
    };
    int iterations = 0;
    double step = 0;
    Eigen::VectorXd residualForce;
    for (; iterations < 20; ++iterations) {
        const LinearModel lm = linearizeScene(*scene, state, false);
        residualForce = lm.M * accelerations(state);
        // Modal solution, K v = λ M v with vᵀ M v = 1: Δq = Σ v (vᵀ f)/λ over the
        // elastic modes; modes with λ below 1e-12 of the largest are rigid
        // and take no part. (Measured on the bead mill rotors: the free
        // spin's λ is differencing noise, ~1e-14 of the largest, the first
        // bending mode's 1e-8 or more; the short segments' local modes make
        // the largest λ huge, so 1e-8 would cut real modes.)
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(0.5 * (lm.K + lm.K.transpose()), lm.M);
        const Eigen::VectorXd& lambda = modes.eigenvalues();
        const double lambdaMax = lambda.cwiseAbs().maxCoeff();
        Eigen::VectorXd dq = Eigen::VectorXd::Zero(n);
        for (int m = 0; m < n; ++m) {
            if (lambda[m] <= 1e-12 * lambdaMax) continue;
            const auto v = modes.eigenvectors().col(m);
            dq += v * (v.dot(residualForce) / lambda[m]);
        }
        for (int i = 0; i < n; ++i) state.updQ()[i] += dq[i];
        step = dq.cwiseAbs().maxCoeff();
        if (step <= 1e-14 * (1 + state.getQ().normInf())) break;
    }
    if (iterations == 20)
        throw AnalysisError("static_deflection: no equilibrium after 20 Newton steps (last step " +
                            std::to_string(step) + ")");
    const Eigen::VectorXd a = accelerations(state);
    if (!a.allFinite()) throw AnalysisError("static_deflection: the equilibrium search diverged");

    AnalysisResult result;
    result.derived = derivedResults(*scene);
    result.analysis = "static_deflection";
    result.tableName = "deflection_line";
    result.plotXLabel = "position along the shaft [m]";
    result.columnNames = {"position"};
    result.columnUnits = {"m"};
    std::vector<const FlexibleRotor*> rotors;
    std::vector<std::string> rotorNames;
    for (const auto& e : spec.elements)
        if (const auto* r = scene->findElement<FlexibleRotor>(e.name)) {
            rotors.push_back(r);
            rotorNames.push_back(e.name);
        }
    if (!rotors.empty()) {
        // The first rotor's line (a model with more rotors gets the others' probes only).
        const FlexibleRotor& r = *rotors.front();
        result.columnNames.push_back(rotorNames.front() + ".deflection");
        result.columnUnits.push_back("m");
        result.columnNames.push_back(rotorNames.front() + ".lateral");
        result.columnUnits.push_back("m");
        // The nodes: bearings, seal and discs are among them; between nodes
        // the segments are straight.
        for (double x : r.getNodes()) result.rows.push_back({x, r.calcDeflection(state, x), r.calcLateral(state, x)});
        result.plots.push_back({"deflection_line", {1}});
        if (rotors.size() > 1) result.notes.push_back("deflection line of " + rotorNames.front() + " only");
    }
    for (const auto& p : scene->probes())
        result.results.push_back({p.name, p.value(state), p.unit, "at static equilibrium"});
    // The residual that the null space leaves (an unbalance hanging off the
    // free spin) is reported, not hidden.
    SimTK::Matrix Msim;
    scene->matter().calcM(state, Msim);
    Eigen::VectorXd force(n);
    for (int i = 0; i < n; ++i) {
        force[i] = 0;
        for (int j = 0; j < n; ++j) force[i] += Msim(i, j) * a[j];
    }
    result.results.push_back({"equilibrium_residual", force.cwiseAbs().maxCoeff(), "1",
                              "largest generalized force left (N or N*m): nonzero only along unrestrained "
                              "coordinates"});
    result.results.push_back({"newton_iterations", double(iterations + 1), "1", "equilibrium iterations"});
    std::ostringstream note;
    note << (spin != 0 ? "steady state at " + std::to_string(spin) + " rad/s of " + spinBody.name
                       : std::string("static equilibrium at rest"))
         << " after " << iterations + 1 << " Newton step(s), last step " << step;
    result.notes.push_back(note.str());
    return result;
}

AnalysisKind staticDeflectionKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& statics = kind.schema;
    statics.type = "static_deflection";
    statics.doc = "Equilibrium at rest under the constant loads (gravity): every probe there and the "
                  "deflection line of a FlexibleRotor (Newton on the accelerations); with spin_speed, the "
                  "steady state of a rotor turning at that speed (a synchronous whirl under unbalance).";
    statics.params = {
        P::quantity("spin_speed", "rad/s", "speed held on spin_body (0: at rest); loads must then turn with "
                                           "the rotor (unbalance), not stand still (no gravity)")
            .optional(0.0),
        P::body("spin_body", "pin whose speed is held (default: the first body)").optional(""),
    };
    kind.run = [](const ModelSpec& spec, const ProgressFn& progress, const SampleObserver&) {
        return runStaticDeflection(spec, progress);
    };
    return kind;
}

}  // namespace milldyn
