// Tests of the seed-004 oracle (single-roll toothed crusher) on its own: every
// expected value comes from a hand calculation, a limiting case with a known
// closed form, or an independent method written here (state-matrix
// eigenvalues, fixed-step RK4 of the equations of motion, dense scans).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "validation/oracles/RollCrusherOracle.h"

namespace milldyn::oracles {
namespace {

using Complex = std::complex<double>;

constexpr double kPi = 3.14159265358979323846;

// Hand-computed values are exact rationals or one sqrt, so only rounding
// separates them from the oracle.
constexpr double kRoundoffTol = 1e-12;
// Roots from bisection + Newton vs Eigen's Hessenberg QR: both backward stable,
// so they agree to a few ulps of the largest root magnitude; the brief's 1e-10
// leaves room for the 1e4 spread of root magnitudes in the stiff-motor cases.
constexpr double kRootMatchTol = 1e-10;
// RK4 with at most 1 ms steps, h |k|max < 0.04: a damped, forced system does
// not accumulate step errors, its discrete steady state differs from the exact
// one by ~(h |k|)^4/120 < 1e-8; transients are decayed by e^-25 before
// measuring. The margin covers the asymptotic estimates' constants.
constexpr double kRk4AmplitudeTol = 1e-5;  // relative
constexpr double kRk4PhaseTol = 1e-5;      // rad

// ---------------------------------------------------------------------------
// Independent models, written from the paper's equations of motion.
// ---------------------------------------------------------------------------

// x = (phi1', phi2', M0):  I1 w1' = -gamma w1 - M0,  I w2' = M0 - M,
// M0' = C (w1 - w2)   (14)-(16) with the constant gamma w0 dropped.
Eigen::Matrix3d buildTwoMassStateMatrix(const RollCrusherTwoMassParams& p) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A(0, 0) = -p.slipStiffness / p.motorInertia;
  A(0, 2) = -1.0 / p.motorInertia;
  A(1, 2) = 1.0 / p.rotorInertia;
  A(2, 0) = p.shaftStiffness;
  A(2, 1) = -p.shaftStiffness;
  return A;
}

// Slowest decay rate of the free motion, for how long to let transients die.
double slowestDecayRate(const Eigen::MatrixXd& A) {
  const Eigen::VectorXcd eigenvalues =
      Eigen::EigenSolver<Eigen::MatrixXd>(A).eigenvalues();
  double rate = std::numeric_limits<double>::infinity();
  for (int i = 0; i < eigenvalues.size(); ++i)
    rate = std::min(rate, -eigenvalues[i].real());
  return rate;
}

// Steady-state complex amplitudes (output = Im(X e^{iPt})) of the outputs of
// a linear ODE under harmonic forcing, by classic RK4 and projection on
// sin/cos over whole periods (equally spaced samples integrate a sinusoid
// exactly). Transients are left to decay by e^-25 first.
Eigen::VectorXcd integrateToSteadyState(
    const std::function<Eigen::VectorXd(double, const Eigen::VectorXd&)>& rhs,
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& output,
    Eigen::VectorXd x, double P, double decayRate) {
  constexpr double kMaxStep = 1e-3;  // s
  constexpr int kMeasuredPeriods = 2;
  const double period = 2.0 * kPi / P;
  const int stepsPerPeriod =
      std::max(400, static_cast<int>(std::ceil(period / kMaxStep)));
  const double h = period / stepsPerPeriod;
  const int settlePeriods =
      static_cast<int>(std::ceil(25.0 / decayRate / period));
  const long settleSteps = static_cast<long>(settlePeriods) * stepsPerPeriod;
  const long measuredSteps =
      static_cast<long>(kMeasuredPeriods) * stepsPerPeriod;
  Eigen::VectorXd sumSin = Eigen::VectorXd::Zero(output(x).size());
  Eigen::VectorXd sumCos = sumSin;
  for (long step = 0; step < settleSteps + measuredSteps; ++step) {
    const double t = step * h;
    if (step >= settleSteps) {
      const Eigen::VectorXd y = output(x);
      sumSin += y * std::sin(P * t);
      sumCos += y * std::cos(P * t);
    }
    const Eigen::VectorXd k1 = rhs(t, x);
    const Eigen::VectorXd k2 = rhs(t + 0.5 * h, x + 0.5 * h * k1);
    const Eigen::VectorXd k3 = rhs(t + 0.5 * h, x + 0.5 * h * k2);
    const Eigen::VectorXd k4 = rhs(t + h, x + h * k3);
    x += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  // y = S sin + Cc cos = Im((S + i Cc) e^{iPt}).
  const double scale = 2.0 / static_cast<double>(measuredSteps);
  Eigen::VectorXcd amplitudes(sumSin.size());
  for (int i = 0; i < sumSin.size(); ++i)
    amplitudes[i] = Complex(scale * sumSin[i], scale * sumCos[i]);
  return amplitudes;
}

// M0 of the two-mass model (14)-(18) under M = b sin(P t), by RK4 on the
// angles. w0 is kept nonzero on purpose: it must only shift the mean speed.
Complex measureTwoMassShaftTorque(const RollCrusherTwoMassParams& p, double P,
                                  double b) {
  constexpr double kSynchronousSpeed = 10.0;  // rad/s, arbitrary
  const auto rhs = [&](double t, const Eigen::VectorXd& x) {
    // x = (phi1, phi2, w1, w2)
    const double M0 = p.shaftStiffness * (x[0] - x[1]);
    const double M1 = p.slipStiffness * (kSynchronousSpeed - x[2]);
    Eigen::VectorXd dx(4);
    dx << x[2], x[3], (M1 - M0) / p.motorInertia,
        (M0 - b * std::sin(P * t)) / p.rotorInertia;
    return dx;
  };
  const auto output = [&](const Eigen::VectorXd& x) {
    return Eigen::VectorXd::Constant(1, p.shaftStiffness * (x[0] - x[1]));
  };
  Eigen::VectorXd x0(4);
  x0 << 0.0, 0.0, kSynchronousSpeed, kSynchronousSpeed;
  const double decay = slowestDecayRate(buildTwoMassStateMatrix(p));
  return integrateToSteadyState(rhs, output, x0, P, decay)[0] / b;
}

// Chain (2)-(4) built here from the equations, for RK4 and eigenvalue checks.
struct TestChain {
  Eigen::VectorXd inertias;
  Eigen::VectorXd stiffnesses;
  double gamma;

  RollCrusherChainParams params() const {
    return {
        std::vector<double>(inertias.data(), inertias.data() + inertias.size()),
        std::vector<double>(stiffnesses.data(),
                            stiffnesses.data() + stiffnesses.size()),
        gamma};
  }
  int n() const { return static_cast<int>(inertias.size()); }
  // Torques on each mass from the shafts, written term by term from (2).
  Eigen::VectorXd shaftTorquesOnMasses(const Eigen::VectorXd& phi) const {
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(n());
    for (int j = 0; j + 1 < n(); ++j) {
      const double Mj = stiffnesses[j] * (phi[j] - phi[j + 1]);
      tau[j] -= Mj;
      tau[j + 1] += Mj;
    }
    return tau;
  }
  // First-order system in (phi', M_{j,j+1}), with the chain's own ordering.
  Eigen::MatrixXd stateMatrix() const {
    const int N = 2 * n() - 1;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N, N);
    A(0, 0) = -gamma / inertias[0];
    for (int j = 0; j + 1 < n(); ++j) {
      A(j, n() + j) -= 1.0 / inertias[j];
      A(j + 1, n() + j) += 1.0 / inertias[j + 1];
      A(n() + j, j) = stiffnesses[j];
      A(n() + j, j + 1) = -stiffnesses[j];
    }
    return A;
  }
};

// Each shaft torque of the chain under loads Im(L e^{iPt}), by RK4.
Eigen::VectorXcd measureChainShaftTorques(const TestChain& chain, double P,
                                          const Eigen::VectorXcd& loads) {
  const int n = chain.n();
  const auto rhs = [&](double t, const Eigen::VectorXd& x) {
    const Eigen::VectorXd phi = x.head(n);
    const Eigen::VectorXd w = x.tail(n);
    Eigen::VectorXd torque = chain.shaftTorquesOnMasses(phi);
    torque[0] -= chain.gamma * w[0];
    for (int i = 0; i < n; ++i)
      torque[i] -= (loads[i] * std::exp(Complex(0.0, P * t))).imag();
    Eigen::VectorXd dx(2 * n);
    dx << w, torque.cwiseQuotient(chain.inertias);
    return dx;
  };
  const auto output = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd torques(n - 1);
    for (int j = 0; j + 1 < n; ++j)
      torques[j] = chain.stiffnesses[j] * (x[j] - x[j + 1]);
    return torques;
  };
  const double decay = slowestDecayRate(chain.stateMatrix());
  return integrateToSteadyState(rhs, output, Eigen::VectorXd::Zero(2 * n), P,
                                decay);
}

// Index of the entry of `candidates` nearest to z.
std::size_t nearestIndex(const std::vector<Complex>& candidates, Complex z) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i)
    if (std::abs(candidates[i] - z) < std::abs(candidates[best] - z)) best = i;
  return best;
}

template <typename F>
void expectInvalidArgumentNaming(F&& f, const std::string& name) {
  try {
    f();
    ADD_FAILURE() << "expected std::invalid_argument naming " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos)
        << "message: " << e.what();
  }
}

// A well-separated case used throughout: beta0^2 = 100 * 3/2 = 150,
// T = 3/5 s, m = 1/3, slowest decay ~1.6 1/s.
const RollCrusherTwoMassParams kModerate{1.0, 2.0, 100.0, 5.0};

// ---------------------------------------------------------------------------
// Two-mass model
// ---------------------------------------------------------------------------

TEST(RollCrusherTwoMassOracle, DerivedQuantitiesMatchHandCalculation) {
  // I1 = 1, I = 3, C = 12, gamma = 2: I0 = 4, T = I0/gamma = 2, m = 1/4,
  // beta0^2 = 12 * 4/3 = 16; F(k) = k^3 + 2 k^2 + 16 k + 8.
  const RollCrusherTwoMassOracle oracle({1.0, 3.0, 12.0, 2.0});
  EXPECT_NEAR(oracle.getTotalInertia(), 4.0, kRoundoffTol);
  EXPECT_NEAR(oracle.getTimeConstant(), 2.0, kRoundoffTol);
  EXPECT_NEAR(oracle.getInertiaFraction(), 0.25, kRoundoffTol);
  EXPECT_NEAR(oracle.getUndampedFrequency(), 4.0, kRoundoffTol);
  EXPECT_NEAR(std::abs(oracle.evalCharacteristicPolynomial(1.0) - 27.0), 0.0,
              kRoundoffTol);
  EXPECT_NEAR(std::abs(oracle.evalCharacteristicPolynomial(Complex(0.0, 1.0)) -
                       Complex(6.0, 15.0)),
              0.0, kRoundoffTol);
  // gamma^2 I1 I/(C I0^3) = 4*3/(12*64) = 1/64, which the paper equates to
  // gamma^2/(I0^2 beta0^2) = 4/(16*16) = 1/64; gamma^2 I^2/(C I0^3) = 3/64.
  EXPECT_NEAR(oracle.calcPaperValidityParameter(), 1.0 / 64.0, kRoundoffTol);
  EXPECT_NEAR(oracle.calcRealRootCorrectionParameter(), 3.0 / 64.0,
              kRoundoffTol);
  // k1 ~ -2/4, alpha ~ -2*3/(2*1*4) = -3/4,
  // beta^2 ~ 16 - 4*3/4 + 3/4*(6/4)^2 = 14.6875.
  const RollCrusherApproximateRoots approx = oracle.calcPaperApproximateRoots();
  EXPECT_NEAR(approx.realRoot, -0.5, kRoundoffTol);
  EXPECT_NEAR(approx.alpha, -0.75, kRoundoffTol);
  EXPECT_NEAR(approx.betaSquared, 14.6875, kRoundoffTol);
}

TEST(RollCrusherTwoMassOracle, SlipStiffnessAndLoadHarmonicsMatchHandValues) {
  // Mn = 100 N*m, w0 = 104, wn = 100 rad/s: gamma = 100/4.
  EXPECT_NEAR(RollCrusherTwoMassOracle::calcSlipStiffness(100.0, 104.0, 100.0),
              25.0, kRoundoffTol);
  // (27) with l = pi/240: P_k = 240 k.
  const double l = RollCrusherTwoMassOracle::kPaperLoadHalfPeriod;
  EXPECT_NEAR(l, kPi / 240.0, kRoundoffTol);
  EXPECT_NEAR(RollCrusherTwoMassOracle::calcLoadHarmonicFrequency(1, l), 240.0,
              240.0 * kRoundoffTol);
  EXPECT_NEAR(RollCrusherTwoMassOracle::calcLoadHarmonicFrequency(3, l), 720.0,
              720.0 * kRoundoffTol);
}

TEST(RollCrusherTwoMassOracle, StateMatrixIsTheLinearisedEquationsOfMotion) {
  const Eigen::Matrix3d expected = buildTwoMassStateMatrix(kModerate);
  EXPECT_TRUE(RollCrusherTwoMassOracle(kModerate).calcStateMatrix().isApprox(
      expected, kRoundoffTol));
}

TEST(RollCrusherTwoMassOracle,
     RootsSatisfyCubicAndMatchStateMatrixEigenvalues) {
  const std::vector<RollCrusherTwoMassParams> cases = {
      {1.0, 3.0, 12.0, 2.0},       // complex pair, hand example
      kModerate,                   // complex pair, real root leftmost
      {1.0, 10.0, 1000.0, 5.0},    // heavy rotor, light damping
      {1.0, 1e4, 1e4, 1e4},        // heavy rotor, stiff motor (Maxwell limit)
      {1.0, 1e4, 1e4, 3162.0},     // three real roots
      {2.0, 0.0306, 510.0, 455.0}  // light reflected rotor (see docs)
  };
  for (const RollCrusherTwoMassParams& p : cases) {
    SCOPED_TRACE(::testing::Message()
                 << "I1=" << p.motorInertia << " I=" << p.rotorInertia
                 << " C=" << p.shaftStiffness << " gamma=" << p.slipStiffness);
    const RollCrusherTwoMassOracle oracle(p);
    const std::array<Complex, 3> roots = oracle.calcCharacteristicRoots();
    const Eigen::Vector3cd eig =
        Eigen::EigenSolver<Eigen::Matrix3d>(buildTwoMassStateMatrix(p))
            .eigenvalues();
    std::vector<Complex> eigenvalues(eig.data(), eig.data() + 3);
    double scale = 0.0;
    for (const Complex& z : eigenvalues) scale = std::max(scale, std::abs(z));

    // Coefficients of (25), written from the parameters here.
    const double I0 = p.motorInertia + p.rotorInertia;
    const double beta0Sq =
        p.shaftStiffness * I0 / (p.motorInertia * p.rotorInertia);
    const double c2 = p.slipStiffness / p.motorInertia;
    const double c0 = p.slipStiffness * beta0Sq / I0;
    for (const Complex& k : roots) {
      const Complex F = ((k + c2) * k + beta0Sq) * k + c0;
      const double magnitude = std::pow(std::abs(k), 3) + c2 * std::norm(k) +
                               beta0Sq * std::abs(k) + c0;
      EXPECT_LE(std::abs(F), kRoundoffTol * magnitude) << "root " << k;
      const std::size_t match = nearestIndex(eigenvalues, k);
      EXPECT_LE(std::abs(eigenvalues[match] - k), kRootMatchTol * scale)
          << "root " << k << " eigenvalue " << eigenvalues[match];
      eigenvalues.erase(eigenvalues.begin() + static_cast<long>(match));
    }
    // Sorted by real part, then imaginary part.
    for (int i = 0; i + 1 < 3; ++i) {
      EXPECT_TRUE(roots[i].real() < roots[i + 1].real() ||
                  (roots[i].real() == roots[i + 1].real() &&
                   roots[i].imag() <= roots[i + 1].imag()));
    }
  }
}

TEST(RollCrusherTwoMassOracle, CubicAtBracketEndsEqualsCorrectedPaperValues) {
  // F(-gamma/I1) = -C gamma/I1^2 (= the paper's -beta0^2 gamma I/(I0 I1)) and
  // F(-gamma/I0) = gamma^3 I/(I1 I0^3) (printed with I0^2 and labelled
  // F(-gamma/I1)). I1 = 1, I = 3, C = 12, gamma = 2: -24 and 8*3/64 = 0.375.
  const RollCrusherTwoMassOracle oracle({1.0, 3.0, 12.0, 2.0});
  EXPECT_NEAR(oracle.evalCharacteristicPolynomial(-2.0).real(), -24.0,
              kRoundoffTol);
  EXPECT_NEAR(oracle.evalCharacteristicPolynomial(-0.5).real(), 0.375,
              kRoundoffTol);
  const RollCrusherRootSplit split = oracle.calcExactRootSplit();
  EXPECT_GE(split.realRoot, -2.0);
  EXPECT_LE(split.realRoot, -0.5);
}

TEST(RollCrusherTwoMassOracle,
     RootsTendToZeroAndPlusMinusIBeta0AsGammaVanishes) {
  // I1 = 1, I = 3, C = 12: beta0 = 4. For gamma -> 0, F(k) -> k (k^2 + 16).
  // First-order shifts: k1 ~ -gamma/I0, pair ~ -gamma I/(2 I1 I0) +/- i beta0,
  // so each root is within gamma/I1 of its limit and the error of the
  // first-order form shrinks like gamma^3.
  for (double gamma : {1e-2, 1e-4, 1e-6}) {
    SCOPED_TRACE(::testing::Message() << "gamma=" << gamma);
    const RollCrusherTwoMassOracle oracle({1.0, 3.0, 12.0, gamma});
    const std::array<Complex, 3> roots = oracle.calcCharacteristicRoots();
    // Order: pair (alpha = -3 gamma/8) left of k1 = -gamma/4.
    EXPECT_LE(std::abs(roots[0] - Complex(0.0, -4.0)), gamma);
    EXPECT_LE(std::abs(roots[1] - Complex(0.0, 4.0)), gamma);
    EXPECT_LE(std::abs(roots[2]), gamma);
    // Next order of the series (docs): relative 3 gamma^2/64 for k1.
    // Plus a few ulps of |k| ~ 4 for the pair's real part.
    constexpr double kRoundoffAbsTol = 1e-14;
    EXPECT_NEAR(roots[2].real(), -gamma / 4.0,
                0.1 * gamma * gamma * gamma + kRoundoffAbsTol);
    EXPECT_NEAR(roots[1].real(), -3.0 * gamma / 8.0,
                0.1 * gamma * gamma * gamma + kRoundoffAbsTol);
  }
}

TEST(RollCrusherTwoMassOracle,
     ApproximationErrorsFollowNextOrderOfSeriesWhenValid) {
  // I1 = 1, I = 3, C = 1e4, gamma = 10: validity = 100*3/(1e4*64) = 4.6875e-4,
  // gamma^2 I^2/(C I0^3) = 1.40625e-3. Series (docs, sympy) for the relative
  // errors: k1 -> gamma^2 I^2/(C I0^3), alpha -> gamma^2 I1 I/(C I0^3),
  // beta -> half that of beta^2: gamma^4 I^3 (I - 2 I1)/(4 C^2 I0^6)
  // = 1e4*27/(4e8*4096) = 1.6479e-7.
  const RollCrusherTwoMassOracle oracle({1.0, 3.0, 1e4, 10.0});
  // The next terms of the series are O(validity) ~ 1e-3 relative to these,
  // with coefficients of order one to ten.
  constexpr double kLeadingTermTol = 0.02;
  const RollCrusherApproximationErrors errors =
      oracle.calcApproximationErrors();
  EXPECT_NEAR(errors.realRoot / 1.40625e-3, 1.0, kLeadingTermTol);
  EXPECT_NEAR(errors.alpha / 4.6875e-4, 1.0, kLeadingTermTol);
  EXPECT_NEAR(errors.beta / 1.6479e-7, 1.0, kLeadingTermTol);
  EXPECT_NEAR(oracle.calcPaperValidityParameter(), 4.6875e-4, kRoundoffTol);
}

TEST(RollCrusherTwoMassOracle,
     ApproximationsFailForHeavyRotorDespiteSmallValidity) {
  // I1 = 1, I = 1e4, C = 1e4, gamma = 1e4: the paper's parameter is
  // 1e8*1e4/(1e4*1.0001e4^3) ~ 1e-4 << 1, yet gamma^2 I^2/(C I0^3) ~ 1.
  // Hand limit: gamma/I1 >> beta0 makes the motor a damper gamma (its inertia
  // negligible), so the rotor hangs on a spring C in series with a damper:
  // k^2 + (C/gamma) k + C/I = k^2 + k + 1, roots -1/2 +/- i sqrt(3)/2, while
  // the motor root is ~ -gamma/I1 = -1e4. The paper puts k1 at -gamma/I0 ~ -1
  // and the pair at -5000 +/- i sqrt(negative).
  const RollCrusherTwoMassOracle oracle({1.0, 1e4, 1e4, 1e4});
  EXPECT_LT(oracle.calcPaperValidityParameter(), 1e-4);
  EXPECT_GT(oracle.calcRealRootCorrectionParameter(), 0.99);

  // The limit neglects O(I1/I) and O(C I1/gamma^2), both 1e-4.
  constexpr double kMaxwellLimitTol = 1e-3;
  const RollCrusherRootSplit exact = oracle.calcExactRootSplit();
  EXPECT_NEAR(exact.realRoot / -1e4, 1.0, kMaxwellLimitTol);
  EXPECT_NEAR(exact.alpha, -0.5, kMaxwellLimitTol);
  EXPECT_NEAR(exact.beta, std::sqrt(3.0) / 2.0, kMaxwellLimitTol);

  const RollCrusherApproximateRoots approx = oracle.calcPaperApproximateRoots();
  EXPECT_LT(approx.betaSquared, 0.0);
  const RollCrusherApproximationErrors errors =
      oracle.calcApproximationErrors();
  EXPECT_GT(errors.realRoot, 0.99);
  EXPECT_GT(errors.alpha, 1000.0);
  EXPECT_EQ(errors.beta, 1.0);
}

TEST(RollCrusherTwoMassOracle, HarmonicResponseMatchesRk4SteadyState) {
  const RollCrusherTwoMassOracle oracle(kModerate);
  const double beta0 = oracle.getUndampedFrequency();
  constexpr double kLoadAmplitude = 3.0;  // N*m, any
  for (double ratio : {0.3, 0.95, 1.6, 2.5}) {
    const double P = ratio * beta0;
    SCOPED_TRACE(::testing::Message() << "P/beta0=" << ratio);
    const Complex measured =
        measureTwoMassShaftTorque(kModerate, P, kLoadAmplitude);
    const RollCrusherHarmonicResponse response = oracle.calcHarmonicResponse(P);
    EXPECT_NEAR(response.amplitude / std::abs(measured), 1.0, kRk4AmplitudeTol);
    EXPECT_NEAR(std::remainder(response.phase - std::arg(measured), 2.0 * kPi),
                0.0, kRk4PhaseTol);
    // M0 = b (B cos + Ck sin): Ck is the sin part, B the cos part.
    EXPECT_NEAR(response.sinCoefficient, measured.real(),
                kRk4AmplitudeTol * std::abs(measured));
    EXPECT_NEAR(response.cosCoefficient, measured.imag(),
                kRk4AmplitudeTol * std::abs(measured));
  }
}

TEST(RollCrusherTwoMassOracle,
     CoefficientsSolvePaperSystem31WithTrueDeterminant) {
  // (31) and the numerators of (32) are printed correctly; only the
  // determinant is not. Everything here is typed from the paper.
  const RollCrusherTwoMassParams& p = kModerate;
  const RollCrusherTwoMassOracle oracle(p);
  const double T = oracle.getTimeConstant();
  const double m = oracle.getInertiaFraction();
  const double b2 = std::pow(oracle.getUndampedFrequency(), 2);
  const double CI = p.shaftStiffness / p.rotorInertia;
  for (double P : {0.5, 7.0, 12.0, 40.0}) {
    SCOPED_TRACE(::testing::Message() << "P=" << P);
    const double u = P * P * P - P * b2;
    const double v = b2 / T - P * P / (m * T);
    const double deltaB = P / T * (b2 * (b2 - P * P) - CI * (b2 - P * P / m));
    const double deltaC =
        CI * P * (P * P * P - P * b2) - b2 / (T * T) * (b2 - P * P / m);
    const double trueDelta = -(u * u + v * v);
    const RollCrusherHarmonicResponse r = oracle.calcHarmonicResponse(P);
    const double scale = std::abs(trueDelta);
    EXPECT_NEAR(r.cosCoefficient * u + r.sinCoefficient * v, b2 / T,
                kRoundoffTol * std::hypot(b2 / T, CI * P) * 10.0);
    EXPECT_NEAR(r.cosCoefficient * v - r.sinCoefficient * u, CI * P,
                kRoundoffTol * std::hypot(b2 / T, CI * P) * 10.0);
    EXPECT_NEAR(r.cosCoefficient, deltaB / trueDelta,
                kRoundoffTol * std::hypot(deltaB, deltaC) / scale * 10.0);
    EXPECT_NEAR(r.sinCoefficient, deltaC / trueDelta,
                kRoundoffTol * std::hypot(deltaB, deltaC) / scale * 10.0);
    EXPECT_NEAR(oracle.calcDeterminant(P), trueDelta, kRoundoffTol * scale);
    const RollCrusherCramerNumerators n = oracle.calcCramerNumerators(P);
    const double nScale = std::hypot(deltaB, deltaC);
    EXPECT_NEAR(n.deltaB, deltaB, kRoundoffTol * nScale * 10.0);
    EXPECT_NEAR(n.deltaC, deltaC, kRoundoffTol * nScale * 10.0);
  }
}

TEST(RollCrusherTwoMassOracle, StaticGainIsOneSoDynamicFactorEqualsAmplitude) {
  // H(0) = (beta0^2/T)/(beta0^2/T) = 1: in steady running the motor slip
  // carries the whole mean load through the shaft.
  const RollCrusherTwoMassOracle oracle(kModerate);
  EXPECT_NEAR(oracle.calcStaticGain(), 1.0, kRoundoffTol);
  EXPECT_NEAR(oracle.calcHarmonicResponse(0.0).amplitude, 1.0, kRoundoffTol);
  EXPECT_NEAR(oracle.calcHarmonicResponse(0.0).phase, 0.0, kRoundoffTol);
  // D = 1 + O(P^2): at P = 1e-6 the deviation is ~1e-12.
  EXPECT_NEAR(oracle.calcHarmonicResponse(1e-6).amplitude, 1.0, 1e-9);
  for (double P : {1.0, 11.0, 30.0})
    EXPECT_DOUBLE_EQ(oracle.calcDynamicFactor(P),
                     oracle.calcHarmonicResponse(P).amplitude);
}

// Highest interior local maximum of D on a dense log grid, refined by golden
// section: an independent search for the resonant peak.
RollCrusherAmplitudePeak scanForPeak(const RollCrusherTwoMassOracle& oracle) {
  const double beta0 = oracle.getUndampedFrequency();
  const auto D = [&](double P) {
    return oracle.calcHarmonicResponse(P).amplitude;
  };
  constexpr int kGridPoints = 20000;
  const double logLo = std::log(1e-4 * beta0);
  const double logHi = std::log(1e2 * beta0);
  std::vector<double> grid(kGridPoints);
  for (int i = 0; i < kGridPoints; ++i)
    grid[i] = std::exp(logLo + (logHi - logLo) * i / (kGridPoints - 1));
  RollCrusherAmplitudePeak best;
  for (int i = 1; i + 1 < kGridPoints; ++i) {
    if (!(D(grid[i]) > D(grid[i - 1]) && D(grid[i]) >= D(grid[i + 1])))
      continue;
    double a = grid[i - 1];
    double b = grid[i + 1];
    const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
      const double x1 = b - invPhi * (b - a);
      const double x2 = a + invPhi * (b - a);
      if (D(x1) < D(x2))
        a = x1;
      else
        b = x2;
    }
    const double P = 0.5 * (a + b);
    if (!best.exists || D(P) > best.amplitude) best = {true, P, D(P)};
  }
  return best;
}

TEST(RollCrusherTwoMassOracle, AmplitudePeakMatchesDenseScan) {
  const std::vector<RollCrusherTwoMassParams> cases = {
      kModerate,
      {1.0, 3.0, 12.0, 2.0},
      {1.0, 10.0, 1000.0, 5.0},
      {1.0, 3.0, 1e4, 10.0},
      {2.0, 0.0306, 510.0, 455.0}};
  // A maximum is flat: golden section pins P only to ~sqrt(eps) relative,
  // while D itself agrees to rounding.
  constexpr double kPeakFrequencyTol = 1e-6;
  constexpr double kPeakAmplitudeTol = 1e-11;
  for (const RollCrusherTwoMassParams& p : cases) {
    SCOPED_TRACE(::testing::Message()
                 << "I1=" << p.motorInertia << " I=" << p.rotorInertia);
    const RollCrusherTwoMassOracle oracle(p);
    const RollCrusherAmplitudePeak expected = scanForPeak(oracle);
    const RollCrusherAmplitudePeak peak = oracle.calcAmplitudePeak();
    ASSERT_EQ(peak.exists, expected.exists);
    EXPECT_NEAR(peak.frequency / expected.frequency, 1.0, kPeakFrequencyTol);
    EXPECT_NEAR(peak.amplitude / expected.amplitude, 1.0, kPeakAmplitudeTol);
  }
}

TEST(RollCrusherTwoMassOracle,
     HeavyRotorStiffMotorPeakIsThatOfASecondOrderLowPass) {
  // Maxwell limit of the heavy-rotor case above: M0/M = wn^2/(s^2 + (C/gamma)
  // s + wn^2), wn^2 = C/I = 1, zeta = C/(2 gamma wn) = 1/2. A second-order
  // low-pass peaks at wn sqrt(1 - 2 zeta^2) = 1/sqrt(2) with height
  // 1/(2 zeta sqrt(1 - zeta^2)) = 2/sqrt(3).
  const RollCrusherTwoMassOracle oracle({1.0, 1e4, 1e4, 1e4});
  constexpr double kMaxwellLimitTol = 1e-3;  // O(I1/I), O(C I1/gamma^2) = 1e-4
  const RollCrusherAmplitudePeak peak = oracle.calcAmplitudePeak();
  ASSERT_TRUE(peak.exists);
  EXPECT_NEAR(peak.frequency, 1.0 / std::sqrt(2.0), kMaxwellLimitTol);
  EXPECT_NEAR(peak.amplitude, 2.0 / std::sqrt(3.0), kMaxwellLimitTol);
}

TEST(RollCrusherTwoMassOracle, HeavilyDampedDriveHasNoResonantPeak) {
  // I1 = 1, I = 1e4, C = 1e4, gamma = 3162: Maxwell limit with
  // zeta = 1e4/(2*3162) = 1.58 > 1/sqrt(2), so the low-pass is monotone.
  const RollCrusherTwoMassOracle oracle({1.0, 1e4, 1e4, 3162.0});
  EXPECT_FALSE(oracle.calcAmplitudePeak().exists);
  EXPECT_FALSE(scanForPeak(oracle).exists);
}

TEST(RollCrusherTwoMassOracle,
     PrintedDeterminantVanishesWhereAmplitudeIsUnremarkable) {
  // I1 = 1, I = 10, C = 1000, gamma = 5: T = 2.2 s, m = 1/11, beta0 = 33.2.
  // At low P, u ~ -P beta0^2 and v ~ beta0^2/T, so the printed
  // Delta = u^2 - v^2 vanishes near P = 1/T = 0.4545 rad/s: the corner of the
  // motor-slip low-pass, where the true D ~ sqrt((1 + m^2)/2) = 0.710, below
  // the static value 1. Nothing resonates there.
  const RollCrusherTwoMassParams p{1.0, 10.0, 1000.0, 5.0};
  const RollCrusherTwoMassOracle oracle(p);
  const std::vector<double> printed = oracle.calcPrintedResonanceFrequencies();
  ASSERT_FALSE(printed.empty());
  const double Pf = printed.front();
  // First-order estimates above neglect O(1/(T beta0)) = 0.014 terms.
  constexpr double kFirstOrderTol = 0.02;
  EXPECT_NEAR(Pf / (1.0 / 2.2), 1.0, kFirstOrderTol);

  const double beta0Sq = 1100.0;
  const double u = Pf * Pf * Pf - Pf * beta0Sq;
  const double v = beta0Sq / 2.2 - Pf * Pf * 11.0 / 2.2;
  EXPECT_NEAR((u * u - v * v) / (u * u + v * v), 0.0, 1e-9);

  const Complex measured = measureTwoMassShaftTorque(p, Pf, 1.0);
  const double D = oracle.calcHarmonicResponse(Pf).amplitude;
  EXPECT_NEAR(D / std::abs(measured), 1.0, kRk4AmplitudeTol);
  EXPECT_NEAR(D, std::sqrt((1.0 + 1.0 / 121.0) / 2.0), kFirstOrderTol);
  EXPECT_LT(D, 1.0);
  // The printed D_k (34) blows up there.
  EXPECT_GT(std::abs(oracle.calcPrintedAmplitude(Pf * (1.0 + 1e-10))), 1e6);

  // And at the true resonant peak (u ~ 0) the printed Delta is far from 0:
  // the paper's criterion misses the one frequency it is meant to flag.
  const RollCrusherAmplitudePeak peak = oracle.calcAmplitudePeak();
  ASSERT_TRUE(peak.exists);
  const double printedAtPeak = oracle.calcPrintedDeterminant(peak.frequency);
  EXPECT_LT(printedAtPeak, 0.0);
  EXPECT_GT(std::abs(printedAtPeak / oracle.calcDeterminant(peak.frequency)),
            0.5);
}

TEST(RollCrusherTwoMassOracle, PrintedArcsinPhaseLosesQuadrantAboveResonance) {
  // Well above beta0 the shaft torque lags the load by more than pi/2; (34)'s
  // arcsin cannot return such an angle, and it also drops the sign of Delta.
  const RollCrusherTwoMassOracle oracle(kModerate);
  const double P = 2.5 * oracle.getUndampedFrequency();
  const Complex measured = measureTwoMassShaftTorque(kModerate, P, 1.0);
  EXPECT_GT(std::abs(std::arg(measured)), kPi / 2.0);
  EXPECT_NEAR(
      std::remainder(oracle.calcHarmonicResponse(P).phase - std::arg(measured),
                     2.0 * kPi),
      0.0, kRk4PhaseTol);
  const double printed = oracle.calcPrintedPhase(P);
  EXPECT_LE(std::abs(printed), kPi / 2.0);
  EXPECT_GT(std::abs(std::remainder(printed - std::arg(measured), 2.0 * kPi)),
            0.1);
}

TEST(RollCrusherTwoMassOracle, BadParametersThrowNamingTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, -1.0, nan, inf}) {
    SCOPED_TRACE(::testing::Message() << "value=" << bad);
    RollCrusherTwoMassParams p = kModerate;
    p.motorInertia = bad;
    expectInvalidArgumentNaming([&] { RollCrusherTwoMassOracle o(p); },
                                "motorInertia");
    p = kModerate;
    p.rotorInertia = bad;
    expectInvalidArgumentNaming([&] { RollCrusherTwoMassOracle o(p); },
                                "rotorInertia");
    p = kModerate;
    p.shaftStiffness = bad;
    expectInvalidArgumentNaming([&] { RollCrusherTwoMassOracle o(p); },
                                "shaftStiffness");
    p = kModerate;
    p.slipStiffness = bad;
    expectInvalidArgumentNaming([&] { RollCrusherTwoMassOracle o(p); },
                                "slipStiffness");
  }
  expectInvalidArgumentNaming(
      [] { RollCrusherTwoMassOracle::calcSlipStiffness(100.0, 100.0, 104.0); },
      "ratedSpeed");
  expectInvalidArgumentNaming(
      [] { RollCrusherTwoMassOracle::calcSlipStiffness(-1.0, 104.0, 100.0); },
      "ratedTorque");
  expectInvalidArgumentNaming(
      [] { RollCrusherTwoMassOracle::calcLoadHarmonicFrequency(0, 1.0); }, "k");
  expectInvalidArgumentNaming(
      [] { RollCrusherTwoMassOracle::calcLoadHarmonicFrequency(1, -1.0); },
      "halfPeriod");
  const RollCrusherTwoMassOracle oracle(kModerate);
  expectInvalidArgumentNaming([&] { oracle.calcHarmonicResponse(-1.0); }, "P");
  expectInvalidArgumentNaming([&] { oracle.calcHarmonicResponse(nan); }, "P");
  // The message carries the value too.
  try {
    RollCrusherTwoMassParams p = kModerate;
    p.shaftStiffness = -2.5;
    RollCrusherTwoMassOracle o(p);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("-2.5"), std::string::npos);
  }
}

// ---------------------------------------------------------------------------
// Chain
// ---------------------------------------------------------------------------

TestChain makeUniformChain(int n, double inertia, double stiffness,
                           double gamma) {
  return {Eigen::VectorXd::Constant(n, inertia),
          Eigen::VectorXd::Constant(n - 1, stiffness), gamma};
}

TEST(RollCrusherChainOracle, TwoMassChainFrequencyIsBeta0) {
  // n = 2, I1 = 1, I = 3, C = 12, gamma = 0: omega = {0, beta0 = 4}.
  const RollCrusherChainOracle chain({{1.0, 3.0}, {12.0}, 0.0});
  const RollCrusherChainModes modes = chain.calcUndampedModes();
  ASSERT_EQ(modes.frequencies.size(), 2);
  EXPECT_NEAR(modes.frequencies[0], 0.0, 1e-6);  // sqrt of a rounding error
  EXPECT_NEAR(modes.frequencies[1], 4.0, kRoundoffTol);
  // beta0 does not depend on gamma, so any gamma > 0 serves for the oracle.
  EXPECT_NEAR(
      modes.frequencies[1],
      RollCrusherTwoMassOracle({1.0, 3.0, 12.0, 1.0}).getUndampedFrequency(),
      kRoundoffTol);
}

TEST(RollCrusherChainOracle, TwoMassChainDampedEigenvaluesAreTheCubicRoots) {
  const RollCrusherChainOracle chain({{1.0, 2.0}, {100.0}, 5.0});
  const std::vector<Complex> eigenvalues = chain.calcDampedEigenvalues();
  const std::array<Complex, 3> roots =
      RollCrusherTwoMassOracle(kModerate).calcCharacteristicRoots();
  ASSERT_EQ(eigenvalues.size(), 3u);
  for (const Complex& k : roots) {
    const std::size_t match = nearestIndex(eigenvalues, k);
    EXPECT_LE(std::abs(eigenvalues[match] - k), kRootMatchTol * std::abs(k));
  }
  EXPECT_TRUE(chain.calcStateMatrix().isApprox(
      Eigen::MatrixXd(buildTwoMassStateMatrix(kModerate)), kRoundoffTol));
}

TEST(RollCrusherChainOracle, TwoMassChainForcedResponseIsTheTwoMassOracles) {
  const RollCrusherChainOracle chain({{1.0, 2.0}, {100.0}, 5.0});
  const RollCrusherTwoMassOracle oracle(kModerate);
  constexpr double kLoadAmplitude = 7.0;
  for (double P : {2.0, 11.0, 30.0}) {
    const Complex M12 =
        chain
            .calcHarmonicResponse(
                P, RollCrusherChainOracle::makeRowLoads(2, kLoadAmplitude, 0.0))
            .shaftTorques[0];
    const RollCrusherHarmonicResponse r = oracle.calcHarmonicResponse(P);
    EXPECT_NEAR(
        std::abs(M12 - kLoadAmplitude * std::polar(r.amplitude, r.phase)), 0.0,
        kRoundoffTol * kLoadAmplitude * 10.0)
        << "P=" << P;
  }
}

TEST(RollCrusherChainOracle, UniformChainMatchesFreeFreeClosedForm) {
  // Motor free (gamma = 0) and last row free: a free-free chain. For n equal
  // masses I and springs C, interior rows give
  //   -w^2 I v_i = C (v_{i-1} - 2 v_i + v_{i+1});
  // v_i = cos(theta (i - 1/2)) solves it with w^2 = (2C/I)(1 - cos theta)
  // = (4C/I) sin^2(theta/2). The free ends act as mirrors v_0 = v_1 (holds
  // for any theta) and v_{n+1} = v_n, i.e. sin(n theta) sin(theta/2) = 0, so
  // theta = j pi/n:  w_j = 2 sqrt(C/I) sin(j pi/(2n)), j = 0..n-1.
  constexpr int n = 10;
  constexpr double I = 2.0;
  constexpr double C = 50.0;
  const RollCrusherChainOracle chain(makeUniformChain(n, I, C, 0.0).params());
  const Eigen::VectorXd w = chain.calcUndampedModes().frequencies;
  ASSERT_EQ(w.size(), n);
  EXPECT_NEAR(w[0], 0.0, 1e-6);
  for (int j = 1; j < n; ++j)
    EXPECT_NEAR(w[j], 2.0 * std::sqrt(C / I) * std::sin(j * kPi / (2.0 * n)),
                kRoundoffTol * 100.0)
        << "j=" << j;
}

TEST(RollCrusherChainOracle, HeavyMotorChainApproachesFixedFreeClosedForm) {
  // A motor 1e8 times heavier than a row is a fixed base for the N rows
  // behind it. With v_0 = 0 and v_i = sin(theta i), the free end
  // v_{N+1} = v_N gives cos(theta (N + 1/2)) sin(theta/2) = 0, so
  // theta = (2j - 1) pi/(2N + 1):
  //   w_j = 2 sqrt(C/I) sin((2j - 1) pi/(2 (2N + 1))), j = 1..N.
  constexpr int N = 9;
  constexpr double I = 3.0;
  constexpr double C = 40.0;
  TestChain spec = makeUniformChain(N + 1, I, C, 0.0);
  spec.inertias[0] = 1e8 * I;
  const Eigen::VectorXd w =
      RollCrusherChainOracle(spec.params()).calcUndampedModes().frequencies;
  // The base still moves by O(I/I_motor) = 1e-8.
  constexpr double kHeavyBaseTol = 1e-6;
  for (int j = 1; j <= N; ++j) {
    const double expected = 2.0 * std::sqrt(C / I) *
                            std::sin((2 * j - 1) * kPi / (2.0 * (2 * N + 1)));
    EXPECT_NEAR(w[j] / expected, 1.0, kHeavyBaseTol) << "j=" << j;
  }
}

TEST(RollCrusherChainOracle, ModeShapesAreMassOrthonormalEigenvectors) {
  const TestChain spec{
      (Eigen::VectorXd(5) << 1.5, 4.0, 2.0, 3.0, 1.0).finished(),
      (Eigen::VectorXd(4) << 80.0, 30.0, 55.0, 20.0).finished(), 0.0};
  const RollCrusherChainOracle chain(spec.params());
  const RollCrusherChainModes modes = chain.calcUndampedModes();
  const Eigen::MatrixXd M = spec.inertias.asDiagonal();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(5, 5);
  for (int i = 0; i < 5; ++i)
    K.col(i) = -spec.shaftTorquesOnMasses(Eigen::VectorXd::Unit(5, i));
  const Eigen::MatrixXd& V = modes.shapes;
  EXPECT_TRUE((V.transpose() * M * V)
                  .isApprox(Eigen::MatrixXd::Identity(5, 5), kRoundoffTol));
  const Eigen::MatrixXd residual =
      K * V - M * V * modes.frequencies.array().square().matrix().asDiagonal();
  EXPECT_LE(residual.norm(), kRoundoffTol * K.norm() * 10.0);
  EXPECT_TRUE(chain.calcStiffnessMatrix().isApprox(K, kRoundoffTol));
  for (int j = 0; j < 5; ++j) EXPECT_GT(V(0, j), 0.0);
}

TEST(RollCrusherChainOracle,
     DampedEigenvaluesTendToUndampedModesAsGammaVanishes) {
  TestChain spec{(Eigen::VectorXd(5) << 1.5, 4.0, 2.0, 3.0, 1.0).finished(),
                 (Eigen::VectorXd(4) << 80.0, 30.0, 55.0, 20.0).finished(),
                 0.0};
  const Eigen::VectorXd w =
      RollCrusherChainOracle(spec.params()).calcUndampedModes().frequencies;
  // gamma = 0: eigenvalues 0 (rigid speed) and +/- i w_j.
  {
    const std::vector<Complex> lambda =
        RollCrusherChainOracle(spec.params()).calcDampedEigenvalues();
    ASSERT_EQ(lambda.size(), 9u);
    std::vector<double> positiveImag;
    for (const Complex& z : lambda) {
      EXPECT_NEAR(z.real(), 0.0, 1e-9);
      if (z.imag() > 1e-6) positiveImag.push_back(z.imag());
    }
    ASSERT_EQ(positiveImag.size(), 4u);
    std::sort(positiveImag.begin(), positiveImag.end());
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(positiveImag[j] / w[j + 1], 1.0, 1e-10);
  }
  // gamma > 0: every mode moves the motor (a tridiagonal chain has no mode
  // with a node at its end), so every eigenvalue is damped; the one that was
  // 0 becomes ~ -gamma/I0 for small gamma.
  spec.gamma = 1e-3;
  const std::vector<Complex> lambda =
      RollCrusherChainOracle(spec.params()).calcDampedEigenvalues();
  for (const Complex& z : lambda) EXPECT_LT(z.real(), 0.0) << z;
  // The rigid-body eigenvalue is the one nearest 0 (elastic ones ~ +/- i w_j).
  const Complex rigid = *std::min_element(
      lambda.begin(), lambda.end(), [](const Complex& a, const Complex& b) {
        return std::abs(a) < std::abs(b);
      });
  EXPECT_NEAR(rigid.real() / (-1e-3 / spec.inertias.sum()), 1.0, 1e-3);
  EXPECT_EQ(rigid.imag(), 0.0);
}

TEST(RollCrusherChainOracle, ForcedResponseMatchesRk4SteadyState) {
  const TestChain spec{(Eigen::VectorXd(4) << 1.0, 2.0, 1.5, 1.0).finished(),
                       (Eigen::VectorXd(3) << 60.0, 40.0, 50.0).finished(),
                       4.0};
  const RollCrusherChainOracle chain(spec.params());
  const Eigen::VectorXcd loads =
      RollCrusherChainOracle::makeRowLoads(4, 2.0, 2.0 * kPi / 3.0);
  for (double P : {3.0, 8.0}) {
    SCOPED_TRACE(::testing::Message() << "P=" << P);
    const Eigen::VectorXcd expected =
        chain.calcHarmonicResponse(P, loads).shaftTorques;
    const Eigen::VectorXcd measured = measureChainShaftTorques(spec, P, loads);
    const double scale = measured.cwiseAbs().maxCoeff();
    for (int j = 0; j < 3; ++j)
      EXPECT_LE(std::abs(expected[j] - measured[j]), kRk4AmplitudeTol * scale)
          << "shaft " << j << ": " << expected[j] << " vs " << measured[j];
  }
}

TEST(RollCrusherChainOracle, StaggeredRowsCancelOnRigidRotorButLoadTheShafts) {
  // Motor + nine rows staggered evenly, (13): M_i = b sin(P t + (i-2) 2pi/9).
  constexpr int kRows = 9;
  constexpr double b = 1.0;
  const TestChain spec = makeUniformChain(kRows + 1, 1.0, 1e4, 100.0);
  const RollCrusherChainOracle chain(spec.params());
  const Eigen::VectorXcd staggered =
      RollCrusherChainOracle::makeRowLoads(kRows + 1, b, 2.0 * kPi / kRows);
  const Eigen::VectorXcd inPhase =
      RollCrusherChainOracle::makeRowLoads(kRows + 1, b, 0.0);

  // A rigid rotor (or the two-mass model) only feels the sum: nine unit
  // phasors evenly round the circle sum to 0.
  EXPECT_NEAR(std::abs(staggered.sum()), 0.0, 1e-14 * kRows);
  EXPECT_NEAR(std::abs(inPhase.sum()), kRows * b, kRoundoffTol);

  // Quasi-static limit (P << 1/T = 10 and P << w1 = 200 sin(pi/20) = 31.3):
  // shaft j carries the loads of the rows beyond it, |sum of m consecutive
  // phasors| = b |sin(m pi/9)/sin(pi/9)|, m = 9 - j. Deviations are O(P T).
  constexpr double kQuasiStaticP = 1e-4;
  constexpr double kQuasiStaticTol = 1e-4;
  const Eigen::VectorXcd stagTorques =
      chain.calcHarmonicResponse(kQuasiStaticP, staggered).shaftTorques;
  const Eigen::VectorXcd phaseTorques =
      chain.calcHarmonicResponse(kQuasiStaticP, inPhase).shaftTorques;
  for (int j = 0; j < kRows; ++j) {
    const int m = kRows - j;
    EXPECT_NEAR(std::abs(stagTorques[j]),
                b * std::abs(std::sin(m * kPi / kRows) / std::sin(kPi / kRows)),
                kQuasiStaticTol)
        << "shaft " << j;
    EXPECT_NEAR(std::abs(phaseTorques[j]), m * b, kQuasiStaticTol * m)
        << "shaft " << j;
  }

  // Dynamically too: at half the first elastic frequency the internal shafts
  // carry several b while the lumped model sees no load at all.
  const double w1 = chain.calcUndampedModes().frequencies[1];
  const Eigen::VectorXcd dynamic =
      chain.calcHarmonicResponse(0.5 * w1, staggered).shaftTorques;
  EXPECT_GT(dynamic.cwiseAbs().maxCoeff(), 2.0 * b);
}

TEST(RollCrusherChainOracle, ReductionsToTwoMassMatchClosedForms) {
  // n = 2: both reductions return the chain itself.
  {
    const RollCrusherChainOracle chain({{1.0, 3.0}, {12.0}, 2.0});
    for (auto reduction : {RollCrusherChainReduction::SeriesCompliance,
                           RollCrusherChainReduction::FirstFrequency}) {
      const RollCrusherTwoMassParams p = chain.reduceToTwoMass(reduction);
      EXPECT_EQ(p.motorInertia, 1.0);
      EXPECT_EQ(p.rotorInertia, 3.0);
      EXPECT_NEAR(p.shaftStiffness, 12.0, 12.0 * kRoundoffTol);
      EXPECT_EQ(p.slipStiffness, 2.0);
    }
  }
  // Uniform free-free chain, n = 10: series C/9; first-frequency keeps
  // w1 = 2 sqrt(C/I) sin(pi/20), so the reduced beta0 equals it.
  constexpr int n = 10;
  constexpr double I = 2.0;
  constexpr double C = 50.0;
  const RollCrusherChainOracle chain(makeUniformChain(n, I, C, 3.0).params());
  const RollCrusherTwoMassParams series =
      chain.reduceToTwoMass(RollCrusherChainReduction::SeriesCompliance);
  EXPECT_NEAR(series.shaftStiffness, C / 9.0, kRoundoffTol);
  EXPECT_NEAR(series.rotorInertia, 9.0 * I, kRoundoffTol);
  const RollCrusherTwoMassParams first =
      chain.reduceToTwoMass(RollCrusherChainReduction::FirstFrequency);
  EXPECT_NEAR(RollCrusherTwoMassOracle(first).getUndampedFrequency(),
              2.0 * std::sqrt(C / I) * std::sin(kPi / 20.0),
              100.0 * kRoundoffTol);
  EXPECT_EQ(first.slipStiffness, 3.0);
}

TEST(RollCrusherChainOracle, BadParametersThrowNamingTheParameter) {
  expectInvalidArgumentNaming(
      [] {
        RollCrusherChainOracle c({{1.0}, {}, 0.0});
      },
      "inertias.size()");
  expectInvalidArgumentNaming(
      [] {
        RollCrusherChainOracle c({{1.0, 2.0, 3.0}, {5.0}, 0.0});
      },
      "stiffnesses.size()");
  expectInvalidArgumentNaming(
      [] {
        RollCrusherChainOracle c({{1.0, 2.0, 3.0, -4.0}, {5.0, 5.0, 5.0}, 0.0});
      },
      "inertias[3]");
  expectInvalidArgumentNaming(
      [] {
        RollCrusherChainOracle c({{1.0, 2.0}, {0.0}, 0.0});
      },
      "stiffnesses[0]");
  expectInvalidArgumentNaming(
      [] {
        RollCrusherChainOracle c({{1.0, 2.0}, {5.0}, -1.0});
      },
      "slipStiffness");
  const RollCrusherChainOracle chain({{1.0, 3.0}, {12.0}, 0.0});
  expectInvalidArgumentNaming(
      [&] { chain.calcHarmonicResponse(1.0, Eigen::VectorXcd::Zero(3)); },
      "loads.size()");
  expectInvalidArgumentNaming(
      [&] { chain.calcHarmonicResponse(0.0, Eigen::VectorXcd::Zero(2)); }, "P");
  expectInvalidArgumentNaming(
      [] { RollCrusherChainOracle::makeRowLoads(1, 1.0, 0.0); }, "numMasses");
  expectInvalidArgumentNaming(
      [] { RollCrusherChainOracle::makeRowLoads(3, -1.0, 0.0); }, "amplitude");
  // gamma = 0 and P = beta0 = 4 exactly: K - 16 M = [[-4, -12], [-12, -36]]
  // is singular in floating point too.
  EXPECT_THROW(chain.calcHarmonicResponse(
                   4.0, RollCrusherChainOracle::makeRowLoads(2, 1.0, 0.0)),
               std::domain_error);
}

// ---------------------------------------------------------------------------
// Reducer
// ---------------------------------------------------------------------------

TEST(RollCrusherReducer, ReflectionDividesByRatioSquaredAndKeepsFrequencies) {
  // A 600 kg*m^2 rotor behind u = 140 weighs 600/19600 on the motor shaft.
  EXPECT_NEAR(RollCrusherReducer::reflectInertia(600.0, 140.0), 600.0 / 19600.0,
              kRoundoffTol);
  EXPECT_NEAR(RollCrusherReducer::reflectStiffness(1e7, 140.0), 1e7 / 19600.0,
              1e7 / 19600.0 * kRoundoffTol);
  EXPECT_NEAR(RollCrusherReducer::reflectTorque(1400.0, 140.0), 10.0,
              kRoundoffTol);
  // Written on the low-speed shaft, the motor Jm weighs Jm u^2 there and
  //   beta^2 = C_low (Jm u^2 + J_low)/(Jm u^2 J_low).
  // Reflecting rotor and shaft to the motor must give the same frequency.
  constexpr double Jm = 2.0;
  constexpr double Jlow = 600.0;
  constexpr double Clow = 1e7;
  constexpr double u = 140.0;
  const double expected =
      std::sqrt(Clow * (Jm * u * u + Jlow) / (Jm * u * u * Jlow));
  const RollCrusherTwoMassOracle reflected(
      {Jm, RollCrusherReducer::reflectInertia(Jlow, u),
       RollCrusherReducer::reflectStiffness(Clow, u), 1.0});
  EXPECT_NEAR(reflected.getUndampedFrequency() / expected, 1.0, kRoundoffTol);
  expectInvalidArgumentNaming(
      [] { RollCrusherReducer::reflectInertia(1.0, 0.0); }, "ratio");
  expectInvalidArgumentNaming(
      [] { RollCrusherReducer::reflectInertia(-1.0, 2.0); }, "lowSpeedInertia");
  expectInvalidArgumentNaming(
      [] { RollCrusherReducer::reflectStiffness(0.0, 2.0); },
      "lowSpeedStiffness");
}

}  // namespace
}  // namespace milldyn::oracles
