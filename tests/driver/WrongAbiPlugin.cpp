// A plugin library built against another plugin ABI: the loader must refuse it.

#include "plugins/scene/ElementRegistry.h"

extern "C" int milldyn_plugin_abi_version() { return milldyn::kPluginAbiVersion + 1000; }
extern "C" const char* milldyn_plugin_simbody_version() { return MILLDYN_SIMBODY_VERSION; }
extern "C" void milldyn_register_elements(milldyn::ElementRegistry&) {}
