#include "plugins/charges/SegmentCharge.h"

#include "plugins/charges/ChargePowerLaw.h"
#include "plugins/charges/CircularSegment.h"

#include <cstdio>

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <limits>
#include <map>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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

/// An angle wrapped into (−π, π].
double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }
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
    if (p.lagTableSpeed.size() != p.lagTableLag.size())
        bad("lag_table_speed and lag_table_lag must have as many entries");
    for (std::size_t i = 1; i < p.lagTableSpeed.size(); ++i)
        if (!(p.lagTableSpeed[i] > p.lagTableSpeed[i - 1])) bad("lag_table_speed must increase strictly");
    if (p.motion == ChargeMotionMode::TorqueArm) {
        if (!(p.gravity.norm() > 0)) bad("motion: torque_arm needs gravity (the charge's weight is its load)");
        if (!(p.smoothingSpeed > 0) || !std::isfinite(p.smoothingSpeed)) bad("smoothing_speed must be > 0 rad/s");
        // The lag laws: a lag from the downward vertical in the turning
        // sense, between hanging (0) and level with the axis (90°).
        auto lagInRange = [](double a) { return a >= 0 && a <= M_PI / 2; };
        if (p.powerLaw == ChargePowerLaw::Lag) {
            if (!lagInRange(p.lag)) bad("lag must be in [0, 90] deg");
            for (double a : p.lagTableLag)
                if (!lagInRange(a)) bad("lag_table_lag entries must be in [0, 90] deg");
        }
        if (!(p.startSpeedFraction > 0) || !std::isfinite(p.startSpeedFraction))
            bad("start_speed_fraction must be > 0");
        if (!std::isfinite(p.ballSizeFactor)) bad("ball_size_factor must be finite");
    }
    if (p.motion == ChargeMotionMode::Frozen) {
        if (!(p.gravity.norm() > 0)) bad("motion: frozen needs gravity (the block's weight is its load)");
        if (!(p.releaseAngle > 0 && p.releaseAngle < M_PI)) bad("release_angle must be in (0, 180) deg");
        if (!(p.safeAngle > 0 && p.safeAngle < M_PI)) bad("safe_angle must be in (0, 180) deg");
        if (!(p.frozenInitialLag > -M_PI && p.frozenInitialLag < p.releaseAngle))
            bad("initial_lag must be in (-180 deg, release_angle)");
    }
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

double SegmentCharge::calcCriticalSpeed() const { return std::sqrt(m_p.gravity.norm() / m_p.drumRadius); }

double SegmentCharge::calcLagAtSpeedFraction(double phi) const {
    const std::vector<double>& x = m_p.lagTableSpeed;
    const std::vector<double>& y = m_p.lagTableLag;
    const std::size_t n = x.size();
    if (n == 0) return m_p.lag;
    if (n == 1 || phi <= x.front()) return y.front();
    if (phi >= x.back()) return y.back();
    // Monotone cubic Hermite (Fritsch & Carlson 1980): secant slopes d_k,
    // end slopes one-sided, interior slopes the harmonic mean of the
    // neighbouring secants (0 where they differ in sign): C¹, no overshoot.
    std::vector<double> d(n - 1), m(n);
    for (std::size_t k = 0; k + 1 < n; ++k) d[k] = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
    m[0] = d[0];
    m[n - 1] = d[n - 2];
    for (std::size_t k = 1; k + 1 < n; ++k) {
        if (d[k - 1] * d[k] <= 0) {
            m[k] = 0;
            continue;
        }
        const double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
        const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
        m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k]);
    }
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), phi) - x.begin()) - 1;
    const double h = x[k + 1] - x[k], t = (phi - x[k]) / h;
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
    const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    return h00 * y[k] + h10 * h * m[k] + h01 * y[k + 1] + h11 * h * m[k + 1];
}

double SegmentCharge::calcUnbalanceMoment() const {
    // |g| in the plane of the cross-section: the weight's moment arm is there.
    return calcMass() * calcCentroidDistance() * std::hypot(m_p.gravity[0], m_p.gravity[1]);
}

double SegmentCharge::calcLawPower(double phi) const {
    const double omega = phi * calcCriticalSpeed();
    switch (m_p.powerLaw) {
        case ChargePowerLaw::Bond:
            return calcMass() * charge_power::calcBondSpecificPower(2 * m_p.drumRadius, calcFillFraction(m_p.halfAngle),
                                                                   phi, m_p.ballSizeFactor);
        case ChargePowerLaw::MorrellC:
            return charge_power::calcMorrellNetPower(m_p.drumRadius, m_p.length, m_p.bulkDensity,
                                                     calcFillFraction(m_p.halfAngle), phi, m_p.gravity.norm());
        case ChargePowerLaw::Lag: break;
    }
    return calcUnbalanceMoment() * std::sin(calcLagAtSpeedFraction(phi)) * omega;
}

double SegmentCharge::calcLawTorque(double phi) const {
    if (m_p.powerLaw == ChargePowerLaw::Lag) return calcUnbalanceMoment() * std::sin(calcLagAtSpeedFraction(phi));
    // Start rule: below φ_s the torque stays at its φ_s value (P/ω has no
    // value at ω = 0; a charge carried up to its running lag from the first
    // turn loads the shell so).
    const double held = std::max(std::abs(phi), m_p.startSpeedFraction);
    return calcLawPower(held) / (held * calcCriticalSpeed());
}

double SegmentCharge::calcTorqueArmLag(double omega) const {
    const double phi = std::abs(omega) / calcCriticalSpeed();
    if (m_p.powerLaw == ChargePowerLaw::Lag) return calcLagAtSpeedFraction(phi) * std::tanh(omega / m_p.smoothingSpeed);
    // A correlation's equivalent lag: the torque arm that gives its torque
    // (the builder checks it stays below 90°).
    const double ratio = std::min(1.0, calcLawTorque(phi) / calcUnbalanceMoment());
    return std::asin(ratio) * std::tanh(omega / m_p.smoothingSpeed);
}

double SegmentCharge::calcTorqueArmTorque(double omega) const {
    // The weight m g at the centroid r_c u, u at α from the downward
    // vertical d: the z component of (r_c u) × (m g) is
    // m r_c |g| (cos(d + α) sin d − sin(d + α) cos d) = −m r_c |g| sin α,
    // |g| the gravity in the plane of the cross-section.
    if (m_p.powerLaw == ChargePowerLaw::Lag) return -calcUnbalanceMoment() * std::sin(calcTorqueArmLag(omega));
    // A correlation: T = P/ω, odd and smooth through standstill.
    const double phi = std::abs(omega) / calcCriticalSpeed();
    return -calcLawTorque(phi) * std::tanh(omega / m_p.smoothingSpeed);
}

double SegmentCharge::calcFractionOfCritical(const State& s) const {
    return calcDrumSpeed(s) / calcCriticalSpeed();
}

double SegmentCharge::calcFrozenLag(const State& s) const {
    const double hang = Value<Real>::downcast(m_matter.getDiscreteVariable(s, m_hangAngle));
    return m_drum.getOneQ(s, kQ) - hang;
}

bool SegmentCharge::isReleased(const State& s) const {
    return Value<Real>::downcast(m_matter.getDiscreteVariable(s, m_released)) > 0.5;
}

double SegmentCharge::getAngleReached(const State& s) const {
    return Value<Real>::downcast(m_matter.getDiscreteVariable(s, m_angleReached));
}

double SegmentCharge::calcFrozenTorque(const State& s) const {
    if (isReleased(s)) return 0;
    // Packed until the latch: the release is a located event (the witness
    // θ_r − θ, FrozenReleaseTrigger), so the integrator stops at θ = θ_r
    // (to its localization window) and the latch flips there; the moment
    // stays continuous up to that instant.
    return -calcUnbalanceMoment() * std::sin(calcFrozenLag(s));
}

double SegmentCharge::calcReleaseWitness(const State& s) const {
    return isReleased(s) ? -1.0 : m_p.releaseAngle - calcFrozenLag(s);
}

double SegmentCharge::calcFrozenLatch(const State& s) const {
    return isReleased(s) || calcFrozenLag(s) >= m_p.releaseAngle ? 1.0 : 0.0;
}

double SegmentCharge::updateFrozenLatch(State& s) const {
    const double latch = calcFrozenLatch(s);
    const bool was = isReleased(s);
    double& reached = Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_angleReached));
    if (latch > 0.5) {
        reached = std::max(reached, m_p.releaseAngle);
    } else {
        reached = std::max(reached, calcFrozenLag(s));
    }
    if ((latch > 0.5) == was) return 0;
    Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_released)) = latch;
    return 1;
}

void SegmentCharge::setFrozenStart(State& s) const {
    Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_hangAngle)) =
        m_drum.getOneQ(s, kQ) - m_p.frozenInitialLag;
    Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_released)) = 0;
    Value<Real>::updDowncast(m_matter.updDiscreteVariable(s, m_angleReached)) = m_p.frozenInitialLag;
}

double SegmentCharge::calcDrumSpeed(const State& s) const { return m_drum.getBodyAngularVelocity(s)[2]; }

void SegmentCharge::realizeTopology(State& s) const {
    m_heldTorque = m_matter.allocateDiscreteVariable(s, Stage::Dynamics, new Value<Real>(0.0));
    m_hangAngle = m_matter.allocateDiscreteVariable(s, Stage::Dynamics, new Value<Real>(0.0));
    m_released = m_matter.allocateDiscreteVariable(s, Stage::Dynamics, new Value<Real>(0.0));
    // Read by an output only: changing it invalidates nothing the motion uses.
    m_angleReached = m_matter.allocateDiscreteVariable(s, Stage::Report, new Value<Real>(0.0));
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
    if (m_p.motion == ChargeMotionMode::TorqueArm) return calcDirectionOfLag(s, calcTorqueArmLag(calcDrumSpeed(s)));
    if (m_p.motion == ChargeMotionMode::Frozen) return calcDirectionOfLag(s, calcLag(s));
    // The body's mass centre lies on its −y axis.
    const Vec3 down = -m_charge.getBodyRotation(s).y();
    return std::atan2(down[1], down[0]);
}

double SegmentCharge::calcDirectionOfLag(const State& s, double lag) const {
    if (m_p.lagFrom == LagReference::Vertical) return calcDownAngle() + lag;
    Vec3 out = m_drum.getBodyOriginLocation(s) - m_carrier.getBodyOriginLocation(s);
    const double outAngle = std::atan2(out[1], out[0]);
    // u = sin α e_out + cos α e_t: at angle outAngle + atan2(cos α, sin α).
    return outAngle + std::atan2(std::cos(lag), std::sin(lag));
}

double SegmentCharge::calcDownAngle() const {
    const Vec3& g = m_p.gravity;
    return g[0] == 0 && g[1] == 0 ? -M_PI / 2 : std::atan2(g[1], g[0]);
}

double SegmentCharge::calcLag(const State& s) const {
    if (m_p.motion == ChargeMotionMode::TorqueArm) return calcTorqueArmLag(calcDrumSpeed(s));
    // Frozen: the block's lag while packed; once fallen it hangs (0).
    if (m_p.motion == ChargeMotionMode::Frozen) return isReleased(s) ? 0.0 : wrapAngle(calcFrozenLag(s));
    if (m_p.lagFrom == LagReference::Vertical) return wrapAngle(calcDirection(s) - calcDownAngle());
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
    if (m_p.motion == ChargeMotionMode::TorqueArm || m_p.motion == ChargeMotionMode::Frozen)
        return calcDrumSpeed(s);  // the charge stands still (torque arm) or the couple turns with the shell
    return -m_charge.getOneU(s, kU);  // the charge's pin is on the drum
}

double SegmentCharge::calcWallTorque(const State& s) const {
    switch (m_p.motion) {
        case ChargeMotionMode::WithDrum: return 0;
        case ChargeMotionMode::Held: return getHeldTorque(s);
        case ChargeMotionMode::DynamicLag: return m_p.wallDrag * calcSlipSpeed(s);
        case ChargeMotionMode::TorqueArm: return -calcTorqueArmTorque(calcDrumSpeed(s));
        case ChargeMotionMode::Frozen: return 0.0 - calcFrozenTorque(s);  // +0, not -0, once released
    }
    return 0;
}

void SegmentCharge::calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                              Vector& mobilityForces) const {
    if (m_p.motion == ChargeMotionMode::WithDrum) return;
    if (m_p.motion == ChargeMotionMode::TorqueArm) {
        // The couple that moves the weight's line of action from the axis
        // (where the shell's mass properties carry it) to the centroid.
        m_drum.applyBodyTorque(s, Vec3(0, 0, calcTorqueArmTorque(calcDrumSpeed(s))), bodyForces);
        return;
    }
    if (m_p.motion == ChargeMotionMode::Frozen) {
        m_drum.applyBodyTorque(s, Vec3(0, 0, calcFrozenTorque(s)), bodyForces);
        return;
    }
    // A mobility force on the charge's pin: drum on charge, and the opposite
    // on the drum.
    m_charge.applyOneMobilityForce(s, kU, calcWallTorque(s), mobilityForces);
}

namespace {

/// The frozen charge's release as a Simbody event: the witness θ_r − θ
/// falls through zero where the packed block reaches its release angle (−1
/// once released, so it never triggers again). The integrator localizes the
/// sign change (kReleaseWindow: Simbody's required localization window,
/// default 0.1; the 4 m ball mill's window came out 8e-13 s wide)
/// and returns the state at the window's start (Integrator::
/// ReachedEventTrigger): Simulation::run puts it on the trajectory, and the
/// next step end, past θ_r, flips the latch (the kept value
/// SegmentCharge::updateFrozenLatch). A TimeStepper calls handleEvent,
/// which flips it as well.
class FrozenReleaseTrigger : public TriggeredEventHandler {
public:
    explicit FrozenReleaseTrigger(const SegmentCharge* charge) : TriggeredEventHandler(Stage::Position), m_charge(charge) {
        getTriggerInfo().setTriggerOnRisingSignTransition(false);
        getTriggerInfo().setRequiredLocalizationTimeWindow(kReleaseWindow);
    }
    Real getValue(const State& s) const override { return m_charge->calcReleaseWitness(s); }
    void handleEvent(State& s, Real, bool& shouldTerminate) const override {
        m_charge->updateFrozenLatch(s);
        shouldTerminate = false;
    }
    static constexpr double kReleaseWindow = 1e-6;

private:
    const SegmentCharge* m_charge;
};

/// The keys each motion uses besides the segment's (drum, drum_radius,
/// length, bulk_density, fill, half_angle, motion, lag_from).
const std::map<std::string, std::set<std::string>>& keysOfMotion() {
    static const std::map<std::string, std::set<std::string>> keys = {
        {"with_drum", {"initial_direction"}},
        {"held", {"lag"}},
        {"dynamic_lag", {"wall_drag", "initial_direction", "initial_lag"}},
        {"torque_arm", {"lag", "lag_table_speed", "lag_table_lag", "smoothing_speed", "power_law", "ball_size_factor",
                        "start_speed_fraction", "initial_speed_fraction"}},
        {"frozen", {"release_angle", "safe_angle", "initial_lag", "initial_speed_fraction"}},
    };
    return keys;
}

/// A key the motion does not use is an error naming the motion. Checked
/// when the element is built, not when the file is read: a model's other
/// fidelity levels may hold an element of the same name with another
/// motion, which `--set elements.NAME.KEY` also reaches.
void checkKeysOfMotion(const ElementSpec& e) {
    const std::string& motion = e.text("motion");
    const std::set<std::string>& own = keysOfMotion().at(motion);
    for (const auto& [key, value] : e.params) {
        if (!value.given || own.count(key)) continue;
        bool usedElsewhere = false;
        for (const auto& [other, keys] : keysOfMotion()) usedElsewhere = usedElsewhere || keys.count(key);
        if (!usedElsewhere) continue;
        std::string list;
        for (const auto& k : own) list += (list.empty() ? "" : ", ") + k;
        throw e.error(key, "not used with motion: " + motion + " (it takes " + list + ")");
    }
}

ChargeMotionMode motionOf(const std::string& word) {
    if (word == "held") return ChargeMotionMode::Held;
    if (word == "dynamic_lag") return ChargeMotionMode::DynamicLag;
    if (word == "torque_arm") return ChargeMotionMode::TorqueArm;
    if (word == "frozen") return ChargeMotionMode::Frozen;
    return ChargeMotionMode::WithDrum;
}

/// Whether a body's pin axis stays put in ground: it is on ground, or on the
/// axis of a body whose axis stays put (a shell on a girth-gear body on
/// ground). A drum off its parent's axis is carried round it.
bool axisIsFixed(const MobilizedBody& body) {
    if (body.isGround()) return true;
    const MobilizedBody parent = body.getParentMobilizedBody();
    if (parent.isGround()) return true;
    const Vec3 offset = body.getDefaultInboardFrame().p();
    if (std::hypot(offset[0], offset[1]) > 0) return false;
    return axisIsFixed(parent);
}

/// The gravity of the scene's UniformGravity (zero if none).
Vec3 sceneGravity(Scene& scene) {
    const GeneralForceSubsystem& forces = scene.forces();
    for (int i = 0; i < forces.getNumForces(); ++i) {
        const Force& f = forces.getForce(ForceIndex(i));
        if (Force::UniformGravity::isInstanceOf(f)) return Force::UniformGravity::downcast(f).getGravity();
    }
    return Vec3(0);
}

/// Adds mass m with its centre at `comInDrum` and central polar inertia
/// `centralPolar` (about z) to the drum's mass properties.
void addToDrum(MobilizedBody& drumBody, double m, const Vec3& comInDrum, double centralPolar) {
    const Inertia central(centralPolar / 2, centralPolar / 2, centralPolar);
    const MassProperties d = drumBody.getDefaultMassProperties();
    const double total = d.getMass() + m;
    const Inertia aboutOrigin = d.getInertia() + central + Inertia(comInDrum, m);
    drumBody.setDefaultMassProperties(
        MassProperties(total, (d.getMass() * d.getMassCenter() + m * comInDrum) / total, aboutOrigin));
}

/// A correlation must give a charge and a torque the torque arm can carry
/// (an equivalent lag of at most 90°) from φ_s up to 150 % of critical.
void checkCorrelation(const ElementSpec& spec, const SegmentCharge& c) {
    const SegmentChargeParams& p = c.params();
    const double top = 1.5, from = p.startSpeedFraction;
    for (int i = 0; i <= 400 && from < top; ++i) {
        const double phi = from + (top - from) * i / 400;
        const double torque = c.calcLawTorque(phi);
        const std::string at = "at fill " + formatNumber(100 * SegmentCharge::calcFillFraction(p.halfAngle)) + " % and " +
                               formatNumber(100 * phi) + " % of critical speed";
        if (!std::isfinite(torque))
            throw spec.error("fill", "power_law " + spec.text("power_law") + " has no charge " + at +
                                         " (Morrell's 2 pi beta J exceeds the bed's angle): lower the fill or raise "
                                         "start_speed_fraction");
        if (torque > c.calcUnbalanceMoment())
            throw spec.error("power_law", spec.text("power_law") + " asks " + formatNumber(torque) + " N*m " + at +
                                              ", more than the charge's weight can give at 90 deg lag (m g r_c = " +
                                              formatNumber(c.calcUnbalanceMoment()) +
                                              " N*m): check bulk_density and fill");
    }
}

void buildSegmentCharge(const ElementSpec& spec, Scene& scene) {
    checkKeysOfMotion(spec);
    // Copies, not a pointer into the scene's body list: adding the charge's
    // body below may move that list.
    const SceneBody drum = *scene.findBody(spec.text("drum"));
    const MobilizedBody carrier = drum.mobod.getParentMobilizedBody();
    const bool fixedAxis = axisIsFixed(drum.mobod);
    SegmentChargeParams p;
    p.drumRadius = spec.number("drum_radius");
    p.length = spec.number("length");
    p.bulkDensity = spec.number("bulk_density");
    p.halfAngle = spec.has("half_angle") && spec.params.at("half_angle").given
                      ? spec.number("half_angle")
                      : SegmentCharge::calcHalfAngleForFill(spec.number("fill"));
    const std::string& motion = spec.text("motion");
    p.motion = motionOf(motion);
    // lag_from: auto is the vertical on a fixed axis (tumbling mill), the
    // carrier radius on a carried one (planetary: the papers' α).
    const std::string& lagFrom = spec.text("lag_from");
    p.lagFrom = lagFrom == "vertical"         ? LagReference::Vertical
                : lagFrom == "carrier_radius" ? LagReference::CarrierRadius
                : fixedAxis                   ? LagReference::Vertical
                                              : LagReference::CarrierRadius;
    if (p.lagFrom == LagReference::CarrierRadius && fixedAxis)
        throw spec.error("lag_from", "carrier_radius is measured from the line carrier axis -> drum axis, and drum '" +
                                         drum.name + "' turns about a fixed axis (no carrier): use lag_from: vertical");
    if (p.motion == ChargeMotionMode::TorqueArm && p.lagFrom != LagReference::Vertical)
        throw spec.error("lag_from", "motion: torque_arm holds the charge at a lag from the vertical (the weight's "
                                     "torque arm): use lag_from: vertical");
    if (p.motion == ChargeMotionMode::Frozen && p.lagFrom != LagReference::Vertical)
        throw spec.error("lag_from", "motion: frozen lifts the block from the downward vertical: use lag_from: vertical");
    if (p.motion == ChargeMotionMode::Frozen && !carrier.isGround())
        throw spec.error("motion", "frozen: drum '" + drum.name + "' must turn on a pin on ground (its angle is the "
                                   "block's lift)");
    const std::string& law = spec.text("power_law");
    p.powerLaw = law == "bond" ? ChargePowerLaw::Bond : law == "morrell_c" ? ChargePowerLaw::MorrellC : ChargePowerLaw::Lag;
    p.ballSizeFactor = spec.number("ball_size_factor");
    p.startSpeedFraction = spec.number("start_speed_fraction");
    p.releaseAngle = spec.number("release_angle");
    p.safeAngle = spec.number("safe_angle");
    if (p.motion == ChargeMotionMode::Frozen) p.frozenInitialLag = spec.number("initial_lag");
    p.lag = spec.number("lag");
    p.initialDirection = spec.number("initial_direction");
    p.wallDrag = spec.number("wall_drag");
    p.gravity = sceneGravity(scene);
    if (spec.params.at("lag_table_speed").given) {
        p.lagTableSpeed = spec.numbers("lag_table_speed");
        p.lagTableLag = spec.numbers("lag_table_lag");
    }
    if ((p.motion == ChargeMotionMode::TorqueArm || p.motion == ChargeMotionMode::Frozen) && !(p.gravity.norm() > 0))
        throw spec.error("motion", motion + ": the charge's weight is its load, and the model has no gravity");
    const double criticalSpeed = std::sqrt(p.gravity.norm() / p.drumRadius);
    p.smoothingSpeed = spec.params.at("smoothing_speed").given ? spec.number("smoothing_speed") : 0.02 * criticalSpeed;
    const bool initialLagGiven = spec.params.at("initial_lag").given;
    const double initialLag = spec.number("initial_lag");
    const double chargeMass =
        p.bulkDensity * p.length * p.drumRadius * p.drumRadius * circular_segment::calcAreaFactor(p.halfAngle) / 2;
    if (!(chargeMass >= std::numeric_limits<double>::min())) {
        // m ≈ (2/3)·ρ·l·r²·γ³ for a thin segment: a half-angle so small that
        // the mass underflows is no charge (issue 26 item 7).
        const double smallest =
            std::cbrt(1.5 * std::numeric_limits<double>::min() / (p.bulkDensity * p.length * p.drumRadius * p.drumRadius));
        const bool byAngle = spec.has("half_angle") && spec.params.at("half_angle").given;
        throw spec.error(byAngle ? "half_angle" : "fill",
                         "the segment's half-angle " + formatNumber(p.halfAngle) + " rad gives a charge of mass " +
                             formatNumber(chargeMass) + " kg: with these drum_radius, length and bulk_density it must be at least " +
                             formatNumber(smallest) + " rad");
    }
    auto* impl = new SegmentCharge(scene.matter(), carrier, drum.mobod, p);
    if (p.motion == ChargeMotionMode::TorqueArm && p.powerLaw != ChargePowerLaw::Lag)
        checkCorrelation(spec, *impl);

    const double m = impl->calcMass(), lc = impl->calcCentroidDistance();
    // k_c m r², not J_axis − m l_c² (two nearly equal numbers for a thin charge)
    const double centralPolar = m * p.drumRadius * p.drumRadius * circular_segment::calcCentralInertiaFactor(p.halfAngle);
    MobilizedBody drumBody = drum.mobod;  // handles: a copy is the body
    MobilizedBody chargeBody;
    // The frame a held or steady charge stands still in: ground on a fixed
    // axis (even a drum on a coaxial body), the carrier on a carried one.
    const MobilizedBody reference = fixedAxis ? MobilizedBody(scene.matter().getGround()) : carrier;
    if (p.motion == ChargeMotionMode::WithDrum) {
        // Turns with the drum, its centroid at initial_direction in the drum
        // frame: its mass properties are added to the drum's instead of a
        // welded body of its own. The motion and every reaction at the
        // drum's joint are the same; a welded body would cost a body in
        // every realization and carry nothing an output reads (the charge's
        // lag follows from the drum's angle).
        addToDrum(drumBody, m, Vec3(lc * std::cos(p.initialDirection), lc * std::sin(p.initialDirection), 0),
                  centralPolar);
    } else if (p.motion == ChargeMotionMode::TorqueArm || p.motion == ChargeMotionMode::Frozen) {
        // Mass and axis inertia on the shell's axis; the couple in calcForce
        // moves the weight to the centroid (frozen: the block turns with the
        // shell, its polar moment about the axis is J_Bz too).
        addToDrum(drumBody, m, Vec3(0), impl->calcAxisInertia());
    } else {
        // The body's mass centre lies on its −y axis.
        const Vec3 com(0, -lc, 0);
        const Inertia central(centralPolar / 2, centralPolar / 2, centralPolar);
        const Body::Rigid body(MassProperties(m, com, central + Inertia(com, m)));
        chargeBody = MobilizedBody::Pin(drumBody, Transform(), body, Transform());
        impl->setBody(chargeBody);
        // Scene bodies are pins (analyses read one angle and speed from each).
        scene.addBody(spec.name, chargeBody);
        // In steady running on a fixed axis the charge stands at its lag:
        // relative to the drum it turns back at the drum's speed.
        if (carrier.isGround()) scene.addSpeedRelation(spec.name, drum.name, -1.0);
        if (p.motion == ChargeMotionMode::DynamicLag) {
            // Steady running: the charge stands still in the carrier frame
            // (at its running lag), it does not merely stop accelerating.
            const MobilizedBody cb = chargeBody, c = reference;
            scene.addSteadyResidual({spec.name + ".speed_in_carrier_frame", [cb, c](const State& s) {
                                         return cb.getBodyAngularVelocity(s)[2] - c.getBodyAngularVelocity(s)[2];
                                     }});
        }
    }
    // Schematic: the drum wall and the charge's segment where it is now.
    const MobilizedBody drumMobod = drum.mobod;
    const std::string drumName = drum.name;
    scene.addSketch([impl, drumMobod, drumName](const State& s, Sketch& k) {
        const Vec3 b = drumMobod.getBodyOriginLocation(s);
        const double r = impl->params().drumRadius;
        k.circle("drum", b[0], b[1], r, drumName);
        // The lag in its convention (docs/charges.md: lag_from).
        char lag[64];
        std::snprintf(lag, sizeof lag, "lag %.0f deg from %s", impl->calcLag(s) * 180 / M_PI,
                      impl->params().lagFrom == LagReference::Vertical ? "vertical" : "carrier radius");
        k.segment("charge", b[0], b[1], r, impl->calcDirection(s), impl->params().halfAngle, lag);
    });
    Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);

    if (p.motion == ChargeMotionMode::Held || p.motion == ChargeMotionMode::DynamicLag) {
        const MobilizedBody cb = chargeBody, d = drum.mobod;
        const bool held = p.motion == ChargeMotionMode::Held;
        const System* system = &scene.system();
        scene.addInitializer([impl, cb, d, reference, held, system, initialLagGiven, initialLag](State& s) {
            const SegmentChargeParams& q = impl->params();
            system->realize(s, Stage::Position);
            const double direction = held              ? impl->calcDirectionOfLag(s, q.lag)
                                     : initialLagGiven ? impl->calcDirectionOfLag(s, initialLag)
                                                       : q.initialDirection;
            cb.setOneQ(s, kQ, impl->calcRelativeAngleFor(s, direction));
            // Held: still in its reference frame; dynamic: starts with the drum.
            system->realize(s, Stage::Velocity);
            const double still = reference.getBodyAngularVelocity(s)[2] - d.getBodyAngularVelocity(s)[2];
            cb.setOneU(s, kU, held ? still : 0.0);
        });
    }
    if (p.motion == ChargeMotionMode::Held) {
        const MobilizedBody cb = chargeBody;
        scene.addKinetostaticUnknown(
            {spec.name + ".wall_torque", [impl](State& s, double T) { impl->setHeldTorque(s, T); },
             [impl](const State& s) { return impl->getHeldTorque(s); },
             // the charge's angular acceleration in its reference frame
             [cb, reference](const State& s) {
                 return cb.getBodyAngularAcceleration(s)[2] - reference.getBodyAngularAcceleration(s)[2];
             }});
    }
    // The lag's convention, in words: the note below; the lag's plot axis.
    const bool vertical = p.lagFrom == LagReference::Vertical;
    const std::string convention =
        vertical ? "from the downward vertical, + in the +z (turning) sense"
                 : "from the leading tangent towards the outward carrier radius (seed 000 eq 22)";
    scene.addProbe({spec.name + ".lag", "rad", ProbeRole::Generic, Stage::Position,
                    [impl](const State& s) { return impl->calcLag(s); },
                    // Short enough for a plot's y axis.
                    vertical ? "lag from downward vertical, + turning (lag_from: vertical)"
                             : "lag from leading tangent to carrier radius (lag_from: carrier_radius)"});
    const bool frozen = p.motion == ChargeMotionMode::Frozen;
    if (p.motion == ChargeMotionMode::TorqueArm || frozen) {
        scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::ResistanceTorque, Stage::Velocity,
                        [impl](const State& s) { return impl->calcWallTorque(s); }});
        scene.addProbe({spec.name + ".fraction_of_critical", "1", ProbeRole::Generic, Stage::Velocity,
                        [impl](const State& s) { return impl->calcFractionOfCritical(s); },
                        "drum speed / critical speed sqrt(2g/D)"});
    } else {
        scene.addProbe({spec.name + ".wall_torque", "N*m", ProbeRole::Generic, Stage::Velocity,
                        [impl](const State& s) { return impl->calcWallTorque(s); }});
    }
    if (frozen) {
        // Lifting the packed block stores m g Δh in it; its fall spends it
        // (impact and heat in the charge): a load on the drive.
        scene.addProbe({spec.name + ".lift_power", "W", ProbeRole::ResistancePower, Stage::Velocity,
                        [impl](const State& s) { return impl->calcWallTorque(s) * impl->calcSlipSpeed(s); }});
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Load,
                             [impl](const State& s) { return impl->calcWallTorque(s) * impl->calcSlipSpeed(s); },
                             "lifting the packed charge (spent by its fall)"});
        scene.addProbe({spec.name + ".released", "1", ProbeRole::Generic, Stage::Position,
                        [impl](const State& s) { return impl->isReleased(s) ? 1.0 : 0.0; }});
        scene.addProbe({spec.name + ".angle_reached", "rad", ProbeRole::Generic, Stage::Position,
                        [impl](const State& s) { return impl->getAngleReached(s); },
                        "largest lag of the packed block (step ends; release angle once released)"});
        scene.addInitializer([impl](State& s) { impl->setFrozenStart(s); });
        scene.system().addEventHandler(new FrozenReleaseTrigger(impl));
        scene.addLaggedValue({spec.name + ".release", true,
                              [impl](const State& s) { return impl->calcFrozenLatch(s); },
                              [impl](State& s, double) { return impl->updateFrozenLatch(s); }});
    } else if (p.motion != ChargeMotionMode::WithDrum) {
        scene.addProbe({spec.name + ".grinding_power", "W", ProbeRole::ResistancePower, Stage::Velocity,
                        [impl](const State& s) { return impl->calcWallTorque(s) * impl->calcSlipSpeed(s); }});
        scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Load, [impl](const State& s) {
                                 return impl->calcWallTorque(s) * impl->calcSlipSpeed(s);
                             }});
    }
    scene.addDerivedValue({spec.name + ".mass", m, "kg", "m_z = ρ l r² (2γ − sin 2γ)/2 (seed 000 eq 3)"});
    scene.addDerivedValue({spec.name + ".centroid_radius", lc, "m",
                           "l_c = 4 r sin³γ / (3 (2γ − sin 2γ)), centroid from the drum axis (seed 000 eq 6)"});
    scene.addDerivedValue({spec.name + ".half_angle", p.halfAngle, "rad", "γ, the segment's half-angle"});
    scene.addDerivedValue({spec.name + ".fill", SegmentCharge::calcFillFraction(p.halfAngle), "1",
                           "(2γ − sin 2γ)/(2π), filled fraction of the cross-section"});
    scene.addDerivedValue({spec.name + ".axis_inertia", impl->calcAxisInertia(), "kg*m^2",
                           "J_Bz about the drum axis (seed 000 eq 13)"});
    if (p.gravity.norm() > 0)
        scene.addDerivedValue({spec.name + ".critical_speed", criticalSpeed, "rad/s",
                               "ω_c = sqrt(|g|/r) = sqrt(2|g|/D): a particle at the wall is held at the top "
                               "(ball radius neglected)"});
    if (spec.params.at("initial_speed_fraction").given) {
        if (!carrier.isGround())
            throw spec.error("initial_speed_fraction", "drum '" + drum.name + "' must turn on a pin on ground");
        const MobilizedBody d = drum.mobod;
        const double speed = spec.number("initial_speed_fraction") * criticalSpeed;
        scene.addInitializer([d, speed](State& s) { d.setOneU(s, kU, speed); });
    }
    if (p.motion == ChargeMotionMode::TorqueArm && p.powerLaw != ChargePowerLaw::Lag) {
        scene.addDerivedValue({spec.name + ".start_torque", impl->calcLawTorque(0), "N*m",
                               "the law's torque held below start_speed_fraction (P(φ_s)/(φ_s ω_c))"});
    }
    if (frozen) {
        const double W = impl->calcUnbalanceMoment(), lc0 = lc;
        const double tr = p.releaseAngle, ts = p.safeAngle;
        scene.addDerivedValue({spec.name + ".unbalance_moment", W, "N*m", "m |g| r_c, the block's moment at 90 deg"});
        scene.addDerivedValue({spec.name + ".release_torque", W * std::sin(tr), "N*m",
                               "m |g| r_c sin θ_r, the block's moment as it breaks loose"});
        scene.addDerivedValue({spec.name + ".fall_height", lc0 * (1 - std::cos(tr)), "m",
                               "r_c (1 − cos θ_r), the centroid's drop from release to hanging"});
        scene.addDerivedValue({spec.name + ".fall_energy", W * (1 - std::cos(tr)), "J",
                               "m |g| r_c (1 − cos θ_r), the energy of the fall"});
        scene.addDerivedValue({spec.name + ".safe_angle_torque", W * std::sin(ts), "N*m",
                               "m |g| r_c sin θ_s, the moment at the protection's trip angle"});
        scene.note("frozen charge " + spec.name,
                   tr > ts ? "breaks loose at " + formatNumber(tr * 180 / M_PI) + " deg, past the safe angle " +
                                 formatNumber(ts * 180 / M_PI) +
                                 " deg: frozen-charge protection must trip the drive at the safe angle "
                                 "(still packed there)"
                           : "breaks loose at " + formatNumber(tr * 180 / M_PI) + " deg, within the safe angle " +
                                 formatNumber(ts * 180 / M_PI) + " deg");
    }
    scene.note(p.motion == ChargeMotionMode::WithDrum
                   ? "charge " + spec.name + " (SegmentCharge, with_drum) folded into " + drum.name
               : p.motion == ChargeMotionMode::TorqueArm || frozen
                   ? "charge " + spec.name + " (SegmentCharge, " + motion + ") on " + drum.name + ", no body"
                   : "body " + spec.name + " (SegmentCharge, " + motion + ")",
               "charge of " + drum.name + ": " + std::to_string(m) + " kg, centroid " + std::to_string(lc) +
                   " m from the axis, half-angle " + std::to_string(p.halfAngle * 180 / M_PI) + " deg" +
                   (p.motion == ChargeMotionMode::WithDrum ? std::string() : std::string(", lag ") + convention) +
                   (p.motion == ChargeMotionMode::WithDrum
                        ? "; turns with its drum, so its mass is the drum's (no body of its own)"
                    : p.motion == ChargeMotionMode::TorqueArm
                        ? "; mass and axis inertia added to the shell, weight's moment m g r_c sin(lag) as a couple"
                        : ""));
}

}  // namespace

void registerSegmentCharge(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "SegmentCharge";
    s.needsGravity = true;
    // What a motion needs of the analysis (checked by the dispatch and the transient).
    using Need = ElementSchema::AnalysisNeed;
    s.analysisNeeds = {
        {"motion", "held", Need::Kind::EachInstant, "a held charge's wall torque is solved at each instant",
         "motion: with_drum or dynamic_lag"},
        {"motion", "frozen", Need::Kind::StepHistory, "the release is carried from step to step", "another motion"},
    };
    s.initialStateKeys = {{"initial_speed_fraction", "the drum's speed"}};
    s.doc = "Grinding charge as a circular segment in a drum (rigid with it, held at a lag, dragged, or a torque arm).";
    s.params = {
        P::body("drum", "drum (on a pin on its carrier, or on ground) holding the charge"),
        P::quantity("drum_radius", "m", "r: inner radius of the drum").above(0),
        P::quantity("length", "m", "l: inner length of the drum").above(0),
        P::quantity("bulk_density", "kg/m^3", "ρ: bulk density of balls, material and voids").above(0),
        P::quantity("fill", "1", "fill fraction of the cross-section (50 % = half disc)").optional(0.5).above(0).atMost(1),
        P::quantity("half_angle", "rad", "γ: segment half-angle (overrides fill)").optional(M_PI / 2).above(0).atMost(M_PI),
        P::choice("motion", {"with_drum", "held", "dynamic_lag", "torque_arm", "frozen"}, "how the charge moves")
            .optional(std::string("with_drum")),
        P::choice("lag_from", {"auto", "vertical", "carrier_radius"},
                  "what the lag is measured from (auto: vertical on a fixed axis, carrier_radius on a carrier)")
            .optional(std::string("auto")),
        P::quantity("lag", "rad", "α held (motion: held, torque_arm)").optional(0.0).atLeast(-M_PI).atMost(M_PI),
        P::quantityList("lag_table_speed", "1", 2, 100, "torque_arm: fractions of critical speed, increasing")
            .optional(0.0).atLeast(0),
        P::quantityList("lag_table_lag", "rad", 2, 100, "torque_arm: lag at each lag_table_speed")
            .optional(0.0).atLeast(-M_PI).atMost(M_PI),
        P::quantity("smoothing_speed", "rad/s", "torque_arm: ω_ε of lag·tanh(ω/ω_ε) (default 2 % of ω_c)")
            .optional(0.0).above(0),
        P::quantity("initial_direction", "rad", "direction of B→c from +x at t = 0").optional(-M_PI / 2),
        P::quantity("initial_lag", "rad", "dynamic_lag, frozen: lag at t = 0, in the lag_from convention")
            .optional(0.0).atLeast(-M_PI).atMost(M_PI),
        P::choice("power_law", {"lag", "bond", "morrell_c"},
                  "torque_arm: what sets the load: the lag (or lag table), Bond's ball-mill power equation, "
                  "Morrell's C-model net power")
            .optional(std::string("lag")),
        P::quantity("ball_size_factor", "W/kg", "power_law bond: S_s, Bond's ball-size term (kW per tonne of balls)")
            .optional(0.0),
        P::quantity("start_speed_fraction", "1",
                    "power_law bond, morrell_c: below this fraction of critical speed the torque is held at its value "
                    "there")
            .optional(0.5).above(0).atMost(1),
        P::quantity("initial_speed_fraction", "1",
                    "torque_arm, frozen: the drum's speed at t = 0 as a fraction of critical speed (initial_state: "
                    "file; overrides the drum's initial_speed)")
            .optional(0.0).atLeast(-3).atMost(3),
        P::quantity("release_angle", "rad", "frozen: lag of the packed block at which it breaks loose and falls")
            .optional(0.0).above(0).below(M_PI),
        P::quantity("safe_angle", "rad",
                    "frozen: the protection's trip angle, the lag past which a packed charge must have fallen")
            .optional(0.0).above(0).below(M_PI),
        P::quantity("wall_drag", "N*m*s/rad", "c_w of the wall drag (motion: dynamic_lag)").optional(0.0).atLeast(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const std::string& motion = e.text("motion");
        if (motion == "dynamic_lag" && !(e.number("wall_drag") > 0))
            throw e.error("wall_drag", "motion: dynamic_lag needs a wall_drag > 0 N*m*s/rad");
        if (e.params.at("initial_lag").given && e.params.at("initial_direction").given)
            throw e.error("initial_lag", "give initial_lag or initial_direction, not both");
        if (motion == "frozen")
            for (const char* key : {"release_angle", "safe_angle"})
                if (!e.params.at(key).given) throw e.error("motion", std::string("frozen needs ") + key);
        if (motion == "frozen" && e.params.at("initial_lag").given &&
            !(e.number("initial_lag") < e.number("release_angle")))
            throw e.error("initial_lag", "must be below release_angle");
        const std::string& law = e.text("power_law");
        if (motion == "torque_arm" && law != "lag") {
            for (const char* key : {"lag", "lag_table_speed", "lag_table_lag"})
                if (e.params.at(key).given)
                    throw e.error(key, std::string("not used with power_law: ") + law + " (the correlation sets the load)");
        }
        if (motion == "torque_arm" && law == "lag") {
            for (const char* key : {"ball_size_factor", "start_speed_fraction"})
                if (e.params.at(key).given)
                    throw e.error(key, "used only with power_law: bond or morrell_c");
        }
        if (e.params.at("ball_size_factor").given && law != "bond")
            throw e.error("ball_size_factor", "used only with power_law: bond");
        // The lag laws hold the charge between hanging (0) and level with
        // the axis (90°), in the turning sense (a shell turning −z mirrors it).
        if (motion == "torque_arm" && law == "lag") {
            auto outside = [](double a) { return !(a >= 0 && a <= M_PI / 2); };
            if (e.params.at("lag").given && outside(e.number("lag")))
                throw e.error("lag", "must be in [0, 90] deg (from the downward vertical, in the turning sense), got " +
                                         formatNumber(e.number("lag") * 180 / M_PI) + " deg");
            if (e.params.at("lag_table_lag").given)
                for (double a : e.numbers("lag_table_lag"))
                    if (outside(a))
                        throw e.error("lag_table_lag", "every entry must be in [0, 90] deg, got " +
                                                           formatNumber(a * 180 / M_PI) + " deg");
        }
        const bool speeds = e.params.at("lag_table_speed").given, lags = e.params.at("lag_table_lag").given;
        if (speeds != lags)
            throw e.error(speeds ? "lag_table_speed" : "lag_table_lag",
                          "lag_table_speed and lag_table_lag go together");
        if (speeds) {
            if (e.params.at("lag").given) throw e.error("lag", "give lag or the lag table, not both");
            const auto& x = e.numbers("lag_table_speed");
            if (x.size() != e.numbers("lag_table_lag").size())
                throw e.error("lag_table_lag", "needs as many entries as lag_table_speed (" +
                                                   std::to_string(x.size()) + ")");
            for (std::size_t i = 1; i < x.size(); ++i)
                if (!(x[i] > x[i - 1])) throw e.error("lag_table_speed", "must increase strictly");
        }
    };
    registry.add({std::move(s), buildSegmentCharge});
}

}  // namespace milldyn
