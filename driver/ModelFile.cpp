#include "driver/ModelFile.h"

#include "driver/Units.h"
#include "plugins/scene/Schedule.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <unordered_map>
#include <sstream>

namespace milldyn {

const BodySpec* ModelSpec::findBody(const std::string& bodyName) const {
    for (const auto& b : bodies)
        if (b.name == bodyName) return &b;
    return nullptr;
}

const ElementSpec* ModelSpec::findElement(const std::string& elementName) const {
    for (const auto& e : elements)
        if (e.name == elementName) return &e;
    return nullptr;
}

const std::vector<std::string>& integratorNames() {
    static const std::vector<std::string> names = {
        "RungeKuttaMerson", "RungeKutta3",        "RungeKutta2",   "RungeKuttaFeldberg",
        "CPodes",           "CPodesAdams",        "Verlet",        "SemiExplicitEuler",
        "SemiExplicitEuler2", "ExplicitEuler"};
    return names;
}

namespace {

/// The tag of an override value given as an SI number (Override::bareNumberIsSI).
const char* const kSiNumberTag = "!milldyn-si";

std::string joinWords(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string near = nearestName(word, candidates);
    return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

std::string formatNumber(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

/// Model and part files larger than this are refused before reading.
constexpr std::size_t kMaxModelFileBytes = 64u << 20;

/// Reads a regular file whole. A FIFO, device (/dev/zero) or directory is
/// refused without blocking: opened non-blocking and checked with fstat on
/// the open descriptor. Returns false with the reason.
bool readRegularFile(const std::string& path, std::string& text, std::string& why) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = errno == ENOENT ? "no such file" : std::strerror(errno);
        return false;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        why = S_ISDIR(st.st_mode) ? "it is a directory, not a file"
                                  : "it is not a regular file (a FIFO or device would never end)";
        return false;
    }
    if (static_cast<std::size_t>(st.st_size) > kMaxModelFileBytes) {
        ::close(fd);
        why = "it is larger than " + std::to_string(kMaxModelFileBytes >> 20) + " MiB";
        return false;
    }
    text.clear();
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            why = std::string("read error: ") + std::strerror(errno);
            ::close(fd);
            return false;
        }
        if (n == 0) break;
        text.append(buf, static_cast<std::size_t>(n));
        if (text.size() > kMaxModelFileBytes) {  // grew while being read
            ::close(fd);
            why = "it is larger than " + std::to_string(kMaxModelFileBytes >> 20) + " MiB";
            return false;
        }
    }
    ::close(fd);
    return true;
}

}  // namespace

void checkModelText(const std::string& text, const std::string& file, const std::string& includedFrom) {
    int line = 1, column = 1;
    const auto* p = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    for (std::size_t i = 0; i < n;) {
        const unsigned char c = p[i];
        auto fail = [&](const std::string& reason) {
            throw SpecError({file, line, column, includedFrom}, "<text>", reason);
        };
        if (c == 0) fail("NUL byte in the model text");
        std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        bool ok = len > 0 && i + len <= n;
        for (std::size_t k = 1; ok && k < len; ++k) ok = (p[i + k] & 0xC0) == 0x80;
        if (ok && len > 1) {  // no overlong forms, surrogates or code points above U+10FFFF
            unsigned cp = c & (0xFF >> (len + 1));
            for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (p[i + k] & 0x3F);
            ok = cp >= (len == 2 ? 0x80u : len == 3 ? 0x800u : 0x10000u) && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
        }
        if (!ok) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", c);
            fail(std::string("byte ") + hex + " is not UTF-8 (model files are UTF-8 text)");
        }
        if (c == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        i += len;
    }
}

namespace {

/// Records where the events of one document start (yaml-cpp's parser
/// reports them to a handler; only the document start is of interest).
struct DocumentStartHandler : YAML::EventHandler {
    bool started = false;
    YAML::Mark mark;
    void OnDocumentStart(const YAML::Mark& m) override {
        started = true;
        mark = m;
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
};

/// Parses the single YAML document of `text`; a second document is refused.
/// (Not YAML::LoadAll: on some malformed input it never returns, adding
/// empty documents until memory runs out; fuzz finding of scene_build_fuzz.)
YAML::Node loadOneDocument(const std::string& text, const std::string& file, const std::string& includedFrom) {
    try {
        YAML::Node root = YAML::Load(text);
        std::istringstream in(text);
        YAML::Parser parser(in);
        DocumentStartHandler first, second;
        if (parser.HandleNextDocument(first) && parser.HandleNextDocument(second) && second.started) {
            const YAML::Mark& m = second.mark;
            throw SpecError({file, m.line >= 0 ? m.line + 1 : 1, m.column >= 0 ? m.column + 1 : 1, includedFrom},
                            "<document>", "a second YAML document (after '---'): a model file holds one");
        }
        return root;
    } catch (const YAML::ParserException& e) {
        throw SpecError({file, e.mark.line + 1, e.mark.column + 1, includedFrom}, "", "malformed YAML: " + e.msg);
    }
}

/// A key that tells yaml-cpp nodes apart in a hash table: the address of the
/// node's data (its tag string lives there, one per node, stable while the
/// node exists). Two nodes with one key are then told apart by Node::is.
/// Not the source position: a part included N times puts N nodes at each
/// position, and a lookup by position compared all N (quadratic expansion).
const void* nodeKey(const YAML::Node& n) { return &n.Tag(); }

/// Reads one YAML document into a ModelSpec, remembering which nodes came
/// from --set so their diagnostics point at the command line.
class Reader {
public:
    Reader(std::string file, const ModelFileReader& lookups, std::string* resolved = nullptr)
        : m_file(std::move(file)), m_lookups(lookups), m_resolved(resolved) {}

    ModelSpec read(const std::string& text, const std::vector<Override>& overrides) {
        checkModelText(text, m_file, "");
        for (const auto& o : overrides) checkOverridePath(o.path);
        for (const auto& o : overrides) checkModelText(o.path + "=" + o.value, "<--set " + o.path + ">", "");
        YAML::Node root = loadOneDocument(text, m_file, "");
        if (!root || root.IsNull()) throw SpecError({m_file, 1, 1}, "", "the model file is empty");
        requireMap(root, "<document>");
        adopt(root);
        std::vector<OpenFile> open{{canonicalPath(m_file), m_file}};
        resolveIncludes(root, open);  // first: --set reaches included values too
        if (m_presetsBeside) readPresetsBeside(root);
        // The preset's settings first, every other --set after them: an
        // explicit --integrator or --set wins over the preset's choice.
        auto isPresetPath = [](const Override& o) { return o.path == "preset" || o.path.rfind("presets.", 0) == 0; };
        // The scenario that runs: `use_scenario` as the last --set (--scenario
        // NAME) or the file gives it. A --set of `scenario.KEY` (--end-time,
        // --accuracy's scenario keys, a preset's scenario settings) acts on
        // it: with a named scenario selected, the default `scenario:` is only
        // checked, and setting it would be silently without effect.
        for (const auto& o : overrides)
            if (o.path == "use_scenario") m_selectedScenario = o.value;
        if (m_selectedScenario.empty() && root["use_scenario"] && root["use_scenario"].IsScalar())
            m_selectedScenario = root["use_scenario"].Scalar();
        for (const auto& o : overrides)
            if (isPresetPath(o)) applyOverride(root, o);
        ModelSpec spec;
        applyPreset(root, spec);
        for (const auto& o : overrides)
            if (!isPresetPath(o)) applyOverride(root, o);
        if (m_resolved) *m_resolved = YAML::Dump(root);

        spec.file = m_file;
        checkKeys(root, "", modelFileKeys().document);
        const YAML::Node version = required(root, "format_version", "");
        const double versionNumber = readNumber(version, "format_version", "1");
        if (!(versionNumber >= 1 && versionNumber <= 1e6) || versionNumber != std::floor(versionNumber))
            throw error(version, "format_version",
                        "must be a whole number (this milldyn reads version " +
                            std::to_string(kModelFormatVersion) + "), got " + scalar(version, "format_version"));
        spec.formatVersion = static_cast<int>(versionNumber);
        if (spec.formatVersion != kModelFormatVersion)
            throw error(version, "format_version",
                        "unsupported format version " + scalar(version, "format_version") +
                            " (this milldyn reads version " + std::to_string(kModelFormatVersion) + ")");
        spec.name = scalar(required(root, "name", ""), "name");
        if (root["description"]) spec.description = scalar(root["description"], "description");

        if (root["fidelity"]) readFidelity(root["fidelity"], spec);
        readBodies(required(root, "bodies", ""), spec);
        if (root["gravity"]) readVector3(root["gravity"], "gravity", "m/s^2", spec.gravity);
        if (root["elements"]) readElements(root["elements"], spec);
        readScenarios(root, spec);
        if (!spec.fidelity.empty()) keepSelectedFidelity(spec);
        if (root["integrator"]) readIntegrator(root["integrator"], spec.integrator);
        if (root["outputs"]) readOutputs(root["outputs"], spec.outputs);
        spec.readNotes = m_readNotes;
        checkRunSize(spec);
        checkSwitchOffAtStart(spec);
        return spec;
    }

    /// A motor switched off at 0 s in a start from rest never drives: the
    /// run was judged a stall ("the drive cannot take the load"), which
    /// says something false about the drive (issue 26 item 5). From a
    /// steady or given state the same key is a coast-down from t = 0, and
    /// stays allowed.
    static void checkSwitchOffAtStart(const ModelSpec& spec) {
        if (spec.scenario.type != "transient" || spec.scenario.text("initial_state") != "rest") return;
        for (const auto& e : spec.elements)
            if (e.has("switch_off_time") && e.number("switch_off_time") == 0)
                throw e.error("switch_off_time",
                              "0 s switches " + e.name + " off before it drives: from initial_state rest it never "
                              "starts anything; give a time > 0, or start from steady running "
                              "(initial_state: steady) for a coast-down from t = 0");
    }

    /// Work the run would do, refused up front with its estimate rather
    /// than found out after hours or gigabytes (issue 16, item 9).
    static void checkRunSize(const ModelSpec& spec) {
        if (spec.scenario.type != "transient" || !spec.scenario.has("end_time")) return;
        const double end = spec.scenario.number("end_time");
        const double samples = end / spec.outputs.sampleInterval;
        if (samples > kMaxSamples)
            throw spec.scenario.error(
                "end_time", "end_time " + formatNumber(end) + " s at outputs.sample_interval " +
                                formatNumber(spec.outputs.sampleInterval) + " s would write " + formatNumber(samples) +
                                " rows, more than " + formatNumber(kMaxSamples) + ": use a longer sample_interval");
        if (spec.integrator.maxStep > 0 && end / spec.integrator.maxStep > kMaxSteps)
            throw spec.scenario.error("end_time", "end_time " + formatNumber(end) + " s at integrator.max_step " +
                                                      formatNumber(spec.integrator.maxStep) + " s needs at least " +
                                                      formatNumber(end / spec.integrator.maxStep) + " steps, more than " +
                                                      formatNumber(kMaxSteps) + ": use a longer max_step");
    }
    static constexpr double kMaxSamples = 1e7;  ///< rows of one run's table
    static constexpr double kMaxSteps = 1e9;    ///< steps the max_step forces
    static constexpr double kMinBodyInertia = 1e-9;  ///< kg*m^2

private:
    std::string m_file;
    const ModelFileReader& m_lookups;
    std::string* m_resolved;  ///< if set: the document after includes, preset and --set
    std::vector<std::pair<YAML::Node, SourceLocation>> m_overridden;  // node, "<--set path>"
    std::string m_selectedScenario;  // use_scenario's name, empty: the default scenario runs

    /// `scenario` or `scenario.KEY` redirected to `scenarios.NAME[.KEY]` when
    /// a named scenario runs; every other path as given.
    std::string runningScenarioPath(const std::string& path) const {
        if (m_selectedScenario.empty()) return path;
        if (path == "scenario") return "scenarios." + m_selectedScenario;
        if (path.rfind("scenario.", 0) == 0) return "scenarios." + m_selectedScenario + path.substr(8);
        return path;
    }
    mutable std::vector<std::string> m_readNotes;  // ModelSpec::readNotes

    /// A body's or element's name: its outputs' column prefix and the
    /// handle of --set, so never empty nor blank (issue 26 item 7).
    void checkName(const YAML::Node& node, const std::string& key, const std::string& name) const {
        if (name.find_first_not_of(" \t") == std::string::npos)
            throw error(node, key, "a name must not be empty: it prefixes the outputs' columns and --set paths");
    }

    bool isOverridden(const YAML::Node& n) const {
        for (const auto& o : m_overridden)
            if (o.first.is(n)) return true;
        return false;
    }
    struct AddedKey {
        YAML::Node map;
        std::string key;
        SourceLocation where;  ///< the --set, or the include's set: key
    };
    std::vector<AddedKey> m_addedKeys;  // keys --set created, for their diagnostics

    /// One included part file: its path (relative to the working directory,
    /// as the user would open it) and the chain that brought it in.
    struct Inclusion {
        std::string file;
        std::string includedFrom;
    };
    std::vector<Inclusion> m_inclusions;
    /// Every node of every included file, with the index of its inclusion:
    /// yaml-cpp marks know line and column but not the file. Keyed by node
    /// identity (nodeKey), so a lookup costs the same however often a part
    /// is included.
    std::unordered_map<const void*, std::vector<std::pair<YAML::Node, std::size_t>>> m_origin;
    /// The one node memory of this read. yaml-cpp gives every document, and
    /// every node made with YAML::Node(type), a memory (a std::set of its
    /// nodes); joining two nodes merges the right-hand memory into the left
    /// one and points only the right-hand node's holder at it, so the other
    /// parts' holders kept pointing at memories already merged elsewhere and
    /// every later join copied those whole again: including one part N
    /// times cost O(N^2) set insertions (issue 16 item 10; 67 % of the time
    /// in std::_Rb_tree_increment). Every document is adopted into this one
    /// memory as soon as it is parsed and every list assembled here is made
    /// in it, so each later join finds the two memories the same and costs
    /// nothing.
    YAML::Node m_memory{YAML::NodeType::Sequence};
    void adopt(const YAML::Node& n) {
        m_memory.push_back(n);  // merges n's memory (its document's nodes) into m_memory's, once
        if (m_lookups.work) ++m_lookups.work->documentsAdopted;
    }
    /// Lists the includes assembled (a file's bodies: after its parts'),
    /// located where the file's own list (or its include:) was written.
    std::vector<std::pair<YAML::Node, SourceLocation>> m_placed;

    SourceLocation whereKey(const YAML::Node& map, const YAML::Node& keyNode) const {
        if (keyNode.IsScalar())
            for (const auto& a : m_addedKeys)
                if (a.map.is(map) && a.key == keyNode.Scalar()) return a.where;
        return where(keyNode);
    }

    SourceLocation where(const YAML::Node& n) const {
        for (const auto& o : m_overridden)
            if (o.first.is(n)) return o.second;
        for (const auto& p : m_placed)
            if (p.first.is(n)) return p.second;
        std::string file = m_file, chain;
        const auto bucket = m_origin.find(nodeKey(n));
        if (bucket != m_origin.end())
            for (const auto& o : bucket->second)
                if (countComparison(), o.first.is(n)) {
                    file = m_inclusions[o.second].file;
                    chain = m_inclusions[o.second].includedFrom;
                    break;
                }
        const YAML::Mark m = n.Mark();
        if (m.line < 0) return {file, 1, 1, chain};
        return {file, m.line + 1, m.column + 1, chain};
    }

    void countComparison() const {
        if (m_lookups.work) ++m_lookups.work->originComparisons;
    }

    SpecError error(const YAML::Node& n, const std::string& key, const std::string& reason) const {
        return SpecError(where(n), key, reason);
    }

    static std::string typeName(const YAML::Node& n) {
        switch (n.Type()) {
            case YAML::NodeType::Map: return "a mapping";
            case YAML::NodeType::Sequence: return "a list";
            case YAML::NodeType::Scalar: return "a scalar";
            case YAML::NodeType::Null: return "nothing";
            default: return "an undefined value";
        }
    }

    void requireMap(const YAML::Node& n, const std::string& key) const {
        if (!n.IsMap()) throw error(n, key, "expected a mapping (key: value lines), got " + typeName(n));
    }

    void requireList(const YAML::Node& n, const std::string& key) const {
        if (!n.IsSequence()) throw error(n, key, "expected a list, got " + typeName(n));
    }

    std::string scalar(const YAML::Node& n, const std::string& key) const {
        if (!n.IsScalar()) throw error(n, key, "expected a single value, got " + typeName(n));
        return n.Scalar();
    }

    YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& prefix) const {
        const YAML::Node n = map[key];
        if (!n) throw error(map, prefix + key, "missing required key '" + key + "'");
        return n;
    }

    /// Unknown keys (with a suggestion) and duplicate keys.
    void checkKeys(const YAML::Node& map, const std::string& prefix,
                   const std::vector<std::string>& allowed) const {
        std::set<std::string> seen;
        for (auto it = map.begin(); it != map.end(); ++it) {
            const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
            if (!seen.insert(key).second) throw SpecError(whereKey(map, it->first), prefix + key, "duplicate key");
            bool known = false;
            for (const auto& a : allowed) known = known || a == key;
            if (!known)
                throw SpecError(whereKey(map, it->first), prefix + key,
                                "unknown key '" + key + "'" + didYouMean(key, allowed));
        }
    }

    double readNumber(const YAML::Node& n, const std::string& key, const std::string& unit) const {
        const std::string text = scalar(n, key);
        try {
            const double v = n.Tag() == kSiNumberTag ? units::toSI(text, unit) : units::toSIRequiringUnit(text, unit);
            if (!std::isfinite(v)) throw error(n, key, "value is not finite");
            return v;
        } catch (const units::UnitError& e) {
            SourceLocation loc = where(n);
            // Point at the offending character when the scalar is plain text.
            if (n.Mark().line >= 0 && n.Tag() != "!") loc.column += static_cast<int>(e.column());
            throw SpecError(loc, key, e.what());
        }
    }

    bool readBool(const YAML::Node& n, const std::string& key) const {
        const std::string text = scalar(n, key);
        if (text == "true" || text == "yes" || text == "on") return true;
        if (text == "false" || text == "no" || text == "off") return false;
        throw error(n, key, "expected true or false, got '" + text + "'");
    }

    void checkRange(const YAML::Node& n, const std::string& key, const ParamSchema& p, double v) const {
        const std::string unit = p.unit == "1" ? "" : " " + p.unit;
        if (p.min) {
            const bool ok = p.minExclusive ? v > *p.min : v >= *p.min;
            if (!ok)
                throw error(n, key, std::string("must be ") + (p.minExclusive ? "> " : ">= ") +
                                        formatNumber(*p.min) + unit + ", got " + formatNumber(v) + unit);
        }
        if (p.max) {
            const bool ok = p.maxExclusive ? v < *p.max : v <= *p.max;
            if (!ok)
                throw error(n, key, std::string("must be ") + (p.maxExclusive ? "< " : "<= ") +
                                        formatNumber(*p.max) + unit + ", got " + formatNumber(v) + unit);
        }
    }

    /// Reads the keys of an element or scenario against its schema.
    void readParams(const YAML::Node& map, const ElementSchema& schema, const std::string& prefix,
                    const std::vector<std::string>& reservedKeys, const ModelSpec& model,
                    ElementSpec& out) const {
        std::vector<std::string> allowed = reservedKeys;
        for (const auto& p : schema.params) allowed.push_back(p.key);
        checkKeys(map, prefix, allowed);

        for (const auto& p : schema.params) {
            const std::string key = prefix + p.key;
            ParamValue v;
            v.where = where(map);
            const YAML::Node n = map[p.key];
            if (!n) {
                if (p.required) throw error(map, key, "missing required key '" + p.key + "'");
                v.number = p.defaultValue.value_or(0.0);
                v.text = p.defaultText;
                out.params[p.key] = v;
                continue;
            }
            v.given = true;
            v.where = where(n);
            switch (p.kind) {
                case ParamKind::Quantity:
                    v.number = readNumber(n, key, p.unit);
                    checkRange(n, key, p, v.number);
                    break;
                case ParamKind::Choice: {
                    v.text = scalar(n, key);
                    bool ok = false;
                    for (const auto& c : p.choices) ok = ok || c == v.text;
                    if (!ok)
                        throw error(n, key, "unknown value '" + v.text + "' (expected one of " +
                                                joinWords(p.choices) + ")" +
                                                didYouMean(v.text, p.choices));
                    break;
                }
                case ParamKind::BodyRef:
                    v.text = scalar(n, key);
                    requireBody(n, key, v.text, model);
                    break;
                case ParamKind::BodyPair:
                    requireList(n, key);
                    if (n.size() != 2)
                        throw error(n, key, "expected a list of two body names, got " +
                                                std::to_string(n.size()) + " items");
                    for (std::size_t i = 0; i < 2; ++i) {
                        v.names.push_back(scalar(n[i], key));
                        v.itemWhere.push_back(where(n[i]));
                        requireBody(n[i], key, v.names.back(), model);
                    }
                    break;
                case ParamKind::BodyList:
                    requireList(n, key);
                    requireCount(n, key, p);
                    for (std::size_t i = 0; i < n.size(); ++i) {
                        v.names.push_back(scalar(n[i], key));
                        v.itemWhere.push_back(where(n[i]));
                        requireBody(n[i], key, v.names.back(), model);
                    }
                    break;
                case ParamKind::QuantityList:
                    requireList(n, key);
                    requireCount(n, key, p);
                    for (std::size_t i = 0; i < n.size(); ++i) {
                        v.numbers.push_back(readNumber(n[i], key, p.unit));
                        checkRange(n[i], key, p, v.numbers.back());
                    }
                    break;
                case ParamKind::Text:
                    if (isScheduleParam(p))
                        readSchedule(n, key, v, model);
                    else
                        v.text = scalar(n, key);
                    break;
            }
            out.params[p.key] = v;
        }
        if (schema.crossCheck) schema.crossCheck(out);
    }

    /// A schedule key: a map of one shape, `{ramp: {duration: 10 s}}` or
    /// `{table: [[0 s, 0], [2 s, 1]]}`, into the shape's name (v.text) and
    /// its numbers in SI (v.numbers, as Schedule::decode takes them); with
    /// `after: {shaft: NAME, speed: VALUE}` beside the shape, the trigger's
    /// shaft in v.names and its speed [rad/s] in v.number.
    void readSchedule(const YAML::Node& n, const std::string& key, ParamValue& v, const ModelSpec& model) const {
        requireMap(n, key);
        std::vector<std::string> shapes = Schedule::shapeNames();
        std::vector<std::string> allowedKeys = shapes;
        allowedKeys.push_back("after");
        checkKeys(n, key + ".", allowedKeys);
        const YAML::Node after = n["after"];
        const std::size_t count = n.size() - (after ? 1 : 0);
        if (count != 1)
            throw error(n, key, "expected one shape (" + joinWords(shapes) + "), got " + std::to_string(count));
        auto it = n.begin();
        if (it->first.Scalar() == "after") ++it;
        v.text = it->first.Scalar();
        if (after) {
            const std::string a = key + ".after";
            requireMap(after, a);
            checkKeys(after, a + ".", {"shaft", "speed"});
            const YAML::Node shaft = after["shaft"], speed = after["speed"];
            if (!shaft) throw error(after, a + ".shaft", "missing required key 'shaft'");
            if (!speed) throw error(after, a + ".speed", "missing required key 'speed'");
            v.names = {scalar(shaft, a + ".shaft")};
            v.itemWhere = {where(shaft)};
            requireBody(shaft, a + ".shaft", v.names[0], model);
            v.number = readNumber(speed, a + ".speed", "rad/s");
        }
        const YAML::Node body = it->second;
        const std::string sub = key + "." + v.text;
        if (v.text == "table") {
            requireList(body, sub);
            if (body.size() < 2) throw error(body, sub, "expected at least 2 rows [time, factor]");
            for (std::size_t i = 0; i < body.size(); ++i) {
                const YAML::Node row = body[i];
                requireList(row, sub);
                if (row.size() != 2)
                    throw error(row, sub, "expected a row [time, factor], got " + std::to_string(row.size()) + " items");
                v.numbers.push_back(readNumber(row[0], sub, "s"));
                v.numbers.push_back(readNumber(row[1], sub, "1"));
            }
        } else {
            requireMap(body, sub);
            std::vector<std::string> allowed;
            for (const auto& k : Schedule::keysOf(v.text)) allowed.push_back(k.name);
            checkKeys(body, sub + ".", allowed);
            for (const auto& k : Schedule::keysOf(v.text)) {
                const YAML::Node x = body[k.name];
                if (!x) {
                    if (k.required) throw error(body, sub + "." + k.name, "missing required key '" + k.name + "'");
                    v.numbers.push_back(k.defaultValue);
                } else {
                    v.numbers.push_back(readNumber(x, sub + "." + k.name, k.unit));
                }
            }
        }
        try {
            Schedule::decode(v.text, v.numbers);
        } catch (const std::invalid_argument& e) {
            throw error(body, sub, e.what());
        }
    }

    void requireCount(const YAML::Node& n, const std::string& key, const ParamSchema& p) const {
        if (n.size() < p.minCount || n.size() > p.maxCount)
            throw error(n, key, "expected " + std::to_string(p.minCount) + " to " + std::to_string(p.maxCount) +
                                    " items, got " + std::to_string(n.size()));
    }

    void requireBody(const YAML::Node& n, const std::string& key, const std::string& bodyName,
                     const ModelSpec& model) const {
        if (model.findBody(bodyName)) return;
        std::vector<std::string> names;
        for (const auto& b : model.bodies) names.push_back(b.name);
        throw error(n, key, "no body named '" + bodyName + "'" + didYouMean(bodyName, names));
    }

    void readFidelity(const YAML::Node& n, ModelSpec& spec) const {
        requireMap(n, "fidelity");
        checkKeys(n, "fidelity.", modelFileKeys().fidelity);
        const YAML::Node levels = required(n, "levels", "fidelity.");
        requireList(levels, "fidelity.levels");
        if (levels.size() == 0) throw error(levels, "fidelity.levels", "expected at least one level");
        for (const auto& l : levels) spec.fidelityLevels.push_back(scalar(l, "fidelity.levels"));
        const YAML::Node level = required(n, "level", "fidelity.");
        spec.fidelity = scalar(level, "fidelity.level");
        checkLevel(level, "fidelity.level", spec.fidelity, spec);
    }

    /// A model file without a presets: block takes them from
    /// MODEL.presets.yaml beside it when that exists (`milldyn front
    /// --write-presets` writes it; docs/model-format.md "Presets"). Its
    /// nodes are registered like a part's, so a bad line is located in it.
    void readPresetsBeside(YAML::Node root) {
        if (root["presets"]) return;
        const std::string file = presetsFileBeside(m_file);
        std::error_code ec;
        if (!std::filesystem::exists(file, ec)) return;
        std::string text, why;
        if (!readRegularFile(file, text, why))
            throw SpecError({file, 1, 1}, "presets", "cannot open the presets beside the model: " + why);
        m_inclusions.push_back({file, m_file});
        checkModelText(text, file, m_file);
        YAML::Node doc = loadOneDocument(text, file, m_file);
        if (!doc || doc.IsNull()) throw SpecError({file, 1, 1, m_file}, "", "the presets file is empty");
        adopt(doc);
        registerNodes(doc, m_inclusions.size() - 1);
        requireMap(doc, "<document>");
        checkKeys(doc, "", {"presets"});
        root["presets"] = required(doc, "presets", "");
        m_readNotes.push_back("presets: read from " + file + " (beside the model: docs/model-format.md \"Presets\")");
    }

public:
    /// Whether read() looks for MODEL.presets.yaml beside m_file (a file
    /// read from disk; not a text in memory).
    bool m_presetsBeside = false;

private:
    /// `presets: {NAME: {why: TEXT, set: {path: value, ...}}}` and the one
    /// `preset:` (or --preset) selects: its settings are applied as if
    /// written in the file (diagnostics point at the preset's lines).
    void applyPreset(YAML::Node root, ModelSpec& spec) {
        const YAML::Node all = root["presets"];
        if (all) {
            requireMap(all, "presets");
            for (auto it = all.begin(); it != all.end(); ++it) {
                const std::string name = scalar(it->first, "presets");
                const std::string prefix = "presets." + name + ".";
                requireMap(it->second, "presets." + name);
                checkKeys(it->second, prefix, modelFileKeys().preset);
                scalar(required(it->second, "why", prefix), prefix + "why");
                requireMap(required(it->second, "set", prefix), prefix + "set");
                spec.presetNames.push_back(name);
            }
        }
        const YAML::Node selected = root["preset"];
        if (!selected) return;
        const std::string name = scalar(selected, "preset");
        if (!all) throw error(selected, "preset", "unknown preset '" + name + "': the model defines no presets: block");
        if (std::find(spec.presetNames.begin(), spec.presetNames.end(), name) == spec.presetNames.end())
            throw error(selected, "preset", "unknown preset '" + name + "' (expected one of " +
                                                joinWords(spec.presetNames) + ")" + didYouMean(name, spec.presetNames));
        const YAML::Node chosen = all[name];
        const YAML::Node settings = chosen["set"];
        for (auto it = settings.begin(); it != settings.end(); ++it) {
            const std::string path = scalar(it->first, "presets." + name + ".set");
            const YAML::Node value = it->second;
            scalar(value, "presets." + name + ".set." + path);
            setValue(root, runningScenarioPath(path), &value, "", where(value));
        }
        spec.preset = name;
        spec.presetWhy = chosen["why"].Scalar();
    }

    void checkLevel(const YAML::Node& n, const std::string& key, const std::string& level, const ModelSpec& spec) const {
        if (std::find(spec.fidelityLevels.begin(), spec.fidelityLevels.end(), level) == spec.fidelityLevels.end())
            throw error(n, key, "unknown fidelity level '" + level + "' (expected one of " +
                                    joinWords(spec.fidelityLevels) + ")" + didYouMean(level, spec.fidelityLevels));
    }

    /// `fidelity: [2-mass]` on a body or element: the levels it belongs to.
    std::vector<std::string> readMemberLevels(const YAML::Node& item, const std::string& prefix,
                                              const ModelSpec& spec) const {
        std::vector<std::string> levels;
        const YAML::Node n = item["fidelity"];
        if (!n) return levels;
        if (spec.fidelityLevels.empty())
            throw error(n, prefix + "fidelity", "the model declares no fidelity levels (top-level 'fidelity:')");
        requireList(n, prefix + "fidelity");
        for (const auto& l : n) {
            levels.push_back(scalar(l, prefix + "fidelity"));
            checkLevel(l, prefix + "fidelity", levels.back(), spec);
        }
        return levels;
    }

    static bool sharesLevel(const std::vector<std::string>& a, const std::vector<std::string>& b) {
        if (a.empty() || b.empty()) return true;
        for (const auto& x : a)
            if (std::find(b.begin(), b.end(), x) != b.end()) return true;
        return false;
    }

    /// Drops bodies and elements of other levels, then checks that nothing
    /// kept refers to something dropped.
    void keepSelectedFidelity(ModelSpec& spec) const {
        auto kept = [&](const std::vector<std::string>& levels) {
            return levels.empty() || std::find(levels.begin(), levels.end(), spec.fidelity) != levels.end();
        };
        auto levels = [](const std::vector<std::string>& l) {
            std::string text;
            for (const auto& x : l) text += (text.empty() ? "" : ", ") + x;
            return text;
        };
        std::vector<BodySpec> bodies;
        for (const auto& b : spec.bodies) {
            if (kept(b.fidelity)) bodies.push_back(b);
            else spec.notBuilt.push_back({"body " + b.name, "fidelity levels " + levels(b.fidelity)});
        }
        std::vector<ElementSpec> elements;
        for (const auto& e : spec.elements) {
            if (kept(e.fidelity)) elements.push_back(e);
            else spec.notBuilt.push_back({"element " + e.name + " (" + e.type + ")", "fidelity levels " + levels(e.fidelity)});
        }
        spec.bodies = bodies;
        spec.elements = elements;
        const std::string why = "' is not part of fidelity level '" + spec.fidelity + "'";
        for (const auto& b : spec.bodies)
            if (b.joint.parent != "ground" && !spec.findBody(b.joint.parent))
                throw SpecError(b.joint.where, b.name + ".joint.parent", "body '" + b.joint.parent + why);
        if (spec.bodies.empty())
            throw SpecError({m_file, 1, 1}, "fidelity.level", "no body belongs to level '" + spec.fidelity + "'");
        auto checkRefs = [&](const ElementSpec& e, const std::string& prefix) {
            for (const auto& kv : e.params) {
                const ParamValue& v = kv.second;
                for (std::size_t i = 0; i < v.names.size(); ++i)
                    if (!spec.findBody(v.names[i]))
                        throw SpecError(i < v.itemWhere.size() ? v.itemWhere[i] : v.where, prefix + kv.first,
                                        "body '" + v.names[i] + why);
                const ElementSchema* schema = prefix == "scenario." ? m_lookups.analysisSchema(e.type)
                                                                    : m_lookups.elementSchema(e.type);
                const ParamSchema* p = schema ? schema->find(kv.first) : nullptr;
                if (p && p->kind == ParamKind::BodyRef && !v.text.empty() && !spec.findBody(v.text))
                    throw SpecError(v.where, prefix + kv.first, "body '" + v.text + why);
            }
        };
        for (const auto& e : spec.elements) checkRefs(e, e.name + ".");
        checkRefs(spec.scenario, "scenario.");
    }

    void readBodies(const YAML::Node& list, ModelSpec& spec) const {
        requireList(list, "bodies");
        if (list.size() == 0) throw error(list, "bodies", "a model needs at least one body");
        for (const auto& n : list) {
            requireMap(n, "bodies");
            BodySpec b;
            b.where = where(n);
            b.name = scalar(required(n, "name", "bodies."), "name");
            checkName(n["name"], "name", b.name);
            const std::string prefix = b.name + ".";
            checkKeys(n, prefix, modelFileKeys().body);
            b.fidelity = readMemberLevels(n, prefix, spec);
            if (b.name == "ground") throw error(n["name"], "name", "'ground' is reserved for the fixed frame");
            if (spec.findBody(b.name)) throw error(n["name"], "name", "a body named '" + b.name + "' exists already");
            const YAML::Node inertia = required(n, "inertia", prefix);
            b.inertia = readNumber(inertia, prefix + "inertia", "kg*m^2");
            // Bounded below: 4.9e-324 kg*m^2 passed and the first torque's
            // acceleration overflowed, blamed on the motor (issue 26 item 7).
            if (!(b.inertia > 0))
                throw error(inertia, prefix + "inertia",
                            "moment of inertia must be > 0 kg*m^2, got " + formatNumber(b.inertia));
            if (!(b.inertia >= kMinBodyInertia))
                throw error(inertia, prefix + "inertia",
                            "moment of inertia must be >= " + formatNumber(kMinBodyInertia) +
                                " kg*m^2 (a 3 mm steel disc; below it any torque's acceleration is beyond the "
                                "integrator), got " + formatNumber(b.inertia));
            if (n["mass"]) {
                b.mass = readNumber(n["mass"], prefix + "mass", "kg");
                if (b.mass < 0) throw error(n["mass"], prefix + "mass", "mass must be >= 0 kg, got " + formatNumber(b.mass));
            }
            if (n["mass_centre"]) {
                const YAML::Node c = n["mass_centre"];
                readVector3(c, prefix + "mass_centre", "m", b.massCentre);
                const double offAxis2 = b.massCentre[0] * b.massCentre[0] + b.massCentre[1] * b.massCentre[1];
                if (offAxis2 > 0 && !(b.mass > 0))
                    throw error(c, prefix + "mass_centre", "a mass centre off the joint axis needs a mass > 0 kg");
                if (!(b.inertia > b.mass * offAxis2))
                    throw error(c, prefix + "mass_centre",
                                "inertia about the joint axis (" + formatNumber(b.inertia) +
                                    " kg*m^2) must exceed mass*distance^2 = " + formatNumber(b.mass * offAxis2) +
                                    " kg*m^2 (parallel-axis theorem)");
            }
            if (n["initial_angle"]) b.initialAngle = readNumber(n["initial_angle"], prefix + "initial_angle", "rad");
            if (n["initial_speed"]) b.initialSpeed = readNumber(n["initial_speed"], prefix + "initial_speed", "rad/s");
            readJoint(required(n, "joint", prefix), prefix, spec, b.joint);
            spec.bodies.push_back(b);
        }
    }

    void readJoint(const YAML::Node& n, const std::string& prefix, const ModelSpec& spec, JointSpec& j) const {
        requireMap(n, prefix + "joint");
        j.where = where(n);
        checkKeys(n, prefix + "joint.", modelFileKeys().joint);
        const YAML::Node type = required(n, "type", prefix + "joint.");
        j.type = scalar(type, prefix + "joint.type");
        if (j.type != "pin")
            throw error(type, prefix + "joint.type",
                        "unknown joint type '" + j.type + "' (expected pin)" + didYouMean(j.type, {"pin"}));
        if (n["parent"]) {
            j.parent = scalar(n["parent"], prefix + "joint.parent");
            if (j.parent != "ground" && !spec.findBody(j.parent))
                throw error(n["parent"], prefix + "joint.parent",
                            "no body named '" + j.parent + "' defined above this one (parents come first)");
        }
        if (n["location"]) readVector3(n["location"], prefix + "joint.location", "m", j.location);
    }

    /// `[x, y, z]` in `unit`, each entry finite.
    void readVector3(const YAML::Node& n, const std::string& key, const std::string& unit,
                     std::array<double, 3>& v) const {
        requireList(n, key);
        if (n.size() != 3) throw error(n, key, "expected [x, y, z] in " + unit);
        for (std::size_t i = 0; i < 3; ++i) v[i] = readNumber(n[i], key, unit);
    }

    void readElements(const YAML::Node& list, ModelSpec& spec) const {
        requireList(list, "elements");
        for (const auto& n : list) {
            requireMap(n, "elements");
            ElementSpec e;
            e.where = where(n);
            const YAML::Node type = required(n, "type", "elements.");
            e.type = scalar(type, "type");
            const YAML::Node nameNode = required(n, "name", e.type + ".");
            e.name = scalar(nameNode, "name");
            checkName(nameNode, "name", e.name);
            e.fidelity = readMemberLevels(n, e.name + ".", spec);
            // Names are unique within each fidelity level: two elements of
            // disjoint levels (the 2-mass and 10-mass load) may share one.
            for (const auto& other : spec.elements)
                if (other.name == e.name && sharesLevel(other.fidelity, e.fidelity))
                    throw error(nameNode, "name", "an element named '" + e.name + "' exists already");
            const ElementSchema* schema = m_lookups.elementSchema(e.type);
            if (!schema)
                throw error(type, e.name + ".type",
                            "unknown element type '" + e.type + "'" + didYouMean(e.type, m_lookups.elementTypes));
            readParams(n, *schema, e.name + ".", modelFileKeys().element, spec, e);
            spec.elements.push_back(e);
        }
    }

    /// `scenario:` (the default) and named `scenarios:`, all checked; the
    /// one `use_scenario:` names (default: `scenario`) is kept.
    void readScenarios(const YAML::Node& root, ModelSpec& spec) const {
        std::map<std::string, ElementSpec> named;
        std::vector<std::string> names;
        if (root["scenarios"]) {
            const YAML::Node all = root["scenarios"];
            requireMap(all, "scenarios");
            for (auto it = all.begin(); it != all.end(); ++it) {
                const std::string name = scalar(it->first, "scenarios");
                if (named.count(name)) throw error(it->first, "scenarios." + name, "duplicate scenario name");
                named[name] = readScenario(it->second, "scenarios." + name + ".", spec);
                names.push_back(name);
            }
        }
        if (root["use_scenario"]) {
            const YAML::Node use = root["use_scenario"];
            const std::string name = scalar(use, "use_scenario");
            auto it = named.find(name);
            if (it == named.end())
                throw error(use, "use_scenario", "no scenario named '" + name + "' under scenarios:" +
                                                     didYouMean(name, names));
            if (root["scenario"]) readScenario(root["scenario"], "scenario.", spec);  // still checked
            spec.scenario = it->second;
            return;
        }
        if (!root["scenario"])
            throw error(root, "scenario",
                        names.empty() ? "missing required key 'scenario'"
                                      : "missing required key 'scenario' (or use_scenario: one of " +
                                            joinWords(names) + ")");
        spec.scenario = readScenario(root["scenario"], "scenario.", spec);
    }

    ElementSpec readScenario(const YAML::Node& n, const std::string& prefix, const ModelSpec& spec) const {
        requireMap(n, prefix.substr(0, prefix.size() - 1));
        ElementSpec s;
        s.name = "scenario";
        s.where = where(n);
        const YAML::Node kind = required(n, "analysis", prefix);
        s.type = scalar(kind, prefix + "analysis");
        const ElementSchema* schema = m_lookups.analysisSchema(s.type);
        if (!schema)
            throw error(kind, prefix + "analysis",
                        "unknown analysis '" + s.type + "'" + didYouMean(s.type, m_lookups.analysisKinds));
        // `--set scenario.analysis=linearize` on a transient scenario: the
        // keys the new analysis does not take are dropped, with a note.
        if (isOverridden(kind)) {
            std::vector<std::string> dropped;
            for (auto it = n.begin(); it != n.end(); ++it) {
                const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string();
                if (key != "analysis" && !schema->find(key)) dropped.push_back(key);
            }
            YAML::Node map = n;
            for (const auto& key : dropped) map.remove(key);
            if (!dropped.empty())
                m_readNotes.push_back(prefix + "analysis set to " + s.type + ": dropped " + joinWords(dropped) +
                                      " (not keys of " + s.type + ")");
        }
        readParams(n, *schema, prefix, modelFileKeys().scenario, spec, s);
        return s;
    }

    void readIntegrator(const YAML::Node& n, IntegratorSpec& integ) const {
        requireMap(n, "integrator");
        integ.where = where(n);
        checkKeys(n, "integrator.", modelFileKeys().integrator);
        if (n["name"]) {
            integ.name = scalar(n["name"], "integrator.name");
            const auto& names = integratorNames();
            if (std::find(names.begin(), names.end(), integ.name) == names.end())
                throw error(n["name"], "integrator.name",
                            "unknown integrator '" + integ.name + "'" + didYouMean(integ.name, names));
        }
        if (n["accuracy"]) {
            integ.accuracy = readNumber(n["accuracy"], "integrator.accuracy", "1");
            // Simbody asserts 0 < accuracy < 1 (an abort, not an exception).
            if (!(integ.accuracy > 0 && integ.accuracy < 1))
                throw error(n["accuracy"], "integrator.accuracy",
                            "must lie in (0, 1) (Simbody refuses 1 and above), got " + formatNumber(integ.accuracy));
        }
        if (n["max_step"]) {
            integ.maxStep = readNumber(n["max_step"], "integrator.max_step", "s");
            if (integ.maxStep < 0) throw error(n["max_step"], "integrator.max_step", "must be >= 0 s");
        }
    }

    void readOutputs(const YAML::Node& n, OutputSpec& out) const {
        requireMap(n, "outputs");
        out.where = where(n);
        checkKeys(n, "outputs.", modelFileKeys().outputs);
        if (n["sample_interval"]) {
            out.sampleInterval = readNumber(n["sample_interval"], "outputs.sample_interval", "s");
            if (!(out.sampleInterval > 0))
                throw error(n["sample_interval"], "outputs.sample_interval", "must be > 0 s");
        }
        if (n["plots"]) out.plots = readBool(n["plots"], "outputs.plots");
        if (n["energy_balance"]) out.energyBalance = readBool(n["energy_balance"], "outputs.energy_balance");
        if (n["columns"]) readNames(n["columns"], "outputs.columns", out.columns, out.columnWhere);
        if (n["peaks"]) readNames(n["peaks"], "outputs.peaks", out.peaks, out.peakWhere);
        if (n["statistics"]) readNames(n["statistics"], "outputs.statistics", out.statistics, out.statisticsWhere);
        if (n["statistics_period"]) readStatisticsPeriod(n["statistics_period"], out);
        if (n["sweep_plots"]) readNames(n["sweep_plots"], "outputs.sweep_plots", out.sweepPlots, out.sweepPlotsWhere);
    }

    /// `statistics_period: auto | hold | <time> | revolutions of BODY`
    /// (the body is checked against the scene when the transient runs).
    void readStatisticsPeriod(const YAML::Node& n, OutputSpec& out) const {
        const std::string key = "outputs.statistics_period";
        const std::string text = scalar(n, key);
        out.statisticsPeriodWhere = where(n);
        const std::string revolutions = "revolutions of ";
        if (text == "auto" || text == "hold") {
            out.statisticsPeriod = text;
        } else if (text.compare(0, revolutions.size(), revolutions) == 0) {
            std::string body = text.substr(revolutions.size());
            body.erase(0, body.find_first_not_of(' '));
            body.erase(body.find_last_not_of(' ') + 1);
            if (body.empty()) throw error(n, key, "'revolutions of' names no body");
            out.statisticsPeriod = "revolutions";
            out.statisticsPeriodBody = body;
        } else {
            if (text.find_first_of("0123456789") == std::string::npos)
                throw error(n, key,
                            "'" + text + "' is none of auto, hold, a time (e.g. 0.2 s) or 'revolutions of BODY'");
            out.statisticsPeriodTime = readNumber(n, key, "s");
            if (!(out.statisticsPeriodTime > 0)) throw error(n, key, "a period must be > 0 s");
            out.statisticsPeriod = "time";
        }
    }

    /// A list of names, or (from --set) one value with names separated by commas.
    void readNames(const YAML::Node& c, const std::string& key, std::vector<std::string>& names,
                   std::vector<SourceLocation>& at) const {
        if (c.IsScalar()) {
            std::stringstream list(c.Scalar());
            for (std::string name; std::getline(list, name, ',');) {
                name.erase(0, name.find_first_not_of(' '));
                name.erase(name.find_last_not_of(' ') + 1);
                if (name.empty()) throw error(c, key, "an empty name between commas");
                names.push_back(name);
                at.push_back(where(c));
            }
        } else {
            requireList(c, key);
            for (const auto& item : c) {
                names.push_back(scalar(item, key));
                at.push_back(where(item));
            }
        }
        if (names.empty()) throw error(c, key, "expected at least one name (leave it out for all)");
    }

    // ------------------------------------------------------------ include:

    /// The file chain being included, outermost first: the cycle check.
    struct OpenFile {
        std::string canonical;
        std::string display;
    };

    static std::string canonicalPath(const std::string& file) {
        std::error_code ec;
        const auto c = std::filesystem::weakly_canonical(file, ec);
        return ec ? std::filesystem::path(file).lexically_normal().string() : c.string();
    }

    static std::string formatLocation(const SourceLocation& at) {
        return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
               (at.includedFrom.empty() ? "" : ", included from " + at.includedFrom);
    }

    void registerNodes(const YAML::Node& n, std::size_t inclusion, int depth = 0) {
        // Aliases repeat nodes, never nest without end, but a hostile file
        // could still nest very deep: yaml-cpp itself stops long before this.
        if (depth > 10000) return;
        // A node reached again through an alias is registered once: a part
        // file of nested aliases is walked in linear time.
        auto& bucket = m_origin[nodeKey(n)];
        for (const auto& o : bucket)
            if (countComparison(), o.first.is(n)) return;
        bucket.emplace_back(n, inclusion);
        if (m_lookups.work) ++m_lookups.work->nodesRegistered;
        if (n.IsMap()) {
            for (auto it = n.begin(); it != n.end(); ++it) {
                m_origin[nodeKey(it->first)].emplace_back(it->first, inclusion);
                if (m_lookups.work) ++m_lookups.work->nodesRegistered;
                registerNodes(it->second, inclusion, depth + 1);
            }
        } else if (n.IsSequence()) {
            for (const auto& child : n) registerNodes(child, inclusion, depth + 1);
        }
    }

    /// Replaces `include:` of `doc` (the model file or a part file): every
    /// part's bodies and elements go in front of doc's own, in include order,
    /// after the part's own includes, its `set:` and its `prefix:`.
    void resolveIncludes(YAML::Node doc, std::vector<OpenFile>& open) {
        if (!doc["include"]) return;
        const YAML::Node includeNode = doc["include"];
        int seen = 0;
        for (auto it = doc.begin(); it != doc.end(); ++it)
            if (it->first.IsScalar() && it->first.Scalar() == "include" && ++seen == 2)
                throw SpecError(whereKey(doc, it->first), "include", "duplicate key");
        std::vector<YAML::Node> entries;
        if (includeNode.IsScalar() || includeNode.IsMap()) {  // one entry
            entries.push_back(includeNode);
        } else {
            requireList(includeNode, "include");
            for (const auto& e : includeNode) entries.push_back(e);
        }
        std::vector<YAML::Node> bodies, elements;
        for (const auto& entry : entries) {
            YAML::Node part = includePart(entry, open);
            for (const char* key : {"bodies", "elements"}) {
                if (!part[key]) continue;
                const YAML::Node list = part[key];
                requireList(list, key);
                for (const auto& item : list) (std::string(key) == "bodies" ? bodies : elements).push_back(item);
            }
        }
        const SourceLocation includeAt = where(includeNode);
        for (const char* key : {"bodies", "elements"}) {
            const std::vector<YAML::Node>& items = std::string(key) == "bodies" ? bodies : elements;
            if (items.empty()) continue;
            YAML::Node merged(YAML::NodeType::Sequence);
            adopt(merged);  // made in this read's memory: the pushes below merge nothing
            for (const auto& item : items) merged.push_back(item);  // the same nodes: locations kept
            SourceLocation at = includeAt;
            if (doc[key]) {
                const YAML::Node own = doc[key];
                requireList(own, key);
                at = where(own);
                for (const auto& item : own) merged.push_back(item);
                doc.remove(key);
            }
            doc[key] = merged;
            m_placed.emplace_back(doc[key], at);
        }
        doc.remove("include");
    }

    /// Reads one `include:` entry (`path` or `{file: path, prefix: p_, set:
    /// {path: value}}`) and returns the part, its own includes resolved,
    /// `set:` applied and `prefix:` prepended to its names.
    YAML::Node includePart(const YAML::Node& entry, std::vector<OpenFile>& open) {
        // Plain copies: a default YAML::Node is a defined null, and Node
        // assignment would write into the tree.
        const bool isMap = entry.IsMap();
        if (isMap) checkKeys(entry, "include.", modelFileKeys().include);
        const YAML::Node fileNode = isMap ? required(entry, "file", "include.") : entry;
        const bool hasPrefix = isMap && entry["prefix"], hasSet = isMap && entry["set"];
        const YAML::Node prefixNode = hasPrefix ? entry["prefix"] : YAML::Node();
        const YAML::Node setNode = hasSet ? entry["set"] : YAML::Node();
        if (!isMap && !entry.IsScalar())
            throw error(entry, "include", "expected a file name or {file: ..., prefix: ..., set: {...}}, got " +
                                              typeName(entry));
        const std::string written = scalar(fileNode, "include.file");
        if (written.empty()) throw error(fileNode, "include.file", "empty file name");
        const SourceLocation entryAt = where(fileNode);
        // Relative to the including file, as a C #include "...".
        const std::filesystem::path base = std::filesystem::path(open.back().display).parent_path();
        const std::filesystem::path writtenPath(written);
        const std::string file =
            (writtenPath.is_absolute() ? writtenPath : base / writtenPath).lexically_normal().string();
        const std::string canonical = canonicalPath(file);
        for (std::size_t i = 0; i < open.size(); ++i)
            if (open[i].canonical == canonical) {
                std::string cycle;
                for (std::size_t k = i; k < open.size(); ++k) cycle += open[k].display + " -> ";
                throw error(fileNode, "include", "include cycle: " + cycle + file);
            }
        if (open.size() > 32) throw error(fileNode, "include", "includes nest deeper than 32 files");

        std::string text, why;
        if (!readRegularFile(file, text, why)) throw error(fileNode, "include", "cannot open '" + file + "': " + why);

        const std::string chain = formatLocation(entryAt);
        m_inclusions.push_back({file, chain});
        const std::size_t inclusion = m_inclusions.size() - 1;
        checkModelText(text, file, chain);
        YAML::Node part = loadOneDocument(text, file, chain);
        if (!part || part.IsNull()) throw SpecError({file, 1, 1, chain}, "", "the part file is empty");
        adopt(part);
        registerNodes(part, inclusion);
        requireMap(part, "<document>");
        checkKeys(part, "", modelFileKeys().part);
        if (part["format_version"]) {
            const YAML::Node v = part["format_version"];
            if (readNumber(v, "format_version", "1") != kModelFormatVersion)
                throw error(v, "format_version",
                            "unsupported format version " + scalar(v, "format_version") + " (this milldyn reads version " +
                                std::to_string(kModelFormatVersion) + ")");
        }
        open.push_back({canonical, file});
        resolveIncludes(part, open);
        open.pop_back();

        if (hasSet) {
            requireMap(setNode, "include.set");
            for (auto it = setNode.begin(); it != setNode.end(); ++it) {
                const std::string path = scalar(it->first, "include.set");
                if (path.empty() || path.front() == '.' || path.back() == '.' || path.find("..") != std::string::npos)
                    throw SpecError(whereKey(setNode, it->first), path, "malformed path");
                const YAML::Node value = it->second;
                setValue(part, path, &value, "", whereKey(setNode, it->first));
            }
            // A path that named no key of the part (`c.damping` for
            // `elements.c.damping`) created one; it was silently ignored.
            checkKeys(part, "", {"format_version", "description", "bodies", "elements"});
        }
        if (hasPrefix) {
            const std::string prefix = scalar(prefixNode, "include.prefix");
            if (prefix.empty() || prefix.find_first_of(". \t") != std::string::npos)
                throw error(prefixNode, "include.prefix", "expected a non-empty prefix without dots or spaces");
            applyPrefix(part, prefix);
        }
        return part;
    }

    /// Prepends `prefix` to the names of the part's bodies and elements and
    /// to every reference to one of its bodies (joint parents, the body keys
    /// of elements); references to bodies outside the part stay as written.
    void applyPrefix(YAML::Node part, const std::string& prefix) const {
        std::set<std::string> bodyNames;
        if (part["bodies"] && part["bodies"].IsSequence())
            for (const auto& b : part["bodies"])
                if (b.IsMap() && b["name"] && b["name"].IsScalar()) bodyNames.insert(b["name"].Scalar());
        std::vector<YAML::Node> renamed;  // an aliased name is one node: rename it once
        auto rename = [&](YAML::Node n, bool onlyBodies) {
            if (!n || !n.IsScalar() || (onlyBodies && !bodyNames.count(n.Scalar()))) return;
            for (const auto& r : renamed)
                if (r.is(n)) return;
            n = prefix + n.Scalar();  // a string assignment keeps the node's mark
            renamed.push_back(n);
        };
        if (part["bodies"] && part["bodies"].IsSequence())
            for (YAML::Node b : part["bodies"]) {
                if (!b.IsMap()) continue;
                rename(b["name"], false);
                if (b["joint"] && b["joint"].IsMap()) rename(b["joint"]["parent"], true);
            }
        if (part["elements"] && part["elements"].IsSequence())
            for (YAML::Node e : part["elements"]) {
                if (!e.IsMap()) continue;
                rename(e["name"], false);
                const ElementSchema* schema =
                    e["type"] && e["type"].IsScalar() ? m_lookups.elementSchema(e["type"].Scalar()) : nullptr;
                if (!schema) continue;  // the reader reports the unknown type
                for (const auto& p : schema->params) {
                    YAML::Node v = e[p.key];
                    if (!v) continue;
                    if (p.kind == ParamKind::BodyRef) rename(v, true);
                    if ((p.kind == ParamKind::BodyPair || p.kind == ParamKind::BodyList) && v.IsSequence())
                        for (YAML::Node item : v) rename(item, true);
                }
            }
    }

    /// How many places of the document hold `target` (an anchored block
    /// used through aliases is one node at several places), counted up to 2.
    /// Each distinct node is visited once (the count of paths from it is
    /// remembered), so a file of nested aliases (a "billion laughs") takes
    /// time linear in its size, not in its expansion.
    static int occurrences(const YAML::Node& root, const YAML::Node& target) {
        NodeMemo memo;
        return occurrencesFrom(root, target, memo);
    }
    /// Nodes by identity (Node::is), bucketed by nodeKey.
    struct NodeMemo {
        std::unordered_map<const void*, std::vector<std::pair<YAML::Node, int>>> buckets;
        static const void* key(const YAML::Node& n) { return nodeKey(n); }
        const int* find(const YAML::Node& n) const {
            const auto it = buckets.find(key(n));
            if (it == buckets.end()) return nullptr;
            for (const auto& e : it->second)
                if (e.first.is(n)) return &e.second;
            return nullptr;
        }
        void put(const YAML::Node& n, int v) { buckets[key(n)].emplace_back(n, v); }
    };
    static int occurrencesFrom(const YAML::Node& node, const YAML::Node& target, NodeMemo& memo) {
        if (const int* known = memo.find(node)) return *known;
        int count = node.is(target) ? 1 : 0;
        if (node.IsMap())
            for (auto it = node.begin(); it != node.end() && count < 2; ++it)
                count += occurrencesFrom(it->second, target, memo);
        else if (node.IsSequence())
            for (auto it = node.begin(); it != node.end() && count < 2; ++it) count += occurrencesFrom(*it, target, memo);
        count = std::min(count, 2);
        memo.put(node, count);
        return count;
    }

    /// Walks `a.b.c`, descending into lists by item name or index, and
    /// replaces (or adds) the last key's value. A name shared by items of
    /// different fidelity levels reaches all of them.
    void applyOverride(YAML::Node root, const Override& o) {
        const SourceLocation at("<--set " + o.path + ">", 1, 1);
        if (o.path == "include" || o.path.rfind("include.", 0) == 0)
            throw SpecError(at, o.path, "includes are resolved before --set applies: change the file, or --set the "
                                        "included values by their names");
        const std::size_t before = m_overridden.size();
        setValue(root, runningScenarioPath(o.path), nullptr, o.value, at);
        // A number given as SI (Override::bareNumberIsSI) is marked so that
        // readNumber takes it without a unit.
        if (o.bareNumberIsSI)
            for (std::size_t i = before; i < m_overridden.size(); ++i)
                if (m_overridden[i].first.IsScalar()) m_overridden[i].first.SetTag(kSiNumberTag);
    }

    /// Sets the value at `path` (see applyOverride) to `valueNode` (a node of
    /// an including file's `set:`, which keeps its own location) or, when
    /// that is null, to `valueText` located at `at`.
    void setValue(YAML::Node root, const std::string& path, const YAML::Node* valueNode, const std::string& valueText,
                  const SourceLocation& at) {
        const std::string noun = valueNode ? "set:" : "--set";
        auto fail = [&](const std::string& reason) { return SpecError(at, path, reason); };
        std::vector<std::string> parts;
        std::stringstream ss(path);
        for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
        std::vector<YAML::Node> nodes(1);
        nodes[0].reset(root);
        for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
            const std::string& part = parts[i];
            std::vector<YAML::Node> next;
            for (YAML::Node& node : nodes) {
                if (node.IsSequence()) {
                    // `name@level`: only the copy of that fidelity level.
                    const auto levelMark = part.find('@');
                    const std::string itemName = part.substr(0, levelMark);
                    const std::string level = levelMark == std::string::npos ? "" : part.substr(levelMark + 1);
                    auto ofLevel = [&](const YAML::Node& item) {
                        if (level.empty()) return true;
                        const YAML::Node levels = item["fidelity"];
                        if (!levels || !levels.IsSequence()) return false;
                        for (const auto& l : levels)
                            if (l.IsScalar() && l.Scalar() == level) return true;
                        return false;
                    };
                    for (std::size_t k = 0; k < node.size(); ++k)
                        if (node[k].IsMap() && node[k]["name"] && node[k]["name"].IsScalar() &&
                            node[k]["name"].Scalar() == itemName && ofLevel(node[k])) {
                            next.emplace_back();
                            next.back().reset(node[k]);  // operator= would copy into the tree
                        }
                    if (next.empty() && !level.empty())
                        throw fail("no list item named '" + itemName + "' of fidelity level '" + level + "'");
                    if (next.empty() && !part.empty() && part.size() < 9 &&
                        part.find_first_not_of("0123456789") == std::string::npos && std::stoul(part) < node.size()) {
                        next.emplace_back();
                        next.back().reset(node[std::stoul(part)]);
                    }
                    if (next.empty()) throw fail("no list item named '" + part + "' at this point of the path");
                } else if (node.IsMap()) {
                    if (!node[part]) {
                        // An optional section the file leaves out (integrator:,
                        // outputs:): create it; the reader then checks its keys.
                        node[part] = YAML::Node(YAML::NodeType::Map);
                        m_addedKeys.push_back({node, part, at});
                        m_overridden.emplace_back(node[part], at);
                    }
                    const YAML::Node child = node[part];
                    next.emplace_back();
                    next.back().reset(child);
                } else {
                    throw fail("'" + (i > 0 ? parts[i - 1] : part) + "' is a single value, the path goes no deeper");
                }
            }
            // An anchored block used through aliases is one node: changing it
            // would change every use. yaml-cpp cannot copy it without losing
            // the source locations, so such an override is refused.
            for (const auto& n : next)
                if (occurrences(root, n) > 1)
                    throw fail("'" + part + "' is an anchored block used through aliases (*name); " + noun +
                               " would change every use of it: write the value in the file instead");
            nodes.swap(next);  // element-wise operator= would write into the tree
        }
        const std::string& last = parts.back();
        // A list value from the command line: `[0, -9.81 m/s^2, 0]`, items
        // single values, each located at the --set.
        YAML::Node list;
        const auto first = valueText.find_first_not_of(" \t");
        const bool listText = !valueNode && first != std::string::npos && valueText[first] == '[';
        if (listText) {
            try {
                list = YAML::Load(valueText);
            } catch (const YAML::Exception&) {
                throw fail("expected a list [a, b, ...], got '" + valueText + "'");
            }
            if (!list.IsSequence()) throw fail("expected a list [a, b, ...], got '" + valueText + "'");
            for (const auto& item : list)
                if (!item.IsScalar()) throw fail("list items must be single values");
        }
        for (YAML::Node& node : nodes) {
            // One item of a list by its index: `gravity.1=-9.81 m/s^2`.
            if (node.IsSequence() && !valueNode && !listText && !last.empty() && last.size() < 9 &&
                last.find_first_not_of("0123456789") == std::string::npos) {
                const std::size_t index = std::stoul(last);
                if (index >= node.size())
                    throw fail("item " + last + " of a list of " + std::to_string(node.size()) + " items");
                if (!node[index].IsScalar()) throw fail("--set replaces single values or lists of them");
                node[index] = valueText;  // a new scalar in place
                m_overridden.emplace_back(node[index], at);
                continue;
            }
            if (!node.IsMap()) throw fail("the path must end at a key of a mapping");
            if (!valueNode && !listText && node[last] && !node[last].IsScalar() && !node[last].IsNull())
                throw fail(node[last].IsSequence() ? "this key holds a list: give [a, b, ...] or set one item by "
                                                     "its index (" + path + ".0=...)"
                                                   : "--set replaces single values only");
            if (!node[last]) m_addedKeys.push_back({node, last, at});
            // Assigning into an existing node would write through YAML aliases
            // (&x / *x) into every other use of the value: detach it first.
            if (node[last]) node.remove(last);
            if (valueNode) {
                node[last] = *valueNode;  // the same node: it keeps its file, line and column
            } else if (listText) {
                YAML::Node copy = YAML::Load(valueText);  // a node of its own for each place
                node[last] = copy;
                m_overridden.emplace_back(node[last], at);
                for (const auto& item : node[last]) m_overridden.emplace_back(item, at);
            } else {
                node[last] = valueText;
                m_overridden.emplace_back(node[last], at);
            }
        }
    }
};

}  // namespace

const ModelFileKeys& modelFileKeys() {
    static const ModelFileKeys keys{
        // "include" is resolved and removed before the check; listed for "did you mean".
        {"format_version", "name", "description", "fidelity", "bodies", "elements", "scenario", "scenarios",
         "use_scenario", "integrator", "outputs", "presets", "preset", "gravity", "include"},
        {"format_version", "description", "include", "bodies", "elements"},
        {"name", "inertia", "mass", "mass_centre", "joint", "initial_angle", "initial_speed", "fidelity"},
        {"type", "parent", "location"},
        {"name", "accuracy", "max_step"},
        {"sample_interval", "plots", "columns", "energy_balance", "peaks", "statistics", "statistics_period",
         "sweep_plots"},
        {"level", "levels"},
        {"why", "set"},
        {"file", "prefix", "set"},
        {"type", "name", "fidelity"},
        {"analysis"}};
    return keys;
}

std::string gravityWarning(const ModelSpec& spec, const ModelFileReader& reader) {
    if (spec.gravity[0] != 0 || spec.gravity[1] != 0 || spec.gravity[2] != 0) return "";
    std::vector<std::string> needing;
    for (const auto& e : spec.elements) {
        const ElementSchema* schema = reader.elementSchema(e.type);
        if (schema && schema->needsGravity) needing.push_back(e.name + " (" + e.type + ")");
    }
    if (needing.empty()) return "";
    return "the model has no gravity: but " + joinWords(needing) +
           (needing.size() == 1 ? " is" : " are") +
           " loaded by weight; add e.g. gravity: [0, -9.80665 m/s^2, 0] (without it their weight is 0)";
}

void checkOverridePath(const std::string& path) {
    // The deepest path a model has is a handful of segments; thousands took
    // 43 s (each segment a tree walk) and were echoed whole in the error
    // (issue 26 item 7).
    const std::size_t segments = static_cast<std::size_t>(std::count(path.begin(), path.end(), '.')) + 1;
    if (segments <= kMaxOverrideSegments && path.size() <= kMaxOverridePathLength) return;
    const std::string shown = path.size() <= 40 ? path : path.substr(0, 40) + "...";
    throw SpecError({"<--set " + shown + ">", 1, 1}, shown,
                    "the path has " + std::to_string(segments) + " segments and " + std::to_string(path.size()) +
                        " characters: at most " + std::to_string(kMaxOverrideSegments) + " segments and " +
                        std::to_string(kMaxOverridePathLength) + " characters");
}

Override parseOverride(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SpecError({"<--set>", 1, 1}, text, "expected --set path=value");
    Override o{text.substr(0, eq), text.substr(eq + 1)};
    checkOverridePath(o.path);
    if (o.path.front() == '.' || o.path.back() == '.' || o.path.find("..") != std::string::npos)
        throw SpecError({"<--set>", 1, 1}, o.path, "malformed path");
    return o;
}

std::string presetsFileBeside(const std::string& model) {
    const std::string suffix = ".yaml";
    if (model.size() > suffix.size() && model.compare(model.size() - suffix.size(), suffix.size(), suffix) == 0)
        return model.substr(0, model.size() - suffix.size()) + ".presets.yaml";
    return model + ".presets.yaml";
}

ModelSpec readModelText(const std::string& text, const std::string& displayName,
                        const ModelFileReader& reader, const std::vector<Override>& overrides) {
    return Reader(displayName, reader).read(text, overrides);
}

ModelSpec readModelFile(const std::string& path, const ModelFileReader& reader,
                        const std::vector<Override>& overrides, std::string* resolvedDocument) {
    std::string text, why;
    if (!readRegularFile(path, text, why)) throw SpecError({path, 1, 1}, "<file>", "cannot open the model file: " + why);
    Reader r(path, reader, resolvedDocument);
    r.m_presetsBeside = true;
    return r.read(text, overrides);
}

}  // namespace milldyn
