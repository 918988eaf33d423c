// Closed-form (kinetostatic) oracle for the horizontal planetary mill with
// external rolling and a gear drive (seed 000: Khves'ko, Vaitekhovich,
// Borovskiy, "Dynamic model of a horizontal planetary mill", 2022). SI units
// throughout; the model, the misprints and the chosen free parameters are
// written out in docs/oracles/planetary_gear.md.
//
// This file knows nothing of Simbody nor of ModelSpec on purpose: it takes its
// own parameter struct, so it cannot share a bug with the model it judges.
#pragma once

#include <array>

#include <Eigen/Core>

namespace milldyn::oracles {

/// Eq (21) prints M_trA = 2 R_A f d_A/2 = R_A f d_A. R_A from (16) is already
/// the whole reaction of the carrier shaft, so the factor 2 is either two
/// journals that each (wrongly) carry all of R_A, or a misprint. Both readings
/// are kept so that a comparison can name the one it uses.
enum class CarrierFrictionReading {
  kAsPrinted,       ///< M_trA = R_A f d_A (the paper's eq 21).
  kTotalLoadHalfD,  ///< M_trA = R_A f d_A/2 (journal carrying the total R_A).
};

/// How the charge moves. The paper treats drum and charge as one rigid body
/// turning at w2 (its J_pr (1), v_c (5), (22) and Phi_r = m w2^2 Bc (25) all
/// say so); the alternative keeps the charge's segment fixed in the carrier
/// frame at the lag alpha, with the drum wall sliding under it. Only the second
/// dissipates; the two give different steady-state drive torques (see
/// PlanetaryGearOracle).
enum class ChargeMotion {
  kRotatesWithDrum,     ///< The paper's model.
  kHeldInCarrierFrame,  ///< Segment fixed in the carrier frame at its angle.
};

/// Geometry, masses and friction of the mill. Field names, not symbols, are
/// what a std::invalid_argument message names. Defaults are the paper's
/// stated or implied values, where it has one; the rest must be set.
struct PlanetaryGearParameters {
  double drumRadius{0.0};    ///< r [m] > 0: inner radius of the drum, also
                             ///< the pitch radius of its gear.
  double drumLength{0.0};    ///< l [m] > 0: inner length of the drum.
  double wallThickness{0.0};  ///< delta [m] in (0, r]: wall and bottoms; the
                              ///< thin-wall formulas of (3), (9) need delta<<r.
  double shellDensity{0.0};   ///< rho_b [kg/m^3] > 0: wall and bottoms.
  double chargeDensity{0.0};  ///< rho_z [kg/m^3] >= 0: bulk density of the
                              ///< charge (balls + material + voids).
  double sunRadius{0.0};      ///< R [m] > 0: pitch radius of the fixed gear.
  double carrierMass{0.0};    ///< m1 [kg] >= 0: carrier bar B1-B2, a uniform
                              ///< bar of length 2(R+r) centred on A (eq 2).
  double carrierJournalDiameter{0.0};  ///< d_A [m] >= 0.
  double drumJournalDiameter{0.0};     ///< d_B [m] >= 0 (same at B1 and B2).
  double frictionCoefficient{0.0};     ///< f [-] in [0, 1], journal friction.
  double fillHalfAngle{1.5707963267948966};  ///< gamma [rad] in (0, pi]: the
      ///< charge is a circular segment of central angle 2 gamma; 50 % fill
      ///< (the paper's half disc) is pi/2. See calcFillHalfAngle().
  double pressureAngle{0.3490658503988659};  ///< [rad] in [0, pi/2): 20 deg.
  double lagAngle{0.0};  ///< alpha [rad] in [0, pi]: steady-state position of
      ///< the charge, eq (22): the angle between B->c_v (towards A) and B->c
      ///< is 90 deg + alpha. alpha < pi/2 puts the charge on the side the
      ///< drum wall moves towards (ahead of the arm), pi/2 straight outwards,
      ///< > pi/2 behind the arm. The paper does not give it.
  double gravity{9.80665};  ///< g [m/s^2] >= 0; 0 switches gravity off.
  double startTimeConstant{1.0};  ///< tau [s] > 0 of eps = eps0 e^(-t/tau);
      ///< the paper writes e^(-t), i.e. tau = 1 s.
  CarrierFrictionReading carrierFriction{CarrierFrictionReading::kAsPrinted};
};

/// Where the mechanism is and how it moves, for the kinetostatic solver. All
/// angles are in the fixed frame G: origin at the carrier axis A, x
/// horizontal, y up, z towards the viewer; positive rotation is
/// counterclockwise about z.
struct PlanetaryGearMotionState {
  double carrierAngle{0.0};  ///< phi [rad]: direction of A->B2 from +x; B1 is
                             ///< opposite. phi = 0 is the paper's Fig. 3.
  double carrierRate{0.0};   ///< w1 [rad/s] >= 0 (forward running: friction
                             ///< is added as a loss, eq 20).
  double carrierAcceleration{0.0};  ///< eps1 [rad/s^2]; >= 0 when w1 = 0.
  std::array<double, 2> chargeDirection{{-1.5707963267948966,
                                         -1.5707963267948966}};
      ///< theta_i [rad]: direction of B_i->c_i (drum axis to charge
      ///< centroid) for drums B1, B2; -pi/2 is hanging straight down.
};

/// Loads on one drum (drum + charge as one free body), vectors in G [N].
struct PlanetaryDrumLoads {
  Eigen::Vector2d p_AB{Eigen::Vector2d::Zero()};  ///< drum axis B [m].
  Eigen::Vector2d p_Ac{Eigen::Vector2d::Zero()};  ///< loaded-drum mass centre.
  Eigen::Vector2d inertiaForce{Eigen::Vector2d::Zero()};  ///< d'Alembert
      ///< resultant -sum(m a) of shell and charge [N].
  double inertiaMomentAboutAxis{0.0};  ///< d'Alembert moment about B [N*m],
                                       ///< inertia couples included.
  double weightMomentAboutAxis{0.0};   ///< moment of the weight about B.
  double gearTangentialForce{0.0};  ///< F [N]: component of the fixed gear's
      ///< force on the drum along e_t = z x e_out (the direction B moves).
  double gearRadialForce{0.0};  ///< N = |F| tan(pressure angle) [N] >= 0,
                                ///< pushing the drum away from A.
  Eigen::Vector2d gearForce{Eigen::Vector2d::Zero()};  ///< F e_t + N e_out.
  double gearMomentAboutAxis{0.0};  ///< = -r F [N*m]: what the gear must
      ///< apply about B; at steady state, the charge-holding ("lifting")
      ///< moment that the paper's "only friction" omits.
  Eigen::Vector2d bearingForce{Eigen::Vector2d::Zero()};  ///< carrier pin on
      ///< drum at B [N]; its norm is R_B of eq (21).
  double bearingFrictionTorque{0.0};  ///< M_trB = |R_B| f d_B/2 [N*m].
};

/// Kinetostatic solution for the whole mill.
struct PlanetaryGearLoads {
  std::array<PlanetaryDrumLoads, 2> drums;  ///< [0] = B1, [1] = B2.
  Eigen::Vector2d carrierBearingForce{Eigen::Vector2d::Zero()};  ///< ground
      ///< on carrier at A [N]; its norm is R_A of eq (21).
  double carrierFrictionTorque{0.0};  ///< M_trA [N*m], by
                                      ///< PlanetaryGearParameters::carrierFriction.
  double frictionlessTorque{0.0};  ///< carrier torque from the carrier's
      ///< moment balance (16)/(26) with the frictionless reactions [N*m].
  double driveTorque{0.0};  ///< eq (20): frictionlessTorque + M_trA +
                            ///< (M_trB1 + M_trB2) R/r [N*m].
};

/// Which torque history Fig. 10 is taken to show (see
/// calcStartTorqueHistory).
enum class StartTorqueModel {
  kPaperTangentialInertia,  ///< (16)-(21) at w = 0 with eps(t): the paper.
  kRigidChargeKinetostatics,  ///< Full kinetostatics at (phi(t), w(t),
      ///< eps(t)), drums and charge turned by kappa phi(t): adds centrifugal
      ///< loads and the charge's moving weight, which the paper leaves out.
};

/// Kinetostatic oracle of the horizontal planetary mill with external rolling.
///
/// System: a carrier B1-A-B2 (arm R+r each side) turns about the fixed
/// horizontal axis A at w1. Each drum (radius r) turns on a pin at B_i and
/// rolls on the outside of a fixed gear of pitch radius R centred on A.
/// Gravity acts along -y. Each drum holds a charge shaped as a circular
/// segment (half-angle gamma; the paper's 50 % fill is gamma = pi/2).
///
/// <pre>
///   masses (3):  m_d = rho_b pi r^2 delta,  m_st = rho_b 2 pi r l delta,
///                m_b = 2 m_d + m_st,  m_z = rho_z l r^2 (2g - sin 2g)/2,
///                m_bz = m_b + m_z                        (g = gamma)
///   kinematics (4), (15):  w2 = kappa w1,  kappa = (R+r)/r,
///                          w_r = w2 - w1 = w1 R/r
///   centroid (6):  B2c2 = 4 r sin^3 g / (3 (2g - sin 2g))  (= 4r/(3 pi)),
///                  Bc = m_z B2c2/m_bz,  cc2 = B2c2 - Bc
///   inertia (7)-(13):  J_B^b = m_d r^2 + m_st r^2                   (9)
///       J_B^z = m_z r^2 (12g - 4 sin 2g - sin 4g)/(12 (2g - sin 2g))
///             (= m_z r^2/2 at g = pi/2)                             (13)
///       J_c = J_B^b + m_b Bc^2 + J_B^z - m_z (B2c2^2 - cc2^2)   (7),(8),(12)
///   carrier (2):  J1 = m1 (R+r)^2/3
///   reduced inertia (1), (23):  J_pr = J1 + 2 kappa^2 [m_bz cvc^2 + J_c],
///       cvc^2 = r^2 + Bc^2 + 2 r Bc sin(alpha)   (alpha = 0 at start-up)
///   start law:  eps = eps0 e^(-t/tau),  w = eps0 tau (1 - e^(-t/tau)),
///               eps0 = wy/(tau (1 - e^(-t_p/tau)))            (Fig. 6)
///   start-up (16)-(19), w = 0:  eps2 = kappa eps0,
///       Phi^t = m_bz eps2 cvc,  M_C^Phi = J_c eps2,  M_A^Phi = J1 eps0,
///       F r = M_C^Phi + Phi^t sin(beta) Bc,  N = F tan 20 deg
///   friction (21):  M_trA = R_A f d_A (or d_A/2),  M_trB = R_B f d_B/2
///   drive torque (20):  M = J_pr eps0 + M_trA + (M_trB1 + M_trB2) R/r
///   steady state (25):  Phi_e = m_bz w1^2 (R+r)  (printed with w2^2),
///                       Phi_r = m_bz w2^2 Bc
/// </pre>
///
/// Misprints corrected here (each is tested against its printed form): (1)
/// and (23) count the carrier twice, 2(J1 + ...); (6) prints m_7 for m_z; (8)
/// prints the carrier mass m_1 for the shell mass m_b; (25) gives Phi_e with
/// w2^2. The steady-state equations (26)-(28) mix mirrored axes for the two
/// drums: this class solves every state in vector form in the one fixed
/// frame G instead.
///
/// How the loads are found: each drum is a free body under its d'Alembert
/// inertia forces, its weight, the gear force at the pitch point
/// B - r e_out and the pin force at B. The moment about B fixes F; the force
/// balance gives the pin force; the carrier's moment balance about A gives
/// the frictionless torque, and (20) adds friction through the power balance
/// (14). Friction is a first-order correction, as in the paper: reactions are
/// those of the frictionless mechanism, and the loss is added as if the
/// motion were forward (w1 >= 0, w_r >= 0).
///
/// Gravity: the paper keeps the weights G1 and G_bz in the force equations
/// of (16)-(18), so they load the bearings (and friction); with the charges
/// hanging and the carrier level they have no moment about A, so J_pr eps0
/// is still the frictionless start torque. This class does the same and lets
/// g = 0 switch them off.
///
/// What the paper leaves out, available here: any carrier angle and any
/// state (phi, w1, eps1) of the start, with centrifugal loads
/// (calcLoads, StartTorqueModel::kRigidChargeKinetostatics); and the
/// steady-state charge-holding torque. With the rigid charge (the paper's
/// model), the frictionless steady torque is
///   M = -2 m_bz Bc w1^2 kappa^2 R cos(alpha),
/// a conservative exchange with the drums' kinetic energy that averages to
/// zero over a drum turn; with the charge held in the carrier frame it is
///   M = +2 m_z B2c2 w1^2 (R/r)(R+r) cos(alpha) = 2 T_wall w_r/w1,
/// the power the wall dissipates sliding under the charge. Both vanish only
/// at alpha = pi/2 (charge straight outwards), where, without gravity, the
/// pins carry just the centripetal forces. Gravity never enters these
/// frictionless torques (the drums are point-symmetric about A), but an
/// off-vertical charge's weight has a moment about B that the gear takes, so
/// the fixed gear, not A, carries part of the weight.
///
/// Units: SI (m, kg, s, rad, N, N*m).
class PlanetaryGearOracle {
 public:
  /// Throws std::invalid_argument naming the first out-of-range field of
  /// `params` and its value.
  explicit PlanetaryGearOracle(const PlanetaryGearParameters& params);

  const PlanetaryGearParameters& getParameters() const { return m_p; }

  // --- Circular segment (the charge's cross-section), any radius. ---------

  /// Fill fraction (2 gamma - sin 2 gamma)/(2 pi) of a segment of half-angle
  /// `halfAngle` gamma [rad] in (0, pi].
  static double calcFillFraction(double halfAngle);
  /// Inverse of calcFillFraction: gamma [rad] for `fillFraction` in (0, 1].
  static double calcFillHalfAngle(double fillFraction);
  /// Distance [m] from the circle centre to the segment's centroid,
  /// 4 r sin^3 g/(3 (2g - sin 2g)); 4r/(3 pi) at g = pi/2 (eq 6).
  static double calcSegmentCentroidDistance(double radius, double halfAngle);
  /// Segment's moment of inertia about the circle's axis divided by its mass
  /// [m^2]: r^2 (12g - 4 sin 2g - sin 4g)/(12 (2g - sin 2g)); r^2/2 at pi/2.
  static double calcSegmentAxisInertiaPerMass(double radius, double halfAngle);

  // --- Masses (3). [kg] ----------------------------------------------------
  double calcBottomMass() const;      ///< m_d, one bottom.
  double calcWallMass() const;        ///< m_st.
  double calcShellMass() const;       ///< m_b = 2 m_d + m_st.
  double calcChargeMass() const;      ///< m_z.
  double calcLoadedDrumMass() const;  ///< m_bz = m_b + m_z.

  // --- Kinematics (4), (15). ----------------------------------------------
  double calcSpeedRatio() const;  ///< kappa = (R+r)/r [-].
  /// w2 = kappa w1 [rad/s] for carrier rate `carrierRate` w1 [rad/s].
  double calcDrumRate(double carrierRate) const;
  /// w_r = w1 R/r [rad/s] (the paper prints its unit as N*m).
  double calcRelativeDrumRate(double carrierRate) const;

  // --- Mass geometry (6)-(13), (2). ---------------------------------------
  double calcChargeCentroidOffset() const;  ///< B2c2 [m].
  double calcMassCentreOffset() const;      ///< Bc [m].
  double calcCentroidSeparation() const;    ///< cc2 = B2c2 - Bc [m].
  double calcShellInertiaAboutAxis() const;   ///< J_B^b (9) [kg*m^2].
  double calcChargeInertiaAboutAxis() const;  ///< J_B^z (13) [kg*m^2].
  double calcLoadedDrumInertia() const;  ///< J_c (7), corrected [kg*m^2].
  /// J_c with (8) as printed (carrier mass m1 for m_b) [kg*m^2].
  double calcLoadedDrumInertiaAsPrinted() const;
  double calcCarrierInertia() const;  ///< J1 (2) [kg*m^2].

  // --- Reduced inertia (1), (5), (22), (23). ------------------------------
  /// |c_v c| [m], c_v being the pitch point: (5) at `lagAngle` alpha = 0,
  /// (22) in general; alpha [rad] in [0, pi].
  double calcMassCentreLever(double lagAngle) const;
  /// J_pr [kg*m^2], corrected (carrier once), charge at lag `lagAngle` alpha
  /// [rad] in [0, pi]: alpha = 0 is the start-up (1), otherwise (23).
  double calcReducedInertia(double lagAngle) const;
  /// J_pr as printed in (1)/(23), 2(J1 + ...) [kg*m^2].
  double calcReducedInertiaAsPrinted(double lagAngle) const;
  /// J_pr [kg*m^2] for any configuration, from the parts' velocities.
  double calcReducedInertia(const PlanetaryGearMotionState& state,
                            ChargeMotion motion) const;

  // --- Inertia and centrifugal forces (19), (25). [N], [N*m] --------------
  /// Phi^t = m_bz eps2 cvc at start-up, for carrier acceleration
  /// `carrierAcceleration` eps0 [rad/s^2].
  double calcStartUpInertiaForce(double carrierAcceleration) const;
  /// M_C^Phi = J_c eps2.
  double calcStartUpDrumInertiaMoment(double carrierAcceleration) const;
  /// M_A^Phi = J1 eps0.
  double calcCarrierInertiaMoment(double carrierAcceleration) const;
  /// Phi_e = m_bz w1^2 (R+r), corrected, for `carrierRate` w1 [rad/s].
  double calcTransportCentrifugalForce(double carrierRate) const;
  /// Phi_e as printed in (25): m_bz w2^2 (R+r).
  double calcTransportCentrifugalForceAsPrinted(double carrierRate) const;
  /// Phi_r = m_bz w2^2 Bc (rigid charge).
  double calcRelativeCentrifugalForce(double carrierRate) const;

  // --- Kinetostatics. ------------------------------------------------------
  /// Loads in any state. Throws std::invalid_argument for w1 < 0, for
  /// eps1 < 0 at w1 = 0, or for non-finite entries.
  PlanetaryGearLoads calcLoads(const PlanetaryGearMotionState& state,
                               ChargeMotion motion) const;
  /// The paper's start-up state, Fig. 3: carrier level, charges hanging,
  /// w1 = 0, eps1 = `carrierAcceleration` eps0 >= 0.
  static PlanetaryGearMotionState makeStartUpState(double carrierAcceleration);
  /// Steady state (eps1 = 0) at carrier rate `carrierRate` w1 >= 0 and angle
  /// `carrierAngle` phi, both charges at the lag alpha in the carrier frame.
  PlanetaryGearMotionState makeSteadyState(double carrierRate,
                                           double carrierAngle) const;
  /// State at time `time` t >= 0 of the exponential start from rest with
  /// initial acceleration `initialAcceleration` eps0 >= 0, carrier level and
  /// charges hanging at t = 0, charges turning with their drums.
  PlanetaryGearMotionState makeStartState(double initialAcceleration,
                                          double time) const;
  /// (16)-(21) at w = 0: calcLoads(makeStartUpState(eps0), kRotatesWithDrum).
  PlanetaryGearLoads calcStartUpLoads(double carrierAcceleration) const;
  /// (20): drive torque at the start [N*m].
  double calcStartUpTorque(double carrierAcceleration) const;
  /// (22)-(28), corrected and in vector form.
  PlanetaryGearLoads calcSteadyStateLoads(double carrierRate,
                                          double carrierAngle,
                                          ChargeMotion motion) const;

  // --- Start law and Fig. 6 / Fig. 10. ------------------------------------
  /// eps0 = wy/(tau (1 - e^(-t_p/tau))) [rad/s^2] so that w(t_p) = wy, for
  /// `steadyRate` wy [rad/s] >= 0 and `accelerationTime` t_p [s] > 0.
  double calcInitialAcceleration(double steadyRate,
                                 double accelerationTime) const;
  /// eps(t) = eps0 e^(-t/tau) [rad/s^2], t [s] >= 0.
  double calcStartAcceleration(double initialAcceleration, double time) const;
  /// w(t) = eps0 tau (1 - e^(-t/tau)) [rad/s].
  double calcStartRate(double initialAcceleration, double time) const;
  /// phi(t) = eps0 tau (t - tau (1 - e^(-t/tau))) [rad].
  double calcStartAngle(double initialAcceleration, double time) const;
  /// M(t_p)/M(t_p -> inf) = 1/(1 - e^(-t_p/tau)) of the frictionless initial
  /// torque; `accelerationTime` [s] > 0, `timeConstant` [s] > 0.
  static double calcInitialTorqueRatio(double accelerationTime,
                                       double timeConstant);
  /// Fig. 10, reading (a): initial drive torque (20) [N*m] against the chosen
  /// acceleration time t_p [s] > 0 for `steadyRate` wy [rad/s] >= 0. This is
  /// the reading the equations support: it falls from ~4x its large-t_p
  /// value at t_p = 0.29 s to within 5 % at 3 s, as the figure's text says.
  double calcInitialTorqueVsAccelerationTime(double steadyRate,
                                             double accelerationTime) const;
  /// Fig. 10, reading (b): drive torque [N*m] at time `time` t [s] >= 0 of a
  /// start with fixed t_p. Under the paper's assumptions it is largest at
  /// t = 0 and has no peak at 0.3-0.4 s.
  double calcStartTorqueHistory(double steadyRate, double accelerationTime,
                                double time, StartTorqueModel model) const;

  // --- Scaling at equal centrifugal factor. -------------------------------
  /// K = w1^2 (R+r)/g0 [-], g0 = 9.80665 m/s^2 (a similarity number, so the
  /// standard value regardless of PlanetaryGearParameters::gravity).
  double calcCentrifugalFactor(double carrierRate) const;
  /// w1 [rad/s] that gives this mill the same K as `reference` running at
  /// `referenceCarrierRate` [rad/s] >= 0: w1_ref sqrt((R+r)_ref/(R+r)).
  double calcCarrierRateForEqualCentrifugalFactor(
      const PlanetaryGearOracle& reference,
      double referenceCarrierRate) const;

 private:
  PlanetaryGearParameters m_p;
};

}  // namespace milldyn::oracles
