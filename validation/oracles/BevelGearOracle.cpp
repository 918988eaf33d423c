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

BevelShaftReactions bevelShaftReactions(const BevelShaftModel& m, double thrust, double separating, double tangential) {
    BevelShaftReactions out;
    const double span = m.bearingB - m.bearingA, arm = m.meshPosition - m.bearingA;
    const double Fx = m.apexSide * thrust, Fy = -separating, Fz = m.tangentialSense * tangential;
    // xy plane, moments about A (+z): span·B_y + arm·F_y − r·F_x = 0.
    out.By = (m.meanRadius * Fx - arm * Fy) / span;
    out.Ay = -Fy - out.By;
    // xz plane, moments about A (+y): −span·B_z − arm·F_z = 0.
    out.Bz = -arm * Fz / span;
    out.Az = -Fz - out.Bz;
    out.radialA = std::hypot(out.Ay, out.Az);
    out.radialB = std::hypot(out.By, out.Bz);
    out.thrust = -Fx;
    return out;
}

}  // namespace milldyn::oracles
