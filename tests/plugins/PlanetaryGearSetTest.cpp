// Tests of PlanetaryGearSet (issue 32 item 1). Expected values come from
// Willis' equation, the statics of sun, planets and carrier worked by hand
// in the comments, and validation/oracles/PlanetaryStageOracle (Lin &
// Parker's torsional model), never from the element's own outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <map>
#include <string>

#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "tests/driver/ReaderTestHelpers.h"
#include "validation/oracles/PlanetaryStageOracle.h"

namespace milldyn {
namespace {

using test::contains;
using test::readErrorOf;
using test::readText;

namespace oc = milldyn::oracles;

// z_s = 24, z_p = 30, z_r = 84, m = 10 mm: r_s = 0.12 m, r_p = 0.15 m,
// r_r = 0.42 m, a = 0.27 m; three planets at 90, 210 and 330 deg.
constexpr double kZs = 24, kZp = 30, kZr = 84, kModule = 0.01;
constexpr double kRs = 0.12, kRp = 0.15, kRr = 0.42, kA = 0.27;
constexpr double kJs = 2, kJr = 30, kJc = 20, kJp = 0.5, kMp = 20;
const double kDeg = M_PI / 180;

std::string planetAt(const std::string& name, double deg, const std::string& parent) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "  - {name: %s, inertia: 0.5 kg*m^2, mass: 20 kg, joint: {type: pin, parent: %s, location: [%.17g m, "
                  "%.17g m, 0 m]}}\n",
                  name.c_str(), parent.c_str(), kA * std::cos(deg * kDeg), kA * std::sin(deg * kDeg));
    return text;
}

/// A stage with `fixed` ("sun", "ring", "carrier") omitted from the set,
/// `driven` turned by a linear motor, `loaded` braked by a constant torque.
std::string stage(const std::string& fixed, const std::string& driven, const std::string& loaded,
                  const std::string& setExtra, double load = 8000) {
    // The fixed member is ground: no body of its own.
    std::string bodies = "bodies:\n";
    if (fixed != "sun") bodies += "  - {name: sun, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}\n";
    if (fixed != "ring") bodies += "  - {name: ring, inertia: 30 kg*m^2, joint: {type: pin, parent: ground}}\n";
    if (fixed != "carrier") bodies += "  - {name: carrier, inertia: 20 kg*m^2, joint: {type: pin, parent: ground}}\n";
    const std::string parent = fixed == "carrier" ? "ground" : "carrier";
    bodies += planetAt("p1", 90, parent) + planetAt("p2", 210, parent) + planetAt("p3", 330, parent);
    std::string set = "  - {type: PlanetaryGearSet, name: stage, planets: [p1, p2, p3], teeth: [24, 30, 84], "
                      "module: 10 mm";
    for (const std::string m : {"sun", "ring", "carrier"})
        if (m != fixed) set += ", " + m + ": " + m;
    set += setExtra + "}\n";
    return "format_version: 1\nname: planetary stage\n" + bodies +
           "elements:\n"
           "  - {type: InductionMotor, name: motor, body: " +
           driven +
           ", law: linear, rated_torque: 30000 N*m, rated_speed: 990 rpm, synchronous_speed: 1000 rpm}\n" + set +
           "  - {type: ResistanceTorque, name: load, body: " + loaded + ", constant_torque: " + std::to_string(load) +
           " N*m}\n"
           "scenario: {analysis: transient, end_time: 1 s}\n";
}

struct Steady {
    std::map<std::string, double> probe;
    std::map<std::string, double> speed;
};

Steady steadyOf(const std::string& text, LinearModel* lm = nullptr) {
    const ModelSpec spec = readText("stage.yaml", text, {});
    auto scene = buildScene(spec);
    SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(s, SimTK::Stage::Acceleration);
    Steady out;
    for (const auto& p : scene->probes()) out.probe[p.name] = p.value(s);
    for (const auto& b : scene->bodies()) out.speed[b.name] = pinSpeed(s, b.mobod);
    // The steady state is steady: no body accelerates.
    for (int i = 0; i < s.getNU(); ++i) EXPECT_NEAR(s.getUDot()[i], 0, 1e-6) << "udot " << i;
    if (lm) *lm = linearizeScene(*scene, s, true, true);
    return out;
}

/// Absolute speeds of sun, ring and carrier (0 for the fixed member).
double member(const Steady& st, const std::string& name, const std::string& fixed) {
    return name == fixed ? 0.0 : st.speed.at(name);
}

// Willis: (ω_s − ω_c)/(ω_r − ω_c) = −z_r/z_s = −3.5, for each fixed member,
// rigid and compliant; and the oracle's third speed from the other two.
TEST(PlanetaryGearSet, WillisEquationForEveryFixedMember) {
    struct Case {
        const char *fixed, *driven, *loaded;
    };
    for (const Case c : {Case{"ring", "sun", "carrier"}, Case{"sun", "carrier", "ring"},
                         Case{"carrier", "sun", "ring"}, Case{"sun", "ring", "carrier"}}) {
        for (const std::string law : {"", ", law: compliant, sun_mesh_stiffness: 1e9 N/m, ring_mesh_stiffness: 1e9 N/m, "
                                          "sun_mesh_damping: 1e4 N*s/m, ring_mesh_damping: 1e4 N*s/m"}) {
            const Steady st = steadyOf(stage(c.fixed, c.driven, c.loaded, law, 2000));
            const double ws = member(st, "sun", c.fixed), wr = member(st, "ring", c.fixed),
                         wc = member(st, "carrier", c.fixed);
            SCOPED_TRACE(std::string(c.fixed) + " fixed, " + c.driven + " driven" + law);
            EXPECT_GT(std::abs(st.speed.at(c.driven)), 90);  // near 1000 rpm: the motor turns it
            EXPECT_NEAR((ws - wc) / (wr - wc), -kZr / kZs, 1e-9);
            EXPECT_NEAR(wc, oc::willisCarrierSpeed(kZs, kZr, ws, wr), 1e-9 * std::abs(st.speed.at(c.driven)));
            // Planets relative to the carrier roll on the sun: r_s (ω_s − ω_c) + r_p q̇ = 0.
            for (const char* p : {"p1", "p2", "p3"})
                EXPECT_NEAR(st.speed.at(p), -kRs * (ws - wc) / kRp, 1e-9 * std::abs(st.speed.at(c.driven)));
            // Mesh frequency z_r |ω_r − ω_c| = z_s |ω_s − ω_c|.
            EXPECT_NEAR(st.probe.at("stage.mesh_frequency"), oc::planetaryMeshFrequency(kZr, wr, wc),
                        1e-9 * st.probe.at("stage.mesh_frequency"));
            EXPECT_NEAR(st.probe.at("stage.mesh_frequency"), kZs * std::abs(ws - wc) / (2 * M_PI),
                        1e-9 * st.probe.at("stage.mesh_frequency"));
        }
    }
}

// Sun driven, ring fixed, carrier loaded by T_L = 8000 N*m, steady running,
// no gravity. Hand statics: the carrier takes T_L, so the sun carries
// T_s = T_L z_s/(z_s + z_r) = 8000·24/108 = 1777.8 N*m; each planet
// F_t = T_s/(n r_s); the carrier holds each planet back with 2 F_t along
// −e_t and pulls it inward with the centrifugal m_p a ω_c²; the separating
// forces of the two meshes (F_t tan α each) cancel at the pin.
TEST(PlanetaryGearSet, MeshForcesAndPlanetBearingsAgainstHandStatics) {
    for (const std::string law : {"", ", law: compliant, sun_mesh_stiffness: 2e9 N/m, ring_mesh_stiffness: 3e9 N/m, "
                                      "sun_mesh_damping: 1e4 N*s/m, ring_mesh_damping: 1e4 N*s/m"}) {
        SCOPED_TRACE(law);
        const Steady st = steadyOf(stage("ring", "sun", "carrier", law));
        const double TL = 8000, Ts = TL * kZs / (kZs + kZr), Ft = Ts / (3 * kRs);
        const double wc = st.speed.at("carrier");
        const double centrifugal = kMp * kA * wc * wc;
        const oc::PlanetaryStatics h = oc::planetaryStatics(
            {kZs, kZp, kZr, kModule, 20 * kDeg, 3, 0, 0, kJs, kJr, kJc, kJp, kMp}, Ts, {});
        for (const char* p : {"p1", "p2", "p3"}) {
            const std::string stem = std::string("stage.") + p;
            EXPECT_NEAR(st.probe.at(stem + ".sun_mesh_force"), Ft, 1e-9 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".ring_mesh_force"), Ft, 1e-9 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".sun_mesh_force"), h.meshForce[0], 1e-9 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".bearing_tangential_force"), -2 * Ft, 1e-8 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".bearing_radial_force"), -centrifugal, 1e-8 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".bearing_force"), std::hypot(2 * Ft, centrifugal), 1e-8 * Ft) << p;
            EXPECT_NEAR(st.probe.at(stem + ".load_share"), 1.0, 1e-9) << p;
        }
        // Torques of the set on its members: the motor's, the ring's
        // reaction, the load's; they balance.
        EXPECT_NEAR(st.probe.at("stage.torque_on_sun"), -st.probe.at("motor.torque"), 1e-8 * Ts);
        EXPECT_NEAR(st.probe.at("stage.torque_on_sun"), -Ts, 1e-8 * Ts);
        EXPECT_NEAR(st.probe.at("stage.torque_on_carrier"), TL, 1e-8 * TL);
        EXPECT_NEAR(st.probe.at("stage.torque_on_ring"), -kRr * 3 * Ft, 1e-8 * TL);
        EXPECT_NEAR(st.probe.at("stage.torque_on_sun") + st.probe.at("stage.torque_on_ring") +
                        st.probe.at("stage.torque_on_carrier"),
                    0.0, 1e-8 * TL);
        EXPECT_NEAR(st.probe.at("stage.load_sharing_factor"), 1.0, 1e-9);
    }
}

// Load sharing with carrier-pin position errors e = [+1, 0, −1] µm:
// F_k = T_s/(n r_s) − 2 k_t (e_k − ē), k_t = cos²α k_s k_r/(k_s + k_r)
// (oracle). With k_s = 2e9, k_r = 3e9 N/m: k_t = 1.06e9 N/m, so
// 2 k_t e = 2.12 kN against T_s/(n r_s) = 4.94 kN: F = 2.82, 4.94, 7.06 kN.
TEST(PlanetaryGearSet, UnequalLoadSharingWithPinPositionErrors) {
    const std::string law = ", law: compliant, sun_mesh_stiffness: 2e9 N/m, ring_mesh_stiffness: 3e9 N/m, "
                            "sun_mesh_damping: 1e4 N*s/m, ring_mesh_damping: 1e4 N*s/m, "
                            "pin_position_errors: [1 um, 0 um, -1 um]";
    const Steady st = steadyOf(stage("ring", "sun", "carrier", law));
    const double Ts = 8000 * kZs / (kZs + kZr);
    oc::PlanetaryStageModel m{kZs, kZp, kZr, kModule, 20 * kDeg, 3, 2e9, 3e9, kJs, kJr, kJc, kJp, kMp};
    const oc::PlanetaryStatics h = oc::planetaryStatics(m, Ts, {1e-6, 0, -1e-6});
    const char* names[3] = {"p1", "p2", "p3"};
    const double F0 = Ts / (3 * kRs);
    for (int k = 0; k < 3; ++k) {
        const std::string stem = std::string("stage.") + names[k];
        EXPECT_NEAR(st.probe.at(stem + ".sun_mesh_force"), h.meshForce[k], 1e-7 * F0) << names[k];
        EXPECT_NEAR(st.probe.at(stem + ".ring_mesh_force"), h.meshForce[k], 1e-7 * F0) << names[k];
        EXPECT_NEAR(st.probe.at(stem + ".load_share"), 3 * h.meshForce[k] / (3 * F0), 1e-7) << names[k];
    }
    // A planet whose pin is ahead (+e_t) carries less: sharing is unequal.
    EXPECT_LT(st.probe.at("stage.p1.sun_mesh_force"), 0.9 * F0);
    EXPECT_NEAR(st.probe.at("stage.load_sharing_factor"), h.loadSharingFactor, 1e-7);
    EXPECT_GT(h.loadSharingFactor, 1.05);
}

// Natural frequencies of the compliant stage (ring fixed, sun with the
// motor's rotor, carrier) against Lin & Parker's torsional model (oracle);
// the planet mode, of multiplicity n − 1 = 2, in closed form.
TEST(PlanetaryGearSet, NaturalFrequenciesAgainstTorsionalPlanetaryModel) {
    const std::string law = ", law: compliant, sun_mesh_stiffness: 2e9 N/m, ring_mesh_stiffness: 3e9 N/m";
    LinearModel lm;
    steadyOf(stage("ring", "sun", "carrier", law), &lm);
    oc::PlanetaryStageModel m{kZs, kZp, kZr, kModule, 20 * kDeg, 3, 2e9, 3e9, kJs, kJr, kJc, kJp, kMp};
    const std::vector<double> oracle = oc::torsionalPlanetaryFrequencies(m, 'r');
    std::vector<double> model;
    const double top = lm.naturalFrequencies.maxCoeff();
    for (int i = 0; i < lm.naturalFrequencies.size(); ++i)
        if (lm.naturalFrequencies[i] > 1e-6 * top) model.push_back(lm.naturalFrequencies[i]);
    ASSERT_EQ(model.size(), oracle.size());
    ASSERT_EQ(model.size(), 4u);  // sun, carrier, 3 planets less the rigid rotation
    for (std::size_t i = 0; i < model.size(); ++i) EXPECT_NEAR(model[i], oracle[i], 1e-6 * oracle[i]) << i;
    const double planetMode = oc::planetModeFrequency(m);
    int multiplicity = 0;
    for (double w : model) multiplicity += std::abs(w - planetMode) < 1e-6 * planetMode ? 1 : 0;
    EXPECT_EQ(multiplicity, 2);
}

// Rigid meshes in the linear analyses: the stage reduces to a ratio. Ring
// fixed; the carrier drives a table through a coupling k = 1e6 N*m/rad.
// Referred to the carrier: J_eq = J_c + n m_p a² + J_s (1 + z_r/z_s)² +
// n J_p (1 − z_r/z_p)² (planet absolute speed ω_c (1 − z_r/z_p));
// one elastic mode ω² = k (J_eq + J_t)/(J_eq J_t).
TEST(PlanetaryGearSet, RigidStageReducesInLinearize) {
    std::string text = stage("ring", "sun", "carrier", "");
    text = test::replacedIn(text, "elements:\n",
                            "  - {name: table, inertia: 500 kg*m^2, joint: {type: pin, parent: ground, location: [0 m, "
                            "0 m, 2 m]}}\nelements:\n");
    text = test::replacedIn(text, "body: carrier, constant_torque", "body: table, constant_torque");
    text = test::replacedIn(text, "scenario:", "  - {type: TorsionalCoupling, name: shaft, bodies: [carrier, table], "
                                               "stiffness: 1e6 N*m/rad}\nscenario:");
    LinearModel lm;
    steadyOf(text, &lm);
    const double i = 1 + kZr / kZs, ip = 1 - kZr / kZp;
    const double Jeq = kJc + 3 * kMp * kA * kA + kJs * i * i + 3 * kJp * ip * ip, Jt = 500;
    const double w = std::sqrt(1e6 * (Jeq + Jt) / (Jeq * Jt));
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_NEAR(lm.naturalFrequencies[1], w, 1e-6 * w);
}

// frequency_response through a rigid stage (issue 32 item 3): the
// table's periodic load is projected on the independent coordinates.
// Hand model: the stage reduced to the carrier (J_eq as above) with the
// motor's slope b0 = M_n/(ω_s − ω_n) on the sun, i² b0 on the carrier; the
// flange k, c to the table J_t, unit torque −1 on the table:
//   [J_eq 0; 0 J_t] ẍ + [i²b0 + c, −c; −c, c] ẋ + [k, −k; −k, k] x = [0; −1],
// flange torque k(x1 − x2) + c(ẋ1 − ẋ2), quasi-static amplitude 1. Its peak
// over the analysis's own log grid; and a time simulation at 1.6·√(k/J_t).
TEST(PlanetaryGearSet, FrequencyResponseThroughARigidStage) {
    std::string text = stage("ring", "sun", "carrier", "");
    text = test::replacedIn(text, "elements:\n",
                            "  - {name: table, inertia: 500 kg*m^2, joint: {type: pin, parent: ground, location: [0 m, "
                            "0 m, 2 m]}}\nelements:\n");
    const double i = 1 + kZr / kZs, ip = 1 - kZr / kZp;
    const double Jeq = kJc + 3 * kMp * kA * kA + kJs * i * i + 3 * kJp * ip * ip, Jt = 500, k = 1e6, c = 3000;
    const double b0 = 30000 / ((1000 - 990) * 2 * M_PI / 60), ceq = i * i * b0;
    const double Pmin = 20, Pmax = 200, wcheck = 1.6 * std::sqrt(k / Jt);
    const int points = 400;
    char scenario[700];
    std::snprintf(scenario, sizeof scenario,
                  "  - {type: TorsionalCoupling, name: shaft, bodies: [carrier, table], stiffness: 1e6 N*m/rad, "
                  "damping: 3000 N*m*s/rad}\n"
                  "  - {type: PeriodicLoad, name: rows, bodies: [table], rows: 1, mean_torque: 3000 N*m, amplitudes: "
                  "[500 N*m], fundamental_frequency: 10 rad/s, arrangement: in_phase}\n"
                  "scenario: {analysis: frequency_response, load: rows, frequency_min: %g rad/s, frequency_max: "
                  "%g rad/s, points: %d, check_frequencies: [%.17g rad/s]}\nintegrator: {accuracy: 1e-8}",
                  Pmin, Pmax, points, wcheck);
    text = test::replacedIn(text, "scenario: {analysis: transient, end_time: 1 s}", scenario);
    const AnalysisResult r = runAnalysis(readText("stage.yaml", text, {}));
    std::map<std::string, double> v;
    for (const auto& x : r.results) v[x.name] = x.value;
    using C = std::complex<double>;
    auto flange = [&](double P) {
        const C I(0, 1);
        const C a11 = k - P * P * Jeq + I * P * (ceq + c), a12 = -k - I * P * c, a22 = k - P * P * Jt + I * P * c;
        const C det = a11 * a22 - a12 * a12;
        const C x1 = -a12 * C(-1) / det, x2 = a11 * C(-1) / det;  // Cramer, f = [0, −1]
        return std::abs((k + I * P * c) * (x1 - x2));
    };
    double peak = 0, peakAt = 0;
    for (int n = 0; n < points; ++n) {
        const double P = Pmin * std::pow(Pmax / Pmin, double(n) / (points - 1));
        if (flange(P) > peak) {
            peak = flange(P);
            peakAt = P;
        }
    }
    ASSERT_TRUE(v.count("shaft.torque.peak_frequency"));
    EXPECT_NEAR(v.at("shaft.torque.peak_frequency"), peakAt, 1e-12 * peakAt);
    EXPECT_NEAR(v.at("shaft.torque.peak_dynamic_factor"), peak, 1e-5 * peak);
    ASSERT_TRUE(v.count("time_check_amplitude_rel_diff"));
    EXPECT_LT(v.at("time_check_amplitude_rel_diff"), 1e-3);
    std::cout << "peak DF " << v.at("shaft.torque.peak_dynamic_factor") << " at " << peakAt << " rad/s; time check "
              << v.at("time_check_amplitude_rel_diff") << ", phase " << v.at("time_check_phase_diff") << "\n";
}

TEST(PlanetaryGearSet, ResonanceMapTakesARigidStageAndReportsTheMeshOrder) {
    std::string text = stage("ring", "sun", "carrier", "");
    text = test::replacedIn(text, "elements:\n",
                            "  - {name: table, inertia: 500 kg*m^2, joint: {type: pin, parent: ground, location: [0 m, "
                            "0 m, 2 m]}}\nelements:\n");
    text = test::replacedIn(text, "body: carrier, constant_torque", "body: table, constant_torque");
    text = test::replacedIn(text, "scenario: {analysis: transient, end_time: 1 s}",
                            "  - {type: TorsionalCoupling, name: shaft, bodies: [carrier, table], stiffness: 1e6 "
                            "N*m/rad}\nscenario: {analysis: resonance_map, rotor: table, speed_min: 1 rad/s, "
                            "speed_max: 100 rad/s, points: 50}");
    const ModelSpec spec = readText("stage.yaml", text, {});
    const AnalysisResult r = runAnalysis(spec);
    bool perRotor = false;
    for (const auto& v : r.results)
        if (v.name == "stage.mesh_frequency.per_rotor_speed") {
            perRotor = true;
            EXPECT_NEAR(v.value, kZr, 1e-6 * kZr);  // z_r per turn of the carrier, the table's speed
        }
    EXPECT_TRUE(perRotor);
}

// Issue 26 item 6: a GearMesh planet on a carrier driven through a
// TorsionalCoupling (ratio 10) from a motor; the carrier loaded by 5000
// N*m. Steady running: the coupling passes 5000/10 = 500 N*m, the carrier
// and planet do not accelerate. (The GearMesh held no steady residual, so
// the search ended on a state that broke the rolling constraint.)
TEST(PlanetaryGearSet, GearMeshPlanetSteadyStateThroughACoupling) {
    const std::string text =
        "format_version: 1\nname: repro\nbodies:\n"
        "  - {name: sun, inertia: 10 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: carrier, inertia: 1000 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: planet, inertia: 100 kg*m^2, mass: 500 kg, joint: {type: pin, parent: carrier, location: [1 m, 0 m, "
        "0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: sun, rated_torque: 1000 N*m, rated_speed: 990 rpm, "
        "synchronous_speed: 1000 rpm}\n"
        "  - {type: TorsionalCoupling, name: stage, bodies: [sun, carrier], ratio: 10, stiffness: 1e6 N*m/rad, damping: "
        "100 N*m*s/rad}\n"
        "  - {type: GearMesh, name: ring, carrier: carrier, planet: planet, fixed_pitch_radius: 2 m, "
        "planet_pitch_radius: 1 m, rolling: internal}\n"
        "  - {type: ResistanceTorque, name: load, body: carrier, constant_torque: 5000 N*m}\n"
        "scenario: {analysis: transient, initial_state: steady, end_time: 0.01 s}\n";
    const Steady st = steadyOf(text);
    EXPECT_NEAR(st.probe.at("stage.torque"), 500, 1e-6 * 500);
    EXPECT_NEAR(st.probe.at("motor.torque"), 500, 1e-6 * 500);
    // Rolling inside the fixed ring (R = 2 m, r = 1 m): R q_c + r q_p = 0,
    // the planet's pin speed relative to the carrier −(R/r) ω_c.
    EXPECT_NEAR(st.speed.at("planet"), -2 * st.speed.at("carrier"), 1e-9 * std::abs(st.speed.at("carrier")));
}

TEST(PlanetaryGearSet, RefusesBadSets) {
    std::string bad = test::replacedIn(stage("ring", "sun", "carrier", ""), "teeth: [24, 30, 84]", "teeth: [24, 30, 80]");
    EXPECT_TRUE(contains(readErrorOf("s.yaml", bad, {}).what(), "z_ring must be z_sun + 2 z_planet"));
    bad = stage("ring", "sun", "carrier", ", pin_position_errors: [1 um, 0 um, 0 um]");
    EXPECT_TRUE(contains(readErrorOf("s.yaml", bad, {}).what(), "not used by law: rigid"));
    bad = stage("ring", "sun", "carrier", ", law: compliant, sun_mesh_stiffness: 1e9 N/m");
    EXPECT_TRUE(contains(readErrorOf("s.yaml", bad, {}).what(), "ring_mesh_stiffness"));
    // A planet off the pitch circle: refused at build, naming the distance.
    bad = test::replacedIn(stage("ring", "sun", "carrier", ""), "module: 10 mm", "module: 11 mm");
    const ModelSpec spec = readText("s.yaml", bad, {});
    try {
        buildScene(spec);
        ADD_FAILURE() << "accepted a planet off the pitch circle";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "from the set's axis")) << e.what();
    }
}

}  // namespace
}  // namespace milldyn
