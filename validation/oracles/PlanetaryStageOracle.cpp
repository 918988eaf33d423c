#include "validation/oracles/PlanetaryStageOracle.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {

// Müller eq (2.1): ω_s − i_0 ω_r − (1 − i_0) ω_c = 0 with i_0 = −z_r/z_s.
double willisCarrierSpeed(double zs, double zr, double ws, double wr) { return (zs * ws + zr * wr) / (zs + zr); }
double willisSunSpeed(double zs, double zr, double wr, double wc) { return wc - zr / zs * (wr - wc); }
double willisRingSpeed(double zs, double zr, double ws, double wc) { return wc - zs / zr * (ws - wc); }

PlanetaryStatics planetaryStatics(const PlanetaryStageModel& m, double sunTorque, const std::vector<double>& e) {
    const int n = m.planets;
    const double rs = m.module * m.sunTeeth / 2, rp = m.module * m.planetTeeth / 2, rr = rs + 2 * rp;
    const double c2 = std::cos(m.pressureAngle) * std::cos(m.pressureAngle);
    const double kt = e.empty() ? 0.0
                                : c2 * m.sunMeshStiffness * m.ringMeshStiffness /
                                      (m.sunMeshStiffness + m.ringMeshStiffness);
    double mean = 0;
    for (double v : e) mean += v / n;
    PlanetaryStatics out;
    double sum = 0, top = 0;
    for (int k = 0; k < n; ++k) {
        const double f = sunTorque / (n * rs) - 2 * kt * ((e.empty() ? 0.0 : e[k]) - mean);
        if (!(f * sunTorque > 0)) throw std::domain_error("planetaryStatics: a planet loses contact");
        out.meshForce.push_back(f);
        out.bearingForce.push_back(2 * std::abs(f));
        sum += f;
        top = std::max(top, std::abs(f));
    }
    out.sunTorque = -rs * sum;
    out.ringTorque = -rr * sum;
    out.carrierTorque = (rs + rr) * sum;
    out.loadSharingFactor = n * top / std::abs(sum);
    return out;
}

std::vector<double> torsionalPlanetaryFrequencies(const PlanetaryStageModel& m, char fixed) {
    const int n = m.planets;
    const double rs = m.module * m.sunTeeth / 2, rp = m.module * m.planetTeeth / 2, rr = rs + 2 * rp;
    const double a = rs + rp, ca = std::cos(m.pressureAngle);
    // Coordinates: θ_s, θ_r, θ_c, θ_p1..θ_pn (absolute). Along the line of
    // action (Lin & Parker, rotational part): δ_sn = cos α (r_s θ_s + r_p θ_pn − a θ_c),
    // δ_rn = cos α (r_r θ_r − r_p θ_pn − a θ_c); V = Σ ½ k δ².
    const int N = 3 + n;
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(N, N), K = Eigen::MatrixXd::Zero(N, N);
    M(0, 0) = m.sunInertia;
    M(1, 1) = m.ringInertia;
    M(2, 2) = m.carrierInertia + n * m.planetMass * a * a;
    for (int k = 0; k < n; ++k) {
        M(3 + k, 3 + k) = m.planetInertia;
        Eigen::VectorXd gs = Eigen::VectorXd::Zero(N), gr = Eigen::VectorXd::Zero(N);
        gs(0) = ca * rs;
        gs(3 + k) = ca * rp;
        gs(2) = -ca * a;
        gr(1) = ca * rr;
        gr(3 + k) = -ca * rp;
        gr(2) = -ca * a;
        K += m.sunMeshStiffness * gs * gs.transpose() + m.ringMeshStiffness * gr * gr.transpose();
    }
    const int drop = fixed == 's' ? 0 : fixed == 'r' ? 1 : 2;
    std::vector<int> keep;
    for (int i = 0; i < N; ++i)
        if (i != drop) keep.push_back(i);
    Eigen::MatrixXd Mr(N - 1, N - 1), Kr(N - 1, N - 1);
    for (int i = 0; i < N - 1; ++i)
        for (int j = 0; j < N - 1; ++j) {
            Mr(i, j) = M(keep[i], keep[j]);
            Kr(i, j) = K(keep[i], keep[j]);
        }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kr, Mr);
    std::vector<double> w;
    const double top = std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff()));
    for (int i = 0; i < es.eigenvalues().size(); ++i) {
        const double v = std::sqrt(std::max(0.0, es.eigenvalues()[i]));
        if (v > 1e-6 * top) w.push_back(v);
    }
    std::sort(w.begin(), w.end());
    return w;
}

double planetModeFrequency(const PlanetaryStageModel& m) {
    const double rp = m.module * m.planetTeeth / 2, ca = std::cos(m.pressureAngle);
    return std::sqrt((m.sunMeshStiffness + m.ringMeshStiffness) * ca * ca * rp * rp / m.planetInertia);
}

double planetaryMeshFrequency(double zr, double wr, double wc) { return zr * std::abs(wr - wc) / (2 * M_PI); }

}  // namespace milldyn::oracles
