#pragma once
// Simulation: time integration of a Scene with Simbody's integrators.
// Samples are interpolated (they never force a step boundary, which would
// cap the step at the sample interval); the integrator stops exactly only
// at scheduled switch events and at the end. A watched function's first
// zero crossing (a shaft coming to rest) is located by re-integrating from
// the last accepted step, so its time is as accurate as the integration.

#include "driver/ModelSpec.h"
#include "plugins/scene/Scene.h"

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn {

/// An analysis that failed (diverged, integrator gave up): names the
/// element or quantity and the simulated time. The driver exits 1.
class AnalysisError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A Simbody exception's text on one line: without its "SimTK Exception
/// thrown at FILE:LINE:" header, whitespace runs folded, at most 300 chars.
std::string simbodyMessage(const std::string& what);

/// Creates a Simbody integrator by its model-file name (integratorNames()).
std::unique_ptr<SimTK::Integrator> makeIntegrator(const SimTK::System& system, const std::string& name);

struct RunStatistics {
    std::string integrator;
    double accuracy = 0;
    long steps = 0;
    long realizations = 0;
    long stepAttempts = 0;
    long consistencyRestarts = 0;  ///< restarts after iterating kept reactions
};

/// Solves a scene's instantaneous unknowns in a state (held charges' wall
/// torques z_x: their residual accelerations zero; journals' kept reactions
/// z_L: equal to what the realized state says they are) to the relative
/// `tolerance`, leaving the state realized to Acceleration at the solution.
/// Both are one system g(z) = [residuals; current − kept] = 0, solved by a
/// quasi-Newton iteration with one realization per iteration: its Jacobian
/// is made by finite differences once (z's n + m columns) and then kept up
/// to date by Broyden's update from every iteration's secant, across the
/// instants of a run; each instant starts from the last six solutions
/// extrapolated (instants equally spaced: kinetostatic angles, replay
/// samples). A kept value that is −1, 0 or 1 (a breakaway direction) is
/// iterated by plain substitution, never extrapolated. Converged when every
/// Newton correction of a torque and every relative change of a kept value
/// is at most a tenth of `tolerance`; the state is then the one realized
/// last, so a converged instant costs no realization beyond its iterations
/// (docs/benchmarks.md, "Kinetostatic throughput").
class InstantSolver {
public:
    explicit InstantSolver(const Scene& scene) : m_scene(scene) {}
    /// Returns the number of iterations (realizations to Acceleration, but
    /// for the Jacobian's). Throws AnalysisError if they do not converge.
    int solve(SimTK::State& s, double tolerance);
    /// Forgets earlier instants (a new run).
    void reset() {
        m_history.clear();
        m_haveJacobian = false;
    }

private:
    const Scene& m_scene;
    std::vector<Eigen::VectorXd> m_history;  // the last (up to six) solutions, newest last
    Eigen::MatrixXd m_jacobian;              // dg/dz
    bool m_haveJacobian = false;
    std::vector<bool> m_discrete;  // kept values iterated by substitution
    void write(SimTK::State& s, const Eigen::VectorXd& z) const;
    /// g at z (writes z into s, realizes it once); `current` gets the kept
    /// values' current values.
    Eigen::VectorXd evaluate(SimTK::State& s, const Eigen::VectorXd& z, Eigen::VectorXd& current) const;
    void makeJacobian(SimTK::State& s, const Eigen::VectorXd& z, const Eigen::VectorXd& g);
};

class Simulation {
public:
    Simulation(const Scene& scene, const IntegratorSpec& settings);

    /// Starts from `state` (its time is the start time). With `allowReplay`
    /// a scene without free degrees of freedom is replayed instead of
    /// integrated (see replayReason()).
    void initialize(const SimTK::State& state, bool allowReplay = false);

    /// Why the run is a replay, or why a replay was not possible (empty when
    /// it was not asked for). A scene has no free degrees of freedom when
    /// every mobility is prescribed by a drive with a known time law
    /// (Scene::prescribedTrajectories), fixed by a constraint, or held by a
    /// kinetostatic unknown, and it has no scheduled switchings and no
    /// continuous states but the energy meter's. Its state at time t then
    /// follows from t alone: the replay places it at each sample (the
    /// drives' laws, the elements' initializers, instant unknowns and
    /// journal reactions solved to consistency as in the kinetostatic
    /// analysis) and realizes it once; the energy meter's integrals are
    /// summed by the trapezoid rule over the samples. No integrator runs.
    bool isReplay() const { return m_replay; }
    const std::string& replayReason() const { return m_replayReason; }
    /// The reason when it is news for the run's summary: a replay, or a
    /// replay that the count allowed and the placement refused; empty when
    /// the scene simply has free motion (`milldyn info` says so).
    std::string replayNote() const { return m_replay || m_replayRefused ? m_replayReason : std::string(); }

    using SampleFn = std::function<void(const SimTK::State&)>;

    /// A falling quantity whose arrival at zero ends the run (a shaft's
    /// speed at standstill). Loads are regularised near zero speed, so the
    /// quantity only creeps towards zero: the run detects its crossing of
    /// `threshold` (above the regularisation band, where the dynamics are
    /// still the unregularised ones), then extrapolates to zero with the
    /// exact rate there; the extrapolation spans threshold/|rate| seconds.
    struct Watch {
        std::function<double(const SimTK::State&)> value;  ///< at Stage::Velocity
        std::function<double(const SimTK::State&)> rate;   ///< d(value)/dt, at Acceleration
        double threshold = 0;
        double notBefore = 0;
        std::string what;
    };

    /// Advances to `endTime`, calling onSample at every multiple of
    /// `sampleInterval` (and at the start and the end) with a state
    /// realized to Acceleration. Applies the scene's switch events. With a
    /// watch, stops at the threshold crossing (the last sample) and returns
    /// the extrapolated time of zero; otherwise returns nullopt.
    /// onStep sees the integrated trajectory itself, whatever the sampling:
    /// the start, every accepted step end, the state just after each
    /// switching (same time, new switch state) and a located crossing, each
    /// realized to Acceleration; during the call trajectoryAt() gives the
    /// trajectory anywhere in the last two steps (design loads, verdicts and
    /// crossings are judged from it, never from the samples).
    /// Throws AnalysisError if the integrator fails or a sample is not finite.
    std::optional<double> run(double endTime, double sampleInterval, const SampleFn& onSample,
                              const Watch* watch = nullptr, const SampleFn& onStep = {});

    /// During onStep: the earliest time trajectoryAt() can give (the start
    /// of the step before the current one, or the last switching).
    double trajectoryFrom() const { return m_ends.empty() ? 0 : m_ends.front().t; }
    /// During onStep: the state at time t in [trajectoryFrom(), the current
    /// step end], interpolated by the integrator's own interpolant (cubic
    /// Hermite from the step ends' y and ẏ; prescribed motion re-applied),
    /// realized to Acceleration, with the current step end's discrete
    /// variables. A replay places the state at t exactly.
    const SimTK::State& trajectoryAt(double t);

    const SimTK::State& state() const;
    /// The state of the last onSample call of the last run() (realized to
    /// Acceleration): the end, or the located crossing of a watch.
    const SimTK::State& lastSample() const;
    /// The scene's probe values (Scene::probes() order) at the sample being
    /// passed to onSample, already checked finite: evaluated once per
    /// sample, so recorders and summaries need not evaluate them again.
    const std::vector<double>& probeValues() const { return m_probeValues; }
    RunStatistics statistics() const;

private:
    const Scene& m_scene;
    IntegratorSpec m_settings;
    std::unique_ptr<SimTK::Integrator> m_integrator;
    RunStatistics m_extra;  // work done by crossing searches
    SimTK::State m_crossingSample;
    bool m_lastSampleIsCrossing = false;
    bool m_sampleByHermite = false;  // a sample needs no projection (see initialize())
    SimTK::State m_sample;           // the interpolated sample (own sampling)
    // The last (up to three) step ends since the last restart, for
    // trajectoryAt(): time, y and ẏ.
    struct StepEnd {
        double t = 0;
        SimTK::Vector y, ydot;
    };
    std::vector<StepEnd> m_ends;
    SimTK::State m_within;           // trajectoryAt()'s state
    bool m_haveWithin = false;
    /// Records the state (realized to Acceleration) as a step end; `restart`
    /// forgets the earlier ones (a switching: no interpolation across it).
    void pushStepEnd(const SimTK::State& s, bool restart);
    std::vector<double> m_probeValues;

    /// Fills m_probeValues; throws AnalysisError naming the body or element
    /// whose output is not finite.
    void evaluateAndCheck(const SimTK::State& state);
    /// Iterates the scene's each-step lagged values (iterated journal
    /// reactions) to consistency at the current step end and restarts the
    /// integrator there if they changed; true if it did.
    bool makeLaggedValuesConsistent();
    void accumulateStatistics();
    SimTK::State locateCrossing(const SimTK::State& before, double tAfter, const Watch& watch);

    // Replay (no free degrees of freedom).
    InstantSolver m_instant{m_scene};  // the samples' instant unknowns
    bool m_replay = false;
    bool m_replayRefused = false;
    std::string m_replayReason;
    SimTK::State m_replayState;
    double m_replayStart = 0;                       // [s]
    std::vector<std::pair<double, double>> m_trajectoryStart;  // {angle [rad], speed [rad/s]} per trajectory
    /// Places m_replayState at time t (energy integrals advanced by the
    /// trapezoid rule from the previous placement), realized to Acceleration.
    void placeReplay(double t);
    std::optional<double> runReplay(double endTime, double sampleInterval, const SampleFn& onSample,
                                    const SampleFn& onStep);
};

/// Empty if a transient of `scene` from `start` can be replayed (see
/// Simulation::isReplay), else why it is integrated ("integrated: ...").
/// Counts mobilities only; Simulation also checks the placement.
std::string whyNoReplay(const Scene& scene, const SimTK::State& start);


/// Solves for steady running about the mean load (periodic excitations off
/// while solving): all accelerations zero and every steady residual of the
/// scene (coupling twist rates) zero, the first body's angle held. Starts
/// from the scene's speed hints, with every starting sequence at its end
/// (Scene::StartSequence::finish) and the elements' own states at their
/// steady running (Scene::steadyInitializers). Returns the state with the excitations on,
/// realized to Acceleration. Throws AnalysisError naming the largest residual if it does
/// not converge.
SimTK::State solveSteadyState(const Scene& scene, const SimTK::State& guess);

}  // namespace milldyn
