#pragma once
// What an out-of-tree plugin library exports, so that `milldyn --plugin
// lib.so` can load it (OpenSim's `-L` convention). Write, in one .cpp of the
// plugin:
//
//   #include "plugins/scene/PluginApi.h"
//   void registerMyElements(milldyn::ElementRegistry& r) { r.add({schema, builder}); }
//   MILLDYN_PLUGIN(registerMyElements)
//
// The loader refuses a library built against another plugin ABI, another
// Simbody version or another NDEBUG setting (the engine tag, e.g.
// "3.7 Release": plugins/scene/EngineTag.h), with a message naming both.

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/EngineTag.h"

#define MILLDYN_PLUGIN(registerFunction)                                                          \
    extern "C" int milldyn_plugin_abi_version() { return milldyn::kPluginAbiVersion; }             \
    extern "C" const char* milldyn_plugin_simbody_version() { return MILLDYN_ENGINE_TAG; }         \
    extern "C" void milldyn_register_elements(milldyn::ElementRegistry& registry) {                \
        registerFunction(registry);                                                               \
    }
