// The dq machine oracle (validation/oracles/DqMachineOracle) against
// independent computations: its held response against the T equivalent
// circuit of StartOracle (a different formula: the rotor's copper loss over
// the slip, 3·|I_r|²·(Rr/s)/(ω_s/p)), its transient settling onto that
// response, the energy its transient keeps, and its bad input.

#include "validation/oracles/DqMachineOracle.h"
#include "validation/oracles/StartOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {
namespace {

// Modelica MSL's IM_SquirrelCageData (models/start_bench_dq.yaml).
DqMachine mslMachine() {
    const double w = 2 * M_PI * 50, k = std::sqrt(1 - 0.0667);
    return {0.03, 0.04, 3 * (1 - k) / w, 3 * (1 - k) / w, 3 * k / w, 2, 100, 50};
}

TEST(DqMachineOracle, HeldResponseIsTheEquivalentCircuitTimesVoltageSquared) {
    const DqMachine m = mslMachine();
    for (double s : {1.0, 0.5, 0.2, 0.04}) {
        const double circuit = equivalentCircuitTorque(s, m.rs, m.rr, m.lls, m.llr, m.lm, m.polePairs, m.phaseVoltage, m.frequency);
        EXPECT_NEAR(dqHeldResponse(m, s, 1.0, 0.0).torque, circuit, 1e-10 * circuit) << s;
        EXPECT_NEAR(dqHeldResponse(m, s, 1 / std::sqrt(3.0), 0.0).torque, circuit / 3, 1e-10 * circuit) << s;
        // Current ∝ V: the circuit's |V/Z| at half the voltage.
        EXPECT_NEAR(dqHeldResponse(m, s, 0.5, 0.0).statorCurrent, 0.5 * dqHeldResponse(m, s, 1.0, 0.0).statorCurrent, 1e-9);
    }
}

TEST(DqMachineOracle, LockedRotorTransientSettlesOntoTheHeldResponse) {
    // J = 1e15: the rotor stays at rest (s = 1); the switch-on DC flux
    // decays with Ls/Rs + Lr/Rr ≈ 0.55 s, so after 9 s it is ~1e-7 of it.
    const DqMachine m = mslMachine();
    const auto run = dqMachineStart(m, {}, 1e15, [](double) { return 0.0; }, 1e-5, 9.0, 100000);
    const DqHeldResponse held = dqHeldResponse(m, 1.0, 1.0, 0.0);
    EXPECT_NEAR(run.back().torque, held.torque, 1e-5 * held.torque);
    EXPECT_NEAR(run.back().statorCurrent, held.statorCurrent, 1e-5 * held.statorCurrent);
    // The soft start's ramp at standstill: i = u·I0 + u'·I1 once settled.
    DqSupply soft;
    soft.kind = DqSupply::Kind::SoftStart;
    soft.initialVoltage = 0.2;
    soft.rampTime = 20;
    const auto ramp = dqMachineStart(m, soft, 1e15, [](double) { return 0.0; }, 1e-5, 9.0, 100000);
    const double u = 0.2 + 0.8 * 9.0 / 20;
    const DqHeldResponse lagged = dqHeldResponse(m, 1.0, u, 0.8 / 20);
    EXPECT_NEAR(ramp.back().torque, lagged.torque, 1e-5 * lagged.torque);
    // ... which is not the V² law alone: the lag (1.4e-4 of the torque here)
    // is more than ten times the settling tolerance above.
    EXPECT_GT(std::abs(lagged.torque - u * u * held.torque), 10 * 1e-5 * lagged.torque);
}

TEST(DqMachineOracle, FreeStartKeepsItsEnergyAndRunsUpToNearSynchronous) {
    // A free start of an inertia: ∫P_in dt = ∫P_cu dt + ½Jω² + W_field(end).
    // Trapezoidal sums of the 10 µs samples: their error on the 50/100 Hz
    // ripple is at most ~(ω·h)²/12 ≈ 1e-6 of the energies (seen 5.5e-9).
    const DqMachine m = mslMachine();
    const double J = 2, h = 1e-5;
    const auto run = dqMachineStart(m, {}, J, [](double) { return 0.0; }, h, 2.0, 1);
    double in = 0, cu = 0;
    for (std::size_t i = 1; i < run.size(); ++i) {
        in += 0.5 * h * (run[i].inputPower + run[i - 1].inputPower);
        cu += 0.5 * h * (run[i].copperLoss + run[i - 1].copperLoss);
    }
    const double kinetic = 0.5 * J * run.back().speed * run.back().speed;
    EXPECT_NEAR(in, cu + kinetic + run.back().fieldEnergy, 1e-7 * in);  // seen 5.5e-9
    // The field at the end is about the no-load magnetising field (3/4)·Ls·|V̂/(ω_e·Ls)|².
    const double ls = m.lls + m.lm, noLoad = 0.75 * ls * std::pow(std::sqrt(2.0) * 100 / (2 * M_PI * 50 * ls), 2);
    EXPECT_NEAR(run.back().fieldEnergy, noLoad, 0.05 * noLoad);
    const double ws = 2 * M_PI * 50 / 2;
    EXPECT_NEAR(run.back().speed, ws, 1e-3 * ws);
}

TEST(DqMachineOracle, RejectsAStepThatMissesTheSwitchAndATimeToNowhere) {
    DqSupply sd;
    sd.kind = DqSupply::Kind::StarDelta;
    sd.switchTime = 1.000005;
    EXPECT_THROW(dqMachineStart(mslMachine(), sd, 1, [](double) { return 0.0; }, 1e-5 * 1.1, 2, 1), std::invalid_argument);
    EXPECT_THROW(dqMachineStart(mslMachine(), {}, 1, [](double) { return 0.0; }, 0, 2, 1), std::invalid_argument);
    std::vector<DqSample> flat(3);
    EXPECT_TRUE(std::isnan(dqTimeToFraction({}, 0.95)));
    flat[0].time = 0, flat[1].time = 1, flat[2].time = 2;
    flat[1].speed = 1, flat[2].speed = 2;
    EXPECT_DOUBLE_EQ(dqTimeToFraction(flat, 0.75), 1.5);
}

}  // namespace
}  // namespace milldyn::oracles
