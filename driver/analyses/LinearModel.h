#pragma once
// The linear model of a Scene about an operating point:
//   M·q̈ + C·q̇ + K·q = f      (q, q̇ deviations from the operating point)
// M from Simbody (calcM), C and K from central differences of the
// accelerations: K = −M·∂q̈/∂q, C = −M·∂q̈/∂q̇. Joints with q̇ = u only (pin,
// gimbal, bushing; not ball or free, whose q are quaternions).

#include "plugins/scene/Scene.h"

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

namespace milldyn {

struct LinearModel {
    Eigen::MatrixXd M, C, K;       ///< [kg*m^2], [N*m*s/rad], [N*m/rad]
    Eigen::MatrixXd A;             ///< first-order state matrix [q; u]
    Eigen::VectorXcd eigenvalues;  ///< of A, sorted by |imag| then real [1/s]
    Eigen::VectorXd naturalFrequencies;  ///< undamped, from K v = ω² M v [rad/s]
    Eigen::MatrixXd modeShapes;          ///< columns, max |entry| = 1
    std::vector<std::string> dofNames;   ///< mobilityNames(): body names for pins
    /// Output rows: probe p's deviation ≈ outputQ.row(p)·q + outputU.row(p)·q̇.
    Eigen::MatrixXd outputQ, outputU;
    std::vector<std::string> outputNames, outputUnits;
};

/// Linearizes `scene` about `operatingPoint` (the excitations it carries are
/// switched off for the derivatives). Throws AnalysisError for joints whose
/// q̇ differs from u.
/// With `withModes` false only M, C, K, A and the output rows are filled
/// (no eigenproblems: what a static solve needs, at O(n²) instead of O(n³)).
LinearModel linearizeScene(const Scene& scene, const SimTK::State& operatingPoint, bool withModes = true);

/// Fills naturalFrequencies and modeShapes from K v = ω² M v (K's symmetric
/// part); linearizeScene does this unless told not to.
void calcUndampedModes(LinearModel& model);

struct AnalysisResult;
/// Adds M, C, K, A and the eigenvalue and mode tables to a result.
void addLinearModelOutputs(const LinearModel& model, AnalysisResult& result);

/// Complex amplitudes of q for the forcing f·e^{iPt}: (K − P²M + iP·C)·X = f.
Eigen::VectorXcd harmonicResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force);

}  // namespace milldyn
