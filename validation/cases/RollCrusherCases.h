#pragma once
// What the roll-crusher cases (RollCrusherCases.cpp) share with their
// report section (RollCrusherReport.cpp): curves of the multibody model
// and of the oracle, computed the way the cases compare them.

#include <string>
#include <vector>

namespace milldyn {

/// The reducer's dynamic factor against rotor speed, rows in phase: the
/// 2-mass multibody map, the oracle's superposition Σ b_k D(k z Ω)/Σ b_k,
/// and the 10-mass multibody map (a model-to-model comparison), over the
/// speed span of the roll_crusher_resonance_map case.
struct RollCrusherResonanceCurves {
    std::vector<double> speedRpm;                        ///< rotor speed [rpm]
    std::vector<double> multibody2, oracle2, multibody10;  ///< dynamic factor [1]
    double threshold = 0;                                  ///< the scenario's band threshold [1]
};
RollCrusherResonanceCurves computeRollCrusherResonanceMap(int points);

/// The 10-mass chain's first elastic mode shapes, reflected to the motor
/// shaft and scaled so that the largest entry is +1: multibody (Simbody
/// linearization) and the chain oracle's K v = w^2 M v.
struct RollCrusherModeShapes {
    std::vector<std::string> bodies;                         ///< chain order from the motor
    std::vector<double> frequencyMultibody, frequencyOracle;  ///< [rad/s], per mode
    std::vector<std::vector<double>> multibody, oracle;       ///< [mode][body]
};
RollCrusherModeShapes computeRollCrusherModeShapes(int modes);

/// The 2-mass reducer torque amplitude per unit load, D(P), rows in phase:
/// linearized multibody and the corrected eqs (29)-(34).
struct RollCrusherResponseCurves {
    std::vector<double> frequency;           ///< forcing frequency P [rad/s]
    std::vector<double> multibody, oracle;   ///< D [1]
    std::vector<double> printedResonances;   ///< where the misprinted Delta = u^2 - v^2 vanishes [rad/s]
    double beta0 = 0;                        ///< [rad/s]
};
RollCrusherResponseCurves computeRollCrusherResponse(int points);

}  // namespace milldyn
