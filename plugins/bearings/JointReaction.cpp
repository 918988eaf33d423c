// JointReaction: output-only element reporting the force a body's parent
// exerts on it through its joint (a bearing reaction), from Simbody.

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/MobilizerReactions.h"

#include <cmath>

namespace milldyn {

namespace {

void buildJointReaction(const ElementSpec& spec, Scene& scene) {
    const SceneBody* body = scene.findBody(spec.text("body"));
    // Force of the parent on the body at its joint axis (the mobilizer's
    // M-frame origin), ground axes [N]. Includes every constraint, motion
    // and applied force (docs/simbody-notes.md); needs Stage::Acceleration.
    const MobilizerReactions* reactions = &scene.mobilizerReactions();
    const SimTK::MobilizedBody mobod = body->mobod;
    auto force = [reactions, mobod](const SimTK::State& s) { return reactions->getForce(s, mobod); };
    const std::string stem = spec.name + ".on_" + body->name + "_at_axis";
    scene.addProbe({stem + "_x_ground", "N", ProbeRole::Generic, SimTK::Stage::Acceleration,
                    [force](const SimTK::State& s) { return force(s)[0]; }});
    scene.addProbe({stem + "_y_ground", "N", ProbeRole::Generic, SimTK::Stage::Acceleration,
                    [force](const SimTK::State& s) { return force(s)[1]; }});
    scene.addProbe({stem + "_magnitude", "N", ProbeRole::Generic, SimTK::Stage::Acceleration,
                    [force](const SimTK::State& s) { return force(s).norm(); }});
    // Schematic: the reaction as an arrow at the joint axis (same force as
    // the _x_ground/_y_ground columns).
    const std::string label = spec.name;
    scene.addSketch([force, mobod, label](const SimTK::State& s, Sketch& k) {
        const SimTK::Vec3 f = force(s), at = mobod.getBodyOriginLocation(s);
        k.arrow("reaction", at[0], at[1], f[0], f[1], label);
    });
    scene.note("output " + spec.name + " (JointReaction)",
               "force of " + body->name + "'s parent on it at its joint axis, ground axes");
}

}  // namespace

void registerJointReaction(ElementRegistry& registry) {
    ElementSchema s;
    s.type = "JointReaction";
    s.doc = "Output only: the bearing reaction of a body's joint (force of the parent on the body, ground axes).";
    s.params = {ParamSchema::body("body", "body whose joint reaction is reported")};
    s.outputOnly = true;
    registry.add({std::move(s), buildJointReaction});
}

}  // namespace milldyn
