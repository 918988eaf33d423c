#include "validation/oracles/GearPairOracle.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {

HelicalMeshForces helicalMeshForces(double torque, double r, double phiN, double psi) {
    if (!(r > 0)) throw std::invalid_argument("helicalMeshForces: pitch radius must be > 0");
    HelicalMeshForces f;
    f.tangential = torque / r;
    f.radial = std::abs(f.tangential) * std::tan(phiN) / std::cos(psi);
    f.axial = f.tangential * std::tan(psi);
    f.normal = std::abs(f.tangential) / (std::cos(phiN) * std::cos(psi));
    return f;
}

std::array<double, 4> twoSupportReactions(const std::vector<ShaftLoad>& loads, double zA, double zB) {
    if (zA == zB) throw std::invalid_argument("twoSupportReactions: supports at the same z");
    const double span = zB - zA;
    double sumX = 0, sumY = 0, momX = 0, momY = 0;
    for (const auto& l : loads) {
        sumX += l.fx;
        sumY += l.fy;
        // Moment about the support A line, per plane: lever (z − zA) for the
        // lateral force, plus the couple of the axial force at its offset.
        momX += l.fx * (l.z - zA) - l.fz * l.x;
        momY += l.fy * (l.z - zA) - l.fz * l.y;
    }
    const double rBx = -momX / span, rBy = -momY / span;
    return {-sumX - rBx, -sumY - rBy, rBx, rBy};
}

std::vector<double> gearedChainFrequencies(const std::vector<double>& J, const std::vector<double>& n,
                                           const std::vector<double>& k) {
    const std::size_t m = J.size();
    if (m < 2 || n.size() != m || k.size() != m - 1)
        throw std::invalid_argument("gearedChainFrequencies: m inertias, m ratios, m-1 springs");
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m), K = Eigen::MatrixXd::Zero(m, m);
    for (std::size_t i = 0; i < m; ++i) M(i, i) = J[i] / (n[i] * n[i]);
    for (std::size_t i = 0; i + 1 < m; ++i) {
        const double kr = k[i] / (n[i] * n[i]);
        K(i, i) += kr;
        K(i + 1, i + 1) += kr;
        K(i, i + 1) -= kr;
        K(i + 1, i) -= kr;
    }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
    std::vector<double> w;
    for (int i = 0; i < es.eigenvalues().size(); ++i) w.push_back(std::sqrt(std::max(0.0, es.eigenvalues()[i])));
    std::sort(w.begin(), w.end());
    return w;
}

double meshTorsionalStiffness(double k, double r1, double phiN, double psi) {
    const double alphaT = std::atan(std::tan(phiN) / std::cos(psi));
    const double rb = r1 * std::cos(alphaT);
    return k * rb * rb;
}

}  // namespace milldyn::oracles
