#include "driver/analyses/AnalysisRegistry.h"

#include <map>
#include <stdexcept>

namespace milldyn {

// Each analysis file defines its kind beside its run function.
AnalysisKind transientKind();          // TransientKind.cpp
AnalysisKind coastdownIdentifyKind();  // CoastdownIdentify.cpp
AnalysisKind linearizeKind();          // Linearize.cpp
AnalysisKind staticDeflectionKind();   // StaticDeflection.cpp
AnalysisKind frequencyResponseKind();  // FrequencyResponse.cpp
AnalysisKind kinetostaticKind();       // Kinetostatic.cpp
AnalysisKind resonanceMapKind();       // ResonanceMap.cpp
AnalysisKind campbellKind();           // Campbell.cpp

namespace {

std::map<std::string, AnalysisKind> makeRegistry() {
    std::map<std::string, AnalysisKind> kinds;
    auto add = [&kinds](AnalysisKind k) {
        if (k.schema.type.empty() || !k.run) throw std::logic_error("an analysis kind needs a name and a run");
        const std::string name = k.schema.type;
        if (!kinds.emplace(name, std::move(k)).second) throw std::logic_error("analysis '" + name + "' listed twice");
    };
    // The list: one line per analysis.
    add(transientKind());
    add(coastdownIdentifyKind());
    add(linearizeKind());
    add(staticDeflectionKind());
    add(frequencyResponseKind());
    add(kinetostaticKind());
    add(resonanceMapKind());
    add(campbellKind());
    return kinds;
}

const std::map<std::string, AnalysisKind>& registry() {
    static const std::map<std::string, AnalysisKind> kinds = makeRegistry();
    return kinds;
}

}  // namespace

const AnalysisKind* findAnalysisKind(const std::string& name) {
    const auto& all = registry();
    auto it = all.find(name);
    return it == all.end() ? nullptr : &it->second;
}

std::vector<const AnalysisKind*> analysisKindList() {
    std::vector<const AnalysisKind*> out;
    for (const auto& kv : registry()) out.push_back(&kv.second);
    return out;
}

const ElementSchema* findAnalysisSchema(const std::string& kind) {
    const AnalysisKind* k = findAnalysisKind(kind);
    return k ? &k->schema : nullptr;
}

std::vector<std::string> analysisKinds() {
    std::vector<std::string> names;
    for (const auto& kv : registry()) names.push_back(kv.first);
    return names;
}

}  // namespace milldyn
