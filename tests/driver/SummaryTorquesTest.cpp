// The transient summary never adds torques on different shafts (issue 32:
// a faked vertical roller mill reported one "resistance torque" summed over
// the table and the motor shaft). Two shafts, each with its own load and
// drive: the summary reports each on its shaft, with no sum; loads on one
// shaft are summed under the one name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

namespace milldyn {
namespace {

std::string twoShafts(const std::string& secondLoadBody) {
    return "format_version: 1\n"
           "name: two shafts\n"
           "bodies:\n"
           "  - {name: a, inertia: 1 kg*m^2, joint: {type: pin, parent: ground}, initial_speed: 10 rad/s}\n"
           "  - {name: b, inertia: 4 kg*m^2, joint: {type: pin, parent: ground}, initial_speed: 20 rad/s}\n"
           "elements:\n"
           "  - {type: AppliedTorque, name: drive_a, body: a, torque: 5 N*m}\n"
           "  - {type: AppliedTorque, name: drive_b, body: b, torque: 7 N*m}\n"
           "  - {type: ResistanceTorque, name: load_a, body: a, constant_torque: 3 N*m}\n"
           "  - {type: ResistanceTorque, name: load_b, body: " + secondLoadBody + ", constant_torque: 11 N*m}\n"
           "scenario: {analysis: transient, initial_state: file, end_time: 0.5 s, speed_body: a}\n"
           "integrator: {name: RungeKuttaMerson, accuracy: 1e-9}\n"
           "outputs: {sample_interval: 0.1 s}\n";
}

TEST(SummaryTorques, TorquesOnDifferentShaftsAreReportedEachOnItsShaftNeverAdded) {
    const AnalysisResult r = runAnalysis(readModelText(twoShafts("b"), "two.yaml", defaultModelReader()));
    EXPECT_EQ(r.find("resistance_torque"), nullptr);
    EXPECT_EQ(r.find("drive_torque"), nullptr);
    EXPECT_EQ(r.find("peak_drive_torque"), nullptr);
    ASSERT_NE(r.find("resistance_torque.load_a.torque"), nullptr);
    ASSERT_NE(r.find("resistance_torque.load_b.torque"), nullptr);
    EXPECT_NEAR(r.find("resistance_torque.load_a.torque")->value, 3.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque.load_a.torque")->referredTo, "a");
    EXPECT_NEAR(r.find("resistance_torque.load_b.torque")->value, 11.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque.load_b.torque")->referredTo, "b");
    ASSERT_NE(r.find("drive_torque.drive_b.torque"), nullptr);
    EXPECT_NEAR(r.find("drive_torque.drive_b.torque")->value, 7.0, 1e-12);
    ASSERT_NE(r.find("peak_drive_torque.drive_a.torque"), nullptr);
    EXPECT_NEAR(r.find("peak_drive_torque.drive_a.torque")->value, 5.0, 1e-12);
    // Power adds across shafts: 3·ω_a + 11·ω_b at the end, ω from the
    // torque balances (5 − 3)/1 and (7 − 11)/4 rad/s².
    const double wa = 10 + 2.0 * 0.5, wb = 20 - 1.0 * 0.5;
    EXPECT_NEAR(r.find("power")->value, 3 * wa + 11 * wb, 1e-6);
}

TEST(SummaryTorques, LoadsOnOneShaftAreSummedUnderOneName) {
    const AnalysisResult r = runAnalysis(readModelText(twoShafts("a"), "two.yaml", defaultModelReader()));
    ASSERT_NE(r.find("resistance_torque"), nullptr);
    EXPECT_NEAR(r.find("resistance_torque")->value, 14.0, 1e-9);
    EXPECT_EQ(r.find("resistance_torque")->referredTo, "a");
    EXPECT_EQ(r.find("resistance_torque.load_a.torque"), nullptr);
}

// A shaft turning −z (behind a reversing gear stage) with a constant load, a
// journal and disc drag: every load's NAME.torque is what it takes from the
// shaft, + about +z, so all three are negative and resistance_torque is
// their sum (a journal or drag reported as a magnitude was subtracted:
// the dual-pinion mill's −790 kN·m against −806 kN·m). Closed forms at the
// last sample, with the speed ω < 0 read from the run:
//   constant:  M0·tanh(ω/ωs)                      (ResistanceTorque)
//   journal:   m·g·f·d/2·tanh(ω/ωs)               (JournalFriction, mass on a pin)
//   drag:      negative, its power T·ω = |T·ω|       (DiscDrag; its law is DiscDragTest's)
TEST(SummaryTorques, LossesOnAShaftTurningBackwardsAreSignedAndSummed) {
    const std::string model =
        "format_version: 1\nname: backwards\ngravity: [0, -10 m/s^2, 0]\n"
        "bodies:\n  - {name: drum, mass: 200 kg, inertia: 5 kg*m^2, joint: {type: pin}, initial_speed: -20 rad/s}\n"
        "elements:\n"
        "  - {type: AppliedTorque, name: drive, body: drum, torque: -40 N*m}\n"
        "  - {type: ResistanceTorque, name: load, body: drum, constant_torque: 12 N*m}\n"
        "  - {type: JournalFriction, name: journal, body: drum, friction_coefficient: 0.05, journal_diameter: 100 mm}\n"
        "  - {type: DiscDrag, name: drag, body: drum, disc_diameter: 0.6 m, discs: 2, "
        "medium_density: 1000 kg/m^3, medium_viscosity: 1e-5 m^2/s}\n"
        "scenario: {analysis: transient, initial_state: file, end_time: 0.5 s, speed_body: drum}\n"
        "integrator: {name: RungeKuttaMerson, accuracy: 1e-9}\noutputs: {sample_interval: 0.1 s}\n";
    const AnalysisResult r = runAnalysis(readModelText(model, "backwards.yaml", defaultModelReader()));
    const auto last = [&](const std::string& column) {
        const std::size_t c = r.findColumn(column);
        EXPECT_NE(c, std::string::npos) << column;
        return c == std::string::npos ? NAN : r.rows.back()[c];
    };
    const double w = last("drum.speed");
    ASSERT_LT(w, -1.0) << "the drum should still turn −z";
    const double load = last("load.torque"), journal = last("journal.torque"), drag = last("drag.torque");
    EXPECT_NEAR(load, 12 * std::tanh(w / 0.01), 1e-9);
    EXPECT_NEAR(journal, 200 * 10 * 0.05 * 0.05 * std::tanh(w / 0.01), 1e-9);
    EXPECT_LT(drag, 0);
    // The drag's power is what it absorbs: T·ω > 0 with both negative.
    EXPECT_NEAR(last("drag.power"), drag * w, 1e-9 * std::abs(drag * w));
    ASSERT_NE(r.find("resistance_torque"), nullptr);
    EXPECT_NEAR(r.find("resistance_torque")->value, load + journal + drag, 1e-9 * std::abs(load + journal + drag));
}

// Signed peaks and the reversal (run_max., run_min.): two inertias J1 = 1,
// J2 = 3 kg*m^2 joined by a shaft k = 1e4 N*m/rad, c = 10 N*m*s/rad, a step
// torque T = 100 N*m on J1 and J2 turning 2 rad/s faster at t = 0. With
// θ = φ1 − φ2, J* = J1·J2/(J1 + J2):
//   θ'' + (c/J*)·θ' + (k/J*)·θ = T/J1,  θ(0) = 0, θ'(0) = v0 = −2 rad/s,
// and the shaft torque M = k·θ + c·θ' oscillates about T·J2/(J1 + J2) = 75 N*m:
//   θ = θs + e^(−σt)·(A cos ωd t + B sin ωd t), θs = T·J*/(J1·k), A = −θs,
//   B = (v0 + σ·A)/ωd, σ = c/(2J*), ωd = sqrt(k/J* − σ²);
//   M = k·θs + e^(−σt)·(P cos ωd t + Q sin ωd t),
//   P = k·A + c·(ωd·B − σ·A), Q = k·B − c·(σ·B + ωd·A),
// extreme where tan(ωd t) = (ωd·Q − σ·P)/(σ·Q + ωd·P), every π/ωd.
struct TwoMassClosedForm {
    double J1 = 1, J2 = 3, k = 1e4, c = 10, T = 100, v0 = -2;
    double Js() const { return J1 * J2 / (J1 + J2); }
    double sigma() const { return c / (2 * Js()); }
    double wd() const { return std::sqrt(k / Js() - sigma() * sigma()); }
    double thetaS() const { return T * Js() / (J1 * k); }
    double P() const {
        const double A = -thetaS(), B = (v0 + sigma() * A) / wd();
        return k * A + c * (wd() * B - sigma() * A);
    }
    double Q() const {
        const double A = -thetaS(), B = (v0 + sigma() * A) / wd();
        return k * B - c * (sigma() * B + wd() * A);
    }
    double torque(double t) const {
        return k * thetaS() + std::exp(-sigma() * t) * (P() * std::cos(wd() * t) + Q() * std::sin(wd() * t));
    }
    /// {largest, smallest} torque over [0, end]: the stationary points and the ends.
    std::pair<double, double> extremes(double end) const {
        const double phase = std::atan2(wd() * Q() - sigma() * P(), sigma() * Q() + wd() * P());
        double hi = std::max(torque(0), torque(end)), lo = std::min(torque(0), torque(end));
        for (int n = -2; n < 1000; ++n) {
            const double t = (phase + n * M_PI) / wd();
            if (t < 0 || t > end) continue;
            hi = std::max(hi, torque(t));
            lo = std::min(lo, torque(t));
        }
        return {hi, lo};
    }
};

std::string twoMassChain(const std::string& interval) {
    return "format_version: 1\n"
           "name: two mass\n"
           "bodies:\n"
           "  - {name: a, inertia: 1 kg*m^2, joint: {type: pin}, initial_speed: 0 rad/s}\n"
           "  - {name: b, inertia: 3 kg*m^2, joint: {type: pin}, initial_speed: 2 rad/s}\n"
           "elements:\n"
           "  - {type: AppliedTorque, name: drive, body: a, torque: 100 N*m}\n"
           "  - {type: TorsionalCoupling, name: shaft, bodies: [a, b], stiffness: 1e4 N*m/rad, damping: 10 N*m*s/rad}\n"
           "scenario: {analysis: transient, initial_state: file, end_time: 0.3 s}\n"
           "outputs: {sample_interval: " + interval + "}\n";
}

TEST(SummaryTorques, CouplingPeakCarriesItsSignAndRunMaxMinAreTheClosedFormsExtremes) {
    const TwoMassClosedForm cf;
    const auto [hi, lo] = cf.extremes(0.3);
    // The closed form overshoots both ways: +226.65 and −106.87 N*m.
    ASSERT_GT(hi, 200);
    ASSERT_LT(lo, -100);
    for (const std::string interval : {"0.02 s", "0.0005 s"}) {
        const AnalysisResult r = runAnalysis(readModelText(twoMassChain(interval), "two.yaml", defaultModelReader()));
        ASSERT_NE(r.find("run_max.shaft.torque"), nullptr) << interval;
        ASSERT_NE(r.find("run_min.shaft.torque"), nullptr) << interval;
        ASSERT_NE(r.find("peak.shaft.torque"), nullptr) << interval;
        // Integrator accuracy 1e-6 (the default): within 1e-4 of the swing.
        EXPECT_NEAR(r.find("run_max.shaft.torque")->value, hi, 1e-4 * (hi - lo)) << interval;
        EXPECT_NEAR(r.find("run_min.shaft.torque")->value, lo, 1e-4 * (hi - lo)) << interval;
        EXPECT_EQ(r.find("peak.shaft.torque")->value, r.find("run_max.shaft.torque")->value) << interval;
        EXPECT_EQ(r.find("run_min.shaft.torque")->referredTo, "a");
    }
    // The reversal the larger: J2 20 rad/s ahead, the first (negative) lobe dominates
    // and the signed peak is negative.
    TwoMassClosedForm fast;
    fast.v0 = -20;
    const auto [fhi, flo] = fast.extremes(0.3);
    ASSERT_GT(-flo, fhi);
    std::string model = twoMassChain("0.02 s");
    model.replace(model.find("initial_speed: 2 rad/s"), 22, "initial_speed: 20 rad/s");
    const AnalysisResult r = runAnalysis(readModelText(model, "two.yaml", defaultModelReader()));
    EXPECT_NEAR(r.find("peak.shaft.torque")->value, flo, 1e-4 * (fhi - flo));
    EXPECT_NEAR(r.find("run_max.shaft.torque")->value, fhi, 1e-4 * (fhi - flo));
}

}  // namespace
}  // namespace milldyn
