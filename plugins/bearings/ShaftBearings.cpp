#include "plugins/bearings/ShaftBearings.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/transmissions/BevelGearPair.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

ShaftBearings::ShaftBearings(const SimbodyMatterSubsystem& matter, const MobilizerReactions& reactions,
                             const MobilizedBody& body, const ShaftBearingsParams& p, const ShaftBearingsMesh& mesh)
    : JournalFriction(matter, reactions, body, p.friction), m_allReactions(reactions), m_shaft(body), m_sp(p),
      m_mesh(mesh) {
    if (!std::isfinite(p.position1) || !std::isfinite(p.position2) || p.position1 == p.position2)
        throw std::invalid_argument("ShaftBearings: positions must be finite and different");
    if (p.thrustBearing != 1 && p.thrustBearing != 2)
        throw std::invalid_argument("ShaftBearings: the thrust bearing is bearing 1 or 2");
    if (mesh.mesh && (!std::isfinite(mesh.position) || !std::isfinite(mesh.angle)))
        throw std::invalid_argument("ShaftBearings: mesh_position and mesh_angle must be finite");
}

SpatialVec ShaftBearings::calcShaftReaction(const State& s) const {
    SpatialVec r = m_allReactions.get(s)[m_shaft.getMobilizedBodyIndex()];
    if (!m_mesh.mesh) return r;
    const MobilizedBodyIndex shaft = m_shaft.getMobilizedBodyIndex();
    const double rm = m_mesh.mesh->meanRadiusOn(shaft), th = m_mesh.angle;
    // Pin frame F (z the axis) in ground: the parent's rotation and F in it.
    const Rotation R_GF = m_shaft.getParentMobilizedBody().getBodyRotation(s) * m_shaft.getInboardFrame(s).R();
    const Vec3 force = R_GF * m_mesh.mesh->calcShaftForce(s, shaft, th);
    const Vec3 point = R_GF * Vec3(rm * std::cos(th), rm * std::sin(th), m_mesh.position);
    r[0] -= point % force;
    r[1] -= force;
    return r;
}

std::array<Vec3, 2> ShaftBearings::calcBearingForces(const State& s) const {
    const SpatialVec r = calcShaftReaction(s);
    const Vec3& moment = r[0];
    const Vec3& force = r[1];
    const double z1 = m_sp.position1, z2 = m_sp.position2;
    const Vec3 f2((moment[1] - z1 * force[0]) / (z2 - z1), (-moment[0] - z1 * force[1]) / (z2 - z1), 0);
    const Vec3 f1(force[0] - f2[0], force[1] - f2[1], 0);
    return {f1, f2};
}

double ShaftBearings::calcAxialLoad(const State& s) const {
    return calcShaftReaction(s)[1][2];
}

double ShaftBearings::calcReaction(const State& s) const {
    const auto f = calcBearingForces(s);
    return f[0].norm() + f[1].norm();
}

double ShaftBearings::calcBearingTorque(const State& s, int i) const {
    return calcFrictionTorque(calcBearingForces(s)[i].norm(), m_sp.friction, m_shaft.getOneU(s, MobilizerUIndex(0)));
}

namespace {

void buildShaftBearings(const ElementSpec& spec, Scene& scene) {
    const SceneBody* body = scene.findBody(spec.text("body"));
    ShaftBearingsParams p;
    const auto& z = spec.numbers("positions");
    p.position1 = z.at(0);
    p.position2 = z.at(1);
    p.friction.frictionCoefficient = spec.number("friction_coefficient");
    p.friction.journalDiameter = spec.number("journal_diameter");
    p.friction.smoothingSpeed = spec.number("smoothing_speed");
    p.friction.coupling = readReactionCoupling(spec);
    p.thrustBearing = spec.text("thrust_bearing") == "bearing_2" ? 2 : 1;
    ShaftBearingsMesh mesh;
    if (spec.has("mesh")) {
        const std::string name = spec.text("mesh");
        mesh.mesh = scene.findElement<BevelShaftLoads>(name);
        if (!mesh.mesh)
            throw spec.error("mesh", "no BevelGearPair named '" + name +
                                         "' listed before this element (list the bevel pair first)");
        const MobilizedBodyIndex i = body->mobod.getMobilizedBodyIndex();
        if (i != mesh.mesh->pinionIndex() && i != mesh.mesh->wheelIndex())
            throw spec.error("body", "'" + body->name + "' is neither the pinion nor the wheel of " + name);
        mesh.position = spec.number("mesh_position");
        mesh.angle = spec.number("mesh_angle");
    }
    auto* impl = new ShaftBearings(scene.matter(), scene.mobilizerReactions(), body->mobod, p, mesh);
    Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    for (int i = 0; i < 2; ++i) {
        const std::string stem = spec.name + ".bearing_" + std::to_string(i + 1);
        scene.addProbe({stem + ".radial_load", "N", ProbeRole::Generic, Stage::Acceleration,
                        [impl, i](const State& s) { return impl->calcBearingForces(s)[i].norm(); }});
        scene.addProbe({stem + ".x_ground", "N", ProbeRole::Generic, Stage::Acceleration,
                        [impl, i](const State& s) { return impl->calcBearingForces(s)[i][0]; }});
        scene.addProbe({stem + ".y_ground", "N", ProbeRole::Generic, Stage::Acceleration,
                        [impl, i](const State& s) { return impl->calcBearingForces(s)[i][1]; }});
        if (p.friction.frictionCoefficient > 0)
            scene.addProbe({stem + ".friction_torque", "N*m", ProbeRole::Generic, Stage::Acceleration,
                            [impl, i](const State& s) { return std::abs(impl->calcBearingTorque(s, i)); }});
    }
    scene.addProbe({spec.name + ".axial_load", "N", ProbeRole::Generic, Stage::Acceleration,
                    [impl](const State& s) { return impl->calcAxialLoad(s); },
                    "thrust: force of the housing on the shaft along its +z"});
    scene.addProbe({spec.name + ".bearing_" + std::to_string(p.thrustBearing) + ".axial_load", "N",
                    ProbeRole::Generic, Stage::Acceleration, [impl](const State& s) { return impl->calcAxialLoad(s); },
                    "the locating bearing's thrust on the shaft along its +z (the other bearing floats)"});
    if (p.friction.frictionCoefficient > 0 && p.friction.journalDiameter > 0) {
        // Signed like every load's (+ about +z, what the bearings take from
        // the shaft); the per-bearing friction_torque above is a magnitude.
        scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::ResistanceTorque, Stage::Velocity,
                        [impl](const State& s) { return impl->calcTorque(s); }});
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                             [impl](const State& s) { return impl->calcPower(s); }});
        addKeptLoad(scene, spec.name, impl);
    }
    const MobilizedBody mobod = body->mobod;
    const std::string label = spec.name;
    scene.addSketch([impl, mobod, label](const State& s, Sketch& k) {
        const Vec3 at = mobod.getBodyOriginLocation(s);
        const auto f = impl->calcBearingForces(s);
        k.arrow("reaction", at[0], at[1], f[0][0], f[0][1], label + ".bearing_1");
        k.arrow("reaction", at[0], at[1], f[1][0], f[1][1], label + ".bearing_2");
    });
    scene.note("force " + spec.name + " (ShaftBearings, " + describeReactionCoupling(p.friction.coupling) + ")",
               body->name + " on two bearings at z = " + std::to_string(p.position1) + " m and " +
                   std::to_string(p.position2) + " m (bearing " + std::to_string(p.thrustBearing) +
                   " locating); loads split from Simbody's pin reaction by statics" +
                   (mesh.mesh ? ", with " + spec.text("mesh") + "'s tooth force at z = " +
                                    std::to_string(mesh.position) + " m"
                              : std::string()));
}

}  // namespace

void registerShaftBearings(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "ShaftBearings";
    s.doc = "A shaft on two bearings at axial positions: radial load and journal friction per bearing (statics).";
    s.params = {
        P::body("body", "shaft on a pin; its frame's z is the axis, z = 0 at the joint location"),
        P::quantityList("positions", "m", 1, 100, "[z1, z2]: the bearings' axial positions in the shaft's frame"),
        P::quantity("friction_coefficient", "1", "f (0: loads only)").optional(0.0).atLeast(0).atMost(1),
        P::quantity("journal_diameter", "m", "d").optional(0.0).atLeast(0),
        P::quantity("smoothing_speed", "rad/s", "omega_s of tanh(u/omega_s)").optional(1e-3).above(0),
        P::choice("thrust_bearing", {"bearing_1", "bearing_2"}, "the locating bearing: it takes the whole thrust")
            .optional(std::string("bearing_1")),
        P::text("mesh", "a BevelGearPair listed before, on this shaft: its tooth force loads the bearings")
            .optional(std::string()),
        P::quantity("mesh_position", "m", "with mesh: z_m of the mean point in the shaft's frame").optional(0.0),
        P::quantity("mesh_angle", "rad", "with mesh: direction of the mean point from the axis, from x towards y")
            .optional(0.0),
    };
    for (ParamSchema& k : reactionCouplingParams()) s.params.push_back(std::move(k));
    s.crossCheck = [](const ElementSpec& e) {
        readReactionCoupling(e);
        const auto& z = e.numbers("positions");
        if (z.size() == 1)
            throw e.error("positions", "1 bearing cannot carry the shaft's tilting moment (a journal on the pin "
                                       "is JournalFriction); give two");
        if (z.size() > 2)
            throw e.error("positions", std::to_string(z.size()) +
                                           " bearings: a rigid shaft on more than two supports is statically "
                                           "indeterminate (the split needs their stiffness and alignment); give two");
        if (z[0] == z[1]) throw e.error("positions", "the two bearings must be at different axial positions");
        if (e.has("mesh")) {
            if (e.text("mesh").empty()) throw e.error("mesh", "name a BevelGearPair");
            if (!e.has("mesh_position"))
                throw e.error("mesh", "needs mesh_position: the mean point's axial position in the shaft's frame");
        } else {
            for (const char* key : {"mesh_position", "mesh_angle"})
                if (e.has(key)) throw e.error(key, "only with mesh: (a BevelGearPair on this shaft)");
        }
        if (e.has("friction_coefficient") && e.number("friction_coefficient") > 0 && !(e.number("journal_diameter") > 0))
            throw e.error("journal_diameter", "friction needs the journal diameter d > 0 m");
    };
    registry.add({std::move(s), buildShaftBearings});
}

}  // namespace milldyn
