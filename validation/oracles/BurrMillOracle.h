// Closed-form oracle for the MMP-50 burr mill (seed 003: Eremyants & Akanov,
// "Experimental evaluation of the resistance torque on the working organ of a
// burr mill"). Everything is reduced to the motor shaft and in SI units.
//
// This file knows nothing of Simbody nor of ModelSpec on purpose: it takes its
// own parameter structs, so it cannot share a bug with the model it judges.
#pragma once

#include <array>
#include <string_view>

namespace milldyn::oracles {

/// Two inertias coupled by a torsional spring-damper, reduced to the motor
/// shaft: J1 is everything before the belt (motor rotor, driving pulley), J2
/// everything after it (driven pulley, transmission shaft, screw, millstone).
struct TwoMassDrive {
  double J1;  ///< motor-side inertia [kg*m^2], > 0.
  double J2;  ///< mill-side inertia [kg*m^2], > 0.
  double c;   ///< coupling stiffness [N*m/rad], > 0.
  double b;   ///< coupling viscous damping [N*m*s/rad], >= 0 and below
              ///< critical, 2*sqrt(c*J1*J2/(J1+J2)).
};

/// Linear working branch of an induction motor's torque-speed curve,
/// paper eqs (3)-(4):
/// <pre>
///   M0(w1) = M00 - b0*w1                                            (3)
///   M00 = Mn*wc/(wc - wn),   b0 = Mn/(wc - wn)                      (4)
/// </pre>
/// It is the chord through (wc, 0) and (wn, Mn), so it is only meaningful
/// near synchronous speed: extrapolated to standstill it gives ~28*Mn. The
/// paper only ever evaluates it at the steady operating point (eq 13), which
/// is where it is valid.
///
/// Because wc - wn is a small difference of two near-equal numbers, M00 and
/// b0 are very sensitive to how wn was rounded (dM00/dwn = Mn*wc/(wc-wn)^2,
/// about 178 N*m per rad/s for the 5.5 kW motor). That is why the class can
/// also be built from the paper's printed coefficients, which Table 1 used.
class MotorLinearBranch {
 public:
  /// From the nameplate: rated torque `ratedTorque` Mn [N*m] > 0, rated speed
  /// `ratedSpeed` wn [rad/s] and synchronous speed `synchronousSpeed` wc
  /// [rad/s] with 0 < wn < wc.
  static MotorLinearBranch fromNameplate(double ratedTorque, double ratedSpeed,
                                         double synchronousSpeed);

  /// From the coefficients directly: M00 [N*m] > 0, b0 [N*m*s/rad] > 0.
  static MotorLinearBranch fromCoefficients(double M00, double b0);

  /// M00 [N*m]: the branch extrapolated to zero speed.
  double getM00() const { return m_M00; }
  /// b0 [N*m*s/rad]: torque lost per unit of speed.
  double getB0() const { return m_b0; }

  /// No-load speed M00/b0 [rad/s]; equals wc when built from the nameplate.
  double calcNoLoadSpeed() const { return m_M00 / m_b0; }

  /// Eq (3): motor torque [N*m] at motor speed `omega1` [rad/s] (finite).
  double calcTorque(double omega1) const;

  /// Eq (13), M0(wy) = Mc solved for wy (the OCR prints "-" for "="):
  /// wy = (M00 - Mc)/b0 [rad/s], for a resistance torque `Mc` [N*m] with
  /// 0 <= Mc < M00.
  double calcSteadySpeed(double Mc) const;

 private:
  MotorLinearBranch(double M00, double b0) : m_M00(M00), m_b0(b0) {}

  double m_M00;
  double m_b0;
};

/// Coast-down of the two-mass drive after the motor is switched off, with a
/// constant resistance torque Mc on the millstone (paper eqs (1)-(11), with
/// the misprints corrected as derived in PHYSICS.md "003"):
/// <pre>
///   J1 phi1'' + b (phi1' - phi2') + c (phi1 - phi2) =  0              (1)
///   J2 phi2'' - b (phi1' - phi2') - c (phi1 - phi2) = -Mc             (2)
///
///   phi = phi1 - phi2,  Jn = J1 J2/(J1+J2),  2h = b/Jn,  k^2 = c/Jn,
///   lambda = sqrt(k^2 - h^2)
///   phi'' + 2h phi' + k^2 phi = Mc/J2                                 (7)
///   phi(0) = Mc/c,  phi'(0) = 0,  w1(0) = w2(0) = wy
///
///   phi(t) = Mc/(J2 k^2) [1 + (J2/J1) e^(-ht) ((h/lambda) sin(lambda t)
///                                             + cos(lambda t))]       (9)
///   w1(t) = wy - Mc/(lambda (J1+J2)) (lambda t + (J2/J1) e^(-ht) sin(lambda
///   t))
///                                                                    (10)
///   w2(t) = wy - Mc/(lambda (J1+J2)) (lambda t - e^(-ht) sin(lambda t))
///                                                                    (11)
/// </pre>
/// As printed, (1)-(2) carry first derivatives and a "+" coupling sign in (2)
/// (no action = reaction), (7) reads "phi'' = 2h phi' + k^2 phi = Mc/J2"
/// (taken as "-" it is negative damping), k is never defined, and (8)-(9)
/// print e^(-hi) for e^(-ht). The corrected system above is the one whose
/// solution is the printed (9)-(11), which is how the correction was
/// confirmed.
///
/// Assumptions: the motor torque is zero from t = 0 on; before t = 0 the
/// drive ran steadily at wy, so the coupling carried exactly Mc with no
/// twist rate; Mc is constant while the millstone turns forward. The
/// formulas are therefore exact only until w2 first reaches 0 (first stop):
/// after that a real millstone stays stopped (dry friction), whereas the
/// formulas describe it reversing. Only the underdamped case h < k is
/// covered, as in the paper.
///
/// A useful property (used by calcFirstStopTime and
/// identifyResistanceFirstStop): w2 is non-increasing for every h < k. The
/// bracket in (11) has derivative lambda (1 - f(t)) with
/// f(t) = e^(-ht) (cos(lambda t) - (h/lambda) sin(lambda t)); f(0) = 1, and
/// its later maxima, at lambda t = 2 (n pi - atan(h/lambda)), are
/// e^(-2 (h/lambda) (n pi - atan(h/lambda))) <= 1 (n >= 1). So the first stop
/// is also the only zero crossing of (11).
class TwoMassCoastDown {
 public:
  /// `drive` as documented on TwoMassDrive, resistance torque `Mc` [N*m] >= 0,
  /// steady speed before switch-off `omegaY` wy [rad/s] >= 0.
  TwoMassCoastDown(const TwoMassDrive& drive, double Mc, double omegaY);

  const TwoMassDrive& getDrive() const { return m_drive; }
  double getResistanceTorque() const { return m_Mc; }
  double getSteadySpeed() const { return m_omegaY; }

  /// Jn = J1 J2/(J1+J2) [kg*m^2].
  double getReducedInertia() const { return m_Jn; }
  /// h = b/(2 Jn) [1/s].
  double getDecayRate() const { return m_h; }
  /// k = sqrt(c/Jn) [rad/s].
  double getUndampedFrequency() const { return m_k; }
  /// lambda = sqrt(k^2 - h^2) [rad/s].
  double getDampedFrequency() const { return m_lambda; }

  /// Eq (10): motor speed w1 [rad/s] at time `t` [s] >= 0.
  double calcMotorSpeed(double t) const;
  /// Eq (11): millstone speed w2 [rad/s] at time `t` [s] >= 0.
  double calcMillstoneSpeed(double t) const;
  /// Eq (9): twist phi = phi1 - phi2 [rad] at time `t` [s] >= 0.
  double calcTwist(double t) const;
  /// phi' = w1 - w2 = -Mc/(J1 lambda) e^(-ht) sin(lambda t) [rad/s].
  double calcTwistRate(double t) const;
  /// Torque the coupling applies to the mill side, c phi + b phi' [N*m]
  /// (the motor side gets its negative); equals Mc at t = 0.
  double calcCouplingTorque(double t) const;

  /// Eq (12) inverted: the stop time of the mean line w = wy - Mc t/(J1+J2),
  /// i.e. wy (J1+J2)/Mc [s]. Requires Mc > 0.
  double calcMeanLineStopTime() const;

  /// The first t* > 0 [s] with w2(t*) = 0 in eq (11), to about 1e-15
  /// relative. Requires Mc > 0; returns 0 when wy = 0.
  double calcFirstStopTime() const;

 private:
  double calcBracketTerm(double t) const;  // e^(-ht) sin(lambda t) / lambda

  TwoMassDrive m_drive;
  double m_Mc;
  double m_omegaY;
  double m_Jn;
  double m_h;
  double m_k;
  double m_lambda;
};

/// Eq (12): steady speed [rad/s] that a mean line w = wy - Mc t/(J1+J2)
/// needs to reach zero at `runoutTime` t_v [s] >= 0, for resistance `Mc`
/// [N*m] >= 0 and total inertia `totalInertia` J1+J2 [kg*m^2] > 0.
double calcMeanLineSpeed(double Mc, double runoutTime, double totalInertia);

/// Eq (12) solved for t_v: wy (J1+J2)/Mc [s], `Mc` [N*m] > 0, `omegaY`
/// [rad/s] >= 0, `totalInertia` [kg*m^2] > 0.
double calcMeanLineRunoutTime(double Mc, double omegaY, double totalInertia);

/// Eq (14), i.e. (12) = (13) solved for Mc: identification (a), by the mean
/// line. Mc = M00/(1 + b0 t_v/(J1+J2)) [N*m], for a measured `runoutTime`
/// t_v [s] > 0 and `totalInertia` J1+J2 [kg*m^2] > 0.
double identifyResistanceMeanLine(const MotorLinearBranch& motor,
                                  double totalInertia, double runoutTime);

/// Identification (b), by the exact first stop: the Mc [N*m] for which the
/// oscillating system started at wy = (M00 - Mc)/b0 (eq 13) has its first
/// stop (eq 11) exactly at the measured `runoutTime` t_v [s] > 0.
/// Because Mc enters (11) only as a factor and wy is linear in Mc, the root
/// is closed-form (no iteration), with g(t) = t - e^(-ht) sin(lambda t)/lambda:
/// <pre>
///   Mc = M00 / (1 + b0 g(t_v)/(J1+J2))
/// </pre>
/// which is eq (14) with t_v replaced by g(t_v); w2 being non-increasing
/// (see TwoMassCoastDown) makes t_v the first stop, not a later crossing.
double identifyResistanceFirstStop(const MotorLinearBranch& motor,
                                   const TwoMassDrive& drive,
                                   double runoutTime);

/// Eq (15): N = Mc wy [W], `Mc` [N*m] >= 0, `omegaY` [rad/s] >= 0.
double calcResistancePower(double Mc, double omegaY);

/// Millstone torque from the motor-shaft resistances: M_zh = (Mc - Mc_idle) u_p
/// [N*m]; `Mc`, `McIdle` [N*m] >= 0, belt ratio `beltRatio` u_p > 0 (the
/// idle part is friction of the drive itself, not grinding).
double calcMillstoneTorque(double Mc, double McIdle, double beltRatio);

/// Eq (16), empirical: M_zh = a q^m [N*m] with q in kg/min, a = 4.8
/// N*m*(min/kg)^2.5 and m = 2.5 (the paper prints the unit of a as
/// (min/kg)^-2.5, which does not give N*m). Takes the feed rate
/// `feedRate` [kg/s] >= 0 in SI and converts it to kg/min internally, since
/// a is only defined for that unit. `a` [N*m*(min/kg)^m] > 0, `m` > 0.
double calcMillstoneTorqueEmpirical(double feedRate, double a = 4.8,
                                    double m = 2.5);

// ---------------------------------------------------------------------------
// Data as printed in the paper (values copied, not recomputed).

/// Mill-side parameters as printed in the paper.
struct PrintedMillParameters {
  double J2;                ///< [kg*m^2], 982.4e-4.
  double c;                 ///< [N*m/rad], 537 (printed with unit "N/m").
  double beltRatio;         ///< u_p [-], 3.12.
  double synchronousSpeed;  ///< wc [rad/s], 157.08: 1500 rpm, 4-pole at 50 Hz
                            ///< (not printed; implied by 4A...4 motors and by
                            ///< M00/b0 of the printed coefficients).
  double feedCoefficient;   ///< a in eq (16) [N*m*(min/kg)^2.5], 4.8.
  double feedExponent;      ///< m in eq (16) [-], 2.5.
};

/// One of the two motors as printed in the paper.
struct PrintedMotor {
  double motorPowerKW;   ///< nameplate power [kW] (a label, not used in SI).
  double J1;             ///< motor-side inertia [kg*m^2].
  double ratedTorque;    ///< Mn [N*m].
  double ratedSpeedRpm;  ///< nn [rpm] as printed.
  double ratedSpeed;     ///< wn [rad/s] as printed (nn rounded to 0.1 rad/s).
  double M00;            ///< printed M00 [N*m].
  double b0;             ///< printed b0 [N*m*s/rad] (labelled "M0" for 5.5 kW).
};

/// One column of Table 1 as printed in the paper.
struct Table1Row {
  double motorPowerKW;         ///< 5.5 or 3.2 [kW].
  std::string_view feedLabel;  ///< "idle", "50-70 kg/h" or "130-150 kg/h".
  double runoutTime_s;         ///< t_v [s].
  double Mc_Nm;                ///< Mc [N*m].
  double omega_radps;          ///< wy [rad/s].
  double power_W;              ///< N_c [W] (printed in kW).
  double Mzh_Nm;               ///< M_zh [N*m].
};

/// As printed in the paper.
const PrintedMillParameters& getPrintedMillParameters();
/// As printed in the paper: 5.5 kW then 3.2 kW.
const std::array<PrintedMotor, 2>& getPrintedMotors();
/// As printed in the paper; throws std::invalid_argument for a power other
/// than 5.5 or 3.2 kW.
const PrintedMotor& findPrintedMotor(double motorPowerKW);
/// As printed in the paper, including the inconsistent t_v = 1.10 s of the
/// 5.5 kW, 50-70 kg/h column (its Mc, w and N follow from t_v = 1.00 s).
/// Order: 5.5 kW idle, 50-70, 130-150, then 3.2 kW idle, 50-70, 130-150.
const std::array<Table1Row, 6>& getPrintedTable1();

/// The printed drive for one motor with a chosen coupling damping `b`
/// [N*m*s/rad] (the paper gives none).
TwoMassDrive makePrintedDrive(const PrintedMotor& motor, double b);

/// Table 1 quantities recomputed from a run-out time.
struct Table1Check {
  double Mc_Nm;        ///< eq (14) [N*m].
  double omega_radps;  ///< eq (13) [rad/s].
  double power_W;      ///< eq (15) [W].
  double Mzh_Nm;       ///< (Mc - Mc_idle) u_p [N*m], unrounded Mc values.
};

/// Recomputes a Table 1 column from its t_v: Mc by eq (14), wy by (13), N by
/// (15), and M_zh from Mc and the Mc of `idleRunoutTime` [s] > 0 by eq (14).
/// `totalInertia` J1+J2 [kg*m^2] > 0, `beltRatio` u_p > 0.
Table1Check computeTable1Row(const Table1Row& row,
                             const MotorLinearBranch& motor,
                             double totalInertia, double idleRunoutTime,
                             double beltRatio);

/// Same, with the paper's printed M00, b0, J1, J2, u_p for the row's motor and
/// the printed idle t_v of that motor.
Table1Check computeTable1Row(const Table1Row& row);

}  // namespace milldyn::oracles
