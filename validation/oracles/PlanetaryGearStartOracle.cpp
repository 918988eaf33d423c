#include "validation/oracles/PlanetaryGearStartOracle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

CatalogueCurve::CatalogueCurve(const CatalogueMotor& m) {
    const double Mn = m.ratedTorque, wc = m.synchronousSpeed;
    double wk = m.breakdownSpeed;
    if (!(wk > 0)) {
        const double sn = (wc - m.ratedSpeed) / wc, l = m.breakdownRatio;
        wk = wc * (1 - sn * (l + std::sqrt(l * l - 1)));
    }
    m_x = {0.0};
    m_y = {m.lockedRotorRatio * Mn};
    if (m.pullUpRatio > 0) {
        m_x.push_back(m.pullUpSpeed);
        m_y.push_back(m.pullUpRatio * Mn);
    }
    m_x.insert(m_x.end(), {wk, m.ratedSpeed, wc});
    m_y.insert(m_y.end(), {m.breakdownRatio * Mn, Mn, 0.0});
    const std::size_t n = m_x.size();
    for (std::size_t k = 0; k + 1 < n; ++k)
        if (!(m_x[k + 1] > m_x[k])) throw std::invalid_argument("CatalogueCurve: speeds not increasing");
    // Fritsch–Carlson: secants, averaged tangents (0 at an extreme), then
    // each interval's tangents scaled into the monotone region α² + β² <= 9.
    std::vector<double> d(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) d[k] = (m_y[k + 1] - m_y[k]) / (m_x[k + 1] - m_x[k]);
    m_m.assign(n, 0.0);
    m_m[0] = d[0];
    m_m[n - 1] = d[n - 2];
    for (std::size_t k = 1; k + 1 < n; ++k) m_m[k] = d[k - 1] * d[k] <= 0 ? 0.0 : 0.5 * (d[k - 1] + d[k]);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (d[k] == 0) {
            m_m[k] = m_m[k + 1] = 0;
            continue;
        }
        const double a = m_m[k] / d[k], b = m_m[k + 1] / d[k], h = a * a + b * b;
        if (h > 9) {
            const double t = 3 / std::sqrt(h);
            m_m[k] = t * a * d[k];
            m_m[k + 1] = t * b * d[k];
        }
    }
}

double CatalogueCurve::operator()(double w) const {
    const std::size_t n = m_x.size();
    if (w <= m_x[0]) return m_y[0];
    if (w >= m_x[n - 1]) return m_y[n - 1] + m_m[n - 1] * (w - m_x[n - 1]);
    std::size_t k = 0;
    while (w > m_x[k + 1]) ++k;
    const double h = m_x[k + 1] - m_x[k], t = (w - m_x[k]) / h;
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
    const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    return h00 * m_y[k] + h10 * h * m_m[k] + h01 * m_y[k + 1] + h11 * h * m_m[k + 1];
}

double calcSmallWrap(const VBelt& b) {
    return kPi - 2 * std::asin(std::abs(b.drivenRadius - b.driverRadius) / b.centreDistance);
}

double calcBeltCapacity(const VBelt& b) {
    const double E = std::exp(b.frictionCoefficient * calcSmallWrap(b));
    return 2 * b.pretension * (E - 1) / (E + 1);
}

double calcSlippingTightTension(const VBelt& b) {
    const double E = std::exp(b.frictionCoefficient * calcSmallWrap(b));
    return 2 * b.pretension * E / (E + 1);
}

PlanetaryMotorStartOracle::PlanetaryMotorStartOracle(const PlanetaryGearParameters& mill, const CatalogueMotor& motor,
                                                     const VBelt& belt, double motorInertia)
    : m_mill(mill), m_motor(motor), m_catalogue(motor), m_belt(belt), m_motorInertia(motorInertia) {
    if (!(belt.centreDistance > std::abs(belt.drivenRadius - belt.driverRadius)))
        throw std::invalid_argument("PlanetaryMotorStartOracle: centreDistance too short for the sheaves");
}

double PlanetaryMotorStartOracle::calcMillInertia() const {
    return 0.5 * (m_mill.calcReducedInertia(0.0) + m_mill.calcReducedInertia(kPi));
}

PlanetaryRunningLoads PlanetaryMotorStartOracle::calcRunningLoads(double w, double phi) const {
    const PlanetaryGearParameters& p = m_mill.getParameters();
    const double kappa = m_mill.calcSpeedRatio();
    const double s = (m_belt.drivenRadius - m_belt.driverRadius) / m_belt.centreDistance;
    const double cb = std::sqrt(1 - s * s);
    const Eigen::Vector2d u(std::cos(m_belt.lineAngle), std::sin(m_belt.lineAngle));  // A toward the motor
    const Eigen::Vector2d n(-u.y(), u.x());                                             // z × u
    // The drums (and the charges rigid with them) turn by κφ in G from
    // hanging at φ = 0.
    PlanetaryGearMotionState st;
    st.carrierAngle = phi;
    st.carrierRate = w;
    st.carrierAcceleration = 0;
    st.chargeDirection = {{-kPi / 2 + kappa * phi, -kPi / 2 + kappa * phi}};
    const PlanetaryGearLoads L = m_mill.calcLoads(st, ChargeMotion::kRotatesWithDrum);
    const double rest = L.driveTorque - L.carrierFrictionTorque;
    // The belt's pull on the carrier's sheave: (T1 + T2) cos β toward the
    // motor, (T1 − T2) sin β across (tight span on the side the torque
    // needs); the ground at A takes it. Fixed point in the torque M.
    PlanetaryRunningLoads out;
    out.driveTorque = rest;
    for (int it = 0; it < 20; ++it) {
        const double dT = out.driveTorque / m_belt.drivenRadius;
        const Eigen::Vector2d pull = 2 * m_belt.pretension * cb * u + dT * s * n;
        out.journalA = L.carrierBearingForce - pull;
        out.driveTorque = rest + out.journalA.norm() * p.frictionCoefficient * p.carrierJournalDiameter / 2;
    }
    out.journalB1 = L.drums[0].bearingForce;
    out.journalB2 = L.drums[1].bearingForce;
    return out;
}

double PlanetaryMotorStartOracle::calcCarrierLoadTorque(double w) const {
    // Over one carrier turn; the frictionless part averages to zero.
    const int samples = 360;
    double sum = 0;
    for (int j = 0; j < samples; ++j) sum += calcRunningLoads(w, 2 * kPi * j / samples).driveTorque;
    return sum / samples;
}

double calcSteadySpeed(const std::function<double(double)>& excess, double lo, double hi) {
    if (!(excess(lo) > 0 && excess(hi) < 0))
        throw std::invalid_argument("calcSteadySpeed: the drive torque does not cross the load in the interval");
    for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        (excess(mid) > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double calcRigidStartTime(double J, const std::function<double(double)>& drive,
                          const std::function<double(double)>& load, double wEnd, int intervals) {
    const int n = std::max(2, intervals + intervals % 2);
    const double h = wEnd / n;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
        const double w = k * h;
        const double excess = drive(w) - load(w);
        if (!(excess > 0)) throw std::invalid_argument("calcRigidStartTime: the drive does not exceed the load");
        sum += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * J / excess;
    }
    return sum * h / 3;
}

double PlanetaryMotorStartOracle::calcSteadyMotorSpeed() const {
    const double i = calcRatio();
    return calcSteadySpeed([&](double wm) { return m_motor(wm) - calcCarrierLoadTorque(wm / i) / i; },
                           0.9 * m_catalogue.ratedSpeed, m_catalogue.synchronousSpeed);
}

double PlanetaryMotorStartOracle::calcStartTime(double fraction, int intervals) const {
    const double i = calcRatio();
    const double J = m_motorInertia + calcMillInertia() / (i * i);
    return calcRigidStartTime(
        J, [&](double wm) { return m_motor(wm); }, [&](double wm) { return calcCarrierLoadTorque(wm / i) / i; },
        fraction * calcSteadyMotorSpeed(), intervals);
}

}  // namespace milldyn::oracles
