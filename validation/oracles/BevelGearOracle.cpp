#include "validation/oracles/BevelGearOracle.h"

#include <cmath>

namespace milldyn::oracles {

BevelLoads bevelLoads(const BevelPairModel& m, double pinionTorque) {
    BevelLoads out;
    out.pinionPitchAngle = std::atan(std::sin(m.shaftAngle) / (m.gearTeeth / m.pinionTeeth + std::cos(m.shaftAngle)));
    out.gearPitchAngle = m.shaftAngle - out.pinionPitchAngle;
    out.speedRatio = m.gearTeeth / m.pinionTeeth;
    const double wt = std::abs(pinionTorque) / m.pinionMeanRadius;
    out.tangential = wt;
    const double g = out.pinionPitchAngle, G = out.gearPitchAngle, psi = m.spiralAngle;
    const double t = std::tan(m.normalPressureAngle);
    // Upper signs: RH driving clockwise, or LH counterclockwise (from the large end).
    const bool upper = m.pinionRightHand == m.pinionClockwiseFromLargeEnd;
    const double pm = upper ? 1.0 : -1.0;  // the "±" of the formulas; "∓" is −pm
    const double c = wt / std::cos(psi);
    out.pinionThrust = c * (t * std::sin(g) - pm * std::sin(psi) * std::cos(g));
    out.pinionSeparating = c * (t * std::cos(g) + pm * std::sin(psi) * std::sin(g));
    out.gearThrust = c * (t * std::sin(G) + pm * std::sin(psi) * std::cos(G));
    out.gearSeparating = c * (t * std::cos(G) - pm * std::sin(psi) * std::sin(G));
    return out;
}

}  // namespace milldyn::oracles
