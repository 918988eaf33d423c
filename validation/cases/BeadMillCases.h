#pragma once
// Helpers of the bead mill cases, shared with the study that makes the
// tables and plots of docs/bead_mill.md (bench/bead_mill_study.cpp).

#include "driver/ModelSpec.h"
#include "validation/oracles/BeadMillOracle.h"

#include <string>

namespace milldyn::beadmill {

/// The two shipped rotors: 0 = 5 discs of 0.1 m, 1 = 8 discs of 0.3 m.
ModelSpec readRotor(int which);
/// Short tag of a shipped rotor ("5disc_0p1m").
std::string rotorTag(int which);
/// The model's FlexibleRotor element (throws if there is none).
ElementSpec& rotorElement(ModelSpec& spec);
const ElementSpec& rotorElement(const ModelSpec& spec);

/// The FlexibleRotor element's rotor as the oracle states it (adapter).
oracles::BeadMillShaft oracleShaft(const ElementSpec& rotor);
/// g [m/s^2] of a model whose gravity is along −y (throws otherwise).
double gravityOf(const ModelSpec& spec);
/// Running speed at 10 m/s disc tip speed [rad/s].
double runningSpeed(const ElementSpec& rotor);

struct StaticResult {
    double seal = 0, end = 0;  ///< deflection along gravity [m]
    int segments = 0;          ///< segments built
    double seconds = 0;        ///< wall time of the analysis [s]
};
/// The static_deflection analysis of `spec`.
StaticResult runStatic(ModelSpec spec);

struct BendingResult {
    double omega = 0;    ///< first bending natural frequency at rest [rad/s]
    double seconds = 0;  ///< wall time (build + linearize) [s]
};
/// The lowest natural frequency whose mode moves the overhang end sideways.
BendingResult firstBending(const ModelSpec& spec);

}  // namespace milldyn::beadmill
