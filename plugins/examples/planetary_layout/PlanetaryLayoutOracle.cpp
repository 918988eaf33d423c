#include "PlanetaryLayoutOracle.h"

#include <cmath>
#include <stdexcept>

namespace planetary_layout {

namespace {
using Vec = Eigen::Vector2d;
Vec unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
Vec perp(const Vec& v) { return {-v.y(), v.x()}; }  // z × v
double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

PlanetaryLayoutOracle::PlanetaryLayoutOracle(const LayoutParameters& p) : m_p(p) {
    if (!(p.drums >= 1 && p.ringRadius > 0 && p.planetRadius > 0 && p.drumMass > 0 && p.drumInertia > 0 &&
          p.drumRadius > 0 && p.drumLength > 0 && p.bulkDensity > 0 && p.fillHalfAngle > 0 &&
          p.fillHalfAngle <= M_PI && p.carrierInertia > 0 && p.carrierMass >= 0))
        throw std::invalid_argument("PlanetaryLayoutOracle: parameters out of range");
    if (p.internal && !(p.planetRadius < p.ringRadius))
        throw std::invalid_argument("PlanetaryLayoutOracle: internal rolling needs r < R");
}

double PlanetaryLayoutOracle::calcArm() const {
    return m_p.internal ? m_p.ringRadius - m_p.planetRadius : m_p.ringRadius + m_p.planetRadius;
}

double PlanetaryLayoutOracle::calcDrumRateRatio() const {
    // v_P = ω1 a e_t + ω2 (s r) e_t = 0 with P − B = s r e_out.
    const double s = m_p.internal ? 1.0 : -1.0;
    return -calcArm() / (s * m_p.planetRadius);
}

double PlanetaryLayoutOracle::calcChargeMass() const {
    const double g = m_p.fillHalfAngle, rd = m_p.drumRadius;
    return m_p.bulkDensity * m_p.drumLength * rd * rd * (2 * g - std::sin(2 * g)) / 2;
}

double PlanetaryLayoutOracle::calcCentroidDistance() const {
    // First moment of the segment about the chord's normal through B:
    // ∫∫ x dA = (2/3) r³ sin³γ (sector's 2/3 r³ sin γ minus the triangle's).
    const double g = m_p.fillHalfAngle, rd = m_p.drumRadius, sg = std::sin(g);
    return m_p.bulkDensity * m_p.drumLength * 2 * rd * rd * rd * sg * sg * sg / 3 / calcChargeMass();
}

double PlanetaryLayoutOracle::calcChargeAxisInertia() const {
    // Sector r⁴ γ/2 minus the triangle B-chord: b h³/2 + b³ h/6, b = r sin γ, h = r cos γ.
    const double g = m_p.fillHalfAngle, rd = m_p.drumRadius;
    const double b = rd * std::sin(g), h = rd * std::cos(g);
    const double perArea = std::pow(rd, 4) * g / 2 - (b * h * h * h / 2 + b * b * b * h / 6);
    return m_p.bulkDensity * m_p.drumLength * perArea;
}

double PlanetaryLayoutOracle::calcReducedInertia(double q1) const {
    const double a = calcArm(), lambda = calcDrumRateRatio();
    const double mz = calcChargeMass(), lc = calcCentroidDistance(), JBz = calcChargeAxisInertia();
    double J = m_p.carrierInertia;
    for (int k = 0; k < m_p.drums; ++k) {
        const Vec eOut = unit(q1 + m_p.firstDrumAngle + 2 * M_PI * k / m_p.drums);
        const Vec u = unit(m_p.chargeDirection0 + lambda * q1);
        // shell: m_b a² + λ² J_b; charge: m_z |a e_t + λ l_c z×u|² + λ² (J_Bz − m_z l_c²)
        const Vec vc = a * perp(eOut) + lambda * lc * perp(u);
        J += m_p.drumMass * a * a + lambda * lambda * m_p.drumInertia + mz * vc.squaredNorm() +
             lambda * lambda * (JBz - mz * lc * lc);
    }
    return J;
}

double PlanetaryLayoutOracle::calcPotentialEnergy(double q1) const {
    const double a = calcArm(), lambda = calcDrumRateRatio();
    const double mz = calcChargeMass(), lc = calcCentroidDistance();
    double V = 0;
    for (int k = 0; k < m_p.drums; ++k) {
        const Vec b = a * unit(q1 + m_p.firstDrumAngle + 2 * M_PI * k / m_p.drums);
        const Vec c = b + lc * unit(m_p.chargeDirection0 + lambda * q1);
        V += m_p.gravity * (m_p.drumMass * b.y() + mz * c.y());
    }
    return V;
}

LayoutLoads PlanetaryLayoutOracle::calcLoads(double q1, double w1, double e1) const {
    const double a = calcArm(), lambda = calcDrumRateRatio(), s = m_p.internal ? 1.0 : -1.0;
    const double mz = calcChargeMass(), lc = calcCentroidDistance();
    const double M = m_p.drumMass + mz, JB = m_p.drumInertia + calcChargeAxisInertia();
    const double w2 = lambda * w1, e2 = lambda * e1;
    const Vec g(0, -m_p.gravity);
    LayoutLoads out;
    out.carrierForce = -m_p.carrierMass * g;
    out.driveTorque = m_p.carrierInertia * e1;
    for (int k = 0; k < m_p.drums; ++k) {
        const Vec eOut = unit(q1 + m_p.firstDrumAngle + 2 * M_PI * k / m_p.drums), eT = perp(eOut);
        const Vec b = a * eOut;
        const Vec rho = mz * lc * unit(m_p.chargeDirection0 + lambda * q1) / M;  // unit's centre from B
        const Vec aB = a * (e1 * eT - w1 * w1 * eOut);
        const Vec aC = aB + e2 * perp(rho) - w2 * w2 * rho;
        DrumLoads d;
        d.tangentialForce = (JB * e2 + M * cross(rho, aB) - M * cross(rho, g)) / (s * m_p.planetRadius);
        d.separatingForce = std::abs(d.tangentialForce) * std::tan(m_p.pressureAngle);
        const Vec gear = d.tangentialForce * eT - s * d.separatingForce * eOut;
        d.bearingForce = M * aC - M * g - gear;
        out.carrierForce += d.bearingForce;
        out.driveTorque += cross(b, d.bearingForce);
        out.drums.push_back(d);
    }
    return out;
}

double PlanetaryLayoutOracle::calcInitialAcceleration(double steadySpeed, double accelerationTime,
                                                      double timeConstant) {
    // ω(t) = ε0 τ (1 − e^(−t/τ)) = ω_y at t_p.
    return steadySpeed / (timeConstant * (1 - std::exp(-accelerationTime / timeConstant)));
}

}  // namespace planetary_layout
