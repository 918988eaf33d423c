// Validation of the bevel and planetary gear elements (issue 32) against
// validation/oracles/PlanetaryStageOracle (Willis' kinematics, the statics
// of sun, planets and carrier with load sharing, Lin & Parker's torsional
// planetary model) and validation/oracles/BevelGearOracle (the textbook
// straight- and spiral-bevel tooth forces), on small stages written here
// and on the shipped vertical roller mill (models/vertical_roller_mill_4p2MW.yaml).
//  - planetary_stage_willis_*: steady running with each member fixed;
//  - planetary_stage_load_sharing: compliant meshes, carrier pins out of place;
//  - planetary_stage_frequencies: natural frequencies against the torsional model;
//  - planetary_stage_vrm_statics: the mill's planet mesh forces and bearing loads;
//  - planetary_stage_vrm_planet_mode: the mill's planet mode (multiplicity 2);
//  - bevel_vrm_forces, bevel_straight_shaft_angle_70: tooth forces on both shafts;
//  - bevel_shaft_bearings_*_hand, bevel_vrm_bearings: the tooth forces on the
//    shafts' bearings (ShaftBearings with mesh:) against the shafts' statics.

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "validation/cases/ValidationCases.h"
#include "validation/oracles/BevelGearOracle.h"
#include "validation/oracles/PlanetaryStageOracle.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;

// Steady running is solved by Newton to round-off; the forces are sums of
// terms of order 1e5 N: 1e-8 relative.
constexpr double kStaticsTolerance = 1e-8;
// linearize differences the accelerations (step 1e-5 relative); the mesh
// forces are linear in the angles.
constexpr double kFrequencyTolerance = 1e-6;
const double kDeg = M_PI / 180;

struct Steady {
    std::map<std::string, double> probe, speed;
    LinearModel lm;
};

Steady steadyOf(const ModelSpec& spec, bool linearize) {
    auto scene = buildScene(spec);
    SimTK::State s = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(s, SimTK::Stage::Acceleration);
    Steady out;
    for (const auto& p : scene->probes()) out.probe[p.name] = p.value(s);
    for (const auto& b : scene->bodies()) out.speed[b.name] = pinSpeed(s, b.mobod);
    if (linearize) out.lm = linearizeScene(*scene, s, true, true);
    return out;
}

Steady steadyOfText(const std::string& text, bool linearize = false) {
    return steadyOf(readModelText(text, "planetary_stage.yaml", defaultModelReader()), linearize);
}

// The stage of tests/plugins/PlanetaryGearSetTest.cpp: z 24/30/84, m 10 mm,
// planets at 90/210/330 deg (a = 0.27 m), J_s 2, J_r 30, J_c 20, J_p 0.5
// kg*m^2, m_p 20 kg; `fixed` omitted from the set.
constexpr double kZs = 24, kZp = 30, kZr = 84;
std::string stageText(const std::string& fixed, const std::string& driven, const std::string& loaded,
                      const std::string& extra) {
    std::string text = "format_version: 1\nname: planetary stage\nbodies:\n";
    if (fixed != "sun") text += "  - {name: sun, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}\n";
    if (fixed != "ring") text += "  - {name: ring, inertia: 30 kg*m^2, joint: {type: pin, parent: ground}}\n";
    if (fixed != "carrier") text += "  - {name: carrier, inertia: 20 kg*m^2, joint: {type: pin, parent: ground}}\n";
    const std::string parent = fixed == "carrier" ? "ground" : "carrier";
    int k = 0;
    for (double deg : {90.0, 210.0, 330.0}) {
        char line[300];
        std::snprintf(line, sizeof line,
                      "  - {name: p%d, inertia: 0.5 kg*m^2, mass: 20 kg, joint: {type: pin, parent: %s, location: "
                      "[%.17g m, %.17g m, 0 m]}}\n",
                      ++k, parent.c_str(), 0.27 * std::cos(deg * kDeg), 0.27 * std::sin(deg * kDeg));
        text += line;
    }
    text += "elements:\n  - {type: InductionMotor, name: motor, body: " + driven +
            ", law: linear, rated_torque: 30000 N*m, rated_speed: 990 rpm, synchronous_speed: 1000 rpm}\n"
            "  - {type: PlanetaryGearSet, name: stage, planets: [p1, p2, p3], teeth: [24, 30, 84], module: 10 mm";
    for (const std::string m : {"sun", "ring", "carrier"})
        if (m != fixed) text += ", " + m + ": " + m;
    text += extra + "}\n  - {type: ResistanceTorque, name: load, body: " + loaded +
            ", constant_torque: 8000 N*m}\nscenario: {analysis: transient, end_time: 1 s}\n";
    return text;
}

oc::PlanetaryStageModel smallStage(double ks, double kr) {
    return {kZs, kZp, kZr, 0.01, 20 * kDeg, 3, ks, kr, 2, 30, 20, 0.5, 20};
}

void willis(std::vector<ValidationRow>& rows, const std::string& fixed, const std::string& driven,
            const std::string& loaded) {
    const std::string name = "planetary_stage_willis_" + fixed + "_fixed";
    const Steady st = steadyOfText(stageText(fixed, driven, loaded, ""));
    auto w = [&](const std::string& m) { return m == fixed ? 0.0 : st.speed.at(m); };
    const double ws = w("sun"), wr = w("ring"), wc = w("carrier");
    rows.push_back(compareRow(name, "(w_s - w_c)/(w_r - w_c)", "1", (ws - wc) / (wr - wc), -kZr / kZs, 1e-9,
                              "Willis (Mueller eq 2.1): -z_r/z_s; " + driven + " driven, " + loaded + " loaded"));
    const double oracle = fixed == "carrier" ? oc::willisRingSpeed(kZs, kZr, ws, wc)
                          : fixed == "sun"   ? oc::willisCarrierSpeed(kZs, kZr, ws, wr)
                                             : oc::willisCarrierSpeed(kZs, kZr, ws, wr);
    rows.push_back(compareRow(name, fixed == "carrier" ? "ring speed" : "carrier speed", "rad/s",
                              fixed == "carrier" ? wr : wc, oracle, 1e-9, "third speed from the other two"));
    rows.push_back(compareRow(name, "mesh frequency", "Hz", st.probe.at("stage.mesh_frequency"),
                              oc::planetaryMeshFrequency(kZr, wr, wc), 1e-9, "z_r |w_r - w_c|/(2 pi)"));
}

void loadSharing(std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_stage_load_sharing";
    const Steady st = steadyOfText(stageText("ring", "sun", "carrier",
                                             ", law: compliant, sun_mesh_stiffness: 2e9 N/m, ring_mesh_stiffness: 3e9 "
                                             "N/m, sun_mesh_damping: 1e4 N*s/m, ring_mesh_damping: 1e4 N*s/m, "
                                             "pin_position_errors: [1 um, 0 um, -1 um]"));
    const double Ts = 8000 * kZs / (kZs + kZr);  // ring fixed, steady: the carrier's load over 1 + z_r/z_s
    const oc::PlanetaryStatics h = oc::planetaryStatics(smallStage(2e9, 3e9), Ts, {1e-6, 0, -1e-6});
    for (int k = 0; k < 3; ++k) {
        const std::string p = "p" + std::to_string(k + 1);
        ValidationRow r = compareRow(name, p + " sun mesh force", "N", st.probe.at("stage." + p + ".sun_mesh_force"),
                                     h.meshForce[k], 1e-7, "F_k = T_s/(n r_s) - 2 k_t (e_k - mean e)");
        rows.push_back(r);
    }
    rows.push_back(compareRow(name, "load sharing factor", "1", st.probe.at("stage.load_sharing_factor"),
                              h.loadSharingFactor, 1e-7, "n max F_k / sum F_k, pins at +1, 0, -1 um"));
}

void frequencies(std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_stage_frequencies";
    const Steady st = steadyOfText(
        stageText("ring", "sun", "carrier", ", law: compliant, sun_mesh_stiffness: 2e9 N/m, ring_mesh_stiffness: 3e9 N/m"),
        true);
    const std::vector<double> oracle = oc::torsionalPlanetaryFrequencies(smallStage(2e9, 3e9), 'r');
    std::vector<double> model;
    const double top = st.lm.naturalFrequencies.maxCoeff();
    for (int i = 0; i < st.lm.naturalFrequencies.size(); ++i)
        if (st.lm.naturalFrequencies[i] > 1e-6 * top) model.push_back(st.lm.naturalFrequencies[i]);
    if (model.size() != oracle.size())
        throw std::runtime_error(name + ": " + std::to_string(model.size()) + " elastic modes, the oracle has " +
                                 std::to_string(oracle.size()));
    for (std::size_t i = 0; i < model.size(); ++i)
        rows.push_back(compareRow(name, "natural frequency " + std::to_string(i + 1), "rad/s", model[i], oracle[i],
                                  kFrequencyTolerance, "Lin & Parker torsional model, ring fixed"));
}

// The mill's steady running at full load.
const char* kMill = "/vertical_roller_mill_4p2MW.yaml";
constexpr double kMillZs = 30, kMillZr = 180, kMillRs = 0.33, kMillA = 1.155, kMillMp = 4000;

Steady millSteady(bool linearize) {
    return steadyOf(readModelFile(modelsDirectory() + kMill, defaultModelReader()), linearize);
}

void millStatics(std::vector<ValidationRow>& rows, const Steady& st) {
    const std::string name = "planetary_stage_vrm_statics";
    // The grinding load's torque at the steady table speed (its law: M0 + b ω),
    // carried by the carrier; the ring fixed: T_s = T_L z_s/(z_s + z_r).
    const double wt = st.speed.at("table"), TL = 1.1e6 + 7.3e4 * wt;
    const double Ts = TL * kMillZs / (kMillZs + kMillZr), Ft = Ts / (3 * kMillRs);
    const double wc = st.speed.at("carrier"), centrifugal = kMillMp * kMillA * wc * wc;
    for (const char* p : {"planet1", "planet2", "planet3"}) {
        const std::string stem = std::string("stage.") + p;
        rows.push_back(compareRow(name, std::string(p) + " sun mesh force", "N", st.probe.at(stem + ".sun_mesh_force"),
                                  Ft, kStaticsTolerance, "F_t = T_s/(n r_s)"));
        rows.push_back(compareRow(name, std::string(p) + " ring mesh force", "N",
                                  st.probe.at(stem + ".ring_mesh_force"), Ft, kStaticsTolerance,
                                  "planet moment balance: F_ring = F_sun"));
        rows.push_back(compareRow(name, std::string(p) + " bearing force", "N", st.probe.at(stem + ".bearing_force"),
                                  std::hypot(2 * Ft, centrifugal), kStaticsTolerance,
                                  "2 F_t tangential with the centrifugal m_p a w_c^2 radial"));
    }
    rows.push_back(compareRow(name, "torque on carrier", "N*m", st.probe.at("stage.torque_on_carrier"), TL,
                              kStaticsTolerance, "the grinding torque, through the planet pins"));
    rows.push_back(compareRow(name, "torque on sun", "N*m", st.probe.at("stage.torque_on_sun"), -Ts,
                              kStaticsTolerance, "-T_L z_s/(z_s + z_r)"));
}

void millPlanetMode(std::vector<ValidationRow>& rows, const Steady& st) {
    const std::string name = "planetary_stage_vrm_planet_mode";
    oc::PlanetaryStageModel m{30, 75, 180, 0.022, 20 * kDeg, 3, 8e9, 9e9, 0, 0, 0, 1360, 4000};
    const double w = oc::planetModeFrequency(m);
    int found = 0;
    double nearest = 0;
    for (int i = 0; i < st.lm.naturalFrequencies.size(); ++i) {
        const double v = st.lm.naturalFrequencies[i];
        if (std::abs(v - w) < std::abs(nearest - w)) nearest = v;
        if (std::abs(v - w) <= kFrequencyTolerance * w) ++found;
    }
    rows.push_back(compareRow(name, "planet mode", "rad/s", nearest, w, kFrequencyTolerance,
                              "Lin & Parker: w^2 = (k_s + k_r) cos^2(alpha) r_p^2/J_p, sun, ring, carrier at rest"));
    rows.push_back(compareRow(name, "multiplicity", "1", found, 2, 0, "n - 1 = 2 planet modes"));
}

void bevelRows(std::vector<ValidationRow>& rows, const std::string& name, const Steady& st, const std::string& element,
               const oc::BevelPairModel& m, double pinionTorque) {
    const oc::BevelLoads o = oc::bevelLoads(m, pinionTorque);
    const double tol = kStaticsTolerance;
    auto row = [&](const std::string& what, const std::string& probe, double oracle) {
        ValidationRow r = compareRow(name, what, "N", st.probe.at(element + "." + probe), oracle, tol,
                                     "error relative to W_t");
        rows.push_back(withError(r, std::abs(st.probe.at(element + "." + probe) - oracle) / o.tangential));
    };
    row("tangential force", "tangential_force", o.tangential);
    row("pinion thrust", "pinion_axial_force", o.pinionThrust);
    row("pinion separating force", "pinion_radial_force", o.pinionSeparating);
    row("wheel thrust", "wheel_axial_force", o.gearThrust);
    row("wheel separating force", "wheel_radial_force", o.gearSeparating);
}

void millBevel(std::vector<ValidationRow>& rows, const Steady& st) {
    oc::BevelPairModel m;
    m.pinionTeeth = 17;
    m.gearTeeth = 85;
    m.pinionMeanRadius = 0.16;
    m.shaftAngle = 90 * kDeg;
    m.normalPressureAngle = 20 * kDeg;
    m.spiralAngle = 35 * kDeg;
    m.pinionRightHand = true;
    m.pinionClockwiseFromLargeEnd = st.speed.at("bevel_pinion") < 0;
    // The pinion passes the sun's torque over the bevel ratio (steady, no losses).
    const double wt = st.speed.at("table"), TL = 1.1e6 + 7.3e4 * wt;
    const double Ts = TL * kMillZs / (kMillZs + kMillZr);
    bevelRows(rows, "bevel_vrm_forces", st, "bevel", m, Ts * 17 / 85);
}

void straightBevel(std::vector<ValidationRow>& rows) {
    const std::string text =
        "format_version: 1\nname: bevel\nbodies:\n"
        "  - {name: pinion, inertia: 1.5 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: wheel, inertia: 40 kg*m^2, joint: {type: pin, parent: ground, location: [1 m, 0 m, 0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 3000 N*m, rated_speed: 1485 "
        "rpm, synchronous_speed: 1500 rpm}\n"
        "  - {type: BevelGearPair, name: bevel, bodies: [pinion, wheel], teeth: [17, 53], mean_pitch_radius: 0.1 m, "
        "shaft_angle: 70 deg}\n"
        "  - {type: ResistanceTorque, name: load, body: wheel, constant_torque: 5000 N*m}\n"
        "scenario: {analysis: transient, end_time: 1 s}\n";
    const Steady st = steadyOfText(text);
    oc::BevelPairModel m;
    m.pinionTeeth = 17;
    m.gearTeeth = 53;
    m.pinionMeanRadius = 0.1;
    m.shaftAngle = 70 * kDeg;
    m.normalPressureAngle = 20 * kDeg;
    bevelRows(rows, "bevel_straight_shaft_angle_70", st, "bevel", m, 5000 * 17.0 / 53.0);
    rows.push_back(compareRow("bevel_straight_shaft_angle_70", "speed ratio w1/w2", "1",
                              st.speed.at("pinion") / st.speed.at("wheel"), -53.0 / 17.0, 1e-9,
                              "-z2/z1, both axes away from the apex"));
}

// One shaft's bearing rows: milldyn's ShaftBearings (its x/y_ground in the
// pin frame, which is ground's here) projected on the oracle's y (towards the
// mean point, angle theta) and z (tangential), and its thrust.
void bearingRows(std::vector<ValidationRow>& rows, const std::string& name, const Steady& st,
                 const std::string& element, double theta, const oc::BevelShaftReactions& o, double scale,
                 int locating) {
    const double c = std::cos(theta), s = std::sin(theta);
    auto row = [&](const std::string& what, double model, double oracle) {
        ValidationRow r = compareRow(name, what, "N", model, oracle, kStaticsTolerance, "error relative to W_t");
        rows.push_back(withError(r, std::abs(model - oracle) / scale));
    };
    const std::string b1 = element + ".bearing_1.", b2 = element + ".bearing_2.";
    auto along = [&](const std::string& b, double cy, double cz) {
        return st.probe.at(b + "x_ground") * cy + st.probe.at(b + "y_ground") * cz;
    };
    row(element + " bearing 1 towards the mean point", along(b1, c, s), o.Ay);
    row(element + " bearing 1 tangential", along(b1, -s, c), o.Az);
    row(element + " bearing 2 towards the mean point", along(b2, c, s), o.By);
    row(element + " bearing 2 tangential", along(b2, -s, c), o.Bz);
    row(element + " bearing 1 radial load", st.probe.at(b1 + "radial_load"), o.radialA);
    row(element + " bearing 2 radial load", st.probe.at(b2 + "radial_load"), o.radialB);
    row(element + " thrust (locating bearing " + std::to_string(locating) + ")",
        st.probe.at(element + ".bearing_" + std::to_string(locating) + ".axial_load"), o.thrust);
}

// A spiral bevel (Σ 90°, β 30°) on shafts with bearings, pinion overhung,
// wheel straddle-mounted, the mean points off the frames' x: the bearings'
// forces against the textbook tooth forces and the shafts' statics.
void shaftBearings(std::vector<ValidationRow>& rows, const std::string& hand) {
    const std::string name = "bevel_shaft_bearings_" + hand + "_hand";
    const double thP = 30 * kDeg, thW = 200 * kDeg;
    const std::string text =
        "format_version: 1\nname: bevel bearings\nbodies:\n"
        "  - {name: pinion, inertia: 1.5 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: wheel, inertia: 40 kg*m^2, joint: {type: pin, parent: ground, location: [1 m, 0 m, 0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: pinion, law: linear, rated_torque: 3000 N*m, rated_speed: 1485 "
        "rpm, synchronous_speed: 1500 rpm}\n"
        "  - {type: BevelGearPair, name: bevel, bodies: [pinion, wheel], teeth: [17, 53], mean_pitch_radius: 0.1 m, "
        "spiral_angle: 30 deg, hand: " + hand + ", wheel_axis: towards_apex}\n"
        "  - {type: ResistanceTorque, name: load, body: wheel, constant_torque: 5000 N*m}\n"
        "  - {type: ShaftBearings, name: pinion_bearings, body: pinion, positions: [0.15 m, 0.45 m], mesh: bevel, "
        "mesh_position: 0 m, mesh_angle: 30 deg}\n"
        "  - {type: ShaftBearings, name: wheel_bearings, body: wheel, positions: [-0.3 m, 0.4 m], thrust_bearing: "
        "bearing_2, mesh: bevel, mesh_position: 0.1 m, mesh_angle: 200 deg}\n"
        "scenario: {analysis: transient, end_time: 1 s}\n";
    const Steady st = steadyOfText(text);
    oc::BevelPairModel m;
    m.pinionTeeth = 17;
    m.gearTeeth = 53;
    m.pinionMeanRadius = 0.1;
    m.shaftAngle = 90 * kDeg;
    m.normalPressureAngle = 20 * kDeg;
    m.spiralAngle = 30 * kDeg;
    m.pinionRightHand = hand == "right";
    const double wp = st.speed.at("pinion"), ww = st.speed.at("wheel");
    m.pinionClockwiseFromLargeEnd = wp < 0;
    const oc::BevelLoads f = oc::bevelLoads(m, 5000 * 17.0 / 53.0);
    // Pinion: +z away from the apex, driving (force against its turning);
    // wheel: +z towards the apex (wheel_axis), driven (force with its turning).
    const oc::BevelShaftModel pin{0.15, 0.45, 0, 0.1, 1, wp > 0 ? -1.0 : 1.0};
    const oc::BevelShaftModel whl{-0.3, 0.4, 0.1, 0.1 * 53 / 17, -1, ww > 0 ? 1.0 : -1.0};
    bearingRows(rows, name, st, "pinion_bearings", thP,
                oc::bevelShaftReactions(pin, f.pinionThrust, f.pinionSeparating, f.tangential), f.tangential, 1);
    bearingRows(rows, name, st, "wheel_bearings", thW,
                oc::bevelShaftReactions(whl, f.gearThrust, f.gearSeparating, f.tangential), f.tangential, 2);
}

// The mill's bevel shafts (models/parts/vertical_roller_mill_train.yaml):
// the pinion overhung (mean point at z 0, bearings at 0.3 and 0.8 m, mean
// point below the axis: -90 deg), the sun shaft's wheel between its bearings
// (-0.5 and 0.9 m, the mean point at z 0 towards +x, +z towards the apex).
void millBevelBearings(std::vector<ValidationRow>& rows, const Steady& st) {
    oc::BevelPairModel m;
    m.pinionTeeth = 17;
    m.gearTeeth = 85;
    m.pinionMeanRadius = 0.16;
    m.shaftAngle = 90 * kDeg;
    m.normalPressureAngle = 20 * kDeg;
    m.spiralAngle = 35 * kDeg;
    m.pinionRightHand = true;
    const double wp = st.speed.at("bevel_pinion"), ww = st.speed.at("sun_shaft");
    m.pinionClockwiseFromLargeEnd = wp < 0;
    const double wt = st.speed.at("table"), TL = 1.1e6 + 7.3e4 * wt;
    const double Ts = TL * kMillZs / (kMillZs + kMillZr);
    const oc::BevelLoads f = oc::bevelLoads(m, Ts * 17 / 85);
    const oc::BevelShaftModel pin{0.3, 0.8, 0, 0.16, 1, wp > 0 ? -1.0 : 1.0};
    const oc::BevelShaftModel sun{-0.5, 0.9, 0, 0.8, -1, ww > 0 ? 1.0 : -1.0};
    bearingRows(rows, "bevel_vrm_bearings", st, "pinion_bearings", -90 * kDeg,
                oc::bevelShaftReactions(pin, f.pinionThrust, f.pinionSeparating, f.tangential), f.tangential, 1);
    bearingRows(rows, "bevel_vrm_bearings", st, "sun_shaft_bearings", 0,
                oc::bevelShaftReactions(sun, f.gearThrust, f.gearSeparating, f.tangential), f.tangential, 1);
}

}  // namespace

std::vector<ValidationRow> gearboxCases(const std::string& filter) {
    std::vector<ValidationRow> rows;
    auto want = [&filter](const std::string& name) { return filter.empty() || name.find(filter) != std::string::npos; };
    if (want("planetary_stage_willis_ring_fixed")) willis(rows, "ring", "sun", "carrier");
    if (want("planetary_stage_willis_sun_fixed")) willis(rows, "sun", "carrier", "ring");
    if (want("planetary_stage_willis_carrier_fixed")) willis(rows, "carrier", "sun", "ring");
    if (want("planetary_stage_load_sharing")) loadSharing(rows);
    if (want("planetary_stage_frequencies")) frequencies(rows);
    const bool statics = want("planetary_stage_vrm_statics"), mode = want("planetary_stage_vrm_planet_mode"),
               bevel = want("bevel_vrm_forces"), bearings = want("bevel_vrm_bearings");
    if (statics || mode || bevel || bearings) {
        const Steady st = millSteady(mode);
        if (statics) millStatics(rows, st);
        if (mode) millPlanetMode(rows, st);
        if (bevel) millBevel(rows, st);
        if (bearings) millBevelBearings(rows, st);
    }
    if (want("bevel_straight_shaft_angle_70")) straightBevel(rows);
    for (const std::string hand : {"right", "left"})
        if (want("bevel_shaft_bearings_" + hand + "_hand")) shaftBearings(rows, hand);
    return rows;
}

}  // namespace milldyn
