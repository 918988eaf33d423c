#include "PlanetaryLayout.h"

#include <Simbody.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace planetary_layout {

using milldyn::ElementSpec;
using milldyn::ElementType;
using milldyn::ParamSchema;
using milldyn::ParamValue;
using milldyn::Scene;

namespace {

/// A value the layout hands to one of its sub-elements, and the layout's key
/// it came from (so that an error the sub-element finds points there).
struct Given {
    double number = 0;
    std::string text;
    std::string from;
};
Given num(double v, const std::string& from) { return {v, "", from}; }
Given word(const std::string& t, const std::string& from) { return {0, t, from}; }

/// Builds one built-in element through the registry, as the scene builder
/// would for a model-file entry: the keys the layout gives, every other key
/// at the type's registered default, the type's cross-check, its builder.
void buildSubElement(const ElementSpec& layout, Scene& scene, const std::string& typeName, const std::string& name,
                     const std::map<std::string, Given>& values) {
    const ElementType* type = milldyn::ElementRegistry::instance().find(typeName);
    if (!type) throw std::logic_error("PlanetaryLayout: milldyn has no element type " + typeName);
    ElementSpec spec;
    spec.type = typeName;
    spec.name = name;
    spec.where = layout.where;
    spec.fidelity = layout.fidelity;
    for (const auto& kv : values)
        if (!type->schema.find(kv.first))
            throw std::logic_error("PlanetaryLayout: " + typeName + " has no key " + kv.first);
    for (const ParamSchema& p : type->schema.params) {
        ParamValue v;
        auto it = values.find(p.key);
        if (it != values.end()) {
            v.number = it->second.number;
            v.text = it->second.text;
            v.where = layout.whereOf(it->second.from);
            v.given = true;
        } else if (p.required) {
            throw std::logic_error("PlanetaryLayout: gives no value for " + typeName + "." + p.key);
        } else {
            v.number = p.defaultValue.value_or(0.0);
            v.text = p.defaultText;
            v.where = layout.where;
        }
        spec.params[p.key] = v;
    }
    if (type->schema.crossCheck) type->schema.crossCheck(spec);
    type->build(spec, scene);
}

void buildPlanetaryLayout(const ElementSpec& spec, Scene& scene) {
    const milldyn::SceneBody* carrierBody = scene.findBody(spec.text("carrier"));
    const SimTK::MobilizedBody carrier = carrierBody->mobod;  // a handle: stays valid as bodies are added
    const std::string carrierName = carrierBody->name;
    if (carrier.getParentMobilizedBody().getMobilizedBodyIndex() != SimTK::GroundIndex)
        throw spec.error("carrier", "'" + carrierName + "' must be on a pin on ground (the fixed gear's axis)");

    const bool internal = spec.text("rolling") == "internal";
    const double R = spec.number("fixed_pitch_radius"), r = spec.number("planet_pitch_radius");
    const double arm = internal ? R - r : R + r;  // [m] carrier axis A to drum axis B
    const int n = static_cast<int>(spec.number("drums"));
    const double theta0 = spec.number("first_drum_angle");
    const double drumMass = spec.number("drum_mass"), drumInertia = spec.number("drum_inertia");
    const std::string& prefix = spec.text("prefix");

    for (int k = 1; k <= n; ++k) {
        const std::string K = std::to_string(k);
        const std::string drum = prefix + "drum" + K;
        if (scene.findBody(drum)) throw spec.error("prefix", "a body named '" + drum + "' exists already");

        // The drum shell: centre of mass on its axis, polar moment J about
        // it (a thin disc's Inertia(J/2, J/2, J), as the scene builder does
        // for model-file bodies).
        const double theta = theta0 + 2 * M_PI * (k - 1) / n;
        const SimTK::Vec3 location(arm * std::cos(theta), arm * std::sin(theta), 0);
        const SimTK::Body::Rigid body(SimTK::MassProperties(
            drumMass, SimTK::Vec3(0), SimTK::Inertia(drumInertia / 2, drumInertia / 2, drumInertia)));
        SimTK::MobilizedBody parent = carrier;
        SimTK::MobilizedBody::Pin pin(parent, SimTK::Transform(location), body, SimTK::Transform());
        scene.addBody(drum, pin);
        scene.note("body " + drum + " (PlanetaryLayout " + spec.name + ", pin on " + carrierName + ")",
                   "drum " + K + " of " + std::to_string(n) + " at " + std::to_string(arm) + " m, " +
                       std::to_string(std::fmod(theta * 180 / M_PI + 360, 360.0)) + " deg on the carrier");

        buildSubElement(spec, scene, "GearMesh", prefix + "mesh" + K,
                        {{"carrier", word(carrierName, "carrier")},
                         {"planet", word(drum, "drums")},
                         {"fixed_pitch_radius", num(R, "fixed_pitch_radius")},
                         {"planet_pitch_radius", num(r, "planet_pitch_radius")},
                         {"rolling", word(spec.text("rolling"), "rolling")},
                         {"pressure_angle", num(spec.number("pressure_angle"), "pressure_angle")}});
        // SegmentCharge refuses the keys its motion does not use.
        std::map<std::string, Given> charge = {
            {"drum", word(drum, "drums")},
            {"drum_radius", num(spec.number("drum_radius"), "drum_radius")},
            {"length", num(spec.number("drum_length"), "drum_length")},
            {"bulk_density", num(spec.number("bulk_density"), "bulk_density")},
            {"fill", num(spec.number("fill"), "fill")},
            {"motion", word(spec.text("charge_motion"), "charge_motion")}};
        if (spec.text("charge_motion") == "held") charge["lag"] = num(spec.number("lag"), "lag");
        if (spec.text("charge_motion") == "dynamic_lag") charge["wall_drag"] = num(spec.number("wall_drag"), "wall_drag");
        buildSubElement(spec, scene, "SegmentCharge", prefix + "charge" + K, charge);
        buildSubElement(spec, scene, "JournalFriction", prefix + "friction_B" + K,
                        {{"body", word(drum, "drums")},
                         {"friction_coefficient", num(spec.number("friction_coefficient"), "friction_coefficient")},
                         {"journal_diameter", num(spec.number("journal_diameter"), "journal_diameter")},
                         {"reaction", word(spec.text("reaction"), "reaction")}});
        buildSubElement(spec, scene, "JointReaction", prefix + "reaction_B" + K, {{"body", word(drum, "drums")}});
    }
}

}  // namespace

void registerPlanetaryLayout(milldyn::ElementRegistry& registry) {
    using P = ParamSchema;
    milldyn::ElementSchema s;
    s.type = "PlanetaryLayout";
    s.doc = "A planetary mill's drums on a carrier, rolling inside a fixed ring or on a fixed sun "
            "(example plugin): drums, gears, charges, journals from a few numbers.";
    s.params = {
        P::body("carrier", "carrier on a pin on ground; its axis is the fixed gear's axis"),
        P::quantity("drums", "1", "n: number of drums, evenly spaced").atLeast(1).atMost(12),
        P::choice("rolling", {"internal", "external"}, "drums inside a fixed ring or outside a fixed sun"),
        P::quantity("fixed_pitch_radius", "m", "R: pitch radius of the fixed ring (internal) or sun (external)")
            .above(0),
        P::quantity("planet_pitch_radius", "m", "r: pitch radius of each drum's gear").above(0),
        P::quantity("pressure_angle", "rad", "line-of-action angle").optional(20.0 * M_PI / 180).atLeast(0).below(
            M_PI / 2),
        P::quantity("first_drum_angle", "rad", "θ0: position of drum 1 on the carrier, from its +x axis")
            .optional(0.0),
        P::quantity("drum_mass", "kg", "m_b: mass of one drum shell (centre on its axis)").above(0),
        P::quantity("drum_inertia", "kg*m^2", "J_b: polar moment of one drum shell about its axis").above(0),
        P::quantity("drum_radius", "m", "inner radius of a drum (the charge's)").above(0),
        P::quantity("drum_length", "m", "inner length of a drum").above(0),
        P::quantity("bulk_density", "kg/m^3", "ρ of the charge (balls, material, voids)").above(0),
        P::quantity("fill", "1", "fill fraction of a drum's cross-section").optional(0.5).above(0).atMost(1),
        P::choice("charge_motion", {"with_drum", "held", "dynamic_lag"}, "SegmentCharge motion")
            .optional(std::string("with_drum")),
        P::quantity("lag", "rad", "α of a held charge").optional(0.0).atLeast(-M_PI).atMost(M_PI),
        P::quantity("wall_drag", "N*m*s/rad", "c_w of a dynamic_lag charge").optional(0.0).atLeast(0),
        P::quantity("friction_coefficient", "1", "f of the drums' journals").optional(0.0).atLeast(0).atMost(1),
        P::quantity("journal_diameter", "m", "d of the drums' journals").optional(0.0).atLeast(0),
        P::choice("reaction", {"lagged", "iterated"}, "JournalFriction reaction coupling")
            .optional(std::string("lagged")),
        P::text("prefix", "put in front of every body and element name the layout makes").optional(std::string("")),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const double n = e.number("drums");
        if (n != std::floor(n)) throw e.error("drums", "must be a whole number");
        if (e.text("rolling") == "internal" && !(e.number("planet_pitch_radius") < e.number("fixed_pitch_radius")))
            throw e.error("planet_pitch_radius", "drums rolling inside a ring need r < R");
        if (e.text("charge_motion") == "dynamic_lag" && !(e.number("wall_drag") > 0))
            throw e.error("wall_drag", "charge_motion: dynamic_lag needs a wall_drag > 0 N*m*s/rad");
        // Internal rolling: the drums must clear each other on the arm.
        const double R = e.number("fixed_pitch_radius"), r = e.number("planet_pitch_radius");
        const double arm = e.text("rolling") == "internal" ? R - r : R + r;
        if (n > 1 && !(2 * arm * std::sin(M_PI / n) > 2 * r))
            throw e.error("drums", std::to_string(static_cast<int>(n)) + " drums of pitch radius " +
                                       std::to_string(r) + " m overlap on an arm of " + std::to_string(arm) + " m");
    };
    registry.add({std::move(s), buildPlanetaryLayout});
}

}  // namespace planetary_layout
