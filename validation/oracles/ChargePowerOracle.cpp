#include "validation/oracles/ChargePowerOracle.h"

#include <cmath>

namespace milldyn::oracles {

double bondKilowattsPerTonne(const BondBallMill& mill, double cs) {
    // Rowland (1982): kWb = 4.879 D^0.3 (3.2 − 3 V_p) C_s (1 − 0.1/2^(9 − 10 C_s)) + S_s
    return 4.879 * std::pow(mill.diameter, 0.3) * (3.2 - 3 * mill.ballFill) * cs *
               (1 - 0.1 / std::pow(2.0, 9 - 10 * cs)) +
           mill.ballSizeFactor;
}

double bondPower(const BondBallMill& mill, double cs) {
    const double ballTonnes =
        mill.ballFill * M_PI * mill.diameter * mill.diameter / 4 * mill.length * mill.ballBulkDensity / 1000;
    return bondKilowattsPerTonne(mill, cs) * ballTonnes * 1000;
}

double morrellNetPower(const MorrellMill& mill, double phi, double g) {
    const double pi = M_PI;
    const double rm = mill.diameter / 2, L = mill.length, rho = mill.chargeDensity, J = mill.chargeFill;
    // Mill speed N_m [rev/s] from the critical speed 42.3/sqrt(D) rpm.
    const double criticalRpm = 60 / (2 * pi) * std::sqrt(2 * g / mill.diameter);
    const double Nm = phi * criticalRpm / 60;
    // Toe and shoulder (Morrell 1996 Part 2).
    const double phiLimit = 0.35 * (3.364 - J);
    const double phiC = phi > phiLimit ? phi : phiLimit;
    const double thetaT = 2.5307 * (1.2796 - J) * (1 - std::exp(-19.42 * (phiC - phi))) + pi / 2;
    const double thetaS = pi / 2 - (thetaT - pi / 2) * ((0.3386 + 0.1041 * phi) + (1.54 - 2.5673 * phi) * J);
    const double z = std::pow(1 - J, 0.4532);
    // Inner surface of the charge (Part 1): free-fall and circulation times.
    const double rBar = rm / 2 * (1 + std::sqrt(1 - 2 * pi * J / (2 * pi + thetaS - thetaT)));
    const double tf = std::sqrt(2 * rBar * (std::sin(thetaS) - std::sin(thetaT)) / g);
    const double Nbar = Nm / 2;
    const double tc = (2 * pi - thetaT + thetaS) / (2 * pi * Nbar);
    const double beta = tc / (tf + tc);
    const double ri = rm * std::sqrt(1 - 2 * pi * beta * J / (2 * pi + thetaS - thetaT));
    // Net power: potential and kinetic terms (Part 1).
    const double first = pi * g * L * Nm * rm / (3 * (rm - z * ri)) *
                         (2 * std::pow(rm, 3) - 3 * z * rm * rm * ri + std::pow(ri, 3) * (3 * z - 2)) *
                         (rho * (std::sin(thetaS) - std::sin(thetaT)));
    const double second = L * rho * std::pow(Nm * rm * pi / (rm - z * ri), 3) *
                          (std::pow(rm - z * ri, 4) - std::pow(ri, 4) * std::pow(z - 1, 4));
    return first + second;
}

double frozenUnbalanceTorque(double mass, double centroidRadius, double lag, double g) {
    return mass * g * centroidRadius * std::sin(lag);
}

double frozenFallEnergy(double mass, double centroidRadius, double releaseAngle, double g) {
    return mass * g * centroidRadius * (1 - std::cos(releaseAngle));
}

}  // namespace milldyn::oracles
