// resonance_map: the dynamic factor of every coupling torque against the
// rotor speed, the load harmonics following the speed, from the linear
// model about steady running. A time-clock load's harmonic k is taken at
// P_k = k·z·Ω (z load events per revolution, a scenario key); a
// shaft-angle load's at its own order o_k (events per revolution of its
// shaft) times its shaft's speed, ρ_g·Ω for the shafts of group g (speed
// ratio ρ_g to the rotor in steady running).
//
// The factor at a speed superposes the harmonics (and groups) at their
// worst phase: DF(Ω) = Σ_k B_k·Σ_g A_kg(P_kg) / (Σ_k B_k · A_static), A
// and the groups as in LoadResponse.h.
// Speed bands where the first coupling's DF exceeds `threshold` are
// reported as bands to avoid.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/analyses/LinearModel.h"
#include "driver/analyses/LoadResponse.h"

#include <cmath>
#include <cstdio>

namespace milldyn {

namespace {

/// The scene's order excitations (a gear pair's tooth-mesh frequency
/// z·|ω_gear|) against the rotor speed Ω: the steady speed ratio ρ =
/// ω_gear/Ω makes each a line f = z·|ρ|·Ω; where it meets an elastic
/// natural frequency ω_k, at Ω_k = ω_k/(z|ρ|), the mesh excites mode k.
/// Adds a column per excitation to `result` (values per row of `speeds`)
/// and the crossings in the range as results and notes.
void addOrderExcitations(const Scene& scene, const SimTK::State& steady, const LinearModel& lm,
                         const SceneBody& rotor, double wMin, double wMax, AnalysisResult& result) {
    const double rotorSpeed = pinSpeed(steady, rotor.mobod);
    for (const auto& e : scene.orderExcitations()) {
        const SceneBody* body = scene.findBody(e.body);
        if (!body || !(std::abs(rotorSpeed) > 0)) continue;
        const double perRotor = e.eventsPerRevolution * std::abs(pinSpeed(steady, body->mobod) / rotorSpeed);
        result.columnNames.push_back(e.name);
        result.columnUnits.push_back("rad/s");
        for (auto& row : result.rows) row.push_back(perRotor * row[0]);
        // The same in Hz beside (the probe NAME.mesh_frequency of a run is Hz).
        result.columnNames.push_back(e.name + "_hz");
        result.columnUnits.push_back("Hz");
        for (auto& row : result.rows) row.push_back(perRotor * row[0] / (2 * M_PI));
        result.results.push_back({e.name + ".per_rotor_speed", perRotor, "1",
                                  "excitation frequency per rotor speed: z x (speed of " + e.body + ")/(speed of " +
                                      rotor.name + ") at steady running"});
        int elastic = 0;  // numbered as every output numbers them: elastic modes from 1 (elasticModes)
        for (int k : elasticModes(lm)) {
            const double wk = lm.naturalFrequencies[k];
            ++elastic;
            const double at = wk / perRotor;
            if (at < wMin || at > wMax) continue;
            const std::string tag = e.name + ".meets_mode_" + std::to_string(elastic);
            result.results.push_back({tag + "_at_rotor_speed", at, "rad/s",
                                      "rotor speed where this excitation equals natural frequency " +
                                          std::to_string(elastic)});
            char text[200];
            std::snprintf(text, sizeof text, "%s meets mode %d (%.4g Hz) at %.4g rpm of %s", e.name.c_str(), elastic,
                          wk / (2 * M_PI), at * 60 / (2 * M_PI), rotor.name.c_str());
            result.notes.push_back(text);
        }
    }
}

/// resonance_map without a load: the order excitations only (a Campbell
/// diagram of the tooth-mesh frequencies against the natural frequencies).
AnalysisResult runOrderMap(const ModelSpec& spec, const Scene& scene, const SimTK::State& steady,
                           const LinearModel& lm, const ProgressFn& progress) {
    const ElementSpec& sc = spec.scenario;
    const SceneBody* rotor = scene.findBody(sc.text("rotor"));
    if (!rotor) throw sc.error("rotor", "'" + sc.text("rotor") + "' is not a body of this model");
    if (scene.orderExcitations().empty())
        throw sc.error("rotor", "the model has no excitation that follows the speed (a GearPair with teeth or "
                                "module) and no load");
    AnalysisResult result;
    result.derived = derivedResults(scene);
    result.analysis = "resonance_map";
    result.tableName = "resonance_map";
    result.plotXLabel = "rotor speed [rad/s]";
    result.columnNames = {"rotor_speed", "rotor_speed_rpm"};
    result.columnUnits = {"rad/s", "rpm"};
    const double wMin = sc.number("speed_min"), wMax = sc.number("speed_max");
    const int points = static_cast<int>(sc.number("points"));
    for (int i = 0; i < points; ++i) {
        const double w = wMin + (wMax - wMin) * i / (points - 1);
        result.rows.push_back({w, w * 60 / (2 * M_PI)});
    }
    addOrderExcitations(scene, steady, lm, *rotor, wMin, wMax, result);
    int elastic = 0;
    for (int k : elasticModes(lm)) {
        const std::string number = std::to_string(++elastic);
        result.columnNames.push_back("natural_frequency_" + number);
        result.columnUnits.push_back("rad/s");
        for (auto& row : result.rows) row.push_back(lm.naturalFrequencies[k]);
        result.columnNames.push_back("natural_frequency_" + number + "_hz");
        result.columnUnits.push_back("Hz");
        for (auto& row : result.rows) row.push_back(lm.naturalFrequencies[k] / (2 * M_PI));
    }
    addLinearModelOutputs(lm, result);
    // The plot in rad/s (the Hz columns beside are the same lines).
    std::vector<std::size_t> cols;
    for (std::size_t c = 2; c < result.columnNames.size(); ++c)
        if (result.columnUnits[c] == "rad/s") cols.push_back(c);
    result.plots.push_back({"resonance_map", cols});
    if (progress) progress(points, points);
    return result;
}

}  // namespace

AnalysisResult runResonanceMap(const ModelSpec& spec, const ProgressFn& progress) {
    const ElementSpec& sc = spec.scenario;
    auto scene = buildScene(spec);
    const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    // Rigid meshes (GearPair, GearMesh, PlanetaryGearSet, BeltDrive) are
    // reduced to independent coordinates, as linearize does.
    // The dq machines' fluxes as scenario.motor_model says (default their states).
    const LinearModel lm =
        linearizeScene(*scene, steady, true, true, motorModelFromName(sc.text("motor_model")));
    const std::vector<std::string> motorNotes = motorDampingNotes(*scene, lm);
    if (sc.text("load").empty()) {
        AnalysisResult orders = runOrderMap(spec, *scene, steady, lm, progress);
        orders.notes.insert(orders.notes.end(), motorNotes.begin(), motorNotes.end());
        return orders;
    }
    const HarmonicForcing* load = scene->findElement<HarmonicForcing>(sc.text("load"));
    if (!load)
        throw sc.error("load", "'" + sc.text("load") + "' is not an element of this model with a periodic forcing "
                                                       "(a load that declares its harmonics)");
    const bool timeClock = load->forcingClock() == HarmonicForcing::Clock::Time;
    // Given means > 0 (the key's default 0 is "none"; a scenario built in
    // code sets the number without marking it given).
    const bool eventsGiven = sc.number("load_events_per_revolution") > 0;
    if (timeClock && !eventsGiven)
        throw sc.error("load", "'" + sc.text("load") + "' is a function of time: give load_events_per_revolution "
                                                       "(z, its fundamental P_1 = z·Ω)");
    if (!timeClock && eventsGiven)
        throw sc.error("load_events_per_revolution",
                       "not used: the harmonics of '" + sc.text("load") +
                           "' follow its shafts' angles, at the orders it declares (cycles per revolution)");
    const LoadResponse response(*scene, lm, *load, steady);
    const auto& outputs = response.couplingOutputs();
    if (outputs.empty()) throw sc.error("load", "the model has no coupling whose torque could respond");
    std::vector<double> b;
    for (int k = 1; k <= load->forcingHarmonicCount(); ++k) b.push_back(load->forcingAmplitude(k));
    double bSum = 0;
    for (double v : b) bSum += v;
    if (!(bSum > 0)) throw sc.error("load", "the load has no harmonic amplitudes");
    const std::vector<double>& groups = response.groupSpeedRatios();

    const double z = timeClock ? sc.number("load_events_per_revolution") : 0.0;
    const double wMin = sc.number("speed_min"), wMax = sc.number("speed_max");
    const int points = static_cast<int>(sc.number("points"));
    const double threshold = sc.number("threshold");

    AnalysisResult result;
    result.notes = motorNotes;
    result.derived = derivedResults(*scene);
    result.analysis = "resonance_map";
    result.tableName = "resonance_map";
    result.plotXLabel = "rotor speed [rad/s]";
    result.columnNames = {"rotor_speed", "rotor_speed_rpm"};
    result.columnUnits = {"rad/s", "rpm"};
    for (int p : outputs) {
        result.columnNames.push_back(scene->probes()[p].name + ".dynamic_factor");
        result.columnUnits.push_back("1");
    }
    // Each harmonic's share, for every coupling.
    for (int p : outputs)
        for (std::size_t k = 0; k < b.size(); ++k) {
            result.columnNames.push_back(scene->probes()[p].name + ".dynamic_factor_k" + std::to_string(k + 1));
            result.columnUnits.push_back("1");
        }
    // A peak is taken only among speeds where some harmonic reaches the
    // coupling: where every harmonic's row pattern cancels there
    // (LoadResponse::cancels) the factor is round-off (~1e-16), not a response.
    std::vector<double> peak(outputs.size(), 0.0), peakAt(outputs.size(), 0.0), worstRatio(outputs.size(), 0.0);
    std::vector<std::size_t> peakRow(outputs.size(), 0);
    std::vector<bool> reached(outputs.size(), false);
    for (int i = 0; i < points; ++i) {
        const double w = wMin + (wMax - wMin) * i / (points - 1);
        std::vector<double> row = {w, w * 60 / (2 * M_PI)};
        std::vector<double> perHarmonic;
        for (std::size_t o = 0; o < outputs.size(); ++o) {
            double sum = 0;
            bool cancelled = true;
            for (std::size_t k = 0; k < b.size(); ++k) {
                const int harmonic = static_cast<int>(k + 1);
                double a = 0;
                for (std::size_t g = 0; g < groups.size(); ++g) {
                    const int group = static_cast<int>(g);
                    const double P = timeClock ? (k + 1) * z * w : load->forcingOrder(harmonic) * groups[g] * w;
                    a += std::abs(response.output(P, harmonic, outputs[o], group));
                    if (b[k] > 0) {
                        const double ratio = response.patternRatio(P, harmonic, outputs[o], group);
                        worstRatio[o] = std::max(worstRatio[o], ratio);
                        cancelled = cancelled && ratio <= LoadResponse::kCancelled;
                    }
                }
                sum += b[k] * a;
                perHarmonic.push_back(a / response.staticReference(outputs[o]));
            }
            const double df = sum / (bSum * response.staticReference(outputs[o]));
            row.push_back(df);
            if (!cancelled && (!reached[o] || df > peak[o])) {
                peak[o] = df;
                peakAt[o] = w;
                peakRow[o] = static_cast<std::size_t>(i);
                reached[o] = true;
            }
        }
        row.insert(row.end(), perHarmonic.begin(), perHarmonic.end());
        result.rows.push_back(row);
        if (progress) progress(i + 1, points);
    }
    addLinearModelOutputs(lm, result);
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        const std::string& name = scene->probes()[outputs[o]].name;
        if (!reached[o]) {
            result.results.push_back({name + ".pattern_ratio", worstRatio[o], "1",
                                      "largest amplitude of the load's row pattern over the in-phase rows' amplitude, "
                                      "over speeds and harmonics: round-off, the forcing cancels"});
            char ratio[32];
            std::snprintf(ratio, sizeof ratio, "%.1e", worstRatio[o]);
            const std::string terms = load->forcingTermName();
            result.notes.push_back(name + ": no peak: the " + terms + " of " + sc.text("load") +
                                   " cancel at this coupling at every speed and harmonic (amplitude at most " + ratio +
                                   " of the " + terms + "' in-phase amplitude: round-off); its dynamic factors are "
                                   "zero but for round-off");
            continue;
        }
        result.results.push_back({name + ".peak_dynamic_factor", peak[o], "1", "largest over the speed range"});
        result.results.push_back({name + ".peak_speed", peakAt[o], "rad/s", "rotor speed of that peak"});
        // The peak with its band (the speeds around it above the
        // threshold) or a note that it stays below; and what limits it.
        const std::size_t column = 2 + o;
        std::size_t from = peakRow[o], to = peakRow[o];
        while (from > 0 && result.rows[from - 1][column] > threshold) --from;
        while (to + 1 < result.rows.size() && result.rows[to + 1][column] > threshold) ++to;
        char text[400];
        if (peak[o] > threshold) {
            result.results.push_back({name + ".peak_band_from", result.rows[from][0], "rad/s",
                                      "the band around the peak where the dynamic factor exceeds the threshold, from"});
            result.results.push_back({name + ".peak_band_to", result.rows[to][0], "rad/s", "... to"});
            std::snprintf(text, sizeof text, "%s: peak dynamic factor %.4g at %.5g rpm, in the band %.5g-%.5g rpm above "
                                             "the threshold %.3g",
                          name.c_str(), peak[o], peakAt[o] * 60 / (2 * M_PI), result.rows[from][1], result.rows[to][1],
                          threshold);
        } else {
            std::snprintf(text, sizeof text, "%s: peak dynamic factor %.4g at %.5g rpm stays below the threshold %.3g: "
                                             "no band to avoid",
                          name.c_str(), peak[o], peakAt[o] * 60 / (2 * M_PI), threshold);
        }
        std::string note = text;
        // The harmonic that dominates the peak and the mode nearest its
        // frequency: a resonance's peak is set by that mode's damping.
        std::size_t dominant = 0;
        const std::size_t perHarmonic0 = 2 + outputs.size() + o * b.size();
        for (std::size_t k = 1; k < b.size(); ++k)
            if (b[k] * result.rows[peakRow[o]][perHarmonic0 + k] > b[dominant] * result.rows[peakRow[o]][perHarmonic0 + dominant])
                dominant = k;
        const double P = timeClock ? (dominant + 1) * z * peakAt[o]
                                   : load->forcingOrder(int(dominant + 1)) * std::abs(groups.empty() ? 1.0 : groups[0]) * peakAt[o];
        int nearest = -1;
        for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i)
            if (lm.eigenvalues[i].imag() > 0 && !isRigidEigenvalue(lm, lm.eigenvalues[i]) &&
                (nearest < 0 || std::abs(lm.eigenvalues[i].imag() - P) < std::abs(lm.eigenvalues[nearest].imag() - P)))
                nearest = int(i);
        if (nearest >= 0) {
            const auto l = lm.eigenvalues[nearest];
            const double zeta = -l.real() / std::abs(l);
            if (std::abs(P - l.imag()) <= 0.2 * l.imag())
                std::snprintf(text, sizeof text, "; harmonic %zu at %.4g Hz meets the damped mode at %.4g Hz, damping "
                                                 "ratio %.3g (a resonance peaks near 1/(2·ratio) = %.3g times its "
                                                 "static response)",
                              dominant + 1, P / (2 * M_PI), l.imag() / (2 * M_PI), zeta, zeta > 0 ? 1 / (2 * zeta) : 0.0);
            else
                std::snprintf(text, sizeof text, "; harmonic %zu at %.4g Hz, no mode within 20 %% (nearest damped mode "
                                                 "%.4g Hz): not a resonance",
                              dominant + 1, P / (2 * M_PI), l.imag() / (2 * M_PI));
            note += text;
        }
        // A coupling the load hardly loads quasi-statically (a free
        // flywheel's shaft: its torque is inertia, ∝ P²) has a factor over
        // almost nothing: say so, with the amplitude it stands for.
        double largestReference = 0;
        for (int p : outputs) largestReference = std::max(largestReference, response.staticReference(p));
        const double reference = response.staticReference(outputs[o]);
        result.results.push_back({name + ".static_reference", reference, "1",
                                  "quasi-static in-phase amplitude per unit harmonic amplitude (the factor's denominator)"});
        if (reference < 0.01 * largestReference) {
            std::snprintf(text, sizeof text, "; its quasi-static response %.3g (per unit load amplitude) is %.2g of the "
                                             "largest coupling's: the factor is over almost nothing, not a magnification "
                                             "(its peak amplitude is %.3g per unit load amplitude)",
                          reference, reference / largestReference, peak[o] * reference);
            note += text;
        }
        if (from == to && peak[o] > threshold)
            note += "; the band is one grid point wide: the peak's value depends on the grid (refine points or "
                    "narrow the range around it)";
        if (peakRow[o] == 0 || peakRow[o] + 1 == result.rows.size())
            note += "; the peak is at the edge of the speed range: it may rise beyond it";
        result.notes.push_back(note);
    }
    // Bands above the threshold, for every coupling (NAME.avoid_band_i_*);
    // avoid_band_i_* and avoid_bands without a name are the first
    // coupling's (the drive's), as before.
    int firstBands = 0;
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        const std::string& name = scene->probes()[outputs[o]].name;
        const std::size_t column = 2 + o;
        int bands = 0;
        for (std::size_t i = 0; i < result.rows.size();) {
            if (result.rows[i][column] <= threshold) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j + 1 < result.rows.size() && result.rows[j + 1][column] > threshold) ++j;
            ++bands;
            const std::string tag = "avoid_band_" + std::to_string(bands);
            result.results.push_back({name + "." + tag + "_from", result.rows[i][0], "rad/s",
                                      "dynamic factor of " + name + " above threshold from"});
            result.results.push_back({name + "." + tag + "_to", result.rows[j][0], "rad/s", "... to"});
            if (o == 0) {
                result.results.push_back({tag + "_from", result.rows[i][0], "rad/s",
                                          "dynamic factor above threshold from (the first coupling, " + name + ")"});
                result.results.push_back({tag + "_to", result.rows[j][0], "rad/s", "... to"});
            }
            char text[200];
            std::snprintf(text, sizeof text, "avoid %.2f-%.2f rpm: %s dynamic factor above %.3g", result.rows[i][1],
                          result.rows[j][1], name.c_str(), threshold);
            result.notes.push_back(text);
            i = j + 1;
        }
        result.results.push_back({name + ".avoid_bands", double(bands), "1", "speed bands above the threshold"});
        if (o == 0) firstBands = bands;
    }
    result.results.push_back({"avoid_bands", double(firstBands), "1",
                              "speed bands above the threshold of the first coupling (" +
                                  scene->probes()[outputs[0]].name + ")"});
    // The load's first body is the rotor whose speed is swept.
    const std::vector<SimTK::MobilizedBody> loadBodies = load->forcingBodies();
    for (const auto& rotor : scene->bodies())
        if (!loadBodies.empty() && rotor.mobod.getMobilizedBodyIndex() == loadBodies[0].getMobilizedBodyIndex())
            addOrderExcitations(*scene, steady, lm, rotor, wMin, wMax, result);
    std::vector<std::size_t> cols;
    for (std::size_t o = 0; o < outputs.size(); ++o) cols.push_back(2 + o);
    result.plots.push_back({"resonance_map", cols});
    return result;
}

AnalysisKind resonanceMapKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& map = kind.schema;
    map.type = "resonance_map";
    map.doc = "Dynamic factor of every coupling torque against rotor speed, the load harmonics following "
              "the speed; bands above a threshold are reported as speeds to avoid.";
    map.params = {
        P::text("load", "name of the periodic load (PeriodicLoad, AngleLoad; none: gear-mesh frequencies only)")
            .optional(std::string("")),
        P::text("rotor", "body whose speed is swept when there is no load").optional(std::string("")),
        P::quantity("speed_min", "rad/s", "lowest rotor speed").above(0),
        P::quantity("speed_max", "rad/s", "highest rotor speed").above(0),
        P::quantity("points", "1", "speeds, evenly spaced").optional(600.0).atLeast(2).atMost(100000),
        P::quantity("load_events_per_revolution", "1",
                    "z: P_1 = z·Ω (teeth per sprocket row); a time-based load only (an AngleLoad's orders are "
                    "its own)").optional(0.0)
            .above(0),
        P::quantity("threshold", "1", "dynamic factor above which a speed band is to be avoided")
            .optional(1.3).above(0),
        motorModelParam(),
    };
    map.crossCheck = [](const ElementSpec& e) {
        if (e.number("speed_max") <= e.number("speed_min")) throw e.error("speed_max", "must exceed speed_min");
        if (!e.has("load") && e.has("load_events_per_revolution"))
            throw e.error("load_events_per_revolution", "not used without a load");
        if (!e.has("load") && !e.has("rotor"))
            throw e.error("load", "give a periodic load (load) or, for gear-mesh frequencies only, the rotor body (rotor)");
        if (e.has("load") && e.has("rotor")) throw e.error("rotor", "not used with a load (the load's body is the rotor)");
    };
    kind.run = [](const ModelSpec& spec, const ProgressFn& progress, const SampleObserver&) {
        return runResonanceMap(spec, progress);
    };
    return kind;
}

}  // namespace milldyn
