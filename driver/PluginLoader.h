#pragma once
// Loads plugin libraries (`--plugin lib.so`) that add element types to the
// one registry. See plugins/scene/PluginApi.h for what a plugin exports.

#include <string>

namespace milldyn {

/// Loads the library and registers its element types. Throws SpecError
/// (located at `<--plugin path>`) when it cannot be loaded, lacks the entry
/// points, was built against another plugin ABI or engine (Simbody version
/// and NDEBUG setting, plugins/scene/EngineTag.h), or
/// registers a type that exists already.
void loadPlugin(const std::string& path);

}  // namespace milldyn
