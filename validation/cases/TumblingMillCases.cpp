// Validation of the tumbling ball mill's girth-gear drive (issue 19,
// models/tumbling_ball_mill_3x4m.yaml) against validation/oracles/
// GearPairOracle (textbook statics and vibration, no Simbody):
//  - the girth-gear mesh forces at steady running (tangential from the
//    shell's load torque, radial = tangential · tan α_n / cos β) and both
//    trunnion and both pinion bearing forces against the statics of a
//    rigid shaft on two supports (weight, mesh force at the pitch point in
//    the gear's plane), spur and helical;
//  - the natural frequencies of the geared chain (motor, couplings,
//    reducer mesh, pinion, girth mesh, shell) from `linearize` against the
//    chain reduced to the motor shaft with ratio² (generalized eigenproblem);
//  - the tooth counts derived from pitch radius and module;
//  - the energy balance of a start.

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "validation/cases/ValidationCases.h"
#include "validation/oracles/GearPairOracle.h"
#include "validation/oracles/TumblingMillOracle.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;

// Steady running is solved by Newton to round-off and the bearing split is
// exact statics, so model and oracle differ by round-off of sums of forces
// of order 1e6 N: 1e-8 relative to the shaft's largest load.
constexpr double kStaticsTolerance = 1e-8;
// linearize takes K by central differences of the accelerations (step
// 1e-6 relative): the mesh forces are linear in the angles, so the
// frequencies agree to the eigen-solver's round-off; 1e-6 allows for the
// differences' truncation.
constexpr double kFrequencyTolerance = 1e-6;
// The energy balance residual at integrator accuracy 1e-6 (docs/validation.md: ~1e-7 of the flow).
constexpr double kEnergyTolerance = 1e-6;

const char* kModel = "/tumbling_ball_mill_3x4m.yaml";

ModelSpec readMill() { return readModelFile(modelsDirectory() + kModel, defaultModelReader()); }

ElementSpec& element(ModelSpec& spec, const std::string& name) {
    for (auto& e : spec.elements)
        if (e.name == name) return e;
    throw std::runtime_error(spec.file + ": no element named " + name);
}

const BodySpec& body(const ModelSpec& spec, const std::string& name) {
    for (const auto& b : spec.bodies)
        if (b.name == name) return b;
    throw std::runtime_error(spec.file + ": no body named " + name);
}

/// Probe values by name at `state` (realized to Acceleration).
std::map<std::string, double> probesAt(const Scene& scene, const SimTK::State& state) {
    std::map<std::string, double> v;
    for (const auto& p : scene.probes()) v[p.name] = p.value(state);
    return v;
}

/// A row whose error is taken relative to `scale` (a component may be near
/// zero while the shaft's load is not).
ValidationRow compareScaled(const std::string& caseName, const std::string& quantity, double value, double oracle,
                            double scale, double tolerance) {
    ValidationRow r = compareRow(caseName, quantity, "N", value, oracle, tolerance,
                                 "error relative to the shaft's largest load");
    r = withError(r, std::abs(value - oracle) / scale);
    return r;
}

/// The torque-arm charge held at a constant 40 deg (the model's lag table
/// replaced: the oracle has no interpolation of its own), bearing friction
/// off, the girth gear's helix set. Returns the charge as the oracle
/// states it and its lag.
oc::CircularSegmentCharge prepareStatics(ModelSpec& spec, double helixAngle, double lag) {
    ElementSpec& charge = element(spec, "charge");
    charge.params["lag_table_speed"].given = false;
    charge.params["lag_table_lag"].given = false;
    charge.params["lag"].number = lag;
    charge.params["lag"].given = true;
    for (const char* b : {"trunnions", "pinion_bearings"}) element(spec, b).params["friction_coefficient"].number = 0;
    ElementSpec& gear = element(spec, "girth_gear");
    gear.params["helix_angle"].number = helixAngle;
    if (helixAngle != 0) gear.params["module"].given = false;  // a normal module would not give whole teeth
    return {charge.number("drum_radius"), charge.number("length"), charge.number("bulk_density"),
            charge.number("fill")};
}

void girthGearStatics(std::vector<ValidationRow>& rows, double helixAngle, const std::string& caseName) {
    ModelSpec spec = readMill();
    const double lag = 40 * M_PI / 180;
    const oc::CircularSegmentCharge charge = prepareStatics(spec, helixAngle, lag);
    const double g = -spec.gravity[1];
    // At the running speed the smoothing tanh(ω/ω_ε) is 1 to round-off (ω/ω_ε ≈ 38).
    const double load = oc::torqueArmTorque(charge, lag, g);
    auto scene = buildScene(spec);
    SimTK::State state = solveSteadyState(*scene, initialState(*scene, spec));
    scene->system().realize(state, SimTK::Stage::Acceleration);
    const auto v = probesAt(*scene, state);

    const ElementSpec& gear = element(spec, "girth_gear");
    const double r1 = gear.numbers("pitch_radii")[0], r2 = gear.numbers("pitch_radii")[1];
    const double alpha = gear.number("pressure_angle"), zMesh = gear.number("axial_position");
    // The shell turns forward (+z) and the pinion drives it: torque `load` on the shell.
    const oc::HelicalMeshForces f = oc::helicalMeshForces(load, r2, alpha, helixAngle);
    rows.push_back(compareRow(caseName, "girth gear |tangential force| vs m g r_c sin(40 deg)/r2", "N",
                              std::abs(v.at("girth_gear.tangential_force")), std::abs(f.tangential),
                              kStaticsTolerance));
    rows.push_back(compareRow(caseName, "girth gear radial force vs W_t tan(a_n)/cos(b)", "N",
                              v.at("girth_gear.radial_force"), f.radial, kStaticsTolerance));
    rows.push_back(compareRow(caseName, "girth gear normal force vs W_t/(cos(a_n) cos(b))", "N",
                              v.at("girth_gear.normal_force"), f.normal, kStaticsTolerance));

    const BodySpec& shell = body(spec, "shell");
    const BodySpec& pinion = body(spec, "pinion");
    const double shellMass = shell.mass + oc::segmentMass(charge);  // the charge's weight rests on the shell
    // The pitch point, from the shell's axis towards the pinion's.
    const double dx = pinion.joint.location[0] - shell.joint.location[0];
    const double dy = pinion.joint.location[1] - shell.joint.location[1];
    const double d = std::hypot(dx, dy), ux = dx / d, uy = dy / d;
    // On the shell at P = r2 u: W_t along z × u (forward), W_r away from
    // the pinion (−u), W_a along z for a positive helix (the sign the
    // element documents: F_a = F_t tan β on gear 2 with F_t its tangential
    // force). The pinion takes the opposite at P = −r1 u from its axis.
    const double sign = v.at("girth_gear.tangential_force") >= 0 ? 1.0 : -1.0;
    const double fx = f.tangential * -uy - f.radial * ux, fy = f.tangential * ux - f.radial * uy;
    const double fz = sign * std::abs(f.tangential) * std::tan(helixAngle);
    const auto& trunnions = element(spec, "trunnions").numbers("positions");
    const auto shellR = oc::twoSupportReactions(
        {{0, 0, shell.massCentre[2], 0, -shellMass * g, 0},
         {r2 * ux, r2 * uy, zMesh - shell.joint.location[2], fx, fy, fz}},
        trunnions[0], trunnions[1]);
    const double shellScale = shellMass * g;
    const char* names[4] = {"bearing_1.x_ground", "bearing_1.y_ground", "bearing_2.x_ground", "bearing_2.y_ground"};
    for (int i = 0; i < 4; ++i)
        rows.push_back(compareScaled(caseName, std::string("trunnion ") + names[i] + " vs beam statics",
                                     v.at(std::string("trunnions.") + names[i]), shellR[i], shellScale,
                                     kStaticsTolerance));
    const auto& pb = element(spec, "pinion_bearings").numbers("positions");
    const auto pinionR = oc::twoSupportReactions(
        {{0, 0, pinion.massCentre[2], 0, -pinion.mass * g, 0},
         {-r1 * ux, -r1 * uy, zMesh - pinion.joint.location[2], -fx, -fy, -fz}},
        pb[0], pb[1]);
    const double pinionScale = std::hypot(fx, fy);
    for (int i = 0; i < 4; ++i)
        rows.push_back(compareScaled(caseName, std::string("pinion ") + names[i] + " vs beam statics",
                                     v.at(std::string("pinion_bearings.") + names[i]), pinionR[i], pinionScale,
                                     kStaticsTolerance));
    if (helixAngle != 0) {
        rows.push_back(compareRow(caseName, "pinion thrust vs W_a = W_t tan(b)", "N",
                                  std::abs(v.at("pinion_bearings.axial_load")), std::abs(fz), kStaticsTolerance));
        rows.push_back(compareRow(caseName, "trunnion thrust vs W_a = W_t tan(b)", "N",
                                  std::abs(v.at("trunnions.axial_load")), std::abs(fz), kStaticsTolerance));
    }
}

void chainFrequencies(std::vector<ValidationRow>& rows) {
    const std::string caseName = "tumbling_mill_chain_frequencies";
    ModelSpec spec = readMill();
    spec.scenario = defaultScenario("linearize");
    auto scene = buildScene(spec);
    const SimTK::State state = solveSteadyState(*scene, initialState(*scene, spec));
    const LinearModel lm = linearizeScene(*scene, state);

    // The chain, shaft by shaft, from the model file's numbers.
    const ElementSpec& hs = element(spec, "hs_coupling");
    const ElementSpec& red = element(spec, "reducer");
    const ElementSpec& ls = element(spec, "ls_coupling");
    const ElementSpec& girth = element(spec, "girth_gear");
    auto stage = [](const ElementSpec& e) { return e.numbers("pitch_radii")[1] / e.numbers("pitch_radii")[0]; };
    auto mesh = [](const ElementSpec& e) {
        return oc::meshTorsionalStiffness(e.number("mesh_stiffness"), e.numbers("pitch_radii")[0],
                                          e.number("pressure_angle"), e.number("helix_angle"));
    };
    oc::GearedChain chain;
    for (const char* b : {"motor_shaft", "reducer_input", "reducer_output", "pinion", "shell"})
        chain.inertias.push_back(body(spec, b).inertia);
    // The torque-arm charge turns with the shell: its polar moment about the axis.
    const ElementSpec& charge = element(spec, "charge");
    chain.inertias.back() += oc::segmentAxisInertia({charge.number("drum_radius"), charge.number("length"),
                                                     charge.number("bulk_density"), charge.number("fill")});
    chain.ratios = {hs.number("ratio"), stage(red), ls.number("ratio"), stage(girth)};
    chain.stiffnesses = {hs.number("stiffness"), mesh(red), ls.number("stiffness"), mesh(girth)};
    const std::vector<double> w = oc::gearedChainFrequencies(chain);
    if (lm.naturalFrequencies.size() != static_cast<int>(w.size()))
        throw std::runtime_error(caseName + ": the model has " + std::to_string(lm.naturalFrequencies.size()) +
                                 " modes, the chain " + std::to_string(w.size()));
    for (std::size_t i = 1; i < w.size(); ++i)
        rows.push_back(compareRow(caseName, "natural frequency " + std::to_string(i) + " vs chain eigen (ratio^2)",
                                  "rad/s", lm.naturalFrequencies[static_cast<int>(i)], w[i], kFrequencyTolerance));
}

void teethFromModule(std::vector<ValidationRow>& rows) {
    ModelSpec spec = readMill();
    auto scene = buildScene(spec);
    const ElementSpec& girth = element(spec, "girth_gear");
    std::map<std::string, double> derived;
    for (const auto& d : scene->derivedValues()) derived[d.name] = d.value;
    for (int i = 0; i < 2; ++i)
        rows.push_back(compareRow("tumbling_mill_girth_gear_teeth", "teeth of gear " + std::to_string(i + 1) +
                                                                         " vs 2 r / m",
                                  "1", derived.at("girth_gear.teeth_" + std::to_string(i + 1)),
                                  2 * girth.numbers("pitch_radii")[i] / girth.number("module"), 0));
}

void startEnergy(std::vector<ValidationRow>& rows) {
    const AnalysisResult r = runAnalysis(readMill());
    const double in = r.find("energy_from_sources")->value;
    const double out = r.find("energy_to_loads")->value + r.find("energy_dissipated")->value +
                       r.find("kinetic_energy_change")->value + r.find("potential_energy_change")->value;
    rows.push_back(compareRow("tumbling_mill_start_energy", "energy from the motor vs loads + heat + stored", "J",
                              in, out, kEnergyTolerance,
                              "the shipped start from rest to steady running; the energy meter's integrals"));
}

}  // namespace

std::vector<ValidationRow> tumblingMillCases(const std::string& filter) {
    std::vector<ValidationRow> rows;
    auto want = [&filter](const std::string& name) { return filter.empty() || name.find(filter) != std::string::npos; };
    if (want("tumbling_mill_girth_gear_statics_spur")) girthGearStatics(rows, 0, "tumbling_mill_girth_gear_statics_spur");
    if (want("tumbling_mill_girth_gear_statics_helical"))
        girthGearStatics(rows, 8 * M_PI / 180, "tumbling_mill_girth_gear_statics_helical");
    if (want("tumbling_mill_chain_frequencies")) chainFrequencies(rows);
    if (want("tumbling_mill_girth_gear_teeth")) teethFromModule(rows);
    if (want("tumbling_mill_start_energy")) startEnergy(rows);
    return rows;
}

}  // namespace milldyn
