#include "validation/oracles/BurrMillOracle.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn::oracles {

namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void throwBadParameter(const char* where, const char* name,
                                    double value, const char* unit,
                                    const std::string& requirement) {
  std::ostringstream message;
  message.precision(17);
  message << where << ": " << name << " = " << value;
  if (unit[0] != '\0') message << ' ' << unit;
  message << " is invalid: " << requirement;
  throw std::invalid_argument(message.str());
}

void requirePositive(const char* where, const char* name, double value,
                     const char* unit) {
  // The negated comparison also rejects NaN.
  if (!(value > 0.0) || !std::isfinite(value))
    throwBadParameter(where, name, value, unit, "must be positive and finite");
}

void requireNonNegative(const char* where, const char* name, double value,
                        const char* unit) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throwBadParameter(where, name, value, unit,
                      "must be non-negative and finite");
}

void requireFinite(const char* where, const char* name, double value,
                   const char* unit) {
  if (!std::isfinite(value))
    throwBadParameter(where, name, value, unit, "must be finite");
}

void validateDrive(const char* where, const TwoMassDrive& drive) {
  requirePositive(where, "J1", drive.J1, "kg*m^2");
  requirePositive(where, "J2", drive.J2, "kg*m^2");
  requirePositive(where, "c", drive.c, "N*m/rad");
  requireNonNegative(where, "b", drive.b, "N*m*s/rad");
  const double Jn = drive.J1 * drive.J2 / (drive.J1 + drive.J2);
  const double bCritical = 2.0 * std::sqrt(drive.c * Jn);
  if (!(drive.b < bCritical)) {
    std::ostringstream requirement;
    requirement.precision(17);
    requirement << "must be below critical damping 2*sqrt(c*Jn) = " << bCritical
                << " N*m*s/rad (eqs 8-11 hold only for the underdamped case)";
    throwBadParameter(where, "b", drive.b, "N*m*s/rad", requirement.str());
  }
}

}  // namespace

// --- MotorLinearBranch -------------------------------------------------------

MotorLinearBranch MotorLinearBranch::fromNameplate(double ratedTorque,
                                                   double ratedSpeed,
                                                   double synchronousSpeed) {
  constexpr const char* kWhere = "MotorLinearBranch::fromNameplate";
  requirePositive(kWhere, "ratedTorque", ratedTorque, "N*m");
  requirePositive(kWhere, "ratedSpeed", ratedSpeed, "rad/s");
  requirePositive(kWhere, "synchronousSpeed", synchronousSpeed, "rad/s");
  if (!(ratedSpeed < synchronousSpeed)) {
    std::ostringstream requirement;
    requirement.precision(17);
    requirement << "must be below synchronousSpeed = " << synchronousSpeed
                << " rad/s (an induction motor runs with positive slip)";
    throwBadParameter(kWhere, "ratedSpeed", ratedSpeed, "rad/s",
                      requirement.str());
  }
  const double slipSpeed = synchronousSpeed - ratedSpeed;
  return MotorLinearBranch(ratedTorque * synchronousSpeed / slipSpeed,
                           ratedTorque / slipSpeed);
}

MotorLinearBranch MotorLinearBranch::fromCoefficients(double M00, double b0) {
  constexpr const char* kWhere = "MotorLinearBranch::fromCoefficients";
  requirePositive(kWhere, "M00", M00, "N*m");
  requirePositive(kWhere, "b0", b0, "N*m*s/rad");
  return MotorLinearBranch(M00, b0);
}

double MotorLinearBranch::calcTorque(double omega1) const {
  requireFinite("MotorLinearBranch::calcTorque", "omega1", omega1, "rad/s");
  return m_M00 - m_b0 * omega1;
}

double MotorLinearBranch::calcSteadySpeed(double Mc) const {
  constexpr const char* kWhere = "MotorLinearBranch::calcSteadySpeed";
  requireNonNegative(kWhere, "Mc", Mc, "N*m");
  if (!(Mc < m_M00)) {
    std::ostringstream requirement;
    requirement.precision(17);
    requirement << "must be below M00 = " << m_M00
                << " N*m, else the linear branch has no forward steady speed";
    throwBadParameter(kWhere, "Mc", Mc, "N*m", requirement.str());
  }
  return (m_M00 - Mc) / m_b0;
}

// --- TwoMassCoastDown --------------------------------------------------------

TwoMassCoastDown::TwoMassCoastDown(const TwoMassDrive& drive, double Mc,
                                   double omegaY)
    : m_drive(drive), m_Mc(Mc), m_omegaY(omegaY) {
  constexpr const char* kWhere = "TwoMassCoastDown";
  validateDrive(kWhere, drive);
  requireNonNegative(kWhere, "Mc", Mc, "N*m");
  requireNonNegative(kWhere, "omegaY", omegaY, "rad/s");
  m_Jn = drive.J1 * drive.J2 / (drive.J1 + drive.J2);
  m_h = drive.b / (2.0 * m_Jn);
  m_k = std::sqrt(drive.c / m_Jn);
  m_lambda = std::sqrt((m_k - m_h) * (m_k + m_h));
}

double TwoMassCoastDown::calcBracketTerm(double t) const {
  return std::exp(-m_h * t) * std::sin(m_lambda * t) / m_lambda;
}

double TwoMassCoastDown::calcMotorSpeed(double t) const {
  requireNonNegative("TwoMassCoastDown::calcMotorSpeed", "t", t, "s");
  const double J = m_drive.J1 + m_drive.J2;
  return m_omegaY -
         m_Mc / J * (t + m_drive.J2 / m_drive.J1 * calcBracketTerm(t));
}

double TwoMassCoastDown::calcMillstoneSpeed(double t) const {
  requireNonNegative("TwoMassCoastDown::calcMillstoneSpeed", "t", t, "s");
  const double J = m_drive.J1 + m_drive.J2;
  return m_omegaY - m_Mc / J * (t - calcBracketTerm(t));
}

double TwoMassCoastDown::calcTwist(double t) const {
  requireNonNegative("TwoMassCoastDown::calcTwist", "t", t, "s");
  const double phiStatic = m_Mc / (m_drive.J2 * m_k * m_k);
  return phiStatic * (1.0 + m_drive.J2 / m_drive.J1 * std::exp(-m_h * t) *
                                (m_h / m_lambda * std::sin(m_lambda * t) +
                                 std::cos(m_lambda * t)));
}

double TwoMassCoastDown::calcTwistRate(double t) const {
  requireNonNegative("TwoMassCoastDown::calcTwistRate", "t", t, "s");
  return -m_Mc / m_drive.J1 * calcBracketTerm(t);
}

double TwoMassCoastDown::calcCouplingTorque(double t) const {
  return m_drive.c * calcTwist(t) + m_drive.b * calcTwistRate(t);
}

double TwoMassCoastDown::calcMeanLineStopTime() const {
  requirePositive("TwoMassCoastDown::calcMeanLineStopTime", "Mc", m_Mc, "N*m");
  return calcMeanLineRunoutTime(m_Mc, m_omegaY, m_drive.J1 + m_drive.J2);
}

double TwoMassCoastDown::calcFirstStopTime() const {
  constexpr const char* kWhere = "TwoMassCoastDown::calcFirstStopTime";
  requirePositive(kWhere, "Mc", m_Mc, "N*m");
  if (m_omegaY == 0.0) return 0.0;

  // w2 = (Mc/J) (tMean - t + e^(-ht) sin(lambda t)/lambda), and the last term
  // is at most 1/lambda in magnitude: w2 > 0 before tMean - 1/lambda and
  // w2 < 0 after tMean + 1/lambda, so the first stop lies in between. The
  // upper end gets extra room so that rounding cannot leave w2(tEnd) = +0.
  const double tMean = calcMeanLineStopTime();
  const double margin = 1.0 / m_lambda;
  double tLow = std::max(0.0, tMean - margin);
  const double tEnd = tMean + 1.5 * margin;
  // w2 is non-increasing (class comment), so one sign change exists; scanning
  // in quarter half-periods anyway keeps the bracket on the FIRST crossing
  // even if that property were lost to rounding near a stationary point.
  const double step = kPi / (4.0 * m_lambda);
  double tHigh = tLow;
  while (calcMillstoneSpeed(tHigh) > 0.0) {
    tLow = tHigh;
    tHigh = std::min(tHigh + step, tEnd);
    if (tHigh == tEnd) break;
  }
  if (calcMillstoneSpeed(tHigh) > 0.0)
    throw std::logic_error(
        "TwoMassCoastDown::calcFirstStopTime: no sign change found in the "
        "bracket [tMean - 1/lambda, tMean + 1.5/lambda]");
  if (tHigh == tLow) return tHigh;

  // Bisection to adjacent doubles: robust on a function that may be flat at
  // the root (b = 0 makes w2' vanish once per period) and only ~60 steps here.
  while (true) {
    const double tMid = 0.5 * (tLow + tHigh);
    if (tMid <= tLow || tMid >= tHigh) break;
    if (calcMillstoneSpeed(tMid) > 0.0)
      tLow = tMid;
    else
      tHigh = tMid;
  }
  return tHigh;
}

// --- Free functions
// ------------------------------------------------------------

double calcMeanLineSpeed(double Mc, double runoutTime, double totalInertia) {
  constexpr const char* kWhere = "calcMeanLineSpeed";
  requireNonNegative(kWhere, "Mc", Mc, "N*m");
  requireNonNegative(kWhere, "runoutTime", runoutTime, "s");
  requirePositive(kWhere, "totalInertia", totalInertia, "kg*m^2");
  return Mc * runoutTime / totalInertia;
}

double calcMeanLineRunoutTime(double Mc, double omegaY, double totalInertia) {
  constexpr const char* kWhere = "calcMeanLineRunoutTime";
  requirePositive(kWhere, "Mc", Mc, "N*m");
  requireNonNegative(kWhere, "omegaY", omegaY, "rad/s");
  requirePositive(kWhere, "totalInertia", totalInertia, "kg*m^2");
  return omegaY * totalInertia / Mc;
}

double identifyResistanceMeanLine(const MotorLinearBranch& motor,
                                  double totalInertia, double runoutTime) {
  constexpr const char* kWhere = "identifyResistanceMeanLine";
  requirePositive(kWhere, "totalInertia", totalInertia, "kg*m^2");
  requirePositive(kWhere, "runoutTime", runoutTime, "s");
  return motor.getM00() / (1.0 + motor.getB0() * runoutTime / totalInertia);
}

double identifyResistanceFirstStop(const MotorLinearBranch& motor,
                                   const TwoMassDrive& drive,
                                   double runoutTime) {
  constexpr const char* kWhere = "identifyResistanceFirstStop";
  validateDrive(kWhere, drive);
  requirePositive(kWhere, "runoutTime", runoutTime, "s");
  // Mc and wy only scale the shape g(t), so the dynamics enter through the
  // drive alone; a unit-load coast-down supplies h and lambda.
  const TwoMassCoastDown shape(drive, 1.0, 0.0);
  const double h = shape.getDecayRate();
  const double lambda = shape.getDampedFrequency();
  const double g = runoutTime - std::exp(-h * runoutTime) *
                                    std::sin(lambda * runoutTime) / lambda;
  return motor.getM00() / (1.0 + motor.getB0() * g / (drive.J1 + drive.J2));
}

double calcResistancePower(double Mc, double omegaY) {
  requireNonNegative("calcResistancePower", "Mc", Mc, "N*m");
  requireNonNegative("calcResistancePower", "omegaY", omegaY, "rad/s");
  return Mc * omegaY;
}

double calcMillstoneTorque(double Mc, double McIdle, double beltRatio) {
  constexpr const char* kWhere = "calcMillstoneTorque";
  requireNonNegative(kWhere, "Mc", Mc, "N*m");
  requireNonNegative(kWhere, "McIdle", McIdle, "N*m");
  requirePositive(kWhere, "beltRatio", beltRatio, "");
  return (Mc - McIdle) * beltRatio;
}

double calcMillstoneTorqueEmpirical(double feedRate, double a, double m) {
  constexpr const char* kWhere = "calcMillstoneTorqueEmpirical";
  requireNonNegative(kWhere, "feedRate", feedRate, "kg/s");
  requirePositive(kWhere, "a", a, "N*m*(min/kg)^m");
  requirePositive(kWhere, "m", m, "");
  constexpr double kSecondsPerMinute = 60.0;
  return a * std::pow(feedRate * kSecondsPerMinute, m);
}

// --- Data as printed in the paper
// ----------------------------------------------

const PrintedMillParameters& getPrintedMillParameters() {
  static const PrintedMillParameters kParameters{982.4e-4, 537.0, 3.12,
                                                 157.08,   4.8,   2.5};
  return kParameters;
}

const std::array<PrintedMotor, 2>& getPrintedMotors() {
  static const std::array<PrintedMotor, 2> kMotors{{
      {5.5, 190.7e-4, 36.3, 1446.0, 151.4, 1010.0, 6.428},
      {3.2, 107.7e-4, 21.3, 1437.0, 150.5, 506.0, 3.221},
  }};
  return kMotors;
}

const PrintedMotor& findPrintedMotor(double motorPowerKW) {
  for (const PrintedMotor& motor : getPrintedMotors())
    if (motor.motorPowerKW == motorPowerKW) return motor;
  throwBadParameter("findPrintedMotor", "motorPowerKW", motorPowerKW, "kW",
                    "the paper has only 5.5 and 3.2 kW motors");
}

const std::array<Table1Row, 6>& getPrintedTable1() {
  static const std::array<Table1Row, 6> kTable{{
      {5.5, "idle", 1.12, 16.2, 154.6, 2500.0, 0.0},
      {5.5, "50-70 kg/h", 1.10, 18.1, 154.3, 2790.0, 5.93},
      {5.5, "130-150 kg/h", 0.60, 29.8, 152.5, 4550.0, 42.43},
      {3.2, "idle", 1.20, 13.9, 152.8, 2120.0, 0.0},
      {3.2, "50-70 kg/h", 1.10, 15.1, 152.4, 2300.0, 3.74},
      {3.2, "130-150 kg/h", 0.60, 27.0, 148.7, 4020.0, 40.91},
  }};
  return kTable;
}

TwoMassDrive makePrintedDrive(const PrintedMotor& motor, double b) {
  const PrintedMillParameters& mill = getPrintedMillParameters();
  const TwoMassDrive drive{motor.J1, mill.J2, mill.c, b};
  validateDrive("makePrintedDrive", drive);
  return drive;
}

Table1Check computeTable1Row(const Table1Row& row,
                             const MotorLinearBranch& motor,
                             double totalInertia, double idleRunoutTime,
                             double beltRatio) {
  constexpr const char* kWhere = "computeTable1Row";
  requirePositive(kWhere, "row.runoutTime_s", row.runoutTime_s, "s");
  requirePositive(kWhere, "idleRunoutTime", idleRunoutTime, "s");
  requirePositive(kWhere, "beltRatio", beltRatio, "");
  Table1Check check{};
  check.Mc_Nm =
      identifyResistanceMeanLine(motor, totalInertia, row.runoutTime_s);
  check.omega_radps = motor.calcSteadySpeed(check.Mc_Nm);
  check.power_W = calcResistancePower(check.Mc_Nm, check.omega_radps);
  const double McIdle =
      identifyResistanceMeanLine(motor, totalInertia, idleRunoutTime);
  check.Mzh_Nm = calcMillstoneTorque(check.Mc_Nm, McIdle, beltRatio);
  return check;
}

Table1Check computeTable1Row(const Table1Row& row) {
  const PrintedMotor& printed = findPrintedMotor(row.motorPowerKW);
  const PrintedMillParameters& mill = getPrintedMillParameters();
  double idleRunoutTime = 0.0;
  for (const Table1Row& candidate : getPrintedTable1())
    if (candidate.motorPowerKW == row.motorPowerKW &&
        candidate.feedLabel == "idle")
      idleRunoutTime = candidate.runoutTime_s;
  return computeTable1Row(
      row, MotorLinearBranch::fromCoefficients(printed.M00, printed.b0),
      printed.J1 + mill.J2, idleRunoutTime, mill.beltRatio);
}

}  // namespace milldyn::oracles
