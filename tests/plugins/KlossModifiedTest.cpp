// Tests of the modified Kloss law with a stated starting torque
// (plugins/motors/TorqueSpeedCurve.h, law kloss_modified). Expected values
// come from the nameplate data themselves (M(sn) = Mn, M(1) = Mst, max Mk)
// or from the closed forms of validation/oracles/StartOracle.h, which solve
// for sk and a by a different elimination than the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"
#include "plugins/motors/TorqueSpeedCurve.h"
#include "tests/driver/ReaderTestHelpers.h"
#include "validation/oracles/StartOracle.h"

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRpm = 2 * kPi / 60;

// The start bench's 15 kW 4-pole motor: sn = 0.02, λ = 2.5.
TorqueSpeedCurveParams bench(double startingRatio) {
    TorqueSpeedCurveParams p;
    p.law = TorqueSpeedCurveParams::Law::KlossModified;
    p.ratedTorque = 97.4;
    p.ratedSpeed = 1470 * kRpm;
    p.synchronousSpeed = 1500 * kRpm;
    p.breakdownRatio = 2.5;
    p.lockedRotorRatio = startingRatio;
    return p;
}

TEST(KlossModified, PassesThroughRatedAndStartingPointsWithBreakdownAsMaximum) {
    for (double mu : {0.6, 0.8, 1.0, 1.15}) {
        const TorqueSpeedCurveParams p = bench(mu);
        const TorqueSpeedCurve c(p);
        EXPECT_NEAR(c.torque(p.ratedSpeed), p.ratedTorque, 1e-12 * p.ratedTorque) << mu;
        EXPECT_NEAR(c.torque(0), mu * p.ratedTorque, 1e-12 * p.ratedTorque) << mu;
        // The maximum over 0 <= ω <= ωc on a grid of 2e5 points: at most
        // λ·Mn, and within the grid's resolution of it (M is flat at sk:
        // a step h in s costs Mk·(h/sk)²/… < 1e-6 here).
        double best = 0;
        for (int i = 0; i <= 200000; ++i) best = std::max(best, c.torque(p.synchronousSpeed * i / 200000.0));
        EXPECT_LE(best, p.breakdownRatio * p.ratedTorque * (1 + 1e-14)) << mu;
        EXPECT_NEAR(best, p.breakdownRatio * p.ratedTorque, 1e-6 * p.ratedTorque) << mu;
        // The oracle's independent solve and torque formula.
        double sk = 0, a = 0;
        ASSERT_TRUE(oc::modifiedKlossFit(0.02, 2.5, mu, sk, a)) << mu;
        EXPECT_NEAR(c.breakdownSlip(), sk, 1e-9) << mu;
        EXPECT_NEAR(c.asymmetry(), a, 1e-7 * std::max(1.0, a)) << mu;
        EXPECT_GT(a, 0) << mu;
        for (int i = 0; i < 100; ++i) {
            const double w = p.synchronousSpeed * (i + 0.5) / 100;  // skip s = 0
            const double s = (p.synchronousSpeed - w) / p.synchronousSpeed;
            EXPECT_NEAR(c.torque(w), oc::modifiedKlossTorque(s, 2.5 * 97.4, sk, a), 1e-7 * 97.4) << mu << " " << w;
        }
    }
}

TEST(KlossModified, ClassicStartingTorqueGivesZeroAsymmetryAndTheKlossCurve) {
    // Plain Kloss: sk = 0.02·(2.5 + √5.25) = 0.0958258, M(1)/Mn = 2λ/(1/sk + sk) = 0.474769.
    const double sk = oc::klossBreakdownSlip(0.02, 2.5);
    const double mu0 = oc::klossTorque(1.0, 2.5, sk) / 1.0;  // Mk = λ·Mn with Mn = 1
    EXPECT_NEAR(mu0, 0.474769, 1e-6);
    const TorqueSpeedCurve modified(bench(mu0));
    TorqueSpeedCurveParams k = bench(0);
    k.law = TorqueSpeedCurveParams::Law::Kloss;
    const TorqueSpeedCurve kloss(k);
    EXPECT_NEAR(modified.asymmetry(), 0.0, 1e-9);
    for (int i = 0; i <= 300; ++i) {
        const double w = k.synchronousSpeed * i / 300.0;
        EXPECT_NEAR(modified.torque(w), kloss.torque(w), 1e-9 * k.ratedTorque) << w;
    }
}

TEST(KlossModified, DataWithoutASolutionAreRefusedWithTheAttainableRange) {
    // Physical stator resistance keeps q = a·sk below 1: with sn = 0.02 and
    // λ = 2.5 at q → 1, sk = 0.02·(4 + √15) = 0.15746 and
    // μ = 2·2.5·2/(1/sk + sk + 2) = 1.17532: μ = 2 is out of reach.
    try {
        fitModifiedKloss(0.02, 2.5, 2.0);
        FAIL() << "no throw";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("must lie in [0.474769, 1.17532)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(fitModifiedKloss(0.02, 2.5, 0.3), std::invalid_argument);  // below plain Kloss: R1 < 0
    EXPECT_THROW(fitModifiedKloss(0.02, 2.5, 2.6), std::invalid_argument);  // above breakdown
    double sk = 0, a = 0;
    EXPECT_FALSE(oc::modifiedKlossFit(0.02, 2.5, 2.0, sk, a));
}

// A start of a pure inertia (J = 1.5 kg·m², no load) through the transient:
// the time to each sampled slip against the oracle's closed form, itself
// checked against a Simpson quadrature of J·dω/M(ω).
TEST(KlossModified, InertiaStartMatchesTheClosedFormAndItsQuadrature) {
    const double J = 1.5, wc = 1500 * kRpm, Mk = 2.5 * 97.4;
    double sk = 0, a = 0;
    ASSERT_TRUE(oc::modifiedKlossFit(0.02, 2.5, 1.0, sk, a));
    // Quadrature in slip from 1 down to 0.1: t = ∫ J·ωc/M(s) ds.
    const int n = 20000;
    const double s0 = 0.1, h = (1 - s0) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double s = s0 + i * h;
        sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * J * wc / oc::modifiedKlossTorque(s, Mk, sk, a);
    }
    EXPECT_NEAR(oc::modifiedKlossInertiaStartTime(J, wc, Mk, sk, a, s0), sum * h / 3, 1e-10);

    const std::string text = std::string(MILLDYN_SOURCE_DIR) + "/models/start_bench_kloss_modified.yaml";
    const AnalysisResult r = runAnalysis(readModelFile(text, defaultModelReader()));
    int compared = 0;
    for (std::size_t i = 1; i < r.rows.size(); ++i) {
        const double t = r.value(i, "time"), s = (wc - r.value(i, "shaft.speed")) / wc;
        if (s < 0.05) break;
        EXPECT_NEAR(t, oc::modifiedKlossInertiaStartTime(J, wc, Mk, sk, a, s), 1e-6 * t) << t;
        ++compared;
    }
    EXPECT_GT(compared, 20);
    EXPECT_EQ(r.verdict, "completed") << r.verdictText;
}

// Bad input: the bench file with its law lines replaced; one line
// file:line:col: error: key: reason (tests/driver/ReaderTestHelpers.h).
TEST(KlossModified, BadInputGivesOneLocatedLine) {
    std::ifstream in(std::string(MILLDYN_SOURCE_DIR) + "/models/start_bench_kloss_modified.yaml");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string bench = buffer.str();
    const std::string stated = "    law: kloss_modified\n    locked_rotor_ratio: 1.0\n";
    auto errorOf = [&](const std::string& lawLines) {
        return test::readErrorOf("m.yaml", test::replacedIn(bench, stated, lawLines), {});
    };
    test::expectSpecError(errorOf("    law: kloss_modified\n    locked_rotor_ratio: 3\n"), "m.yaml", 21, 25,
                          "motor.locked_rotor_ratio", "starting torque above the breakdown torque (3 >= breakdown ratio 2.5)");
    test::expectSpecError(errorOf("    law: kloss_modified\n    locked_rotor_ratio: 2\n"), "m.yaml", 21, 25,
                          "motor.locked_rotor_ratio", "must lie in [0.474769, 1.17532)");
    test::expectSpecError(errorOf("    law: kloss_modified\n"), "m.yaml", 20, 10, "motor.law",
                          "the kloss_modified law needs locked_rotor_ratio");
    test::expectSpecError(errorOf("    law: kloss\n    locked_rotor_ratio: 1\n"), "m.yaml", 21, 25,
                          "motor.locked_rotor_ratio", "not used with law kloss");
    EXPECT_NO_THROW(test::readText("m.yaml", bench, {}));
}

}  // namespace
}  // namespace milldyn
