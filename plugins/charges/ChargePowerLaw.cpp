#include "plugins/charges/ChargePowerLaw.h"

#include <cmath>
#include <limits>

namespace milldyn {
namespace charge_power {

double calcBondSpeedFactor(double phi) {
    const double a = std::abs(phi);
    // 0.1/2^(9 − 10φ) written as 0.1·2^(10φ − 9): no overflow at large φ.
    return std::max(0.0, a * (1 - 0.1 * std::exp2(10 * a - 9)));
}

double calcBondSpecificPower(double diameter, double fill, double phi, double ballSizeFactor) {
    // kW per tonne of balls = W per kg.
    const double kWb = 4.879 * std::pow(diameter, 0.3) * (3.2 - 3 * fill) * calcBondSpeedFactor(phi) + ballSizeFactor;
    return std::max(0.0, kWb);
}

MorrellCharge calcMorrellCharge(double rm, double J, double phi, double g) {
    MorrellCharge c;
    const double halfPi = M_PI / 2, twoPi = 2 * M_PI;
    const double limit = 0.35 * (3.364 - J);
    const double phiC = phi <= limit ? limit : phi;  // fully centrifuged above the limit
    c.toe = 2.5307 * (1.2796 - J) * (1 - std::exp(-19.42 * (phiC - phi))) + halfPi;
    c.shoulder = halfPi - (c.toe - halfPi) * ((0.3386 + 0.1041 * phi) + (1.54 - 2.5673 * phi) * J);
    c.z = std::pow(1 - J, 0.4532);
    const double active = twoPi + c.shoulder - c.toe;  // the angle the charge's bed spans, + 2π
    const double meanFill = 1 - twoPi * J / active;
    const double drop = std::sin(c.shoulder) - std::sin(c.toe);
    if (!(active > 0) || !(meanFill >= 0) || !(drop >= 0)) return c;
    const double meanRadius = rm / 2 * (1 + std::sqrt(meanFill));
    const double fall = std::sqrt(2 * meanRadius * drop / g);  // t_f
    // β = t_c/(t_f + t_c), t_c = (2π − θ_T + θ_S)/(2π N̄), N̄ = N_m/2,
    // N_m = φ ω_c/(2π), ω_c = sqrt(g/r_m): written as 1/(1 + t_f/t_c) so
    // that it stays finite as φ → 0 (t_c → ∞).
    const double nBar = phi * std::sqrt(g / rm) / twoPi / 2;
    const double beta = 1 / (1 + fall * twoPi * nBar / active);
    const double inner = 1 - twoPi * beta * J / active;
    if (!(inner >= 0)) return c;
    c.innerRadius = rm * std::sqrt(inner);
    c.valid = true;
    return c;
}

double calcMorrellNetPower(double rm, double L, double rho, double J, double phi, double g) {
    const MorrellCharge c = calcMorrellCharge(rm, J, phi, g);
    if (!c.valid) return std::numeric_limits<double>::quiet_NaN();
    const double nm = phi * std::sqrt(g / rm) / (2 * M_PI);  // rev/s
    const double ri = c.innerRadius, z = c.z, d = rm - z * ri;
    const double potential = M_PI * g * L * nm * rm / (3 * d) *
                             (2 * rm * rm * rm - 3 * z * rm * rm * ri + ri * ri * ri * (3 * z - 2)) * rho *
                             (std::sin(c.shoulder) - std::sin(c.toe));
    const double v = nm * rm * M_PI / d;
    const double kinetic = L * rho * v * v * v * (std::pow(d, 4) - std::pow(ri, 4) * std::pow(z - 1, 4));
    return potential + kinetic;
}

}  // namespace charge_power
}  // namespace milldyn
