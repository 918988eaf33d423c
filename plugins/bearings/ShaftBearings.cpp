#include "plugins/bearings/ShaftBearings.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

ShaftBearings::ShaftBearings(const SimbodyMatterSubsystem& matter, const MobilizerReactions& reactions,
                             const MobilizedBody& body, const ShaftBearingsParams& p)
    : JournalFriction(matter, reactions, body, p.friction), m_allReactions(reactions), m_shaft(body), m_sp(p) {
    if (!std::isfinite(p.position1) || !std::isfinite(p.position2) || p.position1 == p.position2)
        throw std::invalid_argument("ShaftBearings: positions must be finite and different");
}

std::array<Vec3, 2> ShaftBearings::calcBearingForces(const State& s) const {
    const SpatialVec& r = m_allReactions.get(s)[m_shaft.getMobilizedBodyIndex()];
    const Vec3& moment = r[0];
    const Vec3& force = r[1];
    const double z1 = m_sp.position1, z2 = m_sp.position2;
    const Vec3 f2((moment[1] - z1 * force[0]) / (z2 - z1), (-moment[0] - z1 * force[1]) / (z2 - z1), 0);
    const Vec3 f1(force[0] - f2[0], force[1] - f2[1], 0);
    return {f1, f2};
}

double ShaftBearings::calcAxialLoad(const State& s) const {
    return m_allReactions.get(s)[m_shaft.getMobilizedBodyIndex()][1][2];
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
    auto* impl = new ShaftBearings(scene.matter(), scene.mobilizerReactions(), body->mobod, p);
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
                    [impl](const State& s) { return impl->calcAxialLoad(s); }});
    if (p.friction.frictionCoefficient > 0 && p.friction.journalDiameter > 0) {
        scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::ResistanceTorque, Stage::Velocity,
                        [impl](const State& s) { return std::abs(impl->calcTorque(s)); }});
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
                   std::to_string(p.position2) + " m; loads split from Simbody's pin reaction by statics");
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
        if (e.has("friction_coefficient") && e.number("friction_coefficient") > 0 && !(e.number("journal_diameter") > 0))
            throw e.error("journal_diameter", "friction needs the journal diameter d > 0 m");
    };
    registry.add({std::move(s), buildShaftBearings});
}

}  // namespace milldyn
