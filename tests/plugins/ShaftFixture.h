#pragma once
// Shared by the element tests: a MultibodySystem of pin-jointed shafts turning
// about z, and the few measurements the tests take on it. Each shaft is a thin
// disc Inertia(J/2, J/2, J) with 1 kg on its axis and no gravity acts, so its
// equation of motion is J·u̇ = (sum of mobility torques on it), whatever the
// mass: the tests rely on that to turn accelerations into torques.

#include "plugins/scene/ElementRegistry.h"

#include <Simbody.h>

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn::test {

// On the axis, the mass only has to be > 0 for Simbody to accept the body.
constexpr double kShaftMass = 1.0;  // kg

// The accuracy the brief fixes for trajectory tests: RungeKuttaMerson's local
// error is held near 1e-9 relative, so conserved quantities drift by ~1e-9
// per characteristic time.
constexpr double kIntegratorAccuracy = 1e-9;

class ShaftSystem {
public:
    ShaftSystem() : m_matter(m_system), m_forces(m_system) {}
    ShaftSystem(const ShaftSystem&) = delete;
    ShaftSystem& operator=(const ShaftSystem&) = delete;

    /// A shaft on a pin to ground about z, polar moment J [kg*m^2].
    SimTK::MobilizedBody::Pin addShaft(double polarInertia) {
        const double J = polarInertia;
        const SimTK::Body::Rigid body(
            SimTK::MassProperties(kShaftMass, SimTK::Vec3(0), SimTK::Inertia(J / 2, J / 2, J)));
        return SimTK::MobilizedBody::Pin(m_matter.updGround(), SimTK::Transform(), body,
                                         SimTK::Transform());
    }

    SimTK::MultibodySystem& system() { return m_system; }
    SimTK::SimbodyMatterSubsystem& matter() { return m_matter; }
    SimTK::GeneralForceSubsystem& forces() { return m_forces; }

    /// Closes the topology (call after the last force) and returns the
    /// default state: every angle and speed 0, every element's default
    /// discrete state.
    SimTK::State defaultState() {
        m_system.realizeTopology();
        return m_system.getDefaultState();
    }

private:
    SimTK::MultibodySystem m_system;
    SimTK::SimbodyMatterSubsystem m_matter;
    SimTK::GeneralForceSubsystem m_forces;
};

inline void setShaft(SimTK::State& state, const SimTK::MobilizedBody& shaft, double angle,
                     double speed) {
    shaft.setOneQ(state, SimTK::MobilizerQIndex(0), angle);
    shaft.setOneU(state, SimTK::MobilizerUIndex(0), speed);
}

inline double shaftSpeed(const SimTK::State& state, const SimTK::MobilizedBody& shaft) {
    return shaft.getOneU(state, SimTK::MobilizerUIndex(0));
}

/// The mobility torque that this one force element applies to `shaft`
/// [N*m]; Force::calcForceContribution keeps every other element out.
inline double torqueOn(const SimTK::MultibodySystem& system, const SimTK::Force& force,
                       const SimTK::State& state, const SimTK::MobilizedBody& shaft) {
    system.realize(state, SimTK::Stage::Velocity);
    SimTK::Vector_<SimTK::SpatialVec> bodyForces;
    SimTK::Vector_<SimTK::Vec3> particleForces;
    SimTK::Vector mobilityForces;
    force.calcForceContribution(state, bodyForces, particleForces, mobilityForces);
    return shaft.getOneFromUPartition(state, 0, mobilityForces);
}

/// u̇ of `shaft` with every force of the system acting [rad/s^2].
inline double shaftAcceleration(const SimTK::MultibodySystem& system, const SimTK::State& state,
                                const SimTK::MobilizedBody& shaft) {
    system.realize(state, SimTK::Stage::Acceleration);
    return shaft.getOneUDot(state, SimTK::MobilizerUIndex(0));
}

/// z component of the system's angular momentum about the ground origin
/// [kg*m^2/s], from Simbody's own mass-properties bookkeeping.
inline double angularMomentumZ(const SimTK::MultibodySystem& system, const SimTK::State& state) {
    system.realize(state, SimTK::Stage::Velocity);
    return system.getMatterSubsystem().calcSystemMomentumAboutGroundOrigin(state)[0][2];
}

using StateFunction = std::function<double(const SimTK::State&)>;

/**
 * Integrates `initial` to `endTime` with RungeKuttaMerson at
 * kIntegratorAccuracy, ending a step exactly on each of `intervals` equal
 * sub-intervals (no interpolation, so every sample has the integrator's full
 * accuracy), and integrates each integrand along the way by composite
 * Simpson. `onSample(state, runningIntegrals)` is called at the start and at
 * the end of every Simpson pair, where the running integrals are complete.
 * Integrands and onSample see states realized to Acceleration.
 * Returns the final state; `integrals` receives the integrals over the run.
 */
inline SimTK::State integrateWithQuadrature(
    const SimTK::MultibodySystem& system, const SimTK::State& initial, double endTime,
    int intervals, const std::vector<StateFunction>& integrands, std::vector<double>& integrals,
    const std::function<void(const SimTK::State&, const std::vector<double>&)>& onSample = {}) {
    if (intervals <= 0 || intervals % 2 != 0)
        throw std::invalid_argument("integrateWithQuadrature: intervals must be even and > 0");
    SimTK::RungeKuttaMersonIntegrator integ(system);
    integ.setAccuracy(kIntegratorAccuracy);
    integ.setAllowInterpolation(false);
    integ.initialize(initial);

    const double t0 = integ.getTime();
    const double h = (endTime - t0) / intervals;
    auto sample = [&](std::vector<double>& values) {
        const SimTK::State& s = integ.getState();
        system.realize(s, SimTK::Stage::Acceleration);
        values.resize(integrands.size());
        for (std::size_t i = 0; i < integrands.size(); ++i) values[i] = integrands[i](s);
    };

    // stepTo() also returns at the start of a continuous interval and on
    // internal events; only ReachedReportTime means the sample is there.
    auto advanceTo = [&](double t) {
        for (int tries = 0; tries < 1000; ++tries)
            if (integ.stepTo(t) == SimTK::Integrator::ReachedReportTime) break;
        EXPECT_EQ(integ.getTime(), t) << "integrator did not land on the sample";
    };

    integrals.assign(integrands.size(), 0.0);
    std::vector<double> f0, f1, f2;
    sample(f0);
    if (onSample) onSample(integ.getState(), integrals);
    for (int k = 2; k <= intervals; k += 2) {
        advanceTo(t0 + (k - 1) * h);
        sample(f1);
        advanceTo(t0 + k * h);
        sample(f2);
        for (std::size_t i = 0; i < integrands.size(); ++i)
            integrals[i] += h / 3 * (f0[i] + 4 * f1[i] + f2[i]);
        if (onSample) onSample(integ.getState(), integrals);
        f0.swap(f2);
    }
    return integ.getState();
}

/// Runs `make` and checks it throws std::invalid_argument whose what()
/// contains `parameter`.
template <class Make>
void expectInvalidArgumentNaming(const std::string& parameter, Make&& make) {
    try {
        make();
        ADD_FAILURE() << "no std::invalid_argument for " << parameter;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos)
            << "message does not name " << parameter << ": " << e.what();
    }
}

/// One force element on one shaft of inertia J [kg*m^2], with a state to
/// set speeds in: the fixture of the single-shaft element tests.
template <class Element, class Params>
struct ElementOnShaft {
    ElementOnShaft(const Params& p, double J)
        : shaft(rig.addShaft(J)),
          element(new Element(rig.forces(), shaft, p)),
          force(rig.forces(), element),
          state(rig.defaultState()) {}

    /// The mobility torque the element applies to the shaft at speed ω.
    double torqueAt(double omega) {
        setShaft(state, shaft, 0.0, omega);
        return torqueOn(rig.system(), force, state, shaft);
    }

    ShaftSystem rig;
    SimTK::MobilizedBody::Pin shaft;
    Element* element;  // owned by force
    SimTK::Force::Custom force;
    SimTK::State state;
};

// ---- element specs as the model-file reader hands them over ---------------

inline ParamValue number(double v) {
    ParamValue p;
    p.number = v;
    p.given = true;
    return p;
}

inline ParamValue word(const std::string& w) {
    ParamValue p;
    p.text = w;
    p.given = true;
    return p;
}

inline ParamValue names(const std::vector<std::string>& n) {
    ParamValue p;
    p.names = n;
    p.given = true;
    return p;
}

inline ParamValue numbers(const std::vector<double>& v) {
    ParamValue p;
    p.numbers = v;
    p.given = true;
    return p;
}

/// A registered element type; throws if it is missing.
inline const ElementType& registeredType(const std::string& type) {
    const ElementType* t = ElementRegistry::instance().find(type);
    if (!t) throw std::runtime_error(type + " is not registered");
    return *t;
}

}  // namespace milldyn::test
