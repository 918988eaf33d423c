// Tests of the seed-001 oracle (horizontal bead mill rotor) on its own: every
// expected value is a hand calculation, a textbook closed form for a special
// case (Roark / AISC beam tables, Schlichting's disc coefficients), or the
// text of the paper (the ranges quoted for eq 2).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "validation/oracles/BeadMillOracle.h"

namespace milldyn::oracles {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Closed forms evaluated two ways differ only by rounding.
constexpr double kRoundoff = 1e-12;

// ---------------------------------------------------------------- disc drag

TEST(BeadMillDrag, LaminarPowerByHand) {
    // ρ = 1000, ν = 1e-6, ω = 100, r = 0.1: N = 0.616π·1000·1e4·1e-4·√(1e-4) = 6.16π W per disc.
    EXPECT_NEAR(beadMillLaminarPower(1000, 1e-6, 100, 0.1, 1), 6.16 * kPi, 6.16 * kPi * kRoundoff);
    EXPECT_NEAR(beadMillLaminarPower(1000, 1e-6, 100, 0.1, 5), 5 * 6.16 * kPi, 30.8 * kPi * kRoundoff);
}

TEST(BeadMillDrag, LaminarMatchesSchlichtingMomentCoefficient) {
    // Schlichting: disc wetted on both sides, M = C_M·ρω²r⁵/2, C_M = 3.87/√Re
    // (3.87 is 1.232π rounded to three figures).
    const double rho = 1800, nu = 5e-5, omega = 150, r = 0.08;
    const double re = beadMillDiscReynolds(omega, r, nu);
    EXPECT_NEAR(re, omega * r * r / nu, re * kRoundoff);
    const double M = beadMillLaminarPower(rho, nu, omega, r, 1) / omega;
    const double cm = 2 * M / (rho * omega * omega * std::pow(r, 5));
    EXPECT_NEAR(cm * std::sqrt(re), 3.87, 0.001);
}

TEST(BeadMillDrag, TurbulentPowerByHand) {
    // Re = 100·0.01/1e-6 = 1e6, Re^-0.2 = 10^-1.2; M = 0.073·1000·1e4·1e-5·10^-1.2.
    const double M = 0.073 * 100 * std::pow(10.0, -1.2);
    EXPECT_NEAR(beadMillTurbulentPower(1000, 1e-6, 100, 0.1, 1), M * 100, M * 100 * kRoundoff);
    // Schlichting's turbulent C_M = 0.146·Re^-0.2 for both faces.
    const double cm = 2 * M / (1000 * 1e4 * 1e-5);
    EXPECT_NEAR(cm, 0.146 * std::pow(1e6, -0.2), 1e-12);
}

TEST(BeadMillDrag, RejectsBadInput) {
    EXPECT_THROW(beadMillLaminarPower(0, 1e-6, 100, 0.1, 1), std::invalid_argument);
    EXPECT_THROW(beadMillLaminarPower(1000, -1, 100, 0.1, 1), std::invalid_argument);
    EXPECT_THROW(beadMillTurbulentPower(1000, 1e-6, 0, 0.1, 1), std::invalid_argument);
    EXPECT_THROW(beadMillTurbulentPower(1000, 1e-6, 100, 0.1, 0), std::invalid_argument);
    EXPECT_THROW(beadMillDiscReynolds(100, std::nan(""), 1e-6), std::invalid_argument);
}

// ------------------------------------------------------------------ beam

BeadMillShaft plainShaft(double Lp, double a) {
    BeadMillShaft s;
    s.youngsModulus = 2.1e11;
    s.diameter = 0.02;
    s.density = 0;
    s.span = Lp;
    s.overhang = a;
    return s;
}

TEST(BeadMillBeam, TipLoadOnOverhang) {
    // Roark: overhang a, span l, load P at the free end:
    //   w_end = P a²(l + a)/(3EI); at x1 from B on the overhang: P x1 (2al + 3a x1 − x1²)/(6EI);
    //   in the span the shaft rises: max upward P a l²/(9√3 EI) at l/√3 from A.
    const double Lp = 0.2, a = 0.3, P = 100;
    BeadMillBeam beam(plainShaft(Lp, a));
    const double EI = 2.1e11 * kPi * std::pow(0.02, 4) / 64;
    EXPECT_NEAR(beam.getSecondMoment() * 2.1e11, EI, EI * kRoundoff);
    const std::vector<BeadMillPointLoad> tip = {{Lp + a, P}};
    const double wEnd = P * a * a * (Lp + a) / (3 * EI);
    EXPECT_NEAR(beam.calcDeflection(Lp + a, tip), wEnd, wEnd * kRoundoff);
    const double x1 = 0.04;
    const double wSeal = P * x1 * (2 * a * Lp + 3 * a * x1 - x1 * x1) / (6 * EI);
    EXPECT_NEAR(beam.calcDeflection(Lp + x1, tip), wSeal, wSeal * kRoundoff);
    const double wUp = -P * a * Lp * Lp / (9 * std::sqrt(3.0) * EI);
    EXPECT_NEAR(beam.calcDeflection(Lp / std::sqrt(3.0), tip), wUp, std::abs(wUp) * kRoundoff);
    EXPECT_NEAR(beam.calcDeflection(0, tip), 0, 1e-18);
    EXPECT_NEAR(beam.calcDeflection(Lp, tip), 0, 1e-18);
}

TEST(BeadMillBeam, LoadInSpanTiltsOverhangUp) {
    // Central load P in the span: midspan P l³/(48EI); slope at B P l²/(16EI),
    // the overhang (straight) rises by that slope times x1.
    const double Lp = 0.25, a = 0.15, P = 250;
    BeadMillBeam beam(plainShaft(Lp, a));
    const double EI = 2.1e11 * beam.getSecondMoment();
    const std::vector<BeadMillPointLoad> mid = {{Lp / 2, P}};
    const double wMid = P * std::pow(Lp, 3) / (48 * EI);
    EXPECT_NEAR(beam.calcDeflection(Lp / 2, mid), wMid, wMid * kRoundoff);
    const double wEnd = -P * Lp * Lp / (16 * EI) * a;
    EXPECT_NEAR(beam.calcDeflection(Lp + a, mid), wEnd, std::abs(wEnd) * kRoundoff);
}

TEST(BeadMillBeam, UniformLoadWholeShaft) {
    // AISC case "beam overhanging one support, uniformly distributed load":
    // free end w a (4a² l − l³ + 3a³)/(24EI).
    const double Lp = 0.3, a = 0.2, q = 400;
    BeadMillBeam beam(plainShaft(Lp, a));
    const double EI = 2.1e11 * beam.getSecondMoment();
    const double wEnd = q * a * (4 * a * a * Lp - std::pow(Lp, 3) + 3 * std::pow(a, 3)) / (24 * EI);
    EXPECT_NEAR(beam.calcDeflection(Lp + a, {}, q), wEnd, std::abs(wEnd) * kRoundoff);
    // Without an overhang: simply supported, 5 q l⁴/(384 EI) at midspan.
    BeadMillBeam ss(plainShaft(Lp, 0));
    const double wMid = 5 * q * std::pow(Lp, 4) / (384 * EI);
    EXPECT_NEAR(ss.calcDeflection(Lp / 2, {}, q), wMid, wMid * kRoundoff);
}

TEST(BeadMillBeam, BearingSpringsAddRigidBodyMotion) {
    // Tip load P: reactions R_A = −P a/l (down), R_B = P (l + a)/l. A rigid
    // shaft on springs k then moves its end by P (a² + (l + a)²)/(l² k).
    const double Lp = 0.2, a = 0.25, P = 80, k = 2e7;
    BeadMillShaft s = plainShaft(Lp, a);
    s.stiffnessA = s.stiffnessB = k;
    BeadMillBeam soft(s), rigid(plainShaft(Lp, a));
    const std::vector<BeadMillPointLoad> tip = {{Lp + a, P}};
    const double rigidBody = P * (a * a + (Lp + a) * (Lp + a)) / (Lp * Lp * k);
    const double diff = soft.calcDeflection(Lp + a, tip) - rigid.calcDeflection(Lp + a, tip);
    EXPECT_NEAR(diff, rigidBody, rigidBody * 1e-11);
    // Bearing A rises by |R_A|/k.
    EXPECT_NEAR(soft.calcDeflection(0, tip), -P * a / Lp / k, P * a / Lp / k * kRoundoff);
}

TEST(BeadMillBeam, FiniteElementStaticAgreesWithMohrIntegral) {
    // Hermite elements are exact at the nodes for uniform EI; the rigid
    // supports are a penalty 1e8 above the element stiffness scale.
    BeadMillShaft s = plainShaft(0.2, 0.28);
    s.density = 7850;
    s.stiffnessB = 5e7;
    for (int i = 0; i < 5; ++i) s.discs.push_back({0.2 + 0.08 + 0.04 * i, 0.6, 4e-4});
    BeadMillBeam beam(s);
    for (double x : {0.28, 0.36, 0.48, 0.1}) {
        const double mohr = beam.calcGravityDeflection(x, 9.81);
        EXPECT_NEAR(beam.calcFiniteElementGravityDeflection(x, 9.81, 48), mohr, std::abs(mohr) * 1e-6) << x;
    }
}

TEST(BeadMillCriticalSpeed, SingleMassOnMasslessOverhangIsExactForAllThree) {
    // ω² = k/m with k = 3EI/(a²(l + a)) at the free end.
    const double Lp = 0.2, a = 0.25, m = 3;
    BeadMillShaft s = plainShaft(Lp, a);
    s.discs = {{Lp + a, m, 0}};
    BeadMillBeam beam(s);
    const double EI = 2.1e11 * beam.getSecondMoment();
    const double omega = std::sqrt(3 * EI / (a * a * (Lp + a)) / m);
    EXPECT_NEAR(beam.calcRayleighCriticalSpeed(false), omega, omega * 1e-12);
    EXPECT_NEAR(beam.calcRayleighCriticalSpeed(true), omega, omega * 1e-12);
    EXPECT_NEAR(beam.calcDunkerleyCriticalSpeed(), omega, omega * 1e-12);
    EXPECT_NEAR(beam.calcFiniteElementFrequencies(8, false, false).at(0), omega, omega * 1e-9);
}

TEST(BeadMillCriticalSpeed, SimplySupportedBareShaftTextbookValues) {
    // Uniform simply supported beam, c = √(EI/(μL⁴)): exact π²·c; Rayleigh
    // with the self-weight curve √(3024/31)·c; Dunkerley ∫ μ α(x,x) dx = μL⁴/(90EI),
    // i.e. √90·c.
    BeadMillShaft s = plainShaft(0.5, 0);
    s.density = 7850;
    BeadMillBeam beam(s);
    const double c = std::sqrt(2.1e11 * beam.getSecondMoment() / (beam.getMassPerLength() * std::pow(0.5, 4)));
    EXPECT_NEAR(beam.calcFiniteElementFrequencies(200, false, false).at(0), kPi * kPi * c, kPi * kPi * c * 1e-8);
    EXPECT_NEAR(beam.calcRayleighCriticalSpeed(false), std::sqrt(3024.0 / 31) * c, c * 1e-10);
    // Dunkerley's shaft lumps: midpoint rule, error O(1/n²).
    EXPECT_NEAR(beam.calcDunkerleyCriticalSpeed(2000), std::sqrt(90.0) * c, c * 1e-5);
    // Second mode, 4π²·c.
    const auto two = beam.calcFiniteElementFrequencies(200, false, false, 2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_NEAR(two[1], 4 * kPi * kPi * c, 4 * kPi * kPi * c * 1e-6);
}

BeadMillShaft fiveDiscRotor(double Lp) {
    BeadMillShaft s;
    s.youngsModulus = 2.1e11;
    s.diameter = beadMillShaftDiameter(5, 0.1, Lp);
    s.density = 7850;
    s.span = Lp;
    s.overhang = 0.26;
    for (int i = 0; i < 5; ++i) s.discs.push_back({Lp + 0.08 + 0.04 * i, 0.6, 3.9e-4});
    return s;
}

TEST(BeadMillCriticalSpeed, BoundsOrderOnTheFiveDiscRotor) {
    // Without diametral inertia: Dunkerley <= exact <= Rayleigh (either trial).
    for (double Lp : {0.15, 0.267, 0.5}) {
        BeadMillBeam beam(fiveDiscRotor(Lp));
        const double fe = beam.calcFiniteElementFrequencies(200, false, false).at(0);
        EXPECT_LE(beam.calcDunkerleyCriticalSpeed(), fe) << Lp;
        EXPECT_GE(beam.calcRayleighCriticalSpeed(true) * (1 + 1e-9), fe) << Lp;
        EXPECT_GE(beam.calcRayleighCriticalSpeed(false) * (1 + 1e-9), fe) << Lp;
        // Disc and shaft rotary inertia only lower the frequency.
        EXPECT_LT(beam.calcFiniteElementFrequencies(200, true, true).at(0), fe) << Lp;
    }
}

TEST(BeadMillCriticalSpeed, FiniteElementsConverge) {
    BeadMillBeam beam(fiveDiscRotor(0.2));
    const double fine = beam.calcFiniteElementFrequencies(400, true, true).at(0);
    EXPECT_NEAR(beam.calcFiniteElementFrequencies(40, true, true).at(0), fine, fine * 1e-6);
}

TEST(BeadMillWhirl, SingleMassWithoutInertiaIsTheOneDegreeFormula) {
    // Tip mass m with unbalance m·e on a massless overhang, no rotary inertia:
    // y = Ω²·m·e/(k − m·Ω²), k = 3EI/(a²(l + a)); critical √(k/m).
    const double Lp = 0.2, a = 0.25, m = 3, me = 3e-5, W = 150;
    BeadMillShaft s = plainShaft(Lp, a);
    s.discs = {{Lp + a, m, 0, 0, me}};
    BeadMillBeam beam(s);
    const double k = 3 * 2.1e11 * beam.getSecondMoment() / (a * a * (Lp + a));
    const double y = W * W * me / (k - m * W * W);
    EXPECT_NEAR(beam.calcSynchronousWhirl(Lp + a, W, 8), y, y * 1e-9);
    EXPECT_NEAR(beam.calcForwardCriticalSpeed(8), std::sqrt(k / m), std::sqrt(k / m) * 1e-9);
    EXPECT_NEAR(beam.calcSynchronousWhirl(Lp + a, 0, 8), 0, 1e-18);
}

TEST(BeadMillWhirl, ThinDiscGyroscopicMomentByHand) {
    // A disc (m, I_d, I_p) at the tip of a massless overhang. Tip flexibility
    // (Roark): w/P = a²(l + a)/(3EI), θ/P = w/M = a(2l + 3a)/(6EI),
    // θ/M = (l + 3a)/(3EI). Forward synchronous whirl: the disc's moment is
    // (I_p − I_d)Ω²θ against the tilt, so with K_t the inverse flexibility
    //   det(K_t − Ω²·diag(m, I_d − I_p)) = 0     (critical),
    //   (K_t − Ω²·diag(m, I_d − I_p))·[w, θ] = Ω²·[m·e, 0]   (whirl).
    const double Lp = 0.2, a = 0.25, m = 3, Id = 0.01, Ip = 0.02, me = 3e-5;
    BeadMillShaft s = plainShaft(Lp, a);
    s.discs = {{Lp + a, m, Id, Ip, me}};
    BeadMillBeam beam(s);
    const double EI = 2.1e11 * beam.getSecondMoment();
    const double fww = a * a * (Lp + a) / (3 * EI), fwt = a * (2 * Lp + 3 * a) / (6 * EI),
                 ftt = (Lp + 3 * a) / (3 * EI);
    const double det = fww * ftt - fwt * fwt;
    const double kww = ftt / det, kwt = -fwt / det, ktt = fww / det;
    const double J = Id - Ip;
    // det = (kww − Ω²m)(ktt − Ω²J) − kwt² = 0: quadratic in x = Ω².
    const double qa = m * J, qb = -(kww * J + ktt * m), qc = kww * ktt - kwt * kwt;
    const double disc = std::sqrt(qb * qb - 4 * qa * qc);
    double x1 = (-qb + disc) / (2 * qa), x2 = (-qb - disc) / (2 * qa);
    const double critical = std::sqrt(std::max(x1, x2) > 0 && std::min(x1, x2) > 0 ? std::min(x1, x2)
                                                                                   : std::max(x1, x2));
    EXPECT_NEAR(beam.calcForwardCriticalSpeed(8), critical, critical * 1e-9);
    // Stiffer than without the disc's rotation (J = 0: √(k/m)).
    EXPECT_GT(critical, std::sqrt(3 * EI / (a * a * (Lp + a)) / m));
    const double W = 0.6 * critical;
    const double A = kww - W * W * m, B = kwt, C = ktt - W * W * J;
    const double w = W * W * me * C / (A * C - B * B);
    EXPECT_NEAR(beam.calcSynchronousWhirl(Lp + a, W, 8), w, std::abs(w) * 1e-9);
}

TEST(BeadMillBeam, RejectsBadShafts) {
    BeadMillShaft s = plainShaft(0.2, 0.1);
    s.diameter = 0;
    EXPECT_THROW(BeadMillBeam{s}, std::invalid_argument);
    s = plainShaft(0.2, 0.1);
    s.discs = {{0.5, 1, 0}};
    EXPECT_THROW(BeadMillBeam{s}, std::invalid_argument);
    s = plainShaft(0.2, 0.1);
    s.stiffnessA = 0;
    EXPECT_THROW(BeadMillBeam{s}, std::invalid_argument);
    BeadMillBeam ok(plainShaft(0.2, 0.1));
    EXPECT_THROW(ok.calcDeflection(0.4, {}), std::invalid_argument);
    EXPECT_THROW(ok.calcRayleighCriticalSpeed(true), std::invalid_argument);  // no mass
}

// -------------------------------------------------------- eq (2), Table 1

// The text's statements, in mm, printed to the half millimetre: a value
// counts as inside a range when it is within 0.25 mm of it.
constexpr double kHalfMmRounding = 0.25;
const double kSpans[] = {0.15, 0.2, 0.267, 0.3, 0.35, 0.4, 0.45, 0.5};

double dmm(int k, double D, double L, BeadMillTableReading r = BeadMillTableReading::Resolved) {
    return 1e3 * beadMillShaftDiameter(k, D, L, r);
}

TEST(BeadMillTable, ResolvedReadingGivesTheQuotedDiameterRanges) {
    // "5 discs of 0.1 m: 16.5 to 21.5 mm; 8 discs of 0.3 m: 34.5 to 40.5 mm"
    // over 0.15 <= L_p <= 0.5 (d grows with L_p in every block).
    EXPECT_NEAR(dmm(5, 0.1, 0.15), 16.5, kHalfMmRounding);
    EXPECT_NEAR(dmm(5, 0.1, 0.5), 21.5, kHalfMmRounding);
    EXPECT_NEAR(dmm(8, 0.3, 0.15), 34.5, kHalfMmRounding);
    EXPECT_NEAR(dmm(8, 0.3, 0.5), 40.5, kHalfMmRounding);
    for (int k = 5; k <= 8; ++k)
        for (double D : {0.1, 0.17, 0.23, 0.3})
            for (int i = 0; i + 1 < 8; ++i) EXPECT_LT(dmm(k, D, kSpans[i]), dmm(k, D, kSpans[i + 1]));
}

TEST(BeadMillTable, LiteralReadingContradictsTheText) {
    using R = BeadMillTableReading;
    // As printed, 5 discs of 0.1 m give 23.5..28.9 mm, 8 of 0.3 m 25.0..31.0 mm,
    // and bigger discs give a thinner shaft.
    EXPECT_GT(dmm(5, 0.1, 0.15, R::Literal), 16.5 + 5);
    EXPECT_LT(dmm(8, 0.3, 0.5, R::Literal), 40.5 - 5);
    EXPECT_LT(dmm(5, 0.3, 0.3, R::Literal), dmm(5, 0.1, 0.3, R::Literal));
    // The two readings are the same numbers, columns mirrored (k = 5 and 8).
    EXPECT_DOUBLE_EQ(dmm(5, 0.1, 0.3, R::Literal), dmm(5, 0.3, 0.3, R::Resolved));
    EXPECT_DOUBLE_EQ(dmm(8, 0.17, 0.3, R::Literal), dmm(8, 0.23, 0.3, R::Resolved));
}

TEST(BeadMillTable, DiscDiameterEffectSixToEightMillimetres) {
    // "0.1 → 0.3 m discs: +6..8 mm". Holds for k = 5 (6.8..7.5) and k = 6
    // (7.8..8.2); k = 7 (8.6..8.9) and k = 8 (9.4) exceed it (docs/oracles/bead_mill.md).
    for (double L : kSpans) {
        for (int k : {5, 6}) {
            const double inc = dmm(k, 0.3, L) - dmm(k, 0.1, L);
            EXPECT_GE(inc, 6 - kHalfMmRounding) << k << " " << L;
            EXPECT_LE(inc, 8 + kHalfMmRounding) << k << " " << L;
        }
        EXPECT_GT(dmm(8, 0.3, L) - dmm(8, 0.1, L), 8 + kHalfMmRounding);
    }
}

TEST(BeadMillTable, DiscCountEffectEightToTenMillimetres) {
    // "5 → 8 discs: +8..10 mm". Holds for D = 0.1 (8.4..9.5) and 0.17 m
    // (9.0..9.7); 0.23 m reaches 10.5 and 0.3 m 11.0..11.5.
    for (double L : kSpans) {
        for (double D : {0.1, 0.17}) {
            const double inc = dmm(8, D, L) - dmm(5, D, L);
            EXPECT_GE(inc, 8 - kHalfMmRounding) << D << " " << L;
            EXPECT_LE(inc, 10 + kHalfMmRounding) << D << " " << L;
        }
        EXPECT_GT(dmm(8, 0.3, L) - dmm(5, 0.3, L), 10 + kHalfMmRounding);
    }
}

TEST(BeadMillTable, SpanEffects) {
    // "L_p 0.15 → 0.267 m: +2.5..4 mm; 0.267 → 0.5 m: +2..2.5 mm" — every
    // block and column: 2.9..3.5 and 1.9..2.5 mm.
    for (int k = 5; k <= 8; ++k)
        for (double D : {0.1, 0.17, 0.23, 0.3}) {
            const double first = dmm(k, D, 0.267) - dmm(k, D, 0.15);
            const double second = dmm(k, D, 0.5) - dmm(k, D, 0.267);
            EXPECT_GE(first, 2.5 - kHalfMmRounding);
            EXPECT_LE(first, 4 + kHalfMmRounding);
            EXPECT_GE(second, 2 - kHalfMmRounding);
            EXPECT_LE(second, 2.5 + kHalfMmRounding);
        }
}

TEST(BeadMillTable, RejectsValuesOutsideTheTable) {
    EXPECT_THROW(beadMillShaftDiameter(4, 0.1, 0.2), std::invalid_argument);
    EXPECT_THROW(beadMillShaftDiameter(5, 0.2, 0.2), std::invalid_argument);
    EXPECT_THROW(beadMillShaftDiameter(5, 0.1, 0.6), std::invalid_argument);
    EXPECT_THROW(beadMillShaftDiameter(5, 0.1, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace milldyn::oracles
