// An out-of-tree plugin: a new element type, `ConstantTorque`, registered
// through the same registry the built-ins use. Built by CMake into
// build/libmilldyn_example_plugin.so; load it with
//   build/milldyn run MODEL --plugin build/libmilldyn_example_plugin.so
// (docs/plugins.md walks through it).

#include "plugins/scene/PluginApi.h"

#include <Simbody.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

/**
 * A constant torque on one pin-jointed shaft (a brake or a test load).
 * <pre>
 *   the shaft gets +M as a mobility force; power M·ω; not conservative
 * </pre>
 */
class ConstantTorque : public SimTK::Force::Custom::Implementation {
public:
    ConstantTorque(const SimTK::MobilizedBody& shaft, double torque) : m_shaft(shaft), m_torque(torque) {
        if (!std::isfinite(torque))
            throw std::invalid_argument("ConstantTorque: torque = " + std::to_string(torque) + " is not finite");
    }
    double torque() const { return m_torque; }
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector& mobilityForces) const override {
        m_shaft.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), m_torque, mobilityForces);
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody m_shaft;
    double m_torque;
};

void buildConstantTorque(const milldyn::ElementSpec& spec, milldyn::Scene& scene) {
    const milldyn::SceneBody* shaft = scene.findBody(spec.text("body"));
    auto* impl = new ConstantTorque(shaft->mobod, spec.number("torque"));
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const SimTK::MobilizedBody mobod = shaft->mobod;
    scene.addProbe({spec.name + ".torque", "N*m", milldyn::ProbeRole::DriveTorque, SimTK::Stage::Position,
                    [impl](const SimTK::State&) { return impl->torque(); }});
    scene.addEnergyFlow({spec.name, milldyn::EnergyFlow::Kind::Source, [impl, mobod](const SimTK::State& s) {
                             return impl->torque() * milldyn::pinSpeed(s, mobod);
                         }});
    scene.note("force " + spec.name + " (ConstantTorque, from a plugin)", "acts on body " + shaft->name);
}

void registerExampleElements(milldyn::ElementRegistry& registry) {
    using P = milldyn::ParamSchema;
    milldyn::ElementSchema s;
    s.type = "ConstantTorque";
    s.doc = "A constant torque on a shaft (example plugin).";
    s.params = {P::body("body", "shaft the torque acts on"), P::quantity("torque", "N*m", "torque, signed")};
    registry.add({std::move(s), buildConstantTorque});
}

}  // namespace

MILLDYN_PLUGIN(registerExampleElements)
