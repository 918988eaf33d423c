#include "validation/oracles/TumblingMillOracle.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double segmentCentralAngle(double fill) {
    if (!(fill > 0 && fill <= 1)) throw std::domain_error("fill must be in (0, 1]");
    // f(θ) = θ − sin θ − 2πJ rises on (0, 2π) (f' = 1 − cos θ >= 0); Newton
    // safeguarded by the bracket [lo, hi].
    const double target = 2 * kPi * fill;
    double lo = 0, hi = 2 * kPi, t = kPi;
    for (int i = 0; i < 200; ++i) {
        const double f = t - std::sin(t) - target;
        (f < 0 ? lo : hi) = t;
        const double d = 1 - std::cos(t);
        double next = d > 0 ? t - f / d : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 1e-15 * (1 + t)) return next;
        t = next;
    }
    return t;
}

double segmentArea(const CircularSegmentCharge& c) {
    const double t = segmentCentralAngle(c.fill);
    return c.drumRadius * c.drumRadius * (t - std::sin(t)) / 2;
}

double segmentCentroidDistance(const CircularSegmentCharge& c) {
    const double t = segmentCentralAngle(c.fill);
    const double s = std::sin(t / 2);
    return 4 * c.drumRadius * s * s * s / (3 * (t - std::sin(t)));
}

double segmentAxisInertia(const CircularSegmentCharge& c) {
    const double t = segmentCentralAngle(c.fill), R = c.drumRadius;
    const double sector = R * R * R * R * t / 4;
    const double triangle = R * R * R * R * std::sin(t) * (2 + std::cos(t)) / 12;
    return c.bulkDensity * c.length * (sector - triangle);
}

double segmentMass(const CircularSegmentCharge& c) { return c.bulkDensity * c.length * segmentArea(c); }

double criticalSpeed(double drumDiameter, double g) { return std::sqrt(2 * g / drumDiameter); }

double torqueArmTorque(const CircularSegmentCharge& c, double lag, double g) {
    return segmentMass(c) * g * segmentCentroidDistance(c) * std::sin(lag);
}

double klossRunningSpeed(const KlossMotor& m, double loadTorque) {
    const double sn = (m.synchronousSpeed - m.ratedSpeed) / m.synchronousSpeed;
    const double l = m.breakdownRatio;
    const double sk = sn * (l + std::sqrt(l * l - 1));
    const double Mk = l * m.ratedTorque;
    if (loadTorque > Mk) throw std::domain_error("load above the breakdown torque");
    if (loadTorque <= 0) return m.synchronousSpeed;
    // M = T: s/s_k + s_k/s = 2a, a = Mk/T: s/s_k = a − sqrt(a² − 1) (the
    // stable branch, s < s_k).
    const double a = Mk / loadTorque;
    const double s = sk * (a - std::sqrt(a * a - 1));
    return m.synchronousSpeed * (1 - s);
}

namespace {
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solveChain(const GearedChain& chain) {
    const std::size_t n = chain.inertias.size();
    if (n == 0 || chain.stiffnesses.size() + 1 != n || chain.ratios.size() + 1 != n)
        throw std::invalid_argument("GearedChain: n inertias need n - 1 stiffnesses and ratios");
    // Referred to shaft 0: angle of shaft k is θ_k = N_k·φ_k with N_k the
    // product of ratios before it, so J_k → J_k/N_k², and spring k (on
    // shaft k, between φ_k and φ_{k+1}) → c_k/N_k².
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n), K = Eigen::MatrixXd::Zero(n, n);
    double N = 1;
    for (std::size_t k = 0; k < n; ++k) {
        M(k, k) = chain.inertias[k] / (N * N);
        if (k + 1 < n) {
            const double c = chain.stiffnesses[k] / (N * N);
            K(k, k) += c;
            K(k + 1, k + 1) += c;
            K(k, k + 1) -= c;
            K(k + 1, k) -= c;
            N *= chain.ratios[k];
        }
    }
    return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(K, M);
}
}  // namespace

std::vector<double> gearedChainFrequencies(const GearedChain& chain) {
    const auto eig = solveChain(chain);
    std::vector<double> w;
    for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
        w.push_back(std::sqrt(std::max(0.0, eig.eigenvalues()[i])));
    return w;
}

std::vector<std::vector<double>> gearedChainModeShapes(const GearedChain& chain) {
    const auto eig = solveChain(chain);
    std::vector<std::vector<double>> shapes;
    for (Eigen::Index m = 0; m < eig.eigenvectors().cols(); ++m) {
        Eigen::VectorXd v = eig.eigenvectors().col(m);
        Eigen::Index at = 0;
        v.cwiseAbs().maxCoeff(&at);
        v /= v[at];
        shapes.emplace_back(v.data(), v.data() + v.size());
    }
    return shapes;
}

}  // namespace milldyn::oracles
