#pragma once
// campbell: a Campbell diagram — the train's elastic natural frequencies
// against the running speed, linearized at each speed's operating point,
// with the excitation lines (load harmonics per revolution, tooth-mesh and
// belt-passing orders, supply and twice slip frequency, fixed-frequency
// loads, extra orders) and every crossing inside the speed range, located
// on the mode curve. Campbell.cpp states the equations and the method.

#include "driver/analyses/Analysis.h"

namespace milldyn {

/// Runs a campbell scenario. Throws SpecError for keys the model cannot
/// honour (a supply to scale without a motor), AnalysisError when an
/// operating point cannot be found.
AnalysisResult runCampbell(const ModelSpec& spec, const ProgressFn& progress);

}  // namespace milldyn
