#include "driver/ReducedInertia.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>
#include <vector>

namespace milldyn {

using namespace SimTK;

void addReducedInertias(Scene& scene) {
    const MultibodySystem& system = scene.system();
    const SimbodyMatterSubsystem& matter = scene.matter();
    State s = system.getDefaultState();
    const int n = s.getNU();
    if (n == 0) return;
    try {
        system.realize(s, Stage::Position);
    } catch (const std::exception&) {
        return;  // a configuration the default state cannot realize: nothing to refer
    }
    // Rows that the rigid motion must zero: the constraints' G and the steady
    // residuals, linear in u (differences from u = 0).
    Matrix g;
    matter.calcG(s, g);
    const auto& residuals = scene.steadyResiduals();
    ::Eigen::MatrixXd rows(g.nrow() + static_cast<int>(residuals.size()), n);
    for (int i = 0; i < g.nrow(); ++i)
        for (int j = 0; j < n; ++j) rows(i, j) = g(i, j);
    std::vector<double> atRest(residuals.size());
    s.updU() = 0;
    system.realize(s, Stage::Velocity);
    for (std::size_t k = 0; k < residuals.size(); ++k) atRest[k] = residuals[k].value(s);
    for (int j = 0; j < n; ++j) {
        s.updU() = 0;
        s.updU()[j] = 1;
        system.realize(s, Stage::Velocity);
        for (std::size_t k = 0; k < residuals.size(); ++k)
            rows(g.nrow() + static_cast<int>(k), j) = residuals[k].value(s) - atRest[k];
    }
    ::Eigen::VectorXd v;
    if (rows.rows() == 0) {
        if (n != 1) {
            scene.note("no reduced inertia", std::to_string(n) + " independent motions, not one rigid train");
            return;
        }
        v = ::Eigen::VectorXd::Ones(1);
    } else {
        ::Eigen::FullPivLU<::Eigen::MatrixXd> lu(rows);
        lu.setThreshold(1e-10);
        const ::Eigen::MatrixXd kernel = lu.kernel();
        if (lu.dimensionOfKernel() != 1) {
            scene.note("no reduced inertia", std::to_string(lu.dimensionOfKernel()) +
                                                 " independent rigid motions, not one rigid train");
            return;
        }
        v = kernel.col(0);
    }
    for (int j = 0; j < n; ++j) s.updU()[j] = v[j];
    system.realize(s, Stage::Velocity);
    const double twiceEnergy = 2 * matter.calcKineticEnergy(s);
    const double scale = v.cwiseAbs().maxCoeff();
    for (const SceneBody& b : scene.bodies()) {
        const double w = b.mobod.getBodyAngularVelocity(s)[2];
        if (!(std::abs(w) > 1e-9 * scale)) continue;
        scene.addDerivedValue({b.name + ".reduced_inertia", twiceEnergy / (w * w), "kg*m^2",
                               "the whole train's inertia referred to " + b.name +
                                   ": 2T/ω² moving as one rigid train, in the default configuration"});
    }
}

}  // namespace milldyn
