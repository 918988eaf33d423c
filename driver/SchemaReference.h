#pragma once
// The model format described from the one registry of schemas (element types,
// plugins included, and analyses): the text `milldyn elements [TYPE]` prints,
// the JSON Schema `milldyn schema` prints (for YAML editors: completion and
// checks of keys), and the bash completion script `milldyn completion` prints.
#include "driver/ModelFile.h"

#include <nlohmann/json.hpp>

#include <string>

namespace milldyn {

/// One paragraph per element type (or only `type`): its keys with kind,
/// unit, default and range. Throws SpecError for an unknown type (with
/// "did you mean").
std::string formatElementReference(const ModelFileReader& reader, const std::string& type = "");

/// The same for the analyses (`scenario.analysis`).
std::string formatAnalysisReference(const ModelFileReader& reader, const std::string& kind = "");

/// JSON Schema (draft 2020-12) of a model file, generated from the schemas.
nlohmann::json modelJsonSchema(const ModelFileReader& reader);

/// "number with unit" text of one key for humans: "N*m/rad, >= 0, default 0".
std::string describeParam(const ParamSchema& p);

/// A bash completion script for milldyn's commands, options, element types
/// and analyses (source it, or install it as
/// share/bash-completion/completions/milldyn).
std::string bashCompletionScript(const ModelFileReader& reader);

}  // namespace milldyn
