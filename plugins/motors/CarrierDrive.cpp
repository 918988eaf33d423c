#include "plugins/motors/CarrierDrive.h"

#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace milldyn {

using namespace SimTK;

CarrierDrive::CarrierDrive(const CarrierDriveParams& p) : m_p(p) {
    auto bad = [](const std::string& what) { throw std::invalid_argument("CarrierDrive: " + what); };
    if (!(p.steadySpeed >= 0) || !std::isfinite(p.steadySpeed)) bad("steady_speed must be finite and >= 0 rad/s");
    if (!(p.accelerationTime > 0) || !std::isfinite(p.accelerationTime)) bad("acceleration_time must be > 0 s");
    if (!(p.timeConstant > 0) || !std::isfinite(p.timeConstant)) bad("time_constant must be > 0 s");
}

double CarrierDrive::calcInitialAcceleration() const {
    if (!m_p.exponential) return 0;
    return m_p.steadySpeed / (m_p.timeConstant * -std::expm1(-m_p.accelerationTime / m_p.timeConstant));
}

double CarrierDrive::calcAcceleration(double t) const {
    return m_p.exponential ? calcInitialAcceleration() * std::exp(-t / m_p.timeConstant) : 0.0;
}

double CarrierDrive::calcSpeed(double t) const {
    if (!m_p.exponential) return m_p.steadySpeed;
    return calcInitialAcceleration() * m_p.timeConstant * -std::expm1(-t / m_p.timeConstant);
}

std::pair<double, double> CarrierDrive::calcAdvance(double t0, double u0, double t) const {
    if (!m_p.exponential) return {u0 * (t - t0), u0};
    const double e0 = calcInitialAcceleration(), tau = m_p.timeConstant;
    // V is the speed from rest (calcSpeed); expm1 keeps P accurate near
    // t = 0 (no 1 − e^(−t/τ) cancellation).
    auto V = [this](double x) { return calcSpeed(x); };
    auto P = [&](double x) { return e0 * tau * (x + tau * std::expm1(-x / tau)); };
    return {(u0 - V(t0)) * (t - t0) + P(t) - P(t0), u0 + V(t) - V(t0)};
}

void CarrierDrive::calcPrescribedAcceleration(const State& s, int nu, Real* udot) const {
    for (int i = 0; i < nu; ++i) udot[i] = 0;
    if (nu > 0) udot[0] = calcAcceleration(s.getTime());
}

/// Drive torque [N*m] a prescribed motion of `body` needs, at Acceleration.
double calcPrescribedDriveTorque(const State& s, const SimbodyMatterSubsystem& matter, const MobilizedBody& body) {
    Vector motionForces;
    matter.findMotionForces(s, motionForces);
    return -body.getOneFromUPartition(s, 0, motionForces);
}

namespace {

void buildCarrierDrive(const ElementSpec& spec, Scene& scene) {
    const SceneBody* body = scene.findBody(spec.text("body"));
    CarrierDriveParams p;
    p.exponential = spec.text("law") == "exponential";
    p.steadySpeed = spec.number("steady_speed");
    p.accelerationTime = spec.number("acceleration_time");
    p.timeConstant = spec.number("time_constant");
    auto* impl = new CarrierDrive(p);
    MobilizedBody mobod = body->mobod;
    Motion::Custom motion(mobod, impl);
    const SimbodyMatterSubsystem* matter = &scene.matter();
    auto torque = [matter, mobod](const State& s) { return calcPrescribedDriveTorque(s, *matter, mobod); };
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::DriveTorque, Stage::Acceleration, torque});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::Generic, Stage::Acceleration,
                    [torque, mobod](const State& s) { return torque(s) * pinSpeed(s, mobod); }});
    scene.addProbe({spec.name + ".prescribed_acceleration", "rad/s^2", ProbeRole::Generic, Stage::Time,
                    [impl](const State& s) { return impl->calcAcceleration(s.getTime()); }});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Source,
                         [torque, mobod](const State& s) { return torque(s) * pinSpeed(s, mobod); }});
    if (p.exponential)
        scene.addDerivedValue({spec.name + ".initial_acceleration", impl->calcInitialAcceleration(), "rad/s^2",
                               "ε0 = ω_y/(τ (1 − e^(−t_p/τ))) of ε = ε0 e^(−t/τ) (seed 000, Fig. 6; ε0 = ω_y/(1 − "
                               "e^(−t_p)) with the paper's τ = 1 s)"});
    // A prescribed motion cannot be switched off (its body would stop
    // following the law a replay places it by): a coast-down refuses it.
    const std::string name = spec.name;
    scene.addDrive({name, body->name, p.steadySpeed, INFINITY,
                    [name](State&, bool on) {
                        if (!on)
                            throw std::invalid_argument("CarrierDrive " + name +
                                                        " prescribes its body's motion and cannot be switched off "
                                                        "(a coast-down needs a motor)");
                    },
                    "prescribed " + spec.text("law") + " law"});
    scene.addPrescribedTrajectory(
        {body->name, mobod, [impl](double t0, double u0, double t) { return impl->calcAdvance(t0, u0, t); }});
    scene.note("motion " + spec.name + " (CarrierDrive, " + spec.text("law") + ")",
               body->name + " follows the prescribed law; drive torque = −findMotionForces");
}

}  // namespace

void registerCarrierDrive(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "CarrierDrive";
    s.doc = "Prescribed start of a carrier (seed 000: ε = ε0 e^(−t/τ)) or steady speed; torque from Simbody.";
    s.params = {
        P::body("body", "carrier (or shaft) on a pin"),
        P::choice("law", {"exponential", "steady"}, "start law").optional(std::string("exponential")),
        P::quantity("steady_speed", "rad/s", "ω_y reached (exponential) or held (steady)").atLeast(0),
        P::quantity("acceleration_time", "s", "t_p with ω(t_p) = ω_y").optional(1.0).above(0),
        P::quantity("time_constant", "s", "τ of e^(−t/τ); the paper's e^(−t) is 1 s").optional(1.0).above(0),
    };
    registry.add({std::move(s), buildCarrierDrive});
}

}  // namespace milldyn
