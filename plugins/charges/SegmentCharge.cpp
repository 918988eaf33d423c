#include "plugins/charges/SegmentCharge.h"

#include "plugins/charges/CircularSegment.h"

#include <cstdio>

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

namespace {
const MobilizerQIndex kQ(0);
const MobilizerUIndex kU(0);

/// Direction angle [rad] of a body's +x axis in ground.
double absoluteAngle(const State& s, const MobilizedBody& b) {
    const Vec3 x = b.getBodyRotation(s).x();
    return std::atan2(x[1], x[0]);
}
}  // namespace

SegmentCharge::SegmentCharge(const SimbodyMatterSubsystem& matter, const MobilizedBody& carrier,
                             const MobilizedBody& drum, const SegmentChargeParams& p)
    : m_matter(matter), m_carrier(carrier), m_drum(drum), m_p(p) {
    auto bad = [](const std::string& what) { throw std::invalid_argument("SegmentCharge: " + what); };
    if (!(p.drumRadius > 0) || !std::isfinite(p.drumRadius)) bad("drum_radius must be finite and > 0 m");
    if (!(p.length > 0) || !std::isfinite(p.length)) bad("length must be finite and > 0 m");
    if (!(p.bulkDensity > 0) || !std::isfinite(p.bulkDensity)) bad("bulk_density must be finite and > 0 kg/m^3");
    if (!(p.halfAngle > 0 && p.halfAngle <= M_PI)) bad("the segment half-angle must be in (0, 180] deg");
    if (!(p.wallDrag >= 0) || !std::isfinite(p.wallDrag)) bad("wall_drag must be finite and >= 0 N*m*s/rad");
}

// The segment's geometry: plugins/charges/CircularSegment (series near γ = 0).
double SegmentCharge::calcFillFraction(double g) { return circular_segment::calcFillFraction(g); }

double SegmentCharge::calcHalfAngleForFill(double fill) {
    if (!(fill > 0 && fill <= 1)) throw std::invalid_argument("SegmentCharge: fill must be in (0, 1]");
    return circular_segment::calcHalfAngleForFill(fill);
}

double SegmentCharge::calcMass() const {
    const double r = m_p.drumRadius;
    return m_p.bulkDensity * m_p.length * r * r * circular_segment::calcAreaFactor(m_p.halfAngle) / 2;
}

double SegmentCharge::calcCentroidDistance() const {
    return m_p.drumRadius * circular_segment::calcCentroidFactor(m_p.halfAngle);
}

double SegmentCharge::calcAxisInertia() const {
    const double r = m_p.drumRadius;
    return calcMass() * r * r * circular_segment::calcAxisInertiaFactor(m_p.halfAngle);
}

void SegmentCharge::realizeTopology(State& s) const {
    m_heldTorque = m_matter.allocateDiscreteVariable(s, Stage::Dynamics, new Value<Real>(0.0));
}

double SegmentCharge::getHeldTorque(const State& s) const {
    return Value<Real>::downcast(m_matter.getDiscreteVariable(s, m_heldTorque));
}

void SegmentCharge::setHeldTorque(State& s, double torque) const {
    Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_heldTorque)) = torque;
}

double SegmentCharge::calcDirection(const State& s) const {
    // Turning with the drum, the charge is part of the drum's body (folded
    // in by the builder): its centroid is at initial_direction in the drum
    // frame.
    if (m_p.motion == ChargeMotionMode::WithDrum) return absoluteAngle(s, m_drum) + m_p.initialDirection;
    // The body's mass centre lies on its −y axis.
    const Vec3 down = -m_charge.getBodyRotation(s).y();
    return std::atan2(down[1], down[0]);
}

double SegmentCharge::calcDirectionOfLag(const State& s, double lag) const {
    Vec3 out = m_drum.getBodyOriginLocation(s) - m_carrier.getBodyOriginLocation(s);
    const double outAngle = std::atan2(out[1], out[0]);
    // u = sin α e_out + cos α e_t: at angle outAngle + atan2(cos α, sin α).
    return outAngle + std::atan2(std::cos(lag), std::sin(lag));
}

double SegmentCharge::calcLag(const State& s) const {
    Vec3 out = m_drum.getBodyOriginLocation(s) - m_carrier.getBodyOriginLocation(s);
    out[2] = 0;
    out = out / out.norm();
    const Vec3 t(-out[1], out[0], 0);
    const double d = calcDirection(s);
    const Vec3 u(std::cos(d), std::sin(d), 0);
    return std::atan2(dot(u, out), dot(u, t));
}

double SegmentCharge::calcRelativeAngleFor(const State& s, double direction) const {
    // Body angle = direction + 90° (mass centre on −y), less the drum's angle.
    return direction + M_PI / 2 - absoluteAngle(s, m_drum);
}

double SegmentCharge::calcSlipSpeed(const State& s) const {
    if (m_p.motion == ChargeMotionMode::WithDrum) return 0;
    return -m_charge.getOneU(s, kU);  // the charge's pin is on the drum
}

double SegmentCharge::calcWallTorque(const State& s) const {
    switch (m_p.motion) {
        case ChargeMotionMode::WithDrum: return 0;
        case ChargeMotionMode::Held: return getHeldTorque(s);
        case ChargeMotionMode::DynamicLag: return m_p.wallDrag * calcSlipSpeed(s);
    }
    return 0;
}

void SegmentCharge::calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const {
    if (m_p.motion == ChargeMotionMode::WithDrum) return;
    // A mobility force on the charge's pin: drum on charge, and the opposite
    // on the drum.
    m_charge.applyOneMobilityForce(s, kU, calcWallTorque(s), mobilityForces);
}

namespace {

void buildSegmentCharge(const ElementSpec& spec, Scene& scene) {
    // Copies, not a pointer into the scene's body list: adding the charge's
    // body below may move that list.
    const SceneBody drum = *scene.findBody(spec.text("drum"));
    const MobilizedBody carrier = drum.mobod.getParentMobilizedBody();
    SegmentChargeParams p;
    p.drumRadius = spec.number("drum_radius");
    p.length = spec.number("length");
    p.bulkDensity = spec.number("bulk_density");
    p.halfAngle = spec.has("half_angle") && spec.params.at("half_angle").given
                      ? spec.number("half_angle")
                      : SegmentCharge::calcHalfAngleForFill(spec.number("fill"));
    const std::string& motion = spec.text("motion");
    p.motion = motion == "with_drum" ? ChargeMotionMode::WithDrum
               : motion == "held"    ? ChargeMotionMode::Held
                                     : ChargeMotionMode::DynamicLag;
    p.lag = spec.number("lag");
    p.initialDirection = spec.number("initial_direction");
    p.wallDrag = spec.number("wall_drag");
    auto* impl = new SegmentCharge(scene.matter(), carrier, drum.mobod, p);

    const double m = impl->calcMass(), lc = impl->calcCentroidDistance();
    // k_c m r², not J_axis − m l_c² (two nearly equal numbers for a thin charge)
    const double centralPolar = m * p.drumRadius * p.drumRadius * circular_segment::calcCentralInertiaFactor(p.halfAngle);
    // About the mass centre: polar about z (a disc), so the same in any
    // frame turned about z.
    const Inertia central(centralPolar / 2, centralPolar / 2, centralPolar);
    MobilizedBody drumBody = drum.mobod;  // handles: a copy is the body
    MobilizedBody chargeBody;
    if (p.motion == ChargeMotionMode::WithDrum) {
        // Turns with the drum, its centroid at initial_direction in the drum
        // frame: its mass properties are added to the drum's instead of a
        // welded body of its own. The motion and every reaction at the
        // drum's joint are the same; a welded body would cost a body in
        // every realization and carry nothing an output reads (the charge's
        // lag follows from the drum's angle).
        const Vec3 comInDrum(lc * std::cos(p.initialDirection), lc * std::sin(p.initialDirection), 0);
        const MassProperties d = drumBody.getDefaultMassProperties();
        const double total = d.getMass() + m;
        const Inertia aboutOrigin = d.getInertia() + central + Inertia(comInDrum, m);
        drumBody.setDefaultMassProperties(
            MassProperties(total, (d.getMass() * d.getMassCenter() + m * comInDrum) / total, aboutOrigin));
    } else {
        // The body's mass centre lies on its −y axis.
        const Vec3 com(0, -lc, 0);
        const Body::Rigid body(MassProperties(m, com, central + Inertia(com, m)));
        chargeBody = MobilizedBody::Pin(drumBody, Transform(), body, Transform());
        impl->setBody(chargeBody);
        // Scene bodies are pins (analyses read one angle and speed from each).
        scene.addBody(spec.name, chargeBody);
    }
    // Schematic: the drum wall and the charge's segment where it is now.
    const MobilizedBody drumMobod = drum.mobod;
    const std::string drumName = drum.name;
    scene.addSketch([impl, drumMobod, drumName](const State& s, Sketch& k) {
        const Vec3 b = drumMobod.getBodyOriginLocation(s);
        const double r = impl->params().drumRadius;
        k.circle("drum", b[0], b[1], r, drumName);
        char lag[48];
        std::snprintf(lag, sizeof lag, "lag %.0f deg", impl->calcLag(s) * 180 / M_PI);
        k.segment("charge", b[0], b[1], r, impl->calcDirection(s), impl->params().halfAngle, lag);
    });
    Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);

    if (p.motion != ChargeMotionMode::WithDrum) {
        const MobilizedBody cb = chargeBody, d = drum.mobod;
        const bool held = p.motion == ChargeMotionMode::Held;
        const System* system = &scene.system();
        scene.addInitializer([impl, cb, d, held, system](State& s) {
            const SegmentChargeParams& q = impl->params();
            system->realize(s, Stage::Position);
            const double direction = held ? impl->calcDirectionOfLag(s, q.lag) : q.initialDirection;
            cb.setOneQ(s, kQ, impl->calcRelativeAngleFor(s, direction));
            // Held: still in the carrier frame; dynamic: starts with the drum.
            cb.setOneU(s, kU, held ? -d.getOneU(s, kU) : 0.0);
        });
    }
    if (p.motion == ChargeMotionMode::Held) {
        const MobilizedBody cb = chargeBody, d = drum.mobod;
        scene.addKinetostaticUnknown(
            {spec.name + ".wall_torque", [impl](State& s, double T) { impl->setHeldTorque(s, T); },
             [impl](const State& s) { return impl->getHeldTorque(s); },
             // the charge's angular acceleration in the carrier frame
             [cb, d](const State& s) { return d.getOneUDot(s, kU) + cb.getOneUDot(s, kU); }});
    }
    scene.addProbe({spec.name + ".lag", "rad", ProbeRole::Generic, Stage::Position,
                    [impl](const State& s) { return impl->calcLag(s); }});
    scene.addProbe({spec.name + ".wall_torque", "N*m", ProbeRole::Generic, Stage::Velocity,
                    [impl](const State& s) { return impl->calcWallTorque(s); }});
    if (p.motion != ChargeMotionMode::WithDrum) {
        scene.addProbe({spec.name + ".grinding_power", "W", ProbeRole::ResistancePower, Stage::Velocity,
                        [impl](const State& s) { return impl->calcWallTorque(s) * impl->calcSlipSpeed(s); }});
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Load, [impl](const State& s) {
                                 return impl->calcWallTorque(s) * impl->calcSlipSpeed(s);
                             }});
    }
    scene.note(p.motion == ChargeMotionMode::WithDrum
                   ? "charge " + spec.name + " (SegmentCharge, with_drum) folded into " + drum.name
                   : "body " + spec.name + " (SegmentCharge, " + motion + ")",
               "charge of " + drum.name + ": " + std::to_string(m) + " kg, centroid " + std::to_string(lc) +
                   " m from the axis, half-angle " + std::to_string(p.halfAngle * 180 / M_PI) + " deg" +
                   (p.motion == ChargeMotionMode::WithDrum
                        ? "; turns with its drum, so its mass is the drum's (no body of its own)"
                        : ""));
}

}  // namespace

void registerSegmentCharge(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "SegmentCharge";
    s.doc = "Grinding charge as a circular-segment body in a drum (rigid with it, held at a lag, or dragged).";
    s.params = {
        P::body("drum", "drum (on a pin on its carrier) holding the charge"),
        P::quantity("drum_radius", "m", "r: inner radius of the drum").above(0),
        P::quantity("length", "m", "l: inner length of the drum").above(0),
        P::quantity("bulk_density", "kg/m^3", "ρ: bulk density of balls, material and voids").above(0),
        P::quantity("fill", "1", "fill fraction of the cross-section (50 % = half disc)").optional(0.5).above(0).atMost(1),
        P::quantity("half_angle", "rad", "γ: segment half-angle (overrides fill)").optional(M_PI / 2).above(0).atMost(M_PI),
        P::choice("motion", {"with_drum", "held", "dynamic_lag"}, "how the charge moves").optional(
            std::string("with_drum")),
        P::quantity("lag", "rad", "α held in the carrier frame (motion: held)").optional(0.0).atLeast(-M_PI).atMost(M_PI),
        P::quantity("initial_direction", "rad", "direction of B→c from +x at t = 0").optional(-M_PI / 2),
        P::quantity("wall_drag", "N*m*s/rad", "c_w of the wall drag (motion: dynamic_lag)").optional(0.0).atLeast(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.text("motion") == "dynamic_lag" && !(e.number("wall_drag") > 0))
            throw e.error("wall_drag", "motion: dynamic_lag needs a wall_drag > 0 N*m*s/rad");
    };
    registry.add({std::move(s), buildSegmentCharge});
}

}  // namespace milldyn
