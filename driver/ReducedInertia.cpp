#include "driver/ReducedInertia.h"

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseQR>

#include <cmath>
#include <string>
#include <vector>

namespace milldyn {

using namespace SimTK;

namespace {

constexpr double kRankThreshold = 1e-10;  // relative, as the LU's threshold before
constexpr int kDenseFallbackLimit = 400;   // mobilities up to which a dense check may run

/// The kernel of `a` (rows x n) when it is one-dimensional: its dimension,
/// and in `v` its vector. Sparse QR with COLAMD: A P = Q [R11 R12; 0 0],
/// so v = P [-R11⁻¹ R12; 1] for the one column found dependent.
int sparseKernel(const ::Eigen::SparseMatrix<double>& a, int n, ::Eigen::VectorXd& v, ReducedInertiaWork& work) {
    // SparseQR wants at least as many rows as columns: zero rows change nothing.
    ::Eigen::SparseMatrix<double> padded = a;
    if (padded.rows() < n) padded.conservativeResize(n, n);
    padded.makeCompressed();
    double largest = 0;
    for (int j = 0; j < padded.outerSize(); ++j) largest = std::max(largest, padded.col(j).norm());
    ::Eigen::SparseQR<::Eigen::SparseMatrix<double>, ::Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(kRankThreshold * std::max(largest, 1e-300));
    qr.compute(padded);
    if (qr.info() != ::Eigen::Success) return -1;
    const int rank = static_cast<int>(qr.rank());
    const ::Eigen::SparseMatrix<double> r = qr.matrixR();
    work.factorNonzeros += r.nonZeros();
    const int kernel = n - rank;
    if (kernel != 1) return kernel;
    ::Eigen::VectorXd y = ::Eigen::VectorXd::Ones(n);
    if (rank > 0) {
        const ::Eigen::SparseMatrix<double> r11 = r.topLeftCorner(rank, rank);
        const ::Eigen::VectorXd r12 = ::Eigen::VectorXd(r.col(rank)).head(rank);
        y.head(rank) = -r11.triangularView<::Eigen::Upper>().solve(r12);
    }
    v = qr.colsPermutation() * y;
    return 1;
}

}  // namespace

void addReducedInertias(Scene& scene, ReducedInertiaWork* workOut) {
    ReducedInertiaWork work;
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
    const int rowCount = g.nrow() + static_cast<int>(residuals.size());
    std::vector<::Eigen::Triplet<double>> entries;
    for (int i = 0; i < g.nrow(); ++i)
        for (int j = 0; j < n; ++j)
            if (g(i, j) != 0) entries.emplace_back(i, j, g(i, j));
    std::vector<double> atRest(residuals.size());
    s.updU() = 0;
    system.realize(s, Stage::Velocity);
    ++work.realizations;
    for (std::size_t k = 0; k < residuals.size(); ++k) atRest[k] = residuals[k].value(s);
    for (int j = 0; j < n && !residuals.empty(); ++j) {
        s.updU() = 0;
        s.updU()[j] = 1;
        system.realize(s, Stage::Velocity);
        ++work.realizations;
        for (std::size_t k = 0; k < residuals.size(); ++k) {
            const double d = residuals[k].value(s) - atRest[k];
            if (d != 0) entries.emplace_back(g.nrow() + static_cast<int>(k), j, d);
        }
    }
    ::Eigen::SparseMatrix<double> rows(rowCount, n);
    rows.setFromTriplets(entries.begin(), entries.end());
    work.matrixNonzeros = rows.nonZeros();
    ::Eigen::VectorXd v;
    int kernel = 0;
    if (rowCount == 0) {
        kernel = n;
        if (n == 1) v = ::Eigen::VectorXd::Ones(1);
    } else {
        kernel = sparseKernel(rows, n, v, work);
        // The kernel found must be one: |A v| small against |A| |v|.
        const double scale = v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
        double largest = 0;
        for (int k = 0; k < rows.outerSize(); ++k) largest = std::max(largest, rows.col(k).norm());
        const bool checked = kernel == 1 && scale > 0 && (rows * v).norm() <= 1e-8 * largest * v.norm();
        if (!checked && n <= kDenseFallbackLimit) {
            work.dense = true;
            ::Eigen::FullPivLU<::Eigen::MatrixXd> lu{::Eigen::MatrixXd(rows)};
            lu.setThreshold(kRankThreshold);
            kernel = static_cast<int>(lu.dimensionOfKernel());
            if (kernel == 1) v = lu.kernel().col(0);
        } else if (!checked && kernel == 1) {
            kernel = -1;
        }
    }
    if (workOut) *workOut = work;
    if (kernel != 1) {
        scene.note("no reduced inertia",
                   kernel < 0 ? std::string("the train's rigid motion could not be found to accuracy")
                              : std::to_string(kernel) + " independent " + (rowCount == 0 ? "motions" : "rigid motions") +
                                    ", not one rigid train");
        return;
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
