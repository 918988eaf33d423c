#include "validation/oracles/BeadMillOracle.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("BeadMillOracle: " + what);
}

double positivePart(double v) { return v > 0 ? v : 0; }

void checkDrag(double density, double viscosity, double omega, double radius, int discs) {
    require(std::isfinite(density) && density > 0, "density must be finite and > 0");
    require(std::isfinite(viscosity) && viscosity > 0, "viscosity must be finite and > 0");
    require(std::isfinite(omega) && omega > 0, "omega must be finite and > 0");
    require(std::isfinite(radius) && radius > 0, "radius must be finite and > 0");
    require(discs >= 1, "discs must be >= 1");
}

// Sorted, de-duplicated points of [a, b] (the pieces on which an integrand is
// one polynomial).
std::vector<double> pieces(std::vector<double> points, double a, double b) {
    points.push_back(a);
    points.push_back(b);
    std::vector<double> out;
    for (double p : points)
        if (p >= a && p <= b) out.push_back(p);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end(), [](double u, double v) { return std::abs(u - v) < 1e-15; }),
              out.end());
    return out;
}

// 5-point Gauss–Legendre on [a, b]: exact for polynomials up to degree 9.
template <class F>
double gauss5(double a, double b, F f) {
    static const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                0.9061798459386640};
    static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                0.2369268850561891};
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    double sum = 0;
    for (int i = 0; i < 5; ++i) sum += w[i] * f(c + h * x[i]);
    return sum * h;
}


}  // namespace

// ---------------------------------------------------------------- disc drag

double beadMillDiscReynolds(double omega, double radius, double viscosity) {
    checkDrag(1, viscosity, omega, radius, 1);
    return omega * radius * radius / viscosity;
}

double beadMillLaminarPower(double density, double viscosity, double omega, double radius, int discs) {
    checkDrag(density, viscosity, omega, radius, discs);
    return 0.616 * kPi * density * omega * omega * std::pow(radius, 4) * discs * std::sqrt(viscosity * omega);
}

double beadMillTurbulentPower(double density, double viscosity, double omega, double radius, int discs) {
    checkDrag(density, viscosity, omega, radius, discs);
    const double re = omega * radius * radius / viscosity;
    const double torque = 0.073 * density * omega * omega * std::pow(radius, 5) * std::pow(re, -0.2);
    return discs * torque * omega;
}

// ------------------------------------------------------ overhung shaft beam

BeadMillBeam::BeadMillBeam(BeadMillShaft s) : m_shaft(std::move(s)) {
    require(std::isfinite(m_shaft.youngsModulus) && m_shaft.youngsModulus > 0, "youngsModulus must be > 0");
    require(std::isfinite(m_shaft.diameter) && m_shaft.diameter > 0, "diameter must be > 0");
    require(std::isfinite(m_shaft.density) && m_shaft.density >= 0, "density must be >= 0");
    require(std::isfinite(m_shaft.span) && m_shaft.span > 0, "span must be > 0");
    require(std::isfinite(m_shaft.overhang) && m_shaft.overhang >= 0, "overhang must be >= 0");
    require(m_shaft.stiffnessA > 0 && m_shaft.stiffnessB > 0, "bearing stiffness must be > 0 (inf: rigid)");
    for (const auto& d : m_shaft.discs) {
        require(d.position >= 0 && d.position <= getLength() + 1e-12, "disc position must lie on the shaft");
        require(std::isfinite(d.mass) && d.mass >= 0, "disc mass must be >= 0");
        require(std::isfinite(d.diametralInertia) && d.diametralInertia >= 0, "disc inertia must be >= 0");
        require(std::isfinite(d.polarInertia) && d.polarInertia >= 0, "disc polar inertia must be >= 0");
        require(std::isfinite(d.unbalance) && d.unbalance >= 0, "disc unbalance must be >= 0");
    }
}

double BeadMillBeam::getSecondMoment() const { return kPi * std::pow(m_shaft.diameter, 4) / 64; }

double BeadMillBeam::getMassPerLength() const {
    return m_shaft.density * kPi * m_shaft.diameter * m_shaft.diameter / 4;
}

namespace {
// Loads of one case: point loads and a uniform load qS on the span, qO on the overhang.
struct LoadCase {
    const std::vector<BeadMillPointLoad>* points;
    double qS, qO;
};

void reactions(const LoadCase& lc, double Lp, double a, double& RA, double& RB) {
    double total = lc.qS * Lp + lc.qO * a, momentA = lc.qS * Lp * Lp / 2 + lc.qO * a * (Lp + a / 2);
    for (const auto& p : *lc.points) {
        total += p.force;
        momentA += p.force * p.position;
    }
    RB = momentA / Lp;
    RA = total - RB;
}

double moment(const LoadCase& lc, double Lp, double s, double RA, double RB) {
    double M = RA * s + RB * positivePart(s - Lp);
    for (const auto& p : *lc.points) M -= p.force * positivePart(s - p.position);
    if (s <= Lp) M -= lc.qS * s * s / 2;
    else M -= lc.qS * Lp * (s - Lp / 2) + lc.qO * (s - Lp) * (s - Lp) / 2;
    return M;
}

double deflection(const BeadMillShaft& sh, double EI, double x, const LoadCase& lc) {
    const double Lp = sh.span, a = sh.overhang, L = Lp + a;
    require(x >= -1e-12 && x <= L + 1e-12, "deflection point x must lie on the shaft");
    double RA, RB;
    reactions(lc, Lp, a, RA, RB);
    const std::vector<BeadMillPointLoad> unit = {{x, 1.0}};
    const LoadCase uc{&unit, 0, 0};
    double rA, rB;
    reactions(uc, Lp, a, rA, rB);
    std::vector<double> bp = {Lp, x};
    for (const auto& p : *lc.points) bp.push_back(p.position);
    const auto s = pieces(bp, 0, L);
    auto f = [&](double t) { return moment(lc, Lp, t, RA, RB) * moment(uc, Lp, t, rA, rB); };
    double w = 0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const double h = s[i + 1] - s[i];
        w += h / 6 * (f(s[i]) + 4 * f(0.5 * (s[i] + s[i + 1])) + f(s[i + 1]));  // exact: cubic integrand
    }
    w /= EI;
    if (std::isfinite(sh.stiffnessA)) w += RA * rA / sh.stiffnessA;
    if (std::isfinite(sh.stiffnessB)) w += RB * rB / sh.stiffnessB;
    return w;
}
}  // namespace

void BeadMillBeam::calcReactions(const std::vector<BeadMillPointLoad>& loads, double q, double& RA,
                                 double& RB) const {
    reactions({&loads, q, q}, m_shaft.span, m_shaft.overhang, RA, RB);
}

double BeadMillBeam::calcMoment(double s, const std::vector<BeadMillPointLoad>& loads, double q, double RA,
                                double RB) const {
    return moment({&loads, q, q}, m_shaft.span, s, RA, RB);
}

double BeadMillBeam::calcDeflection(double x, const std::vector<BeadMillPointLoad>& loads,
                                    double uniformLoad) const {
    return deflection(m_shaft, m_shaft.youngsModulus * getSecondMoment(), x, {&loads, uniformLoad, uniformLoad});
}

double BeadMillBeam::calcGravityDeflection(double x, double g) const {
    std::vector<BeadMillPointLoad> loads;
    for (const auto& d : m_shaft.discs) loads.push_back({d.position, d.mass * g});
    return calcDeflection(x, loads, getMassPerLength() * g);
}

double BeadMillBeam::calcInfluence(double x, double c) const {
    return calcDeflection(x, {{c, 1.0}}, 0);
}

double BeadMillBeam::calcRayleighCriticalSpeed(bool modeSigned) const {
    const double g = 9.81;  // cancels; any value
    const double Lp = m_shaft.span, L = getLength(), EI = m_shaft.youngsModulus * getSecondMoment();
    const double mu = getMassPerLength();
    auto sign = [&](double s) { return (modeSigned && s < Lp) ? -1.0 : 1.0; };
    std::vector<BeadMillPointLoad> loads;
    for (const auto& d : m_shaft.discs) loads.push_back({d.position, sign(d.position) * d.mass * g});
    const LoadCase lc{&loads, sign(0) * mu * g, mu * g};
    auto y = [&](double x) { return deflection(m_shaft, EI, x, lc); };
    double work = 0, inertia = 0;
    for (const auto& p : loads) {
        const double yi = y(p.position);
        work += p.force * yi;
    }
    for (const auto& d : m_shaft.discs) inertia += d.mass * std::pow(y(d.position), 2);
    if (mu > 0) {
        std::vector<double> bp = {Lp};
        for (const auto& d : m_shaft.discs) bp.push_back(d.position);
        const auto s = pieces(bp, 0, L);
        for (std::size_t i = 0; i + 1 < s.size(); ++i) {
            const double qi = sign(0.5 * (s[i] + s[i + 1])) * mu * g;
            work += gauss5(s[i], s[i + 1], [&](double t) { return qi * y(t); });
            inertia += gauss5(s[i], s[i + 1], [&](double t) { return mu * y(t) * y(t); });
        }
    }
    require(inertia > 0, "Rayleigh: the rotor has no mass");
    return std::sqrt(work / inertia);
}

double BeadMillBeam::calcDunkerleyCriticalSpeed(int shaftLumps) const {
    require(shaftLumps >= 1, "shaftLumps must be >= 1");
    double sum = 0;
    for (const auto& d : m_shaft.discs) sum += d.mass * calcInfluence(d.position, d.position);
    const double mu = getMassPerLength(), L = getLength();
    if (mu > 0) {
        const double h = L / shaftLumps;
        for (int j = 0; j < shaftLumps; ++j) {
            const double x = (j + 0.5) * h;
            sum += mu * h * calcInfluence(x, x);
        }
    }
    require(sum > 0, "Dunkerley: the rotor has no mass");
    return 1 / std::sqrt(sum);
}

struct BeadMillBeam::Mesh {
    std::vector<double> nodes;  // positions [m]
    int nodeOf(double x) const {
        int best = 0;
        for (int i = 1; i < int(nodes.size()); ++i)
            if (std::abs(nodes[i] - x) < std::abs(nodes[best] - x)) best = i;
        return best;
    }
};

BeadMillBeam::Mesh BeadMillBeam::buildMesh(int elements) const {
    require(elements >= 1, "elements must be >= 1");
    std::vector<double> bp = {m_shaft.span};
    for (const auto& d : m_shaft.discs) bp.push_back(d.position);
    const auto s = pieces(bp, 0, getLength());
    Mesh mesh;
    const double L = getLength();
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const int n = std::max(1, int(std::lround(elements * (s[i + 1] - s[i]) / L)));
        for (int j = 0; j < n; ++j) mesh.nodes.push_back(s[i] + (s[i + 1] - s[i]) * j / n);
    }
    mesh.nodes.push_back(s.back());
    return mesh;
}

namespace {
// Assembles K and M (2 dofs per node: w, θ) of a Hermite beam mesh.
void assemble(const std::vector<double>& nodes, double EI, double mu, double rhoI, Eigen::MatrixXd& K,
              Eigen::MatrixXd& M) {
    const int n = 2 * int(nodes.size());
    K = Eigen::MatrixXd::Zero(n, n);
    M = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
        const double h = nodes[e + 1] - nodes[e];
        Eigen::Matrix4d k, m, r;
        k << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h, 6 * h, 2 * h * h,
            -6 * h, 4 * h * h;
        m << 156, 22 * h, 54, -13 * h, 22 * h, 4 * h * h, 13 * h, -3 * h * h, 54, 13 * h, 156, -22 * h, -13 * h,
            -3 * h * h, -22 * h, 4 * h * h;
        r << 36, 3 * h, -36, 3 * h, 3 * h, 4 * h * h, -3 * h, -h * h, -36, -3 * h, 36, -3 * h, 3 * h, -h * h, -3 * h,
            4 * h * h;
        const int o = 2 * int(e);
        K.block<4, 4>(o, o) += EI / (h * h * h) * k;
        M.block<4, 4>(o, o) += mu * h / 420 * m + rhoI / (30 * h) * r;
    }
}
int nearestNode(const std::vector<double>& nodes, double x) {
    int best = 0;
    for (int i = 1; i < int(nodes.size()); ++i)
        if (std::abs(nodes[i] - x) < std::abs(nodes[best] - x)) best = i;
    return best;
}

// K and M of the mesh with the rigid supports eliminated and the bearing
// springs added; the shaft's rotary coefficient `rhoI` per length [kg*m] and
// `discRotary(d)` on each disc's rotation dof [kg*m^2] (negative values are
// allowed: the synchronous whirl's I_d − I_p).
struct Reduced {
    Eigen::MatrixXd K, M;
    std::vector<int> keep;  // full dof of each reduced dof
    int fullSize = 0;
};
template <class DiscRotary>
Reduced reduce(const BeadMillShaft& sh, const std::vector<double>& nodes, double EI, double mu, double rhoI,
               DiscRotary discRotary) {
    Eigen::MatrixXd K, M;
    assemble(nodes, EI, mu, rhoI, K, M);
    for (const auto& d : sh.discs) {
        const int i = nearestNode(nodes, d.position);
        M(2 * i, 2 * i) += d.mass;
        M(2 * i + 1, 2 * i + 1) += discRotary(d);
    }
    Reduced r;
    r.fullSize = int(K.rows());
    const int iA = nearestNode(nodes, 0), iB = nearestNode(nodes, sh.span);
    for (int dof = 0; dof < K.rows(); ++dof) {
        if (dof == 2 * iA && !std::isfinite(sh.stiffnessA)) continue;
        if (dof == 2 * iB && !std::isfinite(sh.stiffnessB)) continue;
        r.keep.push_back(dof);
    }
    if (std::isfinite(sh.stiffnessA)) K(2 * iA, 2 * iA) += sh.stiffnessA;
    if (std::isfinite(sh.stiffnessB)) K(2 * iB, 2 * iB) += sh.stiffnessB;
    const int n = int(r.keep.size());
    r.K.resize(n, n);
    r.M.resize(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            r.K(i, j) = K(r.keep[i], r.keep[j]);
            r.M(i, j) = M(r.keep[i], r.keep[j]);
        }
    return r;
}

// The largest `count` eigenvalues μ = 1/ω² of K⁻¹M as ω ascending; K = L·Lᵀ
// and L⁻¹·M·L⁻ᵀ is symmetric, so M may be singular or indefinite.
std::vector<double> lowestOmegas(const Reduced& r, int count) {
    const int n = int(r.keep.size());
    Eigen::LLT<Eigen::MatrixXd> llt(r.K);
    require(llt.info() == Eigen::Success, "finite elements: stiffness not positive definite");
    const Eigen::MatrixXd Linv = llt.matrixL().solve(Eigen::MatrixXd::Identity(n, n));
    const Eigen::MatrixXd C = Linv * r.M * Linv.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()), Eigen::EigenvaluesOnly);
    std::vector<double> omegas;
    for (int i = n - 1; i >= 0 && int(omegas.size()) < count; --i) {
        const double mu = eig.eigenvalues()[i];
        if (mu <= 1e-14 * eig.eigenvalues()[n - 1]) break;
        omegas.push_back(1 / std::sqrt(mu));
    }
    return omegas;
}

// Hermite interpolation of a full nodal vector (w, θ per node) at x.
double interpolate(const std::vector<double>& nodes, const Eigen::VectorXd& u, double x) {
    std::size_t e = 0;
    while (e + 2 < nodes.size() && x > nodes[e + 1]) ++e;
    const double h = nodes[e + 1] - nodes[e], t = (x - nodes[e]) / h;
    const double N1 = 1 - 3 * t * t + 2 * t * t * t, N2 = h * (t - 2 * t * t + t * t * t);
    const double N3 = 3 * t * t - 2 * t * t * t, N4 = h * (t * t * t - t * t);
    return N1 * u(2 * e) + N2 * u(2 * e + 1) + N3 * u(2 * e + 2) + N4 * u(2 * e + 3);
}

}  // namespace

std::vector<double> BeadMillBeam::calcFiniteElementFrequencies(int elements, bool discInertia,
                                                               bool shaftRotaryInertia, int count) const {
    const Mesh mesh = buildMesh(elements);
    const double rhoI = shaftRotaryInertia ? m_shaft.density * getSecondMoment() : 0;
    const Reduced r = reduce(m_shaft, mesh.nodes, m_shaft.youngsModulus * getSecondMoment(), getMassPerLength(), rhoI,
                             [&](const BeadMillDisc& d) { return discInertia ? d.diametralInertia : 0.0; });
    return lowestOmegas(r, count);
}

double BeadMillBeam::calcForwardCriticalSpeed(int elements) const {
    const Mesh mesh = buildMesh(elements);
    // Forward synchronous whirl: rotary terms I_d − I_p (discs) and
    // ρI − 2ρI = −ρI (shaft) per unit Ω².
    const Reduced r = reduce(m_shaft, mesh.nodes, m_shaft.youngsModulus * getSecondMoment(), getMassPerLength(),
                             -m_shaft.density * getSecondMoment(),
                             [](const BeadMillDisc& d) { return d.diametralInertia - d.polarInertia; });
    const auto omegas = lowestOmegas(r, 1);
    require(!omegas.empty(), "forward critical speed: none");
    return omegas.front();
}

double BeadMillBeam::calcSynchronousWhirl(double x, double omega, int elements) const {
    require(x >= 0 && x <= getLength() + 1e-12, "whirl point x must lie on the shaft");
    require(std::isfinite(omega) && omega >= 0, "omega must be finite and >= 0");
    const Mesh mesh = buildMesh(elements);
    const Reduced r = reduce(m_shaft, mesh.nodes, m_shaft.youngsModulus * getSecondMoment(), getMassPerLength(),
                             -m_shaft.density * getSecondMoment(),
                             [](const BeadMillDisc& d) { return d.diametralInertia - d.polarInertia; });
    Eigen::VectorXd fFull = Eigen::VectorXd::Zero(r.fullSize);
    for (const auto& d : m_shaft.discs) fFull(2 * mesh.nodeOf(d.position)) += d.unbalance * omega * omega;
    const int n = int(r.keep.size());
    Eigen::VectorXd f(n);
    for (int i = 0; i < n; ++i) f(i) = fFull(r.keep[i]);
    const Eigen::VectorXd y = (r.K - omega * omega * r.M).fullPivLu().solve(f);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(r.fullSize);
    for (int i = 0; i < n; ++i) u(r.keep[i]) = y(i);
    return interpolate(mesh.nodes, u, x);
}

double BeadMillBeam::calcFiniteElementGravityDeflection(double x, double g, int elements) const {
    require(x >= 0 && x <= getLength(), "deflection point x must lie on the shaft");
    const Mesh mesh = buildMesh(elements);
    const double EI = m_shaft.youngsModulus * getSecondMoment(), q = getMassPerLength() * g;
    Eigen::MatrixXd K, M;
    assemble(mesh.nodes, EI, 0, 0, K, M);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(K.rows());
    for (std::size_t e = 0; e + 1 < mesh.nodes.size(); ++e) {
        const double h = mesh.nodes[e + 1] - mesh.nodes[e];
        f.segment<4>(2 * e) += q * h / 12 * Eigen::Vector4d(6, h, 6, -h);
    }
    for (const auto& d : m_shaft.discs) f(2 * mesh.nodeOf(d.position)) += d.mass * g;
    const int iA = mesh.nodeOf(0), iB = mesh.nodeOf(m_shaft.span);
    // Rigid supports by a penalty far above the shaft's own stiffness scale.
    const double rigid = 1e8 * EI / std::pow(mesh.nodes[1] - mesh.nodes[0], 3);
    K(2 * iA, 2 * iA) += std::isfinite(m_shaft.stiffnessA) ? m_shaft.stiffnessA : rigid;
    K(2 * iB, 2 * iB) += std::isfinite(m_shaft.stiffnessB) ? m_shaft.stiffnessB : rigid;
    const Eigen::VectorXd u = K.ldlt().solve(f);
    return interpolate(mesh.nodes, u, x);
}

// -------------------------------------------------------- eq (2), Table 1

double beadMillShaftDiameter(int discs, double discDiameter, double span, BeadMillTableReading reading) {
    const std::array<double, 4> k = papers::beadMillTableRow(discs, discDiameter, reading);
    require(span >= papers::kBeadMillTableSpanMin - 1e-12 && span <= papers::kBeadMillTableSpanMax + 1e-12,
            "span L_p must lie in [0.15, 0.5] m (eq 2)");
    const double L = span;
    const double dMillimetre = k[0] * L * L * L - k[1] * L * L + k[2] * L + k[3];
    return dMillimetre * 1e-3;
}

}  // namespace milldyn::oracles
