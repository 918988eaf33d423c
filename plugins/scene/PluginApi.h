#pragma once
// What an out-of-tree plugin library exports, so that `milldyn --plugin
// lib.so` can load it (OpenSim's `-L` convention). Write, in one .cpp of the
// plugin:
//
//   #include "plugins/scene/PluginApi.h"
//   void registerMyElements(milldyn::ElementRegistry& r) { r.add({schema, builder}); }
//   MILLDYN_PLUGIN(registerMyElements)
//
// The loader refuses a library built against another plugin ABI or another
// Simbody version, with a message naming both.

#include "plugins/scene/ElementRegistry.h"

#ifndef MILLDYN_SIMBODY_VERSION
#error "MILLDYN_SIMBODY_VERSION must be defined (CMake sets it from find_package(Simbody))"
#endif

#define MILLDYN_PLUGIN(registerFunction)                                                          \
    extern "C" int milldyn_plugin_abi_version() { return milldyn::kPluginAbiVersion; }             \
    extern "C" const char* milldyn_plugin_simbody_version() { return MILLDYN_SIMBODY_VERSION; }    \
    extern "C" void milldyn_register_elements(milldyn::ElementRegistry& registry) {                \
        registerFunction(registry);                                                               \
    }
