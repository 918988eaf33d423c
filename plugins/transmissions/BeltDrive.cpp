#include "plugins/transmissions/BeltDrive.h"

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
}  // namespace

BeltSpans calcBeltSpans(const Vec3& fixedCentre, double r0, const Vec3& drumCentre, double rA) {
    BeltSpans b;
    Vec3 d = drumCentre - fixedCentre;
    d[2] = 0;
    b.centreDistance = d.norm();
    if (!(b.centreDistance > 0)) throw std::invalid_argument("BeltDrive: the sheave centres coincide");
    const double s = (r0 - rA) / b.centreDistance;
    if (!(std::abs(s) <= 1))
        throw std::invalid_argument("BeltDrive: |r0 − r_A| = " + std::to_string(std::abs(r0 - rA)) +
                                    " m exceeds the centre distance " + std::to_string(b.centreDistance) +
                                    " m: no open belt (sin β > 1)");
    b.sinBeta = s;
    b.beta = std::asin(std::abs(s));
    b.wrapFixed = M_PI + 2 * std::asin(s);
    b.wrapDrum = M_PI - 2 * std::asin(s);
    const double cb = std::sqrt(std::max(0.0, 1 - s * s));
    b.out = d / b.centreDistance;
    const Vec3 t(-b.out[1], b.out[0], 0);  // z × e
    // A line n·p = h touches both circles on the same side iff
    // n·(p_A − p_O) = r0 − r_A: n = s e ± cb t (validation/oracles does the same
    // in its own code; docs/oracles/planetary_belt.md section 5).
    const Vec3 nLead = s * b.out + cb * t, nTrail = s * b.out - cb * t;
    b.leadPoint = drumCentre + rA * nLead;
    b.trailPoint = drumCentre + rA * nTrail;
    b.leadFixedPoint = fixedCentre + r0 * nLead;
    b.trailFixedPoint = fixedCentre + r0 * nTrail;
    b.leadDir = -cb * b.out + s * t;
    b.trailDir = -cb * b.out - s * t;
    return b;
}

BeltDrive::BeltDrive(const MobilizedBody& carrier, const MobilizedBody& drum, const BeltDriveParams& p)
    : m_carrier(carrier), m_drum(drum), m_p(p), m_nominalDistance(0) {
    auto bad = [](const std::string& what) { throw std::invalid_argument("BeltDrive: " + what); };
    if (!(p.fixedSheaveRadius > 0) || !std::isfinite(p.fixedSheaveRadius))
        bad("fixed_sheave_radius must be finite and > 0 m");
    if (!(p.drumSheaveRadius > 0) || !std::isfinite(p.drumSheaveRadius))
        bad("drum_sheave_radius must be finite and > 0 m");
    if (!(p.tightToSlack > 1) || !std::isfinite(p.tightToSlack)) bad("tight_to_slack must be finite and > 1");
    if (!(p.frictionCoefficient >= 0) || !std::isfinite(p.frictionCoefficient))
        bad("friction_coefficient must be finite and >= 0");
    if (p.law == BeltLaw::Elastic) {
        if (!(p.pretension >= 0) || !std::isfinite(p.pretension)) bad("pretension must be finite and >= 0 N");
        if (!(p.spanStiffness > 0) || !std::isfinite(p.spanStiffness)) bad("span_stiffness must be finite and > 0 N/m");
        if (!(p.spanDamping > 0) || !std::isfinite(p.spanDamping)) bad("span_damping must be finite and > 0 N*s/m");
    }
    if (drum.getParentMobilizedBody().getMobilizedBodyIndex() != carrier.getMobilizedBodyIndex())
        bad("the drum must be on a pin on the carrier");
    if (!carrier.getParentMobilizedBody().isGround()) bad("the carrier must be on a pin on ground");
    // Nominal geometry: the drum's pin location on the carrier (its M frame).
    const Vec3 a = drum.getDefaultInboardFrame().p() - carrier.getDefaultOutboardFrame().p();
    m_nominalDistance = std::hypot(a[0], a[1]);
    if (!(m_nominalDistance > 0)) bad("the drum's pin must be off the carrier's axis");
    calcBeltSpans(Vec3(0), p.fixedSheaveRadius, Vec3(m_nominalDistance, 0, 0), p.drumSheaveRadius);  // checks sin β
}

double BeltDrive::calcDrumAngle(double carrierAngle) const {
    return -m_p.fixedSheaveRadius / m_p.drumSheaveRadius * carrierAngle;
}

double BeltDrive::calcDrumSpeed(double carrierSpeed) const { return calcDrumAngle(carrierSpeed); }

double BeltDrive::calcFeed(const State& s) const {
    return m_p.fixedSheaveRadius * m_carrier.getOneQ(s, kQ) + m_p.drumSheaveRadius * m_drum.getOneQ(s, kQ);
}

double BeltDrive::calcFeedRate(const State& s) const {
    return m_p.fixedSheaveRadius * m_carrier.getOneU(s, kU) + m_p.drumSheaveRadius * m_drum.getOneU(s, kU);
}

Vec3 BeltDrive::calcFixedCentre(const State& s) const {
    // Sheave centres on the pin axes (the mobilizers' M frames).
    return m_carrier.findStationLocationInGround(s, m_carrier.getDefaultOutboardFrame().p());
}

Vec3 BeltDrive::calcDrumCentre(const State& s) const {
    return m_drum.findStationLocationInGround(s, m_drum.getDefaultOutboardFrame().p());
}

BeltSpans BeltDrive::calcSpans(const State& s) const {
    return calcBeltSpans(calcFixedCentre(s), m_p.fixedSheaveRadius, calcDrumCentre(s), m_p.drumSheaveRadius);
}

double BeltDrive::calcGripRatio(const State& s) const {
    const BeltSpans b = calcSpans(s);
    return std::exp(m_p.frictionCoefficient * std::min(b.wrapFixed, b.wrapDrum));
}

double BeltDrive::calcDrumAbsoluteSpeed(const State& s) const {
    return m_carrier.getOneU(s, kU) + m_drum.getOneU(s, kU);
}

double BeltDrive::calcInverseCentreOffset() const {
    return (m_p.fixedSheaveRadius - m_p.drumSheaveRadius) / (m_p.drumSheaveRadius * m_nominalDistance);
}

// ---------------------------------------------------------------- rigid law

RigidBeltConstraint::RigidBeltConstraint(SimbodyMatterSubsystem& matter, const MobilizedBody& carrier,
                                         const MobilizedBody& drum, const BeltDriveParams& p)
    : Implementation(matter, 1, 0, 0), BeltDrive(carrier, drum, p) {
    m_groundBody = addConstrainedBody(matter.getGround());
    m_carrierBody = addConstrainedBody(carrier);
    m_drumBody = addConstrainedBody(drum);
    m_carrierMob = addConstrainedMobilizer(carrier);
    m_drumMob = addConstrainedMobilizer(drum);
}

void RigidBeltConstraint::calcPositionErrors(const State& s, const Array_<Transform, ConstrainedBodyIndex>&,
                                             const Array_<Real, ConstrainedQIndex>& q, Array_<Real>& perr) const {
    const MobilizerQIndex q0(0);
    perr[0] = m_p.fixedSheaveRadius * getOneQ(s, q, m_carrierMob, q0) +
              m_p.drumSheaveRadius * getOneQ(s, q, m_drumMob, q0);
}

void RigidBeltConstraint::calcPositionDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                const Array_<Real, ConstrainedQIndex>& qdot,
                                                Array_<Real>& pverr) const {
    const MobilizerQIndex q0(0);
    pverr[0] = m_p.fixedSheaveRadius * getOneQDot(s, qdot, m_carrierMob, q0) +
               m_p.drumSheaveRadius * getOneQDot(s, qdot, m_drumMob, q0);
}

void RigidBeltConstraint::calcPositionDotDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>&,
                                                   const Array_<Real, ConstrainedQIndex>& qdotdot,
                                                   Array_<Real>& paerr) const {
    const MobilizerQIndex q0(0);
    paerr[0] = m_p.fixedSheaveRadius * getOneQDotDot(s, qdotdot, m_carrierMob, q0) +
               m_p.drumSheaveRadius * getOneQDotDot(s, qdotdot, m_drumMob, q0);
}

void RigidBeltConstraint::calcTensions(double lambda, double& lead, double& trail) const {
    // ΔT = T_lead − T_trail = −λ; with the ratio ρ, T_tight − T_slack = |λ|
    // and T_tight = ρ T_slack (paper: ρ = 2, T_slack = |λ|).
    const double rho = m_p.tightToSlack;
    const double slack = std::abs(lambda) / (rho - 1);
    const double tight = slack + std::abs(lambda);
    if (-lambda >= 0) {
        lead = tight;
        trail = slack;
    } else {
        lead = slack;
        trail = tight;
    }
}

void RigidBeltConstraint::calcTensions(const State& s, const Constraint& self, double& lead, double& trail) const {
    calcTensions(self.getMultipliersAsVector(s)[0], lead, trail);
}

void RigidBeltConstraint::addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                                        Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                                        Array_<Real, ConstrainedQIndex>&) const {
    double lead = 0, trail = 0;
    calcTensions(multipliers[0], lead, trail);
    const Transform& X_AC = getBodyTransformFromState(s, m_carrierBody);  // A is Ground here
    const Transform& X_AD = getBodyTransformFromState(s, m_drumBody);
    const BeltSpans b = calcBeltSpans(X_AC * m_carrier.getDefaultOutboardFrame().p(), m_p.fixedSheaveRadius,
                                      X_AD * m_drum.getDefaultOutboardFrame().p(), m_p.drumSheaveRadius);
    // Simbody applies −(these forces): the belt pulls the drum sheave along
    // each span toward O with its tension. Only ΔT = −λ does work (moments
    // r_A ΔT about A, r0 ΔT about O: G^T λ of x = r0 q1 + r_A q2); the common
    // part is a pull through A toward O.
    addInStationForce(s, m_drumBody, ~X_AD.R() * (b.leadPoint - X_AD.p()), -lead * b.leadDir, bodyForcesInA);
    addInStationForce(s, m_drumBody, ~X_AD.R() * (b.trailPoint - X_AD.p()), -trail * b.trailDir, bodyForcesInA);
}

// -------------------------------------------------------------- elastic law

BeltSpanForce calcBeltSpanForce(double T0, double k, double c, double E, double xe, double xdot) {
    BeltSpanForce f;
    const double yMax = T0 * (E - 1) / (E + 1);
    const double yStick = k * xe + c * xdot;
    if (std::abs(yStick) <= yMax) {
        f.y = yStick;
    } else {
        f.slipping = true;
        f.y = yStick > 0 ? yMax : -yMax;
        const double xeDot = (f.y - k * xe) / c;
        f.slipSpeed = xdot - xeDot;
    }
    return f;
}

double calcBeltSpanEnergy(double T0, double k, double xe) {
    const double a = std::max(0.0, T0 - k * xe), b = std::max(0.0, T0 + k * xe);
    return (a * a + b * b - 2 * T0 * T0) / (2 * k);
}

double calcBeltDissipatedPower(double T0, double k, const BeltSpanForce& f, double xe, double xdot) {
    // Power into the belt from the bodies less the rate of its elastic energy
    // (the span stretched by x carries T0 + y, the other T0 − y).
    const double xeDot = xdot - f.slipSpeed;
    const double in = (std::max(0.0, T0 + f.y) - std::max(0.0, T0 - f.y)) * xdot;
    const double elastic = (std::max(0.0, T0 + k * xe) - std::max(0.0, T0 - k * xe)) * xeDot;
    return in - elastic;
}

ElasticBeltForce::ElasticBeltForce(const GeneralForceSubsystem& forces, const MobilizedBody& carrier,
                                   const MobilizedBody& drum, const BeltDriveParams& p)
    : BeltDrive(carrier, drum, p), m_forces(forces), m_maxY(0) {}

void ElasticBeltForce::realizeTopology(State& s) const { m_slip = m_forces.allocateZ(s, Vector(1, 0.0)); }

double ElasticBeltForce::getSlip(const State& s) const { return m_forces.getZ(s)[m_slip]; }

void ElasticBeltForce::setSlip(State& s, double slip) const { m_forces.updZ(s)[m_slip] = slip; }

ElasticBeltForce::Tensions ElasticBeltForce::calcTensions(const State& s) const {
    const BeltSpanForce f = calcBeltSpanForce(m_p.pretension, m_p.spanStiffness, m_p.spanDamping, calcGripRatio(s),
                                              calcStretch(s), calcFeedRate(s));
    Tensions t;
    t.y = f.y;
    t.slipping = f.slipping;
    t.slipSpeed = f.slipSpeed;
    t.lead = std::max(0.0, m_p.pretension - t.y);
    t.trail = std::max(0.0, m_p.pretension + t.y);
    return t;
}

void ElasticBeltForce::calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const {
    const Tensions t = calcTensions(s);
    const BeltSpans b = calcSpans(s);
    const Rotation& R = m_drum.getBodyRotation(s);
    const Vec3 pA = m_drum.getBodyOriginLocation(s);
    m_drum.applyForceToBodyPoint(s, ~R * (b.leadPoint - pA), t.lead * b.leadDir, bodyForces);
    m_drum.applyForceToBodyPoint(s, ~R * (b.trailPoint - pA), t.trail * b.trailDir, bodyForces);
    // The opposite pulls act on the fixed sheave, i.e. on ground: nothing to apply.
}

Real ElasticBeltForce::calcPotentialEnergy(const State& s) const {
    return calcBeltSpanEnergy(m_p.pretension, m_p.spanStiffness, calcStretch(s));
}

double ElasticBeltForce::calcDissipatedPower(const State& s) const {
    const Tensions t = calcTensions(s);
    BeltSpanForce f;
    f.y = t.y;
    f.slipSpeed = t.slipSpeed;
    f.slipping = t.slipping;
    return calcBeltDissipatedPower(m_p.pretension, m_p.spanStiffness, f, calcStretch(s), calcFeedRate(s));
}

void ElasticBeltForce::realizeAcceleration(const State& s) const {
    m_forces.updZDot(s)[m_slip] = calcTensions(s).slipSpeed;
}

// ------------------------------------------------------------------ element

namespace {

void addCommonProbes(const std::string& name, const BeltDrive* belt, Scene& scene,
                     std::function<void(const State&, double&, double&)> tensions, Stage stage) {
    scene.addProbe({name + ".tension_lead", "N", ProbeRole::Generic, stage, [tensions](const State& s) {
                        double l, t;
                        tensions(s, l, t);
                        return l;
                    }});
    scene.addProbe({name + ".tension_trail", "N", ProbeRole::Generic, stage, [tensions](const State& s) {
                        double l, t;
                        tensions(s, l, t);
                        return t;
                    }});
    scene.addProbe({name + ".tension_tight", "N", ProbeRole::Generic, stage, [tensions](const State& s) {
                        double l, t;
                        tensions(s, l, t);
                        return std::max(l, t);
                    }});
    scene.addProbe({name + ".tension_slack", "N", ProbeRole::Generic, stage, [tensions](const State& s) {
                        double l, t;
                        tensions(s, l, t);
                        return std::min(l, t);
                    }});
    const double rA = belt->params().drumSheaveRadius;
    scene.addProbe({name + ".drum_torque", "N*m", ProbeRole::Generic, stage, [tensions, rA](const State& s) {
                        double l, t;
                        tensions(s, l, t);
                        return rA * (l - t);  // on the drum about A, counter-clockwise +
                    }});
    // Schematic: both sheaves, the carrier arm O-A and the two spans
    // labelled with their tensions.
    const double r0 = belt->params().fixedSheaveRadius;
    scene.addSketch([belt, tensions, r0, rA](const State& s, Sketch& k) {
        const BeltSpans b = belt->calcSpans(s);
        double lead = 0, trail = 0;
        tensions(s, lead, trail);
        char tl[64], tt[64];
        std::snprintf(tl, sizeof tl, "%.3g kN", lead / 1000);
        std::snprintf(tt, sizeof tt, "%.3g kN", trail / 1000);
        const Vec3 o = belt->calcFixedCentre(s), a = belt->calcDrumCentre(s);
        k.circle("sheave", o[0], o[1], r0);
        k.circle("sheave", a[0], a[1], rA);
        k.line("carrier", o[0], o[1], a[0], a[1]);
        k.line("belt", b.leadPoint[0], b.leadPoint[1], b.leadFixedPoint[0], b.leadFixedPoint[1], tl);
        k.line("belt", b.trailPoint[0], b.trailPoint[1], b.trailFixedPoint[0], b.trailFixedPoint[1], tt);
    });
    scene.addProbe({name + ".beta", "rad", ProbeRole::Generic, Stage::Position,
                    [belt](const State& s) { return belt->calcSpans(s).beta; }});
    scene.addProbe({name + ".wrap_fixed", "rad", ProbeRole::Generic, Stage::Position,
                    [belt](const State& s) { return belt->calcSpans(s).wrapFixed; }});
    scene.addProbe({name + ".wrap_drum", "rad", ProbeRole::Generic, Stage::Position,
                    [belt](const State& s) { return belt->calcSpans(s).wrapDrum; }});
    scene.addProbe({name + ".grip_ratio", "1", ProbeRole::Generic, Stage::Position,
                    [belt](const State& s) { return belt->calcGripRatio(s); }});
    scene.addProbe({name + ".drum_absolute_speed", "rad/s", ProbeRole::Generic, Stage::Velocity,
                    [belt](const State& s) { return belt->calcDrumAbsoluteSpeed(s); }});
    // 1 when the drum turns in the ground frame, 0 when it translates
    // (r0 = r_A: l_AD = ∞, the paper's c = 1).
    const double inv = belt->calcInverseCentreOffset();
    scene.addProbe({name + ".drum_turns", "1", ProbeRole::Generic, Stage::Position,
                    [inv](const State&) { return inv != 0 ? 1.0 : 0.0; }});
    scene.addProbe({name + ".inverse_centre_offset", "1/m", ProbeRole::Generic, Stage::Position,
                    [inv](const State&) { return inv; }});
}

void buildBeltDrive(const ElementSpec& spec, Scene& scene) {
    const SceneBody* carrier = scene.findBody(spec.text("carrier"));
    const SceneBody* drum = scene.findBody(spec.text("drum"));
    if (drum->mobod.getParentMobilizedBody().getMobilizedBodyIndex() != carrier->mobod.getMobilizedBodyIndex())
        throw spec.error("drum", "'" + drum->name + "' must be jointed to the carrier '" + carrier->name + "'");
    if (!carrier->mobod.getParentMobilizedBody().isGround())
        throw spec.error("carrier", "'" + carrier->name + "' must be jointed to ground (the fixed sheave is on its axis)");
    BeltDriveParams p;
    p.fixedSheaveRadius = spec.number("fixed_sheave_radius");
    p.drumSheaveRadius = spec.number("drum_sheave_radius");
    // Seed 002's kinematics and criteria (eqs 1-8) from the sheaves and the
    // arm l_OA, the drum axis's distance from the carrier axis.
    {
        const Vec3 a = drum->mobod.getDefaultInboardFrame().p();
        const double arm = std::hypot(a[0], a[1]), r0 = p.fixedSheaveRadius, rA = p.drumSheaveRadius;
        scene.addDerivedValue({spec.name + ".arm", arm, "m", "l_OA, carrier axis to drum axis (seed 002)"});
        scene.addDerivedValue({spec.name + ".drum_speed_ratio", 1 - r0 / rA, "1",
                               "ω/Ω = 1 − r0/r_A, drum speed per carrier speed (seed 002 eqs 1-4)"});
        scene.addDerivedValue({spec.name + ".criterion_k", rA / (arm + rA), "1", "k = r_A/(l_OA + r_A) (seed 002 eq 6)"});
        scene.addDerivedValue({spec.name + ".criterion_c", r0 / rA, "1", "c = r0/r_A (seed 002 eq 8, default reading)"});
        if (arm > 0)
            scene.addDerivedValue({spec.name + ".sin_belt_angle", std::abs(r0 - rA) / arm, "1",
                                   "sin β = |r0 − r_A|/l_OA (seed 002 eq 5)"});
        if (r0 != rA && arm > 0)
            scene.addDerivedValue({spec.name + ".instant_centre_distance", rA * arm / (r0 - rA), "m",
                                   "l_AD = r_A l_OA/(r0 − r_A), drum axis to its instantaneous centre on line OA, "
                                   "signed as eq (4) (seed 002); none when r0 = r_A (the drum translates)"});
    }
    p.law = spec.text("law") == "elastic" ? BeltLaw::Elastic : BeltLaw::Rigid;
    p.tightToSlack = spec.number("tight_to_slack");
    p.pretension = spec.number("pretension");
    p.spanStiffness = spec.number("span_stiffness");
    p.spanDamping = spec.number("span_damping");
    p.frictionCoefficient = spec.number("friction_coefficient");
    const MobilizedBody c = carrier->mobod, d = drum->mobod;
    const BeltDrive* belt = nullptr;
    try {
        if (p.law == BeltLaw::Rigid) {
            auto* impl = new RigidBeltConstraint(scene.matter(), c, d, p);
            Constraint::Custom constraint(impl);
            belt = impl;
            const ConstraintIndex index = constraint.getConstraintIndex();
            const SimbodyMatterSubsystem* matter = &scene.matter();
            addCommonProbes(spec.name, belt, scene,
                            [impl, matter, index](const State& s, double& l, double& t) {
                                impl->calcTensions(s, matter->getConstraint(index), l, t);
                            },
                            Stage::Acceleration);
            scene.addProbe({spec.name + ".slip_speed", "m/s", ProbeRole::Generic, Stage::Position,
                            [](const State&) { return 0.0; }});
            // The paper's ratio must be one the belt can hold.
            scene.addProbe({spec.name + ".grip_exceeded", "1", ProbeRole::Generic, Stage::Position,
                            [impl](const State& s) {
                                return impl->params().tightToSlack > impl->calcGripRatio(s) ? 1.0 : 0.0;
                            }});
        } else {
            auto* impl = new ElasticBeltForce(scene.forces(), c, d, p);
            Force::Custom force(scene.forces(), impl);
            scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
            belt = impl;
            addCommonProbes(spec.name, belt, scene,
                            [impl](const State& s, double& l, double& t) {
                                const auto T = impl->calcTensions(s);
                                l = T.lead;
                                t = T.trail;
                            },
                            Stage::Velocity);
            scene.addProbe({spec.name + ".slip_speed", "m/s", ProbeRole::Generic, Stage::Velocity,
                            [impl](const State& s) { return impl->calcTensions(s).slipSpeed; }});
            scene.addProbe({spec.name + ".slip", "m", ProbeRole::Generic, Stage::Position,
                            [impl](const State& s) { return impl->getSlip(s); }});
            scene.addProbe({spec.name + ".stretch", "m", ProbeRole::Generic, Stage::Position,
                            [impl](const State& s) { return impl->calcStretch(s); }});
            scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Dissipation,
                                 [impl](const State& s) { return impl->calcDissipatedPower(s); }});
            // Kinetostatics: the stretch that keeps the belt's stretch
            // constant (x'' = r0 q1'' + r_A q2'' = 0), i.e. the drum following
            // the carrier as the rigid belt would.
            const double r0 = p.fixedSheaveRadius, rA = p.drumSheaveRadius;
            scene.addKinetostaticUnknown({spec.name + ".stretch",
                                          [impl](State& s, double v) { impl->setStretch(s, v); },
                                          [impl](const State& s) { return impl->calcStretch(s); },
                                          [c, d, r0, rA](const State& s) {
                                              return r0 * c.getOneUDot(s, kU) + rA * d.getOneUDot(s, kU);
                                          }});
        }
    } catch (const std::invalid_argument& e) {
        throw spec.error("fixed_sheave_radius", e.what());
    }
    scene.addInitializer([belt, c, d](State& s) {
        d.setOneQ(s, kQ, belt->calcDrumAngle(c.getOneQ(s, kQ)));
        d.setOneU(s, kU, belt->calcDrumSpeed(c.getOneU(s, kU)));
    });
    scene.addSpeedRelation(drum->name, carrier->name, 1 - p.fixedSheaveRadius / p.drumSheaveRadius);
    const bool turns = belt->calcInverseCentreOffset() != 0;
    scene.note("belt " + spec.name + " (BeltDrive, " + spec.text("law") + ")",
               drum->name + "'s sheave belted to a fixed sheave on " + carrier->name + "'s axis; ω = Ω(1 − r0/r_A)" +
                   (turns ? "" : "; r0 = r_A: the drum does not turn in the ground frame (it translates)"));
}

}  // namespace

void registerBeltDrive(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "BeltDrive";
    s.doc = "Open belt from a sheave fixed on the carrier axis to a sheave on a drum (seed 002): rigid (T1 = 2 T2) or "
            "elastic with Euler-Eytelwein slip.";
    s.params = {
        P::body("carrier", "carrier on a pin on ground; the fixed sheave sits on its axis"),
        P::body("drum", "drum on a pin on the carrier, carrying the drum sheave"),
        P::quantity("fixed_sheave_radius", "m", "r0: the sheave fixed (not turning) on the carrier axis").above(0),
        P::quantity("drum_sheave_radius", "m", "r_A: the sheave rigid with the drum").above(0),
        P::choice("law", {"rigid", "elastic"}, "tension law: the paper's rigid T1 = 2 T2, or an elastic belt")
            .optional(std::string("rigid")),
        P::quantity("tight_to_slack", "1", "rigid: T_tight/T_slack (paper: 2)").optional(2.0).above(1),
        P::quantity("pretension", "N", "elastic: T0 in each span at rest").optional(0.0).atLeast(0),
        P::quantity("span_stiffness", "N/m", "elastic: k_s = EA/span length of each span").optional(1.0).above(0),
        P::quantity("span_damping", "N*s/m", "elastic: c_s of each span").optional(1.0).above(0),
        // At most 10 (a V-belt's μ/sin(half groove angle) is about 1.7): the
        // grip e^(μθ) stays finite (issue 26 item 7).
        P::quantity("friction_coefficient", "1", "μ belt on sheave (V-belt: μ/sin(half groove angle))")
            .optional(0.3)
            .atLeast(0)
            .atMost(10),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.text("carrier") == e.text("drum")) throw e.error("drum", "the drum and the carrier must be different bodies");
        if (e.text("law") == "elastic")
            for (const char* key : {"pretension", "span_stiffness", "span_damping"})
                if (!e.params.at(key).given) throw e.error(key, "law: elastic needs " + std::string(key));
    };
    registry.add({std::move(s), buildBeltDrive});
}

}  // namespace milldyn
