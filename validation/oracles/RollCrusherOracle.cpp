#include "validation/oracles/RollCrusherOracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace milldyn::oracles {

namespace {

using Complex = std::complex<double>;

[[noreturn]] void throwBadParameter(const char* where, const std::string& name,
                                    double value, const char* unit,
                                    const char* requirement) {
  std::ostringstream message;
  message.precision(17);
  message << where << ": " << name << " = " << value;
  if (unit[0] != '\0') message << ' ' << unit;
  message << " is invalid: " << requirement;
  throw std::invalid_argument(message.str());
}

void requirePositive(const char* where, const std::string& name, double value,
                     const char* unit) {
  // The negated comparison also rejects NaN.
  if (!(value > 0.0) || !std::isfinite(value))
    throwBadParameter(where, name, value, unit, "must be positive and finite");
}

void requireNonNegative(const char* where, const std::string& name,
                        double value, const char* unit) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throwBadParameter(where, name, value, unit,
                      "must be non-negative and finite");
}

void requireFinite(const char* where, const std::string& name, double value,
                   const char* unit) {
  if (!std::isfinite(value))
    throwBadParameter(where, name, value, unit, "must be finite");
}

std::string indexed(const char* name, std::size_t index) {
  return std::string(name) + "[" + std::to_string(index) + "]";
}

bool lessByRealThenImag(const Complex& a, const Complex& b) {
  if (a.real() != b.real()) return a.real() < b.real();
  return a.imag() < b.imag();
}

// Monic cubic z^3 + c2 z^2 + c1 z + c0 with real coefficients.
struct MonicCubic {
  double c2;
  double c1;
  double c0;

  double operator()(double z) const { return ((z + c2) * z + c1) * z + c0; }
  Complex operator()(Complex z) const { return ((z + c2) * z + c1) * z + c0; }
  Complex derivative(Complex z) const { return (3.0 * z + 2.0 * c2) * z + c1; }
};

// Bisection to the last representable point: slow only by a constant, and it
// cannot fail as long as f(lo) < 0 < f(hi), which every caller proves.
double bisectRoot(const MonicCubic& f, double lo, double hi) {
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    if (f(mid) < 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return std::abs(f(lo)) <= std::abs(f(hi)) ? lo : hi;
}

// Deflation loses a few digits when the real root nearly cancels c2; Newton
// steps on the undeflated cubic win them back. A step is kept only if it
// lowers |f|, so a double root (f' ~ 0) cannot make things worse.
Complex polishRoot(const MonicCubic& f, Complex z) {
  for (int iteration = 0; iteration < 4; ++iteration) {
    const Complex fz = f(z);
    const Complex dfz = f.derivative(z);
    if (fz == 0.0 || dfz == 0.0) break;
    const Complex candidate = z - fz / dfz;
    if (!(std::abs(f(candidate)) < std::abs(fz))) break;
    z = candidate;
  }
  return z;
}

// Roots given one real root r of the cubic, sorted.
std::array<Complex, 3> completeRoots(const MonicCubic& f, double r) {
  // (z - r)(z^2 + p z + q): matching z^2 and z^0 coefficients.
  const double p = f.c2 + r;
  const double q = (r != 0.0) ? -f.c0 / r : f.c1;
  const double halfP = 0.5 * p;
  const double discriminant = halfP * halfP - q;
  Complex z1, z2;
  if (discriminant < 0.0) {
    z1 = polishRoot(f, Complex(-halfP, std::sqrt(-discriminant)));
    z2 = std::conj(z1);
  } else {
    // Avoids cancellation between -p/2 and the square root.
    const double s = -(halfP + std::copysign(std::sqrt(discriminant), halfP));
    const double other = (s != 0.0) ? q / s : 0.0;
    z1 = polishRoot(f, Complex(s, 0.0));
    z2 = polishRoot(f, Complex(other, 0.0));
  }
  std::array<Complex, 3> roots{polishRoot(f, Complex(r, 0.0)), z1, z2};
  std::sort(roots.begin(), roots.end(), lessByRealThenImag);
  return roots;
}

std::array<Complex, 3> solveMonicCubic(const MonicCubic& f) {
  // Cauchy's bound: every root has |z| < R, so f(-R) < 0 < f(R).
  const double R =
      1.0 + std::max({std::abs(f.c2), std::abs(f.c1), std::abs(f.c0)});
  return completeRoots(f, bisectRoot(f, -R, R));
}

// Real parts of the roots that are real up to rounding and positive.
std::vector<double> positiveRealRoots(const std::array<Complex, 3>& roots) {
  constexpr double kImaginaryTolerance = 1e-9;
  std::vector<double> result;
  for (const Complex& z : roots) {
    if (z.real() > 0.0 &&
        std::abs(z.imag()) <= kImaginaryTolerance * std::abs(z))
      result.push_back(z.real());
  }
  return result;
}

constexpr const char* kTwoMass = "RollCrusherTwoMassParams";
constexpr const char* kChain = "RollCrusherChainParams";

}  // namespace

// ---------------------------------------------------------------------------
// RollCrusherTwoMassOracle
// ---------------------------------------------------------------------------

RollCrusherTwoMassOracle::RollCrusherTwoMassOracle(
    const RollCrusherTwoMassParams& params)
    : m_params(params) {
  requirePositive(kTwoMass, "motorInertia (I1)", params.motorInertia, "kg*m^2");
  requirePositive(kTwoMass, "rotorInertia (I)", params.rotorInertia, "kg*m^2");
  requirePositive(kTwoMass, "shaftStiffness (C)", params.shaftStiffness,
                  "N*m/rad");
  requirePositive(kTwoMass, "slipStiffness (gamma)", params.slipStiffness,
                  "N*m*s/rad");
  const double I1 = params.motorInertia;
  const double I = params.rotorInertia;
  m_I0 = I1 + I;
  m_T = m_I0 / params.slipStiffness;
  m_m = I1 / m_I0;
  m_beta0Squared = params.shaftStiffness * m_I0 / (I1 * I);
  m_beta0 = std::sqrt(m_beta0Squared);
}

double RollCrusherTwoMassOracle::calcSlipStiffness(double ratedTorque,
                                                   double synchronousSpeed,
                                                   double ratedSpeed) {
  constexpr const char* where = "RollCrusherTwoMassOracle::calcSlipStiffness";
  requirePositive(where, "ratedTorque (Mn)", ratedTorque, "N*m");
  requirePositive(where, "synchronousSpeed (w0)", synchronousSpeed, "rad/s");
  requirePositive(where, "ratedSpeed (wn)", ratedSpeed, "rad/s");
  if (!(ratedSpeed < synchronousSpeed))
    throwBadParameter(where, "ratedSpeed (wn)", ratedSpeed, "rad/s",
                      "must be below synchronousSpeed (an induction motor "
                      "runs with positive slip)");
  return ratedTorque / (synchronousSpeed - ratedSpeed);
}

double RollCrusherTwoMassOracle::calcLoadHarmonicFrequency(int k,
                                                           double halfPeriod) {
  constexpr const char* where =
      "RollCrusherTwoMassOracle::calcLoadHarmonicFrequency";
  if (k < 1) throwBadParameter(where, "k", k, "", "must be an integer >= 1");
  requirePositive(where, "halfPeriod (l)", halfPeriod, "");
  return k * 3.14159265358979323846 / halfPeriod;
}

Eigen::Matrix3d RollCrusherTwoMassOracle::calcStateMatrix() const {
  const double I1 = m_params.motorInertia;
  const double I = m_params.rotorInertia;
  const double C = m_params.shaftStiffness;
  const double gamma = m_params.slipStiffness;
  Eigen::Matrix3d A;
  A << -gamma / I1, 0.0, -1.0 / I1,  //
      0.0, 0.0, 1.0 / I,             //
      C, -C, 0.0;
  return A;
}

std::complex<double> RollCrusherTwoMassOracle::evalCharacteristicPolynomial(
    std::complex<double> k) const {
  const MonicCubic F{1.0 / (m_m * m_T), m_beta0Squared, m_beta0Squared / m_T};
  return F(k);
}

std::array<std::complex<double>, 3>
RollCrusherTwoMassOracle::calcCharacteristicRoots() const {
  const MonicCubic F{1.0 / (m_m * m_T), m_beta0Squared, m_beta0Squared / m_T};
  const double gamma = m_params.slipStiffness;
  // The paper's bracket (after (25)), with its second endpoint corrected.
  const double lo = -gamma / m_params.motorInertia;
  const double hi = -gamma / m_I0;
  return completeRoots(F, bisectRoot(F, lo, hi));
}

RollCrusherRootSplit RollCrusherTwoMassOracle::calcExactRootSplit() const {
  const std::array<Complex, 3> roots = calcCharacteristicRoots();
  RollCrusherRootSplit split;
  // Real roots come out with an imaginary part of exactly 0 (real bisection,
  // real Newton steps), so the test below is exact.
  const auto complexRoot =
      std::find_if(roots.begin(), roots.end(),
                   [](const Complex& z) { return z.imag() != 0.0; });
  if (complexRoot != roots.end()) {
    for (const Complex& z : roots)
      if (z.imag() == 0.0) split.realRoot = z.real();
    split.alpha = complexRoot->real();
    split.beta = std::abs(complexRoot->imag());
    return split;
  }
  const double target = -m_params.slipStiffness / m_I0;
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < roots.size(); ++i)
    if (std::abs(roots[i].real() - target) <
        std::abs(roots[nearest].real() - target))
      nearest = i;
  split.realRoot = roots[nearest].real();
  double sum = 0.0;
  for (std::size_t i = 0; i < roots.size(); ++i)
    if (i != nearest) sum += roots[i].real();
  split.alpha = 0.5 * sum;
  split.beta = 0.0;
  return split;
}

RollCrusherApproximateRoots
RollCrusherTwoMassOracle::calcPaperApproximateRoots() const {
  const double I1 = m_params.motorInertia;
  const double I = m_params.rotorInertia;
  const double gamma = m_params.slipStiffness;
  RollCrusherApproximateRoots approx;
  approx.realRoot = -gamma / m_I0;
  approx.alpha = -gamma * I / (2.0 * I1 * m_I0);
  const double g1 = gamma / I1;
  const double g2 = gamma * I / (I1 * m_I0);
  approx.betaSquared = m_beta0Squared - g1 * g1 * I / m_I0 + 0.75 * g2 * g2;
  return approx;
}

RollCrusherApproximationErrors
RollCrusherTwoMassOracle::calcApproximationErrors() const {
  const RollCrusherRootSplit exact = calcExactRootSplit();
  const RollCrusherApproximateRoots approx = calcPaperApproximateRoots();
  RollCrusherApproximationErrors errors;
  // Stability (Routh-Hurwitz) keeps realRoot and alpha strictly negative.
  errors.realRoot =
      std::abs(approx.realRoot - exact.realRoot) / std::abs(exact.realRoot);
  errors.alpha = std::abs(approx.alpha - exact.alpha) / std::abs(exact.alpha);
  const double betaApprox = std::sqrt(std::max(approx.betaSquared, 0.0));
  if (exact.beta > 0.0)
    errors.beta = std::abs(betaApprox - exact.beta) / exact.beta;
  else
    errors.beta =
        betaApprox == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return errors;
}

double RollCrusherTwoMassOracle::calcPaperValidityParameter() const {
  const double gamma = m_params.slipStiffness;
  return gamma * gamma * m_params.motorInertia * m_params.rotorInertia /
         (m_params.shaftStiffness * m_I0 * m_I0 * m_I0);
}

double RollCrusherTwoMassOracle::calcRealRootCorrectionParameter() const {
  const double gamma = m_params.slipStiffness;
  const double I = m_params.rotorInertia;
  return gamma * gamma * I * I / (m_params.shaftStiffness * m_I0 * m_I0 * m_I0);
}

std::complex<double> RollCrusherTwoMassOracle::calcTransferFunction(
    std::complex<double> s) const {
  const Complex numerator =
      m_params.shaftStiffness / m_params.rotorInertia * s +
      m_beta0Squared / m_T;
  return numerator / evalCharacteristicPolynomial(s);
}

double RollCrusherTwoMassOracle::calcU(double P) const {
  return P * (P * P - m_beta0Squared);
}

double RollCrusherTwoMassOracle::calcV(double P) const {
  return (m_beta0Squared - P * P / m_m) / m_T;
}

RollCrusherHarmonicResponse RollCrusherTwoMassOracle::calcHarmonicResponse(
    double P) const {
  requireNonNegative("RollCrusherTwoMassOracle::calcHarmonicResponse", "P", P,
                     "rad/s");
  const double u = calcU(P);
  const double v = calcV(P);
  const double a = m_beta0Squared / m_T;
  const double cP = m_params.shaftStiffness / m_params.rotorInertia * P;
  // Cramer on (31) with its true determinant -(u^2 + v^2).
  const double uvNorm = std::hypot(u, v);
  const double uHat = u / uvNorm;
  const double vHat = v / uvNorm;
  RollCrusherHarmonicResponse response;
  response.cosCoefficient = (a * uHat + cP * vHat) / uvNorm;
  response.sinCoefficient = (a * vHat - cP * uHat) / uvNorm;
  response.amplitude = std::hypot(a, cP) / uvNorm;
  response.phase = std::atan2(response.cosCoefficient, response.sinCoefficient);
  return response;
}

double RollCrusherTwoMassOracle::calcDeterminant(double P) const {
  const double u = calcU(P);
  const double v = calcV(P);
  return -(u * u + v * v);
}

RollCrusherCramerNumerators RollCrusherTwoMassOracle::calcCramerNumerators(
    double P) const {
  requireNonNegative("RollCrusherTwoMassOracle::calcCramerNumerators", "P", P,
                     "rad/s");
  const double u = calcU(P);
  const double v = calcV(P);
  const double a = m_beta0Squared / m_T;
  const double cP = m_params.shaftStiffness / m_params.rotorInertia * P;
  return {-(u * a + v * cP), u * cP - v * a};
}

double RollCrusherTwoMassOracle::calcStaticGain() const {
  return std::abs(calcTransferFunction(Complex(0.0, 0.0)));
}

double RollCrusherTwoMassOracle::calcDynamicFactor(double P) const {
  return calcHarmonicResponse(P).amplitude / calcStaticGain();
}

RollCrusherAmplitudePeak RollCrusherTwoMassOracle::calcAmplitudePeak() const {
  // D^2 = N(x)/Den(x) with x = P^2 = beta0^2 xi, scaled by beta0 so that the
  // coefficients are O(1) whatever the units:
  //   N = a^2 + c^2 xi,  Den = xi (xi - 1)^2 + (a - q xi)^2,
  //   a = 1/(T beta0), q = 1/(m T beta0), c = (C/I)/beta0^2 = m.
  // G = N' Den - N Den' is the cubic below; D is stationary where G = 0.
  const double a = 1.0 / (m_T * m_beta0);
  const double q = a / m_m;
  const double c = m_m;
  const double a2 = a * a;
  const double c2 = c * c;
  const double g3 = -2.0 * c2;
  const double g2 = -(c2 * (q * q - 2.0) + 3.0 * a2);
  const double g1 = -2.0 * a2 * (q * q - 2.0);
  const double g0 = a2 * (c2 - 1.0 + 2.0 * a * q);
  const MonicCubic G{g2 / g3, g1 / g3, g0 / g3};

  RollCrusherAmplitudePeak peak;
  for (double xi : positiveRealRoots(solveMonicCubic(G))) {
    const double slope = (3.0 * g3 * xi + 2.0 * g2) * xi + g1;
    if (!(slope < 0.0)) continue;
    const double P = m_beta0 * std::sqrt(xi);
    const double D = calcHarmonicResponse(P).amplitude;
    if (!peak.exists || D > peak.amplitude) peak = {true, P, D};
  }
  return peak;
}

double RollCrusherTwoMassOracle::calcPrintedDeterminant(double P) const {
  const double u = calcU(P);
  const double v = calcV(P);
  return u * u - v * v;
}

std::vector<double> RollCrusherTwoMassOracle::calcPrintedResonanceFrequencies()
    const {
  // u = +v or u = -v, scaled by beta0 (Pn = P/beta0):
  //   Pn^3 + s q Pn^2 - Pn - s a = 0,  s = +1, -1.
  const double a = 1.0 / (m_T * m_beta0);
  const double q = a / m_m;
  std::vector<double> frequencies;
  for (double s : {1.0, -1.0}) {
    for (double Pn : positiveRealRoots(solveMonicCubic({s * q, -1.0, -s * a})))
      frequencies.push_back(m_beta0 * Pn);
  }
  std::sort(frequencies.begin(), frequencies.end());
  return frequencies;
}

double RollCrusherTwoMassOracle::calcPrintedAmplitude(double P) const {
  const RollCrusherCramerNumerators n = calcCramerNumerators(P);
  return std::hypot(n.deltaB, n.deltaC) / calcPrintedDeterminant(P);
}

double RollCrusherTwoMassOracle::calcPrintedPhase(double P) const {
  const RollCrusherCramerNumerators n = calcCramerNumerators(P);
  return std::asin(n.deltaB / std::hypot(n.deltaB, n.deltaC));
}

// ---------------------------------------------------------------------------
// RollCrusherChainOracle
// ---------------------------------------------------------------------------

RollCrusherChainOracle::RollCrusherChainOracle(RollCrusherChainParams params)
    : m_params(std::move(params)) {
  const std::size_t n = m_params.inertias.size();
  if (n < 2)
    throwBadParameter(kChain, "inertias.size()", static_cast<double>(n), "",
                      "must be >= 2 (the motor and at least one rotor mass)");
  if (m_params.stiffnesses.size() != n - 1)
    throwBadParameter(kChain, "stiffnesses.size()",
                      static_cast<double>(m_params.stiffnesses.size()), "",
                      "must be inertias.size() - 1 (one shaft between each "
                      "pair of neighbouring masses)");
  for (std::size_t i = 0; i < n; ++i)
    requirePositive(kChain, indexed("inertias", i), m_params.inertias[i],
                    "kg*m^2");
  for (std::size_t i = 0; i + 1 < n; ++i)
    requirePositive(kChain, indexed("stiffnesses", i), m_params.stiffnesses[i],
                    "N*m/rad");
  requireNonNegative(kChain, "slipStiffness (gamma)", m_params.slipStiffness,
                     "N*m*s/rad");
}

Eigen::VectorXcd RollCrusherChainOracle::makeRowLoads(int numMasses,
                                                      double amplitude,
                                                      double phaseStep) {
  constexpr const char* where = "RollCrusherChainOracle::makeRowLoads";
  if (numMasses < 2)
    throwBadParameter(where, "numMasses", numMasses, "", "must be >= 2");
  requireNonNegative(where, "amplitude (b)", amplitude, "N*m");
  requireFinite(where, "phaseStep", phaseStep, "rad");
  Eigen::VectorXcd loads = Eigen::VectorXcd::Zero(numMasses);
  for (int i = 1; i < numMasses; ++i)
    loads[i] = std::polar(amplitude, (i - 1) * phaseStep);
  return loads;
}

Eigen::MatrixXd RollCrusherChainOracle::calcIncidenceMatrix() const {
  const int n = getNumMasses();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n - 1, n);
  for (int j = 0; j + 1 < n; ++j) {
    S(j, j) = 1.0;
    S(j, j + 1) = -1.0;
  }
  return S;
}

Eigen::MatrixXd RollCrusherChainOracle::calcMassMatrix() const {
  return Eigen::Map<const Eigen::VectorXd>(m_params.inertias.data(),
                                           getNumMasses())
      .asDiagonal();
}

Eigen::MatrixXd RollCrusherChainOracle::calcStiffnessMatrix() const {
  const Eigen::MatrixXd S = calcIncidenceMatrix();
  const Eigen::Map<const Eigen::VectorXd> C(m_params.stiffnesses.data(),
                                            getNumMasses() - 1);
  return S.transpose() * C.asDiagonal() * S;
}

Eigen::MatrixXd RollCrusherChainOracle::calcDampingMatrix() const {
  const int n = getNumMasses();
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  D(0, 0) = m_params.slipStiffness;
  return D;
}

RollCrusherChainModes RollCrusherChainOracle::calcUndampedModes() const {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      calcStiffnessMatrix(), calcMassMatrix());
  if (solver.info() != Eigen::Success)
    throw std::runtime_error(
        "RollCrusherChainOracle::calcUndampedModes: eigensolver failed");
  RollCrusherChainModes modes;
  // The rigid-body eigenvalue is 0 in exact arithmetic; rounding may make it
  // slightly negative.
  modes.frequencies = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  modes.shapes = solver.eigenvectors();
  for (int j = 0; j < modes.shapes.cols(); ++j)
    if (modes.shapes(0, j) < 0.0) modes.shapes.col(j) *= -1.0;
  return modes;
}

Eigen::MatrixXd RollCrusherChainOracle::calcStateMatrix() const {
  const int n = getNumMasses();
  const Eigen::MatrixXd S = calcIncidenceMatrix();
  const Eigen::Map<const Eigen::VectorXd> inertias(m_params.inertias.data(), n);
  const Eigen::Map<const Eigen::VectorXd> C(m_params.stiffnesses.data(), n - 1);
  const Eigen::VectorXd inverseInertias = inertias.cwiseInverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n - 1, 2 * n - 1);
  A(0, 0) = -m_params.slipStiffness / m_params.inertias[0];
  A.topRightCorner(n, n - 1) = -(inverseInertias.asDiagonal() * S.transpose());
  A.bottomLeftCorner(n - 1, n) = C.asDiagonal() * S;
  return A;
}

std::vector<std::complex<double>>
RollCrusherChainOracle::calcDampedEigenvalues() const {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(calcStateMatrix(), false);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error(
        "RollCrusherChainOracle::calcDampedEigenvalues: eigensolver failed");
  std::vector<Complex> eigenvalues(
      solver.eigenvalues().data(),
      solver.eigenvalues().data() + solver.eigenvalues().size());
  std::sort(eigenvalues.begin(), eigenvalues.end(), lessByRealThenImag);
  return eigenvalues;
}

RollCrusherChainResponse RollCrusherChainOracle::calcHarmonicResponse(
    double P, const Eigen::VectorXcd& loads) const {
  constexpr const char* where = "RollCrusherChainOracle::calcHarmonicResponse";
  requirePositive(where, "P", P, "rad/s");
  const int n = getNumMasses();
  if (loads.size() != n)
    throwBadParameter(where, "loads.size()", static_cast<double>(loads.size()),
                      "", "must equal the number of masses");
  for (int i = 0; i < n; ++i) {
    requireFinite(where, indexed("loads", i) + ".real()", loads[i].real(),
                  "N*m");
    requireFinite(where, indexed("loads", i) + ".imag()", loads[i].imag(),
                  "N*m");
  }
  const Eigen::MatrixXcd Z =
      (calcStiffnessMatrix() - P * P * calcMassMatrix()).cast<Complex>() +
      Complex(0.0, P) * calcDampingMatrix().cast<Complex>();
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(Z);
  if (!lu.isInvertible()) {
    std::ostringstream message;
    message.precision(17);
    message << where << ": P = " << P
            << " rad/s is an undamped eigenfrequency of the chain "
               "(slipStiffness = 0): no steady response";
    throw std::domain_error(message.str());
  }
  RollCrusherChainResponse response;
  // Loads resist the motion: they enter (2) with a minus sign.
  response.angles = lu.solve(-loads);
  const Eigen::Map<const Eigen::VectorXd> C(m_params.stiffnesses.data(), n - 1);
  response.shaftTorques =
      (C.asDiagonal() * calcIncidenceMatrix()).cast<Complex>() *
      response.angles;
  return response;
}

RollCrusherTwoMassParams RollCrusherChainOracle::reduceToTwoMass(
    RollCrusherChainReduction reduction) const {
  RollCrusherTwoMassParams params;
  params.motorInertia = m_params.inertias.front();
  params.rotorInertia = 0.0;
  for (std::size_t i = 1; i < m_params.inertias.size(); ++i)
    params.rotorInertia += m_params.inertias[i];
  params.slipStiffness = m_params.slipStiffness;
  switch (reduction) {
    case RollCrusherChainReduction::SeriesCompliance: {
      double compliance = 0.0;
      for (double C : m_params.stiffnesses) compliance += 1.0 / C;
      params.shaftStiffness = 1.0 / compliance;
      break;
    }
    case RollCrusherChainReduction::FirstFrequency: {
      const double omega1 = calcUndampedModes().frequencies[1];
      const double I0 = params.motorInertia + params.rotorInertia;
      params.shaftStiffness =
          omega1 * omega1 * params.motorInertia * params.rotorInertia / I0;
      break;
    }
  }
  return params;
}

// ---------------------------------------------------------------------------
// RollCrusherReducer
// ---------------------------------------------------------------------------

double RollCrusherReducer::reflectInertia(double lowSpeedInertia,
                                          double ratio) {
  constexpr const char* where = "RollCrusherReducer::reflectInertia";
  requireNonNegative(where, "lowSpeedInertia", lowSpeedInertia, "kg*m^2");
  requirePositive(where, "ratio (u)", ratio, "");
  return lowSpeedInertia / (ratio * ratio);
}

double RollCrusherReducer::reflectStiffness(double lowSpeedStiffness,
                                            double ratio) {
  constexpr const char* where = "RollCrusherReducer::reflectStiffness";
  requirePositive(where, "lowSpeedStiffness", lowSpeedStiffness, "N*m/rad");
  requirePositive(where, "ratio (u)", ratio, "");
  return lowSpeedStiffness / (ratio * ratio);
}

double RollCrusherReducer::reflectTorque(double lowSpeedTorque, double ratio) {
  constexpr const char* where = "RollCrusherReducer::reflectTorque";
  requireFinite(where, "lowSpeedTorque", lowSpeedTorque, "N*m");
  requirePositive(where, "ratio (u)", ratio, "");
  return lowSpeedTorque / ratio;
}

}  // namespace milldyn::oracles
