// Tests of the MMP-50 burr-mill oracle (seed 003). Reference values come from
// the paper's text, from hand calculation written out in the comments, or
// from an independent RK4 integration of the equations of motion in this
// file -- never from the oracle's own output.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "validation/oracles/BurrMillOracle.h"

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Paper parameters, typed in from the seed text (not read from the oracle,
// so that a typo in the oracle's data tables cannot hide here).
constexpr double kJ2 = 982.4e-4;         // kg*m^2
constexpr double kJ1Motor55 = 190.7e-4;  // kg*m^2, 5.5 kW
constexpr double kJ1Motor32 = 107.7e-4;  // kg*m^2, 3.2 kW
constexpr double kC = 537.0;             // N*m/rad
constexpr double kBeltRatio = 3.12;
constexpr double kOmegaC = 157.08;      // rad/s, 1500 rpm
constexpr double kM00Motor55 = 1010.0;  // N*m, printed
constexpr double kB0Motor55 = 6.428;    // N*m*s/rad, printed
constexpr double kM00Motor32 = 506.0;
constexpr double kB0Motor32 = 3.221;

// RK4 with dt = 1e-5 s resolves the ~183 rad/s mode with lambda*dt ~ 2e-3;
// its global error over 1 s is ~1e5 * (lambda dt)^5/120 * 4 rad/s ~ 1e-10
// rad/s, so 1e-8 rad/s leaves two orders of margin yet would catch any
// wrong coefficient in (9)-(11).
constexpr double kRk4Step = 1e-5;             // s
constexpr double kRk4SpeedTolerance = 1e-8;   // rad/s
constexpr double kRk4TwistTolerance = 1e-10;  // rad (twist is ~0.03 rad)

// Closed forms evaluated in double: a few ulps of the ~155 rad/s speeds.
constexpr double kRoundingRelTolerance = 1e-12;

double reducedInertia(double J1, double J2) { return J1 * J2 / (J1 + J2); }

// b for a damping ratio zeta = h/k, i.e. b = 2 zeta sqrt(c Jn).
double dampingForRatio(double zeta, double J1) {
  return 2.0 * zeta * std::sqrt(kC * reducedInertia(J1, kJ2));
}

TwoMassDrive paperDrive55(double b) { return {kJ1Motor55, kJ2, kC, b}; }

MotorLinearBranch printedMotor55() {
  return MotorLinearBranch::fromCoefficients(kM00Motor55, kB0Motor55);
}

using State = std::array<double, 4>;  // phi1, phi2, w1, w2
using Rhs = std::function<State(const State&)>;

State rk4Step(const Rhs& f, const State& y, double dt) {
  auto axpy = [](const State& a, double s, const State& d) {
    State r{};
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + s * d[i];
    return r;
  };
  const State k1 = f(y);
  const State k2 = f(axpy(y, 0.5 * dt, k1));
  const State k3 = f(axpy(y, 0.5 * dt, k2));
  const State k4 = f(axpy(y, dt, k3));
  State r{};
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = y[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  return r;
}

// Corrected (1)-(2) with M0 = 0: the coupling torque acts +tau on the mill,
// -tau on the motor.
Rhs correctedCoastDown(const TwoMassDrive& d, double Mc) {
  return [d, Mc](const State& y) {
    const double tau = d.c * (y[0] - y[1]) + d.b * (y[2] - y[3]);
    return State{y[2], y[3], -tau / d.J1, (tau - Mc) / d.J2};
  };
}

// The steady state before switch-off: equal speeds, twist carrying Mc.
State steadyState(const TwoMassDrive& d, double Mc, double omegaY) {
  return State{Mc / d.c, 0.0, omegaY, omegaY};
}

template <typename Callable>
void expectInvalidArgumentNaming(Callable&& call, const std::string& name) {
  try {
    call();
    ADD_FAILURE() << "expected std::invalid_argument naming " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(name + " ="), std::string::npos)
        << "message does not name '" << name << "': " << e.what();
  }
}

// --- Coast-down solution (9)-(11) --------------------------------------------

TEST(BurrMillOracleTest, CoastDownSpeedsAndTwistMatchRk4OfCorrectedEquations) {
  const double Mc = 16.2;       // N*m, Table 1 idle, 5.5 kW
  const double omegaY = 154.6;  // rad/s
  for (double zeta : {0.0, 0.01, 0.05, 0.5}) {
    const TwoMassDrive drive = paperDrive55(dampingForRatio(zeta, kJ1Motor55));
    const TwoMassCoastDown oracle(drive, Mc, omegaY);
    const Rhs rhs = correctedCoastDown(drive, Mc);
    State y = steadyState(drive, Mc, omegaY);
    // Up to 1.0 s: before the first stop (~1.12 s), where (10)-(11) hold.
    const int stepsPerCheck = 5000;
    for (int i = 1; i <= 100000; ++i) {
      y = rk4Step(rhs, y, kRk4Step);
      if (i % stepsPerCheck != 0) continue;
      const double t = i * kRk4Step;
      SCOPED_TRACE("zeta = " + std::to_string(zeta) +
                   ", t = " + std::to_string(t));
      EXPECT_NEAR(oracle.calcMotorSpeed(t), y[2], kRk4SpeedTolerance);
      EXPECT_NEAR(oracle.calcMillstoneSpeed(t), y[3], kRk4SpeedTolerance);
      EXPECT_NEAR(oracle.calcTwist(t), y[0] - y[1], kRk4TwistTolerance);
      EXPECT_NEAR(oracle.calcTwistRate(t), y[2] - y[3], kRk4SpeedTolerance);
    }
  }
}

TEST(BurrMillOracleTest, FrequenciesFollowFromReducedInertia) {
  const double b = 0.3;  // N*m*s/rad, arbitrary underdamped value
  const TwoMassCoastDown oracle(paperDrive55(b), 16.2, 154.6);
  // Jn = 0.01907*0.09824/0.11731 = 0.0159700 kg*m^2, k = sqrt(537/Jn) =
  // 183.373 rad/s, h = 0.3/(2 Jn) = 9.3926 1/s, lambda = 183.132 rad/s.
  EXPECT_NEAR(oracle.getReducedInertia(), 0.0159700, 1e-7);
  EXPECT_NEAR(oracle.getUndampedFrequency(), 183.373, 1e-3);
  EXPECT_NEAR(oracle.getDecayRate(), 9.3926, 1e-4);
  EXPECT_NEAR(oracle.getDampedFrequency(), 183.132, 1e-3);
}

TEST(BurrMillOracleTest, CouplingCarriesMcAtSwitchOffAndMotorShareOfItLater) {
  const double Mc = 29.8;
  const TwoMassDrive drive = paperDrive55(dampingForRatio(0.05, kJ1Motor55));
  const TwoMassCoastDown oracle(drive, Mc, 152.5);
  const double tolerance = kRoundingRelTolerance * Mc;
  EXPECT_NEAR(oracle.calcTwist(0.0), Mc / kC, kRoundingRelTolerance);
  EXPECT_NEAR(oracle.calcTwistRate(0.0), 0.0, kRoundingRelTolerance);
  EXPECT_NEAR(oracle.calcCouplingTorque(0.0), Mc, tolerance);
  // Once the oscillation has died out (e^(-h t) ~ 1e-20 at 5 s) both masses
  // decelerate at Mc/(J1+J2), so the coupling must supply J1*Mc/(J1+J2):
  // exactly the motor's share.
  EXPECT_NEAR(oracle.calcCouplingTorque(5.0),
              Mc * kJ1Motor55 / (kJ1Motor55 + kJ2), tolerance);
}

TEST(BurrMillOracleTest, InertiaWeightedMeanSpeedFollowsMeanLineExactly) {
  // J1 w1' + J2 w2' = -Mc: the coupling is internal, so the mean speed is
  // the straight line of eq (12) whatever the damping.
  const double Mc = 18.1;
  const double omegaY = 154.3;
  const double J = kJ1Motor55 + kJ2;
  for (double b : {0.0, 0.1, 1.0}) {
    const TwoMassCoastDown oracle(paperDrive55(b), Mc, omegaY);
    for (double t = 0.0; t <= 1.0; t += 0.0137) {
      const double mean = (kJ1Motor55 * oracle.calcMotorSpeed(t) +
                           kJ2 * oracle.calcMillstoneSpeed(t)) /
                          J;
      EXPECT_NEAR(mean, omegaY - Mc * t / J, kRoundingRelTolerance * omegaY)
          << "b = " << b << ", t = " << t;
    }
  }
}

TEST(BurrMillOracleTest, PrintedEq7MinusSignGivesGrowingOscillationNotEq9) {
  // Misprint in (7): "phi'' - 2h phi' + k^2 phi = Mc/J2" (the OCR shows "=")
  // is negative damping. Integrated literally, the twist oscillation grows
  // as e^(+ht), while the corrected (9) decays as e^(-ht).
  const double Mc = 16.2;
  const TwoMassDrive drive = paperDrive55(dampingForRatio(0.05, kJ1Motor55));
  const TwoMassCoastDown oracle(drive, Mc, 154.6);
  const double Jn = reducedInertia(kJ1Motor55, kJ2);
  const double h = drive.b / (2.0 * Jn);
  const double k2 = kC / Jn;
  const double phiStatic = Mc / (kJ2 * k2);
  const double amplitude0 = Mc / kC - phiStatic;

  // Reuse the 4-state integrator with (phi, phi') in the first two slots.
  const Rhs printed = [&](const State& y) {
    return State{y[1], 2.0 * h * y[1] - k2 * y[0] + Mc / kJ2, 0.0, 0.0};
  };
  State y{Mc / kC, 0.0, 0.0, 0.0};
  double maxPrintedDeviation = 0.0;
  double maxOracleDeviation = 0.0;
  for (int i = 1; i <= 30000; ++i) {
    y = rk4Step(printed, y, kRk4Step);
    const double t = i * kRk4Step;
    if (t < 0.25) continue;
    maxPrintedDeviation =
        std::max(maxPrintedDeviation, std::abs(y[0] - phiStatic));
    maxOracleDeviation =
        std::max(maxOracleDeviation, std::abs(oracle.calcTwist(t) - phiStatic));
  }
  // At t >= 0.25 s, e^(+h t) >= 10 and e^(-h t) <= 0.11 for zeta = 0.05.
  EXPECT_GT(maxPrintedDeviation, 5.0 * amplitude0);
  EXPECT_LT(maxOracleDeviation, 0.2 * amplitude0);
}

TEST(BurrMillOracleTest, PrintedEq2CouplingSignBreaksMomentumBalanceAndEq11) {
  // Misprint in (2): "+ b(phi1'-phi2') + c(phi1-phi2)" puts the coupling
  // torque on both masses in the same direction (no action = reaction). The
  // inertia-weighted mean speed then leaves the line of (12), and w2 leaves
  // (11), by far more than the integration error.
  const double Mc = 16.2;
  const double omegaY = 154.6;
  const TwoMassDrive d = paperDrive55(dampingForRatio(0.01, kJ1Motor55));
  const TwoMassCoastDown oracle(d, Mc, omegaY);
  const Rhs printed = [&](const State& y) {
    const double tau = d.c * (y[0] - y[1]) + d.b * (y[2] - y[3]);
    return State{y[2], y[3], -tau / d.J1, (-tau - Mc) / d.J2};
  };
  State y = steadyState(d, Mc, omegaY);
  const int steps = 20000;  // 0.2 s
  for (int i = 0; i < steps; ++i) y = rk4Step(printed, y, kRk4Step);
  const double t = steps * kRk4Step;
  const double J = kJ1Motor55 + kJ2;
  const double mean = (d.J1 * y[2] + d.J2 * y[3]) / J;
  EXPECT_GT(std::abs(mean - (omegaY - Mc * t / J)), 1e3 * kRk4SpeedTolerance);
  EXPECT_GT(std::abs(y[3] - oracle.calcMillstoneSpeed(t)),
            1e3 * kRk4SpeedTolerance);
}

// --- First stop
// ------------------------------------------------------------------

TEST(BurrMillOracleTest,
     FirstStopIsFirstZeroOfEq11AndWithinOneOverLambdaOfMeanLine) {
  // Paper 5.5 kW, idle: Mc from (14) with t_v = 1.12 s and wy from (13), so
  // the mean line stops at exactly 1.12 s. From (11),
  //   t* - t_mean = e^(-h t*) sin(lambda t*)/lambda,
  // so |t* - t_mean| <= e^(-h (t_mean - 1/lambda))/lambda <= 1/lambda
  // (5.45 ms). Found values: b = 0: t* = 1.11690 s (-3.1 ms);
  // zeta = 0.01 (b = 0.0586): -0.61 ms; zeta = 0.05 (b = 0.293): -1.5e-7 s.
  const double tMean = 1.12;
  const double J = kJ1Motor55 + kJ2;
  const double Mc = kM00Motor55 / (1.0 + kB0Motor55 * tMean / J);
  const double omegaY = (kM00Motor55 - Mc) / kB0Motor55;
  for (double zeta : {0.0, 0.01, 0.05}) {
    SCOPED_TRACE("zeta = " + std::to_string(zeta));
    const TwoMassDrive drive = paperDrive55(dampingForRatio(zeta, kJ1Motor55));
    const TwoMassCoastDown oracle(drive, Mc, omegaY);
    const double Jn = reducedInertia(kJ1Motor55, kJ2);
    const double h = drive.b / (2.0 * Jn);
    const double lambda = std::sqrt(kC / Jn - h * h);
    const double tStop = oracle.calcFirstStopTime();

    EXPECT_NEAR(oracle.calcMeanLineStopTime(), tMean, kRoundingRelTolerance);
    EXPECT_LE(std::abs(tStop - tMean),
              std::exp(-h * (tMean - 1.0 / lambda)) / lambda);
    // A zero of (11) to ~1e-12 s: the slope there is O(Mc/J) ~ 140 rad/s^2.
    EXPECT_LE(oracle.calcMillstoneSpeed(tStop), 0.0);
    EXPECT_GT(oracle.calcMillstoneSpeed(tStop - 1e-12 * tStop), 0.0);
    // And the first one: w2 stays positive on a fine grid before it.
    for (double t = 0.0; t < tStop - 1e-9; t += 1e-5)
      ASSERT_GT(oracle.calcMillstoneSpeed(t), 0.0) << "t = " << t;
  }
}

TEST(BurrMillOracleTest, FirstStopAgreesWithSignChangeOfRk4Integration) {
  const double Mc = 29.8;
  const double omegaY = 152.5;
  for (double zeta : {0.0, 0.02}) {
    const TwoMassDrive drive = paperDrive55(dampingForRatio(zeta, kJ1Motor55));
    const Rhs rhs = correctedCoastDown(drive, Mc);
    State y = steadyState(drive, Mc, omegaY);
    State previous = y;
    int i = 0;
    while (y[3] > 0.0) {
      previous = y;
      y = rk4Step(rhs, y, kRk4Step);
      ++i;
    }
    // Linear interpolation inside one 1e-5 s step: error ~ dt^2 w2''/w2' and
    // the RK4 speed error / slope, both well under 1e-7 s.
    const double tCross =
        (i - 1) * kRk4Step + kRk4Step * previous[3] / (previous[3] - y[3]);
    const TwoMassCoastDown oracle(drive, Mc, omegaY);
    EXPECT_NEAR(oracle.calcFirstStopTime(), tCross, 1e-7) << "zeta = " << zeta;
  }
}

TEST(BurrMillOracleTest, FirstStopIsZeroWhenAlreadyAtRest) {
  const TwoMassCoastDown oracle(paperDrive55(0.1), 16.2, 0.0);
  EXPECT_EQ(oracle.calcFirstStopTime(), 0.0);
}

// --- Identification
// --------------------------------------------------------------

TEST(BurrMillOracleTest, MeanLineIdentificationRoundTripsMcThroughRunoutTime) {
  const MotorLinearBranch motor = printedMotor55();
  const double J = kJ1Motor55 + kJ2;
  for (double Mc : {1.0, 16.2, 29.8, 300.0}) {
    const double tv = calcMeanLineRunoutTime(Mc, motor.calcSteadySpeed(Mc), J);
    EXPECT_NEAR(identifyResistanceMeanLine(motor, J, tv), Mc,
                kRoundingRelTolerance * Mc);
  }
}

TEST(BurrMillOracleTest,
     MeanLineSpeedOfEq12MatchesSteadySpeedOfEq13AtIdentifiedMc) {
  const MotorLinearBranch motor = printedMotor55();
  const double J = kJ1Motor55 + kJ2;
  const double tv = 1.12;
  const double Mc = identifyResistanceMeanLine(motor, J, tv);
  EXPECT_NEAR(calcMeanLineSpeed(Mc, tv, J), motor.calcSteadySpeed(Mc),
              kRoundingRelTolerance * 155.0);
  EXPECT_NEAR(motor.calcTorque(motor.calcSteadySpeed(Mc)), Mc,
              kRoundingRelTolerance * kM00Motor55);
}

TEST(BurrMillOracleTest,
     FirstStopIdentificationMakesFirstStopEqualMeasuredTime) {
  const MotorLinearBranch motor = printedMotor55();
  const double tv = 1.12;
  for (double zeta : {0.0, 0.01, 0.05}) {
    SCOPED_TRACE("zeta = " + std::to_string(zeta));
    const TwoMassDrive drive = paperDrive55(dampingForRatio(zeta, kJ1Motor55));
    const double McExact = identifyResistanceFirstStop(motor, drive, tv);
    const TwoMassCoastDown atExact(drive, McExact,
                                   motor.calcSteadySpeed(McExact));
    EXPECT_NEAR(atExact.calcFirstStopTime(), tv, kRoundingRelTolerance * tv);

    // Independently: bisect Mc on firstStop(Mc, wy(Mc)) = tv; first stop
    // falls as Mc rises (more load, lower start speed).
    double lo = 1.0;
    double hi = 100.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double mid = 0.5 * (lo + hi);
      const TwoMassCoastDown trial(drive, mid, motor.calcSteadySpeed(mid));
      (trial.calcFirstStopTime() > tv ? lo : hi) = mid;
    }
    // 1e-11 relative: the bisection resolves t* to ~1e-16 s, and
    // dMc/dt* ~ Mc/t* turns that into ~1e-15 N*m plus rounding in wy(Mc).
    EXPECT_NEAR(McExact, 0.5 * (lo + hi), 1e-11 * McExact);
  }
}

TEST(BurrMillOracleTest, FirstStopIdentificationRoundTripsMcThroughFirstStop) {
  const MotorLinearBranch motor = printedMotor55();
  const TwoMassDrive drive = paperDrive55(dampingForRatio(0.01, kJ1Motor55));
  for (double Mc : {16.2, 18.1, 29.8}) {
    const TwoMassCoastDown oracle(drive, Mc, motor.calcSteadySpeed(Mc));
    const double tStop = oracle.calcFirstStopTime();
    EXPECT_NEAR(identifyResistanceFirstStop(motor, drive, tStop), Mc,
                kRoundingRelTolerance * Mc);
  }
}

TEST(BurrMillOracleTest,
     FirstStopIdentificationDiffersFromEq14ByLessThanPhaseBound) {
  // With g(t) = t - e^(-ht) sin(lambda t)/lambda, identification (b) is (14)
  // with t_v -> g(t_v), so it lies between (14) evaluated at
  // t_v -/+ e^(-h t_v)/lambda. At t_v = 1.12 s (5.5 kW idle, Mc(14) =
  // 16.1936 N*m) the values found are Mc(b) - Mc(a) = -0.0712 N*m (-0.44 %)
  // for b = 0, -0.0091 N*m (-0.056 %) for zeta = 0.01, and -2.1e-6 N*m for
  // zeta = 0.05: the undamped case moves Mc by more than the printing
  // precision (0.05 N*m); any realistic damping makes the mean line exact.
  const MotorLinearBranch motor = printedMotor55();
  const double tv = 1.12;
  const double J = kJ1Motor55 + kJ2;
  const double McMeanLine = identifyResistanceMeanLine(motor, J, tv);
  for (double zeta : {0.0, 0.01, 0.05}) {
    SCOPED_TRACE("zeta = " + std::to_string(zeta));
    const TwoMassDrive drive = paperDrive55(dampingForRatio(zeta, kJ1Motor55));
    const double Jn = reducedInertia(kJ1Motor55, kJ2);
    const double h = drive.b / (2.0 * Jn);
    const double lambda = std::sqrt(kC / Jn - h * h);
    const double shift = std::exp(-h * tv) / lambda;
    const double McExact = identifyResistanceFirstStop(motor, drive, tv);
    EXPECT_GE(McExact, kM00Motor55 / (1.0 + kB0Motor55 * (tv + shift) / J));
    EXPECT_LE(McExact, kM00Motor55 / (1.0 + kB0Motor55 * (tv - shift) / J));
    if (zeta >= 0.05) {
      EXPECT_NEAR(McExact, McMeanLine, 1e-4);
    }
  }
}

// --- Motor linear branch (3)-(4)
// -----------------------------------------------

TEST(BurrMillOracleTest, NameplateWithRatedRpmGivesAbout1008And6p42) {
  // wn = 1446*pi/30 = 151.42477 rad/s, wc - wn = 5.65523 rad/s:
  //   b0 = 36.3/5.65523 = 6.4188, M00 = 6.4188*157.08 = 1008.27.
  // wn = 1437*pi/30 = 150.48229 rad/s, wc - wn = 6.59771 rad/s:
  //   b0 = 21.3/6.59771 = 3.2284, M00 = 3.2284*157.08 = 507.12.
  const auto m55 =
      MotorLinearBranch::fromNameplate(36.3, 1446.0 * kPi / 30.0, kOmegaC);
  EXPECT_NEAR(m55.getM00(), 1008.27, 0.01);
  EXPECT_NEAR(m55.getB0(), 6.4188, 1e-4);
  const auto m32 =
      MotorLinearBranch::fromNameplate(21.3, 1437.0 * kPi / 30.0, kOmegaC);
  EXPECT_NEAR(m32.getM00(), 507.12, 0.01);
  EXPECT_NEAR(m32.getB0(), 3.2284, 1e-4);
  EXPECT_NEAR(m55.calcNoLoadSpeed(), kOmegaC, kRoundingRelTolerance * kOmegaC);
}

TEST(BurrMillOracleTest,
     NameplateWithPrintedRoundedOmegaGivesAbout1004And6p39) {
  // wn = 151.4: wc - wn = 5.68, b0 = 36.3/5.68 = 6.3908, M00 = 1003.87.
  // wn = 150.5: wc - wn = 6.58, b0 = 21.3/6.58 = 3.2371, M00 = 508.48.
  const auto m55 = MotorLinearBranch::fromNameplate(36.3, 151.4, kOmegaC);
  EXPECT_NEAR(m55.getM00(), 1003.87, 0.01);
  EXPECT_NEAR(m55.getB0(), 6.3908, 1e-4);
  const auto m32 = MotorLinearBranch::fromNameplate(21.3, 150.5, kOmegaC);
  EXPECT_NEAR(m32.getM00(), 508.48, 0.01);
  EXPECT_NEAR(m32.getB0(), 3.2371, 1e-4);
}

TEST(BurrMillOracleTest, PrintedCoefficientsLieWithinHalfRpmBandOfNameplate) {
  // The printed 1010 vs 1008.27 differs by more than M00's own rounding
  // (+-0.5 N*m), but the nameplate speed is only given to 1 rpm, and M00
  // moves ~9.4 N*m per half rpm (Mn wc/(wc-wn)^2 * pi/60). So it is not a
  // misprint: the authors' wn lay within 1446 +- 0.5 rpm (b0 = 6.428 means
  // wn = wc - 36.3/6.428 = 151.433 rad/s = 1446.08 rpm). Likewise 3.221 means
  // 1436.85 rpm. And both printed pairs satisfy M00/b0 = wc within M00's
  // rounding: 1010/6.428 = 157.13, 506/3.221 = 157.09.
  struct Case {
    double Mn, rpm, M00, b0;
  };
  for (const Case& m : {Case{36.3, 1446.0, kM00Motor55, kB0Motor55},
                        Case{21.3, 1437.0, kM00Motor32, kB0Motor32}}) {
    const auto slow = MotorLinearBranch::fromNameplate(
        m.Mn, (m.rpm - 0.5) * kPi / 30.0, kOmegaC);
    const auto fast = MotorLinearBranch::fromNameplate(
        m.Mn, (m.rpm + 0.5) * kPi / 30.0, kOmegaC);
    const auto exact =
        MotorLinearBranch::fromNameplate(m.Mn, m.rpm * kPi / 30.0, kOmegaC);
    EXPECT_GT(m.b0, slow.getB0());
    EXPECT_LT(m.b0, fast.getB0());
    EXPECT_GT(m.M00, slow.getM00());
    EXPECT_LT(m.M00, fast.getM00());
    EXPECT_GT(std::abs(m.M00 - exact.getM00()), 0.5);  // beyond M00 rounding
    EXPECT_NEAR(m.M00 / m.b0, kOmegaC, 0.5 / m.b0);
  }
}

// --- Table 1
// -----------------------------------------------------------------------

// The authors evidently computed from the t_v values as printed (to 0.01 s):
// every consistent column rounds exactly to its printed values, so the
// tolerance is half a unit in the last printed digit with no t_v
// propagation (which would add ~0.07 N*m, |dMc/dt_v| ~ Mc/t_v * 0.005 s).
constexpr double kHalfUnitMc = 0.05;     // N*m, printed to 0.1
constexpr double kHalfUnitOmega = 0.05;  // rad/s, printed to 0.1
constexpr double kHalfUnitPower = 5.0;   // W, printed to 0.01 kW
constexpr double kRoundingSlack = 1e-9;  // keep exact halves inside

void expectRowReproduced(const Table1Row& printed,
                         const Table1Check& computed) {
  EXPECT_NEAR(computed.Mc_Nm, printed.Mc_Nm, kHalfUnitMc + kRoundingSlack);
  EXPECT_NEAR(computed.omega_radps, printed.omega_radps,
              kHalfUnitOmega + kRoundingSlack);
  EXPECT_NEAR(computed.power_W, printed.power_W,
              kHalfUnitPower + kRoundingSlack);
}

Table1Row typedRow(double kw, const char* label, double tv, double Mc, double w,
                   double N, double Mzh) {
  return Table1Row{kw, label, tv, Mc, w, N, Mzh};
}

TEST(BurrMillOracleTest, PrintedTable1AndParametersHoldThePaperValues) {
  const std::array<Table1Row, 6> paper{{
      typedRow(5.5, "idle", 1.12, 16.2, 154.6, 2500.0, 0.0),
      typedRow(5.5, "50-70 kg/h", 1.10, 18.1, 154.3, 2790.0, 5.93),
      typedRow(5.5, "130-150 kg/h", 0.60, 29.8, 152.5, 4550.0, 42.43),
      typedRow(3.2, "idle", 1.20, 13.9, 152.8, 2120.0, 0.0),
      typedRow(3.2, "50-70 kg/h", 1.10, 15.1, 152.4, 2300.0, 3.74),
      typedRow(3.2, "130-150 kg/h", 0.60, 27.0, 148.7, 4020.0, 40.91),
  }};
  const auto& table = getPrintedTable1();
  for (std::size_t i = 0; i < paper.size(); ++i) {
    EXPECT_EQ(table[i].motorPowerKW, paper[i].motorPowerKW);
    EXPECT_EQ(table[i].feedLabel, paper[i].feedLabel);
    EXPECT_EQ(table[i].runoutTime_s, paper[i].runoutTime_s);
    EXPECT_EQ(table[i].Mc_Nm, paper[i].Mc_Nm);
    EXPECT_EQ(table[i].omega_radps, paper[i].omega_radps);
    EXPECT_EQ(table[i].power_W, paper[i].power_W);
    EXPECT_EQ(table[i].Mzh_Nm, paper[i].Mzh_Nm);
  }
  const PrintedMillParameters& mill = getPrintedMillParameters();
  EXPECT_EQ(mill.J2, kJ2);
  EXPECT_EQ(mill.c, kC);
  EXPECT_EQ(mill.beltRatio, kBeltRatio);
  EXPECT_EQ(mill.synchronousSpeed, kOmegaC);
  const PrintedMotor& m55 = findPrintedMotor(5.5);
  EXPECT_EQ(m55.J1, kJ1Motor55);
  EXPECT_EQ(m55.M00, kM00Motor55);
  EXPECT_EQ(m55.b0, kB0Motor55);
  EXPECT_EQ(m55.ratedTorque, 36.3);
  EXPECT_EQ(m55.ratedSpeed, 151.4);
  const PrintedMotor& m32 = findPrintedMotor(3.2);
  EXPECT_EQ(m32.J1, kJ1Motor32);
  EXPECT_EQ(m32.M00, kM00Motor32);
  EXPECT_EQ(m32.b0, kB0Motor32);
  EXPECT_EQ(m32.ratedTorque, 21.3);
  EXPECT_EQ(m32.ratedSpeed, 150.5);
}

TEST(BurrMillOracleTest,
     Eq14WithPrintedRunoutTimesReproducesFiveOfSixTable1Columns) {
  const auto& table = getPrintedTable1();
  for (std::size_t i : {0u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE(std::to_string(table[i].motorPowerKW) + " kW " +
                 std::string(table[i].feedLabel));
    expectRowReproduced(table[i], computeTable1Row(table[i]));
  }
}

TEST(BurrMillOracleTest,
     Table1Column55kWMediumFeedFollowsFrom1p00sNotPrinted1p10s) {
  // [T] With the printed 1.10 s, (14) gives 1010/(1 + 6.428*1.10/0.11731) =
  // 16.48 N*m, 1.6 N*m below the printed 18.1 -- far outside even the t_v
  // rounding band (|dMc/dt_v| * 0.005 s = Mc^2 b0/(M00 J) * 0.005 = 0.09).
  Table1Row row = getPrintedTable1()[1];
  ASSERT_EQ(row.runoutTime_s, 1.10);
  const Table1Check asPrinted = computeTable1Row(row);
  EXPECT_NEAR(asPrinted.Mc_Nm, 16.48, 0.01);
  const double tvBand = row.Mc_Nm * row.Mc_Nm * kB0Motor55 /
                        (kM00Motor55 * (kJ1Motor55 + kJ2)) * 0.005;
  EXPECT_GT(std::abs(asPrinted.Mc_Nm - row.Mc_Nm),
            10.0 * (kHalfUnitMc + tvBand));

  row.runoutTime_s = 1.00;
  expectRowReproduced(row, computeTable1Row(row));

  // 1.00 s is the only t_v on the printed 0.01 s grid that yields 18.1 N*m.
  int matches = 0;
  for (int centiseconds = 60; centiseconds <= 120; ++centiseconds) {
    row.runoutTime_s = centiseconds / 100.0;
    if (std::abs(computeTable1Row(row).Mc_Nm - 18.1) <= kHalfUnitMc) ++matches;
  }
  EXPECT_EQ(matches, 1);
}

TEST(BurrMillOracleTest,
     PrintedMillstoneTorqueUsesRoundedMcDifferencesExceptOneCell) {
  // The paper forms M_zh = (Mc - Mc_idle) u_p from the ROUNDED Mc column:
  // 1.9*3.12 = 5.928 -> 5.93, 13.6*3.12 = 42.432 -> 42.43, 1.2*3.12 = 3.744
  // -> 3.74. The 3.2 kW high-feed cell breaks that rule: 13.1*3.12 = 40.872
  // would print 40.87, the unrounded (27.0174 - 13.8793)*3.12 = 40.99 would
  // print 40.99, yet 40.91 is printed [T: arithmetic slip in the paper].
  const auto& table = getPrintedTable1();
  auto roundedProduct = [&](std::size_t row, std::size_t idle) {
    return std::round((table[row].Mc_Nm - table[idle].Mc_Nm) * kBeltRatio *
                      100.0) /
           100.0;
  };
  EXPECT_DOUBLE_EQ(roundedProduct(1, 0), table[1].Mzh_Nm);
  EXPECT_DOUBLE_EQ(roundedProduct(2, 0), table[2].Mzh_Nm);
  EXPECT_DOUBLE_EQ(roundedProduct(4, 3), table[4].Mzh_Nm);
  EXPECT_NEAR(roundedProduct(5, 3), 40.87, 1e-9);
  EXPECT_GT(std::abs(roundedProduct(5, 3) - table[5].Mzh_Nm), 0.03);

  // With unrounded Mc (and t_v = 1.00 s for the misprinted column), every
  // loaded column lies within the rounding of two Mc values, 2*0.05*3.12.
  const double band = 2.0 * kHalfUnitMc * kBeltRatio + 0.005;
  for (std::size_t i : {1u, 2u, 4u, 5u}) {
    Table1Row row = table[i];
    if (i == 1) row.runoutTime_s = 1.00;
    EXPECT_NEAR(computeTable1Row(row).Mzh_Nm, table[i].Mzh_Nm, band)
        << "row " << i;
  }
  EXPECT_EQ(computeTable1Row(table[0]).Mzh_Nm, 0.0);
  EXPECT_EQ(computeTable1Row(table[3]).Mzh_Nm, 0.0);
}

TEST(BurrMillOracleTest, ExplicitTable1OverloadMatchesPrintedDataOverload) {
  const Table1Row& row = getPrintedTable1()[5];
  const Table1Check viaData = computeTable1Row(row);
  const Table1Check explicitArgs = computeTable1Row(
      row, MotorLinearBranch::fromCoefficients(kM00Motor32, kB0Motor32),
      kJ1Motor32 + kJ2, 1.20, kBeltRatio);
  EXPECT_EQ(viaData.Mc_Nm, explicitArgs.Mc_Nm);
  EXPECT_EQ(viaData.omega_radps, explicitArgs.omega_radps);
  EXPECT_EQ(viaData.power_W, explicitArgs.power_W);
  EXPECT_EQ(viaData.Mzh_Nm, explicitArgs.Mzh_Nm);
}

// --- Eq (15), (16)
// -------------------------------------------------------------

TEST(BurrMillOracleTest, PowerIsTorqueTimesSpeed) {
  EXPECT_DOUBLE_EQ(calcResistancePower(16.2, 154.6), 16.2 * 154.6);
}

TEST(BurrMillOracleTest, EmpiricalMillstoneTorqueUsesKgPerMinute) {
  // q = 1 kg/min = 1/60 kg/s gives a*1 = 4.8 N*m: the paper's mean of the
  // medium-feed torques (3.74 and 5.93 N*m). q = 140 kg/h = 7/3 kg/min gives
  // 4.8*(7/3)^2.5 = 4.8*8.3166 = 39.92 N*m, near the 41-42 N*m measured.
  EXPECT_NEAR(calcMillstoneTorqueEmpirical(1.0 / 60.0), 4.8, 1e-12);
  EXPECT_NEAR(calcMillstoneTorqueEmpirical(140.0 / 3600.0), 39.92, 0.005);
  EXPECT_EQ(calcMillstoneTorqueEmpirical(0.0), 0.0);
  EXPECT_NEAR(calcMillstoneTorque(18.1, 16.2, kBeltRatio), 1.9 * 3.12, 1e-12);
}

// --- Bad parameters
// --------------------------------------------------------------

TEST(BurrMillOracleTest, BadParametersThrowInvalidArgumentNamingTheParameter) {
  const TwoMassDrive good = paperDrive55(0.1);
  auto withField = [&](double TwoMassDrive::*field, double value) {
    TwoMassDrive d = good;
    d.*field = value;
    return d;
  };
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(withField(&TwoMassDrive::J1, 0.0), 1.0, 1.0); },
      "J1");
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(withField(&TwoMassDrive::J2, kNaN), 1.0, 1.0); },
      "J2");
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(withField(&TwoMassDrive::c, -537.0), 1.0, 1.0); },
      "c");
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(withField(&TwoMassDrive::b, -0.1), 1.0, 1.0); },
      "b");
  // Critical damping for the 5.5 kW drive: 2 sqrt(537*0.01597) = 5.857.
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(withField(&TwoMassDrive::b, 5.86), 1.0, 1.0); },
      "b");
  expectInvalidArgumentNaming([&] { TwoMassCoastDown(good, -1.0, 1.0); }, "Mc");
  expectInvalidArgumentNaming([&] { TwoMassCoastDown(good, 1.0, -1.0); },
                              "omegaY");
  const TwoMassCoastDown oracle(good, 16.2, 154.6);
  expectInvalidArgumentNaming([&] { oracle.calcMillstoneSpeed(-1e-3); }, "t");
  expectInvalidArgumentNaming(
      [&] { TwoMassCoastDown(good, 0.0, 1.0).calcFirstStopTime(); }, "Mc");
  expectInvalidArgumentNaming(
      [&] { MotorLinearBranch::fromNameplate(36.3, 157.08, 157.08); },
      "ratedSpeed");
  expectInvalidArgumentNaming(
      [&] { MotorLinearBranch::fromNameplate(0.0, 151.4, 157.08); },
      "ratedTorque");
  expectInvalidArgumentNaming(
      [&] { MotorLinearBranch::fromCoefficients(1010.0, 0.0); }, "b0");
  expectInvalidArgumentNaming(
      [&] { MotorLinearBranch::fromCoefficients(-1.0, 6.4); }, "M00");
  expectInvalidArgumentNaming([&] { printedMotor55().calcSteadySpeed(1010.0); },
                              "Mc");
  expectInvalidArgumentNaming(
      [&] { identifyResistanceMeanLine(printedMotor55(), 0.117, 0.0); },
      "runoutTime");
  expectInvalidArgumentNaming(
      [&] { identifyResistanceMeanLine(printedMotor55(), -0.117, 1.0); },
      "totalInertia");
  expectInvalidArgumentNaming(
      [&] { identifyResistanceFirstStop(printedMotor55(), good, -1.0); },
      "runoutTime");
  expectInvalidArgumentNaming([&] { calcMillstoneTorqueEmpirical(-0.01); },
                              "feedRate");
  expectInvalidArgumentNaming([&] { calcMillstoneTorque(18.1, 16.2, 0.0); },
                              "beltRatio");
  expectInvalidArgumentNaming([&] { findPrintedMotor(4.0); }, "motorPowerKW");
}

}  // namespace
}  // namespace milldyn::oracles
