#pragma once
// SceneBuilder: ModelSpec → Scene (a Simbody system with our elements).

#include "driver/ModelSpec.h"
#include "plugins/scene/Scene.h"

#include <memory>

namespace milldyn {

/// Builds bodies (pins, in file order) and every element through the
/// registry, then realizes topology. Throws SpecError (located at the
/// element) when an element refuses its parameters.
std::unique_ptr<Scene> buildScene(const ModelSpec& spec);

/// The body an element acts on, its probes' default shaft: the body of its
/// first body key (a body pair's first, a body list's distinct names joined
/// by ", "); "" if it has none or its type is unknown.
std::string elementShaft(const ElementSpec& e);

/// The model's initial state (angles and speeds from the file), realized to
/// Stage::Position.
SimTK::State initialState(const Scene& scene, const ModelSpec& spec);

}  // namespace milldyn
