// Tests of TorsionalCoupling (plugins/transmissions/TorsionalCoupling.h). Expected values
// are worked out by hand in the comments from the class comment's equations,
// or come from Simbody's own elements and bookkeeping -- never from the
// coupling's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "plugins/scene/ElementRegistry.h"
#include "plugins/transmissions/TorsionalCoupling.h"
#include "tests/plugins/ShaftFixture.h"

namespace milldyn {
namespace {

using test::ShaftSystem;
using test::number;

// Seed 003's belt, typed in from the paper: J1 motor side, J2 millstone,
// c and b of the belt, u_p = 3.12.
constexpr double kJFrom = 190.7e-4;  // kg*m^2
constexpr double kJTo = 982.4e-4;    // kg*m^2
constexpr double kC = 537.0;         // N*m/rad
constexpr double kB = 0.293;         // N*m*s/rad
constexpr double kRatio = 3.12;

// A softer rig for trajectories: the twist mode has
// w^2 = c (1/J1 + n^2/J2) = 2 (50 + 97.33) = 294.7, w = 17.2 rad/s, so
// 2000 Simpson intervals over 1 s resolve the power (frequency 2w) to
// (2w h)^4/180 ~ 5e-10 of the energy.
constexpr double kSoftJFrom = 0.02;  // kg*m^2
constexpr double kSoftJTo = 0.1;     // kg*m^2
constexpr double kSoftC = 2.0;       // N*m/rad
constexpr double kSoftB = 0.01;      // N*m*s/rad, energy decays ~ e^(-1.5 t)
constexpr double kTrajectoryEnd = 1.0;  // s
constexpr int kTrajectoryIntervals = 2000;

// One closed form evaluated in double against the element's few
// multiply-adds: a few ulps of torques ~1e2 N*m.
constexpr double kRoundingRelTolerance = 1e-12;
// Two accelerations from Simbody's O(n) solve of the same torques: ulps.
constexpr double kSolverRelTolerance = 1e-12;
// Energy balance along a run, relative to E0: the integrator's local
// accuracy (1e-9) bounds the drift; seen here ~2e-11 (the 0.5 ms sample grid
// keeps steps short) plus the ~5e-10 quadrature bound. A power-balance
// defect (wrong ratio sign, PE not ½cΔ²) gives O(1) errors.
constexpr double kEnergyRelTolerance = 1e-9;
// Σ J·u is a linear invariant, which every Runge-Kutta method conserves up
// to rounding (seen 1e-15).
constexpr double kMomentumRelTolerance = 1e-12;

TorsionalCouplingParams params(double c, double b, double n) {
    TorsionalCouplingParams p;
    p.stiffness = c;
    p.damping = b;
    p.ratio = n;
    return p;
}

// Two shafts, "from" and "to", joined by one coupling.
struct CoupledShafts {
    explicit CoupledShafts(const TorsionalCouplingParams& p, double jFrom = kJFrom,
                           double jTo = kJTo)
        : from(rig.addShaft(jFrom)),
          to(rig.addShaft(jTo)),
          coupling(new TorsionalCoupling(from, to, p)),
          force(rig.forces(), coupling),
          state(rig.defaultState()) {}

    void set(double qFrom, double qTo, double uFrom, double uTo) {
        test::setShaft(state, from, qFrom, uFrom);
        test::setShaft(state, to, qTo, uTo);
    }
    double torqueOnFrom() { return test::torqueOn(rig.system(), force, state, from); }
    double torqueOnTo() { return test::torqueOn(rig.system(), force, state, to); }

    ShaftSystem rig;
    SimTK::MobilizedBody::Pin from;
    SimTK::MobilizedBody::Pin to;
    TorsionalCoupling* coupling;  // owned by force
    SimTK::Force::Custom force;
    SimTK::State state;
};

// ---- 1. force vs closed form ------------------------------------------------

TEST(TorsionalCouplingTest, TorquesAreMinusTOnFromAndPlusNTOnTo) {
    CoupledShafts rig(params(kC, kB, kRatio));
    rig.set(0.3, 0.05, 10.0, 2.0);
    // Δ = 0.3 − 3.12·0.05 = 0.144 rad, Δ̇ = 10 − 3.12·2 = 3.76 rad/s,
    // T = 537·0.144 + 0.293·3.76 = 77.328 + 1.10168 = 78.42968 N*m,
    // n·T = 3.12·78.42968 = 244.7006016 N*m.
    const double T = 78.42968;
    EXPECT_NEAR(rig.torqueOnFrom(), -T, kRoundingRelTolerance * T);
    EXPECT_NEAR(rig.torqueOnTo(), 244.7006016, kRoundingRelTolerance * 244.7);
}

TEST(TorsionalCouplingTest, PotentialEnergyIsHalfStiffnessTimesTwistSquared) {
    CoupledShafts rig(params(kC, kB, kRatio));
    rig.set(0.3, 0.05, 10.0, 2.0);
    rig.rig.system().realize(rig.state, SimTK::Stage::Dynamics);
    // V = ½·537·0.144² = ½·537·0.020736 = 5.567616 J; the damper stores none.
    EXPECT_NEAR(rig.rig.system().calcPotentialEnergy(rig.state), 5.567616,
                kRoundingRelTolerance * 5.57);
}

TEST(TorsionalCouplingTest, SteadyRunningAtSpeedRatioTransmitsNoTorque) {
    CoupledShafts rig(params(kC, kB, kRatio));
    // q_from = n·q_to and ω_from = n·ω_to: no twist, no twist rate, T = 0
    // exactly (the same product is formed on both sides).
    const double qTo = 0.5, wTo = 50.0;
    rig.set(kRatio * qTo, qTo, kRatio * wTo, wTo);
    EXPECT_EQ(rig.torqueOnFrom(), 0.0);
    EXPECT_EQ(rig.torqueOnTo(), 0.0);
}

TEST(TorsionalCouplingTest, TwistRateAloneGivesDampingTorque) {
    CoupledShafts rig(params(kC, kB, 1.0));
    // Same angles, ω_from − ω_to = 4 rad/s: T = 0.293·4 = 1.172 N*m.
    rig.set(0.7, 0.7, 12.0, 8.0);
    EXPECT_NEAR(rig.torqueOnFrom(), -1.172, kRoundingRelTolerance * 1.172);
    EXPECT_NEAR(rig.torqueOnTo(), 1.172, kRoundingRelTolerance * 1.172);
}

// ---- 2. action = reaction ---------------------------------------------------

TEST(TorsionalCouplingTest, ToShaftTorqueIsMinusRatioTimesFromShaftTorque) {
    CoupledShafts rig(params(kC, kB, kRatio));
    const double states[][4] = {
        {0.3, 0.05, 10.0, 2.0}, {-1.2, 0.4, -3.0, 7.0}, {5.0, 1.0, 150.0, 48.0}, {0, 0, 0, 0}};
    for (const auto& s : states) {
        rig.set(s[0], s[1], s[2], s[3]);
        const double onFrom = rig.torqueOnFrom();
        EXPECT_NEAR(rig.torqueOnTo(), -kRatio * onFrom, kRoundingRelTolerance * (1 + std::abs(onFrom)))
            << "state " << s[0] << ' ' << s[1] << ' ' << s[2] << ' ' << s[3];
    }
}

TEST(TorsionalCouplingTest, AccelerationsObeyJToUdotToEqualsMinusNJFromUdotFrom) {
    CoupledShafts rig(params(kC, kB, kRatio));
    rig.set(-0.4, 0.2, 3.0, -1.0);
    const double aFrom = test::shaftAcceleration(rig.rig.system(), rig.state, rig.from);
    const double aTo = test::shaftAcceleration(rig.rig.system(), rig.state, rig.to);
    // Δ = −0.4 − 0.624 = −1.024, Δ̇ = 3 + 3.12 = 6.12,
    // T = 537·(−1.024) + 0.293·6.12 = −549.888 + 1.79316 = −548.09484 N*m.
    const double T = -548.09484;
    EXPECT_NEAR(kJFrom * aFrom, -T, kSolverRelTolerance * 548.1);
    EXPECT_NEAR(kJTo * aTo, kRatio * T, kSolverRelTolerance * 3.12 * 548.1);
}

// With n ≠ 1 the shafts' angular momentum is not conserved: the housing of
// the reducer (ground, not modelled) takes −(n−1)·T. Only n = 1 is a pure
// internal torque.
TEST(TorsionalCouplingTest, WithRatioGroundTakesNMinusOneTimesTransmittedTorque) {
    CoupledShafts rig(params(kC, kB, kRatio));
    rig.set(-0.4, 0.2, 3.0, -1.0);
    const double aFrom = test::shaftAcceleration(rig.rig.system(), rig.state, rig.from);
    const double aTo = test::shaftAcceleration(rig.rig.system(), rig.state, rig.to);
    const double T = -548.09484;  // as in the test above
    EXPECT_NEAR(kJFrom * aFrom + kJTo * aTo, (kRatio - 1) * T, kSolverRelTolerance * 3.12 * 548.1);
}

TEST(TorsionalCouplingTest, WithUnitRatioTotalAngularMomentumIsConservedAlongTrajectory) {
    CoupledShafts rig(params(kSoftC, kSoftB, 1.0), kSoftJFrom, kSoftJTo);
    // ω_to = −1 would give H = 0.02·5 − 0.1·1 = 0 and hide a sign error.
    rig.set(0.1, 0.0, 5.0, 2.0);
    const double H0 = test::angularMomentumZ(rig.rig.system(), rig.state);
    EXPECT_NEAR(H0, kSoftJFrom * 5.0 + kSoftJTo * 2.0, kRoundingRelTolerance * 0.3);
    double maxDrift = 0;
    std::vector<double> none;
    test::integrateWithQuadrature(
        rig.rig.system(), rig.state, kTrajectoryEnd, kTrajectoryIntervals, {}, none,
        [&](const SimTK::State& s, const std::vector<double>&) {
            maxDrift = std::max(maxDrift, std::abs(test::angularMomentumZ(rig.rig.system(), s) - H0));
        });
    EXPECT_LT(maxDrift, kMomentumRelTolerance * std::abs(H0));
}

// ---- 3. energy balance along a trajectory -----------------------------------

struct EnergyRun {
    double initialEnergy = 0;
    double maxImbalance = 0;  // max |KE + PE + dissipated − E0| over samples
    double dissipated = 0;
};

EnergyRun runEnergyBalance(double b, double n) {
    CoupledShafts rig(params(kSoftC, b, n), kSoftJFrom, kSoftJTo);
    rig.set(0.1, 0.0, 5.0, -1.0);
    SimTK::MultibodySystem& system = rig.rig.system();
    auto energy = [&system](const SimTK::State& s) {
        system.realize(s, SimTK::Stage::Dynamics);
        return system.calcKineticEnergy(s) + system.calcPotentialEnergy(s);
    };
    // Damper power from the shaft speeds, not from the element: b·Δ̇².
    const SimTK::MobilizedBody from = rig.from, to = rig.to;
    auto dissipation = [b, n, from, to](const SimTK::State& s) {
        const double twistRate = test::shaftSpeed(s, from) - n * test::shaftSpeed(s, to);
        return b * twistRate * twistRate;
    };
    EnergyRun run;
    run.initialEnergy = energy(rig.state);
    std::vector<double> integrals;
    test::integrateWithQuadrature(
        system, rig.state, kTrajectoryEnd, kTrajectoryIntervals, {dissipation}, integrals,
        [&](const SimTK::State& s, const std::vector<double>& running) {
            run.maxImbalance = std::max(
                run.maxImbalance, std::abs(energy(s) + running[0] - run.initialEnergy));
        });
    run.dissipated = integrals[0];
    return run;
}

TEST(TorsionalCouplingTest, DampedEnergyPlusDissipationStaysConstantAlongTrajectory) {
    const EnergyRun run = runEnergyBalance(kSoftB, kRatio);
    // E0 = ½·0.02·25 + ½·0.1·1 + ½·2·0.01 = 0.25 + 0.05 + 0.01 = 0.31 J.
    EXPECT_NEAR(run.initialEnergy, 0.31, kRoundingRelTolerance * 0.31);
    // The damper must have taken a sizeable share, else the test is idle.
    EXPECT_GT(run.dissipated, 0.1 * run.initialEnergy);
    EXPECT_LT(run.maxImbalance, kEnergyRelTolerance * run.initialEnergy);
}

TEST(TorsionalCouplingTest, UndampedEnergyIsConservedAlongTrajectory) {
    const EnergyRun run = runEnergyBalance(0.0, kRatio);
    EXPECT_EQ(run.dissipated, 0.0);
    EXPECT_LT(run.maxImbalance, kEnergyRelTolerance * run.initialEnergy);
}

// ---- 4. reduces to Simbody's built-ins --------------------------------------

// With n = 1 and the to-shaft held still at angle q_to, the coupling is a
// spring c about q0 = q_to plus a damper b on the from-shaft:
// Force::MobilityLinearSpring(c, q_to) + Force::MobilityLinearDamper(b).
TEST(TorsionalCouplingTest, WithUnitRatioAndLockedToShaftMatchesMobilityLinearSpringAndDamper) {
    const double qLocked = 0.3;  // rad

    CoupledShafts coupled(params(kC, kB, 1.0));
    // Added after the rig closed its topology, so take a new default state.
    const SimTK::Motion::Steady lock(coupled.to, 0.0);
    coupled.state = coupled.rig.defaultState();

    ShaftSystem reference;
    SimTK::MobilizedBody::Pin alone = reference.addShaft(kJFrom);
    const SimTK::Force::MobilityLinearSpring spring(reference.forces(), alone,
                                                    SimTK::MobilizerQIndex(0), kC, qLocked);
    const SimTK::Force::MobilityLinearDamper damper(reference.forces(), alone,
                                                    SimTK::MobilizerUIndex(0), kB);
    SimTK::State refState = reference.defaultState();

    for (double q : {-1.0, 0.0, 0.3, 0.31, 2.5}) {
        for (double u : {-20.0, 0.0, 0.5, 157.0}) {
            coupled.set(q, qLocked, u, 0.0);
            test::setShaft(refState, alone, q, u);
            const double expected = test::shaftAcceleration(reference.system(), refState, alone);
            EXPECT_NEAR(test::shaftAcceleration(coupled.rig.system(), coupled.state, coupled.from),
                        expected, kSolverRelTolerance * (1 + std::abs(expected)))
                << "q = " << q << ", u = " << u;
            coupled.rig.system().realize(coupled.state, SimTK::Stage::Dynamics);
            reference.system().realize(refState, SimTK::Stage::Dynamics);
            EXPECT_NEAR(coupled.rig.system().calcPotentialEnergy(coupled.state),
                        reference.system().calcPotentialEnergy(refState),
                        kRoundingRelTolerance * (1 + reference.system().calcPotentialEnergy(refState)));
        }
    }
    // The lock must have held the to-shaft, or the comparison meant nothing.
    EXPECT_EQ(test::shaftAcceleration(coupled.rig.system(), coupled.state, coupled.to), 0.0);
}

// ---- 5. bad parameters ------------------------------------------------------

void expectRejected(const TorsionalCouplingParams& p, const std::string& parameter) {
    ShaftSystem rig;
    const SimTK::MobilizedBody::Pin a = rig.addShaft(kJFrom), b = rig.addShaft(kJTo);
    test::expectInvalidArgumentNaming(parameter,
                                      [&] { (void)std::make_unique<TorsionalCoupling>(a, b, p); });
}

TEST(TorsionalCouplingTest, NegativeStiffnessThrowsNamingStiffness) {
    expectRejected(params(-1.0, kB, kRatio), "stiffness");
}

TEST(TorsionalCouplingTest, NegativeDampingThrowsNamingDamping) {
    expectRejected(params(kC, -0.1, kRatio), "damping");
}

TEST(TorsionalCouplingTest, NonPositiveRatioThrowsNamingRatio) {
    expectRejected(params(kC, kB, 0.0), "ratio");
    expectRejected(params(kC, kB, -3.12), "ratio");
}

TEST(TorsionalCouplingTest, NonFiniteParametersThrowNamingTheParameter) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double bad : {inf, nan}) {
        expectRejected(params(bad, kB, kRatio), "stiffness");
        expectRejected(params(kC, bad, kRatio), "damping");
        expectRejected(params(kC, kB, bad), "ratio");
    }
}

TEST(TorsionalCouplingTest, SameShaftAtBothEndsThrowsNamingBodies) {
    ShaftSystem rig;
    const SimTK::MobilizedBody::Pin a = rig.addShaft(kJFrom);
    test::expectInvalidArgumentNaming(
        "bodies", [&] { (void)std::make_unique<TorsionalCoupling>(a, a, params(kC, kB, 1.0)); });
}

TEST(TorsionalCouplingTest, ZeroStiffnessAndDampingAreAccepted) {
    ShaftSystem rig;
    const SimTK::MobilizedBody::Pin a = rig.addShaft(kJFrom), b = rig.addShaft(kJTo);
    EXPECT_NO_THROW(std::make_unique<TorsionalCoupling>(a, b, params(0.0, 0.0, 1.0)));
}

// ---- 6. registry -----------------------------------------------------------


ElementSpec couplingSpec(const std::string& from, const std::string& to) {
    ElementSpec e;
    e.type = "TorsionalCoupling";
    e.name = "belt";
    ParamValue bodies;
    bodies.names = {from, to};
    bodies.given = true;
    e.params["bodies"] = bodies;
    e.params["stiffness"] = number(kC);
    e.params["damping"] = number(kB);
    e.params["ratio"] = number(kRatio);
    return e;
}

TEST(TorsionalCouplingRegistryTest, SchemaListsTheDocumentedKeys) {
    const ElementType* type = ElementRegistry::instance().find("TorsionalCoupling");
    ASSERT_NE(type, nullptr);
    std::set<std::string> keys;
    for (const auto& p : type->schema.params) keys.insert(p.key);
    EXPECT_EQ(keys, (std::set<std::string>{"bodies", "stiffness", "damping", "ratio"}));
    EXPECT_EQ(type->schema.find("bodies")->kind, ParamKind::BodyPair);
    EXPECT_EQ(type->schema.find("stiffness")->unit, "N*m/rad");
    EXPECT_TRUE(type->schema.find("stiffness")->required);
    EXPECT_EQ(type->schema.find("damping")->unit, "N*m*s/rad");
    EXPECT_EQ(type->schema.find("ratio")->defaultValue, 1.0);
}

TEST(TorsionalCouplingRegistryTest, CrossCheckRejectsSameBodyTwiceNamingBodies) {
    const ElementType* type = ElementRegistry::instance().find("TorsionalCoupling");
    ASSERT_NE(type, nullptr);
    ASSERT_TRUE(type->schema.crossCheck);
    EXPECT_NO_THROW(type->schema.crossCheck(couplingSpec("motor_shaft", "millstone")));
    try {
        type->schema.crossCheck(couplingSpec("motor_shaft", "motor_shaft"));
        ADD_FAILURE() << "no SpecError for the same body twice";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "belt.bodies");
    }
}

TEST(TorsionalCouplingRegistryTest, BuiltCouplingAppliesTheClosedFormTorque) {
    const ElementType* type = ElementRegistry::instance().find("TorsionalCoupling");
    ASSERT_NE(type, nullptr);
    Scene scene;
    const SimTK::Body::Rigid body(SimTK::MassProperties(1, SimTK::Vec3(0),
                                                        SimTK::Inertia(kJFrom / 2, kJFrom / 2, kJFrom)));
    SimTK::MobilizedBody::Pin a(scene.matter().updGround(), SimTK::Transform(), body, SimTK::Transform());
    SimTK::MobilizedBody::Pin b(scene.matter().updGround(), SimTK::Transform(), body, SimTK::Transform());
    scene.addBody("motor_shaft", a);
    scene.addBody("millstone", b);
    type->build(couplingSpec("motor_shaft", "millstone"), scene);
    scene.system().realizeTopology();
    SimTK::State state = scene.system().getDefaultState();
    test::setShaft(state, a, 0.3, 10.0);
    test::setShaft(state, b, 0.05, 2.0);
    const SimTK::Force& force = scene.forces().getForce(scene.findForce("belt"));
    // Same state as TorquesAreMinusTOnFromAndPlusNTOnTo: T = 78.42968 N*m.
    EXPECT_NEAR(test::torqueOn(scene.system(), force, state, a), -78.42968, kRoundingRelTolerance * 78.4);
    EXPECT_NEAR(test::torqueOn(scene.system(), force, state, b), 244.7006016, kRoundingRelTolerance * 244.7);
}

}  // namespace
}  // namespace milldyn
