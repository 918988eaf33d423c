#pragma once
// The one registry of element types. Built-in elements register themselves
// through registerBuiltinElements(); a plugin library loaded with --plugin
// registers more through the same call (milldyn_register_elements). The
// model-file reader sees only the schemas; the scene builder calls build().

#include "plugins/scene/ElementSchema.h"
#include "plugins/scene/Scene.h"

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace milldyn {

/// Bump when ElementSpec, Scene or this registry change incompatibly; a
/// plugin built against another value is refused.
// 2: SourceLocation::includedFrom; 3: Scene::addSketch; 4: Scene's shared
// reactions, prescribed trajectories, omit(), LaggedValue current/keep,
// ElementSchema::outputOnly; 5: Probe::label; 6: Scene::addStartSequence, addSteadyInitializer;
// 7: Probe::shaft, Scene's element records, drive facet (addDrive), start holds and regularisation
// speeds; ElementSchema's analysisNeeds, initialStateKeys, regularisationSpeedKey, adjustableResistanceKey;
// 8: Schedule's trigger and shared clock (Schedule.h), AnalysisResult::figures.
constexpr int kPluginAbiVersion = 8;

/// Builds one element into a scene. Throws SpecError for input the schema
/// could not catch, std::invalid_argument from element constructors.
using ElementBuilder = std::function<void(const ElementSpec&, Scene&)>;

struct ElementType {
    ElementSchema schema;
    ElementBuilder build;
};

class ElementRegistry {
public:
    /// The process-wide registry, with the built-in types already in it.
    static ElementRegistry& instance();

    /// Registers a type; throws std::invalid_argument if the name is taken.
    void add(ElementType type);
    /// nullptr when unknown.
    const ElementType* find(const std::string& typeName) const;
    std::vector<std::string> typeNames() const;

private:
    ElementRegistry() = default;
    mutable std::mutex m_mutex;
    // std::map never moves its nodes, so pointers handed out stay valid
    // while plugins add more types.
    std::map<std::string, ElementType> m_types;
};

/// Adds InductionMotor, TorsionalCoupling, ResistanceTorque, ...
void registerBuiltinElements(ElementRegistry& registry);

}  // namespace milldyn
