#pragma once
// A model text two driver tests share: models/start_bench_dq.yaml's machine
// (MSL IMC_DOL, single cage, 50 Hz) on a 2 kg*m^2 shaft against a constant
// 100 N*m, from steady running.

#include <string>

namespace milldyn {

inline const std::string kDqShaft = R"(format_version: 1
name: dq motor and a constant load
bodies:
  - {name: shaft, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: DqInductionMotor, name: motor, body: shaft, stator_resistance: 0.03 ohm, rotor_resistance: 0.04 ohm,
     stator_leakage_inductance: 0.0003239643625499069 H, rotor_leakage_inductance: 0.0003239643625499069 H,
     main_inductance: 0.009225332222963813 H, pole_pairs: 2, phase_voltage: 100 V, frequency: 50 Hz}
  - {type: ResistanceTorque, name: load, body: shaft, constant_torque: 100 N*m}
scenario: {analysis: transient, initial_state: steady, end_time: 1.5 s}
integrator: {name: RungeKuttaMerson, accuracy: 1e-9}
outputs: {sample_interval: 1 ms, plots: false}
)";

}  // namespace milldyn
