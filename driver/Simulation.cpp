#include "driver/Simulation.h"

#include "driver/CpodesMessages.h"

#include "plugins/scene/EnergyMeter.h"
#include "plugins/scene/Format.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <sstream>

namespace milldyn {
namespace {

std::string timeText(double t) {
    std::ostringstream s;
    s.precision(9);
    s << "t = " << t << " s";
    return s.str();
}

// Multistep methods (CPodes) otherwise stop with "mxstep steps taken" on
// long stiff runs; the run's own end time bounds the work instead.
constexpr int kInternalStepLimit = 10'000'000;
// Relative change of kept reactions (iterated journal loads) that ends
// their iteration at a step end.
constexpr double kLaggedTolerance = 1e-12;
// InstantSolver: the solutions an instant's start is extrapolated from (a
// quintic through six; on the planetary turn at 721 angles, converging to
// the full tolerance, 3 gave 3.05 realizations per configuration and 6
// gave 2.25; 2.42 with the tenth below), and the share of the
// tolerance its last iterate must meet: the quasi-Newton iterate is only as
// close to the solution as its last change, where the substitution it
// replaces ended one sweep closer (a contraction of ~2e-3); at a tenth the
// outputs match the substitution's to 1e-13 (docs/benchmarks.md).
constexpr std::size_t kInstantHistory = 6;
constexpr double kInstantMargin = 0.1;
// Fixed-step integrators need a step; used when max_step is not given [s].
constexpr double kDefaultFixedStep = 1e-4;
// A replay's placements over its run, besides the samples (energy
// integrals by the trapezoid rule over them: independent of the sampling).
constexpr double kReplayPlacements = 4000;

/// Cubic Hermite interpolation between two step ends (values y, derivatives
/// f), the same order as Simbody's own interpolation of report times.
void interpolateHermite(double t0, const SimTK::Vector& y0, const SimTK::Vector& f0, double t1,
                        const SimTK::Vector& y1, const SimTK::Vector& f1, double t, SimTK::Vector& y) {
    const double h = t1 - t0, s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = (s3 - 2 * s2 + s) * h, h01 = 3 * s2 - 2 * s3, h11 = (s3 - s2) * h;
    for (int i = 0; i < y.size(); ++i) y[i] = h00 * y0[i] + h10 * f0[i] + h01 * y1[i] + h11 * f1[i];
}

// CPodes' own messages: driver/CpodesMessages (a sink per thread, no text
// of another thread swallowed).
std::unique_ptr<SimTK::Integrator> makeCPodes(const SimTK::System& system, SimTK::CPodes::LinearMultistepMethod method,
                                              SimTK::CPodes::NonlinearSystemIterationType iteration) {
    return makeCpodesIntegrator(system, method, iteration);
}

/// The last error CPodes reported on this thread, on one line ("" if none);
/// clears what was kept.
std::string cpodesError() { return takeCpodesError(); }

std::string number(double v) { return formatNumber(v, 4); }

/// Which element made a failed integration impossible, from the last
/// accepted state: a force element whose generalized force is not finite,
/// or would accelerate a shaft beyond any integration (|F|/M > 1e100 per
/// s^2: an overflow in the making, such as a motor torque of 1e300 N*m);
/// "" when no element stands out.
std::string blameForce(const Scene& scene, const SimTK::State& state) {
    const SimTK::SimbodyMatterSubsystem& matter = scene.matter();
    SimTK::State s = state;
    try {
        scene.system().realize(s, SimTK::Stage::Velocity);
    } catch (const std::exception&) {
        return "";
    }
    SimTK::Matrix M;
    matter.calcM(s, M);
    std::vector<std::string> names;
    for (const auto& p : scene.probes()) {
        const std::string element = p.name.substr(0, p.name.find('.'));
        if (std::find(names.begin(), names.end(), element) == names.end()) names.push_back(element);
    }
    std::string worst;
    double worstAcceleration = 1e100;
    for (const auto& name : names) {
        const SimTK::ForceIndex index = scene.findForce(name);
        if (!index.isValid()) continue;
        SimTK::Vector_<SimTK::SpatialVec> bodyForces(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
        SimTK::Vector_<SimTK::Vec3> particleForces(matter.getNumParticles(), SimTK::Vec3(0));
        SimTK::Vector mobilityForces(s.getNU(), 0.0), generalized;
        try {
            // Scene has no const forces(); getForce and its evaluation are const.
            const SimTK::GeneralForceSubsystem& forces = const_cast<Scene&>(scene).forces();
            forces.getForce(index).calcForceContribution(s, bodyForces, particleForces, mobilityForces);
            matter.multiplyBySystemJacobianTranspose(s, bodyForces, generalized);
        } catch (const std::exception&) {
            continue;
        }
        generalized += mobilityForces;
        for (int k = 0; k < generalized.size(); ++k) {
            const double f = generalized[k], a = std::abs(f) / std::max(M(k, k), 1e-300);
            if (!std::isfinite(f))
                return "element " + name + ": its force on mobility " + std::to_string(k) + " is not finite";
            if (a > worstAcceleration) {
                worstAcceleration = a;
                worst = "element " + name + ": generalized force " + number(f) + " on mobility " + std::to_string(k) +
                        " (acceleration " + number(a) + " per s^2) overflows the integration";
            }
        }
    }
    return worst;
}

/// The body turning fastest in `s` (what a failure names when no element
/// stands out).
std::string fastestBody(const Scene& scene, const SimTK::State& s) {
    std::string name;
    double fastest = -1;
    for (const auto& b : scene.bodies()) {
        const double u = std::abs(pinSpeed(s, b.mobod));
        if (!(u <= fastest)) {
            fastest = u;
            name = "body " + b.name + " (fastest, " + number(pinSpeed(s, b.mobod)) + " rad/s)";
        }
    }
    return name;
}

/// The lagged value (kept journal load) that changes most in one more
/// refresh: what a failure of their fixed point names.
std::string worstLaggedValue(const Scene& scene, SimTK::State& s) {
    try {
        scene.system().realize(s, SimTK::Stage::Acceleration);
        std::vector<double> now;
        for (const auto& v : scene.laggedValues()) now.push_back(v.current(s));
        std::string name;
        double worst = -1;
        for (std::size_t i = 0; i < now.size(); ++i) {
            const double c = scene.laggedValues()[i].keep(s, now[i]);
            if (!(c <= worst)) {
                worst = std::isnan(c) ? INFINITY : c;
                name = scene.laggedValues()[i].name + " (relative change " + number(c) + ")";
            }
        }
        return name;
    } catch (const std::exception&) {
        return "";
    }
}

/// The body whose acceleration is largest in `s` (realized to Acceleration).
std::string mostAcceleratedBody(const Scene& scene, const SimTK::State& s) {
    scene.system().realize(s, SimTK::Stage::Acceleration);
    std::string name;
    double largest = -1;
    for (const auto& b : scene.bodies()) {
        const double a = std::abs(b.mobod.getOneUDot(s, SimTK::MobilizerUIndex(0)));
        if (!(a <= largest)) {
            largest = a;
            name = "body " + b.name + " (acceleration " + number(a) + " rad/s^2)";
        }
    }
    return name;
}

/// An integrator's exception as one line: first what failed (an element
/// whose force overflows, else the fastest body) and the simulated time,
/// then the integrator's and CPodes' own words.
AnalysisError integrationFailure(const Scene& scene, const std::string& integrator, const SimTK::State& lastAccepted,
                                 const std::string& what) {
    const std::string cpodes = cpodesError();
    const std::string blamed = blameForce(scene, lastAccepted);
    const std::string head = (blamed.empty() ? fastestBody(scene, lastAccepted) : blamed) + " at " +
                             timeText(lastAccepted.getTime());
    // The integrator's own text only when no element explains it: an
    // overflowing motor torque is not "Inertia matrix contains a NaN".
    std::string detail = "integrator " + integrator + " failed";
    if (blamed.empty()) detail += ": " + simbodyMessage(what);
    if (!cpodes.empty()) detail += "; CPodes: " + cpodes;
    return AnalysisError(head + " (" + detail + ")");
}

/// Stops a run whose steps have become so small that its end is beyond
/// reach (issue 16 item 11: a 1e30 N*m/rad coupling under CPodes took steps
/// of about 1e-17 s and ran on for ever, each step a return of its own so
/// that the internal step limit never struck): checked every
/// kStepCheckInterval accepted steps, from the run's average step.
constexpr long kStepCheckInterval = 20000;
constexpr double kMaxProjectedSteps = 1e9;
void checkStepRate(const Scene& scene, const std::string& integrator, const SimTK::State& s, double t0, long accepted,
                   double endTime) {
    const double h = (s.getTime() - t0) / double(accepted);
    const double remaining = (endTime - s.getTime()) / h;
    if (!(remaining > kMaxProjectedSteps)) return;
    // An element whose force overflows (CPodes then "continues anyway"
    // with steps of h = 0) is the reason, not the stiffness.
    const std::string blamed = blameForce(scene, s);
    if (!blamed.empty())
        throw AnalysisError(blamed + " at " + timeText(s.getTime()) + " (integrator " + integrator + ": " +
                            std::to_string(accepted) + " steps advanced it by " + number(s.getTime() - t0) + " s)");
    throw AnalysisError(mostAcceleratedBody(scene, s) + " at " + timeText(s.getTime()) + ": the integrator's " +
                        std::to_string(accepted) + " steps average " + number(h) + " s, so reaching t = " +
                        number(endTime) + " s would take " + number(remaining) + " more (more than " +
                        number(kMaxProjectedSteps) + "): a motion of about " + number(1 / h) +
                        " rad/s is beyond integration (integrator " + integrator +
                        "); look for an absurd stiffness or a tiny inertia");
}

/// A failure of the kept loads' fixed point at the state `s`, naming the
/// element whose load moved most.
AnalysisError keptLoadsFailure(const Scene& scene, const SimTK::State& s, const std::string& what) {
    SimTK::State copy = s;
    const std::string culprit = worstLaggedValue(scene, copy);
    return AnalysisError("element " + culprit.substr(0, culprit.find_first_of(". ")) + ": " + what + " at " +
                         timeText(s.getTime()) + ": " + culprit + " (kept journal loads, iterated at each step end)");
}

/// Makes every kept reaction (journal load) consistent with `state`, by
/// fixed point: a lagged load of 0 would give the state no friction.
void settleLaggedValues(const Scene& scene, SimTK::State& state) {
    for (int k = 0; !scene.laggedValues().empty(); ++k) {
        const double change = refreshLaggedValues(scene, state);
        if (!(change > kLaggedTolerance)) break;
        if (k >= 50) throw keptLoadsFailure(scene, state, "no convergence in 50 iterations");
    }
}

/// Copies every discrete variable (kept journal loads, switch flags) of
/// `from` into `to`, a State of the same System: what a sample between two
/// step ends takes from the step's end, without a whole State copy.
void copyDiscreteVariables(const SimTK::State& from, SimTK::State& to) {
    // Only those that may change while integrating (they invalidate Time or
    // a later stage: loads, switches). Model and Instance ones are the
    // system's structure; setting one would undo the realization of `to`.
    for (SimTK::SubsystemIndex i(0); i < from.getNumSubsystems(); ++i)
        for (SimTK::DiscreteVariableIndex k(0); from.hasDiscreteVar({i, k}); ++k)
            if (from.getDiscreteVarInvalidatesStage(i, k) >= SimTK::Stage::Time)
                to.setDiscreteVariable(i, k, from.getDiscreteVariable(i, k));
}

}  // namespace

std::string simbodyMessage(const std::string& what) {
    std::string text = what;
    const std::string header = "SimTK Exception thrown at ";
    if (text.compare(0, header.size(), header) == 0) {
        const auto colonNewline = text.find(":\n");
        text.erase(0, colonNewline == std::string::npos ? header.size() : colonNewline + 2);
    }
    std::string out;
    for (char c : text) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space) {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out.size() > 300 ? out.substr(0, 297) + "..." : out;
}

std::unique_ptr<SimTK::Integrator> makeIntegrator(const SimTK::System& system, const std::string& name) {
    using namespace SimTK;
    if (name == "RungeKuttaMerson") return std::make_unique<RungeKuttaMersonIntegrator>(system);
    if (name == "RungeKutta3") return std::make_unique<RungeKutta3Integrator>(system);
    if (name == "RungeKutta2") return std::make_unique<RungeKutta2Integrator>(system);
    if (name == "RungeKuttaFeldberg") return std::make_unique<RungeKuttaFeldbergIntegrator>(system);
    if (name == "CPodes") return makeCPodes(system, CPodes::BDF, CPodes::Newton);
    if (name == "CPodesAdams") return makeCPodes(system, CPodes::Adams, CPodes::Functional);
    if (name == "Verlet") return std::make_unique<VerletIntegrator>(system);
    if (name == "SemiExplicitEuler") return std::make_unique<SemiExplicitEulerIntegrator>(system, kDefaultFixedStep);
    if (name == "SemiExplicitEuler2") return std::make_unique<SemiExplicitEuler2Integrator>(system);
    if (name == "ExplicitEuler") return std::make_unique<ExplicitEulerIntegrator>(system);
    throw std::invalid_argument("unknown integrator '" + name + "'");
}

void InstantSolver::write(SimTK::State& s, const Eigen::VectorXd& z) const {
    const auto& unknowns = m_scene.kinetostaticUnknowns();
    const auto& lagged = m_scene.laggedValues();
    const std::size_t n = unknowns.size();
    for (std::size_t i = 0; i < n; ++i) unknowns[i].set(s, z[i]);
    for (std::size_t j = 0; j < lagged.size(); ++j) lagged[j].keep(s, z[n + j]);
}

Eigen::VectorXd InstantSolver::evaluate(SimTK::State& s, const Eigen::VectorXd& z, Eigen::VectorXd& current) const {
    const auto& unknowns = m_scene.kinetostaticUnknowns();
    const auto& lagged = m_scene.laggedValues();
    const std::size_t n = unknowns.size(), m = lagged.size();
    write(s, z);
    m_scene.system().realize(s, SimTK::Stage::Acceleration);
    Eigen::VectorXd g(n + m);
    current.resize(m);
    for (std::size_t i = 0; i < n; ++i) g[i] = unknowns[i].residual(s);
    for (std::size_t j = 0; j < m; ++j) {
        current[j] = lagged[j].current(s);
        g[n + j] = current[j] - z[n + j];
    }
    return g;
}

void InstantSolver::makeJacobian(SimTK::State& s, const Eigen::VectorXd& z, const Eigen::VectorXd& g) {
    const Eigen::Index size = z.size();
    m_jacobian.setZero(size, size);
    Eigen::VectorXd current;
    for (Eigen::Index k = 0; k < size; ++k) {
        if (m_discrete[k]) continue;
        // The residuals are linear in the torques; the kept loads enter
        // through a reaction's magnitude, smooth away from zero.
        const double h = 1e-3 * std::max(1.0, std::abs(z[k]));
        Eigen::VectorXd zk = z;
        zk[k] += h;
        m_jacobian.col(k) = (evaluate(s, zk, current) - g) / h;
    }
    m_haveJacobian = true;
}

int InstantSolver::solve(SimTK::State& s, double tolerance) {
    const auto& unknowns = m_scene.kinetostaticUnknowns();
    const auto& lagged = m_scene.laggedValues();
    const std::size_t n = unknowns.size(), m = lagged.size();
    const Eigen::Index size = static_cast<Eigen::Index>(n + m);
    const SimTK::MultibodySystem& system = m_scene.system();
    if (size == 0) {
        system.realize(s, SimTK::Stage::Acceleration);
        return 1;
    }
    int iter = 0;
    Eigen::VectorXd z(size), current;
    if (m_history.empty()) {
        // The first instant: the torques in the state and, for the kept
        // values, one substitution sweep.
        for (std::size_t i = 0; i < n; ++i) z[i] = unknowns[i].get(s);
        m_discrete.assign(size, false);
        if (m > 0) {
            system.realize(s, SimTK::Stage::Acceleration);
            ++iter;
            for (std::size_t j = 0; j < m; ++j) {
                z[n + j] = lagged[j].current(s);
                const double v = z[n + j];
                m_discrete[n + j] = v == -1.0 || v == 0.0 || v == 1.0;
            }
        }
    } else {
        // The last solutions extrapolated by the polynomial through them
        // (equally spaced instants): z = sum_k (-1)^(k+1) C(p, k) h[-k].
        const auto& h = m_history;
        const int p = static_cast<int>(h.size());
        z.setZero();
        double binomial = 1;
        for (int k = 1; k <= p; ++k) {
            binomial = binomial * (p - k + 1) / k;
            z += (k % 2 == 1 ? binomial : -binomial) * h[p - k];
        }
        for (Eigen::Index i = 0; i < size; ++i)
            if (m_discrete[i]) z[i] = h.back()[i];
    }
    // A discrete value: row and column -e_k, so Newton's correction is the
    // substitution (kept = current) and the others do not see it.
    auto maskDiscrete = [&] {
        for (Eigen::Index k = 0; k < size; ++k)
            if (m_discrete[k]) {
                m_jacobian.row(k).setZero();
                m_jacobian.col(k).setZero();
                m_jacobian(k, k) = -1;
            }
    };
    // What a failure names: the unknown or kept load that is worst (not
    // finite, or moving most), and its element (the part before the dot).
    auto failure = [&](const std::string& what, const Eigen::VectorXd& residuals, const Eigen::VectorXd& step) {
        std::string culprit;
        double worst = -1;
        for (Eigen::Index k = 0; k < size; ++k) {
            const std::size_t i = static_cast<std::size_t>(k);
            const bool isTorque = i < n;
            double measure = residuals[k];
            if (isTorque && step.size() == size) measure = step[k];
            if (!isTorque) measure /= std::max(std::abs(current.size() > 0 ? current[i - n] : 0.0), 1e-300);
            measure = std::isfinite(measure) ? std::abs(measure) : INFINITY;
            if (measure > worst) {
                worst = measure;
                culprit = isTorque ? unknowns[i].name : lagged[i - n].name;
            }
        }
        const std::string element = culprit.substr(0, culprit.find_first_of(". "));
        return AnalysisError("element " + element + ": " + what + " at " + timeText(s.getTime()) + ": " + culprit +
                             " (relative residual " + number(worst) +
                             "; held wall torques and journal loads, solved together at each instant)");
    };
    Eigen::VectorXd g = evaluate(s, z, current);
    ++iter;
    bool realizedAtZ = true;
    for (;;) {
        if (!g.allFinite()) throw failure("not finite", g, Eigen::VectorXd());
        // Converged kept values need no Jacobian (the torques do).
        double worstChange = 0;
        for (std::size_t j = 0; j < m; ++j)
            worstChange = std::max(worstChange, std::abs(g[n + j]) / std::max(std::abs(current[j]), 1e-300));
        if (!m_haveJacobian && (n > 0 || worstChange > 0)) {
            makeJacobian(s, z, g);
            maskDiscrete();
            realizedAtZ = false;
        }
        Eigen::VectorXd dz = Eigen::VectorXd::Zero(size);
        if (m_haveJacobian) {
            Eigen::FullPivLU<Eigen::MatrixXd> lu(m_jacobian);
            if (!lu.isInvertible()) {
                makeJacobian(s, z, g);
                maskDiscrete();
                realizedAtZ = false;
                lu.compute(m_jacobian);
            }
            dz = lu.solve(-g);
        }
        // Converged when Newton's correction is round-off on the torque (or
        // on 1 N*m for a torque that is zero) and the kept values are what
        // the realized state says.
        double worstResidual = 0;
        for (std::size_t i = 0; i < n; ++i)
            worstResidual = std::max(worstResidual, std::abs(dz[i]) / std::max(1.0, std::abs(z[i] + dz[i])));
        if (!(worstChange > kInstantMargin * tolerance) && !(worstResidual > kInstantMargin * tolerance)) {
            if (!realizedAtZ) {
                g = evaluate(s, z, current);
                ++iter;
            }
            m_history.push_back(z);
            if (m_history.size() > kInstantHistory) m_history.erase(m_history.begin());
            return iter;
        }
        if (iter >= 100 || !dz.allFinite()) throw failure("no convergence in 100 iterations", g, dz);
        // Slow convergence: the kept Jacobian has drifted; make it anew.
        if (iter % 12 == 0) m_haveJacobian = false;
        z += dz;
        Eigen::VectorXd gNew = evaluate(s, z, current);
        ++iter;
        realizedAtZ = true;
        // Broyden's update from this secant: the Jacobian follows the
        // configuration from instant to instant.
        const double dd = dz.squaredNorm();
        if (m_haveJacobian && dd > 0) {
            m_jacobian += ((gNew - g - m_jacobian * dz) * dz.transpose()) / dd;
            maskDiscrete();
        }
        g = std::move(gNew);
    }
}

Simulation::Simulation(const Scene& scene, const IntegratorSpec& settings)
    : m_scene(scene), m_settings(settings) {
    m_extra.integrator = settings.name;
    m_extra.accuracy = settings.accuracy;
}

void Simulation::initialize(const SimTK::State& start, bool allowReplay) {
    m_instant.reset();
    m_replay = false;
    m_replayRefused = false;
    m_replayReason.clear();
    if (allowReplay) {
        m_replayReason = whyNoReplay(m_scene, start);
        if (m_replayReason.empty()) {
            const RunStatistics integrated = m_extra;  // kept if the placement refuses the replay
            m_replay = true;
            m_replayState = start;
            m_replayStart = start.getTime();
            m_trajectoryStart.clear();
            for (const auto& p : m_scene.prescribedTrajectories())
                m_trajectoryStart.emplace_back(pinAngle(start, p.mobod), pinSpeed(start, p.mobod));
            m_extra.integrator = "replay";
            m_extra.accuracy = 0;
            placeReplay(m_replayStart);
            // The count says no free mobility is left; the placement must
            // also satisfy the constraints (every dependent body placed).
            const SimTK::State& s = m_replayState;
            const double qerr = s.getNQErr() > 0 ? s.getQErr().normInf() : 0;
            const double uerr = s.getNUErr() > 0 ? s.getUErr().normInf() : 0;
            if (qerr <= 1e-9 && uerr <= 1e-9) {
                m_replayReason = "no free degrees of freedom (" + std::to_string(s.getNU()) + " mobilities: " +
                                 std::to_string(m_scene.prescribedTrajectories().size()) + " prescribed by drives, " +
                                 std::to_string(s.getNUDotErr()) + " fixed by constraints, " +
                                 std::to_string(m_scene.kinetostaticUnknowns().size()) +
                                 " held by instant unknowns): replayed at the samples, no integration; "
                                 "journal reactions consistent at each instant; energy integrals by the "
                                 "trapezoid rule over the samples";
                return;
            }
            m_replay = false;
            m_replayRefused = true;
            m_extra = integrated;
            m_replayReason = "integrated: the elements' placement leaves constraint errors (" +
                             std::to_string(std::max(qerr, uerr)) + ")";
        }
    }
    SimTK::State state = start;
    // Switchings due at the start time take effect before the first step.
    for (const auto& e : m_scene.switchEvents())
        if (e.time <= state.getTime()) e.apply(state);
    // Kept reactions (journal loads) start consistent with the start state,
    // lagged or not: a lagged load of 0 would give the first step no friction.
    settleLaggedValues(m_scene, state);
    m_integrator = makeIntegrator(m_scene.system(), m_settings.name);
    m_integrator->setAccuracy(m_settings.accuracy);
    m_integrator->setInternalStepLimit(kInternalStepLimit);
    if (m_settings.maxStep > 0) {
        m_integrator->setMaximumStepSize(m_settings.maxStep);
        if (m_settings.name == "SemiExplicitEuler") m_integrator->setFixedStepSize(m_settings.maxStep);
    }
    m_integrator->setReturnEveryInternalStep(true);
    m_integrator->initialize(state);
    m_integrator->resetAllStatistics();
    // Without constraints or prescribed q, u a sample is the step's
    // interpolant and needs no projection: the Simulation interpolates into
    // one State it keeps (sampleByHermite) instead of Simbody's report-time
    // interpolation, which copies a whole State per sample (72 % of a burr
    // start's instructions at 2 ms sampling).
    const SimTK::State& s = m_integrator->getState();
    m_sampleByHermite = s.getNQErr() == 0 && s.getNUErr() == 0 && s.getNUDotErr() == 0 &&
                        static_cast<int>(m_scene.matter().getFreeQIndex(s).size()) == s.getNQ() &&
                        static_cast<int>(m_scene.matter().getFreeUIndex(s).size()) == s.getNU();
}

const SimTK::State& Simulation::state() const { return m_replay ? m_replayState : m_integrator->getState(); }

const SimTK::State& Simulation::lastSample() const {
    if (m_replay) return m_replayState;
    return m_lastSampleIsCrossing ? m_crossingSample : m_integrator->getState();
}

std::string whyNoReplay(const Scene& scene, const SimTK::State& start) {
    SimTK::State s = start;
    scene.system().realize(s, SimTK::Stage::Instance);
    const SimTK::SimbodyMatterSubsystem& matter = scene.matter();
    if (!scene.switchEvents().empty()) return "integrated: the run has scheduled switchings";
    const int flows = scene.energyMeter() ? static_cast<int>(scene.energyMeter()->flows().size()) : 0;
    if (s.getNZ() != flows) return "integrated: elements have continuous states of their own";
    // A drive prescribing the acceleration leaves q and u states but makes
    // udot known: the free mobilities are those with unknown udot.
    const int nu = s.getNU(), freeU = static_cast<int>(matter.getFreeUDotIndex(s).size());
    const int prescribed = nu - freeU;
    // Every prescribed mobility needs a time law the replay can evaluate.
    int withLaw = 0;
    for (const auto& p : scene.prescribedTrajectories())
        if (p.mobod.getNumU(s) == 1) ++withLaw;
    if (withLaw != prescribed) return "integrated: a prescribed motion has no time law the replay can evaluate";
    const int free = freeU - s.getNUDotErr() - static_cast<int>(scene.kinetostaticUnknowns().size());
    if (free != 0) return "integrated: " + std::to_string(free) + " free degrees of freedom";
    return "";
}

void Simulation::placeReplay(double t) {
    SimTK::State& s = m_replayState;
    const SimTK::MultibodySystem& system = m_scene.system();
    // z: the energy meter's integrals; advanced by the trapezoid rule with
    // the derivatives at the previous placement and at this one.
    const double dt = t - s.getTime();
    SimTK::Vector zdotBefore;
    if (s.getNZ() > 0 && dt > 0) zdotBefore = s.getZDot();
    s.setTime(t);
    const auto& laws = m_scene.prescribedTrajectories();
    for (std::size_t i = 0; i < laws.size(); ++i) {
        const auto motion = laws[i].advance(m_replayStart, m_trajectoryStart[i].second, t);
        laws[i].mobod.setOneQ(s, SimTK::MobilizerQIndex(0), m_trajectoryStart[i].first + motion.first);
        laws[i].mobod.setOneU(s, SimTK::MobilizerUIndex(0), motion.second);
    }
    for (const auto& init : m_scene.initializers()) init(s);
    const int realizedBefore = system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration);
    m_instant.solve(s, kLaggedTolerance);
    if (zdotBefore.size() > 0) {
        const SimTK::Vector zdot = s.getZDot();
        s.updZ() += 0.5 * dt * (zdotBefore + zdot);
        system.realize(s, SimTK::Stage::Acceleration);
    }
    m_extra.realizations += system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration) - realizedBefore;
    ++m_extra.steps;
}

std::optional<double> Simulation::runReplay(double endTime, double sampleInterval, const SampleFn& onSample,
                                            const SampleFn& onStep) {
    const double t0 = m_replayState.getTime();
    // The placements: a grid of its own (max_step, else kReplayPlacements
    // over the run) merged with the sample times, so the energy integrals'
    // trapezoid rule and the design loads do not depend on the sampling.
    const double span = endTime - t0;
    const double h = m_settings.maxStep > 0 ? std::min(m_settings.maxStep, span / kReplayPlacements)
                                            : span / kReplayPlacements;
    auto emit = [&]() {
        evaluateAndCheck(m_replayState);
        if (onSample) onSample(m_replayState);
    };
    auto step = [&](bool restart) {
        if (!onStep) return;
        pushStepEnd(m_replayState, restart);
        onStep(m_replayState);
    };
    emit();
    step(true);
    long k = 1, j = 1;
    while (m_replayState.getTime() < endTime && span > 0) {
        const double tSample = std::min(t0 + k * sampleInterval, endTime);
        const double tGrid = std::min(t0 + j * h, endTime);
        const double t = std::min(tSample, tGrid);
        const double tol = 1e-12 * std::max(1.0, std::abs(t));
        placeReplay(t);
        if (tGrid <= t + tol) ++j;
        const bool atSample = tSample <= t + tol;
        if (atSample) ++k;
        if (atSample) emit();
        step(false);
    }
    return std::nullopt;
}

void Simulation::accumulateStatistics() {
    m_extra.steps += m_integrator->getNumStepsTaken();
    m_extra.realizations += m_integrator->getNumRealizations();
    m_extra.stepAttempts += m_integrator->getNumStepsAttempted();
}

RunStatistics Simulation::statistics() const {
    RunStatistics s = m_extra;
    if (m_replay) return s;
    s.steps += m_integrator->getNumStepsTaken();
    s.realizations += m_integrator->getNumRealizations();
    s.stepAttempts += m_integrator->getNumStepsAttempted();
    return s;
}

void Simulation::evaluateAndCheck(const SimTK::State& state) {
    const double t = state.getTime();
    for (const auto& b : m_scene.bodies()) {
        const double q = pinAngle(state, b.mobod), u = pinSpeed(state, b.mobod);
        if (!std::isfinite(q) || !std::isfinite(u))
            throw AnalysisError("the motion of body " + b.name + " is not finite at " + timeText(t) +
                                " (the analysis diverged)");
    }
    m_probeValues.clear();
    for (const auto& p : m_scene.probes()) {
        const double v = p.value(state);
        m_probeValues.push_back(v);
        if (!std::isfinite(v)) {
            const std::string element = p.name.substr(0, p.name.find('.'));
            throw AnalysisError("element " + element + ": " + p.name + " is not finite at " + timeText(t));
        }
    }
}

void Simulation::pushStepEnd(const SimTK::State& s, bool restart) {
    if (restart) {
        m_ends.clear();
        m_within = s;  // one State copy per run and switching: discrete variables and structure
        m_haveWithin = true;
    }
    if (m_ends.size() == 3) m_ends.erase(m_ends.begin());
    m_ends.push_back({s.getTime(), s.getY(), s.getYDot()});
}

const SimTK::State& Simulation::trajectoryAt(double t) {
    if (m_ends.empty() || !m_haveWithin) throw AnalysisError("internal: trajectoryAt outside a step");
    const SimTK::MultibodySystem& system = m_scene.system();
    t = std::max(m_ends.front().t, std::min(t, m_ends.back().t));
    std::size_t k = 1;
    while (k + 1 < m_ends.size() && m_ends[k].t < t) ++k;
    const SimTK::State& now = m_replay ? m_replayState : m_integrator->getState();
    copyDiscreteVariables(now, m_within);
    if (m_ends.size() == 1 || m_ends[k].t <= m_ends[k - 1].t) {
        m_within.updY() = m_ends.back().y;
        m_within.setTime(m_ends.back().t);
    } else {
        const StepEnd &a = m_ends[k - 1], &b = m_ends[k];
        interpolateHermite(a.t, a.y, a.ydot, b.t, b.y, b.ydot, t, m_within.updY());
        m_within.setTime(t);
    }
    // As Simbody's own interpolated states: prescribed motion re-applied
    // (the interpolant of a prescribed q is close to, not on, its law).
    system.realize(m_within, SimTK::Stage::Time);
    system.prescribeQ(m_within);
    system.realize(m_within, SimTK::Stage::Position);
    system.prescribeU(m_within);
    system.realize(m_within, SimTK::Stage::Acceleration);
    return m_within;
}

std::optional<double> Simulation::run(double endTime, double sampleInterval, const SampleFn& onSample,
                                      const Watch* watch, const SampleFn& onStep) {
    m_ends.clear();
    if (m_replay) {
        // A watch needs a switch-off first, and switchings rule out a replay.
        if (watch) throw AnalysisError("internal: a watched run cannot be a replay");
        return runReplay(endTime, sampleInterval, onSample, onStep);
    }
    SimTK::Integrator& integ = *m_integrator;
    const SimTK::System& system = m_scene.system();
    const double t0 = integ.getTime();

    // The last sample is the integrator's state (no copy) unless it was a
    // located crossing; copying a State costs more than a step here.
    auto emit = [&](const SimTK::State& s) {
        system.realize(s, SimTK::Stage::Acceleration);
        evaluateAndCheck(s);
        m_lastSampleIsCrossing = false;
        if (onSample) onSample(s);
    };
    emit(integ.getState());
    // A step end of the trajectory (the state realized to Acceleration).
    auto step = [&](const SimTK::State& st, bool restart) {
        if (!onStep) return;
        system.realize(st, SimTK::Stage::Acceleration);
        pushStepEnd(st, restart);
        onStep(st);
    };
    step(integ.getState(), true);
    if (endTime <= t0) return std::nullopt;

    std::vector<double> switchTimes;
    for (const auto& e : m_scene.switchEvents())
        if (e.time > t0 && e.time < endTime) switchTimes.push_back(e.time);
    std::sort(switchTimes.begin(), switchTimes.end());
    std::size_t nextSwitch = 0;

    long sampleIndex = 1;
    long accepted = 0;  // steps accepted in this run, for checkStepRate
    cpodesError();      // drops what CPodes said before (warnings of runs that went on)
    // The last accepted step end: only a watch needs it (a crossing is
    // located from it), and only from the watch's notBefore on. A State copy
    // costs more than a step (58 % of the burr demo's instructions when made
    // at every step; docs/benchmarks.md), so the whole State is copied once
    // (here, and after a switching restart) and later step ends only take
    // what integrating changes into it: time, y = {q, u, z} and the discrete
    // variables (kept loads, switch flags) — rememberWatchStart. That is done
    // only at the step ends whose next step may reach notBefore (predicted
    // step size, with a factor 2 of margin) and later ones. Should a step
    // outgrow that margin, the crossing is still located from the last one
    // taken (an earlier accepted step end: the same root, re-integrated over
    // a longer span).
    SimTK::State lastStepEnd = integ.getState();
    auto mayWatchNext = [&](const SimTK::State& st) {
        return st.getTime() + 2 * integ.getPredictedNextStepSize() >= watch->notBefore;
    };
    auto rememberWatchStart = [&](const SimTK::State& st) {
        lastStepEnd.setTime(st.getTime());
        lastStepEnd.updY() = st.getY();
        copyDiscreteVariables(st, lastStepEnd);
    };
    auto watched = [watch](const SimTK::State& st) { return watch->value(st) - watch->threshold; };
    double lastWatch = watch ? watched(lastStepEnd) : 0;

    // Own sampling (m_sampleByHermite): the integrator returns at its step
    // ends only; the samples inside a step are interpolated from the last
    // step end (time, y, ẏ) and this one into m_sample.
    const bool own = m_sampleByHermite;
    // The next sample's time: a multiple of the interval, or the end.
    auto nextSampleTime = [&] { return std::min(t0 + sampleIndex * sampleInterval, endTime); };
    double tPrev = t0;
    SimTK::Vector yPrev, ydotPrev;
    auto rememberStepEnd = [&]() {
        const SimTK::State& e = integ.getState();
        system.realize(e, SimTK::Stage::Acceleration);
        tPrev = e.getTime();
        yPrev = e.getY();
        ydotPrev = e.getYDot();
    };
    if (own) {
        m_sample = integ.getState();  // one copy per run; its discrete part is refreshed per step
        rememberStepEnd();
    }
    // Emits the samples strictly before `until` that fall in the step just taken.
    auto emitInterpolated = [&](double until) {
        const SimTK::State& end = integ.getState();
        bool discreteCopied = false;
        for (;;) {
            const double ts = nextSampleTime();
            if (!(ts < until && ts > tPrev)) break;
            if (!discreteCopied) {
                copyDiscreteVariables(end, m_sample);
                discreteCopied = true;
            }
            interpolateHermite(tPrev, yPrev, ydotPrev, end.getTime(), end.getY(), end.getYDot(), ts, m_sample.updY());
            m_sample.setTime(ts);
            emit(m_sample);
            ++sampleIndex;
        }
    };

    // The last state stepTo returned (time and y): what a failure is judged
    // from when the integrator's state holds the failed trial (non-finite:
    // on Debian's checked engine Simbody's NaN checks throw inside the trial
    // step, so CPodes gives up with the trial's NaN in its state).
    double tReturned = t0;
    SimTK::Vector yReturned = integ.getState().getY();
    while (true) {
        const double hardStop = nextSwitch < switchTimes.size() ? switchTimes[nextSwitch] : endTime;
        SimTK::Integrator::SuccessfulStepStatus status;
        try {
            status = integ.stepTo(own ? hardStop : std::min(nextSampleTime(), hardStop), hardStop);
        } catch (const std::exception& e) {
            SimTK::State last = integ.getState();
            bool finite = true;
            for (int i = 0; i < last.getNY(); ++i) finite = finite && std::isfinite(last.getY()[i]);
            if (!finite) {
                last.setTime(tReturned);
                last.updY() = yReturned;
            }
            throw integrationFailure(m_scene, m_settings.name, last, e.what());
        }
        const SimTK::State& s = integ.getState();
        tReturned = s.getTime();
        yReturned = s.getY();
        system.realize(s, own ? SimTK::Stage::Acceleration : SimTK::Stage::Velocity);

        if (watch && s.getTime() >= watch->notBefore) {
            const double value = watched(s);
            if (lastWatch > 0 && value <= 0) {
                system.realize(lastStepEnd, SimTK::Stage::Velocity);  // the watch's stage, after rememberWatchStart
                m_crossingSample = locateCrossing(lastStepEnd, s.getTime(), *watch);
                const SimTK::State& crossing = m_crossingSample;
                if (own) emitInterpolated(crossing.getTime());
                emit(crossing);
                step(crossing, false);
                m_lastSampleIsCrossing = true;
                const double rate = watch->rate(crossing);
                if (!(rate < 0))
                    throw AnalysisError(watch->what + ": not falling at " + timeText(crossing.getTime()));
                return crossing.getTime() + watch->value(crossing) / -rate;
            }
            if (!integ.isStateInterpolated()) lastWatch = value;
        }
        if (own) emitInterpolated(s.getTime());
        const double nextSample = nextSampleTime();
        if (!integ.isStateInterpolated() && ++accepted % kStepCheckInterval == 0)
            checkStepRate(m_scene, m_settings.name, s, t0, accepted, endTime);
        // A located event: an element's event witness changed sign (a frozen
        // charge's release). The state just before the change (the kept
        // values change at the step end at or after the event) is on the
        // trajectory: Simbody's Runge-Kutta family returns it interpolated,
        // at the start of the event's localization window.
        const bool event = status == SimTK::Integrator::ReachedEventTrigger && s.getTime() <= hardStop;
        if (!integ.isStateInterpolated()) {
            if (event) step(s, false);  // before the change; the state after it starts a new piece
            const bool changed = makeLaggedValuesConsistent();  // may restart: s then is the consistent state
            if (watch && mayWatchNext(integ.getState())) rememberWatchStart(integ.getState());
            // A step end past a hard stop (CPodes steps past and interpolates
            // back) is not on the trajectory: the switch applies before it.
            if (event) {
                if (changed) step(integ.getState(), true);
            } else if (s.getTime() <= hardStop) {
                step(s, false);
            }
        } else if (event) {
            step(s, false);
        } else if (std::abs(s.getTime() - hardStop) <= 1e-12 * std::max(1.0, std::abs(hardStop))) {
            // CPodes stepped past the stop and interpolated back to it: the
            // stop is on the trajectory (the integrator's own interpolant,
            // as accurate as its steps). Without it the trace would join the
            // last step end before the stop to the restarted state after the
            // switching, whose acceleration is the switched one: the cubic
            // between them overshot by up to 182 rad/s on the burr demo.
            step(s, false);
        }

        const double t = s.getTime();
        const bool atSample = std::abs(t - nextSample) <= 1e-12 * std::max(1.0, std::abs(t));
        // A switching instant is always a sample: the state just before it
        // is what a summary of steady running reports.
        const bool atSwitch = nextSwitch < switchTimes.size() && t >= switchTimes[nextSwitch];
        if (atSample || atSwitch || status == SimTK::Integrator::ReachedReportTime) emit(s);
        if (atSample) ++sampleIndex;
        if (t >= endTime) return std::nullopt;
        // CPodes may step past the stop and interpolate back, so the switch
        // is applied to the state at the switch time and the integrator
        // restarts from it, whatever the integrator reported.
        if (atSwitch) {
            SimTK::State restart = s;
            for (const auto& e : m_scene.switchEvents())
                if (e.time == switchTimes[nextSwitch]) e.apply(restart);
            ++nextSwitch;
            accumulateStatistics();
            integ.initialize(restart);
            integ.resetAllStatistics();
            step(integ.getState(), true);
            if (watch) {
                lastStepEnd = integ.getState();
                lastWatch = watched(lastStepEnd);
            }
        }
        if (own) rememberStepEnd();
        if (status == SimTK::Integrator::EndOfSimulation) return std::nullopt;
    }
}

bool Simulation::makeLaggedValuesConsistent() {
    bool any = false;
    for (const auto& v : m_scene.laggedValues()) any = any || v.eachStep;
    if (!any) return false;
    // Not interpolated here: the advanced state is the step end.
    SimTK::State& s = m_integrator->updAdvancedState();
    double change = 0;
    bool changed = false;
    for (int k = 0;; ++k) {
        change = refreshLaggedValues(m_scene, s, true);
        if (!(change > kLaggedTolerance)) break;
        changed = true;
        if (k >= 50) throw keptLoadsFailure(m_scene, s, "no convergence in 50 iterations");
    }
    if (!std::isfinite(change)) throw keptLoadsFailure(m_scene, s, "not finite");
    if (!changed) return false;
    // A discrete change, as an event handler makes: the integrator keeps
    // its step size and restarts its derivative evaluation.
    m_integrator->reinitialize(SimTK::Stage::Dynamics, false);
    ++m_extra.consistencyRestarts;
    return true;
}

SimTK::State Simulation::locateCrossing(const SimTK::State& before, double tAfter, const Watch& watch) {
    const SimTK::System& system = m_scene.system();
    // Each probe re-integrates from the last accepted step: exact to the
    // integration accuracy, unlike the integrator's interpolant.
    auto stateAt = [&](double t) {
        auto integ = makeIntegrator(system, m_settings.name);
        integ->setAccuracy(m_settings.accuracy);
        integ->setInternalStepLimit(kInternalStepLimit);
        if (m_settings.maxStep > 0) integ->setMaximumStepSize(m_settings.maxStep);
        integ->initialize(before);
        // stepTo returns early at a located event (an element's witness,
        // Integrator::ReachedEventTrigger): step on to t, or the state at
        // the event would stand for the state at t. The bracket [before,
        // tAfter] holds no kept-value change (the run remembers the watch
        // start at every step end, after the change), so nothing else of the
        // run's step-end handling applies here.
        for (int pieces = 0; integ->getTime() < t && pieces < 100; ++pieces)
            if (integ->stepTo(t, t) == SimTK::Integrator::EndOfSimulation) break;
        if (integ->getTime() < t)
            throw AnalysisError(watch.what + ": could not integrate to " + timeText(t) + " to locate the crossing");
        m_extra.realizations += integ->getNumRealizations();
        SimTK::State s = integ->getState();
        system.realize(s, SimTK::Stage::Acceleration);
        return s;
    };
    auto f = [&](const SimTK::State& s) { return watch.value(s) - watch.threshold; };
    // Illinois (modified regula falsi): bracketed, superlinear on smooth f.
    double a = before.getTime(), fa = f(before);
    SimTK::State sb = stateAt(tAfter);
    double b = sb.getTime(), fb = f(sb);
    int side = 0;
    for (int i = 0; i < 100; ++i) {
        if (b - a <= 1e-14 * std::max(1.0, std::abs(b)) || fb == 0) break;
        double c = (a * fb - b * fa) / (fb - fa);
        if (!(c > a && c < b)) c = 0.5 * (a + b);
        SimTK::State sc = stateAt(c);
        const double fc = f(sc);
        if (fc > 0) {
            a = c;
            fa = fc;
            if (side == -1) fb *= 0.5;
            side = -1;
        } else {
            b = c;
            fb = fc;
            sb = sc;
            if (side == +1) fa *= 0.5;
            side = +1;
        }
        if (std::abs(fc) <= 1e-14 * std::max(1.0, std::abs(watch.threshold))) {
            sb = sc;
            break;
        }
    }
    return sb;
}

SimTK::State solveSteadyState(const Scene& scene, const SimTK::State& guess) {
    const SimTK::System& system = scene.system();
    SimTK::State state = guess;
    // Steady running is about the mean load: periodic excitations off while
    // solving, back on in the state returned.
    scene.setExcitationsOn(state, false);
    // Steady running is the machine after its start: starters at their end
    // (delta, full voltage, rated frequency, rotor short-circuited), clutches
    // engaged — in the state returned too.
    for (const StartSequence& q : scene.startSequences())
        if (q.finish) q.finish(state);
    const int nq = state.getNQ(), nu = state.getNU();
    const auto hints = scene.speedHints();
    for (const auto& b : scene.bodies()) b.mobod.setOneU(state, SimTK::MobilizerUIndex(0), hints.at(b.name));
    const double heldAngle = nq > 0 ? state.getQ()[0] : 0;
    const auto& residuals = scene.steadyResiduals();
    // The constraints' position and velocity errors are residuals too: an
    // acceleration-level solution whose q, u leave a constraint (a planet's
    // rolling on its carrier) is not a state the integrator can start from;
    // its projection would move the speeds and twists (issue 26 item 6).
    int nQErr = 0, nUErr = 0;
    {
        SimTK::State s = state;
        system.realize(s, SimTK::Stage::Velocity);
        nQErr = s.getNQErr();
        nUErr = s.getNUErr();
    }
    const int nc = nQErr + nUErr;
    const int nr = nu + static_cast<int>(residuals.size()) + nc + (nq > 0 ? 1 : 0);
    const int nx = nq + nu;

    auto setX = [&](SimTK::State& s, const Eigen::VectorXd& x) {
        for (int i = 0; i < nq; ++i) s.updQ()[i] = x[i];
        for (int i = 0; i < nu; ++i) s.updU()[i] = x[nq + i];
    };
    auto residual = [&](const Eigen::VectorXd& x) {
        SimTK::State s = state;
        setX(s, x);
        // Elements' own states (a dq machine's fluxes) at this trial's running.
        for (const auto& f : scene.steadyInitializers()) f(s);
        // Kept reactions (journal loads) consistent with each trial state: a
        // journal's friction at steady running is its running load's, not the
        // zero load of a state never realized (the Kloss speed without it).
        settleLaggedValues(scene, s);
        system.realize(s, SimTK::Stage::Acceleration);
        Eigen::VectorXd r(nr);
        for (int i = 0; i < nu; ++i) r[i] = s.getUDot()[i];
        for (std::size_t k = 0; k < residuals.size(); ++k) r[nu + k] = residuals[k].value(s);
        const int c0 = nu + static_cast<int>(residuals.size());
        for (int i = 0; i < nQErr; ++i) r[c0 + i] = s.getQErr()[i];
        for (int i = 0; i < nUErr; ++i) r[c0 + nQErr + i] = s.getUErr()[i];
        if (nq > 0) r[nr - 1] = s.getQ()[0] - heldAngle;
        return r;
    };
    Eigen::VectorXd x(nx);
    for (int i = 0; i < nq; ++i) x[i] = state.getQ()[i];
    for (int i = 0; i < nu; ++i) x[nq + i] = state.getU()[i];

    Eigen::VectorXd r = residual(x);
    for (int iter = 0; iter < 60; ++iter) {
        Eigen::MatrixXd J(nr, nx);
        for (int j = 0; j < nx; ++j) {
            const double h = 1e-6 * std::max(1.0, std::abs(x[j]));
            Eigen::VectorXd xp = x, xm = x;
            xp[j] += h;
            xm[j] -= h;
            J.col(j) = (residual(xp) - residual(xm)) / (2 * h);
        }
        Eigen::VectorXd dx = J.colPivHouseholderQr().solve(-r);
        // Large speed jumps can leave a motor's stable branch: damp them.
        double scale = 1;
        for (int i = 0; i < nu; ++i) {
            const double limit = 0.25 * std::max(1.0, std::abs(x[nq + i]));
            if (std::abs(dx[nq + i]) > limit) scale = std::min(scale, limit / std::abs(dx[nq + i]));
        }
        x += scale * dx;
        r = residual(x);
        if (scale == 1 && dx.norm() <= 1e-13 * (1 + x.norm())) break;
    }
    setX(state, x);
    for (const auto& f : scene.steadyInitializers()) f(state);
    settleLaggedValues(scene, state);
    system.realize(state, SimTK::Stage::Acceleration);
    // Converged means the accelerations are negligible against what the
    // forces alone would produce over one second of running.
    const double speedScale = std::max(1.0, x.tail(nu).cwiseAbs().maxCoeff());
    if (!r.allFinite() || r.cwiseAbs().maxCoeff() > 1e-8 * speedScale) {
        Eigen::Index worst = 0;
        r.cwiseAbs().maxCoeff(&worst);
        const Eigen::Index nres = static_cast<Eigen::Index>(residuals.size());
        std::string where = worst < nu          ? "acceleration of " + mobilityNames(scene, state)[worst]
                            : worst < nu + nres ? residuals[worst - nu].name
                            : worst < nu + nres + nc ? "a constraint's error (a gear mesh or rolling contact)"
                                                     : "held angle";
        throw AnalysisError("no steady running state found: residual " + std::to_string(r.cwiseAbs().maxCoeff()) +
                            " in " + where + " (does the drive overcome the load?)");
    }
    scene.setExcitationsOn(state, true);
    system.realize(state, SimTK::Stage::Acceleration);
    return state;
}

}  // namespace milldyn
