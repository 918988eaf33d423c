#include "validation/oracles/PlanetaryBeltOracle.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn::oracles {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

std::string formatValue(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

[[noreturn]] void fail(const std::string& name, double value, const std::string& unit, const std::string& rule) {
    throw std::invalid_argument(name + " = " + formatValue(value) + (unit.empty() ? "" : " " + unit) +
                                ": must be " + rule);
}

void requirePositive(const std::string& name, double value, const std::string& unit) {
    if (!(std::isfinite(value) && value > 0.0)) fail(name, value, unit, "finite and > 0");
}

void requireNonNegative(const std::string& name, double value, const std::string& unit) {
    if (!(std::isfinite(value) && value >= 0.0)) fail(name, value, unit, "finite and >= 0");
}

void requireHalfAngle(const std::string& name, double halfAngle) {
    if (!(std::isfinite(halfAngle) && halfAngle > 0.0 && halfAngle < kPi))
        fail(name, halfAngle, "rad", "in the open interval (0, pi)");
}

// x − sin x on [0, 2π]. For small x the difference cancels almost entirely,
// so the Taylor series (alternating, terms falling by x²/((2n+4)(2n+5))) is
// summed instead; at x = 1 both routes agree to a few ulp.
double xMinusSin(double x) {
    if (x >= 2.0 * kSegmentSeriesHalfAngle) return x - std::sin(x);
    const double x2 = x * x;
    double term = x * x2 / 6.0;
    double sum = term;
    for (int n = 0; n < 30; ++n) {
        term *= -x2 / ((2.0 * n + 4.0) * (2.0 * n + 5.0));
        sum += term;
        if (std::abs(term) <= 1e-18 * std::abs(sum)) break;
    }
    return sum;
}

struct Vec2 {
    double x = 0;
    double y = 0;
};
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double wrapAngle(double angle) {
    double wrapped = std::fmod(angle, kTwoPi);
    if (wrapped < 0.0) wrapped += kTwoPi;
    return wrapped >= kTwoPi ? 0.0 : wrapped;
}

// Golden-section search for the maximum of f on [a, b].
template <class F>
double goldenMax(F f, double a, double b) {
    const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - invPhi * (b - a);
    double d = a + invPhi * (b - a);
    double fc = f(c);
    double fd = f(d);
    for (int i = 0; i < 200 && (b - a) > 1e-12; ++i) {
        if (fc >= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - invPhi * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + invPhi * (b - a);
            fd = f(d);
        }
    }
    return 0.5 * (a + b);
}

// Global maximum of a smooth 2π-periodic f: dense samples bracket every
// local maximum (R_A² is a trigonometric polynomial of degree 2 in φ, so it
// has at most two), each is refined, and the best is kept.
template <class F>
double periodicArgMax(F f) {
    constexpr int kSamples = 720;
    const double step = kTwoPi / kSamples;
    std::vector<double> values(kSamples);
    for (int i = 0; i < kSamples; ++i) values[i] = f(i * step);
    double bestAngle = 0.0;
    double bestValue = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < kSamples; ++i) {
        const double here = values[i];
        if (here < values[(i + kSamples - 1) % kSamples] || here < values[(i + 1) % kSamples]) continue;
        double angle = goldenMax(f, (i - 1) * step, (i + 1) * step);
        double value = f(angle);
        if (value < here) {
            angle = i * step;
            value = here;
        }
        if (value > bestValue) {
            bestValue = value;
            bestAngle = angle;
        }
    }
    return wrapAngle(bestAngle);
}

}  // namespace

PlanetaryBeltMaterial suggestedSteelDrumMaterial() {
    PlanetaryBeltMaterial material;
    material.drumLength = 1.0;
    material.shellThickness = 0.010;
    material.coverThickness = 0.015;
    material.sheaveThickness = 0.050;
    material.drumDensity = 7850.0;
    material.chargeDensity = 7800.0;
    material.bulkFraction = 0.6;
    material.gravity = 9.80665;
    return material;
}

void validate(const PlanetaryBeltGeometry& geometry) {
    requirePositive("PlanetaryBeltGeometry.drumRadius (r_b)", geometry.drumRadius, "m");
    requirePositive("PlanetaryBeltGeometry.drumSheaveRadius (r_A)", geometry.drumSheaveRadius, "m");
    requirePositive("PlanetaryBeltGeometry.fixedSheaveRadius (r0)", geometry.fixedSheaveRadius, "m");
    requirePositive("PlanetaryBeltGeometry.carrierArm (l_OA)", geometry.carrierArm, "m");
    const double sinBeta = std::abs(geometry.fixedSheaveRadius - geometry.drumSheaveRadius) / geometry.carrierArm;
    if (sinBeta > 1.0)
        throw std::invalid_argument("PlanetaryBeltGeometry.carrierArm (l_OA) = " + formatValue(geometry.carrierArm) +
                                    " m: too short for the sheaves, sin(beta) = |r0 - r_A|/l_OA (5) = " +
                                    formatValue(sinBeta) + " > 1 (r0 = " + formatValue(geometry.fixedSheaveRadius) +
                                    " m, r_A = " + formatValue(geometry.drumSheaveRadius) + " m)");
}

void validate(const PlanetaryBeltMaterial& material) {
    requirePositive("PlanetaryBeltMaterial.drumLength (L)", material.drumLength, "m");
    requirePositive("PlanetaryBeltMaterial.shellThickness (delta)", material.shellThickness, "m");
    requireNonNegative("PlanetaryBeltMaterial.coverThickness (delta_c)", material.coverThickness, "m");
    requireNonNegative("PlanetaryBeltMaterial.sheaveThickness (h_s)", material.sheaveThickness, "m");
    requirePositive("PlanetaryBeltMaterial.drumDensity (rho_b)", material.drumDensity, "kg/m^3");
    requirePositive("PlanetaryBeltMaterial.chargeDensity (rho_z)", material.chargeDensity, "kg/m^3");
    if (!(std::isfinite(material.bulkFraction) && material.bulkFraction > 0.0 && material.bulkFraction <= 1.0))
        fail("PlanetaryBeltMaterial.bulkFraction", material.bulkFraction, "", "in (0, 1]");
    requireNonNegative("PlanetaryBeltMaterial.gravity (g)", material.gravity, "m/s^2");
}

PlanetaryBeltCriteria criteriaFromGeometry(const PlanetaryBeltGeometry& geometry, CriterionCReading reading) {
    validate(geometry);
    PlanetaryBeltCriteria criteria;
    criteria.k = geometry.drumSheaveRadius / (geometry.carrierArm + geometry.drumSheaveRadius);
    criteria.b = geometry.drumRadius / geometry.drumSheaveRadius;
    criteria.c = reading == CriterionCReading::R0OverRA ? geometry.fixedSheaveRadius / geometry.drumSheaveRadius
                                                        : geometry.drumSheaveRadius / geometry.fixedSheaveRadius;
    return criteria;
}

PlanetaryBeltGeometry geometryFromCriteria(const PlanetaryBeltCriteria& criteria, double drumRadius,
                                           CriterionCReading reading) {
    if (!(std::isfinite(criteria.k) && criteria.k > 0.0 && criteria.k < 1.0))
        fail("PlanetaryBeltCriteria.k (6)", criteria.k, "", "in the open interval (0, 1)");
    requirePositive("PlanetaryBeltCriteria.b (7)", criteria.b, "");
    requirePositive("PlanetaryBeltCriteria.c (8)", criteria.c, "");
    requirePositive("drumRadius (r_b)", drumRadius, "m");
    PlanetaryBeltGeometry geometry;
    geometry.drumRadius = drumRadius;
    geometry.drumSheaveRadius = drumRadius / criteria.b;
    geometry.carrierArm = geometry.drumSheaveRadius * (1.0 - criteria.k) / criteria.k;
    geometry.fixedSheaveRadius = reading == CriterionCReading::R0OverRA ? criteria.c * geometry.drumSheaveRadius
                                                                        : geometry.drumSheaveRadius / criteria.c;
    validate(geometry);
    return geometry;
}

double calcSinBeltAngle(const PlanetaryBeltGeometry& geometry) {
    validate(geometry);
    return std::abs(geometry.fixedSheaveRadius - geometry.drumSheaveRadius) / geometry.carrierArm;
}

PlanetaryBeltKinematics calcKinematics(const PlanetaryBeltGeometry& geometry, double carrierRate) {
    validate(geometry);
    if (!std::isfinite(carrierRate)) fail("carrierRate (Omega)", carrierRate, "rad/s", "finite");
    const double rA = geometry.drumSheaveRadius;
    const double r0 = geometry.fixedSheaveRadius;
    const double arm = geometry.carrierArm;
    PlanetaryBeltKinematics kinematics;
    kinematics.carrierSpeedAtA = carrierRate * arm;
    // Through the belt, independently of (1)–(4): relative to the carrier the
    // fixed sheave turns at −Ω, and the belt passes that on as −Ω·r0/r_A.
    kinematics.relativeRate = -carrierRate * r0 / rA;
    kinematics.drumRate = carrierRate * (rA - r0) / rA;
    // Kept as the inverse so that r0 → r_A stays finite; only its exact zero
    // means translation, and any representable r0 − r_A ≠ 0 gives a finite
    // l_AD unless the radii themselves are near underflow.
    kinematics.inverseCentreOffset = (r0 - rA) / (rA * arm);
    const double offset = rA * arm / (r0 - rA);
    kinematics.hasInstantaneousCentre = r0 != rA && std::isfinite(offset);
    kinematics.centreOffsetFromA = kinematics.hasInstantaneousCentre ? offset : 0.0;
    return kinematics;
}

double calcSegmentArea(double drumRadius, double halfAngle) {
    requirePositive("drumRadius (r_b)", drumRadius, "m");
    requireHalfAngle("halfAngle (gamma)", halfAngle);
    return 0.5 * drumRadius * drumRadius * xMinusSin(2.0 * halfAngle);
}

double calcSegmentCentroidDistance(double drumRadius, double halfAngle) {
    requirePositive("drumRadius (r_b)", drumRadius, "m");
    requireHalfAngle("halfAngle (gamma)", halfAngle);
    const double s = std::sin(halfAngle);
    return 4.0 * drumRadius * s * s * s / (3.0 * xMinusSin(2.0 * halfAngle));
}

double calcFillDegree(double halfAngle) {
    requireHalfAngle("halfAngle (gamma)", halfAngle);
    return xMinusSin(2.0 * halfAngle) / kTwoPi;
}

double calcHalfAngleFromFill(double fill) {
    if (!(std::isfinite(fill) && fill > 0.0 && fill < 1.0)) fail("fill", fill, "", "in the open interval (0, 1)");
    // Solve h(x) = x − sin x − 2π·fill = 0 for x = 2γ ∈ (0, 2π); h is
    // increasing, so a bracket plus Newton (falling back to bisection when a
    // step leaves the bracket) cannot miss.
    const double target = kTwoPi * fill;
    double lo = 0.0;
    double hi = kTwoPi;
    double x = fill < 0.5 ? std::cbrt(6.0 * target) : kTwoPi - std::cbrt(6.0 * (kTwoPi - target));
    x = std::min(std::max(x, 0.0), kTwoPi);
    for (int i = 0; i < 200; ++i) {
        const double h = xMinusSin(x) - target;
        if (h == 0.0) break;
        if (h < 0.0) lo = x; else hi = x;
        const double slope = 1.0 - std::cos(x);
        double next = slope > 0.0 ? x - h / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * x) {
            x = next;
            break;
        }
        x = next;
    }
    return 0.5 * x;
}

PlanetaryBeltMasses calcMasses(const PlanetaryBeltGeometry& geometry, const PlanetaryBeltMaterial& material,
                               double segmentHalfAngle) {
    validate(geometry);
    validate(material);
    requireHalfAngle("segmentHalfAngle (gamma)", segmentHalfAngle);
    const double rb = geometry.drumRadius;
    const double outer = rb + material.shellThickness;
    const double rhoB = material.drumDensity;
    PlanetaryBeltMasses masses;
    masses.shell = rhoB * kPi * (outer * outer - rb * rb) * material.drumLength;
    masses.covers = 2.0 * rhoB * kPi * outer * outer * material.coverThickness;
    masses.sheave = rhoB * kPi * geometry.drumSheaveRadius * geometry.drumSheaveRadius * material.sheaveThickness;
    masses.drum = masses.shell + masses.covers + masses.sheave;
    masses.charge = material.chargeDensity * calcSegmentArea(rb, segmentHalfAngle) * material.drumLength *
                    material.bulkFraction;
    return masses;
}

PlanetaryBeltOracle::PlanetaryBeltOracle(const PlanetaryBeltParameters& parameters) : m_parameters(parameters) {
    if (!(std::isfinite(parameters.carrierRate) && parameters.carrierRate >= 0.0))
        fail("PlanetaryBeltParameters.carrierRate (Omega)", parameters.carrierRate, "rad/s",
             "finite and >= 0 (the charge-lag side assumes counter-clockwise)");
    requireHalfAngle("PlanetaryBeltParameters.segmentHalfAngle (gamma)", parameters.segmentHalfAngle);
    if (!(std::isfinite(parameters.chargeLag) && parameters.chargeLag >= 0.0 && parameters.chargeLag <= kPi))
        fail("PlanetaryBeltParameters.chargeLag (alpha)", parameters.chargeLag, "rad", "in [0, pi]");
    m_masses = calcMasses(parameters.geometry, parameters.material, parameters.segmentHalfAngle);
    m_kinematics = calcKinematics(parameters.geometry, parameters.carrierRate);
    m_sinBeltAngle = calcSinBeltAngle(parameters.geometry);
    m_chargeCentroidDistance =
        calcSegmentCentroidDistance(parameters.geometry.drumRadius, parameters.segmentHalfAngle);
    const double omega2 = parameters.carrierRate * parameters.carrierRate;
    const double drumRate = m_kinematics.drumRate;
    m_inertialForces.drumTransport = m_masses.drum * omega2 * parameters.geometry.carrierArm;
    m_inertialForces.chargeTransport = m_masses.charge * omega2 * parameters.geometry.carrierArm;
    m_inertialForces.chargeRelative = m_masses.charge * drumRate * drumRate * m_chargeCentroidDistance;
}

double PlanetaryBeltOracle::getDrumWeight() const { return m_masses.drum * m_parameters.material.gravity; }

double PlanetaryBeltOracle::getChargeWeight() const { return m_masses.charge * m_parameters.material.gravity; }

PaperReaction PlanetaryBeltOracle::calcPaperReaction(double carrierAngle) const {
    if (!std::isfinite(carrierAngle)) fail("carrierAngle (phi)", carrierAngle, "rad", "finite");
    const double alpha = m_parameters.chargeLag;
    const double lAc = m_chargeCentroidDistance;
    const double rA = m_parameters.geometry.drumSheaveRadius;
    const double sinBeta = m_sinBeltAngle;
    const double cosBeta = std::sqrt(1.0 - sinBeta * sinBeta);
    const double gb = getDrumWeight();
    const double gz = getChargeWeight();
    const double sinPhi = std::sin(carrierAngle);
    const double cosPhi = std::cos(carrierAngle);
    const PlanetaryBeltInertialForces& f = m_inertialForces;
    const double momentForce =
        m_parameters.momentReading == MomentForceReading::TransportCharge ? f.chargeTransport : f.chargeRelative;

    PaperReaction reaction;
    reaction.slackTension = (momentForce * lAc * std::cos(alpha) - gz * lAc * sinPhi) / rA;
    reaction.tightTension = kTightToSlackRatio * reaction.slackTension;
    reaction.xA = f.drumTransport + f.chargeTransport + f.chargeRelative * std::sin(alpha) - (gb + gz) * sinPhi -
                  (kTightToSlackRatio + 1.0) * reaction.slackTension * cosBeta;
    reaction.yA = f.chargeRelative * std::cos(alpha) + (gb + gz) * cosPhi -
                  (kTightToSlackRatio - 1.0) * reaction.slackTension * sinBeta;
    reaction.rA = std::hypot(reaction.xA, reaction.yA);
    return reaction;
}

RebuiltReaction PlanetaryBeltOracle::calcRebuiltReaction(double carrierAngle, ChargeInertia chargeInertia) const {
    if (!std::isfinite(carrierAngle)) fail("carrierAngle (phi)", carrierAngle, "rad", "finite");
    const PlanetaryBeltGeometry& geo = m_parameters.geometry;
    const double omega2 = m_parameters.carrierRate * m_parameters.carrierRate;
    const double drumRate2 = m_kinematics.drumRate * m_kinematics.drumRate;
    const double g = m_parameters.material.gravity;
    const double mb = m_masses.drum;
    const double mz = m_masses.charge;

    const Vec2 pA{geo.carrierArm, 0.0};
    const Vec2 toCentroid{std::sin(m_parameters.chargeLag), -std::cos(m_parameters.chargeLag)};
    const Vec2 rC = m_chargeCentroidDistance * toCentroid;  // from A
    const Vec2 down{-std::sin(carrierAngle), -std::cos(carrierAngle)};

    const Vec2 drumForce = mb * omega2 * pA + mb * g * down;  // acts at A
    const Vec2 chargeInertialForce = chargeInertia == ChargeInertia::SteadyCentroid
                                         ? mz * omega2 * (pA + rC)
                                         : mz * omega2 * pA + mz * drumRate2 * rC;
    const Vec2 chargeForce = chargeInertialForce + mz * g * down;  // acts at C

    // Common external tangents of the circles (O, r0) and (A, r_A): a line
    // n·p = h with unit normal n touches both on the same side iff
    // n·(p_A − p_O) = r0 − r_A, so n = (s, ±√(1 − s²)), s = (r0 − r_A)/l_OA.
    // Its direction from A's tangent point toward O's, (p_O + r0 n) − (p_A + r_A n)
    // = −l_OA·√(1 − s²)·(√(1 − s²), ∓s), is used in unit form so that the
    // degenerate s = ±1 (sheaves internally tangent) still has a direction.
    const double s = (geo.fixedSheaveRadius - geo.drumSheaveRadius) / geo.carrierArm;
    const double cb = std::sqrt(std::max(0.0, 1.0 - s * s));
    const Vec2 leadNormal{s, cb};
    const Vec2 trailNormal{s, -cb};
    const Vec2 leadDir{-cb, s};
    const Vec2 trailDir{-cb, -s};
    const double leadArm = cross(geo.drumSheaveRadius * leadNormal, leadDir);    // +r_A
    const double trailArm = cross(geo.drumSheaveRadius * trailNormal, trailDir); // −r_A

    RebuiltReaction reaction;
    reaction.chargeMomentAboutA = cross(rC, chargeForce);
    const double m = reaction.chargeMomentAboutA;
    double leadTension = 0.0;
    double trailTension = 0.0;
    // The belt has to cancel m; which span is tight follows from its sign.
    reaction.trailingSpanTight = m >= 0.0;
    if (reaction.trailingSpanTight) {
        leadTension = -m / (leadArm + kTightToSlackRatio * trailArm);
        trailTension = kTightToSlackRatio * leadTension;
    } else {
        trailTension = -m / (kTightToSlackRatio * leadArm + trailArm);
        leadTension = kTightToSlackRatio * trailTension;
    }
    reaction.tightTension = std::max(leadTension, trailTension);
    reaction.slackTension = std::min(leadTension, trailTension);

    const Vec2 beltForce = leadTension * leadDir + trailTension * trailDir;
    const Vec2 applied = drumForce + chargeForce + beltForce;
    reaction.forceX = -applied.x;
    reaction.forceY = -applied.y;
    reaction.xA = -reaction.forceX;
    reaction.yA = reaction.forceY;
    reaction.rA = std::hypot(reaction.forceX, reaction.forceY);
    return reaction;
}

ReactionExtremes PlanetaryBeltOracle::calcPaperReactionExtremes() const {
    ReactionExtremes extremes;
    extremes.angleAtMax = periodicArgMax([this](double phi) { return calcPaperReaction(phi).rA; });
    extremes.angleAtMin = periodicArgMax([this](double phi) { return -calcPaperReaction(phi).rA; });
    extremes.max = calcPaperReaction(extremes.angleAtMax).rA;
    extremes.min = calcPaperReaction(extremes.angleAtMin).rA;
    return extremes;
}

ReactionExtremes calcPaperReactionExtremes(double carrierRate, double segmentHalfAngle,
                                           const PlanetaryBeltCriteria& criteria,
                                           const PlanetaryBeltMapSettings& settings) {
    PlanetaryBeltParameters parameters;
    parameters.geometry = geometryFromCriteria(criteria, settings.drumRadius, settings.cReading);
    parameters.material = settings.material;
    parameters.carrierRate = carrierRate;
    parameters.segmentHalfAngle = segmentHalfAngle;
    parameters.chargeLag = settings.chargeLag;
    parameters.momentReading = settings.momentReading;
    return PlanetaryBeltOracle(parameters).calcPaperReactionExtremes();
}

}  // namespace milldyn::oracles
