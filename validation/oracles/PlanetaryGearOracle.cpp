#include "validation/oracles/PlanetaryGearOracle.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStandardGravity = 9.80665;  // m/s^2

[[noreturn]] void throwInvalid(const std::string& name, double value,
                               const std::string& requirement) {
  std::ostringstream msg;
  msg.precision(17);
  msg << name << " = " << value << " is invalid: must be " << requirement;
  throw std::invalid_argument(msg.str());
}

void requireFinite(const std::string& name, double value) {
  if (!std::isfinite(value)) throwInvalid(name, value, "finite");
}

void requirePositive(const std::string& name, double value,
                     const std::string& unit) {
  if (!(std::isfinite(value) && value > 0.0))
    throwInvalid(name, value, "finite and > 0 " + unit);
}

void requireNonNegative(const std::string& name, double value,
                        const std::string& unit) {
  if (!(std::isfinite(value) && value >= 0.0))
    throwInvalid(name, value, "finite and >= 0 " + unit);
}

void requireHalfAngle(const std::string& name, double value) {
  if (!(std::isfinite(value) && value > 0.0 && value <= kPi))
    throwInvalid(name, value, "in (0, pi] rad");
}

void requireLagAngle(const std::string& name, double value) {
  if (!(std::isfinite(value) && value >= 0.0 && value <= kPi))
    throwInvalid(name, value, "in [0, pi] rad");
}

// x - sin x without the cancellation that ruins it for small x (a segment
// area factor with x = 2 gamma): the series' next term after x^11 is below
// 1e-22 relative for x < 0.1.
double xMinusSinX(double x) {
  if (std::abs(x) >= 0.1) return x - std::sin(x);
  const double x2 = x * x;
  return x * x2 / 6.0 *
         (1.0 - x2 / 20.0 *
                    (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0))));
}

// z-component of a x b: the moment of force b applied at lever a.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// z x a: the velocity (per unit rate) of a point at a rotating about z.
Eigen::Vector2d perp(const Eigen::Vector2d& a) {
  return Eigen::Vector2d(-a.y(), a.x());
}

Eigen::Vector2d unit(double angle) {
  return Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

// Outward direction A->B_i: B1 (index 0) is opposite B2.
Eigen::Vector2d outwardDirection(double carrierAngle, int drum) {
  return (drum == 0 ? -1.0 : 1.0) * unit(carrierAngle);
}

void validateState(const PlanetaryGearMotionState& s) {
  requireFinite("PlanetaryGearMotionState.carrierAngle", s.carrierAngle);
  requireNonNegative("PlanetaryGearMotionState.carrierRate", s.carrierRate,
                     "rad/s (friction is added as a loss of forward motion)");
  requireFinite("PlanetaryGearMotionState.carrierAcceleration",
                s.carrierAcceleration);
  if (s.carrierRate == 0.0 && s.carrierAcceleration < 0.0)
    throwInvalid("PlanetaryGearMotionState.carrierAcceleration",
                 s.carrierAcceleration,
                 ">= 0 rad/s^2 at carrierRate = 0 (forward start)");
  requireFinite("PlanetaryGearMotionState.chargeDirection[0]",
                s.chargeDirection[0]);
  requireFinite("PlanetaryGearMotionState.chargeDirection[1]",
                s.chargeDirection[1]);
}

}  // namespace

PlanetaryGearOracle::PlanetaryGearOracle(const PlanetaryGearParameters& p)
    : m_p(p) {
  requirePositive("PlanetaryGearParameters.drumRadius", p.drumRadius, "m");
  requirePositive("PlanetaryGearParameters.drumLength", p.drumLength, "m");
  if (!(std::isfinite(p.wallThickness) && p.wallThickness > 0.0 &&
        p.wallThickness <= p.drumRadius))
    throwInvalid("PlanetaryGearParameters.wallThickness", p.wallThickness,
                 "in (0, drumRadius] m (thin-wall formulas)");
  requirePositive("PlanetaryGearParameters.shellDensity", p.shellDensity,
                  "kg/m^3");
  requireNonNegative("PlanetaryGearParameters.chargeDensity", p.chargeDensity,
                     "kg/m^3");
  requirePositive("PlanetaryGearParameters.sunRadius", p.sunRadius, "m");
  requireNonNegative("PlanetaryGearParameters.carrierMass", p.carrierMass,
                     "kg");
  requireNonNegative("PlanetaryGearParameters.carrierJournalDiameter",
                     p.carrierJournalDiameter, "m");
  requireNonNegative("PlanetaryGearParameters.drumJournalDiameter",
                     p.drumJournalDiameter, "m");
  if (!(std::isfinite(p.frictionCoefficient) && p.frictionCoefficient >= 0.0 &&
        p.frictionCoefficient <= 1.0))
    throwInvalid("PlanetaryGearParameters.frictionCoefficient",
                 p.frictionCoefficient, "in [0, 1]");
  requireHalfAngle("PlanetaryGearParameters.fillHalfAngle", p.fillHalfAngle);
  if (!(std::isfinite(p.pressureAngle) && p.pressureAngle >= 0.0 &&
        p.pressureAngle < 0.5 * kPi))
    throwInvalid("PlanetaryGearParameters.pressureAngle", p.pressureAngle,
                 "in [0, pi/2) rad");
  requireLagAngle("PlanetaryGearParameters.lagAngle", p.lagAngle);
  requireNonNegative("PlanetaryGearParameters.gravity", p.gravity, "m/s^2");
  requirePositive("PlanetaryGearParameters.startTimeConstant",
                  p.startTimeConstant, "s");
  if (p.carrierFriction != CarrierFrictionReading::kAsPrinted &&
      p.carrierFriction != CarrierFrictionReading::kTotalLoadHalfD)
    throwInvalid("PlanetaryGearParameters.carrierFriction",
                 static_cast<double>(p.carrierFriction),
                 "a CarrierFrictionReading enumerator");
}

// --- Segment ---------------------------------------------------------------

double PlanetaryGearOracle::calcFillFraction(double halfAngle) {
  requireHalfAngle("halfAngle", halfAngle);
  return xMinusSinX(2.0 * halfAngle) / (2.0 * kPi);
}

double PlanetaryGearOracle::calcFillHalfAngle(double fillFraction) {
  if (!(std::isfinite(fillFraction) && fillFraction > 0.0 &&
        fillFraction <= 1.0))
    throwInvalid("fillFraction", fillFraction, "in (0, 1]");
  // F(pi - g) = 1 - F(g): solving on the small-angle side for the smaller of
  // F and 1 - F keeps a full fill exactly at pi, and bisection converges
  // because F' = (1 - cos 2g)/pi >= 0. Near F = 1 the answer is inherently
  // ill-conditioned (pi - g ~ (1 - F)^(1/3)).
  const bool upper = fillFraction > 0.5;
  const double target = upper ? 1.0 - fillFraction : fillFraction;
  double lo = 0.0;
  double hi = 0.5 * kPi;
  if (target <= 0.0) {
    hi = 0.0;
  } else {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      if (xMinusSinX(2.0 * mid) / (2.0 * kPi) < target)
        lo = mid;
      else
        hi = mid;
    }
  }
  return upper ? kPi - hi : hi;
}

double PlanetaryGearOracle::calcSegmentCentroidDistance(double radius,
                                                        double halfAngle) {
  requirePositive("radius", radius, "m");
  requireHalfAngle("halfAngle", halfAngle);
  const double s = std::sin(halfAngle);
  return 4.0 * radius * s * s * s / (3.0 * xMinusSinX(2.0 * halfAngle));
}

double PlanetaryGearOracle::calcSegmentAxisInertiaPerMass(double radius,
                                                          double halfAngle) {
  requirePositive("radius", radius, "m");
  requireHalfAngle("halfAngle", halfAngle);
  const double g = halfAngle;
  // 12g - 4 sin 2g - sin 4g = 4 (2g - sin 2g) + (4g - sin 4g), written so
  // that a thin segment (small g) keeps its precision.
  return radius * radius *
         (4.0 * xMinusSinX(2.0 * g) + xMinusSinX(4.0 * g)) /
         (12.0 * xMinusSinX(2.0 * g));
}

// --- Masses ----------------------------------------------------------------

double PlanetaryGearOracle::calcBottomMass() const {
  return m_p.shellDensity * kPi * m_p.drumRadius * m_p.drumRadius *
         m_p.wallThickness;
}

double PlanetaryGearOracle::calcWallMass() const {
  return m_p.shellDensity * 2.0 * kPi * m_p.drumRadius * m_p.drumLength *
         m_p.wallThickness;
}

double PlanetaryGearOracle::calcShellMass() const {
  return 2.0 * calcBottomMass() + calcWallMass();
}

double PlanetaryGearOracle::calcChargeMass() const {
  const double g = m_p.fillHalfAngle;
  return m_p.chargeDensity * m_p.drumLength * m_p.drumRadius *
         m_p.drumRadius * 0.5 * xMinusSinX(2.0 * g);
}

double PlanetaryGearOracle::calcLoadedDrumMass() const {
  return calcShellMass() + calcChargeMass();
}

// --- Kinematics ------------------------------------------------------------

double PlanetaryGearOracle::calcSpeedRatio() const {
  return (m_p.sunRadius + m_p.drumRadius) / m_p.drumRadius;
}

double PlanetaryGearOracle::calcDrumRate(double carrierRate) const {
  return calcSpeedRatio() * carrierRate;
}

double PlanetaryGearOracle::calcRelativeDrumRate(double carrierRate) const {
  return carrierRate * m_p.sunRadius / m_p.drumRadius;
}

// --- Mass geometry ---------------------------------------------------------

double PlanetaryGearOracle::calcChargeCentroidOffset() const {
  return calcSegmentCentroidDistance(m_p.drumRadius, m_p.fillHalfAngle);
}

double PlanetaryGearOracle::calcMassCentreOffset() const {
  return calcChargeMass() * calcChargeCentroidOffset() / calcLoadedDrumMass();
}

double PlanetaryGearOracle::calcCentroidSeparation() const {
  return calcChargeCentroidOffset() - calcMassCentreOffset();
}

double PlanetaryGearOracle::calcShellInertiaAboutAxis() const {
  const double r2 = m_p.drumRadius * m_p.drumRadius;
  return 2.0 * (calcBottomMass() * r2 / 2.0) + calcWallMass() * r2;
}

double PlanetaryGearOracle::calcChargeInertiaAboutAxis() const {
  return calcChargeMass() *
         calcSegmentAxisInertiaPerMass(m_p.drumRadius, m_p.fillHalfAngle);
}

double PlanetaryGearOracle::calcLoadedDrumInertia() const {
  const double Bc = calcMassCentreOffset();
  const double B2c2 = calcChargeCentroidOffset();
  const double cc2 = calcCentroidSeparation();
  const double shell = calcShellInertiaAboutAxis() + calcShellMass() * Bc * Bc;
  const double charge = calcChargeInertiaAboutAxis() -
                        calcChargeMass() * (B2c2 * B2c2 - cc2 * cc2);
  return shell + charge;
}

double PlanetaryGearOracle::calcLoadedDrumInertiaAsPrinted() const {
  const double Bc = calcMassCentreOffset();
  return calcLoadedDrumInertia() +
         (m_p.carrierMass - calcShellMass()) * Bc * Bc;
}

double PlanetaryGearOracle::calcCarrierInertia() const {
  const double arm = m_p.sunRadius + m_p.drumRadius;
  return m_p.carrierMass * arm * arm / 3.0;
}

// --- Reduced inertia -------------------------------------------------------

double PlanetaryGearOracle::calcMassCentreLever(double lagAngle) const {
  requireLagAngle("lagAngle", lagAngle);
  const double r = m_p.drumRadius;
  const double Bc = calcMassCentreOffset();
  return std::sqrt(r * r + Bc * Bc + 2.0 * r * Bc * std::sin(lagAngle));
}

double PlanetaryGearOracle::calcReducedInertia(double lagAngle) const {
  const double k = calcSpeedRatio();
  const double lever = calcMassCentreLever(lagAngle);
  return calcCarrierInertia() +
         2.0 * k * k *
             (calcLoadedDrumMass() * lever * lever + calcLoadedDrumInertia());
}

double PlanetaryGearOracle::calcReducedInertiaAsPrinted(double lagAngle) const {
  return calcReducedInertia(lagAngle) + calcCarrierInertia();
}

double PlanetaryGearOracle::calcReducedInertia(
    const PlanetaryGearMotionState& state, ChargeMotion motion) const {
  validateState(state);
  const double k = calcSpeedRatio();
  const double arm = m_p.sunRadius + m_p.drumRadius;
  const double mb = calcShellMass();
  const double mz = calcChargeMass();
  const double Jshell = calcShellInertiaAboutAxis();
  const double d = calcChargeCentroidOffset();
  const double Jcharge = calcChargeInertiaAboutAxis() - mz * d * d;
  double J = calcCarrierInertia();
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d p_AB = arm * outwardDirection(state.carrierAngle, i);
    const Eigen::Vector2d p_Bc2 = d * unit(state.chargeDirection[i]);
    // Velocities per unit carrier rate.
    const Eigen::Vector2d v_B = perp(p_AB);
    J += mb * v_B.squaredNorm() + Jshell * k * k;
    if (motion == ChargeMotion::kRotatesWithDrum) {
      const Eigen::Vector2d v_c2 = v_B + k * perp(p_Bc2);
      J += mz * v_c2.squaredNorm() + Jcharge * k * k;
    } else {
      const Eigen::Vector2d v_c2 = perp(p_AB + p_Bc2);
      J += mz * v_c2.squaredNorm() + Jcharge;
    }
  }
  return J;
}

// --- Inertia and centrifugal forces ----------------------------------------

double PlanetaryGearOracle::calcStartUpInertiaForce(
    double carrierAcceleration) const {
  return calcLoadedDrumMass() * calcSpeedRatio() * carrierAcceleration *
         calcMassCentreLever(0.0);
}

double PlanetaryGearOracle::calcStartUpDrumInertiaMoment(
    double carrierAcceleration) const {
  return calcLoadedDrumInertia() * calcSpeedRatio() * carrierAcceleration;
}

double PlanetaryGearOracle::calcCarrierInertiaMoment(
    double carrierAcceleration) const {
  return calcCarrierInertia() * carrierAcceleration;
}

double PlanetaryGearOracle::calcTransportCentrifugalForce(
    double carrierRate) const {
  return calcLoadedDrumMass() * carrierRate * carrierRate *
         (m_p.sunRadius + m_p.drumRadius);
}

double PlanetaryGearOracle::calcTransportCentrifugalForceAsPrinted(
    double carrierRate) const {
  const double w2 = calcDrumRate(carrierRate);
  return calcLoadedDrumMass() * w2 * w2 * (m_p.sunRadius + m_p.drumRadius);
}

double PlanetaryGearOracle::calcRelativeCentrifugalForce(
    double carrierRate) const {
  const double w2 = calcDrumRate(carrierRate);
  return calcLoadedDrumMass() * w2 * w2 * calcMassCentreOffset();
}

// --- Kinetostatics ---------------------------------------------------------

PlanetaryGearLoads PlanetaryGearOracle::calcLoads(
    const PlanetaryGearMotionState& s, ChargeMotion motion) const {
  validateState(s);
  const double r = m_p.drumRadius;
  const double arm = m_p.sunRadius + r;
  const double k = calcSpeedRatio();
  const double w1 = s.carrierRate;
  const double e1 = s.carrierAcceleration;
  const double w2 = k * w1;
  const double e2 = k * e1;
  const double mb = calcShellMass();
  const double mz = calcChargeMass();
  const double d = calcChargeCentroidOffset();
  const double Bc = calcMassCentreOffset();
  const double Jshell = calcShellInertiaAboutAxis();
  const double Jcharge = calcChargeInertiaAboutAxis() - mz * d * d;
  const double tanPressure = std::tan(m_p.pressureAngle);
  const Eigen::Vector2d g(0.0, -m_p.gravity);

  PlanetaryGearLoads out;
  double carrierMoment = calcCarrierInertia() * e1;
  Eigen::Vector2d pinForcesSum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 2; ++i) {
    PlanetaryDrumLoads& drum = out.drums[i];
    const Eigen::Vector2d eOut = outwardDirection(s.carrierAngle, i);
    const Eigen::Vector2d eT = perp(eOut);
    const Eigen::Vector2d u = unit(s.chargeDirection[i]);
    const Eigen::Vector2d p_AB = arm * eOut;
    const Eigen::Vector2d p_Bc2 = d * u;
    drum.p_AB = p_AB;
    drum.p_Ac = p_AB + Bc * u;

    // Shell and charge are kept apart (rather than using J_c) so that the
    // charge can also be held in the carrier frame; for the rigid charge the
    // sum is the paper's m_bz a_c and J_c eps2 by Koenig's theorem.
    const Eigen::Vector2d a_B = e1 * perp(p_AB) - w1 * w1 * p_AB;
    Eigen::Vector2d a_c2;
    double chargeCouple;
    if (motion == ChargeMotion::kRotatesWithDrum) {
      a_c2 = a_B + e2 * perp(p_Bc2) - w2 * w2 * p_Bc2;
      chargeCouple = -Jcharge * e2;
    } else {
      const Eigen::Vector2d p_Ac2 = p_AB + p_Bc2;
      a_c2 = e1 * perp(p_Ac2) - w1 * w1 * p_Ac2;
      chargeCouple = -Jcharge * e1;
    }
    const Eigen::Vector2d shellInertia = -mb * a_B;
    const Eigen::Vector2d chargeInertia = -mz * a_c2;
    drum.inertiaForce = shellInertia + chargeInertia;
    drum.inertiaMomentAboutAxis =
        cross(p_Bc2, chargeInertia) - Jshell * e2 + chargeCouple;
    drum.weightMomentAboutAxis = cross(p_Bc2, mz * g);

    // The pitch point is B - r eOut, so F eT there has moment -r F about B.
    drum.gearMomentAboutAxis =
        -(drum.inertiaMomentAboutAxis + drum.weightMomentAboutAxis);
    drum.gearTangentialForce = -drum.gearMomentAboutAxis / r;
    drum.gearRadialForce = std::abs(drum.gearTangentialForce) * tanPressure;
    drum.gearForce = drum.gearTangentialForce * eT + drum.gearRadialForce * eOut;
    drum.bearingForce =
        -(drum.gearForce + drum.inertiaForce + (mb + mz) * g);
    drum.bearingFrictionTorque = drum.bearingForce.norm() *
                                 m_p.frictionCoefficient *
                                 m_p.drumJournalDiameter / 2.0;

    // The drum pushes on the carrier with -bearingForce at B.
    carrierMoment += cross(p_AB, drum.bearingForce);
    pinForcesSum += drum.bearingForce;
  }
  // The carrier's mass centre is on its fixed axis, so only its weight and
  // the pins load A.
  out.carrierBearingForce = pinForcesSum - m_p.carrierMass * g;
  const double journal =
      m_p.carrierFriction == CarrierFrictionReading::kAsPrinted
          ? m_p.carrierJournalDiameter
          : m_p.carrierJournalDiameter / 2.0;
  out.carrierFrictionTorque =
      out.carrierBearingForce.norm() * m_p.frictionCoefficient * journal;
  out.frictionlessTorque = carrierMoment;
  const double reflection = m_p.sunRadius / r;  // w_r/w1, eq (15)
  out.driveTorque = out.frictionlessTorque + out.carrierFrictionTorque +
                    (out.drums[0].bearingFrictionTorque +
                     out.drums[1].bearingFrictionTorque) *
                        reflection;
  return out;
}

PlanetaryGearMotionState PlanetaryGearOracle::makeStartUpState(
    double carrierAcceleration) {
  requireNonNegative("carrierAcceleration", carrierAcceleration, "rad/s^2");
  PlanetaryGearMotionState s;
  s.carrierAngle = 0.0;
  s.carrierRate = 0.0;
  s.carrierAcceleration = carrierAcceleration;
  s.chargeDirection = {{-0.5 * kPi, -0.5 * kPi}};
  return s;
}

PlanetaryGearMotionState PlanetaryGearOracle::makeSteadyState(
    double carrierRate, double carrierAngle) const {
  requireNonNegative("carrierRate", carrierRate, "rad/s");
  requireFinite("carrierAngle", carrierAngle);
  PlanetaryGearMotionState s;
  s.carrierAngle = carrierAngle;
  s.carrierRate = carrierRate;
  s.carrierAcceleration = 0.0;
  // u = sin(alpha) eOut + cos(alpha) eT, i.e. eOut turned by pi/2 - alpha.
  for (int i = 0; i < 2; ++i) {
    const double outAngle = carrierAngle + (i == 0 ? kPi : 0.0);
    s.chargeDirection[i] = outAngle + 0.5 * kPi - m_p.lagAngle;
  }
  return s;
}

PlanetaryGearMotionState PlanetaryGearOracle::makeStartState(
    double initialAcceleration, double time) const {
  requireNonNegative("initialAcceleration", initialAcceleration, "rad/s^2");
  requireNonNegative("time", time, "s");
  PlanetaryGearMotionState s;
  s.carrierAngle = calcStartAngle(initialAcceleration, time);
  s.carrierRate = calcStartRate(initialAcceleration, time);
  s.carrierAcceleration = calcStartAcceleration(initialAcceleration, time);
  // Rolling on a fixed gear turns each drum (absolutely) by kappa phi.
  const double drumAngle = calcSpeedRatio() * s.carrierAngle;
  s.chargeDirection = {{-0.5 * kPi + drumAngle, -0.5 * kPi + drumAngle}};
  return s;
}

PlanetaryGearLoads PlanetaryGearOracle::calcStartUpLoads(
    double carrierAcceleration) const {
  return calcLoads(makeStartUpState(carrierAcceleration),
                   ChargeMotion::kRotatesWithDrum);
}

double PlanetaryGearOracle::calcStartUpTorque(
    double carrierAcceleration) const {
  return calcStartUpLoads(carrierAcceleration).driveTorque;
}

PlanetaryGearLoads PlanetaryGearOracle::calcSteadyStateLoads(
    double carrierRate, double carrierAngle, ChargeMotion motion) const {
  return calcLoads(makeSteadyState(carrierRate, carrierAngle), motion);
}

// --- Start law -------------------------------------------------------------

double PlanetaryGearOracle::calcInitialAcceleration(
    double steadyRate, double accelerationTime) const {
  requireNonNegative("steadyRate", steadyRate, "rad/s");
  requirePositive("accelerationTime", accelerationTime, "s");
  const double tau = m_p.startTimeConstant;
  return steadyRate / (tau * -std::expm1(-accelerationTime / tau));
}

double PlanetaryGearOracle::calcStartAcceleration(double initialAcceleration,
                                                  double time) const {
  requireFinite("initialAcceleration", initialAcceleration);
  requireNonNegative("time", time, "s");
  return initialAcceleration * std::exp(-time / m_p.startTimeConstant);
}

double PlanetaryGearOracle::calcStartRate(double initialAcceleration,
                                          double time) const {
  requireFinite("initialAcceleration", initialAcceleration);
  requireNonNegative("time", time, "s");
  const double tau = m_p.startTimeConstant;
  return initialAcceleration * tau * -std::expm1(-time / tau);
}

double PlanetaryGearOracle::calcStartAngle(double initialAcceleration,
                                           double time) const {
  requireFinite("initialAcceleration", initialAcceleration);
  requireNonNegative("time", time, "s");
  const double tau = m_p.startTimeConstant;
  return initialAcceleration * tau * (time + tau * std::expm1(-time / tau));
}

double PlanetaryGearOracle::calcInitialTorqueRatio(double accelerationTime,
                                                   double timeConstant) {
  requirePositive("accelerationTime", accelerationTime, "s");
  requirePositive("timeConstant", timeConstant, "s");
  return 1.0 / -std::expm1(-accelerationTime / timeConstant);
}

double PlanetaryGearOracle::calcInitialTorqueVsAccelerationTime(
    double steadyRate, double accelerationTime) const {
  return calcStartUpTorque(
      calcInitialAcceleration(steadyRate, accelerationTime));
}

double PlanetaryGearOracle::calcStartTorqueHistory(
    double steadyRate, double accelerationTime, double time,
    StartTorqueModel model) const {
  const double eps0 = calcInitialAcceleration(steadyRate, accelerationTime);
  if (model == StartTorqueModel::kPaperTangentialInertia)
    return calcStartUpTorque(calcStartAcceleration(eps0, time));
  return calcLoads(makeStartState(eps0, time), ChargeMotion::kRotatesWithDrum)
      .driveTorque;
}

// --- Scaling ---------------------------------------------------------------

double PlanetaryGearOracle::calcCentrifugalFactor(double carrierRate) const {
  requireNonNegative("carrierRate", carrierRate, "rad/s");
  return carrierRate * carrierRate * (m_p.sunRadius + m_p.drumRadius) /
         kStandardGravity;
}

double PlanetaryGearOracle::calcCarrierRateForEqualCentrifugalFactor(
    const PlanetaryGearOracle& reference, double referenceCarrierRate) const {
  requireNonNegative("referenceCarrierRate", referenceCarrierRate, "rad/s");
  const PlanetaryGearParameters& q = reference.getParameters();
  return referenceCarrierRate *
         std::sqrt((q.sunRadius + q.drumRadius) /
                   (m_p.sunRadius + m_p.drumRadius));
}

}  // namespace milldyn::oracles
