#include "driver/SceneBuilder.h"

#include "driver/ReducedInertia.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/EnergyMeter.h"

#include <algorithm>
#include <stdexcept>

namespace milldyn {
namespace {
constexpr double kPlaceholderMass = 1.0;  // [kg]

/// `name` is `parent` or one of its outputs ("parent.x").
bool isOrUnder(const std::string& name, const std::string& parent) {
    return name == parent || name.compare(0, parent.size() + 1, parent + ".") == 0;
}

/// Every body an element names (its body keys, in schema order, each once),
/// joined by ", ": the shaft a contribution record gives a probe that names
/// none (a coupling's torque acts on both its bodies).
std::string elementBodies(const ElementSpec& e) {
    const ElementType* type = ElementRegistry::instance().find(e.type);
    if (!type) return "";
    std::vector<std::string> distinct;
    auto add = [&distinct](const std::string& n) {
        if (!n.empty() && std::find(distinct.begin(), distinct.end(), n) == distinct.end()) distinct.push_back(n);
    };
    for (const auto& p : type->schema.params) {
        const auto v = e.params.find(p.key);
        if (v == e.params.end()) continue;
        if (p.kind == ParamKind::BodyRef) add(v->second.text);
        if (p.kind == ParamKind::BodyPair || p.kind == ParamKind::BodyList)
            for (const auto& n : v->second.names) add(n);
    }
    std::string out;
    for (const auto& n : distinct) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& names) {
    const std::string near = nearestName(word, names);
    return near.empty() ? "" : " (did you mean '" + near + "'?)";
}
}  // namespace

std::string elementShaft(const ElementSpec& e) {
    const ElementType* type = ElementRegistry::instance().find(e.type);
    if (!type) return "";
    for (const auto& p : type->schema.params) {
        const auto v = e.params.find(p.key);
        if (v == e.params.end()) continue;
        if (p.kind == ParamKind::BodyRef && !v->second.text.empty()) return v->second.text;
        if (p.kind == ParamKind::BodyPair && !v->second.names.empty()) return v->second.names.front();
        if (p.kind == ParamKind::BodyList && !v->second.names.empty()) {
            std::vector<std::string> distinct;
            for (const auto& n : v->second.names)
                if (std::find(distinct.begin(), distinct.end(), n) == distinct.end()) distinct.push_back(n);
            std::string out;
            for (const auto& n : distinct) out += (out.empty() ? "" : ", ") + n;
            return out;
        }
    }
    return "";
}

std::unique_ptr<Scene> buildScene(const ModelSpec& spec) {
    auto scene = std::make_unique<Scene>();
    for (const auto& b : spec.bodies) {
        // MobilizedBody handles have reference semantics: a copy is the body.
        SimTK::MobilizedBody parent = b.joint.parent == "ground"
                                          ? SimTK::MobilizedBody(scene->matter().updGround())
                                          : scene->findBody(b.joint.parent)->mobod;
        // A shaft with polar moment J about z: Inertia(J/2, J/2, J) keeps the
        // triangle inequality (a thin disc); Inertia(0, 0, J) would throw.
        // Simbody refuses a massless body with inertia. A body whose mass
        // centre is on its pin axis turns the same whatever its mass, so an
        // omitted mass becomes a stated placeholder.
        const double mass = b.mass > 0 ? b.mass : kPlaceholderMass;
        const SimTK::Vec3 com(b.massCentre[0], b.massCentre[1], b.massCentre[2]);
        // `inertia` is about the joint axis; the central polar moment follows
        // from the parallel-axis theorem (the reader checked it is > 0).
        const double offAxis2 = com[0] * com[0] + com[1] * com[1];
        const double central = b.inertia - mass * offAxis2;
        const SimTK::Inertia inertia =
            SimTK::Inertia(central / 2, central / 2, central) + SimTK::Inertia(com, mass);
        const SimTK::Body::Rigid body(SimTK::MassProperties(mass, com, inertia));
        const SimTK::Vec3 location(b.joint.location[0], b.joint.location[1], b.joint.location[2]);
        SimTK::MobilizedBody::Pin pin(parent,
                                      SimTK::Transform(location), body, SimTK::Transform());
        scene->addBody(b.name, pin);
        scene->note("body " + b.name + " (pin on " + b.joint.parent + ")",
                    b.mass > 0 ? "declared in the model file"
                               : "declared in the model file; no mass given, 1 kg placeholder on the axis "
                                 "(no effect on rotation)");
    }
    const SimTK::Vec3 g(spec.gravity[0], spec.gravity[1], spec.gravity[2]);
    if (g.norm() > 0) {
        SimTK::Force::UniformGravity(scene->forces(), scene->matter(), g);
        scene->note("gravity " + std::to_string(g.norm()) + " m/s^2", "gravity: in the model file");
    }
    const ElementRegistry& registry = ElementRegistry::instance();
    const std::vector<std::string>& columns = spec.outputs.columns;
    // A column names an element (all its outputs) or one output "ELEMENT.x".
    auto named = [&](const std::string& output) {
        return std::any_of(columns.begin(), columns.end(), [&](const std::string& c) { return isOrUnder(output, c); });
    };
    std::vector<std::string> flowTypes;  // the type of the element that declared each energy flow
    for (const auto& e : spec.elements) {
        const ElementType* type = registry.find(e.type);
        if (!type) throw SpecError(e.where, e.name + ".type", "unknown element type '" + e.type + "'");
        const bool elementNamed =
            std::any_of(columns.begin(), columns.end(), [&](const std::string& c) { return isOrUnder(c, e.name); });
        if (type->schema.outputOnly && !columns.empty() && !elementNamed) {
            scene->omit("output " + e.name + " (" + e.type + ")", "outputs.columns names none of its outputs");
            continue;
        }
        try {
            // Everything the element registers is recorded under it
            // (Scene::beginElement), with its regularisation speed.
            scene->beginElement(e.name, e.type);
            type->build(e, *scene);
            if (const std::string& key = type->schema.regularisationSpeedKey; !key.empty())
                scene->addRegularisationSpeed({e.name, key, e.number(key)});
            scene->endElement(elementBodies(e));
        } catch (const std::invalid_argument& err) {
            throw SpecError(e.where, e.name, err.what());
        } catch (const SimTK::Exception::Base& err) {
            throw SpecError(e.where, e.name, "Simbody refused it: " + simbodyMessage(err.what()));
        }
        flowTypes.resize(scene->energyFlows().size(), e.type);
    }
    // Every peak and statistic must name one output or a body's speed
    // column: a typo would otherwise drop it silently.
    const std::vector<std::string>& peaks = spec.outputs.peaks;
    const std::vector<std::string>& statistics = spec.outputs.statistics;
    {
        std::vector<std::string> names;
        for (const auto& b : scene->bodies()) names.push_back(speedColumnName(*scene, b));
        for (const auto& p : scene->probes()) names.push_back(p.name);
        auto check = [&](const std::vector<std::string>& list, const std::vector<SourceLocation>& at,
                         const std::string& key) {
            for (std::size_t i = 0; i < list.size(); ++i)
                if (std::find(names.begin(), names.end(), list[i]) == names.end())
                    throw SpecError(at[i], key,
                                    "no output or body speed named '" + list[i] + "'" + suggestion(list[i], names));
        };
        check(peaks, spec.outputs.peakWhere, "outputs.peaks");
        check(statistics, spec.outputs.statisticsWhere, "outputs.statistics");
    }
    if (!columns.empty()) {
        // Every column must name something: a typo would otherwise drop an
        // output silently.
        for (std::size_t i = 0; i < columns.size(); ++i) {
            bool found = spec.findElement(columns[i]) != nullptr;
            for (const auto& p : scene->probes()) found = found || p.name == columns[i];
            if (!found) {
                std::vector<std::string> names;
                for (const auto& e : spec.elements) names.push_back(e.name);
                for (const auto& p : scene->probes()) names.push_back(p.name);
                throw SpecError(spec.outputs.columnWhere[i], "outputs.columns",
                                "no element or output named '" + columns[i] + "'" + suggestion(columns[i], names));
            }
        }
        // The analyses' summaries read the outputs with a role (drive, load,
        // coupling torques, speeds): those stay whatever the columns say.
        const std::size_t dropped =
            scene->retainProbes([&](const Probe& p) { return p.role != ProbeRole::Generic || named(p.name) ||
                                           std::find(peaks.begin(), peaks.end(), p.name) != peaks.end() ||
                                           std::find(statistics.begin(), statistics.end(), p.name) != statistics.end();
                                });
        if (dropped > 0)
            scene->omit(std::to_string(dropped) + " outputs of built elements", "not named in outputs.columns");
    }
    // Only analyses that report an energy balance need the meter: its
    // integrals are continuous states every integration step carries.
    const std::string& analysis = spec.scenario.type;
    if (!spec.outputs.energyBalance) {
        scene->omit("energy meter", "outputs.energy_balance is false");
    } else if (const AnalysisKind* kind = findAnalysisKind(analysis); kind && kind->reportsEnergyBalance) {
        // Last, so that it sees every element's energy flow.
        auto* meter = new EnergyMeter(scene->forces(), scene->energyFlows(), flowTypes);
        SimTK::Force::Custom meterForce(scene->forces(), meter);
        scene->setEnergyMeter(meter);
        scene->note("energy meter (" + std::to_string(scene->energyFlows().size()) + " flows)",
                    "the " + analysis + " analysis reports an energy balance");
    } else {
        scene->omit("energy meter", "the " + analysis + " analysis reports no energy balance");
    }
    scene->system().realizeTopology();
    addReducedInertias(*scene);
    return scene;
}

SimTK::State initialState(const Scene& scene, const ModelSpec& spec) {
    SimTK::State state = scene.system().getDefaultState();
    for (const auto& b : spec.bodies) {
        const SceneBody* body = scene.findBody(b.name);
        body->mobod.setOneQ(state, SimTK::MobilizerQIndex(0), b.initialAngle);
        body->mobod.setOneU(state, SimTK::MobilizerUIndex(0), b.initialSpeed);
    }
    for (const auto& init : scene.initializers()) init(state);
    scene.system().realize(state, SimTK::Stage::Position);
    return state;
}

}  // namespace milldyn
