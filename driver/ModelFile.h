#pragma once
// ModelFile: reads a YAML model file into a checked ModelSpec. Every
// problem is a SpecError with file, line, column and key; nothing
// downstream has to re-check types, units or ranges.

#include "driver/ModelSpec.h"

#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// Finds the schema of an element type or analysis kind; nullptr if unknown.
using SchemaLookup = std::function<const ElementSchema*(const std::string&)>;

/// Work a read did, counted for the tests of its growth (issue 16 item 10:
/// include expansion must cost the same per inclusion however many there are).
struct ReaderWork {
    long long documentsAdopted = 0;   ///< documents and lists joined into the read's one node memory
    long long nodesRegistered = 0;    ///< nodes of part files given their file of origin
    long long originComparisons = 0;  ///< node identity comparisons to find a node's file of origin
};

struct ModelFileReader {
    SchemaLookup elementSchema;
    std::vector<std::string> elementTypes;   ///< for "did you mean"
    SchemaLookup analysisSchema;
    std::vector<std::string> analysisKinds;  ///< for "did you mean"
    ReaderWork* work = nullptr;              ///< if set: counts the read's work
};

/// One `--set path=value` override. Paths address mapping keys by name and
/// sequence items by their `name:` (elements.belt.stiffness) or index.
struct Override {
    std::string path;
    std::string value;
    /// A bare number in `value` is SI (the Python module's numbers); in a
    /// model file and on the command line a dimensional value needs its unit.
    bool bareNumberIsSI = false;
};

/// The keys the reader takes in each section of a model file: the lists it
/// checks every map against, and the ones `milldyn schema` is generated
/// from (issue 26 item 9: the schema refused the documented outputs.peaks).
struct ModelFileKeys {
    std::vector<std::string> document;  ///< the model document (top level)
    std::vector<std::string> part;      ///< an included part file
    std::vector<std::string> body, joint, integrator, outputs, fidelity, preset, include;
    std::vector<std::string> element;   ///< an element's keys besides its type's parameters
    std::vector<std::string> scenario;  ///< a scenario's keys besides its analysis's parameters
};
const ModelFileKeys& modelFileKeys();

/// A model without `gravity:` whose elements are loaded by weight (their
/// schema's needsGravity): one warning naming them, else "".
std::string gravityWarning(const ModelSpec& spec, const ModelFileReader& reader);
/// Model text must be UTF-8 without NUL bytes (YAML 1.2; the JSON outputs
/// need it too): throws SpecError at the line and column of the first
/// offending byte of `text`, read from `file`.
void checkModelText(const std::string& text, const std::string& file, const std::string& includedFrom = {});

/// Parses "path=value"; throws SpecError located at the command line.
Override parseOverride(const std::string& text);
/// The longest --set path: segments (a.b.c has 3) and characters.
constexpr std::size_t kMaxOverrideSegments = 32;
constexpr std::size_t kMaxOverridePathLength = 512;
/// Throws SpecError (the path shortened to 40 characters) for a longer path.
void checkOverridePath(const std::string& path);

/// Reads and checks a model file. Throws SpecError on any bad input. Only
/// regular files are read (a FIFO or device is refused, never waited on);
/// the text must be UTF-8 without NUL bytes and hold one YAML document.
/// `resolvedDocument`, if given, receives the document as it stands after
/// includes, the preset and the overrides (YAML): what determines a run,
/// for the sweep's digest.
ModelSpec readModelFile(const std::string& path, const ModelFileReader& reader,
                        const std::vector<Override>& overrides = {}, std::string* resolvedDocument = nullptr);

/// Where a model file's presets are read from beside it when the file has
/// no presets: block: its path with ".yaml" replaced by ".presets.yaml".
std::string presetsFileBeside(const std::string& model);

/// The same from text in memory (`displayName` appears in diagnostics).
ModelSpec readModelText(const std::string& text, const std::string& displayName,
                        const ModelFileReader& reader, const std::vector<Override>& overrides = {});

}  // namespace milldyn
