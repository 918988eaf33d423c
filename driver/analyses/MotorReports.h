#pragma once
// MotorReports: what a transient reports about its motors beyond their
// probes (issue 28): a dq machine's largest supply voltage dip over every
// accepted step, and, for a start on a static torque–speed curve, whether
// the dq machine of the same data peaks higher at switch-on.

#include "driver/analyses/Analysis.h"
#include "plugins/scene/Scene.h"

namespace milldyn {

/// Adds to `result`, for every DqInductionMotor with a source
/// (short_circuit_power), the result NAME.voltage_dip (its largest dip
/// over the run's accepted steps, kept in `last`) and a note when it
/// exceeds voltage_dip_limit; for every InductionMotor whose data gave a
/// dq switch-on estimate (derived NAME.dq_switch_on_peak_estimate) above
/// its static curve's largest torque, a note that the run's peaks are no
/// design load.
void addMotorReports(const Scene& scene, const SimTK::State& last, AnalysisResult& result);

}  // namespace milldyn
