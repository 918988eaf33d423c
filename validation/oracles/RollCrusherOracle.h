// Closed-form oracle for the torsional models of the single-roll toothed
// crusher for hot sinter (seed 004: Levchenko, Zinchenko, Pavlenko et al.,
// "Modelling the dynamics of a single-roll toothed crusher", 2025).
// Everything is reduced to the motor shaft and in SI units. The derivation and
// every misprint found in the paper are in docs/oracles/roll_crusher.md.
//
// This file knows nothing of Simbody nor of ModelSpec on purpose: it takes its
// own parameter structs, so it cannot share a bug with the model it judges.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <vector>

namespace milldyn::oracles {

/// Two-mass model of the crusher (paper Fig. 3), reduced to the motor shaft.
struct RollCrusherTwoMassParams {
  /// I1: motor rotor (plus coupling, brake, fast gears) [kg*m^2], finite > 0.
  double motorInertia = 0;
  /// I: crusher rotor and slow gears reflected to the motor shaft
  /// (RollCrusherReducer::reflectInertia) [kg*m^2], finite > 0.
  double rotorInertia = 0;
  /// C: torsional stiffness of reducer and shafts reflected to the motor
  /// shaft [N*m/rad], finite > 0.
  double shaftStiffness = 0;
  /// gamma = Mn/(w0 - wn), slope of the motor's linear torque-speed branch
  /// (eqs 1, 15) [N*m*s/rad], finite > 0. Zero is rejected: with no slip
  /// stiffness the rigid-body mode is undamped, T = I0/gamma is infinite and a
  /// constant load torque has no steady state.
  double slipStiffness = 0;
};

/// Roots of the characteristic cubic (24) split the way the paper writes its
/// free solution (26): one real root k1 and a pair alpha +/- i beta.
struct RollCrusherRootSplit {
  double realRoot = 0;  ///< k1 [1/s]
  double alpha = 0;     ///< real part of the pair [1/s]
  double beta = 0;      ///< |imaginary part| of the pair [rad/s], >= 0
};

/// The paper's approximations of the roots (after eq 25).
struct RollCrusherApproximateRoots {
  double realRoot = 0;  ///< k1 ~ -gamma/I0 [1/s]
  double alpha = 0;     ///< alpha ~ -gamma I/(2 I1 I0) [1/s]
  /// beta^2 ~ beta0^2 - (gamma/I1)^2 I/I0 + 3/4 (gamma I/(I1 I0))^2
  /// [rad^2/s^2]; may come out negative, where the paper's form has no
  /// oscillating pair at all.
  double betaSquared = 0;
};

/// |approximate - exact|/|exact| for each part of RollCrusherRootSplit.
struct RollCrusherApproximationErrors {
  double realRoot = 0;
  double alpha = 0;
  /// With beta_approx = sqrt(max(betaSquared, 0)). When the exact pair is
  /// real (beta = 0) this is 0 if beta_approx is 0 too, else +infinity.
  double beta = 0;
};

/// Steady-state response of the shaft torque M0 to a load M = b sin(P t):
/// M0 = b (B cos(P t) + Ck sin(P t)) = b D sin(P t + psi)   (29), (33).
struct RollCrusherHarmonicResponse {
  double cosCoefficient = 0;  ///< B_k/b_k [-]
  double sinCoefficient = 0;  ///< C_k/b_k [-]
  double amplitude = 0;       ///< D_k = sqrt(B^2 + Ck^2) [-] (M0 per unit b)
  double phase = 0;           ///< psi_k = atan2(B, Ck) [rad], in (-pi, pi]
};

/// The paper's Cramer numerators of system (31) per unit b_k; they are
/// printed correctly in (32), unlike the determinant.
struct RollCrusherCramerNumerators {
  double deltaB = 0;  ///< Delta_B [1/s^6]
  double deltaC = 0;  ///< Delta_C [1/s^6]
};

/// The resonant peak of the true amplitude D(P): its highest local maximum
/// at P > 0. It can lie below the static value D(0) = 1 (heavy rotor, where
/// D falls to about m = I1/I0 above P ~ 1/T before the resonance lifts it),
/// and a heavily damped drive may have none.
struct RollCrusherAmplitudePeak {
  bool exists = false;   ///< false when D has no local maximum at P > 0
  double frequency = 0;  ///< P at the peak [rad/s]
  double amplitude = 0;  ///< D at the peak [-]
};

/**
 * Two-mass torsional model of the crusher: motor I1 with a linear
 * slip-torque characteristic, elastic reducer C, rotor I under a load torque
 * M(t) (paper eqs (14)-(37), corrected).
 *
 * <pre>
 *   I1 phi1'' = M1 - M0,   I phi2'' = M0 - M                       (14), (18)
 *   M0 = C (phi1 - phi2)                                            (16)
 *   M1 = gamma (w0 - phi1'),  gamma = Mn/(w0 - wn)                  (15)
 *
 *   I0 = I1 + I,  T = I0/gamma,  m = I1/I0,  beta0^2 = C I0/(I1 I)
 *
 *   M0''' + M0''/(m T) + beta0^2 M0' + beta0^2 M0/T
 *                           = (C/I) M' + beta0^2 M/T       (20), corrected
 *   F(k) = k^3 + k^2/(m T) + beta0^2 k + beta0^2/T = 0             (24), (25)
 *
 *   M = b sin(P t):  u = P^3 - P beta0^2,  v = beta0^2/T - P^2/(m T)
 *   [ u   v ] [B ]   [ b beta0^2/T ]
 *   [ v  -u ] [Ck] = [ b (C/I) P   ]        (31),  det = -(u^2 + v^2)
 *   D = sqrt((beta0^2/T)^2 + (C P/I)^2) / sqrt(u^2 + v^2),
 *   psi = atan2(B, Ck)                                              (34)
 * </pre>
 *
 * The transfer function M0/M is H(s) = (C s/I + beta0^2/T)/F(s); H(0) = 1,
 * so a constant load b gives M0 = b in steady running and D(P) is itself the
 * dynamic factor D(P)/D(0). Routh-Hurwitz (coefficients positive and
 * (1/(mT)) beta0^2 > beta0^2/T because m < 1) makes every root stable, and
 * u^2 + v^2 > 0 for every P (u = 0 only at P = beta0, v = 0 only at
 * P = sqrt(m) beta0), so with gamma > 0 the amplitude is finite everywhere:
 * the paper's "resonance" Delta = 0 (37) comes from the misprinted sign of
 * its determinant, Delta = u^2 - v^2 (calcPrintedDeterminant).
 *
 * The paper's approximations of the roots are a regular expansion in gamma.
 * Carried one order further (docs/oracles/roll_crusher.md), their relative
 * errors are
 * <pre>
 *   k1:    gamma^2 I^2/(C I0^3)            = validity * I/I1
 *   alpha: gamma^2 I1 I/(C I0^3)           = validity (the paper's parameter)
 *   beta^2: gamma^4 I^3 (I - 2 I1)/(2 C^2 I0^6)
 * </pre>
 * so the paper's condition gamma^2 I1 I/(C I0^3) << 1 is not sufficient in
 * the regime it invokes, I >> I1: the real root then needs
 * gamma^2 I^2/(C I0^3) << 1 as well (calcRealRootCorrectionParameter).
 *
 * Assumptions: small motions about a steady run on the linear branch of the
 * motor curve (w0 enters only the mean speed, not M0); lossless, backlash-free
 * reducer with everything reflected to the motor shaft; no damping other than
 * the motor's slip. Units: SI, angles in rad, time in s.
 */
class RollCrusherTwoMassOracle {
 public:
  /// Throws std::invalid_argument naming the parameter that is out of range.
  explicit RollCrusherTwoMassOracle(const RollCrusherTwoMassParams& params);

  /// gamma = Mn/(w0 - wn) [N*m*s/rad] from the nameplate (eqs 1, 15):
  /// `ratedTorque` Mn [N*m] > 0, `synchronousSpeed` w0 [rad/s] and
  /// `ratedSpeed` wn [rad/s] with 0 < wn < w0.
  static double calcSlipStiffness(double ratedTorque, double synchronousSpeed,
                                  double ratedSpeed);

  /// Eq (27): P_k = k pi/l [rad per unit of time of l], harmonic number
  /// `k` >= 1, half-period `halfPeriod` l > 0. The paper's l = pi/240 gives
  /// P_k = 240 k; the paper never states the time unit (see
  /// kPaperLoadHalfPeriod).
  static double calcLoadHarmonicFrequency(int k, double halfPeriod);

  /// l = pi/240 from (27). [A] If t is in seconds this is P_1 = 240 rad/s
  /// (38.2 Hz), far above anything a 4.7 rpm rotor excites; if t is in
  /// minutes P_1 = 4 rad/s, about 8.2 load cycles per rotor revolution.
  static constexpr double kPaperLoadHalfPeriod = 3.14159265358979323846 / 240.0;

  const RollCrusherTwoMassParams& getParams() const { return m_params; }
  double getTotalInertia() const { return m_I0; }          ///< I0 [kg*m^2]
  double getTimeConstant() const { return m_T; }           ///< T [s]
  double getInertiaFraction() const { return m_m; }        ///< m [-]
  double getUndampedFrequency() const { return m_beta0; }  ///< beta0 [rad/s]

  /// State matrix A of x' = A x + (inputs) for x = (phi1', phi2', M0) in
  /// (rad/s, rad/s, N*m); its characteristic polynomial is F(k) of (24).
  Eigen::Matrix3d calcStateMatrix() const;

  /// F(k) of (24) at a complex k [1/s^3].
  std::complex<double> evalCharacteristicPolynomial(
      std::complex<double> k) const;

  /// The three roots of (24) [1/s], sorted by real part, then imaginary part.
  /// The real root is bracketed in [-gamma/I1, -gamma/I0] where F changes sign
  /// (F(-gamma/I1) = -C gamma/I1^2, F(-gamma/I0) = gamma^3 I/(I1 I0^3)),
  /// found by bisection, deflated, and every root polished by Newton's method.
  std::array<std::complex<double>, 3> calcCharacteristicRoots() const;

  /// Exact roots in the paper's (26) form. With a complex pair, k1 is the
  /// real root. When all three are real, k1 is the one nearest -gamma/I0 (the
  /// root the paper approximates), alpha the mean of the other two, beta = 0.
  RollCrusherRootSplit calcExactRootSplit() const;

  /// The paper's approximate roots (after (25)).
  RollCrusherApproximateRoots calcPaperApproximateRoots() const;

  /// Relative errors of calcPaperApproximateRoots against calcExactRootSplit.
  RollCrusherApproximationErrors calcApproximationErrors() const;

  /// The paper's validity parameter gamma^2/(I0^2 beta0^2)
  /// = gamma^2 I1 I/(C I0^3) [-]; to first order the relative error of alpha.
  double calcPaperValidityParameter() const;

  /// gamma^2 I^2/(C I0^3) [-]: to first order the relative error of the
  /// paper's k1 ~ -gamma/I0; equals the validity parameter times I/I1.
  double calcRealRootCorrectionParameter() const;

  /// H(s) = M0/M = (C s/I + beta0^2/T)/F(s) at a complex `s` [1/s] [-].
  std::complex<double> calcTransferFunction(std::complex<double> s) const;

  /// Steady response of M0 to M = b sin(P t) per unit b, for `P` [rad/s],
  /// finite >= 0.
  RollCrusherHarmonicResponse calcHarmonicResponse(double P) const;

  /// The determinant of (31), -(u^2 + v^2) [1/s^6]; never zero.
  double calcDeterminant(double P) const;

  /// Delta_B, Delta_C of (32) at `P` [rad/s] (finite >= 0).
  RollCrusherCramerNumerators calcCramerNumerators(double P) const;

  /// lim_{P->0} D(P) [-]: the steady M0 per unit of a constant load torque.
  /// Equal to 1 for every gamma > 0 (the motor slip carries the mean load).
  double calcStaticGain() const;

  /// Dynamic factor eta(P) = D(P)/calcStaticGain() [-], `P` [rad/s] >= 0:
  /// how many times the shaft torque amplitude exceeds what the same load
  /// amplitude would give if applied slowly. The paper's eta = |D_k| (after
  /// (37)) with its D_k corrected.
  double calcDynamicFactor(double P) const;

  /// The resonant peak of D. Stationary points of D^2 = N(x)/Den(x),
  /// x = P^2, are the roots of the cubic G = N' Den - N Den'
  /// (docs/oracles/roll_crusher.md); maxima are those where G' < 0, since
  /// G has the sign of dD^2/dx.
  RollCrusherAmplitudePeak calcAmplitudePeak() const;

  /// MISPRINT, kept to show it: the paper's printed determinant of (31),
  /// Delta = u^2 - v^2 (32), (37) [1/s^6]. The true one is calcDeterminant.
  double calcPrintedDeterminant(double P) const;

  /// MISPRINT, kept to show it: the positive P [rad/s] where the printed
  /// Delta = u^2 - v^2 vanishes, i.e. the paper's "resonance" condition (37),
  /// ascending. Nothing physical happens there.
  std::vector<double> calcPrintedResonanceFrequencies() const;

  /// MISPRINT, kept to show it: the paper's (34) as printed,
  /// D_k = sqrt(Delta_B^2 + Delta_C^2)/Delta with Delta = u^2 - v^2 [-];
  /// signed, and infinite at calcPrintedResonanceFrequencies.
  double calcPrintedAmplitude(double P) const;

  /// MISPRINT, kept to show it: the paper's (34) phase
  /// psi_k = arcsin(Delta_B/sqrt(Delta_B^2 + Delta_C^2)) [rad], confined to
  /// [-pi/2, pi/2] and with the sign of Delta dropped.
  double calcPrintedPhase(double P) const;

 private:
  double calcU(double P) const;
  double calcV(double P) const;

  RollCrusherTwoMassParams m_params;
  double m_I0;
  double m_T;
  double m_m;
  double m_beta0Squared;
  double m_beta0;
};

/// N-mass chain of the crusher (paper Fig. 2): the motor, then the rotor
/// cut at each sprocket row, all reflected to the motor shaft.
struct RollCrusherChainParams {
  /// I_1..I_n, motor first [kg*m^2], each finite > 0, n >= 2 (the paper has
  /// n = 10: motor plus nine sprocket rows).
  std::vector<double> inertias;
  /// C_{1,2}..C_{n-1,n}: stiffness between mass i and i+1 [N*m/rad], each
  /// finite > 0, exactly n - 1 of them.
  std::vector<double> stiffnesses;
  /// gamma of the motor on mass 1 only [N*m*s/rad], finite >= 0 (0 gives the
  /// undamped chain).
  double slipStiffness = 0;
};

/// Undamped modes of the chain.
struct RollCrusherChainModes {
  /// omega_j [rad/s] ascending, n of them; the first is the rigid-body mode
  /// (0 up to rounding, clamped at 0).
  Eigen::VectorXd frequencies;
  /// Column j is mode j, normalised to v^T M v = 1 [1/sqrt(kg*m^2)], sign
  /// chosen so that the motor's entry is positive.
  Eigen::MatrixXd shapes;
};

/// Steady response of the chain to harmonic loads. A complex amplitude X
/// stands for the signal Im(X e^{iPt}) = |X| sin(P t + arg X), the same
/// convention as RollCrusherHarmonicResponse.
struct RollCrusherChainResponse {
  Eigen::VectorXcd angles;        ///< phi_1..phi_n [rad]
  Eigen::VectorXcd shaftTorques;  ///< M_{1,2}..M_{n-1,n} [N*m]
};

/// How RollCrusherChainOracle::reduceToTwoMass picks the two-mass C.
/// Both keep I1 = I_1 and I = I_2 + ... + I_n, so the total inertia, the
/// rigid-body root k1 and the static gain are those of the chain.
enum class RollCrusherChainReduction {
  /// 1/C = sum 1/C_{i,i+1}: the static twist when the whole load acts on the
  /// last mass. Exact statics for that load case, but the first resonance
  /// moves.
  SeriesCompliance,
  /// C = omega_1^2 I1 I/I0 with omega_1 the chain's first elastic undamped
  /// frequency, so the two-mass beta0 equals it. Preferred for dynamic
  /// factors: the resonance the paper guards against stays where it is.
  FirstFrequency,
};

/**
 * N-mass torsional chain of the crusher (paper eqs (2)-(4), (13)): the motor
 * (mass 1) with slip stiffness gamma, then masses joined by shafts.
 *
 * <pre>
 *   I_1 phi_1'' = gamma (w0 - phi_1') - M_{1,2}                     (2), (4)
 *   I_i phi_i'' = M_{i-1,i} - M_i - M_{i,i+1}     1 < i < n          (2)
 *   I_n phi_n'' = M_{n-1,n} - M_n                                    (2)
 *   M_{i,i+1} = C_{i,i+1} (phi_i - phi_{i+1})                        (3)
 *   M_i(t) = M_2(t + tau_i)   (rows staggered round the rotor)      (13)
 *
 *   M phi'' + D phi' + K phi = -L(t),  M = diag(I_i),
 *   D = diag(gamma, 0, ..., 0),  K = S^T diag(C) S,
 *   (S phi)_j = phi_j - phi_{j+1}
 * </pre>
 *
 * L_i is the load torque M_i on mass i (it resists the motion). Undamped
 * modes solve K v = omega^2 M v. The damped eigenvalues are those of the
 * first-order system in (phi', M_{i,i+1}), 2n - 1 states, which for n = 2 is
 * RollCrusherTwoMassOracle's state and cubic. For L = Im(L_hat e^{iPt}):
 * (K - P^2 M + i P D) X = -L_hat.
 *
 * The paper's torque-form equations (5)-(12) are a rewriting of the same
 * system and carry misprints (docs/oracles/roll_crusher.md); this class works
 * from (2)-(4) directly. Assumptions as for RollCrusherTwoMassOracle.
 */
class RollCrusherChainOracle {
 public:
  /// Throws std::invalid_argument naming the parameter that is out of range.
  explicit RollCrusherChainOracle(RollCrusherChainParams params);

  /// Complex amplitudes of row loads for (13): 0 on the motor (mass 1) and
  /// b e^{i (i - 2) phaseStep} on mass i = 2..n, i.e. M_i = b sin(P t +
  /// (i - 2) phaseStep). For harmonic M_2 a time shift tau_i in (13) is the
  /// phase P tau_i; evenly staggered rows have phaseStep = 2 pi/(n - 1).
  /// `numMasses` >= 2, `amplitude` b [N*m] finite >= 0, `phaseStep` [rad]
  /// finite.
  static Eigen::VectorXcd makeRowLoads(int numMasses, double amplitude,
                                       double phaseStep);

  const RollCrusherChainParams& getParams() const { return m_params; }
  int getNumMasses() const {
    return static_cast<int>(m_params.inertias.size());
  }

  Eigen::MatrixXd calcMassMatrix() const;       ///< M [kg*m^2]
  Eigen::MatrixXd calcStiffnessMatrix() const;  ///< K [N*m/rad]
  Eigen::MatrixXd calcDampingMatrix() const;    ///< D [N*m*s/rad]

  /// Undamped modes, generalized symmetric eigenproblem K v = omega^2 M v.
  RollCrusherChainModes calcUndampedModes() const;

  /// (2n-1)x(2n-1) state matrix for x = (phi_1'..phi_n', M_{1,2}..M_{n-1,n}).
  Eigen::MatrixXd calcStateMatrix() const;

  /// Eigenvalues of calcStateMatrix [1/s], sorted by real, then imaginary part.
  std::vector<std::complex<double>> calcDampedEigenvalues() const;

  /// Steady response to loads L_i = Im(loads_i e^{iPt}) on every mass
  /// (`loads` [N*m], n finite entries; see makeRowLoads), `P` [rad/s] finite
  /// > 0. Throws std::domain_error when K - P^2 M + i P D is singular
  /// (gamma = 0 and P an undamped eigenfrequency).
  RollCrusherChainResponse calcHarmonicResponse(
      double P, const Eigen::VectorXcd& loads) const;

  /// Two-mass parameters for the same motor and total inertia (see
  /// RollCrusherChainReduction); gamma is copied, so a chain with gamma = 0
  /// reduces to parameters RollCrusherTwoMassOracle rejects.
  RollCrusherTwoMassParams reduceToTwoMass(
      RollCrusherChainReduction reduction) const;

 private:
  Eigen::MatrixXd calcIncidenceMatrix() const;  // S

  RollCrusherChainParams m_params;
};

/// Reflection of low-speed-side quantities to the motor shaft through an
/// ideal (lossless, rigid, backlash-free) reducer of ratio u = w_motor/w_low.
/// Kinetic energy (1/2) J w_low^2 = (1/2) (J/u^2) w_motor^2 and elastic
/// energy (1/2) C theta_low^2 = (1/2) (C/u^2) theta_motor^2 are invariant,
/// hence the 1/u^2; power M_low w_low = (M_low/u) w_motor gives 1/u for
/// torques. Natural frequencies are unchanged by the reflection.
struct RollCrusherReducer {
  /// J/u^2 [kg*m^2]; `lowSpeedInertia` [kg*m^2] finite >= 0, `ratio` u [-]
  /// finite > 0 (the crusher's reducer has u up to 140).
  static double reflectInertia(double lowSpeedInertia, double ratio);
  /// C/u^2 [N*m/rad]; `lowSpeedStiffness` [N*m/rad] finite > 0.
  static double reflectStiffness(double lowSpeedStiffness, double ratio);
  /// M/u [N*m]; `lowSpeedTorque` [N*m] finite.
  static double reflectTorque(double lowSpeedTorque, double ratio);
};

}  // namespace milldyn::oracles
