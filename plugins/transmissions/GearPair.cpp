#include "plugins/transmissions/GearPair.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

// ---------------------------------------------------------------- geometry

void GearGeometry::check(const std::string& who) const {
    auto bad = [&who](const std::string& what) { throw std::invalid_argument(who + ": " + what); };
    if (!(pitchRadius1 > 0) || !std::isfinite(pitchRadius1)) bad("pitch radius 1 must be finite and > 0 m");
    if (!(pitchRadius2 > 0) || !std::isfinite(pitchRadius2)) bad("pitch radius 2 must be finite and > 0 m");
    if (internal && !(pitchRadius2 < pitchRadius1)) bad("an internal mesh needs the ring (gear 1) larger than gear 2");
    if (!(pressureAngle >= 0 && pressureAngle < M_PI / 2)) bad("pressure_angle must be in [0, 90) deg");
    if (!(std::abs(helixAngle) < M_PI / 4)) bad("helix_angle must be in (-45, 45) deg");
}

double GearGeometry::calcTransversePressureAngle() const {
    return std::atan(std::tan(pressureAngle) / std::cos(helixAngle));
}

std::string GearGeometry::checkCentreDistance(double pinDistance) const {
    const double a = calcCentreDistance();
    if (std::abs(pinDistance - a) <= kCentreDistanceTolerance * a) return "";
    std::ostringstream os;
    os.precision(9);
    os << "the pins are " << pinDistance << " m apart, but pitch radii " << pitchRadius1 << " m and " << pitchRadius2
       << " m mesh (" << (internal ? "internal" : "external") << ") at a centre distance of " << a << " m ("
       << (internal ? "r1 - r2" : "r1 + r2") << ", tolerance " << kCentreDistanceTolerance << " relative)";
    return os.str();
}

Vec3 GearGeometry::calcLineOfCentres(const Vec3& c1, const Vec3& c2) {
    Vec3 e = c2 - c1;
    e[2] = 0;
    return e / e.norm();
}

Vec3 GearGeometry::calcPitchPointOnGear1(const Vec3& c1, const Vec3& c2) const {
    return c1 + pitchRadius1 * calcLineOfCentres(c1, c2);
}

Vec3 GearGeometry::calcPitchPointOnGear2(const Vec3& c1, const Vec3& c2) const {
    return c2 - getRollingSign() * pitchRadius2 * calcLineOfCentres(c1, c2);
}

double GearGeometry::calcRadialForce(double ft) const {
    return std::abs(ft) * std::tan(pressureAngle) / std::cos(helixAngle);
}

double GearGeometry::calcAxialForce(double ft) const { return ft * std::tan(helixAngle); }

double GearGeometry::calcNormalForce(double ft) const {
    return std::abs(ft) / (std::cos(pressureAngle) * std::cos(helixAngle));
}

Vec3 GearGeometry::calcForceOnGear2(double ft, const Vec3& c1, const Vec3& c2) const {
    const Vec3 e12 = calcLineOfCentres(c1, c2);
    const Vec3 et(-e12[1], e12[0], 0);  // z × e12
    const double separate = internal ? -1.0 : 1.0;
    return ft * et + calcRadialForce(ft) * separate * e12 + Vec3(0, 0, calcAxialForce(ft));
}

// ----------------------------------------------------------- both laws

namespace {

/// z of the mesh plane in a gear's body frame (pins are about the parent's
/// z, so a body's z offset from its parent is its joint location's).
double meshPlaneInBody(const MobilizedBody& gear, double axialPosition) {
    return axialPosition - gear.getDefaultInboardFrame().p()[2];
}

Vec3 stationInBody(const Transform& X_AB, const Vec3& pointInA, double zInBody) {
    Vec3 p = ~X_AB.R() * (pointInA - X_AB.p());
    p[2] = zInBody;
    return p;
}

}  // namespace

// ----------------------------------------------------------- compliant

GearPairForce::GearPairForce(const MobilizedBody& gear1, const MobilizedBody& gear2, const GearPairParams& p)
    : m_gear1(gear1), m_gear2(gear2), m_p(p) {
    p.geometry.check("GearPair");
    if (!(p.meshStiffness > 0) || !std::isfinite(p.meshStiffness))
        throw std::invalid_argument("GearPair: mesh_stiffness must be finite and > 0 N/m");
    if (!(p.meshDamping >= 0) || !std::isfinite(p.meshDamping))
        throw std::invalid_argument("GearPair: mesh_damping must be finite and >= 0 N*s/m");
    if (!(p.backlash >= 0) || !std::isfinite(p.backlash))
        throw std::invalid_argument("GearPair: backlash must be finite and >= 0 m");
    m_cosAlphaT = std::cos(p.geometry.calcTransversePressureAngle());
}

double GearPairForce::calcMeshDisplacement(const State& s) const {
    const MobilizerQIndex q0(0);
    return m_p.geometry.pitchRadius1 * m_gear1.getOneQ(s, q0) +
           m_p.geometry.getRollingSign() * m_p.geometry.pitchRadius2 * m_gear2.getOneQ(s, q0);
}

double GearPairForce::calcLineOfActionGap(double deltaB) const {
    const double half = m_p.backlash / 2;
    if (deltaB > half) return deltaB - half;
    if (deltaB < -half) return deltaB + half;
    return 0;
}

double GearPairForce::calcTangentialForce(const State& s) const {
    const double deltaB = calcMeshDisplacement(s) * m_cosAlphaT;
    const double gap = calcLineOfActionGap(deltaB);
    if (gap == 0 && m_p.backlash > 0) return 0;
    const MobilizerUIndex u0(0);
    const double rateB = (m_p.geometry.pitchRadius1 * m_gear1.getOneU(s, u0) +
                          m_p.geometry.getRollingSign() * m_p.geometry.pitchRadius2 * m_gear2.getOneU(s, u0)) *
                         m_cosAlphaT;
    return (m_p.meshStiffness * gap + m_p.meshDamping * rateB) * m_cosAlphaT;
}

double GearPairForce::calcDampingPower(const State& s) const {
    const double deltaB = calcMeshDisplacement(s) * m_cosAlphaT;
    if (m_p.backlash > 0 && calcLineOfActionGap(deltaB) == 0) return 0;
    const MobilizerUIndex u0(0);
    const double rateB = (m_p.geometry.pitchRadius1 * m_gear1.getOneU(s, u0) +
                          m_p.geometry.getRollingSign() * m_p.geometry.pitchRadius2 * m_gear2.getOneU(s, u0)) *
                         m_cosAlphaT;
    return m_p.meshDamping * rateB * rateB;
}

void GearPairForce::calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const {
    const double ft = calcTangentialForce(s);
    if (ft == 0) return;
    const Vec3 c1 = m_gear1.getBodyOriginLocation(s), c2 = m_gear2.getBodyOriginLocation(s);
    const Vec3 f2 = m_p.geometry.calcForceOnGear2(ft, c1, c2);
    const Vec3 s1 = stationInBody(m_gear1.getBodyTransform(s), m_p.geometry.calcPitchPointOnGear1(c1, c2),
                                  meshPlaneInBody(m_gear1, m_p.axialPosition));
    const Vec3 s2 = stationInBody(m_gear2.getBodyTransform(s), m_p.geometry.calcPitchPointOnGear2(c1, c2),
                                  meshPlaneInBody(m_gear2, m_p.axialPosition));
    m_gear2.applyForceToBodyPoint(s, s2, f2, bodyForces);
    m_gear1.applyForceToBodyPoint(s, s1, -f2, bodyForces);
}

Real GearPairForce::calcPotentialEnergy(const State& s) const {
    const double gap = calcLineOfActionGap(calcMeshDisplacement(s) * m_cosAlphaT);
    return 0.5 * m_p.meshStiffness * gap * gap;
}

// ----------------------------------------------------------- rigid

RollingConstraint::RollingConstraint(SimbodyMatterSubsystem& matter, const MobilizedBody& first,
                                     const MobilizedBody& second, double c1, double c2)
    : Implementation(matter, 1, 0, 0), m_c1(c1), m_c2(c2) {
    m_mob1 = addConstrainedMobilizer(first);
    m_mob2 = addConstrainedMobilizer(second);
}

void RollingConstraint::calcPositionErrors(const State& s, const Array_<Transform, ConstrainedBodyIndex>&,
                                           const Array_<Real, ConstrainedQIndex>& q, Array_<Real>& perr) const {
    const MobilizerQIndex q0(0);
    perr[0] = m_c1 * getOneQ(s, q, m_mob1, q0) + m_c2 * getOneQ(s, q, m_mob2, q0);
}

void RollingConstraint::calcPositionDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                              const Array_<Real, ConstrainedQIndex>& qdot, Array_<Real>& pverr) const {
    const MobilizerQIndex q0(0);
    pverr[0] = m_c1 * getOneQDot(s, qdot, m_mob1, q0) + m_c2 * getOneQDot(s, qdot, m_mob2, q0);
}

void RollingConstraint::calcPositionDotDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                 const Array_<Real, ConstrainedQIndex>& qdotdot,
                                                 Array_<Real>& paerr) const {
    const MobilizerQIndex q0(0);
    paerr[0] = m_c1 * getOneQDotDot(s, qdotdot, m_mob1, q0) + m_c2 * getOneQDotDot(s, qdotdot, m_mob2, q0);
}

GearPairConstraint::GearPairConstraint(SimbodyMatterSubsystem& matter, const MobilizedBody& gear1,
                                       const MobilizedBody& gear2, const GearPairParams& p)
    : RollingConstraint(matter, gear1, gear2, p.geometry.pitchRadius1,
                        p.geometry.getRollingSign() * p.geometry.pitchRadius2),
      m_p(p) {
    p.geometry.check("GearPair");
    m_z1 = meshPlaneInBody(gear1, p.axialPosition);
    m_z2 = meshPlaneInBody(gear2, p.axialPosition);
    m_body1 = addConstrainedBody(gear1);
    m_body2 = addConstrainedBody(gear2);
}

void GearPairConstraint::addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                                       Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                                       Array_<Real, ConstrainedQIndex>&) const {
    // G = [r1, s·r2]: a force λ·e_t at P on gear 1 and −λ·e_t on gear 2
    // have exactly these generalized forces. Simbody applies −(what is
    // added here), so gear 1 pushes gear 2 with +λ·e_t: F_t = λ. The radial
    // and axial parts are workless for pins on one parent (see the class
    // comment), so adding them keeps the constraint force G^T λ.
    const double ft = multipliers[0];
    const Transform& X_A1 = getBodyTransformFromState(s, m_body1);
    const Transform& X_A2 = getBodyTransformFromState(s, m_body2);
    const Vec3 f2 = m_p.geometry.calcForceOnGear2(ft, X_A1.p(), X_A2.p());
    const Vec3 p1 = m_p.geometry.calcPitchPointOnGear1(X_A1.p(), X_A2.p());
    const Vec3 p2 = m_p.geometry.calcPitchPointOnGear2(X_A1.p(), X_A2.p());
    addInStationForce(s, m_body1, stationInBody(X_A1, p1, m_z1), f2, bodyForcesInA);
    addInStationForce(s, m_body2, stationInBody(X_A2, p2, m_z2), -f2, bodyForcesInA);
}

double GearPairConstraint::calcTangentialForce(const State& s, const Constraint& self) const {
    return self.getMultipliersAsVector(s)[0];
}

// ----------------------------------------------------------- element

namespace {

/// Tooth counts from `teeth` or from `module` (z = 2 r cos β / m_n, which
/// must come out whole); 0 when neither is given.
void readTeeth(const ElementSpec& spec, GearPairParams& p) {
    const double r[2] = {p.geometry.pitchRadius1, p.geometry.pitchRadius2};
    double z[2] = {0, 0};
    if (spec.has("teeth")) {
        const auto& t = spec.numbers("teeth");
        for (int i = 0; i < 2; ++i) {
            if (!(t[i] >= 1) || std::abs(t[i] - std::round(t[i])) > 1e-9)
                throw spec.error("teeth", "tooth counts must be whole numbers >= 1, got " + std::to_string(t[i]));
            z[i] = std::round(t[i]);
        }
    }
    if (spec.has("module")) {
        const double mn = spec.number("module");
        for (int i = 0; i < 2; ++i) {
            const double fromModule = 2 * r[i] * std::cos(p.geometry.helixAngle) / mn;
            if (std::abs(fromModule - std::round(fromModule)) > 1e-3 * fromModule) {
                std::ostringstream os;
                os.precision(9);
                os << "pitch radius " << r[i] << " m with module " << mn << " m gives " << fromModule
                   << " teeth on gear " << i + 1 << ", not a whole number (z = 2 r cos(beta) / m_n)";
                throw spec.error("module", os.str());
            }
            if (z[i] > 0 && std::round(fromModule) != z[i])
                throw spec.error("module", "module gives " + std::to_string(std::lround(fromModule)) +
                                               " teeth on gear " + std::to_string(i + 1) + ", teeth says " +
                                               std::to_string(std::lround(z[i])));
            z[i] = std::round(fromModule);
        }
    }
    if (z[0] > 0 && std::abs(z[1] / z[0] - r[1] / r[0]) > 1e-3 * r[1] / r[0]) {
        std::ostringstream os;
        os.precision(9);
        os << "tooth ratio " << z[1] << "/" << z[0] << " = " << z[1] / z[0] << " differs from the pitch radius ratio "
           << r[1] / r[0];
        throw spec.error("teeth", os.str());
    }
    p.teeth1 = z[0];
    p.teeth2 = z[1];
}

void buildGearPair(const ElementSpec& spec, Scene& scene) {
    const auto& names = spec.names("bodies");
    const SceneBody* b1 = scene.findBody(names.at(0));
    const SceneBody* b2 = scene.findBody(names.at(1));
    const MobilizedBody g1 = b1->mobod, g2 = b2->mobod;
    if (g1.getParentMobilizedBody().getMobilizedBodyIndex() != g2.getParentMobilizedBody().getMobilizedBodyIndex())
        throw spec.error("bodies", "'" + b1->name + "' and '" + b2->name +
                                       "' must turn on pins on the same parent body (a planet rolling on a fixed "
                                       "gear about a carrier is a GearMesh)");
    GearPairParams p;
    const auto& radii = spec.numbers("pitch_radii");
    p.geometry.pitchRadius1 = radii.at(0);
    p.geometry.pitchRadius2 = radii.at(1);
    p.geometry.internal = spec.text("mesh") == "internal";
    p.geometry.pressureAngle = spec.number("pressure_angle");
    p.geometry.helixAngle = spec.number("helix_angle");
    p.law = spec.text("law") == "compliant" ? GearPairLaw::Compliant : GearPairLaw::Rigid;
    p.meshStiffness = spec.number("mesh_stiffness");
    p.meshDamping = spec.number("mesh_damping");
    p.backlash = spec.number("backlash");
    p.axialPosition = spec.number("axial_position");
    readTeeth(spec, p);
    if (p.backlash > 0) {
        // Play along the line of action beyond the tooth spacing there (the
        // base pitch p_bt = 2π·r1·cos α_t/z1) is no gear (issue 26 item 7);
        // without tooth counts z1 = 1 bounds it by the whole base circle.
        const double z1 = p.teeth1 > 0 ? p.teeth1 : 1;
        const double basePitch =
            2 * Pi * p.geometry.pitchRadius1 * std::cos(p.geometry.calcTransversePressureAngle()) / z1;
        if (!(p.backlash < basePitch))
            throw spec.error("backlash", "backlash " + formatNumber(p.backlash) +
                                             " m along the line of action must be below the base pitch 2π·r1·cos(α_t)/z1 = " +
                                             formatNumber(basePitch) + " m" +
                                             (p.teeth1 > 0 ? " (z1 = " + formatNumber(z1) + ")"
                                                           : " (no teeth or module given: z1 = 1, the whole base circle)"));
    }
    Vec3 between = g2.getDefaultInboardFrame().p() - g1.getDefaultInboardFrame().p();
    between[2] = 0;
    const std::string misfit = p.geometry.checkCentreDistance(between.norm());
    if (!misfit.empty()) throw spec.error("pitch_radii", misfit);

    const double s = p.geometry.getRollingSign();
    const double r1 = p.geometry.pitchRadius1, r2 = p.geometry.pitchRadius2;
    std::function<double(const State&)> tangential;
    if (p.law == GearPairLaw::Compliant) {
        auto* impl = new GearPairForce(g1, g2, p);
        Force::Custom force(scene.forces(), impl);
        scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
        tangential = [impl](const State& st) { return impl->calcTangentialForce(st); };
        scene.addProbe({spec.name + ".mesh_deflection", "m", ProbeRole::Generic, Stage::Position,
                        [impl](const State& st) { return impl->calcMeshDisplacement(st); }});
        if (p.meshDamping > 0)
            scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                                 [impl](const State& st) { return impl->calcDampingPower(st); }});
    } else {
        auto* impl = new GearPairConstraint(scene.matter(), g1, g2, p);
        Constraint::Custom constraint(impl);
        const ConstraintIndex index = constraint.getConstraintIndex();
        const SimbodyMatterSubsystem* matter = &scene.matter();
        tangential = [impl, matter, index](const State& st) {
            return impl->calcTangentialForce(st, matter->getConstraint(index));
        };
        // The steady-state search moves angles and speeds freely: hold the
        // constraint's position level too.
        scene.addSteadyResidual({spec.name + ".rolling_error", [g1, g2, r1, r2, s](const State& st) {
                                     return r1 * pinAngle(st, g1) + s * r2 * pinAngle(st, g2);
                                 }});
    }
    // Steady running: the mesh's sliding rate along the pitch line is zero
    // (the rigid law's velocity constraint; the compliant mesh's deflection rate).
    scene.addSteadyResidual({spec.name + ".mesh_deflection_rate", [g1, g2, r1, r2, s](const State& st) {
                                 return r1 * pinSpeed(st, g1) + s * r2 * pinSpeed(st, g2);
                             }});
    const Stage stage = p.law == GearPairLaw::Rigid ? Stage::Acceleration : Stage::Velocity;
    const GearGeometry geo = p.geometry;
    scene.addProbe({spec.name + ".tangential_force", "N", ProbeRole::Generic, stage, tangential});
    scene.addProbe({spec.name + ".radial_force", "N", ProbeRole::Generic, stage,
                    [tangential, geo](const State& st) { return geo.calcRadialForce(tangential(st)); }});
    if (geo.helixAngle != 0)
        scene.addProbe({spec.name + ".axial_force", "N", ProbeRole::Generic, stage,
                        [tangential, geo](const State& st) { return geo.calcAxialForce(tangential(st)); }});
    scene.addProbe({spec.name + ".normal_force", "N", ProbeRole::Generic, stage,
                    [tangential, geo](const State& st) { return geo.calcNormalForce(tangential(st)); }});
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::CouplingTorque, stage,
                    [tangential, r1](const State& st) { return tangential(st) * r1; }});
    scene.addProbe({spec.name + ".mesh_power", "W", ProbeRole::Generic, stage,
                    [tangential, r1, g1](const State& st) { return tangential(st) * r1 * pinSpeed(st, g1); }});
    if (p.teeth1 > 0) {
        const double z1 = p.teeth1;
        scene.addProbe({spec.name + ".mesh_frequency", "Hz", ProbeRole::Generic, Stage::Velocity,
                        [z1, g1](const State& st) { return z1 * std::abs(pinSpeed(st, g1)) / (2 * M_PI); }});
        scene.addOrderExcitation({spec.name + ".mesh_frequency", b1->name, p.teeth1});
        scene.addDerivedValue({spec.name + ".teeth_1", p.teeth1, "1", "z1 (from teeth or 2 r1 cos(beta)/m_n)"});
        scene.addDerivedValue({spec.name + ".teeth_2", p.teeth2, "1", "z2"});
        scene.addDerivedValue({spec.name + ".mesh_events_per_revolution_of_" + b1->name, p.teeth1, "1",
                               "tooth-mesh frequency f_z = z1*n1: mesh events per turn of gear 1"});
    }
    scene.addDerivedValue({spec.name + ".ratio", -s * r2 / r1, "1", "omega_1/omega_2 = -s r2/r1 (s = +1 external)"});
    scene.addDerivedValue({spec.name + ".centre_distance", geo.calcCentreDistance(), "m", "r1 + r2 or r1 - r2"});
    scene.addDerivedValue({spec.name + ".transverse_pressure_angle", geo.calcTransversePressureAngle(), "rad",
                           "tan(alpha_t) = tan(alpha_n)/cos(beta)"});
    scene.addInitializer([g1, g2, r1, r2, s](State& st) {
        g2.setOneQ(st, MobilizerQIndex(0), -r1 * g1.getOneQ(st, MobilizerQIndex(0)) / (s * r2));
        g2.setOneU(st, MobilizerUIndex(0), -r1 * g1.getOneU(st, MobilizerUIndex(0)) / (s * r2));
    });
    scene.addSpeedRelation(b1->name, b2->name, -s * r2 / r1);
    scene.addSketch([g1, g2, r1, r2](const State& st, Sketch& k) {
        const Vec3 a = g1.getBodyOriginLocation(st), b = g2.getBodyOriginLocation(st);
        k.circle("gear", a[0], a[1], r1);
        k.circle("gear", b[0], b[1], r2);
    });
    scene.note("gear pair " + spec.name + " (GearPair, " + spec.text("law") + ", " + spec.text("mesh") + ")",
               b1->name + " meshes with " + b2->name + "; force at the pitch point along the line of action");
}

}  // namespace

namespace {
ParamSchema optionalList(ParamSchema p) {
    p.required = false;
    return p;
}
}  // namespace

void registerGearPair(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "GearPair";
    s.doc = "Gear mesh between two shafts on pins on one parent (rigid or compliant; force at the pitch point).";
    s.params = {
        P::bodyPair("bodies", "[gear 1, gear 2]; internal: gear 1 is the ring"),
        P::quantityList("pitch_radii", "m", 2, 2, "[r1, r2]: operating pitch radii, fitting the pin distance"),
        P::choice("mesh", {"external", "internal"}, "external gears, or gear 2 inside ring 1")
            .optional(std::string("external")),
        P::quantity("pressure_angle", "rad", "normal pressure angle alpha_n").optional(20.0 * M_PI / 180).atLeast(0)
            .below(M_PI / 2),
        P::quantity("helix_angle", "rad", "beta of gear 1 (signed; 0: spur)").optional(0.0).above(-M_PI / 4)
            .below(M_PI / 4),
        P::choice("law", {"rigid", "compliant"}, "a constraint, or mesh stiffness and damping")
            .optional(std::string("rigid")),
        P::quantity("mesh_stiffness", "N/m", "compliant: k along the transverse line of action").optional(0.0)
            .atLeast(0),
        P::quantity("mesh_damping", "N*s/m", "compliant: c along the line of action").optional(0.0).atLeast(0),
        P::quantity("backlash", "m", "compliant: play j along the line of action").optional(0.0).atLeast(0),
        P::quantity("axial_position", "m", "z of the mesh plane in the parent's frame").optional(0.0),
        optionalList(P::quantityList("teeth", "1", 2, 2, "[z1, z2] (for the tooth-mesh frequency)")),
        P::quantity("module", "m", "normal module m_n: z = 2 r cos(beta)/m_n").optional(0.0).above(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const auto& n = e.names("bodies");
        if (n.size() == 2 && n[0] == n[1])
            throw e.error("bodies", "a gear pair needs two different bodies, got '" + n[0] + "' twice");
        const auto& r = e.numbers("pitch_radii");
        for (double v : r)
            if (!(v > 0)) throw e.error("pitch_radii", "pitch radii must be > 0 m");
        if (e.text("mesh") == "internal" && r.size() == 2 && !(r[1] < r[0]))
            throw e.error("pitch_radii", "an internal mesh needs the ring (gear 1) larger: r1 > r2");
        if (e.text("law") == "rigid") {
            for (const char* key : {"mesh_stiffness", "mesh_damping", "backlash"})
                if (e.has(key)) throw e.error(key, "not used by law: rigid (use law: compliant)");
        } else if (!(e.number("mesh_stiffness") > 0)) {
            throw e.error(e.has("mesh_stiffness") ? "mesh_stiffness" : "law",
                          "law: compliant needs mesh_stiffness > 0 N/m");
        }
    };
    registry.add({std::move(s), buildGearPair});
}

}  // namespace milldyn
