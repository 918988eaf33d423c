// frequency_response, resonance_map and linearize with the three motor
// models of a DqInductionMotor (scenario.motor_model): dq_states,
// frozen_flux, static_slope.
//
// The train: tests/testdata/dq_belt_crusher_response.yaml, the machine of
// MSL's AIM_SquirrelCage (Krause's fifth-order model) on J1 = 0.3 kg·m², a
// belt k = 1500 N·m/rad, c = 2 N·m·s/rad, ratio n = 3 to J2 = 20 kg·m²
// loaded with 300 N·m, forced on the flywheel by one PeriodicLoad row
// (the load is b·sin(Pt) applied as −that: the generalized force −1 per
// unit b). The expected belt-torque response is computed independently of
// the element (validation/oracles/DqMachineOracle: the textbook's
// equations in currents in the synchronous frame, linearized with the
// chain; no Simbody, no ModelSpec):
//   dq_states:    (iP − A₇)·x̂ = b, A₇ the seven-state Jacobian;
//   static_slope: the three-state chain with the T circuit's dT/dω;
//   frozen_flux:  the three-state chain with no motor term at all
//                 (fluxes held: the torque does not change with the speed),
// written out below.

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

#include "validation/oracles/DqMachineOracle.h"


#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;
using Complex = std::complex<double>;

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata/dq_belt_crusher_response.yaml";

/// The chain of the model file, read from the spec (numbers, not the element).
oc::DqBeltChain chainOf(const ModelSpec& spec, const std::string& loadKey = "mean_torque") {
    oc::DqBeltChain c;
    const ElementSpec& m = *spec.findElement("drive");
    c.machine.rs = m.number("stator_resistance");
    c.machine.rr = m.number("rotor_resistance");
    c.machine.lls = m.number("stator_leakage_inductance");
    c.machine.llr = m.number("rotor_leakage_inductance");
    c.machine.lm = m.number("main_inductance");
    c.machine.polePairs = static_cast<int>(m.number("pole_pairs"));
    c.machine.phaseVoltage = m.number("phase_voltage");
    c.machine.frequency = m.number("frequency");
    c.motorInertia = spec.findBody("motor")->inertia;
    c.flywheelInertia = spec.findBody("flywheel")->inertia;
    const ElementSpec& belt = *spec.findElement("belt");
    c.stiffness = belt.number("stiffness");
    c.damping = belt.number("damping");
    c.ratio = belt.number("ratio");
    c.loadTorque = spec.findElement("crushing")->number(loadKey);
    return c;
}

/// The chain with the machine's torque held (fluxes frozen): J1·dω1/dt =
/// −belt, dφ/dt = ω1 − n·ω2, J2·dω2/dt = n·belt + F.
Complex frozenBeltResponse(const oc::DqBeltChain& c, double P, Complex torque) {
    Eigen::Matrix3d A;
    A << -c.damping / c.motorInertia, -c.stiffness / c.motorInertia, c.damping * c.ratio / c.motorInertia,  //
        1, 0, -c.ratio,                                                                                    //
        c.ratio * c.damping / c.flywheelInertia, c.ratio * c.stiffness / c.flywheelInertia,
        -c.ratio * c.ratio * c.damping / c.flywheelInertia;
    Eigen::Vector3cd b(0, 0, torque / c.flywheelInertia);
    const Eigen::Vector3cd x = (Complex(0, P) * Eigen::Matrix3cd::Identity() - A.cast<Complex>()).fullPivLu().solve(b);
    return c.stiffness * x[1] + c.damping * (x[0] - c.ratio * x[2]);
}

struct ResponseRun {
    AnalysisResult result;
    ModelSpec spec;
};

ResponseRun run(const std::string& motorModel, const std::vector<Override>& more = {}) {
    ResponseRun r;
    std::vector<Override> o = {{"scenario.motor_model", motorModel}, {"outputs.plots", "false"}};
    o.insert(o.end(), more.begin(), more.end());
    r.result = runModelFile(kModel, o, &r.spec);
    return r;
}

/// Compares every row of the frequency response with `expected(P)`, the
/// oracle's belt torque per unit load amplitude (forcing −1 on the flywheel).
template <class Expected>
void expectResponse(const ResponseRun& r, Expected expected, double tolerance) {
    ASSERT_EQ(r.result.rows.size(), 41u);
    double worst = 0;
    for (std::size_t i = 0; i < r.result.rows.size(); ++i) {
        const double P = r.result.value(i, "frequency");
        const Complex model = std::polar(r.result.value(i, "belt.torque.amplitude"), r.result.value(i, "belt.torque.phase"));
        const Complex oracle = expected(P);
        const double err = std::abs(model - oracle) / std::abs(oracle);
        worst = std::max(worst, err);
        EXPECT_LT(err, tolerance) << "at " << P << " rad/s: model " << model << ", oracle " << oracle;
    }
    ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(MotorModelResponse, DqStatesMatchKrausesLinearizedChain) {
    const ResponseRun r = run("dq_states");
    const oc::DqBeltChain c = chainOf(r.spec);
    expectResponse(r, [&](double P) { return oc::dqBeltChainBeltResponse(c, P, -1.0); }, 1e-5);
    // The note says which motor model the damping comes from.
    bool said = false;
    for (const auto& n : r.result.notes) said = said || n.rfind("motor_model dq_states: drive with their flux states", 0) == 0;
    EXPECT_TRUE(said);
}

TEST(MotorModelResponse, StaticSlopeMatchesTheSteadyCurvesSlope) {
    const ResponseRun r = run("static_slope");
    const oc::DqBeltChain c = chainOf(r.spec);
    expectResponse(r, [&](double P) { return oc::dqBeltChainBeltResponse(c, P, -1.0, true); }, 1e-5);
}

TEST(MotorModelResponse, FrozenFluxHasNoMotorTerm) {
    const ResponseRun r = run("frozen_flux");
    const oc::DqBeltChain c = chainOf(r.spec);
    expectResponse(r, [&](double P) { return frozenBeltResponse(c, P, -1.0); }, 1e-5);
}

// The three differ where it matters: at the belt mode the peak dynamic
// factor with the flux states lies between the frozen (no motor damping)
// and the static slope's (most damping), and at a different frequency.
TEST(MotorModelResponse, ThePeaksDifferByModel) {
    const double frozen = run("frozen_flux").result.find("belt.torque.peak_dynamic_factor")->value;
    const double states = run("dq_states").result.find("belt.torque.peak_dynamic_factor")->value;
    const double slope = run("static_slope").result.find("belt.torque.peak_dynamic_factor")->value;
    EXPECT_GT(frozen, states);
    EXPECT_GT(states, slope);
}

// The mode table and linearize's eigenvalues by model against the oracle's.
TEST(MotorModelResponse, LinearizeEigenvaluesPerModel) {
    for (const std::string model : {"dq_states", "static_slope"}) {
        ModelSpec spec;
        const AnalysisResult r =
            runModelFile(std::string(MILLDYN_SOURCE_DIR) + "/models/dq_belt_crusher.yaml",
                         {{"scenario.motor_model", model}, {"outputs.plots", "false"}}, &spec);
        const oc::DqBeltChain c = chainOf(spec, "constant_torque");
        const auto oracle = model == "dq_states" ? oc::dqBeltChainEigenvalues(c) : oc::staticBeltChainEigenvalues(c);
        // The table `eigenvalues` is the chosen model's: every oscillating
        // oracle eigenvalue is there.
        const DataTable* eig = nullptr;
        for (const auto& t : r.extraTables)
            if (t.name == "eigenvalues") eig = &t;
        ASSERT_NE(eig, nullptr);
        int matched = 0;
        for (const Complex& l : oracle) {
            if (l.imag() <= 0) continue;
            double best = 1e300;
            for (const auto& row : eig->rows) best = std::min(best, std::abs(Complex(row[1], row[2]) - l) / std::abs(l));
            EXPECT_LT(best, 1e-5) << model << ": oracle eigenvalue " << l;
            ++matched;
        }
        EXPECT_GT(matched, 0);
        const DataTable* modes = nullptr;
        for (const auto& t : r.extraTables)
            if (t.name == "mode_damping_by_motor_model") modes = &t;
        ASSERT_NE(modes, nullptr);
        ASSERT_EQ(modes->rows.size(), 1u);  // the belt mode
        EXPECT_NEAR(modes->rows[0][2], 0.05, 0.005);  // frozen: about the belt's own damping
    }
}

// Without dq machines the key changes nothing, and a wrong word is refused.
TEST(MotorModelResponse, WrongWordRefused) {
    EXPECT_THROW(run("quasi_static"), std::exception);
}

// The time check integrates the nonlinear machine; with its flux states the
// linear response is what the simulation gives.
TEST(MotorModelResponse, TimeCheckAgreesWithDqStates) {
    const ResponseRun r = run("dq_states", {{"scenario.check_frequencies", "[100 rad/s]"}, {"scenario.points", "41"}});
    ASSERT_NE(r.result.find("time_check_amplitude_rel_diff"), nullptr);
    EXPECT_LT(r.result.find("time_check_amplitude_rel_diff")->value, 1e-3);
    EXPECT_LT(r.result.find("time_check_phase_diff")->value, 1e-3);
}

}  // namespace
}  // namespace milldyn
