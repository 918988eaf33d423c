// linearize: the linear model about steady running, its eigenvalues,
// natural frequencies and mode shapes.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"

#include <cmath>

namespace milldyn {

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

    DataTable eig{"eigenvalues", {"index", "real", "imag", "frequency", "damping_ratio"},
                  {"1", "1/s", "rad/s", "Hz", "1"}, {}};
    const double scale = lm.eigenvalues.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i) {
        const auto l = lm.eigenvalues[i];
        const double mag = std::abs(l);
        // The rigid rotation's eigenvalue is 0 up to differencing noise: no damping ratio.
        const bool rigid = mag <= 1e-9 * scale;
        eig.rows.push_back({double(i + 1), l.real(), l.imag(), std::abs(l.imag()) / (2 * M_PI),
                            rigid ? 0.0 : -l.real() / mag});
    }
    result.extraTables.push_back(eig);

    DataTable modes{"modes", {"mode", "natural_frequency", "natural_frequency_hz"}, {"1", "rad/s", "Hz"}, {}};
    for (int i = 0; i < n; ++i)
        modes.rows.push_back({double(i + 1), lm.naturalFrequencies[i], lm.naturalFrequencies[i] / (2 * M_PI)});
    result.extraTables.push_back(modes);
}

AnalysisResult runLinearize(const ModelSpec& spec, const ProgressFn&) {
    auto scene = buildScene(spec);
    SimTK::State state = initialState(*scene, spec);
    if (spec.scenario.text("operating_point") == "steady") state = solveSteadyState(*scene, state);
    const LinearModel lm = linearizeScene(*scene, state);

    AnalysisResult result;
    result.derived = derivedResults(*scene);
    result.analysis = "linearize";
    result.tableName = "mode_shapes";
    result.plotXLabel = "body index (parents first)";
    const int n = static_cast<int>(lm.M.rows());
    result.columnNames = {"body_index"};
    result.columnUnits = {"1"};
    for (int m = 0; m < n; ++m) {
        result.columnNames.push_back("mode_" + std::to_string(m + 1));
        result.columnUnits.push_back("1");
    }
    for (int b = 0; b < n; ++b) {
        std::vector<double> row = {double(b + 1)};
        for (int m = 0; m < n; ++m) row.push_back(lm.modeShapes(b, m));
        result.rows.push_back(row);
    }
    addLinearModelOutputs(lm, result);

    // Rigid rotation of the whole train is a zero-frequency mode; report the
    // elastic ones.
    const double scale = lm.naturalFrequencies.maxCoeff();
    int elastic = 0;
    std::vector<std::size_t> shapeColumns;
    for (int m = 0; m < n; ++m) {
        if (lm.naturalFrequencies[m] <= 1e-6 * scale) continue;
        ++elastic;
        shapeColumns.push_back(m + 1);
        result.results.push_back({"natural_frequency_" + std::to_string(elastic), lm.naturalFrequencies[m], "rad/s",
                                  "undamped elastic mode " + std::to_string(elastic) + " (" +
                                      std::to_string(lm.naturalFrequencies[m] / (2 * M_PI)) + " Hz)"});
    }
    for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i) {
        const auto l = lm.eigenvalues[i];
        if (l.imag() < 0) continue;  // one of each conjugate pair
        const std::string tag = "eigenvalue_" + std::to_string(i + 1);
        result.results.push_back({tag + "_real", l.real(), "1/s", "damped eigenvalue, real part"});
        if (l.imag() > 0) result.results.push_back({tag + "_imag", l.imag(), "rad/s", "damped eigenvalue, imaginary part"});
    }
    result.results.push_back({"degrees_of_freedom", double(n), "1", "mobilities of the linearized system"});
    result.plots.push_back({"mode_shapes", shapeColumns});
    result.notes.push_back("operating point: " + spec.scenario.text("operating_point") + ", speed of " +
                           scene->bodies().front().name + " " +
                           std::to_string(pinSpeed(state, scene->bodies().front().mobod)) + " rad/s");
    return result;
}

}  // namespace milldyn
