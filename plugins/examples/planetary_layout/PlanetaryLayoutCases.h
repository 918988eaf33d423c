#pragma once
// The PlanetaryLayout plugin's validation cases (multibody vs closed form),
// added to `milldyn validate` when the plugin is loaded.

#include "PlanetaryLayoutOracle.h"
#include "validation/cases/ValidationCases.h"

#include <string>
#include <vector>

namespace planetary_layout {

constexpr double kSteadySpeed = 750 * M_PI / 30;  // [rad/s], the model's steady_speed
constexpr double kAccelerationTime = 4.6;         // [s], its acceleration_time (τ = 1 s)

/// internal_rolling_100x200.yaml: $PLANETARY_LAYOUT_DIR, else the plugin's source directory.
std::string modelPath();
/// The model's values, written independently of the file.
LayoutParameters modelParameters();
/// Cases whose name contains `filter`.
std::vector<milldyn::ValidationRow> planetaryLayoutCases(const std::string& filter);

}  // namespace planetary_layout
