// A plugin library compiled with the other NDEBUG setting than milldyn (the
// build flips it for this file only; CMakeLists.txt), as a plugin built
// against Debian's headers without NDEBUG would be for a Release-engine
// milldyn: the loader must refuse it before registering anything, since
// Simbody's object layouts differ (docs/building.md).

#include "plugins/scene/PluginApi.h"

namespace {
void registerNothing(milldyn::ElementRegistry&) {}
}  // namespace

MILLDYN_PLUGIN(registerNothing)
