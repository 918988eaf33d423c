#include "plugins/loads/DiscDrag.h"

#include "plugins/loads/LoadTorqueOutputs.h"
#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

DiscDrag::DiscDrag(const SimTK::MobilizedBody& body, const DiscDragParams& p) : m_body(body), m_params(p) {
    auto bad = [](const std::string& name, double v, const std::string& rule) {
        throw std::invalid_argument("DiscDrag: " + name + " = " + std::to_string(v) + " is invalid: " + rule);
    };
    if (!(p.density > 0) || !std::isfinite(p.density)) bad("density", p.density, "must be finite and > 0");
    if (!(p.viscosity > 0) || !std::isfinite(p.viscosity)) bad("viscosity", p.viscosity, "must be finite and > 0");
    if (!(p.radius > 0) || !std::isfinite(p.radius)) bad("radius", p.radius, "must be finite and > 0");
    if (p.discs < 1) bad("discs", p.discs, "must be >= 1");
}

double DiscDrag::calcSpeed(const SimTK::State& s) const {
    const SimTK::Vec3 axis = m_body.getBodyRotation(s).z();
    return ~m_body.getBodyAngularVelocity(s) * axis;
}

double DiscDrag::calcReynolds(const SimTK::State& s) const {
    return std::abs(calcSpeed(s)) * m_params.radius * m_params.radius / m_params.viscosity;
}

double DiscDrag::calcTorqueAtSpeed(double omega) const {
    const double w = std::abs(omega), r = m_params.radius, rho = m_params.density, nu = m_params.viscosity;
    if (w == 0) return 0;
    if (m_params.law == DiscDragParams::Law::Laminar)
        return 0.616 * M_PI * rho * std::pow(r, 4) * m_params.discs * std::sqrt(nu * w * w * w);
    const double re = w * r * r / nu;
    return 0.073 * rho * w * w * std::pow(r, 5) * std::pow(re, -0.2) * m_params.discs;
}

double DiscDrag::calcTorque(const SimTK::State& s) const {
    return m_params.schedule.factorAt(s) * calcTorqueAtSpeed(calcSpeed(s));
}

double DiscDrag::calcPower(const SimTK::State& s) const { return calcTorque(s) * std::abs(calcSpeed(s)); }

void DiscDrag::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                         SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
    const double w = calcSpeed(s);
    if (w == 0) return;
    const SimTK::Vec3 axis = m_body.getBodyRotation(s).z();
    const double sign = w > 0 ? 1.0 : -1.0;
    m_body.applyBodyTorque(s, -sign * m_params.schedule.factorAt(s) * calcTorqueAtSpeed(w) * axis,
                           bodyForces);
}

const DiscDrag* addDiscDrag(Scene& scene, const std::string& name, const SimTK::MobilizedBody& body,
                            const DiscDragParams& p) {
    auto* impl = new DiscDrag(body, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(name, "DiscDrag", force.getForceIndex(), impl);
    // calcTorque is the drag's magnitude; the output is signed like every
    // load's (+ about +z: what the discs take from their shaft, so negative
    // on a shaft turning −z), its power T·|ω| >= 0 either way.
    addLoadTorqueOutputs(
        scene, name,
        [impl](const SimTK::State& s) { return (impl->calcSpeed(s) < 0 ? -1.0 : 1.0) * impl->calcTorque(s); },
        [impl](const SimTK::State& s) { return impl->calcPower(s); });
    scene.addProbe({name + ".reynolds", "1", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcReynolds(s); }});
    return impl;
}

namespace {

DiscDragParams dragParams(const ElementSpec& spec) {
    DiscDragParams p;
    p.law = spec.text("law") == "turbulent" ? DiscDragParams::Law::Turbulent : DiscDragParams::Law::Laminar;
    p.density = spec.number("medium_density");
    p.viscosity = spec.number("medium_viscosity");
    p.radius = spec.number("disc_diameter") / 2;
    p.discs = static_cast<int>(spec.number("discs"));
    p.schedule = Schedule::fromSpec(spec);
    return p;
}

void buildDiscDrag(const ElementSpec& spec, Scene& scene) {
    const SceneBody* body = scene.findBody(spec.text("body"));
    const DiscDragParams p = dragParams(spec);
    addDiscDrag(scene, spec.name, body->mobod, p);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    scene.note("force " + spec.name + " (DiscDrag, " + spec.text("law") + ")",
               std::to_string(p.discs) + " disc(s) loading body " + body->name +
                   (p.schedule.isConstant() ? "" : "; torque times the schedule: " + p.schedule.describe()));
}

}  // namespace

void registerDiscDrag(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "DiscDrag";
    s.doc = "Drag torque of k discs turning in the grinding medium: von Kármán laminar disc, both faces "
            "(seed 001 eq 1), or the turbulent law; Reynolds number reported.";
    s.params = {
        P::body("body", "shaft the discs turn with (about its z axis)"),
        P::choice("law", {"laminar", "turbulent"}, "laminar: eq (1); turbulent: 0.073·ρω²r⁵·Re^(-1/5)")
            .optional("laminar"),
        P::quantity("medium_density", "kg/m^3", "density of the medium ρ_c").above(0),
        P::quantity("medium_viscosity", "m^2/s", "kinematic viscosity of the medium ν").above(0),
        P::quantity("disc_diameter", "m", "disc diameter D_d = 2 r_d").above(0),
        P::quantity("discs", "1", "number of discs k on this body").optional(1.0).atLeast(1).atMost(1000),
        scheduleParam("schedule", "f(t) multiplying the torque: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.number("discs") != std::floor(e.number("discs"))) throw e.error("discs", "must be a whole number");
    };
    registry.add({std::move(s), buildDiscDrag});
}

}  // namespace milldyn
