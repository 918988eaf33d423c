#include "plugins/transmissions/PlanetaryGearSet.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/MobilizerReactions.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

void PlanetaryGearSetParams::check() const {
    auto bad = [](const std::string& what) { throw std::invalid_argument("PlanetaryGearSet: " + what); };
    for (double z : {sunTeeth, planetTeeth, ringTeeth})
        if (!(z >= 1) || std::abs(z - std::round(z)) > 1e-9) bad("tooth counts must be whole numbers >= 1");
    if (std::abs(ringTeeth - sunTeeth - 2 * planetTeeth) > 1e-9)
        bad("a set without profile shift needs z_ring = z_sun + 2 z_planet");
    if (!(module > 0) || !std::isfinite(module)) bad("module must be finite and > 0 m");
    if (!(pressureAngle >= 0 && pressureAngle < M_PI / 2)) bad("pressure_angle must be in [0, 90) deg");
    if (law == PlanetaryLaw::Compliant) {
        for (double k : {sunMeshStiffness, ringMeshStiffness})
            if (!(k > 0) || !std::isfinite(k)) bad("compliant meshes need mesh stiffnesses finite and > 0 N/m");
        for (double v : {sunMeshDamping, ringMeshDamping, sunBacklash, ringBacklash})
            if (!(v >= 0) || !std::isfinite(v)) bad("mesh damping and backlash must be finite and >= 0");
    }
}

GearGeometry PlanetaryMesh::geometry(double pressureAngle) const {
    GearGeometry g;
    g.pitchRadius1 = gearRadius;
    g.pitchRadius2 = planetRadius;
    g.internal = kind == PlanetaryMeshKind::Ring;
    g.pressureAngle = pressureAngle;
    return g;
}

// ------------------------------------------------------------ kinematics

double PlanetaryMembers::angle(const State& s, const MobilizedBody& m, bool fixed) const {
    return fixed ? 0.0 : m.getOneQ(s, MobilizerQIndex(0));
}

double PlanetaryMembers::speed(const State& s, const MobilizedBody& m, bool fixed) const {
    return fixed ? 0.0 : m.getOneU(s, MobilizerUIndex(0));
}

double PlanetaryMembers::calcDeflection(const State& s, const PlanetaryMesh& mesh) const {
    const double g = angle(s, gear(mesh.kind), gearFixed(mesh.kind));
    const double c = angle(s, carrier, carrierFixed);
    const double q = planets[mesh.planet].getOneQ(s, MobilizerQIndex(0));
    return mesh.gearRadius * (g - c) + mesh.sign() * mesh.planetRadius * q - mesh.pinError;
}

double PlanetaryMembers::calcDeflectionRate(const State& s, const PlanetaryMesh& mesh) const {
    const double g = speed(s, gear(mesh.kind), gearFixed(mesh.kind));
    const double c = speed(s, carrier, carrierFixed);
    const double u = planets[mesh.planet].getOneU(s, MobilizerUIndex(0));
    return mesh.gearRadius * (g - c) + mesh.sign() * mesh.planetRadius * u;
}

Vec3 PlanetaryMembers::calcRadialDirection(const State& s, int planet) const {
    return GearGeometry::calcLineOfCentres(axis, planets[planet].getBodyOriginLocation(s));
}

namespace {

/// The mesh force at both pitch points, in the plane z = `axialPosition`:
/// on the planet `onPlanet` at P2, its opposite on the gear at P1.
struct MeshForceAt {
    Vec3 onPlanet, atGear, atPlanet;
};

MeshForceAt meshForceAt(const GearGeometry& geo, double ft, const Vec3& axis, const Vec3& planetCentre,
                        double axialPosition) {
    MeshForceAt m;
    m.onPlanet = geo.calcForceOnGear2(ft, axis, planetCentre);
    m.atGear = geo.calcPitchPointOnGear1(axis, planetCentre);
    m.atPlanet = geo.calcPitchPointOnGear2(axis, planetCentre);
    m.atGear[2] = m.atPlanet[2] = axialPosition;
    return m;
}

}  // namespace

// ------------------------------------------------------------- compliant

PlanetaryMeshForces::PlanetaryMeshForces(const PlanetaryMembers& members, const std::vector<PlanetaryMesh>& meshes,
                                         const PlanetaryGearSetParams& p)
    : m_members(members), m_meshes(meshes), m_p(p), m_cosAlpha(std::cos(p.pressureAngle)) {
    p.check();
}

double PlanetaryMeshForces::stiffness(const PlanetaryMesh& m) const {
    return m.kind == PlanetaryMeshKind::Sun ? m_p.sunMeshStiffness : m_p.ringMeshStiffness;
}
double PlanetaryMeshForces::damping(const PlanetaryMesh& m) const {
    return m.kind == PlanetaryMeshKind::Sun ? m_p.sunMeshDamping : m_p.ringMeshDamping;
}
double PlanetaryMeshForces::backlash(const PlanetaryMesh& m) const {
    return m.kind == PlanetaryMeshKind::Sun ? m_p.sunBacklash : m_p.ringBacklash;
}

double PlanetaryMeshForces::gap(const PlanetaryMesh& m, double deltaB) const {
    const double half = backlash(m) / 2;
    if (deltaB > half) return deltaB - half;
    if (deltaB < -half) return deltaB + half;
    return 0;
}

double PlanetaryMeshForces::calcTangentialForce(const State& s, int index) const {
    const PlanetaryMesh& m = m_meshes[index];
    const double deltaB = m_members.calcDeflection(s, m) * m_cosAlpha;
    const double g = gap(m, deltaB);
    if (g == 0 && backlash(m) > 0) return 0;  // inside the play: no contact
    const double rateB = m_members.calcDeflectionRate(s, m) * m_cosAlpha;
    return (stiffness(m) * g + damping(m) * rateB) * m_cosAlpha;
}

double PlanetaryMeshForces::calcDampingPower(const State& s) const {
    double power = 0;
    for (const auto& m : m_meshes) {
        const double deltaB = m_members.calcDeflection(s, m) * m_cosAlpha;
        if (backlash(m) > 0 && gap(m, deltaB) == 0) continue;
        const double rateB = m_members.calcDeflectionRate(s, m) * m_cosAlpha;
        power += damping(m) * rateB * rateB;
    }
    return power;
}

void PlanetaryMeshForces::calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                                   Vector&) const {
    for (std::size_t i = 0; i < m_meshes.size(); ++i) {
        const PlanetaryMesh& m = m_meshes[i];
        const double ft = calcTangentialForce(s, static_cast<int>(i));
        if (ft == 0) continue;
        const MobilizedBody& planet = m_members.planets[m.planet];
        const MeshForceAt f = meshForceAt(m.geometry(m_p.pressureAngle), ft, m_members.axis,
                                          planet.getBodyOriginLocation(s), m_p.axialPosition);
        planet.applyForceToBodyPoint(s, planet.findStationAtGroundPoint(s, f.atPlanet), f.onPlanet, bodyForces);
        if (!m_members.gearFixed(m.kind)) {
            const MobilizedBody& gear = m_members.gear(m.kind);
            gear.applyForceToBodyPoint(s, gear.findStationAtGroundPoint(s, f.atGear), -f.onPlanet, bodyForces);
        }
    }
}

Real PlanetaryMeshForces::calcPotentialEnergy(const State& s) const {
    double v = 0;
    for (const auto& m : m_meshes) {
        const double g = gap(m, m_members.calcDeflection(s, m) * m_cosAlpha);
        v += 0.5 * stiffness(m) * g * g;
    }
    return v;
}

// ----------------------------------------------------------------- rigid

PlanetaryMeshConstraint::PlanetaryMeshConstraint(SimbodyMatterSubsystem& matter, const PlanetaryMembers& members,
                                                 const PlanetaryMesh& mesh, double pressureAngle, double axialPosition)
    : Implementation(matter, 1, 0, 0), m_mesh(mesh), m_geometry(mesh.geometry(pressureAngle)), m_axialPosition(axialPosition),
      m_axis(members.axis), m_hasGear(!members.gearFixed(mesh.kind)), m_hasCarrier(!members.carrierFixed) {
    const MobilizedBody& gear = members.gear(mesh.kind);
    const MobilizedBody& planet = members.planets[mesh.planet];
    if (m_hasGear) m_gearMob = addConstrainedMobilizer(gear);
    if (m_hasCarrier) m_carrierMob = addConstrainedMobilizer(members.carrier);
    m_planetMob = addConstrainedMobilizer(planet);
    m_gearBody = addConstrainedBody(m_hasGear ? gear : matter.getGround());
    m_planetBody = addConstrainedBody(planet);
}

template <class Get>
double PlanetaryMeshConstraint::combine(Get get) const {
    double v = m_mesh.sign() * m_mesh.planetRadius * get(m_planetMob);
    if (m_hasGear) v += m_mesh.gearRadius * get(m_gearMob);
    if (m_hasCarrier) v -= m_mesh.gearRadius * get(m_carrierMob);
    return v;
}

void PlanetaryMeshConstraint::calcPositionErrors(const State& s, const Array_<Transform, ConstrainedBodyIndex>&,
                                                 const Array_<Real, ConstrainedQIndex>& q, Array_<Real>& perr) const {
    perr[0] = combine([&](ConstrainedMobilizerIndex m) { return getOneQ(s, q, m, MobilizerQIndex(0)); });
}

void PlanetaryMeshConstraint::calcPositionDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                    const Array_<Real, ConstrainedQIndex>& qdot,
                                                    Array_<Real>& pverr) const {
    pverr[0] = combine([&](ConstrainedMobilizerIndex m) { return getOneQDot(s, qdot, m, MobilizerQIndex(0)); });
}

void PlanetaryMeshConstraint::calcPositionDotDotErrors(const State& s,
                                                       const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                       const Array_<Real, ConstrainedQIndex>& qdotdot,
                                                       Array_<Real>& paerr) const {
    paerr[0] = combine([&](ConstrainedMobilizerIndex m) { return getOneQDotDot(s, qdotdot, m, MobilizerQIndex(0)); });
}

void PlanetaryMeshConstraint::addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                                            Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                                            Array_<Real, ConstrainedQIndex>&) const {
    // A force λ·e_t at P on the gear and −λ·e_t on the planet have the
    // generalized forces [r_G, −r_G, s·r_p]·λ = Gᵀλ (gear, carrier through
    // the planet's pin, planet). Simbody applies −(what is added here), so
    // the gear pushes the planet with +λ·e_t: F_t = λ. The separating force
    // passes through both axes (workless for coaxial pins).
    const Transform& X_AG = getBodyTransformFromState(s, m_gearBody);
    const Transform& X_AP = getBodyTransformFromState(s, m_planetBody);
    const MeshForceAt f = meshForceAt(m_geometry, multipliers[0], m_axis, X_AP.p(), m_axialPosition);
    addInStationForce(s, m_gearBody, ~X_AG * f.atGear, f.onPlanet, bodyForcesInA);
    addInStationForce(s, m_planetBody, ~X_AP * f.atPlanet, -f.onPlanet, bodyForcesInA);
}

// --------------------------------------------------------------- element

namespace {

/// A member from its key: a body on a pin on ground, or ground when omitted.
MobilizedBody memberOf(const ElementSpec& spec, const Scene& scene, const std::string& key, bool& fixed) {
    fixed = !spec.has(key);
    if (fixed) return MobilizedBody(scene.matter().getGround());
    const SceneBody* b = scene.findBody(spec.text(key));
    if (!b->mobod.getParentMobilizedBody().isGround())
        throw spec.error(key, "'" + b->name + "' must turn on a pin on ground (the set's axis)");
    return b->mobod;
}

std::string num(double v) {
    std::ostringstream os;
    os.precision(9);
    os << v;
    return os.str();
}

void buildPlanetaryGearSet(const ElementSpec& spec, Scene& scene) {
    PlanetaryGearSetParams p;
    const auto& z = spec.numbers("teeth");
    p.sunTeeth = z.at(0);
    p.planetTeeth = z.at(1);
    p.ringTeeth = z.at(2);
    p.module = spec.number("module");
    p.pressureAngle = spec.number("pressure_angle");
    p.law = spec.text("law") == "compliant" ? PlanetaryLaw::Compliant : PlanetaryLaw::Rigid;
    p.sunMeshStiffness = spec.number("sun_mesh_stiffness");
    p.sunMeshDamping = spec.number("sun_mesh_damping");
    p.sunBacklash = spec.number("sun_backlash");
    p.ringMeshStiffness = spec.number("ring_mesh_stiffness");
    p.ringMeshDamping = spec.number("ring_mesh_damping");
    p.ringBacklash = spec.number("ring_backlash");
    p.axialPosition = spec.number("axial_position");
    const auto& planetNames = spec.names("planets");
    const int n = static_cast<int>(planetNames.size());
    p.pinPositionErrors.assign(n, 0.0);
    if (spec.has("pin_position_errors")) p.pinPositionErrors = spec.numbers("pin_position_errors");
    try {
        p.check();
    } catch (const std::invalid_argument& e) {
        throw spec.error("teeth", e.what());
    }

    PlanetaryMembers m;
    m.sun = memberOf(spec, scene, "sun", m.sunFixed);
    m.ring = memberOf(spec, scene, "ring", m.ringFixed);
    m.carrier = memberOf(spec, scene, "carrier", m.carrierFixed);
    // The axis: every member's pin location in ground (pins on ground).
    bool haveAxis = false;
    for (const auto* key : {"sun", "ring", "carrier"}) {
        if (!spec.has(key)) continue;
        Vec3 at = scene.findBody(spec.text(key))->mobod.getDefaultInboardFrame().p();
        at[2] = 0;
        if (!haveAxis) {
            m.axis = at;
            haveAxis = true;
        } else if ((at - m.axis).norm() > 1e-9 * (1 + m.axis.norm()) + 1e-6 * p.ringRadius()) {
            throw spec.error(key, "'" + spec.text(key) + "' turns about (" + num(at[0]) + ", " + num(at[1]) +
                                      ") m, not on the set's axis (" + num(m.axis[0]) + ", " + num(m.axis[1]) + ") m");
        }
    }
    const double rs = p.sunRadius(), rp = p.planetRadius(), rr = p.ringRadius(), a = rs + rp;
    const MobilizedBody planetParent = m.carrierFixed ? MobilizedBody(scene.matter().getGround()) : m.carrier;
    std::vector<std::string> planetBodies;
    std::vector<double> planetAngles;
    for (int k = 0; k < n; ++k) {
        const SceneBody* b = scene.findBody(planetNames[k]);
        if (b->mobod.getParentMobilizedBody().getMobilizedBodyIndex() != planetParent.getMobilizedBodyIndex())
            throw spec.error("planets", "planet '" + b->name + "' must turn on a pin on " +
                                            (m.carrierFixed ? std::string("ground (the carrier is fixed)")
                                                            : "the carrier '" + spec.text("carrier") + "'"));
        // The planet's axis relative to the set's axis, in the carrier's frame.
        Vec3 arm = b->mobod.getDefaultInboardFrame().p() - (m.carrierFixed ? m.axis : Vec3(0));
        arm[2] = 0;
        if (std::abs(arm.norm() - a) > GearGeometry::kCentreDistanceTolerance * a)
            throw spec.error("planets", "planet '" + b->name + "' is " + num(arm.norm()) +
                                            " m from the set's axis; the pitch radii need r_sun + r_planet = " +
                                            num(a) + " m (m z_sun/2 + m z_planet/2)");
        for (const auto& other : planetBodies)
            if (other == b->name) throw spec.error("planets", "planet '" + b->name + "' is listed twice");
        planetBodies.push_back(b->name);
        planetAngles.push_back(std::atan2(arm[1], arm[0]));
        m.planets.push_back(b->mobod);
    }
    std::vector<PlanetaryMesh> meshes;  // sun mesh of planet k at 2k, ring mesh at 2k + 1
    for (int k = 0; k < n; ++k) {
        meshes.push_back({PlanetaryMeshKind::Sun, k, rs, rp, p.pinPositionErrors[k]});
        meshes.push_back({PlanetaryMeshKind::Ring, k, rr, rp, p.pinPositionErrors[k]});
    }

    // The tangential mesh forces, per mesh.
    std::function<double(const State&, int)> tangential;
    if (p.law == PlanetaryLaw::Compliant) {
        auto* impl = new PlanetaryMeshForces(m, meshes, p);
        Force::Custom force(scene.forces(), impl);
        scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
        tangential = [impl](const State& st, int i) { return impl->calcTangentialForce(st, i); };
        if (p.sunMeshDamping > 0 || p.ringMeshDamping > 0)
            scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                                 [impl](const State& st) { return impl->calcDampingPower(st); },
                                 "mesh damping heat"});
        for (int i = 0; i < 2 * n; ++i) {
            const PlanetaryMesh mesh = meshes[i];
            scene.addProbe({spec.name + "." + planetBodies[mesh.planet] +
                                (mesh.kind == PlanetaryMeshKind::Sun ? ".sun_mesh_deflection" : ".ring_mesh_deflection"),
                            "m", ProbeRole::Generic, Stage::Position,
                            [m, mesh](const State& st) { return m.calcDeflection(st, mesh); }});
        }
    } else {
        std::vector<ConstraintIndex> index;
        for (const auto& mesh : meshes) {
            auto* impl = new PlanetaryMeshConstraint(scene.matter(), m, mesh, p.pressureAngle, p.axialPosition);
            Constraint::Custom constraint(impl);
            index.push_back(constraint.getConstraintIndex());
            // The steady search moves angles freely: hold the position level too.
            scene.addSteadyResidual({spec.name + "." + planetBodies[mesh.planet] +
                                         (mesh.kind == PlanetaryMeshKind::Sun ? ".sun" : ".ring") + "_rolling_error",
                                     [m, mesh](const State& st) { return m.calcDeflection(st, mesh); }});
        }
        const SimbodyMatterSubsystem* matter = &scene.matter();
        tangential = [matter, index](const State& st, int i) {
            return matter->getConstraint(index[i]).getMultipliersAsVector(st)[0];
        };
    }
    // Steady running: no mesh slides (the rigid velocity constraints; the
    // compliant meshes' deflection rates).
    for (const auto& mesh : meshes)
        scene.addSteadyResidual({spec.name + "." + planetBodies[mesh.planet] +
                                     (mesh.kind == PlanetaryMeshKind::Sun ? ".sun" : ".ring") + "_mesh_deflection_rate",
                                 [m, mesh](const State& st) { return m.calcDeflectionRate(st, mesh); }});

    const Stage stage = p.law == PlanetaryLaw::Rigid ? Stage::Acceleration : Stage::Velocity;
    const MobilizerReactions* reactions = &scene.mobilizerReactions();
    // Force of the carrier on planet k at its pin [N], ground axes (Simbody's
    // joint reaction: meshes, the planet's inertia, weight and centrifugal force).
    auto bearing = [m, reactions](const State& st, int k) { return reactions->getForce(st, m.planets[k]); };
    for (int k = 0; k < n; ++k) {
        const std::string stem = spec.name + "." + planetBodies[k];
        scene.addProbe({stem + ".sun_mesh_force", "N", ProbeRole::Generic, stage,
                        [tangential, k](const State& st) { return tangential(st, 2 * k); },
                        "tangential force of the sun on the planet, + along e_t (z x e_radial)"});
        scene.addProbe({stem + ".ring_mesh_force", "N", ProbeRole::Generic, stage,
                        [tangential, k](const State& st) { return tangential(st, 2 * k + 1); },
                        "tangential force of the ring on the planet, + along e_t (z x e_radial)"});
        scene.addProbe({stem + ".bearing_force", "N", ProbeRole::Generic, Stage::Acceleration,
                        [bearing, k](const State& st) {
                            Vec3 f = bearing(st, k);
                            f[2] = 0;
                            return f.norm();
                        },
                        "magnitude of the carrier's force on the planet at its pin, in the plane of the set"});
        scene.addProbe({stem + ".bearing_tangential_force", "N", ProbeRole::Generic, Stage::Acceleration,
                        [bearing, m, k](const State& st) {
                            const Vec3 e = m.calcRadialDirection(st, k);
                            return ~bearing(st, k) * Vec3(-e[1], e[0], 0);
                        },
                        "carrier's force on the planet along e_t"});
        scene.addProbe({stem + ".bearing_radial_force", "N", ProbeRole::Generic, Stage::Acceleration,
                        [bearing, m, k](const State& st) { return ~bearing(st, k) * m.calcRadialDirection(st, k); },
                        "carrier's force on the planet along e_radial (outwards)"});
        scene.addProbe({stem + ".load_share", "1", ProbeRole::Generic, stage,
                        [tangential, k, n](const State& st) {
                            double sum = 0;
                            for (int j = 0; j < n; ++j) sum += tangential(st, 2 * j);
                            return sum != 0 ? n * tangential(st, 2 * k) / sum : 1.0;
                        },
                        "n F_sun,k / sum of F_sun: 1 for equal sharing"});
    }
    scene.addProbe({spec.name + ".load_sharing_factor", "1", ProbeRole::Generic, stage,
                    [tangential, n](const State& st) {
                        double sum = 0, top = 0;
                        for (int j = 0; j < n; ++j) {
                            const double f = tangential(st, 2 * j);
                            sum += f;
                            top = j == 0 ? f : (sum > 0 ? std::max(top, f) : std::min(top, f));
                        }
                        return sum != 0 ? n * top / sum : 1.0;
                    },
                    "K_gamma = n max_k F_sun,k / sum of F_sun (ISO 6336-1 mesh load factor)"});
    // Torques the set's meshes and planet pins apply to the members about +z.
    // One is a coupling torque (for the summary's peaks and the linear
    // analyses' outputs): the first member named in sun, ring, carrier order,
    // the shaft the summary names for this element's coupling torque.
    const ProbeRole sunRole = m.sunFixed ? ProbeRole::Generic : ProbeRole::CouplingTorque;
    const ProbeRole ringRole = !m.sunFixed || m.ringFixed ? ProbeRole::Generic : ProbeRole::CouplingTorque;
    scene.addProbe({spec.name + ".torque_on_sun", "N*m", sunRole, stage,
                    [tangential, n, rs](const State& st) {
                        double t = 0;
                        for (int k = 0; k < n; ++k) t -= rs * tangential(st, 2 * k);
                        return t;
                    },
                    "torque of the planets' meshes on the sun, + about z"});
    scene.addProbe({spec.name + ".torque_on_ring", "N*m", ringRole, stage,
                    [tangential, n, rr](const State& st) {
                        double t = 0;
                        for (int k = 0; k < n; ++k) t -= rr * tangential(st, 2 * k + 1);
                        return t;
                    },
                    "torque of the planets' meshes on the ring, + about z"});
    scene.addProbe({spec.name + ".torque_on_carrier", "N*m", ProbeRole::Generic, Stage::Acceleration,
                    [bearing, m, n, a](const State& st) {
                        double t = 0;
                        for (int k = 0; k < n; ++k) {
                            const Vec3 e = m.calcRadialDirection(st, k);
                            t -= a * (~bearing(st, k) * Vec3(-e[1], e[0], 0));
                        }
                        return t;
                    },
                    "torque of the planets' pins on the carrier, + about z (from the joint reactions)"});
    const double zr = p.ringTeeth, zs = p.sunTeeth, zp = p.planetTeeth;
    scene.addProbe({spec.name + ".mesh_frequency", "Hz", ProbeRole::Generic, Stage::Velocity,
                    [m, zr](const State& st) {
                        return zr * std::abs(m.speed(st, m.ring, m.ringFixed) - m.speed(st, m.carrier, m.carrierFixed)) /
                               (2 * M_PI);
                    },
                    "tooth-mesh frequency z_r |w_ring - w_carrier|/(2 pi) = z_s |w_sun - w_carrier|/(2 pi)"});

    // Derived values.
    scene.addDerivedValue({spec.name + ".sun_pitch_radius", rs, "m", "r_s = m z_s/2"});
    scene.addDerivedValue({spec.name + ".planet_pitch_radius", rp, "m", "r_p = m z_p/2"});
    scene.addDerivedValue({spec.name + ".ring_pitch_radius", rr, "m", "r_r = m z_r/2"});
    scene.addDerivedValue({spec.name + ".centre_distance", a, "m", "a = r_s + r_p: sun axis to planet axis"});
    scene.addDerivedValue({spec.name + ".willis_ratio", -zr / zs, "1",
                           "i_0 = (w_s - w_c)/(w_r - w_c) = -z_r/z_s (the stationary ratio, carrier held)"});
    scene.addDerivedValue({spec.name + ".assembly_number", (zs + zr) / n, "1",
                           "(z_s + z_r)/n: a whole number lets n planets sit at equal spacing"});
    for (int k = 0; k < n; ++k)
        scene.addDerivedValue({spec.name + "." + planetBodies[k] + ".angle", planetAngles[k], "rad",
                               "planet's place in the carrier frame, from +x about +z"});

    // Speeds: the fixed member's relation, planets relative to the carrier,
    // the order excitation on the member whose speed gives the mesh frequency.
    const std::string sunName = spec.has("sun") ? spec.text("sun") : "";
    const std::string ringName = spec.has("ring") ? spec.text("ring") : "";
    const std::string carrierName = spec.has("carrier") ? spec.text("carrier") : "";
    if (m.ringFixed) {
        scene.addSpeedRelation(sunName, carrierName, 1 + zr / zs);
        for (const auto& pb : planetBodies) scene.addSpeedRelation(pb, carrierName, -zr / zp);
        scene.addOrderExcitation({spec.name + ".mesh_frequency", carrierName, zr});
        scene.addDerivedValue({spec.name + ".ratio", 1 + zr / zs, "1", "w_sun/w_carrier = 1 + z_r/z_s (ring fixed)"});
    } else if (m.sunFixed) {
        scene.addSpeedRelation(ringName, carrierName, 1 + zs / zr);
        for (const auto& pb : planetBodies) scene.addSpeedRelation(pb, carrierName, zs / zp);
        scene.addOrderExcitation({spec.name + ".mesh_frequency", carrierName, zs});
        scene.addDerivedValue({spec.name + ".ratio", 1 + zs / zr, "1", "w_ring/w_carrier = 1 + z_s/z_r (sun fixed)"});
    } else if (m.carrierFixed) {
        scene.addSpeedRelation(sunName, ringName, -zr / zs);
        for (const auto& pb : planetBodies) scene.addSpeedRelation(pb, sunName, -zs / zp);
        scene.addOrderExcitation({spec.name + ".mesh_frequency", sunName, zs});
        scene.addDerivedValue({spec.name + ".ratio", -zr / zs, "1", "w_sun/w_ring = -z_r/z_s (carrier fixed)"});
    }
    // Initial angles and speeds: the ring from sun and carrier by Willis (or,
    // with a fixed ring, the carrier from the sun), each planet rolling on the sun.
    scene.addInitializer([m, rs, rp, rr](State& st) {
        const MobilizerQIndex q0(0);
        const MobilizerUIndex u0(0);
        for (int level = 0; level < 2; ++level) {
            auto get = [&](const MobilizedBody& b, bool fixed) {
                return fixed ? 0.0 : level == 0 ? b.getOneQ(st, q0) : b.getOneU(st, u0);
            };
            auto set = [&](const MobilizedBody& b, double v) {
                if (level == 0) b.setOneQ(st, q0, v);
                else b.setOneU(st, u0, v);
            };
            const double s = get(m.sun, m.sunFixed);
            if (!m.ringFixed) {
                const double c = get(m.carrier, m.carrierFixed);
                set(m.ring, c - rs * (s - c) / rr);
            } else if (!m.carrierFixed) {
                set(m.carrier, rs * s / (rs + rr));
            }
            const double c = get(m.carrier, m.carrierFixed);
            for (const auto& planet : m.planets) set(planet, -rs * (s - c) / rp);
        }
    });
    scene.addSketch([m, rs, rp, rr](const State& st, Sketch& k) {
        k.circle("gear", m.axis[0], m.axis[1], rs);
        k.circle("gear", m.axis[0], m.axis[1], rr);
        for (const auto& planet : m.planets) {
            const Vec3 b = planet.getBodyOriginLocation(st);
            k.line("carrier", m.axis[0], m.axis[1], b[0], b[1]);
            k.circle("gear", b[0], b[1], rp);
        }
    });
    std::string fixedWhat = m.ringFixed ? "ring fixed" : m.sunFixed ? "sun fixed" : m.carrierFixed ? "carrier fixed"
                                                                                                 : "no member fixed";
    scene.note("planetary gear set " + spec.name + " (PlanetaryGearSet, " + spec.text("law") + ", " + fixedWhat + ")",
               std::to_string(n) + " planets; both meshes of each planet act at their pitch points");
}

}  // namespace

void registerPlanetaryGearSet(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "PlanetaryGearSet";
    s.doc = "Spur planetary stage: sun, planets on a carrier, ring; rigid or compliant meshes, load sharing.";
    auto member = [](const char* key, const char* doc) {
        P p = P::body(key, doc);
        p.required = false;
        return p;
    };
    auto list = [](P p) {
        p.required = false;
        return p;
    };
    s.params = {
        member("sun", "sun body on a pin on ground (omitted: the sun is fixed)"),
        member("ring", "ring body on a pin on ground (omitted: the ring is fixed)"),
        member("carrier", "carrier body on a pin on ground (omitted: the carrier is fixed)"),
        P::bodyList("planets", 1, 32, "planet bodies, each on a pin on the carrier at r_s + r_p from the axis"),
        P::quantityList("teeth", "1", 3, 3, "[z_sun, z_planet, z_ring], z_ring = z_sun + 2 z_planet"),
        P::quantity("module", "m", "module m: pitch radius r = m z/2").above(0),
        P::quantity("pressure_angle", "rad", "pressure angle alpha").optional(20.0 * M_PI / 180).atLeast(0).below(
            M_PI / 2),
        P::choice("law", {"rigid", "compliant"}, "constraints, or mesh stiffness and damping")
            .optional(std::string("rigid")),
        P::quantity("sun_mesh_stiffness", "N/m", "compliant: k of each sun-planet mesh along the line of action")
            .optional(0.0).atLeast(0),
        P::quantity("sun_mesh_damping", "N*s/m", "compliant: c of each sun-planet mesh").optional(0.0).atLeast(0),
        P::quantity("sun_backlash", "m", "compliant: play of each sun-planet mesh along the line of action")
            .optional(0.0).atLeast(0),
        P::quantity("ring_mesh_stiffness", "N/m", "compliant: k of each planet-ring mesh").optional(0.0).atLeast(0),
        P::quantity("ring_mesh_damping", "N*s/m", "compliant: c of each planet-ring mesh").optional(0.0).atLeast(0),
        P::quantity("ring_backlash", "m", "compliant: play of each planet-ring mesh").optional(0.0).atLeast(0),
        list(P::quantityList("pin_position_errors", "m", 1, 32,
                             "compliant: tangential position error of each planet's pin (+ along e_t)")),
        P::quantity("axial_position", "m", "z of the mesh plane in ground").optional(0.0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        int fixed = 0;
        for (const char* key : {"sun", "ring", "carrier"}) fixed += e.has(key) ? 0 : 1;
        if (fixed > 1)
            throw e.error("sun", "name at least two of sun, ring and carrier (an omitted member is fixed to ground)");
        std::vector<std::string> members;
        for (const char* key : {"sun", "ring", "carrier"})
            if (e.has(key)) {
                for (const auto& other : members)
                    if (other == e.text(key)) throw e.error(key, "'" + other + "' is named for two members");
                members.push_back(e.text(key));
            }
        for (const auto& planet : e.names("planets"))
            for (const auto& other : members)
                if (planet == other) throw e.error("planets", "'" + planet + "' is also a sun, ring or carrier");
        if (e.text("law") == "rigid") {
            for (const char* key : {"sun_mesh_stiffness", "sun_mesh_damping", "sun_backlash", "ring_mesh_stiffness",
                                    "ring_mesh_damping", "ring_backlash", "pin_position_errors"})
                if (e.has(key)) throw e.error(key, "not used by law: rigid (use law: compliant)");
        } else {
            for (const char* key : {"sun_mesh_stiffness", "ring_mesh_stiffness"})
                if (!(e.number(key) > 0))
                    throw e.error(e.has(key) ? key : "law", std::string("law: compliant needs ") + key + " > 0 N/m");
        }
        if (e.has("pin_position_errors") && e.numbers("pin_position_errors").size() != e.names("planets").size())
            throw e.error("pin_position_errors", "give one error per planet (" +
                                                     std::to_string(e.names("planets").size()) + "), got " +
                                                     std::to_string(e.numbers("pin_position_errors").size()));
        const auto& z = e.numbers("teeth");
        for (double v : z)
            if (!(v >= 1) || std::abs(v - std::round(v)) > 1e-9)
                throw e.error("teeth", "tooth counts must be whole numbers >= 1");
        if (z.size() == 3 && std::abs(z[2] - z[0] - 2 * z[1]) > 1e-9)
            throw e.error("teeth", "z_ring must be z_sun + 2 z_planet (" + std::to_string(std::lround(z[0])) + " + 2*" +
                                       std::to_string(std::lround(z[1])) + " = " +
                                       std::to_string(std::lround(z[0] + 2 * z[1])) + ", got " +
                                       std::to_string(std::lround(z[2])) + "); profile-shifted sets are not modelled");
    };
    registry.add({std::move(s), buildPlanetaryGearSet});
}

}  // namespace milldyn
