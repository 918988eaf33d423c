#pragma once
// Which Simbody engine this translation unit is compiled for: the Simbody
// version (MILLDYN_SIMBODY_VERSION, set by cmake/Engine.cmake from
// find_package(Simbody)) and its NDEBUG setting, read here from NDEBUG
// itself. Some Simbody classes change layout under NDEBUG, so milldyn and a
// plugin must agree on both (docs/building.md); `milldyn --version` and
// summary.json's run section print it.

#ifndef MILLDYN_SIMBODY_VERSION
#error "MILLDYN_SIMBODY_VERSION must be defined (cmake/Engine.cmake sets it from find_package(Simbody))"
#endif

#ifdef NDEBUG
#define MILLDYN_SIMBODY_BUILD "Release"  // Simbody built with NDEBUG (scripts/build-engine.sh)
#else
#define MILLDYN_SIMBODY_BUILD "checked"  // Simbody built without NDEBUG (Debian's libsimbody-dev)
#endif

// e.g. "3.7 Release": what a plugin reports and the loader compares.
#define MILLDYN_ENGINE_TAG MILLDYN_SIMBODY_VERSION " " MILLDYN_SIMBODY_BUILD

namespace milldyn {
/// e.g. "Simbody 3.7 Release".
inline constexpr const char* kSimbodyEngine = "Simbody " MILLDYN_ENGINE_TAG;
}  // namespace milldyn
