#pragma once
// Shared by the model fuzz targets: a line "#set path=value" at the end of
// the input becomes a --set override, so the override walker is fuzzed with
// the document it edits.

#include "driver/ModelFile.h"

#include <string>
#include <vector>

namespace milldyn::fuzz {

inline std::vector<Override> overridesFromInput(const std::string& text) {
    std::vector<Override> overrides;
    const auto mark = text.rfind("\n#set ");
    if (mark != std::string::npos) {
        try {
            overrides.push_back(parseOverride(text.substr(mark + 6)));
        } catch (const SpecError&) {
        }
    }
    return overrides;
}

}  // namespace milldyn::fuzz
