#include "plugins/transmissions/GearMesh.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

GearMesh::GearMesh(SimbodyMatterSubsystem& matter, const MobilizedBody& carrier, const MobilizedBody& planet,
                   const GearMeshParams& p)
    // Rolling on the fixed gear: R q1 + side r q2 = 0 (q1 the carrier's angle).
    : RollingConstraint(matter, carrier, planet, p.fixedPitchRadius, (p.internal ? 1.0 : -1.0) * p.planetPitchRadius),
      m_p(p), m_side(p.internal ? 1.0 : -1.0) {
    m_geometry.pitchRadius1 = p.fixedPitchRadius;
    m_geometry.pitchRadius2 = p.planetPitchRadius;
    m_geometry.internal = p.internal;
    m_geometry.pressureAngle = p.pressureAngle;
    auto bad = [](const std::string& what) { throw std::invalid_argument("GearMesh: " + what); };
    if (!(p.fixedPitchRadius > 0) || !std::isfinite(p.fixedPitchRadius))
        bad("fixed_pitch_radius must be finite and > 0 m");
    if (!(p.planetPitchRadius > 0) || !std::isfinite(p.planetPitchRadius))
        bad("planet_pitch_radius must be finite and > 0 m");
    if (p.internal && !(p.planetPitchRadius < p.fixedPitchRadius))
        bad("a planet rolling inside a ring needs planet_pitch_radius < fixed_pitch_radius");
    if (!(p.pressureAngle >= 0 && p.pressureAngle < M_PI / 2)) bad("pressure_angle must be in [0, 90) deg");
    if (&planet.getParentMobilizedBody() != &carrier &&
        planet.getParentMobilizedBody().getMobilizedBodyIndex() != carrier.getMobilizedBodyIndex())
        bad("the planet must be on a pin on the carrier");
    m_groundBody = addConstrainedBody(matter.getGround());
    m_carrierBody = addConstrainedBody(carrier);
    m_planetBody = addConstrainedBody(planet);
}

double GearMesh::calcPlanetAngle(double carrierAngle) const {
    // R q1 + side r q2 = 0
    return -m_p.fixedPitchRadius * carrierAngle / (m_side * m_p.planetPitchRadius);
}

double GearMesh::calcPlanetSpeed(double carrierSpeed) const { return calcPlanetAngle(carrierSpeed); }

void GearMesh::addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                             Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                             Array_<Real, ConstrainedQIndex>&) const {
    const double lambda = multipliers[0];
    const Transform& X_AC = getBodyTransformFromState(s, m_carrierBody);  // A is Ground here
    const Transform& X_AP = getBodyTransformFromState(s, m_planetBody);
    const Vec3 pitchPointInA = m_geometry.calcPitchPointOnGear2(X_AC.p(), X_AP.p());
    const Vec3 p_PS = ~X_AP.R() * (pitchPointInA - X_AP.p());
    // Simbody applies −(these forces): the fixed gear pushes the planet with
    // tangential force −λ along e_t and separates it along the line of action.
    const Vec3 applied = -m_geometry.calcForceOnGear2(-lambda, X_AC.p(), X_AP.p());
    addInStationForce(s, m_planetBody, p_PS, applied, bodyForcesInA);
}

double GearMesh::calcTangentialForce(const State& s, const Constraint& self) const {
    return -self.getMultipliersAsVector(s)[0];
}

double GearMesh::calcSeparatingForce(const State& s, const Constraint& self) const {
    return std::abs(calcTangentialForce(s, self)) * std::tan(m_p.pressureAngle);
}

namespace {

void buildGearMesh(const ElementSpec& spec, Scene& scene) {
    const SceneBody* carrier = scene.findBody(spec.text("carrier"));
    const SceneBody* planet = scene.findBody(spec.text("planet"));
    if (planet->mobod.getParentMobilizedBody().getMobilizedBodyIndex() != carrier->mobod.getMobilizedBodyIndex())
        throw spec.error("planet", "'" + planet->name + "' must be jointed to the carrier '" + carrier->name + "'");
    GearMeshParams p;
    p.fixedPitchRadius = spec.number("fixed_pitch_radius");
    p.planetPitchRadius = spec.number("planet_pitch_radius");
    p.internal = spec.text("rolling") == "internal";
    p.pressureAngle = spec.number("pressure_angle");
    GearGeometry geometry;
    geometry.pitchRadius1 = p.fixedPitchRadius;
    geometry.pitchRadius2 = p.planetPitchRadius;
    geometry.internal = p.internal;
    Vec3 arm = planet->mobod.getDefaultInboardFrame().p();  // the planet's axis in the carrier frame
    arm[2] = 0;
    const std::string misfit = geometry.checkCentreDistance(arm.norm());
    if (!misfit.empty()) throw spec.error("planet_pitch_radius", misfit);
    auto* impl = new GearMesh(scene.matter(), carrier->mobod, planet->mobod, p);
    Constraint::Custom constraint(impl);
    const ConstraintIndex index = constraint.getConstraintIndex();
    const SimbodyMatterSubsystem* matter = &scene.matter();
    auto self = [matter, index]() -> const Constraint& { return matter->getConstraint(index); };
    scene.addProbe({spec.name + ".tangential_force", "N", ProbeRole::Generic, Stage::Acceleration,
                    [impl, self](const State& s) { return impl->calcTangentialForce(s, self()); }});
    scene.addProbe({spec.name + ".separating_force", "N", ProbeRole::Generic, Stage::Acceleration,
                    [impl, self](const State& s) { return impl->calcSeparatingForce(s, self()); }});
    const MobilizedBody c = carrier->mobod, pl = planet->mobod;
    scene.addInitializer([impl, c, pl](State& s) {
        pl.setOneQ(s, MobilizerQIndex(0), impl->calcPlanetAngle(c.getOneQ(s, MobilizerQIndex(0))));
        pl.setOneU(s, MobilizerUIndex(0), impl->calcPlanetSpeed(c.getOneU(s, MobilizerUIndex(0))));
    });
    // Steady running keeps the planet at this speed ratio to the carrier.
    scene.addSpeedRelation(planet->name, carrier->name, impl->calcPlanetSpeed(1.0));
    // The steady-state search moves angles and speeds freely: hold the
    // constraint at position and velocity level (as GearPair does), or the
    // search ends on a state that violates it (issue 26 item 6).
    scene.addSteadyResidual({spec.name + ".rolling_error", [impl, c, pl](const State& s) {
                                 return pinAngle(s, pl) - impl->calcPlanetAngle(pinAngle(s, c));
                             }});
    scene.addSteadyResidual({spec.name + ".rolling_rate", [impl, c, pl](const State& s) {
                                 return pinSpeed(s, pl) - impl->calcPlanetSpeed(pinSpeed(s, c));
                             }});
    // The planet's pin speed is relative to the carrier (ω_r = ω1 R/r, eq
    // 15): κ = 1 + ω_r/ω1.
    scene.addDerivedValue({spec.name + ".speed_ratio", 1 + impl->calcPlanetSpeed(1.0), "1",
                           "κ = ω_planet/ω_carrier: (R + r)/r rolling outside the fixed gear (seed 000 eqs 4, 15), "
                           "−(R − r)/r inside a ring"});
    // Schematic: the fixed gear about the carrier's axis, the carrier arm to
    // the planet's axis, the planet's pitch circle.
    const double R = p.fixedPitchRadius, rp = p.planetPitchRadius;
    scene.addSketch([c, pl, R, rp](const State& s, Sketch& k) {
        const Vec3 a = c.getBodyOriginLocation(s), b = pl.getBodyOriginLocation(s);
        k.circle("fixed_gear", a[0], a[1], R, "fixed gear");
        k.line("carrier", a[0], a[1], b[0], b[1]);
        k.circle("gear", b[0], b[1], rp);
    });
    scene.note("constraint " + spec.name + " (GearMesh)",
               planet->name + " rolls " + (p.internal ? "inside a fixed ring" : "on a fixed sun gear") +
                   " about " + carrier->name + "'s axis; mesh force along the line of action");
}

}  // namespace

void registerGearMesh(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "GearMesh";
    s.doc = "Planet gear on a carrier rolling on a fixed gear (holonomic; force along the line of action).";
    s.params = {
        P::body("carrier", "carrier on a pin whose axis is the fixed gear's axis"),
        P::body("planet", "planet (drum) on a pin on the carrier"),
        P::quantity("fixed_pitch_radius", "m", "R: pitch radius of the fixed sun or ring gear").above(0),
        P::quantity("planet_pitch_radius", "m", "r: pitch radius of the planet's gear").above(0),
        P::choice("rolling", {"external", "internal"}, "planet outside the sun or inside the ring")
            .optional(std::string("external")),
        P::quantity("pressure_angle", "rad", "line-of-action angle").optional(20.0 * M_PI / 180).atLeast(0).below(
            M_PI / 2),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.text("carrier") == e.text("planet"))
            throw e.error("planet", "the planet and the carrier must be different bodies");
        if (e.text("rolling") == "internal" && !(e.number("planet_pitch_radius") < e.number("fixed_pitch_radius")))
            throw e.error("planet_pitch_radius", "a planet inside a ring needs r < R");
    };
    registry.add({std::move(s), buildGearMesh});
}

}  // namespace milldyn
