// frequency_response: steady-state amplitude and phase of every coupling
// torque under one harmonic of a load's periodic forcing (HarmonicForcing),
// from the linear model, and checked by time simulation at chosen
// frequencies (where the load can be forced at a chosen frequency).
//
// Amplitude A and phase ψ per unit row amplitude, and the dynamic factor,
// are defined in LoadResponse.h.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/analyses/LinearModel.h"
#include "driver/analyses/LoadResponse.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>

namespace milldyn {
namespace {

using Complex = std::complex<double>;

const HarmonicForcing& findForcingLoad(const Scene& scene, const ModelSpec& spec) {
    const std::string name = spec.scenario.text("load");
    const HarmonicForcing* load = scene.findElement<HarmonicForcing>(name);
    if (!load)
        throw spec.scenario.error("load", "'" + name + "' is not an element of this model with a periodic forcing "
                                          "(a load that declares its harmonics)");
    return *load;
}

struct Fit {
    double amplitude = 0;
    double phase = 0;
};

/// Least-squares fit of a0 + a1·sin(Pt) + a2·cos(Pt) to samples.
Fit fitHarmonic(const std::vector<double>& t, const std::vector<double>& y, double P) {
    Eigen::MatrixXd X(t.size(), 3);
    Eigen::VectorXd Y(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        X(i, 0) = 1;
        X(i, 1) = std::sin(P * t[i]);
        X(i, 2) = std::cos(P * t[i]);
        Y[i] = y[i];
    }
    const Eigen::Vector3d a = X.colPivHouseholderQr().solve(Y);
    return {std::hypot(a[1], a[2]), std::atan2(a[2], a[1])};
}

double wrapPhase(double a) { return std::remainder(a, 2 * M_PI); }

/// Why an output has no response of its own: the pattern of the load's
/// terms (`terms`: "rows", "shafts") cancels there.
std::string cancelNote(const std::string& load, const std::string& terms, int k, double ratio) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1e", ratio);
    return "harmonic " + std::to_string(k) + " of the " + terms + " of " + load +
           " cancels at this coupling (amplitude " + (ratio > 0 ? std::string(text) : std::string("0")) +
           " of the " + terms + "' in-phase amplitude: round-off)";
}

}  // namespace

AnalysisResult runFrequencyResponse(const ModelSpec& spec, const ProgressFn& progress) {
    const ElementSpec& sc = spec.scenario;
    auto scene = buildScene(spec);
    const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    // Rigid meshes (GearPair, GearMesh, PlanetaryGearSet, BeltDrive) are
    // reduced to independent coordinates, as linearize does.
    // The dq machines' fluxes as scenario.motor_model says (default their states).
    const LinearModel lm =
        linearizeScene(*scene, steady, true, true, motorModelFromName(sc.text("motor_model")));
    const HarmonicForcing& load = findForcingLoad(*scene, spec);
    const int k = static_cast<int>(sc.number("harmonic"));
    const LoadResponse response(*scene, lm, load, steady);
    const std::vector<int>& outputs = response.couplingOutputs();
    if (outputs.empty()) throw sc.error("load", "the model has no coupling whose torque could respond");
    // One harmonic of a shaft-angle load is one frequency only if its shafts
    // turn at one speed (resonance_map takes each at its own).
    if (response.groupSpeedRatios().size() > 1)
        throw sc.error("load", "the " + load.forcingTermName() + " of '" + sc.text("load") +
                                   "' turn at different steady speeds, so its harmonic " + std::to_string(k) +
                                   " is not one frequency; use resonance_map, which forces each at its own");
    const std::string terms = load.forcingTermName();
    auto linearOutput = [&](double P, int probe) { return response.output(P, k, probe); };

    AnalysisResult result;
    result.notes = motorDampingNotes(*scene, lm);
    result.derived = derivedResults(*scene);
    result.analysis = "frequency_response";
    result.tableName = "frequency_response";
    result.plotXLabel = "forcing frequency [rad/s]";
    result.columnNames = {"frequency"};
    result.columnUnits = {"rad/s"};
    for (int p : outputs) {
        result.columnNames.push_back(scene->probes()[p].name + ".dynamic_factor");
        result.columnUnits.push_back("1");
    }
    for (int p : outputs) {
        result.columnNames.push_back(scene->probes()[p].name + ".amplitude");
        result.columnUnits.push_back("N*m/N*m");
        result.columnNames.push_back(scene->probes()[p].name + ".phase");
        result.columnUnits.push_back("rad");
    }
    const double Pmin = sc.number("frequency_min"), Pmax = sc.number("frequency_max");
    const int points = static_cast<int>(sc.number("points"));
    // A peak is taken only where the row pattern reaches the coupling: where
    // it cancels there (LoadResponse::cancels) the amplitude is round-off.
    std::vector<double> peak(outputs.size(), 0.0), peakAt(outputs.size(), 0.0), worstRatio(outputs.size(), 0.0);
    std::vector<bool> reached(outputs.size(), false);
    for (int i = 0; i < points; ++i) {
        const double P = Pmin * std::pow(Pmax / Pmin, double(i) / (points - 1));
        std::vector<double> row = {P};
        std::vector<double> rest;
        for (std::size_t o = 0; o < outputs.size(); ++o) {
            const Complex y = linearOutput(P, outputs[o]);
            if (!std::isfinite(std::abs(y)))
                throw AnalysisError("frequency_response: the linear amplitude of " + scene->probes()[outputs[o]].name +
                                    " at " + std::to_string(P) +
                                    " rad/s is unbounded (an undamped natural frequency); choose other points");
            row.push_back(std::abs(y) / response.staticReference(outputs[o]));
            rest.push_back(std::abs(y));
            rest.push_back(std::arg(y));
            const double ratio = response.patternRatio(P, k, outputs[o]);
            worstRatio[o] = std::max(worstRatio[o], ratio);
            if (ratio > LoadResponse::kCancelled && (!reached[o] || std::abs(y) > peak[o])) {
                peak[o] = std::abs(y);
                peakAt[o] = P;
                reached[o] = true;
            }
        }
        row.insert(row.end(), rest.begin(), rest.end());
        result.rows.push_back(row);
    }
    addLinearModelOutputs(lm, result);
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        const std::string& name = scene->probes()[outputs[o]].name;
        if (!reached[o]) {
            result.results.push_back({name + ".pattern_ratio", worstRatio[o], "1",
                                      "largest amplitude of harmonic " + std::to_string(k) +
                                          "'s row pattern over the in-phase rows' amplitude: round-off, the "
                                          "forcing cancels"});
            result.notes.push_back(name + ": no peak: " + cancelNote(sc.text("load"), terms, k, worstRatio[o]));
            continue;
        }
        result.results.push_back({name + ".peak_dynamic_factor", peak[o] / response.staticReference(outputs[o]), "1",
                                  "largest amplitude over the quasi-static in-phase amplitude, in the range"});
        result.results.push_back({name + ".peak_frequency", peakAt[o], "rad/s", "where it occurs"});
    }
    std::vector<std::size_t> factorColumns;
    for (std::size_t o = 0; o < outputs.size(); ++o) factorColumns.push_back(1 + o);
    result.plots.push_back({"dynamic_factor", factorColumns});

    // Time-simulation checks: the same model with only harmonic k of the
    // load, at frequency P, run until transients decay, then fitted.
    const auto& checks = sc.numbers("check_frequencies");
    if (!checks.empty()) {
        // The check forces the load at a chosen frequency: only a load that
        // can be so forced (a time clock) is checked.
        ElementSpec probe;
        for (const auto& el : spec.elements)
            if (el.name == sc.text("load")) probe = el;
        if (!load.setTimeCheckForcing(probe, k, checks.front()))
            throw sc.error("check_frequencies",
                           "'" + sc.text("load") + "' is forced by its shafts' angles: its harmonic " +
                               std::to_string(k) + " is at the shaft speed times its order, so no run at a chosen "
                               "frequency can check it; remove check_frequencies (a transient at the speed "
                               "checks the response)");
    }
    // The length of each check comes from the damping: the slowest mode
    // must decay by e^-14 before the fit. A mode that does not decay (or so
    // slowly that settling takes more than kMaxSettlePeriods periods) is
    // refused with the reason, unless settle_time says how long to run.
    double slowest = 0;  // smallest decay rate of a vibrating or decaying mode
    Complex slowestMode = 0;
    bool undamped = false;
    std::vector<double> undampedFrequencies;  // [rad/s]
    for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i) {
        const Complex lambda = lm.eigenvalues[i];
        if (isRigidEigenvalue(lm, lambda)) continue;  // a rigid-body mode: no transient to wait for
        const double rate = -lambda.real();
        if (rate <= 1e-12 * std::abs(lambda)) {
            undamped = true;
            slowestMode = lambda;
            undampedFrequencies.push_back(std::abs(lambda.imag()));
        } else if (slowest == 0 || rate < slowest) {
            slowest = rate;
            if (!undamped) slowestMode = lambda;
        }
    }
    constexpr double kMaxSettlePeriods = 20000;  // ~1e6 steps at 50 a period: minutes, not hours
    if (!checks.empty() && !(sc.number("settle_time") > 0)) {
        std::ostringstream mode;
        mode << slowestMode.real() << (slowestMode.imag() < 0 ? " - " : " + ") << std::abs(slowestMode.imag())
             << "i 1/s";
        if (undamped)
            throw sc.error("check_frequencies",
                           "the time-simulation check cannot settle: the mode with eigenvalue " + mode.str() +
                               " is undamped, so its transient never decays and the fit would measure it too; "
                               "add damping, or give settle_time to run that long anyway");
        for (const double P : checks) {
            const double settlePeriods = 14.0 / slowest / (2 * M_PI / P);
            if (settlePeriods > kMaxSettlePeriods) {
                std::ostringstream why;
                why << "the time-simulation check at " << P << " rad/s would run " << 14.0 / slowest
                    << " s (" << settlePeriods << " periods, more than " << kMaxSettlePeriods
                    << "): the slowest mode, eigenvalue " << mode.str() << ", decays at " << slowest
                    << " 1/s; give settle_time, or check at a lower frequency";
                throw sc.error("check_frequencies", why.str());
            }
        }
    }
    // A check where the row pattern cancels at a coupling (LoadResponse::
    // cancels: evenly staggered rows on one rigid body) has a linear
    // amplitude of round-off (~1e-16): the simulated one is the integrator's
    // error (~1e-9), and their relative difference (1.3e7 on the 2-mass
    // crusher) measures nothing. There the difference is given relative to
    // the amplitude of the rows in phase (last column `relative_to` 1), and
    // the phases, of round-off, are not compared (phase_diff 0).
    DataTable table{"time_checks",
                    {"frequency", "output", "linear_amplitude", "simulated_amplitude", "amplitude_rel_diff",
                     "linear_phase", "simulated_phase", "phase_diff", "relative_to"},
                    {"rad/s", "1", "N*m/N*m", "N*m/N*m", "1", "rad", "rad", "rad", "1"},
                    {}};
    double worstAmplitude = 0, worstPhase = 0, worstCancelled = 0;
    int compared = 0, cancelled = 0;
    for (std::size_t c = 0; c < checks.size(); ++c) {
        const double P = checks[c];
        const double period = 2 * M_PI / P;
        const double fitTime = sc.number("check_periods") * period;
        // Over fitTime a sinusoid at ω cannot be told from one at P when
        // |P − ω| < 2π/fitTime: an undamped mode's free vibration (which
        // never decays) would enter the fit, and at ω the linear amplitude
        // is unbounded.
        for (const double w : undampedFrequencies)
            if (std::abs(P - w) < 2 * M_PI / fitTime) {
                std::ostringstream why;
                why << "the time-simulation check at " << P << " rad/s is within " << 2 * M_PI / fitTime
                    << " rad/s (2*pi/fit length) of the undamped natural frequency " << w
                    << " rad/s: the linear amplitude is unbounded there and the fit would take in the free "
                       "vibration; add damping or check at another frequency";
                throw sc.error("check_frequencies", why.str());
            }
        ModelSpec checkSpec = spec;
        ElementSpec* e = nullptr;
        for (auto& el : checkSpec.elements)
            if (el.name == sc.text("load")) e = &el;
        const double b = 1.0;  // linear response: any amplitude; 1 N*m keeps the fit simple
        load.setTimeCheckForcing(*e, k, P);
        auto checkScene = buildScene(checkSpec);
        const SimTK::State start = solveSteadyState(*checkScene, initialState(*checkScene, checkSpec));
        const double settle = sc.number("settle_time") > 0 ? sc.number("settle_time")
                              : slowest > 0                ? 14.0 / slowest
                                                           : 20 * period;  // every mode rigid: nothing to wait for
        // The settle time is rounded up to whole periods, so the fit spans whole periods.
        const double tFit = std::ceil(settle / period) * period;
        // Samples are interpolated; a step of at most 1/50 period keeps the
        // interpolant's error far below the integration accuracy.
        IntegratorSpec integrator = checkSpec.integrator;
        integrator.maxStep = integrator.maxStep > 0 ? std::min(integrator.maxStep, period / 50) : period / 50;
        // A scheduled switching (a motor switched off, a load switched on,
        // a starter's step) inside the simulated span changes the operating
        // point the linear model is taken about: the comparison then
        // measures the event, not the linearization. Said, not hidden.
        for (const auto& ev : checkScene->switchEvents())
            if (ev.time > start.getTime() && ev.time <= start.getTime() + tFit + fitTime) {
                std::ostringstream why;
                why << "time check at " << P << " rad/s: its run (" << start.getTime() << " to "
                    << start.getTime() + tFit + fitTime << " s, fit window from " << start.getTime() + tFit
                    << " s) crosses the scheduled event " << ev.what << " at " << ev.time
                    << " s, which the linear model about steady running does not have; its differences measure "
                       "that event, not the linearization";
                result.notes.push_back(why.str());
            }
        Simulation sim(*checkScene, integrator);
        sim.initialize(start);
        std::vector<double> ts;
        std::vector<std::vector<double>> ys(outputs.size());
        sim.run(tFit + fitTime, period / 40, [&](const SimTK::State& s) {
            if (s.getTime() < tFit - 1e-12) return;
            ts.push_back(s.getTime());
            for (std::size_t o = 0; o < outputs.size(); ++o) ys[o].push_back(checkScene->probes()[outputs[o]].value(s));
        });
        for (std::size_t o = 0; o < outputs.size(); ++o) {
            const Fit fit = fitHarmonic(ts, ys[o], P);
            const Complex y = linearOutput(P, outputs[o]);
            const double linAmp = std::abs(y), linPhase = std::arg(y);
            const double ratio = response.patternRatio(P, k, outputs[o]);
            const double phaseDiff = wrapPhase(fit.phase - linPhase);
            if (ratio <= LoadResponse::kCancelled) {
                // The in-phase amplitude: linAmp / ratio, unless both vanish.
                const double inPhase = ratio > 0 ? linAmp / ratio : 0.0;
                const double diff = inPhase > 0 ? std::abs(fit.amplitude / b - linAmp) / inPhase : 0.0;
                worstCancelled = std::max(worstCancelled, diff);
                ++cancelled;
                table.rows.push_back({P, double(o), linAmp, fit.amplitude / b, diff, linPhase, fit.phase, 0.0, 1.0});
                char text[64];
                std::snprintf(text, sizeof text, "%.6g rad/s: %.1e", P, diff);
                result.notes.push_back("time check at " + std::string(text) + " of the in-phase amplitude at " +
                                       scene->probes()[outputs[o]].name + ": " + cancelNote(sc.text("load"), terms, k, ratio) +
                                       "; a relative difference to it would measure nothing");
                continue;
            }
            const double ampDiff = std::abs(fit.amplitude / b - linAmp) / linAmp;
            worstAmplitude = std::max(worstAmplitude, ampDiff);
            worstPhase = std::max(worstPhase, std::abs(phaseDiff));
            ++compared;
            table.rows.push_back({P, double(o), linAmp, fit.amplitude / b, ampDiff, linPhase, fit.phase, phaseDiff, 0.0});
        }
        if (progress) progress(double(c + 1), double(checks.size()));
    }
    if (!checks.empty()) result.extraTables.push_back(table);
    if (!checks.empty() && lm.Afull.size() && lm.motorModel != MotorModel::DqStates)
        result.notes.push_back(std::string("the time checks integrate the dq machines with their fluxes, the linear "
                                           "response here is motor_model ") +
                               motorModelName(lm.motorModel) +
                               ": their differences include that model's error (motor_model dq_states is the "
                               "linearization of what is simulated)");
    if (compared > 0) {
        result.results.push_back({"time_check_amplitude_rel_diff", worstAmplitude, "1",
                                  "largest |simulated − linear|/linear amplitude over the checks"});
        result.results.push_back({"time_check_phase_diff", worstPhase, "rad", "largest phase difference"});
    }
    if (cancelled > 0)
        result.results.push_back({"time_check_cancelled_rel_diff", worstCancelled, "1",
                                  "largest |simulated − linear| over the in-phase amplitude, over the checks where "
                                  "the row pattern cancels at the coupling"});
    result.notes.push_back("harmonic " + std::to_string(k) + " of " + sc.text("load") + ", " +
                           load.forcingDescription());
    return result;
}

AnalysisKind frequencyResponseKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& response = kind.schema;
    response.type = "frequency_response";
    response.doc = "Steady-state amplitude and phase of every coupling torque under one harmonic of a "
                   "periodic load (PeriodicLoad, AngleLoad: any load that declares its harmonics), from the "
                   "linear model, over a frequency range; optionally checked by time simulation at chosen "
                   "frequencies (a time-based load only).";
    response.params = {
        P::text("load", "name of the periodic load whose pattern over its rows or shafts is the forcing"),
        P::quantity("harmonic", "1", "harmonic k of the load (row phases k·φ_r; an AngleLoad's cycle harmonic k)")
            .optional(1.0).above(0)
            .atMost(1000),
        P::quantity("frequency_min", "rad/s", "lowest forcing frequency").above(0),
        P::quantity("frequency_max", "rad/s", "highest forcing frequency").above(0),
        P::quantity("points", "1", "frequencies, log-spaced").optional(200.0).atLeast(2).atMost(100000),
        P::quantityList("check_frequencies", "rad/s", 0, 20,
                        "frequencies at which a time simulation checks the linear response")
            .optional(0.0)
            .above(0),
        P::quantity("check_periods", "1", "forcing periods fitted in each time check").optional(20.0).atLeast(1),
        P::quantity("settle_time", "s", "time for transients to decay before fitting (0: from the slowest "
                                         "eigenvalue)").optional(0.0).atLeast(0),
        motorModelParam(),
    };
    response.crossCheck = [](const ElementSpec& e) {
        if (e.number("frequency_max") <= e.number("frequency_min"))
            throw e.error("frequency_max", "must exceed frequency_min");
        if (e.number("harmonic") != std::floor(e.number("harmonic")))
            throw e.error("harmonic", "must be a whole number");
    };
    kind.run = [](const ModelSpec& spec, const ProgressFn& progress, const SampleObserver&) {
        return runFrequencyResponse(spec, progress);
    };
    kind.timeIntegration = [](const ModelSpec&, const Scene&) {
        return std::string("only the optional time-domain check of the linear response");
    };
    return kind;
}

}  // namespace milldyn
