// FlexibleRotor on its own (its agreement with the beam oracle is the
// bead_mill validation cases): mass bookkeeping, energy conservation of the
// undamped chain (forces and potential energy agree), static equilibrium
// against hand statics, isotropy in the spin angle, and bad input.

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "plugins/shafts/FlexibleRotor.h"
#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace milldyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

// d = 20 mm, L_p = 0.2 m, 3 discs of 0.1 m x 10 mm from 0.08 m past B at
// 0.04 m pitch, overhang 0.18 m (0.08 + 2·0.04 + 0.02).
const char* kModel = R"(format_version: 1
name: rotor test
gravity: [0 m/s^2, -9.80665 m/s^2, 0 m/s^2]
bodies:
  - {name: pulley, inertia: 0.005 kg*m^2, mass: 2 kg, joint: {type: pin}}
elements:
  - type: FlexibleRotor
    name: rotor
    drive_body: pulley
    shaft_diameter: 20 mm
    span: 0.2 m
    segments: 12
    discs: 3
    disc_diameter: 0.1 m
scenario: {analysis: static_deflection}
)";

constexpr double kDensity = 7850, kD = 0.02, kSpan = 0.2, kOverhang = 0.18, kG = 9.80665;

double discMass() { return kDensity * kPi * 0.1 * 0.1 / 4 * 0.01; }
double shaftMass() { return kDensity * kPi * kD * kD / 4 * (kSpan + kOverhang); }

ModelSpec readRotor(const std::vector<Override>& overrides = {}) {
    return test::readText("rotor.yaml", kModel, overrides);
}

TEST(FlexibleRotor, MassIsShaftPlusDiscs) {
    const ModelSpec spec = readRotor();
    auto scene = buildScene(spec);
    const SimTK::State s = initialState(*scene, spec);
    const double total = scene->matter().calcSystemMass(s) - 2.0;  // without the pulley
    EXPECT_NEAR(total, shaftMass() + 3 * discMass(), 1e-12 * total);
    const auto* rotor = scene->findElement<FlexibleRotor>("rotor");
    ASSERT_NE(rotor, nullptr);
    // Nodes at both bearings, the seal and every disc.
    for (double z : {0.0, kSpan, kSpan + 0.04, kSpan + 0.08, kSpan + 0.12, kSpan + 0.16, kSpan + kOverhang}) {
        bool found = false;
        for (double n : rotor->getNodes()) found = found || std::abs(n - z) < 1e-12;
        EXPECT_TRUE(found) << z;
    }
}

TEST(FlexibleRotor, UndampedChainConservesEnergy) {
    // Released undeformed under gravity: it vibrates about the static line.
    // KE + PE (springs, bearings, gravity) must stay constant: a force that
    // did not derive from calcPotentialEnergy would show here.
    const ModelSpec spec = readRotor({{"elements.rotor.segments", "6"}});
    auto scene = buildScene(spec);
    SimTK::State s = initialState(*scene, spec);
    scene->findBody("pulley")->mobod.setOneU(s, SimTK::MobilizerUIndex(0), 50.0);  // and spinning
    const auto& system = scene->system();
    system.realize(s, SimTK::Stage::Dynamics);
    const double e0 = system.calcEnergy(s);
    const double ke0 = system.calcKineticEnergy(s);
    SimTK::RungeKuttaMersonIntegrator integ(system);
    integ.setAccuracy(1e-9);
    integ.initialize(s);
    SimTK::TimeStepper ts(system, integ);
    ts.initialize(s);
    double peMin = 1e300, peMax = -1e300;
    for (int i = 1; i <= 20; ++i) {
        ts.stepTo(i * 2e-4);
        const SimTK::State& x = integ.getState();
        system.realize(x, SimTK::Stage::Dynamics);
        const double pe = system.calcPotentialEnergy(x);
        peMin = std::min(peMin, pe);
        peMax = std::max(peMax, pe);
        EXPECT_NEAR(system.calcEnergy(x), e0, 1e-6 * (peMax - peMin) + 1e-9 * ke0) << x.getTime();
    }
    EXPECT_GT(peMax - peMin, 0.0);  // it did move
}

TEST(FlexibleRotor, StaticBearingForcesBalanceTheWeight) {
    // Hand statics: R_B·L_p = Σ m·g·z (moments about A), R_A = R_B − W,
    // A pulled down by the overhang.
    const ModelSpec spec = readRotor();
    const AnalysisResult r = runAnalysis(spec);
    double moment = shaftMass() * kG * (kSpan + kOverhang) / 2, weight = (shaftMass() + 3 * discMass()) * kG;
    for (int j = 0; j < 3; ++j) moment += discMass() * kG * (kSpan + 0.08 + 0.04 * j);
    const double RB = moment / kSpan, RA = RB - weight;
    EXPECT_NEAR(r.find("rotor.bearing_B_force")->value, RB, 1e-6 * RB);
    EXPECT_NEAR(r.find("rotor.bearing_A_force")->value, RA, 1e-6 * RB);
    EXPECT_GT(r.find("rotor.end_deflection")->value, 0.0);
    EXPECT_NEAR(r.find("rotor.end_lateral")->value, 0.0, 1e-12);
    EXPECT_LT(r.find("equilibrium_residual")->value, 1e-8);
}

TEST(FlexibleRotor, DeflectionDoesNotDependOnTheSpinAngle) {
    const double at0 = runAnalysis(readRotor()).find("rotor.end_deflection")->value;
    const double at1 =
        runAnalysis(readRotor({{"bodies.pulley.initial_angle", "1.1 rad"}})).find("rotor.end_deflection")->value;
    EXPECT_NEAR(at1, at0, 1e-9 * at0);
}

TEST(FlexibleRotor, DiameterOutsideTheFitIsAnError) {
    // No shaft_diameter and 3 discs: eq (2) has no coefficients for k = 3.
    std::string text = test::replacedIn(kModel, "    shaft_diameter: 20 mm\n", "");
    const ModelSpec spec = test::readText("rotor.yaml", text, {});
    try {
        buildScene(spec);
        ADD_FAILURE() << "accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "rotor.shaft_diameter");
        EXPECT_TRUE(test::contains(e.what(), "eq (2)")) << e.what();
        EXPECT_EQ(e.where().line, 7);  // not written: the element's own place
    }
}

TEST(FlexibleRotor, DiscsBeyondTheShaftEndAreAnError) {
    const ModelSpec spec = readRotor({{"elements.rotor.overhang", "0.1 m"}});
    try {
        buildScene(spec);
        ADD_FAILURE() << "accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "rotor.overhang");
    }
}

}  // namespace
}  // namespace milldyn
