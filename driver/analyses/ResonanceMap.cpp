// resonance_map: the dynamic factor of every coupling torque against the
// rotor speed, the load harmonics following the speed (P_k = k·z·Ω for z
// load events per revolution), from the linear model about steady running.
//
// The factor at a speed superposes the harmonics at their worst phase:
// DF(Ω) = Σ_k b_k·A_k(k·z·Ω) / (Σ_k b_k · A_static), A as in LoadResponse.h.
// Speed bands where the first coupling's DF exceeds `threshold` are
// reported as bands to avoid.

#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"
#include "driver/analyses/LoadResponse.h"

#include <cmath>

namespace milldyn {

AnalysisResult runResonanceMap(const ModelSpec& spec, const ProgressFn& progress) {
    const ElementSpec& sc = spec.scenario;
    auto scene = buildScene(spec);
    const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    const LinearModel lm = linearizeScene(*scene, steady);
    const PeriodicLoad* load = scene->findElement<PeriodicLoad>(sc.text("load"));
    if (!load) throw sc.error("load", "'" + sc.text("load") + "' is not a PeriodicLoad element of this model");
    const LoadResponse response(*scene, lm, *load);
    const auto& outputs = response.couplingOutputs();
    if (outputs.empty()) throw sc.error("load", "the model has no coupling whose torque could respond");
    const auto& b = load->params().amplitudes;
    double bSum = 0;
    for (double v : b) bSum += v;
    if (!(bSum > 0)) throw sc.error("load", "the load has no harmonic amplitudes");

    const double z = sc.number("load_events_per_revolution");
    const double wMin = sc.number("speed_min"), wMax = sc.number("speed_max");
    const int points = static_cast<int>(sc.number("points"));
    const double threshold = sc.number("threshold");

    AnalysisResult result;
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
    for (std::size_t k = 0; k < b.size(); ++k) {
        result.columnNames.push_back(scene->probes()[outputs[0]].name + ".dynamic_factor_k" + std::to_string(k + 1));
        result.columnUnits.push_back("1");
    }
    std::vector<double> peak(outputs.size(), 0.0), peakAt(outputs.size(), 0.0);
    for (int i = 0; i < points; ++i) {
        const double w = wMin + (wMax - wMin) * i / (points - 1);
        std::vector<double> row = {w, w * 60 / (2 * M_PI)};
        std::vector<double> perHarmonic;
        for (std::size_t o = 0; o < outputs.size(); ++o) {
            double sum = 0;
            for (std::size_t k = 0; k < b.size(); ++k) {
                const double a = std::abs(response.output((k + 1) * z * w, static_cast<int>(k + 1), outputs[o]));
                sum += b[k] * a;
                if (o == 0) perHarmonic.push_back(a / response.staticReference(outputs[o]));
            }
            const double df = sum / (bSum * response.staticReference(outputs[o]));
            row.push_back(df);
            if (df > peak[o]) {
                peak[o] = df;
                peakAt[o] = w;
            }
        }
        row.insert(row.end(), perHarmonic.begin(), perHarmonic.end());
        result.rows.push_back(row);
        if (progress) progress(i + 1, points);
    }
    addLinearModelOutputs(lm, result);
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        const std::string& name = scene->probes()[outputs[o]].name;
        result.results.push_back({name + ".peak_dynamic_factor", peak[o], "1", "largest over the speed range"});
        result.results.push_back({name + ".peak_speed", peakAt[o], "rad/s", "rotor speed of that peak"});
    }
    // Bands of the first coupling (the drive's) above the threshold.
    int bands = 0;
    for (std::size_t i = 0; i < result.rows.size();) {
        if (result.rows[i][2] <= threshold) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < result.rows.size() && result.rows[j + 1][2] > threshold) ++j;
        ++bands;
        const std::string tag = "avoid_band_" + std::to_string(bands);
        result.results.push_back({tag + "_from", result.rows[i][0], "rad/s", "dynamic factor above threshold from"});
        result.results.push_back({tag + "_to", result.rows[j][0], "rad/s", "... to"});
        char text[160];
        std::snprintf(text, sizeof text, "avoid %.2f-%.2f rpm: %s dynamic factor above %.3g", result.rows[i][1],
                      result.rows[j][1], scene->probes()[outputs[0]].name.c_str(), threshold);
        result.notes.push_back(text);
        i = j + 1;
    }
    result.results.push_back({"avoid_bands", double(bands), "1", "speed bands above the threshold"});
    std::vector<std::size_t> cols;
    for (std::size_t o = 0; o < outputs.size(); ++o) cols.push_back(2 + o);
    result.plots.push_back({"resonance_map", cols});
    return result;
}

}  // namespace milldyn
