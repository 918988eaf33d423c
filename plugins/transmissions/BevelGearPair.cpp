#include "plugins/transmissions/BevelGearPair.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

double BevelGearParams::pinionPitchAngle() const {
    return std::atan2(std::sin(shaftAngle), wheelTeeth / pinionTeeth + std::cos(shaftAngle));
}

double BevelGearParams::transversePressureAngle() const {
    return std::atan(std::tan(pressureAngle) / std::cos(spiralAngle));
}

void BevelGearParams::check() const {
    auto bad = [](const std::string& what) { throw std::invalid_argument("BevelGearPair: " + what); };
    for (double z : {pinionTeeth, wheelTeeth})
        if (!(z >= 1) || std::abs(z - std::round(z)) > 1e-9) bad("tooth counts must be whole numbers >= 1");
    if (!(meanPitchRadius > 0) || !std::isfinite(meanPitchRadius)) bad("mean_pitch_radius must be finite and > 0 m");
    if (!(shaftAngle > 0 && shaftAngle < M_PI)) bad("shaft_angle must be in (0, 180) deg");
    if (!(pressureAngle >= 0 && pressureAngle < M_PI / 2)) bad("pressure_angle must be in [0, 90) deg");
    if (!(spiralAngle >= 0 && spiralAngle < M_PI / 2)) bad("spiral_angle must be in [0, 90) deg");
    if (law == BevelLaw::Compliant) {
        if (!(meshStiffness > 0) || !std::isfinite(meshStiffness)) bad("mesh_stiffness must be finite and > 0 N/m");
        if (!(meshDamping >= 0) || !std::isfinite(meshDamping)) bad("mesh_damping must be finite and >= 0 N*s/m");
        if (!(backlash >= 0) || !std::isfinite(backlash)) bad("backlash must be finite and >= 0 m");
    }
}

BevelForces calcBevelForces(const BevelGearParams& p, double ft) {
    const double wt = std::abs(ft);
    const double d1 = p.pinionPitchAngle(), b = p.spiralAngle, tn = std::tan(p.pressureAngle);
    // σ = hand · sign(torque on the pinion) = hand · sign(−F_t); 0 load: no force.
    const double sigma = ft == 0 ? 0.0 : p.pinionHand * (ft < 0 ? 1.0 : -1.0);
    BevelForces f;
    f.tangential = ft;
    f.pinionAxial = wt / std::cos(b) * (tn * std::sin(d1) - sigma * std::sin(b) * std::cos(d1));
    f.pinionRadial = wt / std::cos(b) * (tn * std::cos(d1) + sigma * std::sin(b) * std::sin(d1));
    const double S = p.shaftAngle;
    f.wheelAxial = -f.pinionAxial * std::cos(S) + f.pinionRadial * std::sin(S);
    f.wheelRadial = f.pinionAxial * std::sin(S) + f.pinionRadial * std::cos(S);
    return f;
}

Vec3 BevelShaftLoads::calcShaftForce(const State& s, MobilizedBodyIndex shaft, double theta) const {
    const BevelGearParams& p = bevelParams();
    const BevelForces f = calcShaftForces(s);
    const Vec3 er(std::cos(theta), std::sin(theta), 0), et(-std::sin(theta), std::cos(theta), 0), ez(0, 0, 1);
    if (shaft == pinionIndex()) return f.pinionAxial * ez - f.pinionRadial * er - f.tangential * et;
    if (shaft == wheelIndex()) {
        const double sense = p.wheelAxisSense;
        return sense * f.wheelAxial * ez - f.wheelRadial * er - sense * f.tangential * et;
    }
    throw std::invalid_argument("BevelShaftLoads: the shaft is neither the pinion nor the wheel");
}

double BevelShaftLoads::meanRadiusOn(MobilizedBodyIndex shaft) const {
    if (shaft == pinionIndex()) return bevelParams().meanPitchRadius;
    if (shaft == wheelIndex()) return bevelParams().wheelMeanPitchRadius();
    throw std::invalid_argument("BevelShaftLoads: the shaft is neither the pinion nor the wheel");
}

// -------------------------------------------------------------- compliant

BevelMeshForce::BevelMeshForce(const MobilizedBody& pinion, const MobilizedBody& wheel, const BevelGearParams& p)
    : m_pinion(pinion), m_wheel(wheel), m_p(p), m_cosAlphaT(std::cos(p.transversePressureAngle())) {
    p.check();
}

double BevelMeshForce::calcMeshDisplacement(const State& s) const {
    return m_p.meanPitchRadius * m_pinion.getOneQ(s, MobilizerQIndex(0)) +
           m_p.wheelAxisSense * m_p.wheelMeanPitchRadius() * m_wheel.getOneQ(s, MobilizerQIndex(0));
}

double BevelMeshForce::calcMeshDisplacementRate(const State& s) const {
    return m_p.meanPitchRadius * m_pinion.getOneU(s, MobilizerUIndex(0)) +
           m_p.wheelAxisSense * m_p.wheelMeanPitchRadius() * m_wheel.getOneU(s, MobilizerUIndex(0));
}

double BevelMeshForce::gap(double deltaB) const {
    const double half = m_p.backlash / 2;
    if (deltaB > half) return deltaB - half;
    if (deltaB < -half) return deltaB + half;
    return 0;
}

double BevelMeshForce::calcTangentialForce(const State& s) const {
    const double g = gap(calcMeshDisplacement(s) * m_cosAlphaT);
    if (g == 0 && m_p.backlash > 0) return 0;
    return (m_p.meshStiffness * g + m_p.meshDamping * calcMeshDisplacementRate(s) * m_cosAlphaT) * m_cosAlphaT;
}

double BevelMeshForce::calcDampingPower(const State& s) const {
    if (m_p.backlash > 0 && gap(calcMeshDisplacement(s) * m_cosAlphaT) == 0) return 0;
    const double rateB = calcMeshDisplacementRate(s) * m_cosAlphaT;
    return m_p.meshDamping * rateB * rateB;
}

void BevelMeshForce::calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const {
    const double ft = calcTangentialForce(s);
    m_pinion.applyOneMobilityForce(s, MobilizerUIndex(0), -m_p.meanPitchRadius * ft, mobilityForces);
    m_wheel.applyOneMobilityForce(s, MobilizerUIndex(0), -m_p.wheelAxisSense * m_p.wheelMeanPitchRadius() * ft,
                                  mobilityForces);
}

Real BevelMeshForce::calcPotentialEnergy(const State& s) const {
    const double g = gap(calcMeshDisplacement(s) * m_cosAlphaT);
    return 0.5 * m_p.meshStiffness * g * g;
}

// ------------------------------------------------------------------ rigid

BevelRollingConstraint::BevelRollingConstraint(SimbodyMatterSubsystem& matter, const MobilizedBody& pinion,
                                               const MobilizedBody& wheel, double c1, double c2)
    : Implementation(matter, 1, 0, 0), m_c1(c1), m_c2(c2) {
    m_mob1 = addConstrainedMobilizer(pinion);
    m_mob2 = addConstrainedMobilizer(wheel);
}

void BevelRollingConstraint::calcPositionErrors(const State& s, const Array_<Transform, ConstrainedBodyIndex>&,
                                                const Array_<Real, ConstrainedQIndex>& q, Array_<Real>& perr) const {
    const MobilizerQIndex q0(0);
    perr[0] = m_c1 * getOneQ(s, q, m_mob1, q0) + m_c2 * getOneQ(s, q, m_mob2, q0);
}

void BevelRollingConstraint::calcPositionDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                   const Array_<Real, ConstrainedQIndex>& qdot,
                                                   Array_<Real>& pverr) const {
    const MobilizerQIndex q0(0);
    pverr[0] = m_c1 * getOneQDot(s, qdot, m_mob1, q0) + m_c2 * getOneQDot(s, qdot, m_mob2, q0);
}

void BevelRollingConstraint::calcPositionDotDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                      const Array_<Real, ConstrainedQIndex>& qdotdot,
                                                      Array_<Real>& paerr) const {
    const MobilizerQIndex q0(0);
    paerr[0] = m_c1 * getOneQDotDot(s, qdotdot, m_mob1, q0) + m_c2 * getOneQDotDot(s, qdotdot, m_mob2, q0);
}

void BevelRollingConstraint::addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                                           Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                           Array_<Real, ConstrainedQIndex>& qForces) const {
    // Gᵀλ on the two pin angles; Simbody applies −Gᵀλ, so the pinion gets
    // −r_m1 λ: λ is F_t.
    const MobilizerQIndex q0(0);
    addInOneQForce(s, m_mob1, q0, m_c1 * multipliers[0], qForces);
    addInOneQForce(s, m_mob2, q0, m_c2 * multipliers[0], qForces);
}

// ---------------------------------------------------------------- element

namespace {

void buildBevelGearPair(const ElementSpec& spec, Scene& scene) {
    const auto& names = spec.names("bodies");
    const SceneBody* b1 = scene.findBody(names.at(0));
    const SceneBody* b2 = scene.findBody(names.at(1));
    const MobilizedBody g1 = b1->mobod, g2 = b2->mobod;
    if (g1.getParentMobilizedBody().getMobilizedBodyIndex() != g2.getParentMobilizedBody().getMobilizedBodyIndex())
        throw spec.error("bodies", "'" + b1->name + "' and '" + b2->name +
                                       "' must turn on pins on the same parent body (the gearbox housing)");
    BevelGearParams p;
    const auto& z = spec.numbers("teeth");
    p.pinionTeeth = z.at(0);
    p.wheelTeeth = z.at(1);
    p.meanPitchRadius = spec.number("mean_pitch_radius");
    p.shaftAngle = spec.number("shaft_angle");
    p.pressureAngle = spec.number("pressure_angle");
    p.spiralAngle = spec.number("spiral_angle");
    p.pinionHand = spec.text("hand") == "left" ? -1 : 1;
    p.wheelAxisSense = spec.text("wheel_axis") == "towards_apex" ? -1 : 1;
    p.law = spec.text("law") == "compliant" ? BevelLaw::Compliant : BevelLaw::Rigid;
    p.meshStiffness = spec.number("mesh_stiffness");
    p.meshDamping = spec.number("mesh_damping");
    p.backlash = spec.number("backlash");
    try {
        p.check();
    } catch (const std::invalid_argument& e) {
        throw spec.error("teeth", e.what());
    }
    const double r1 = p.meanPitchRadius, r2 = p.wheelMeanPitchRadius(), s = p.wheelAxisSense;
    std::function<double(const State&)> tangential;
    if (p.law == BevelLaw::Compliant) {
        auto* impl = new BevelMeshForce(g1, g2, p);
        Force::Custom force(scene.forces(), impl);
        scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
        tangential = [impl](const State& st) { return impl->calcTangentialForce(st); };
        scene.addProbe({spec.name + ".mesh_deflection", "m", ProbeRole::Generic, Stage::Position,
                        [impl](const State& st) { return impl->calcMeshDisplacement(st); }});
        if (p.meshDamping > 0)
            scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                                 [impl](const State& st) { return impl->calcDampingPower(st); }});
    } else {
        auto* impl = new BevelRollingConstraint(scene.matter(), g1, g2, r1, s * r2);
        Constraint::Custom constraint(impl);
        // Applies nothing: it is how a ShaftBearings' `mesh:` finds F_t.
        auto* loads = new BevelRigidShaftLoads(scene.matter(), constraint.getConstraintIndex(), g1, g2, p);
        Force::Custom force(scene.forces(), loads);
        scene.addForce(spec.name, spec.type, force.getForceIndex(), loads);
        tangential = [loads](const State& st) { return loads->calcTangentialForce(st); };
        scene.addSteadyResidual({spec.name + ".rolling_error", [g1, g2, r1, r2, s](const State& st) {
                                     return r1 * pinAngle(st, g1) + s * r2 * pinAngle(st, g2);
                                 }});
    }
    scene.addSteadyResidual({spec.name + ".mesh_deflection_rate", [g1, g2, r1, r2, s](const State& st) {
                                 return r1 * pinSpeed(st, g1) + s * r2 * pinSpeed(st, g2);
                             }});
    const Stage stage = p.law == BevelLaw::Rigid ? Stage::Acceleration : Stage::Velocity;
    auto forces = [tangential, p](const State& st) { return calcBevelForces(p, tangential(st)); };
    scene.addProbe({spec.name + ".tangential_force", "N", ProbeRole::Generic, stage, tangential,
                    "F_t at the mean point: the mesh's torque on the pinion is -r_m1 F_t"});
    scene.addProbe({spec.name + ".pinion_axial_force", "N", ProbeRole::Generic, stage,
                    [forces](const State& st) { return forces(st).pinionAxial; },
                    "on the pinion along its axis, + away from the cone apex"});
    scene.addProbe({spec.name + ".pinion_radial_force", "N", ProbeRole::Generic, stage,
                    [forces](const State& st) { return forces(st).pinionRadial; },
                    "on the pinion, + towards its own axis"});
    scene.addProbe({spec.name + ".wheel_axial_force", "N", ProbeRole::Generic, stage,
                    [forces](const State& st) { return forces(st).wheelAxial; },
                    "on the wheel along its axis, + away from the cone apex"});
    scene.addProbe({spec.name + ".wheel_radial_force", "N", ProbeRole::Generic, stage,
                    [forces](const State& st) { return forces(st).wheelRadial; },
                    "on the wheel, + towards its own axis"});
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::CouplingTorque, stage,
                    [tangential, r1](const State& st) { return tangential(st) * r1; },
                    "r_m1 F_t: torque the pinion passes to the mesh"});
    scene.addProbe({spec.name + ".mesh_power", "W", ProbeRole::Generic, stage,
                    [tangential, r1, g1](const State& st) { return tangential(st) * r1 * pinSpeed(st, g1); }});
    const double z1 = p.pinionTeeth;
    scene.addProbe({spec.name + ".mesh_frequency", "Hz", ProbeRole::Generic, Stage::Velocity,
                    [z1, g1](const State& st) { return z1 * std::abs(pinSpeed(st, g1)) / (2 * M_PI); }});
    scene.addOrderExcitation({spec.name + ".mesh_frequency", b1->name, z1});
    scene.addDerivedValue({spec.name + ".ratio", -s * r2 / r1, "1", "omega_1/omega_2 = -s z2/z1 (s: wheel_axis sense)"});
    scene.addDerivedValue({spec.name + ".wheel_mean_pitch_radius", r2, "m", "r_m2 = r_m1 z2/z1"});
    scene.addDerivedValue({spec.name + ".pinion_pitch_angle", p.pinionPitchAngle(), "rad",
                           "delta_1: tan(delta_1) = sin(Sigma)/(z2/z1 + cos(Sigma))"});
    scene.addDerivedValue({spec.name + ".wheel_pitch_angle", p.wheelPitchAngle(), "rad", "delta_2 = Sigma - delta_1"});
    scene.addDerivedValue({spec.name + ".mean_cone_distance", r1 / std::sin(p.pinionPitchAngle()), "m",
                           "R_m = r_m1/sin(delta_1)"});
    scene.addInitializer([g1, g2, r1, r2, s](State& st) {
        g2.setOneQ(st, MobilizerQIndex(0), -r1 * g1.getOneQ(st, MobilizerQIndex(0)) / (s * r2));
        g2.setOneU(st, MobilizerUIndex(0), -r1 * g1.getOneU(st, MobilizerUIndex(0)) / (s * r2));
    });
    scene.addSpeedRelation(b1->name, b2->name, -s * r2 / r1);
    scene.note("bevel gear pair " + spec.name + " (BevelGearPair, " + spec.text("law") + ", " +
                   (p.spiralAngle > 0 ? "spiral" : "straight") + ")",
               b1->name + " meshes with " + b2->name +
                   "; axial and radial forces reported, not applied to the bodies (a ShaftBearings with mesh: " +
                   spec.name + " adds the tooth force to its shaft's bearing loads)");
}

}  // namespace

void registerBevelGearPair(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "BevelGearPair";
    s.doc = "Straight or spiral bevel mesh (shaft angle Sigma): torsional ratio and signed tooth forces on both shafts.";
    s.params = {
        P::bodyPair("bodies", "[pinion, wheel] on pins on one parent"),
        P::quantityList("teeth", "1", 2, 2, "[z1, z2]"),
        P::quantity("mean_pitch_radius", "m", "r_m1: the pinion's pitch radius at mid face width").above(0),
        P::quantity("shaft_angle", "rad", "Sigma between the axes").optional(M_PI / 2).above(0).below(M_PI),
        P::quantity("pressure_angle", "rad", "normal pressure angle alpha_n").optional(20.0 * M_PI / 180).atLeast(0)
            .below(M_PI / 2),
        P::quantity("spiral_angle", "rad", "mean spiral angle beta_m (0: straight bevel)").optional(0.0).atLeast(0)
            .below(M_PI / 2),
        P::choice("hand", {"right", "left"}, "hand of the pinion's spiral (the wheel's is the other)")
            .optional(std::string("right")),
        P::choice("wheel_axis", {"away_from_apex", "towards_apex"},
                  "sense of the wheel's +z (the pinion's +z points away from the apex)")
            .optional(std::string("away_from_apex")),
        P::choice("law", {"rigid", "compliant"}, "a constraint, or mesh stiffness and damping")
            .optional(std::string("rigid")),
        P::quantity("mesh_stiffness", "N/m", "compliant: k along the transverse line of action").optional(0.0)
            .atLeast(0),
        P::quantity("mesh_damping", "N*s/m", "compliant: c along the line of action").optional(0.0).atLeast(0),
        P::quantity("backlash", "m", "compliant: play j along the line of action").optional(0.0).atLeast(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const auto& n = e.names("bodies");
        if (n.size() == 2 && n[0] == n[1])
            throw e.error("bodies", "a bevel pair needs two different bodies, got '" + n[0] + "' twice");
        for (double z : e.numbers("teeth"))
            if (!(z >= 1) || std::abs(z - std::round(z)) > 1e-9)
                throw e.error("teeth", "tooth counts must be whole numbers >= 1");
        if (e.text("law") == "rigid") {
            for (const char* key : {"mesh_stiffness", "mesh_damping", "backlash"})
                if (e.has(key)) throw e.error(key, "not used by law: rigid (use law: compliant)");
        } else if (!(e.number("mesh_stiffness") > 0)) {
            throw e.error(e.has("mesh_stiffness") ? "mesh_stiffness" : "law",
                          "law: compliant needs mesh_stiffness > 0 N/m");
        }
        if (e.has("hand") && !(e.number("spiral_angle") > 0))
            throw e.error("hand", "a straight bevel (spiral_angle 0) has no hand");
    };
    registry.add({std::move(s), buildBevelGearPair});
}

}  // namespace milldyn
