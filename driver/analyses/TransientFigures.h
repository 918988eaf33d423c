#pragma once
// The figures of a transient, one per question (issue 29 item 3): the
// torques of each shaft in a panel of their own with the sum of its loads,
// the start (speeds, drive torques, currents, coupling torques, slips, with
// the verdict's instants marked), steady operation over its last whole load
// periods, belt tensions and slip, and currents. Drawn from the main table
// by driver/outputs/Writers (formatFigureCommands); docs/model-format.md,
// "Plots".

#include "driver/analyses/Analysis.h"

#include <string>
#include <vector>

namespace milldyn {

/// The instants and windows of one transient run the figures need.
struct TransientFigureTimes {
    bool fromRest = false;  ///< a start was simulated (the start figure)
    double endTime = 0;     ///< the run's last sample [s]
    /// Vertical lines of the start figure besides the summary's start_time
    /// and sequence_end.* (taken from result.results): the timed starter
    /// steps and the drives' switch-offs, at their instants [s].
    std::vector<PlotMarker> steps, switchOffs;
    /// The steady figure's window: whole load periods at the end of the
    /// steady window (steadyTo > steadyFrom), and what they are in words.
    double steadyFrom = 0, steadyTo = 0;
    std::string steadyWhat;
    /// scenario.speed_body: its speed gets a panel of its own in the steady
    /// figure (its fluctuation is the question there), as each drive's shaft.
    std::string speedBody;
};

/// The table column of each torque (N*m) grouped by the shaft its probe acts
/// on (probeShaft; a coupling's driving shaft), in body order; torques of no
/// shaft last under "". Each group: (shaft, columns).
std::vector<std::pair<std::string, std::vector<std::size_t>>> torqueColumnsByShaft(const Scene& scene,
                                                                                  const ModelSpec& spec,
                                                                                  const AnalysisResult& result);

/// Adds the figures (AnalysisResult::figures) of a transient.
void addTransientFigures(const Scene& scene, const ModelSpec& spec, const TransientFigureTimes& times,
                         AnalysisResult& result);

}  // namespace milldyn
