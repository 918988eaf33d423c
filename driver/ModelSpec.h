#pragma once
// ModelSpec: a model file after reading and checking. Plain structs in SI
// units; knows nothing of Simbody (the SceneBuilder turns it into a Scene)
// and nothing of YAML (ModelFile reads it).

#include "plugins/scene/ElementSchema.h"

#include <array>
#include <string>
#include <vector>

namespace milldyn {

constexpr int kModelFormatVersion = 1;

/// How a body is attached to its parent. Only a pin (rotation about the
/// parent's z axis) exists so far.
struct JointSpec {
    std::string type = "pin";
    std::string parent = "ground";
    /// Joint origin in the parent frame [m].
    std::array<double, 3> location{{0, 0, 0}};
    SourceLocation where;
};

struct BodySpec {
    std::string name;
    /// Polar moment of inertia about the joint axis [kg*m^2], > 0.
    double inertia = 0;
    /// Mass [kg], >= 0 (a shaft on a pin needs none).
    double mass = 0;
    /// Mass centre in the body frame, whose origin is on the joint axis [m].
    /// Off the axis it needs a mass, and `inertia` (about the joint axis)
    /// must exceed mass*|xy|^2 (parallel-axis theorem).
    std::array<double, 3> massCentre{{0, 0, 0}};
    JointSpec joint;
    double initialAngle = 0;  ///< [rad]
    double initialSpeed = 0;  ///< [rad/s]
    /// Fidelity levels this body belongs to (empty: all).
    std::vector<std::string> fidelity;
    SourceLocation where;
};

struct IntegratorSpec {
    std::string name = "CPodes";
    double accuracy = 1e-6;  ///< relative accuracy [-]
    double maxStep = 0;      ///< [s]; 0: integrator's choice
    SourceLocation where;
};

struct OutputSpec {
    double sampleInterval = 1e-3;  ///< [s] between CSV rows
    bool plots = true;
    /// `columns:` the outputs wanted, by element name (all its outputs) or
    /// output name; empty: all. Output-only elements nobody names are not
    /// built and other elements' unnamed outputs are not evaluated; the
    /// outputs the analysis itself summarises (drive, load, coupling
    /// torques) and the bodies' angles and speeds are always kept.
    std::vector<std::string> columns;
    std::vector<SourceLocation> columnWhere;  ///< where each column was named
    /// `peaks:` outputs whose largest |value| over the run and value at the
    /// end (before switch-off) the transient summary reports
    /// (peak.NAME, final.NAME).
    std::vector<std::string> peaks;
    std::vector<SourceLocation> peakWhere;
    /// `statistics:` outputs (probes or body speed columns) whose steady-
    /// operation statistics over whole periods of the steady window the
    /// transient summary reports (mean.NAME, min.NAME, max.NAME,
    /// peak_to_peak.NAME, ripple.NAME, rms.NAME, speed_fluctuation.BODY;
    /// driver/analyses/WindowStatistics.h, docs/model-format.md).
    std::vector<std::string> statistics;
    std::vector<SourceLocation> statisticsWhere;
    /// `statistics_period:` how the steady window is cut to whole periods:
    /// "auto" (from the model's periodic loads), "hold" (no cut: the hold
    /// window), "time" (statisticsPeriodTime [s]) or "revolutions" (whole
    /// turns of statisticsPeriodBody).
    std::string statisticsPeriod = "auto";
    double statisticsPeriodTime = 0;  ///< [s]
    std::string statisticsPeriodBody;
    SourceLocation statisticsPeriodWhere;
    /// `sweep_plots:` the results a sweep draws (sweep_NAME.png): result
    /// names, NAME* for every name it begins, `headline` (the default: the
    /// verdict, steady values, peaks, power and statistics; no energy
    /// bookkeeping nor last-instant values) and `all`.
    std::vector<std::string> sweepPlots;
    std::vector<SourceLocation> sweepPlotsWhere;
    /// `energy_balance:` build the energy meter for analyses that report
    /// an energy balance (its integrals are states every step carries).
    bool energyBalance = true;
    SourceLocation where;
};

struct ModelSpec {
    std::string file;  ///< path as given
    int formatVersion = kModelFormatVersion;
    std::string name;
    std::string description;
    /// The model's fidelity levels (e.g. 2-mass, 10-mass) and the one built;
    /// bodies and elements of other levels are read, checked and dropped.
    std::vector<std::string> fidelityLevels;
    std::string fidelity;
    /// What the file declares and the selected level leaves out:
    /// {"body drum3", "fidelity levels 10-mass"}, for `milldyn info`.
    struct Omitted {
        std::string what;
        std::string why;
    };
    std::vector<Omitted> notBuilt;
    std::vector<BodySpec> bodies;
    /// Uniform gravity in the ground frame [m/s^2]; zero (the default) builds
    /// no gravity force, so shafts on pins need none.
    std::array<double, 3> gravity{{0, 0, 0}};
    std::vector<ElementSpec> elements;
    /// The analysis: `type` is its kind ("transient", ...), params its keys.
    ElementSpec scenario;
    IntegratorSpec integrator;
    OutputSpec outputs;
    /// The model's presets (`presets:`), the one applied (`preset:` or
    /// --preset; empty: none) and why it was chosen (its `why:`).
    std::vector<std::string> presetNames;
    std::string preset;
    std::string presetWhy;
    /// What reading changed on the user's behalf, one line each (the keys
    /// `--set scenario.analysis=...` dropped): printed as notes.
    std::vector<std::string> readNotes;

    const BodySpec* findBody(const std::string& name) const;
    const ElementSpec* findElement(const std::string& name) const;
};

/// The integrators Simbody 3.7 has, by the names model files use.
const std::vector<std::string>& integratorNames();

}  // namespace milldyn
