#include "validation/oracles/GearPairOracle.h"

#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {

HelicalMeshForces helicalMeshForces(double torque, double r, double phiN, double psi) {
    if (!(r > 0)) throw std::invalid_argument("helicalMeshForces: pitch radius must be > 0");
    HelicalMeshForces f;
    f.tangential = torque / r;
    f.radial = std::abs(f.tangential) * std::tan(phiN) / std::cos(psi);
    f.axial = f.tangential * std::tan(psi);
    f.normal = std::abs(f.tangential) / (std::cos(phiN) * std::cos(psi));
    return f;
}

std::array<double, 4> twoSupportReactions(const std::vector<ShaftLoad>& loads, double zA, double zB) {
    if (zA == zB) throw std::invalid_argument("twoSupportReactions: supports at the same z");
    const double span = zB - zA;
    double sumX = 0, sumY = 0, momX = 0, momY = 0;
    for (const auto& l : loads) {
        sumX += l.fx;
        sumY += l.fy;
        // Moment about the support A line, per plane: lever (z − zA) for the
        // lateral force, plus the couple of the axial force at its offset.
        momX += l.fx * (l.z - zA) - l.fz * l.x;
        momY += l.fy * (l.z - zA) - l.fz * l.y;
    }
    const double rBx = -momX / span, rBy = -momY / span;
    return {-sumX - rBx, -sumY - rBy, rBx, rBy};
}

double meshTorsionalStiffness(double k, double r1, double phiN, double psi) {
    const double alphaT = std::atan(std::tan(phiN) / std::cos(psi));
    const double rb = r1 * std::cos(alphaT);
    return k * rb * rb;
}

}  // namespace milldyn::oracles
