// The PlanetaryLayout example plugin (docs/new-layout.md): a new mill
// layout (drums rolling inside a fixed ring, or n drums on a sun) added to
// milldyn without touching its sources. CMake builds it into
// build/libmilldyn_planetary_layout.so; load it with
//   build/milldyn run plugins/examples/planetary_layout/internal_rolling_100x200.yaml
//       --plugin build/libmilldyn_planetary_layout.so

#include "PlanetaryLayout.h"
#include "PlanetaryLayoutCases.h"
#include "plugins/scene/PluginApi.h"

namespace {

void registerLayout(milldyn::ElementRegistry& registry) {
    planetary_layout::registerPlanetaryLayout(registry);
    // Its validation cases join `milldyn validate` (resolved from the
    // executable, like the registry).
    milldyn::addValidationCaseGroup(planetary_layout::planetaryLayoutCases);
}

}  // namespace

MILLDYN_PLUGIN(registerLayout)
