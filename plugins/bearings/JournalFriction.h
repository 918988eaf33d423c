#pragma once
// JournalFriction: friction torque in a plain (journal) bearing, driven by
// the reaction the model itself computes in that journal.

#include "plugins/scene/MobilizerReactions.h"
#include "plugins/scene/ElementSchema.h"
#include "plugins/scene/Scene.h"

#include <string>
#include <vector>


namespace milldyn {

/// Where the journal load comes from. The friction torque depends on the
/// reaction, which Simbody knows only after the accelerations (an algebraic
/// loop). Both keep the load in a discrete variable, constant over a step.
enum class ReactionCoupling {
    Lagged,    ///< the reaction at the end of the last step, computed with that step's friction
    Iterated,  ///< at every step's start, iterated until load and reaction agree
    Extrapolated,  ///< linear in time through the reactions at the last two step ends
    FirstOrder,    ///< the reaction with every journal's friction off (seed 000 eq 21, the paper's way)
};

struct JournalFrictionParams {
    double frictionCoefficient = 0;  ///< f [-] in [0, 1]
    double journalDiameter = 0;      ///< d [m] >= 0
    double smoothingSpeed = 1e-3;    ///< ω_s [rad/s] > 0: tanh width at zero relative speed
    ReactionCoupling coupling = ReactionCoupling::Lagged;
    /// At exactly zero relative speed (a start instant), full friction
    /// opposing the relative acceleration the journal would have without
    /// friction (from the applied torques or the prescribed motion), instead
    /// of tanh(0) = 0.
    bool breakaway = false;
};

class JournalFriction;

/// The keys both JournalFriction and ShaftBearings take for the load:
/// `coupling: consistent | first_order` (issue 20 item 1) and `reaction:
/// lagged | iterated | extrapolated`, how the consistent load is obtained
/// (`reaction: first_order` stays accepted as an alias of `coupling:
/// first_order`).
std::vector<ParamSchema> reactionCouplingParams();
/// The coupling those keys choose (`coupling: first_order` leaves
/// `reaction:` unused); throws SpecError at `coupling` when they contradict
/// each other (`coupling: consistent` with `reaction: first_order`).
ReactionCoupling readReactionCoupling(const ElementSpec& spec);
/// "consistent (lagged)", ..., "first_order": the convention in words.
std::string describeReactionCoupling(ReactionCoupling c);
/// Registers the journal's kept load (and its breakaway direction) with the
/// scene's step loop, as `name.load` (`name.breakaway_direction`).
void addKeptLoad(Scene& scene, const std::string& name, JournalFriction* impl);

/**
 * Seed 000 eq (21): a journal of diameter d carrying the radial load |R|
 * (the force its parent exerts on the body through the pin, from
 * Simbody's mobilizer reaction) resists the relative rotation with
 * <pre>
 *   M = |R| f d/2 · tanh(u/ω_s)
 * </pre>
 * u being the body's speed relative to its parent; tanh replaces the sign
 * function so that the torque is smooth at rest (stated width ω_s; below
 * ω_s the journal acts as a stiff viscous damper, not as stiction).
 *
 * The reaction includes the friction torques' own effect on the motion, so
 * M and R form an algebraic loop. The load |R| is kept in a discrete
 * variable (Simbody's sliding-friction prototype, TimsBox, does the same):
 * - Lagged (fast): an auto-update variable takes the reaction computed at
 *   the end of each accepted step; the next step uses it. Error: the load
 *   is one step old and was computed with the previous step's friction.
 * - Iterated: after every accepted step the Simulation iterates
 *   the loads of all journals together, R_{k+1} = R(M(R_k)), at the step's
 *   end state until they change by less than 1e-12 relative, and restarts
 *   the integrator from there. Kinetostatic analyses always iterate.
 * - Extrapolated: the load is linear in time through the reactions at the
 *   last two step ends, so it changes continuously within a step and the
 *   integrator's error control sees it; the error is second order in the
 *   step instead of first (docs/planetary_gear.md measures all three).
 * - FirstOrder: the load is the reaction of the same state with every
 *   journal's friction off (their kept loads set to 0 in a copy of the
 *   state, realized to Acceleration), refreshed after every step and at
 *   every kinetostatic instant: friction changes no journal's load, as in
 *   seed 000 eq (21), where the loads are those of the frictionless
 *   mechanism. It differs from the consistent loads at second order in f.
 * Breakaway (`at_rest: breakaway`): at u = 0 exactly, tanh(u/ω_s) is replaced
 * by the sign of the frictionless relative acceleration (kept with the
 * load), so a start instant carries the friction that resists the motion
 * beginning (seed 000 eq 20) instead of none.
 * A nested realization inside calcForce is not possible: Simbody's force
 * subsystem keeps the state it is realizing in a shared task object, so a
 * realization of another State of the same System from inside a force
 * corrupts the outer one (found here; see docs/simbody-notes.md).
 */
class JournalFriction : public SimTK::Force::Custom::Implementation {
public:
    /// `reactions`: the scene's shared reaction cache (Scene::mobilizerReactions()).
    JournalFriction(const SimTK::SimbodyMatterSubsystem& matter, const MobilizerReactions& reactions,
                    const SimTK::MobilizedBody& body, const JournalFrictionParams& p);

    const JournalFrictionParams& params() const { return m_p; }
    const SimTK::MobilizedBody& body() const { return m_body; }

    /// |R| the journal carries now [N], at Stage::Acceleration (a split
    /// over several bearings overrides it: ShaftBearings).
    virtual double calcReaction(const SimTK::State& s) const;
    /// M = load·f·d/2·tanh(u/ω_s) [N*m], the law every journal uses.
    static double calcFrictionTorque(double load, const JournalFrictionParams& p, double relativeSpeed);
    /// |R| the friction torque is computed from [N] (the kept load).
    double getLoad(const SimTK::State& s) const;
    /// Friction torque on the body, opposing its relative rotation [N*m].
    double calcTorque(const SimTK::State& s) const;
    /// Power it dissipates, M·u [W] >= 0.
    double calcPower(const SimTK::State& s) const;
    /// Sets the kept reaction to `load` [N] (the current reaction, read by
    /// the caller from a realized state); returns the relative change.
    double keepLoad(SimTK::State& s, double load) const;
    /// The reaction [N] and relative acceleration [rad/s^2] this journal
    /// would have in `s` with every journal of the scene frictionless
    /// (realizes a copy of `s`; `s` must not be in the middle of a realization).
    std::pair<double, double> calcFrictionless(const SimTK::State& s) const;
    /// The direction of breakaway friction (sign of the frictionless
    /// relative acceleration), kept like the load; returns 1 if it changed.
    double keepDirection(SimTK::State& s, double direction) const;
    ~JournalFriction() override;

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& s) const override;
    void realizeAcceleration(const SimTK::State& s) const override;

private:
    const SimTK::SimbodyMatterSubsystem& m_matter;
    const MobilizerReactions& m_reactions;
    SimTK::MobilizedBody m_body;
    JournalFrictionParams m_p;
    mutable SimTK::DiscreteVariableIndex m_keptLoad;
    mutable SimTK::DiscreteVariableIndex m_direction;  ///< breakaway: −1, 0, +1

    const SimTK::Vec4& history(const SimTK::State& s) const;
};

}  // namespace milldyn
