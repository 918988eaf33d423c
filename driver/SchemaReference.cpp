#include "driver/SchemaReference.h"
#include "plugins/scene/Format.h"
#include "plugins/scene/Schedule.h"

#include <map>
#include <sstream>
#include <stdexcept>

namespace milldyn {
namespace {

std::string number(double v) { return formatNumber(v, 10); }

std::string kindName(const ParamSchema& p) {
    switch (p.kind) {
        case ParamKind::Quantity: return "number";
        case ParamKind::Choice: return "one of";
        case ParamKind::BodyRef: return "body name";
        case ParamKind::BodyPair: return "[from body, to body]";
        case ParamKind::BodyList: return "list of body names";
        case ParamKind::QuantityList: return "list of numbers";
        case ParamKind::Text: return isScheduleParam(p) ? "schedule {ramp|step_recovery|sine|table: ...}" : "text";
    }
    return "?";
}

bool hasNumbers(const ParamSchema& p) { return p.kind == ParamKind::Quantity || p.kind == ParamKind::QuantityList; }

std::string formatSchemas(const ModelFileReader& reader, const std::vector<std::string>& names,
                          const SchemaLookup& lookup, const std::string& only,
                          const std::string& what) {
    if (!only.empty() && !lookup(only)) {
        const std::string near = nearestName(only, names);
        throw SpecError({"<command line>", 1, 1}, what,
                        "unknown " + what + " '" + only + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    (void)reader;
    std::ostringstream out;
    for (const auto& name : names) {
        if (!only.empty() && name != only) continue;
        const ElementSchema* s = lookup(name);
        if (!s) continue;
        out << name << (s->doc.empty() ? "" : " — " + s->doc) << "\n";
        for (const auto& p : s->params)
            out << "  " << p.key << ": " << describeParam(p) << (p.doc.empty() ? "" : " — " + p.doc) << "\n";
        // Capabilities the generic analyses read (ElementSchema, issue 31 item 4).
        if (!s->regularisationSpeedKey.empty())
            out << "  capability: regularised below " << s->regularisationSpeedKey
                << " (a run-out's stop_speed must be at least 5 times it)\n";
        if (!s->adjustableResistanceKey.empty())
            out << "  capability: adjustable resistance " << s->adjustableResistanceKey
                << " (coastdown_identify's resistance)\n";
        for (const auto& need : s->analysisNeeds)
            out << "  capability: " << need.key << ": " << need.value << " — " << need.why << " ("
                << (need.kind == ElementSchema::AnalysisNeed::Kind::EachInstant
                        ? "kinetostatic, or a replayed transient"
                        : "an integrated transient only")
                << ")\n";
        for (const auto& [key, sets] : s->initialStateKeys)
            out << "  capability: " << key << " sets " << sets << " at t = 0 (transient, initial_state: file only)\n";
        out << "\n";
    }
    return out.str();
}

nlohmann::json paramJson(const ParamSchema& p) {
    using nlohmann::json;
    json j;
    j["description"] = p.doc + (p.doc.empty() ? "" : " ") + "[" + describeParam(p) + "]";
    // A value with its unit ("1490 rpm"); a bare number only where the key is
    // dimensionless, or 0 (the reader refuses any other bare number).
    const json quantity = p.unit == "1" ? json{{"type", json::array({"number", "string"})}}
                                        : json{{"anyOf", json::array({json{{"type", "string"}, {"pattern", "^\\s*[-+.0-9eE]+\\s*[^-+.0-9eE\\s]"}},
                                                                      json{{"const", 0}}})}};
    switch (p.kind) {
        case ParamKind::Quantity:
            j.update(quantity);
            break;
        case ParamKind::QuantityList:
            j["type"] = "array";
            j["items"] = quantity;
            j["minItems"] = p.minCount;
            j["maxItems"] = p.maxCount;
            break;
        case ParamKind::Choice:
            j["enum"] = p.choices;
            break;
        case ParamKind::BodyRef:
        case ParamKind::Text:
            if (isScheduleParam(p)) {
                j["type"] = "object";
                j["minProperties"] = 1;
                j["maxProperties"] = 1;
            } else {
                j["type"] = "string";
            }
            break;
        case ParamKind::BodyPair:
            j["type"] = "array";
            j["items"] = {{"type", "string"}};
            j["minItems"] = 2;
            j["maxItems"] = 2;
            break;
        case ParamKind::BodyList:
            j["type"] = "array";
            j["items"] = {{"type", "string"}};
            j["minItems"] = p.minCount;
            j["maxItems"] = p.maxCount;
            break;
    }
    if (!p.required && !p.defaultText.empty()) j["default"] = p.defaultText;
    return j;
}

/// One object schema per type, selected by `selector` (`type` or `analysis`).
nlohmann::json variants(const std::vector<std::string>& names, const SchemaLookup& lookup,
                        const std::string& selector, const nlohmann::json& reserved) {
    using nlohmann::json;
    json all = json::array();
    for (const auto& name : names) {
        const ElementSchema* s = lookup(name);
        if (!s) continue;
        json props = reserved;
        props[selector] = {{"const", name}};
        json required = json::array({selector});
        if (reserved.contains("name")) required.push_back("name");
        for (const auto& p : s->params) {
            props[p.key] = paramJson(p);
            if (p.required) required.push_back(p.key);
        }
        all.push_back({{"if", {{"properties", {{selector, {{"const", name}}}}}, {"required", {selector}}}},
                       {"then",
                        {{"description", s->doc},
                         {"properties", props},
                         {"required", required},
                         {"additionalProperties", false}}}});
    }
    return all;
}

}  // namespace

std::string describeParam(const ParamSchema& p) {
    std::string text = kindName(p);
    if (p.kind == ParamKind::Choice) {
        for (std::size_t i = 0; i < p.choices.size(); ++i) text += (i ? "|" : " ") + p.choices[i];
    }
    if (hasNumbers(p)) text += p.unit == "1" ? " (dimensionless)" : " in " + p.unit;
    if (p.kind == ParamKind::QuantityList || p.kind == ParamKind::BodyList)
        text += ", " + std::to_string(p.minCount) + " to " + std::to_string(p.maxCount) + " items";
    if (p.min) text += std::string(", ") + (p.minExclusive ? "> " : ">= ") + number(*p.min);
    if (p.max) text += std::string(", ") + (p.maxExclusive ? "< " : "<= ") + number(*p.max);
    if (p.required) {
        text += ", required";
    } else if (p.kind == ParamKind::Quantity && p.defaultValue) {
        text += ", default " + number(*p.defaultValue) + (p.unit == "1" ? "" : " " + p.unit);
    } else if (!p.defaultText.empty()) {
        text += ", default " + p.defaultText;
    } else {
        text += ", optional";
    }
    return text;
}

std::string formatElementReference(const ModelFileReader& reader, const std::string& type) {
    return formatSchemas(reader, reader.elementTypes, reader.elementSchema, type, "element type");
}

std::string formatAnalysisReference(const ModelFileReader& reader, const std::string& kind) {
    return formatSchemas(reader, reader.analysisKinds, reader.analysisSchema, kind, "analysis");
}

namespace {

/// An object schema of the keys the reader takes in one section
/// (modelFileKeys), each typed from `types`. A key the reader takes that
/// has no type here is a programming error, caught by every `milldyn
/// schema` (and its test): the schema cannot drift from the reader again.
nlohmann::json section(const std::vector<std::string>& keys, const std::map<std::string, nlohmann::json>& types,
                       const std::string& where) {
    nlohmann::json props = nlohmann::json::object();
    for (const auto& k : keys) {
        const auto it = types.find(k);
        if (it == types.end()) throw std::logic_error("modelJsonSchema: no type for the reader's key " + where + k);
        props[k] = it->second;
    }
    return {{"type", "object"}, {"additionalProperties", false}, {"properties", props}};
}

}  // namespace

nlohmann::json modelJsonSchema(const ModelFileReader& reader) {
    using nlohmann::json;
    const ModelFileKeys& keys = modelFileKeys();
    // A value with its unit, or a bare number (dimensionless keys; 0).
    const json quantity = {{"type", json::array({"string", "number"})}};
    const json vector3 = {{"type", "array"}, {"items", quantity}, {"minItems", 3}, {"maxItems", 3}};
    const json levels = {{"type", "array"}, {"items", {{"type", "string"}}}};
    const json names = {{"anyOf", json::array({json{{"type", "string"}}, levels})}};
    json elementReserved = json::object();
    for (const auto& k : keys.element)
        if (k != "type") elementReserved[k] = k == "fidelity" ? levels : json{{"type", "string"}};
    const json element = {{"type", "object"},
                          {"required", {"type", "name"}},
                          {"properties", {{"type", {{"enum", reader.elementTypes}}}}},
                          {"allOf", variants(reader.elementTypes, reader.elementSchema, "type", elementReserved)}};
    const json scenario = {{"type", "object"},
                           {"required", {"analysis"}},
                           {"properties", {{"analysis", {{"enum", reader.analysisKinds}}}}},
                           {"allOf", variants(reader.analysisKinds, reader.analysisSchema, "analysis", json::object())}};
    json joint = section(keys.joint, {{"type", {{"enum", {"pin"}}}}, {"parent", {{"type", "string"}}}, {"location", vector3}},
                         "joint.");
    json body = section(keys.body,
                        {{"name", {{"type", "string"}}},
                         {"inertia", quantity},
                         {"mass", quantity},
                         {"mass_centre", vector3},
                         {"initial_angle", quantity},
                         {"initial_speed", quantity},
                         {"fidelity", levels},
                         {"joint", joint}},
                        "bodies.");
    body["required"] = {"name", "inertia", "joint"};
    json includeMap = section(keys.include,
                              {{"file", {{"type", "string"}}}, {"prefix", {{"type", "string"}}}, {"set", {{"type", "object"}}}},
                              "include.");
    includeMap["required"] = {"file"};
    const json include = {{"anyOf", json::array({json{{"type", "string"}}, includeMap})}};
    json preset = section(keys.preset, {{"why", {{"type", "string"}}}, {"set", {{"type", "object"}}}}, "presets.NAME.");
    preset["required"] = {"why", "set"};
    const std::map<std::string, json> top = {
        {"format_version", {{"const", kModelFormatVersion}}},
        {"name", {{"type", "string"}}},
        {"description", {{"type", "string"}}},
        {"gravity", vector3},
        {"fidelity", section(keys.fidelity, {{"level", {{"type", "string"}}}, {"levels", levels}}, "fidelity.")},
        {"bodies", {{"type", "array"}, {"items", body}}},
        {"elements", {{"type", "array"}, {"items", element}}},
        {"scenario", scenario},
        {"scenarios", {{"type", "object"}, {"additionalProperties", scenario}}},
        {"use_scenario", {{"type", "string"}}},
        {"integrator", section(keys.integrator,
                               {{"name", {{"enum", integratorNames()}}},
                                {"accuracy", {{"type", json::array({"number", "string"})}}},
                                {"max_step", quantity}},
                               "integrator.")},
        {"outputs", section(keys.outputs,
                            {{"sample_interval", quantity},
                             {"plots", {{"type", "boolean"}}},
                             {"energy_balance", {{"type", "boolean"}}},
                             {"columns", names},
                             {"peaks", names},
                             {"statistics", names},
                             {"statistics_period", {{"type", "string"}}},
                             {"sweep_plots", names}},
                            "outputs.")},
        {"presets", {{"type", "object"}, {"additionalProperties", preset}}},
        {"preset", {{"type", "string"}}},
        {"include", {{"anyOf", json::array({include, json{{"type", "array"}, {"items", include}}})}}}};
    json schema = section(keys.document, top, "");
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    schema["title"] = "milldyn model file";
    schema["description"] =
        "Generated by `milldyn schema` from the reader's own key lists and the element and analysis schemas "
        "(docs/model-format.md).";
    // Bodies may all come from included parts.
    schema["required"] = {"format_version", "name"};
    schema["anyOf"] = json::array({json{{"required", {"bodies"}}}, json{{"required", {"include"}}}});
    return schema;
}

std::string bashCompletionScript(const ModelFileReader& reader) {
    std::string types, kinds, integrators;
    for (const auto& t : reader.elementTypes) types += (types.empty() ? "" : " ") + t;
    for (const auto& k : reader.analysisKinds) kinds += (kinds.empty() ? "" : " ") + k;
    for (const auto& i : integratorNames()) integrators += (integrators.empty() ? "" : " ") + i;
    std::ostringstream s;
    s << "# bash completion for milldyn (generated by `milldyn completion`)\n"
         "_milldyn() {\n"
         "    local cur prev cmd\n"
         "    cur=\"${COMP_WORDS[COMP_CWORD]}\"\n"
         "    prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
         "    cmd=\"${COMP_WORDS[1]}\"\n"
         "    local commands=\"run info validate sweep merge front elements analyses schema completion help\"\n"
         "    if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
         "        COMPREPLY=( $(compgen -W \"$commands --help --version\" -- \"$cur\") ); return\n"
         "    fi\n"
         "    case \"$prev\" in\n"
         "        --integrator) COMPREPLY=( $(compgen -W \""
      << integrators
      << "\" -- \"$cur\") ); return ;;\n"
         "        --out|--report) COMPREPLY=( $(compgen -d -- \"$cur\") ); return ;;\n"
         "        --plugin) COMPREPLY=( $(compgen -f -X '!*.so' -- \"$cur\") ); return ;;\n"
         "        --set|--grid|--range|--accuracy|--end-time|--scenario|--preset|--filter|--lhs|--seed|--jobs|--shard|--schematic-at|--integrators|--accuracies|--reference|--budget|--repeat) return ;;\n"
         "    esac\n"
         "    local opts=\"--help --plugin\"\n"
         "    case \"$cmd\" in\n"
         "        run) opts=\"$opts --out --set --scenario --integrator --accuracy --end-time --quiet --preset --schematic --schematic-at --check-resolution\" ;;\n"
         "        info) opts=\"$opts --set --scenario --preset --json\" ;;\n"
         "        validate) opts=\"$opts --filter --json --report\" ;;\n"
         "        sweep) opts=\"$opts --grid --lhs --range --seed --jobs --shard --mpi --out --set --quiet --integrator --accuracy --end-time --scenario --preset --no-plots\" ;;\n"
         "        merge) opts=\"$opts --out\" ;;\n"
         "        front) opts=\"$opts --out --set --scenario --preset --integrators --accuracies --reference --budget --repeat --write-presets\" ;;\n"
         "        elements) COMPREPLY=( $(compgen -W \""
      << types
      << " --json\" -- \"$cur\") ); return ;;\n"
         "        analyses) COMPREPLY=( $(compgen -W \""
      << kinds
      << "\" -- \"$cur\") ); return ;;\n"
         "        help) COMPREPLY=( $(compgen -W \"$commands\" -- \"$cur\") ); return ;;\n"
         "    esac\n"
         "    if [[ \"$cur\" == -* ]]; then\n"
         "        COMPREPLY=( $(compgen -W \"$opts\" -- \"$cur\") )\n"
         "    else\n"
         "        COMPREPLY=( $(compgen -f -X '!*.y*ml' -- \"$cur\") $(compgen -d -- \"$cur\") )\n"
         "    fi\n"
         "}\n"
         "complete -F _milldyn milldyn\n";
    return s.str();
}

}  // namespace milldyn
