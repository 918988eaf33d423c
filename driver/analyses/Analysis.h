#pragma once
// The analyses a model file's `scenario:` can ask for, and what they return.

#include "driver/ModelFile.h"
#include "driver/ModelSpec.h"
#include "driver/Simulation.h"

#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// One named result with its unit, for summary.json and the printed summary.
struct ResultScalar {
    std::string name;
    double value = 0;
    std::string unit;
    std::string doc;
    /// For a torque: the body (shaft) it acts on, as the value is given —
    /// a coupling's torque on its driving (from) shaft, a gear pair's on
    /// gear 1; several names, comma-separated, for a sum over loads on
    /// different shafts. Empty for other quantities.
    std::string referredTo = {};
};

/// A further table an analysis writes as NAME.csv.
struct DataTable {
    std::string name;
    std::vector<std::string> columnNames;
    std::vector<std::string> columnUnits;
    std::vector<std::vector<double>> rows;
};

/// A matrix an analysis reports (linear_model.json).
struct NamedMatrix {
    std::string name;
    std::string unit;
    std::vector<std::vector<double>> rows;
};

/// A curve of a figure's panel: one column of the main table, or the sum of
/// several (the loads on one shaft), drawn from the table's CSV.
struct PlotCurve {
    std::string title;
    std::vector<std::size_t> columns;  ///< one: that column; several: their sum
};
/// One panel of a figure: curves of one quantity in one unit; torques of
/// one shaft only (issue 29 item 3: torques on different shafts never share
/// a panel).
struct PlotPanel {
    std::string title;   ///< "torques on mill"
    std::string yLabel;  ///< "torque [N*m]"
    std::string shaft;   ///< the body whose torques these are; empty for other quantities
    std::vector<PlotCurve> curves;
};
/// A vertical line at an instant the summary reports (start_time, a starter
/// step, a sequence's end), drawn at that result's value.
struct PlotMarker {
    double x = 0;
    std::string label;  ///< the result's name: "start_time"
};
/// A figure that answers one question (issue 29 item 3): NAME.png, its
/// panels stacked over one x axis (column 0), over [xFrom, xTo] when
/// xTo > xFrom, else the whole table.
struct PlotFigure {
    std::string name;
    std::string title;
    std::vector<PlotPanel> panels;
    std::vector<PlotMarker> markers;
    double xFrom = 0, xTo = 0;
};

struct AnalysisResult {
    std::string analysis;
    /// The main table, written as TABLENAME.csv (plots read it): column i is
    /// columnNames[i] in columnUnits[i].
    std::string tableName = "timeseries";
    std::vector<std::string> columnNames;
    std::vector<std::string> columnUnits;
    /// Column i's axis label (what it is and its sign convention, from
    /// Probe::label); may be shorter than columnNames, empty entries where
    /// the name and unit say it.
    std::vector<std::string> columnLabels;
    std::vector<std::vector<double>> rows;
    std::vector<ResultScalar> results;
    /// Values the elements derive from their parameters (Scene::addDerivedValue).
    std::vector<ResultScalar> derived;
    std::vector<std::string> notes;  ///< what happened, in words
    /// A transient's start verdict: "completed", "stalled", "unfinished"
    /// (empty: no start was simulated), and the sentence that says why
    /// with the numbers. A run whose start stalled exits 3.
    std::string verdict;
    std::string verdictText;
    RunStatistics statistics;
    /// The columns worth a plot (indices into columnNames) and their titles.
    std::vector<std::pair<std::string, std::vector<std::size_t>>> plots;
    /// Figures per question (start, steady operation, torques per shaft,
    /// belts, currents): a figure named as a plot replaces it, the others
    /// are drawn after the plots.
    std::vector<PlotFigure> figures;
    /// The quantity on the plots' x axis (column 0 of the main table).
    std::string plotXLabel = "time [s]";
    std::vector<DataTable> extraTables;
    /// Degree-of-freedom names and matrices (linear models), if any.
    std::vector<std::string> dofNames;
    std::vector<NamedMatrix> matrices;

    const ResultScalar* find(const std::string& name) const;
    /// Index of the main table's column `name`, or npos.
    std::size_t findColumn(const std::string& name) const;
    /// The main table's value in row `row`, column `name`; throws
    /// std::runtime_error naming the column if there is none.
    double value(std::size_t row, const std::string& name) const;
};

/// The reader that knows every registered element type and analysis kind.
ModelFileReader defaultModelReader();

/// Reads a model file with overrides and runs its scenario.
AnalysisResult runModelFile(const std::string& path, const std::vector<Override>& overrides,
                            ModelSpec* specOut = nullptr);

/// A scenario of this kind with every key at its default (validation cases
/// and tests build scenarios in code, then set the keys they need).
ElementSpec defaultScenario(const std::string& kind);

/// The keys each analysis kind accepts (for the model-file reader).
const ElementSchema* findAnalysisSchema(const std::string& kind);
std::vector<std::string> analysisKinds();

/// Reports progress (simulated time, end time) of a long run.
using ProgressFn = std::function<void(double, double)>;

/// Sees every sample a transient or kinetostatic analysis records: its
/// scene, the state (realized to Stage::Acceleration) and the table row's
/// first column (time [s] or carrier angle [rad]). The schematic draws
/// from it (driver/outputs/Schematic.h).
using SampleObserver = std::function<void(const Scene&, const SimTK::State&, double key)>;

/// Runs the model's scenario. Throws AnalysisError when it fails.
AnalysisResult runAnalysis(const ModelSpec& spec, const ProgressFn& progress = {},
                           const SampleObserver& observer = {});

// The analyses themselves (one file each).
AnalysisResult runTransient(const ModelSpec& spec, const ProgressFn& progress,
                            const SampleObserver& observer = {});
AnalysisResult runCoastdownIdentify(const ModelSpec& spec, const ProgressFn& progress);
AnalysisResult runLinearize(const ModelSpec& spec, const ProgressFn& progress);
AnalysisResult runKinetostatic(const ModelSpec& spec, const ProgressFn& progress,
                               const SampleObserver& observer = {});
AnalysisResult runFrequencyResponse(const ModelSpec& spec, const ProgressFn& progress);
AnalysisResult runResonanceMap(const ModelSpec& spec, const ProgressFn& progress);
AnalysisResult runStaticDeflection(const ModelSpec& spec, const ProgressFn& progress);

/// The scene's derived values as results (AnalysisResult::derived).
std::vector<ResultScalar> derivedResults(const Scene& scene);

/// The shaft a probe named ELEMENT.x acts on: the element's first body key
/// (`body`, `drum`, `carrier`, the first of `bodies`: a coupling's driving
/// shaft, a gear pair's gear 1), or every body of a body list (comma-
/// separated). Empty for a probe that is not ELEMENT.x of a model element.
std::string probeShaft(const ModelSpec& spec, const std::string& probeName);
/// The model's elements that act on `body` (any of their body keys names
/// it), comma-separated; empty if none.
std::string elementsOnBody(const ModelSpec& spec, const std::string& body);
/// The distinct shafts of every probe with this role, comma-separated.
std::string probeShafts(const ModelSpec& spec, const Scene& scene, ProbeRole role);

/// Sum of every probe with this role in this state.
double sumProbes(const Scene& scene, const SimTK::State& state, ProbeRole role);

/// Throws SpecError if scenario.stop_speed lies inside a load's
/// regularisation band.
void checkStopSpeed(const ModelSpec& spec);
/// The registered schema of `e`'s type (its capabilities); nullptr if unknown.
const ElementSchema* schemaOf(const ElementSpec& e);

/// Watches a body's speed falling to zero (stop detected at `threshold`).
Simulation::Watch speedWatch(const SimTK::MobilizedBody& body, double threshold, double notBefore,
                             const std::string& what);

/// The body a scenario names under `key`, or the first body when unset.
const SceneBody& scenarioBody(const Scene& scene, const ElementSpec& scenario, const std::string& key);

/// Adds the energy balance of a run from `start` to `end` (the work of every
/// source, load and dissipation, the changes of kinetic and potential
/// energy, and the residual of ΔKE + ΔPE = W_sources − W_loads − W_dissipated).
void addEnergyBalance(const Scene& scene, const SimTK::State& start, const SimTK::State& end,
                      AnalysisResult& result);

/// Adds the power split of the window [from, to] of one run (both samples
/// of it): the mean power of every EnergyCategory present (motor input,
/// motor loss, grinding, friction, damping), the mechanical shaft input,
/// the rates of change of kinetic, gravitational and elastic energy, and
/// the residual of motor_input − motor_loss = grinding + friction + damping
/// + d(stored)/dt. `window` says which window in words. False (nothing
/// added) without an energy meter or for an empty window.
bool addMeanPower(const Scene& scene, const SimTK::State& from, const SimTK::State& to, const std::string& window,
                  AnalysisResult& result);

/// Adds the usual plots: every speed column, every torque column.
void addDefaultPlots(AnalysisResult& result);

/// The table column of a body's pin speed: `NAME.speed` on ground, else
/// `NAME.speed_rel_PARENT` (a drum's speed relative to its carrier is not
/// an absolute speed: issue 20 item 10).
std::string speedColumnName(const Scene& scene, const SceneBody& body);

/// Records samples of a scene into an AnalysisResult's table.
class SampleTable {
public:
    SampleTable(const Scene& scene, AnalysisResult& result);
    /// One row: time, every body's angle and speed, then `probeValues`
    /// (the scene's probes at `state`, as Simulation::probeValues() has them).
    void record(const SimTK::State& state, const std::vector<double>& probeValues);
    /// Column index of a name, or npos.
    std::size_t column(const std::string& name) const;

private:
    const Scene& m_scene;
    AnalysisResult& m_result;
};

}  // namespace milldyn
