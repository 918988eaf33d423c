#include "plugins/scene/ElementRegistry.h"

#include <stdexcept>

namespace milldyn {

ElementRegistry& ElementRegistry::instance() {
    // Function-local static: initialised once, thread-safe since C++11.
    static ElementRegistry* registry = [] {
        auto* r = new ElementRegistry();
        registerBuiltinElements(*r);
        return r;
    }();
    return *registry;
}

void ElementRegistry::add(ElementType type) {
    std::lock_guard<std::mutex> lock(m_mutex);
    const std::string name = type.schema.type;
    if (name.empty()) throw std::invalid_argument("element type: empty type name");
    if (!type.build) throw std::invalid_argument("element type '" + name + "': no builder");
    if (!m_types.emplace(name, std::move(type)).second)
        throw std::invalid_argument("element type '" + name + "' is already registered");
}

const ElementType* ElementRegistry::find(const std::string& typeName) const {
    std::lock_guard<std::mutex> lock(m_mutex);
    auto it = m_types.find(typeName);
    return it == m_types.end() ? nullptr : &it->second;
}

std::vector<std::string> ElementRegistry::typeNames() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<std::string> names;
    for (const auto& kv : m_types) names.push_back(kv.first);
    return names;
}

}  // namespace milldyn
