#include "plugins/transmissions/ShaftBelt.h"

#include "plugins/scene/ElementRegistry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

namespace {
const MobilizerQIndex kQ(0);
const MobilizerUIndex kU(0);

/// Centre of a shaft's sheave: its pin's location in ground [m].
Vec3 pinCentre(const MobilizedBody& b) { return b.getDefaultInboardFrame().p(); }
}  // namespace

ShaftBelt::ShaftBelt(const GeneralForceSubsystem& forces, const MobilizedBody& driver, const MobilizedBody& driven,
                     const ShaftBeltParams& p)
    : m_forces(forces), m_driver(driver), m_driven(driven), m_p(p) {
    auto bad = [](const std::string& what) { throw std::invalid_argument("ShaftBelt: " + what); };
    if (!(p.driverSheaveRadius > 0) || !std::isfinite(p.driverSheaveRadius))
        bad("driver_sheave_radius must be finite and > 0 m");
    if (!(p.drivenSheaveRadius > 0) || !std::isfinite(p.drivenSheaveRadius))
        bad("driven_sheave_radius must be finite and > 0 m");
    if (!(p.pretension >= 0) || !std::isfinite(p.pretension)) bad("pretension must be finite and >= 0 N");
    if (!(p.spanStiffness > 0) || !std::isfinite(p.spanStiffness)) bad("span_stiffness must be finite and > 0 N/m");
    if (!(p.spanDamping > 0) || !std::isfinite(p.spanDamping)) bad("span_damping must be finite and > 0 N*s/m");
    if (!(p.frictionCoefficient >= 0) || !std::isfinite(p.frictionCoefficient))
        bad("friction_coefficient must be finite and >= 0");
    if (driver.getMobilizedBodyIndex() == driven.getMobilizedBodyIndex()) bad("the two shafts must differ");
    if (!driver.getParentMobilizedBody().isGround() || !driven.getParentMobilizedBody().isGround())
        bad("both shafts must be on pins on ground (their pins' locations are the sheave centres)");
    // calcBeltSpans: the driver's sheave in the role of the "fixed" sheave,
    // the driven's in that of the "drum" sheave; it throws when |r1 − r2| > l.
    const double distance = (pinCentre(driven) - pinCentre(driver)).norm();
    if (!(std::abs(p.drivenSheaveRadius - p.driverSheaveRadius) < distance))
        bad("|r2 − r1| = " + std::to_string(std::abs(p.drivenSheaveRadius - p.driverSheaveRadius)) +
            " m is not below the centre distance " + std::to_string(distance) +
            " m between the shafts' pins: no open belt");
    m_spans = calcBeltSpans(pinCentre(driver), p.driverSheaveRadius, pinCentre(driven), p.drivenSheaveRadius);
    m_wrap = std::min(m_spans.wrapFixed, m_spans.wrapDrum);
    m_grip = std::exp(p.frictionCoefficient * m_wrap);
}

void ShaftBelt::realizeTopology(State& s) const { m_slip = m_forces.allocateZ(s, Vector(1, 0.0)); }

double ShaftBelt::getSlip(const State& s) const { return m_forces.getZ(s)[m_slip]; }

void ShaftBelt::setSlip(State& s, double slip) const { m_forces.updZ(s)[m_slip] = slip; }

double ShaftBelt::calcFeed(const State& s) const {
    return m_p.driverSheaveRadius * m_driver.getOneQ(s, kQ) - m_p.drivenSheaveRadius * m_driven.getOneQ(s, kQ);
}

double ShaftBelt::calcFeedRate(const State& s) const {
    return m_p.driverSheaveRadius * m_driver.getOneU(s, kU) - m_p.drivenSheaveRadius * m_driven.getOneU(s, kU);
}

ShaftBelt::Tensions ShaftBelt::calcTensions(const State& s) const {
    Tensions t;
    t.span = calcBeltSpanForce(m_p.pretension, m_p.spanStiffness, m_p.spanDamping, m_grip, calcStretch(s),
                               calcFeedRate(s));
    t.lead = std::max(0.0, m_p.pretension + t.span.y);
    t.trail = std::max(0.0, m_p.pretension - t.span.y);
    return t;
}

double ShaftBelt::calcDrivenTorque(const State& s) const {
    const Tensions t = calcTensions(s);
    return m_p.drivenSheaveRadius * (t.lead - t.trail);
}

double ShaftBelt::calcDriverTorque(const State& s) const {
    const Tensions t = calcTensions(s);
    return m_p.driverSheaveRadius * (t.lead - t.trail);
}

double ShaftBelt::calcDissipatedPower(const State& s) const {
    return calcBeltDissipatedPower(m_p.pretension, m_p.spanStiffness, calcTensions(s).span, calcStretch(s),
                                   calcFeedRate(s));
}

void ShaftBelt::calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const {
    const Tensions t = calcTensions(s);
    // A span of tension T pulls the driven sheave at its tangent point along
    // the span toward the driver (moment +r2·T_lead, −r2·T_trail about C2)
    // and the driver's sheave the opposite way (−r1·T_lead, +r1·T_trail).
    const BeltSpans& b = m_spans;
    const Rotation& R2 = m_driven.getBodyRotation(s);
    const Vec3 c2 = m_driven.getBodyOriginLocation(s);
    m_driven.applyForceToBodyPoint(s, ~R2 * (b.leadPoint - c2), t.lead * b.leadDir, bodyForces);
    m_driven.applyForceToBodyPoint(s, ~R2 * (b.trailPoint - c2), t.trail * b.trailDir, bodyForces);
    const Rotation& R1 = m_driver.getBodyRotation(s);
    const Vec3 c1 = m_driver.getBodyOriginLocation(s);
    m_driver.applyForceToBodyPoint(s, ~R1 * (b.leadFixedPoint - c1), -t.lead * b.leadDir, bodyForces);
    m_driver.applyForceToBodyPoint(s, ~R1 * (b.trailFixedPoint - c1), -t.trail * b.trailDir, bodyForces);
}

Real ShaftBelt::calcPotentialEnergy(const State& s) const {
    return calcBeltSpanEnergy(m_p.pretension, m_p.spanStiffness, calcStretch(s));
}

void ShaftBelt::realizeAcceleration(const State& s) const {
    m_forces.updZDot(s)[m_slip] = calcTensions(s).span.slipSpeed;
}

namespace {

void buildShaftBelt(const ElementSpec& spec, Scene& scene) {
    const SceneBody* driver = scene.findBody(spec.text("driver"));
    const SceneBody* driven = scene.findBody(spec.text("driven"));
    if (!driver->mobod.getParentMobilizedBody().isGround())
        throw spec.error("driver", "'" + driver->name + "' must be on a pin on ground (its pin is the sheave's centre)");
    if (!driven->mobod.getParentMobilizedBody().isGround())
        throw spec.error("driven", "'" + driven->name + "' must be on a pin on ground (its pin is the sheave's centre)");
    ShaftBeltParams p;
    p.driverSheaveRadius = spec.number("driver_sheave_radius");
    p.drivenSheaveRadius = spec.number("driven_sheave_radius");
    p.pretension = spec.number("pretension");
    p.spanStiffness = spec.number("span_stiffness");
    p.spanDamping = spec.number("span_damping");
    p.frictionCoefficient = spec.number("friction_coefficient");
    ShaftBelt* impl = nullptr;
    try {
        impl = new ShaftBelt(scene.forces(), driver->mobod, driven->mobod, p);
    } catch (const std::invalid_argument& e) {
        throw spec.error("driven_sheave_radius", e.what());
    }
    Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    const std::string& n = spec.name;
    const Stage v = Stage::Velocity;
    scene.addProbe({n + ".torque", "N*m", ProbeRole::CouplingTorque, v,
                    [impl](const State& s) { return impl->calcDriverTorque(s); }});
    scene.addProbe({n + ".driven_torque", "N*m", ProbeRole::Generic, v,
                    [impl](const State& s) { return impl->calcDrivenTorque(s); }});
    scene.addProbe({n + ".tension_tight", "N", ProbeRole::Generic, v, [impl](const State& s) {
                        const auto t = impl->calcTensions(s);
                        return std::max(t.lead, t.trail);
                    }});
    scene.addProbe({n + ".tension_slack", "N", ProbeRole::Generic, v, [impl](const State& s) {
                        const auto t = impl->calcTensions(s);
                        return std::min(t.lead, t.trail);
                    }});
    scene.addProbe({n + ".slip_speed", "m/s", ProbeRole::Generic, v,
                    [impl](const State& s) { return impl->calcTensions(s).span.slipSpeed; }});
    scene.addProbe({n + ".slipping", "1", ProbeRole::Generic, v,
                    [impl](const State& s) { return impl->calcTensions(s).span.slipping ? 1.0 : 0.0; }});
    scene.addProbe({n + ".slip", "m", ProbeRole::Generic, Stage::Position,
                    [impl](const State& s) { return impl->getSlip(s); }});
    scene.addProbe({n + ".stretch", "m", ProbeRole::Generic, Stage::Position,
                    [impl](const State& s) { return impl->calcStretch(s); }});
    scene.addEnergyFlow({n, EnergyFlow::Kind::Dissipation, [impl](const State& s) { return impl->calcDissipatedPower(s); }});
    scene.addSteadyResidual({n + ".feed_rate", [impl](const State& s) { return impl->calcFeedRate(s); }});
    // Kinetostatics: the stretch that keeps the feed steady (x'' = 0).
    const MobilizedBody a = driver->mobod, b = driven->mobod;
    const double r1 = p.driverSheaveRadius, r2 = p.drivenSheaveRadius;
    scene.addKinetostaticUnknown({n + ".stretch", [impl](State& s, double x) { impl->setSlip(s, impl->calcFeed(s) - x); },
                                  [impl](const State& s) { return impl->calcStretch(s); },
                                  [a, b, r1, r2](const State& s) {
                                      return r1 * a.getOneUDot(s, kU) - r2 * b.getOneUDot(s, kU);
                                  }});
    scene.addSpeedRelation(driver->name, driven->name, r2 / r1);
    // The belt's length L = r1·θ1 + r2·θ2 + 2·l·cos β (the open belt's
    // common external tangents) and its passing frequency: one point of the
    // belt passes the driver's sheave 2π·r1/L times per revolution of the
    // driver, an excitation order the Campbell diagram and resonance_map list.
    const double length = impl->getBeltLength();
    scene.addDerivedValue({n + ".belt_length", length, "m",
                           "pitch length of the open belt, r1·θ1 + r2·θ2 + 2·l·cos β (l the pins' distance)"});
    scene.addOrderExcitation({n + ".belt_passing", driver->name, 2 * Pi * r1 / length});
    char text[160];
    std::snprintf(text, sizeof text, "ratio %.4g, wrap %.4g deg on the small sheave, grip e^(μθ) = %.4g", r2 / r1,
                  impl->getWrap() * 180 / Pi, impl->getGripRatio());
    scene.note("force " + n + " (ShaftBelt)", "belts " + driver->name + " to " + driven->name + ": " + text);
}

}  // namespace

void registerShaftBelt(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "ShaftBelt";
    s.doc = "Open (V-)belt between two shafts on ground pins: pretension, elastic spans, Euler-Eytelwein slip "
            "(BeltDrive's elastic law).";
    s.params = {
        P::body("driver", "driving shaft on a pin on ground; its pin location is its sheave's centre"),
        P::body("driven", "driven shaft on a pin on ground; its pin location is its sheave's centre"),
        P::quantity("driver_sheave_radius", "m", "r1: pitch radius of the driver's sheave").above(0),
        P::quantity("driven_sheave_radius", "m", "r2: pitch radius of the driven sheave").above(0),
        P::quantity("pretension", "N", "T0 in each span at rest (all belts of the set)").atLeast(0),
        P::quantity("span_stiffness", "N/m", "k_s = EA/span length of each span (all belts of the set)").above(0),
        P::quantity("span_damping", "N*s/m", "c_s of each span").above(0),
        // At most 10 (a V-belt's μ/sin(half groove angle) is about 1.7): the
        // grip e^(μθ) stays finite (μ ≈ 260 overflowed it; issue 26 item 7).
        P::quantity("friction_coefficient", "1", "μ belt on sheave (V-belt: μ/sin(half groove angle))")
            .atLeast(0)
            .atMost(10),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.text("driver") == e.text("driven")) throw e.error("driven", "the driver and the driven must differ");
    };
    registry.add({std::move(s), buildShaftBelt});
}

}  // namespace milldyn
