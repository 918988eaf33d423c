#pragma once
// A transient's initial state (scenario.initial_state) and the check that a
// transient from initial_state: steady starts steady.

#include "driver/ModelSpec.h"
#include "plugins/scene/Scene.h"

#include <Simbody.h>

namespace milldyn {

/**
 * A run from the solved steady state must start steady. `solved` is the
 * steady solver's state (the configuration it was solved for: drives on,
 * starters finished); `first` is the state the integration starts from
 * (after the switchings due at t = 0 and the integrator's projection onto
 * the constraints). The solved configuration is checked at the start's
 * positions and speeds: every acceleration about the mean load (periodic
 * excitations off) is at most 1e-6 of the largest speed per second;
 * otherwise throws AnalysisError naming the body, the elements on it and
 * any switching at t = 0. A switching at t = 0 (a drive switched off, a
 * supply interruption) disturbs that steady running on purpose and is not
 * itself judged; the running it disturbs still is.
 */
void checkSteadyStart(const Scene& scene, const ModelSpec& spec, const SimTK::State& solved, const SimTK::State& first);

/// The state a transient starts from, by scenario.initial_state: the
/// model's initial speeds (file), every speed 0 (rest), or the solved
/// steady running (steady; solveSteadyState).
SimTK::State transientInitialState(const Scene& scene, const ModelSpec& spec);

}  // namespace milldyn
