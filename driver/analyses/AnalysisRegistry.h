#pragma once
// The registry of analyses (issue 31 item 3): everything generic code asks
// of one analysis kind (`scenario.analysis`) in one AnalysisKind, listed
// once in AnalysisRegistry.cpp, as element types are listed in
// plugins/scene/BuiltinElements.cpp. The reader (its keys), dispatch
// (runAnalysis), `milldyn info` (describeModel: how it integrates in time),
// the scene builder (the energy meter), `--schematic`, the CLI's `analyses`
// command and the Python module read this list; none of them names an
// analysis.
//
// Adding an analysis: define `AnalysisKind fooKind()` in its own file
// beside `runFoo` (schema and run at least; set only the properties it
// has), then declare and list it in AnalysisRegistry.cpp (one line each),
// and add the file to CMakeLists.txt (docs/architecture.md).

#include "driver/analyses/Analysis.h"

#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// How `--schematic` spans a run of an analysis: the axis its instants are
/// on, the run's extent there, and the instants drawn by default.
struct SchematicSpan {
    bool angles = false;             ///< carrier angles [rad]; else times [s]
    double from = 0, to = 0;         ///< the run's extent, from <= to
    std::vector<double> defaults;    ///< drawn when --schematic-at gives none
};

/// One analysis kind. Only `schema` and `run` are required; every other
/// property left empty means "this analysis does not" (integrate in time,
/// keep given initial states, draw a schematic, ...).
struct AnalysisKind {
    /// Its scenario keys (schema.type is the kind's name, `scenario.analysis`).
    ElementSchema schema;
    /// Runs it; throws AnalysisError when it fails. `observer` sees every
    /// sample of a kind that has a schematicSpan (others never call it).
    std::function<AnalysisResult(const ModelSpec&, const ProgressFn&, const SampleObserver&)> run;
    /// How it integrates in time, in words for `milldyn info`, for this
    /// model and its built scene. Empty: "none (KIND analysis)".
    std::function<std::string(const ModelSpec&, const Scene&)> timeIntegration;
    /// Whether it can solve an element condition of each instant (a held
    /// charge's wall torque: ElementSchema::AnalysisNeed::EachInstant).
    bool solvesEachInstant = false;
    /// Whether it carries a history from step to step (a frozen charge's
    /// release latch: AnalysisNeed::StepHistory).
    bool carriesStepHistory = false;
    /// Whether this scenario keeps the state elements' initialStateKeys set
    /// at t = 0 (empty: never; any given one is refused).
    std::function<bool(const ElementSpec& scenario)> keepsInitialState;
    /// Whether it reports an energy balance (the scene builder then builds
    /// the energy meter, whose integrals are states every step carries).
    bool reportsEnergyBalance = false;
    /// How `--schematic` spans this scenario's run. Empty: it draws none.
    std::function<SchematicSpan(const ElementSpec& scenario)> schematicSpan;
};

/// Scenario keys several analyses share: `stop_speed` of those that detect
/// a shaft coming to rest (checked by checkStopSpeed; Analysis.cpp), and
/// `motor_model` of those that build a linear model (LinearModel.cpp).
ParamSchema stopSpeedParam();
ParamSchema motorModelParam();

/// The registered kind of that name; nullptr if none.
const AnalysisKind* findAnalysisKind(const std::string& name);

/// Every registered kind, by name.
std::vector<const AnalysisKind*> analysisKindList();

}  // namespace milldyn
