// Issue 27 item 1: an AngleLoad's harmonics follow its shaft's speed, and
// frequency_response and resonance_map force the linear model with them
// (through the HarmonicForcing capability, as a PeriodicLoad's rows).
//
// The machine: shafts a (J1) and b (J2) on pins; a linear-law motor on a
// (M = M00 − γ·ω, so the linear model has damping γ on a), a
// spring-damper c, d between them; an AngleLoad on b (and on a, for the
// phase pattern). Textbook receptance of the 2-DOF torsional system
// (complex amplitudes e^{iPτ}, a load torque L opposing +ω applied as −L):
//   Z11 = c − P²J1 + iP(γ + d),  Z22 = c − P²J2 + iPd,  Z12 = −(c + iPd),  Δ = Z11·Z22 − Z12²
//   coupling torque T = (c + iPd)(X_a − X_b) per unit L:
//     L on b:  H_b = (c + iPd)(iPγ − P²J1)/Δ      (→ 1 as P → 0: b's load crosses the coupling)
//     L on a:  H_a = (c + iPd)·P²J2/Δ             (→ 0)
// An AngleLoad's harmonic k on shaft j, X cos kψ + Y sin kψ with
// ψ = n·θ − φ and θ = θ_0 + ω·τ, is Im((Y + iX)·e^{ik(nθ_0 − φ)}·e^{iknωτ}).
#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

using Complex = std::complex<double>;

constexpr double kJ1 = 0.5, kJ2 = 0.2, kC = 800.0, kD = 1.0, kGamma = 12.5, kM00 = 2000.0;
constexpr double kMean = 100.0;  // a0 of the crushing part [N*m] (g >= 0 at every angle: 100 − 50 − 10 − 5 > 0)
constexpr int kCycles = 2;      // n, cycles per revolution

std::string num(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

/// The machine with an AngleLoad `load` (its YAML mapping's inner keys) and `scenario`.
std::string model(const std::string& load, const std::string& scenario) {
    return "format_version: 1\nname: angle response\nbodies:\n"
           "  - {name: a, inertia: " + num(kJ1) + " kg*m^2, joint: {type: pin}}\n"
           "  - {name: b, inertia: " + num(kJ2) + " kg*m^2, joint: {type: pin}}\n"
           "elements:\n"
           "  - {type: InductionMotor, name: drive, body: a, law: linear, rated_torque: 100 N*m, rated_speed: 1440 rpm,"
           " synchronous_speed: 1500 rpm, linear_stall_torque: " + num(kM00) + " N*m, linear_slope: " + num(kGamma) +
           " N*m*s/rad}\n"
           "  - {type: TorsionalCoupling, name: shaft, bodies: [a, b], stiffness: " + num(kC) + " N*m/rad, damping: " +
           num(kD) + " N*m*s/rad}\n"
           "  - {type: AngleLoad, name: crushing, " + load + "}\n"
           "scenario: {" + scenario + "}\n"
           "outputs: {plots: false}\n";
}

Complex receptanceB(double P) {
    const Complex i(0, 1);
    const Complex z11 = kC - P * P * kJ1 + i * P * (kGamma + kD), z22 = kC - P * P * kJ2 + i * P * kD,
                  z12 = -(kC + i * P * kD);
    return (kC + i * P * kD) * (i * P * kGamma - P * P * kJ1) / (z11 * z22 - z12 * z12);
}

Complex receptanceA(double P) {
    const Complex i(0, 1);
    const Complex z11 = kC - P * P * kJ1 + i * P * (kGamma + kD), z22 = kC - P * P * kJ2 + i * P * kD,
                  z12 = -(kC + i * P * kD);
    return (kC + i * P * kD) * P * P * kJ2 / (z11 * z22 - z12 * z12);
}

std::size_t column(const AnalysisResult& r, const std::string& name) {
    const std::size_t c = r.findColumn(name);
    if (c == std::string::npos) throw std::runtime_error("no column " + name);
    return c;
}

// One shaft, b: the coupling's amplitude per unit harmonic amplitude is
// |H_b(P)| whatever the phases, and its quasi-static in-phase reference
// is H_b(0) = 1, so the dynamic factor is |H_b(P)| as well.
TEST(AngleLoadResponse, FrequencyResponseOfOneShaftIsTheTwoMassReceptance) {
    const AnalysisResult r = runAnalysis(readModelText(
        model("bodies: [b], shape: fourier, cycles_per_revolution: 2, mean_torque: " + num(kMean) + " N*m, "
              "cosine_amplitudes: [30 N*m, 0 N*m, 5 N*m], sine_amplitudes: [40 N*m, 10 N*m]",
              "analysis: frequency_response, load: crushing, harmonic: 1, frequency_min: 1 rad/s, "
              "frequency_max: 1000 rad/s, points: 25"),
        "angle.yaml", defaultModelReader()));
    ASSERT_EQ(r.rows.size(), 25u);
    const std::size_t amplitude = column(r, "shaft.torque.amplitude"), factor = column(r, "shaft.torque.dynamic_factor");
    for (const auto& row : r.rows) {
        const double closed = std::abs(receptanceB(row[0]));
        EXPECT_NEAR(row[amplitude] / closed, 1.0, 1e-8) << row[0];
        EXPECT_NEAR(row[factor] / closed, 1.0, 1e-8) << row[0];
    }
}

// Two shafts, a and b, each with its own phase: the coupling sees
// H_a·C_a + H_b·C_b (per unit amplitude), whose magnitude depends on the
// relative phase k(n(θ_a0 − θ_b0) − (φ_a − φ_b)); in steady running the
// coupling carries b's mean load, so θ_a0 − θ_b0 = a0/c.
TEST(AngleLoadResponse, FrequencyResponseOfTwoShaftsAddsTheirPhasedReceptances) {
    const double phiA = 0.7, phiB = -0.4;
    for (int k : {1, 3}) {
        const AnalysisResult r = runAnalysis(readModelText(
            model("bodies: [a, b], phases: [" + num(phiA) + " rad, " + num(phiB) +
                      " rad], shape: fourier, cycles_per_revolution: 2, mean_torque: " + num(kMean) + " N*m, "
                      "cosine_amplitudes: [30 N*m, 0 N*m, 5 N*m], sine_amplitudes: [40 N*m, 10 N*m, 2 N*m]",
                  "analysis: frequency_response, load: crushing, harmonic: " + std::to_string(k) +
                      ", frequency_min: 1 rad/s, frequency_max: 1000 rad/s, points: 25"),
            "angle.yaml", defaultModelReader()));
        const std::size_t amplitude = column(r, "shaft.torque.amplitude");
        const std::size_t factor = column(r, "shaft.torque.dynamic_factor");
        const double relative = k * (kCycles * (kMean / kC) - (phiA - phiB));
        for (const auto& row : r.rows) {
            const double P = row[0];
            const double closed = std::abs(receptanceA(P) * std::polar(1.0, relative) + receptanceB(P));
            EXPECT_NEAR(row[amplitude] / closed, 1.0, 1e-8) << "k " << k << " at " << P;
            // In phase, weight 1 on both shafts, quasi-statically: H_a(0) + H_b(0) = 1.
            EXPECT_NEAR(row[factor] / closed, 1.0, 1e-8) << "k " << k << " at " << P;
        }
    }
}

// The resonance map sweeps the shaft's speed Ω: harmonic k of the cycle is
// at k·n·Ω, weighted by its running amplitude B_k = |(a_k, b_k)|:
//   DF(Ω) = Σ_k B_k·|H_b(k·n·Ω)| / Σ_k B_k
TEST(AngleLoadResponse, ResonanceMapTakesTheHarmonicsAtTheirOrdersOfTheShaftSpeed) {
    const std::vector<double> a = {30, 0, 5}, b = {40, 10, 0};
    const AnalysisResult r = runAnalysis(readModelText(
        model("bodies: [b], shape: fourier, cycles_per_revolution: 2, mean_torque: " + num(kMean) + " N*m, listed_harmonics: 3, "
              "cosine_amplitudes: [30 N*m, 0 N*m, 5 N*m], sine_amplitudes: [40 N*m, 10 N*m]",
              "analysis: resonance_map, load: crushing, speed_min: 1 rad/s, speed_max: 100 rad/s, points: 34"),
        "angle.yaml", defaultModelReader()));
    ASSERT_EQ(r.rows.size(), 34u);
    const std::size_t factor = column(r, "shaft.torque.dynamic_factor");
    double sumB = 0;
    for (std::size_t k = 0; k < a.size(); ++k) sumB += std::hypot(a[k], b[k]);
    double largest = 0, largestAt = 0;
    for (const auto& row : r.rows) {
        const double w = row[0];
        double df = 0;
        for (std::size_t k = 0; k < a.size(); ++k)
            df += std::hypot(a[k], b[k]) * std::abs(receptanceB(double(k + 1) * kCycles * w));
        df /= sumB;
        EXPECT_NEAR(row[factor] / df, 1.0, 1e-8) << w;
        if (df > largest) largest = df, largestAt = w;
    }
    ASSERT_NE(r.find("shaft.torque.peak_dynamic_factor"), nullptr);
    EXPECT_NEAR(r.find("shaft.torque.peak_dynamic_factor")->value / largest, 1.0, 1e-8);
    EXPECT_EQ(r.find("shaft.torque.peak_speed")->value, largestAt);
}

TEST(AngleLoadResponse, AShaftAngleLoadRefusesATimeCheckAndAnEventCount) {
    const std::string load = "bodies: [b], shape: half_sine_pulse, peak_torque: 100 N*m, pulse_width: 3.14159 rad";
    try {
        runAnalysis(readModelText(model(load, "analysis: frequency_response, load: crushing, frequency_min: 1 rad/s, "
                                              "frequency_max: 100 rad/s, points: 5, check_frequencies: [10 rad/s]"),
                                  "angle.yaml", defaultModelReader()));
        ADD_FAILURE() << "the time check ran";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.check_frequencies");
        EXPECT_NE(std::string(e.what()).find("forced by its shafts' angles"), std::string::npos) << e.what();
    }
    try {
        runAnalysis(readModelText(model(load, "analysis: resonance_map, load: crushing, speed_min: 1 rad/s, "
                                              "speed_max: 100 rad/s, points: 5, load_events_per_revolution: 3"),
                                  "angle.yaml", defaultModelReader()));
        ADD_FAILURE() << "an event count was taken";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.load_events_per_revolution");
    }
}


// The crushing part opposes motion at every angle, for a series as for a
// table or a pulse: g(ψ) = 100 + 150 cos ψ falls to −50 N*m at ψ = π, and
// is refused at the key that takes it below 0, with the minimum and where;
// 50 + 50 cos 2ψ just touches 0 (at ψ = π/2) and is taken.
TEST(AngleLoadResponse, AFourierCrushingPartThatWouldDriveTheShaftIsRefused) {
    const std::string scenario = "analysis: linearize";
    try {
        readModelText(model("bodies: [b], shape: fourier, mean_torque: 100 N*m, cosine_amplitudes: [150 N*m]", scenario),
                      "angle.yaml", defaultModelReader());
        ADD_FAILURE() << "a crushing part down to −50 N*m was taken";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "crushing.cosine_amplitudes");
        const std::string what = e.what();
        EXPECT_NE(what.find("falls to -50 N*m at ψ = 3.14159 rad"), std::string::npos) << what;
    }
    try {
        readModelText(model("bodies: [b], shape: fourier, mean_torque: -1 N*m", scenario), "angle.yaml",
                      defaultModelReader());
        ADD_FAILURE() << "a negative constant crushing torque was taken";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "crushing.mean_torque");
    }
    EXPECT_NO_THROW(readModelText(
        model("bodies: [b], shape: fourier, mean_torque: 50 N*m, cosine_amplitudes: [0 N*m, 50 N*m]", scenario),
        "angle.yaml", defaultModelReader()));
}

}  // namespace
}  // namespace milldyn
