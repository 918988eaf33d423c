// Issue 26 items 4, 8 and 9 (round three of the reliability probe): tables
// that keep their shape whatever the names hold, sweeps that refuse what they
// would silently ignore, stale staging directories, a schema generated from
// the reader's own key lists, and a reduced inertia that is not cubic in the
// number of bodies. Issue 29 item 4: value lists, log grids, tied paths.

#include "driver/ModelFile.h"
#include "driver/ReducedInertia.h"
#include "driver/SceneBuilder.h"
#include "driver/SchemaReference.h"
#include "driver/Sweep.h"
#include "driver/analyses/Analysis.h"
#include "driver/outputs/OutputSet.h"
#include "driver/outputs/SweepPlots.h"
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace milldyn {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- 26.4: CSV per RFC 4180 ------------------------------------------------

TEST(CsvTables, FieldsWithCommasQuotesAndLineBreaksAreQuotedAndReadBack) {
    EXPECT_EQ(csvField("motor.speed[rad/s]"), "motor.speed[rad/s]");
    EXPECT_EQ(csvField("lo,ad.torque[N*m]"), "\"lo,ad.torque[N*m]\"");
    EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
    // A header of names an element may have, over rows of numbers: one field
    // per column in every record.
    const std::vector<std::string> names = {"time", "lo,ad.torque", "q\"uote.torque", "new\nline.torque"};
    const std::vector<std::string> units = {"s", "N*m", "N*m", "N*m"};
    const std::string csv = formatCsv(names, units, {{0, 1, 2, 3}, {0.5, -1, -2, -3}});
    const auto records = parseCsv(csv);
    ASSERT_EQ(records.size(), 3u) << csv;
    for (const auto& r : records) EXPECT_EQ(r.size(), names.size()) << csv;
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(records[0][i], names[i] + "[" + units[i] + "]");
    EXPECT_EQ(records[2][3], "-3");
    // The lines gnuplot must skip before the data: 2 (one line break in a name).
    EXPECT_EQ(csvHeaderLines(names, units), 2u);
    EXPECT_THROW(parseCsv("a,\"open\n"), std::invalid_argument);
    EXPECT_EQ(parseCsv("a,b\r\n1,2\r\n").size(), 2u);
}

TEST(CsvTables, SweepTableOfANameWithACommaKeepsItsColumns) {
    const std::string dir = (fs::temp_directory_path() / ("milldyn-csvsweep-" + std::to_string(::getpid()))).string();
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<std::string> points;
    for (int i = 0; i < 2; ++i) {
        json p;
        p["index"] = i;
        p["inputs"] = json::array({{{"path", "elements.lo,ad.constant_torque"}, {"value", 10.0 + i}, {"unit", "N*m"}}});
        p["status"] = "ok";
        p["diagnostic"] = i ? "a, \"quoted\"\nreason" : "";
        p["results"] = {{"lo,ad.peak", {{"value", 1.5 * i}, {"unit", "N*m"}}}};
        points.push_back(p.dump());
    }
    writeSweepTable(dir, points, {}, false);
    std::ifstream in(dir + "/sweep.csv");
    std::stringstream text;
    text << in.rdbuf();
    const auto records = parseCsv(text.str());
    ASSERT_EQ(records.size(), 3u) << text.str();
    for (const auto& r : records) EXPECT_EQ(r.size(), 5u) << text.str();
    EXPECT_EQ(records[0][1], "elements.lo,ad.constant_torque[N*m]");
    EXPECT_EQ(records[2][4], "a, \"quoted\"\nreason");
    // The sweep plots read it as written.
    const SweepTable t = parseSweepTable(text.str());
    ASSERT_EQ(t.inputNames.size(), 1u);
    EXPECT_EQ(t.inputNames[0], "elements.lo,ad.constant_torque");
    ASSERT_EQ(t.resultNames.size(), 1u);
    EXPECT_EQ(t.resultNames[0], "lo,ad.peak");
    EXPECT_EQ(t.results[1][0], 1.5);
    fs::remove_all(dir);
}

// ---- 26.4: a path swept twice, or set and swept ------------------------------

TEST(SweepPaths, ThePathSweptTwiceIsRefusedWithTheReason) {
    try {
        makeGrid({parseGrid("elements.grinding.constant_torque=10 N*m:20 N*m:2"),
                  parseGrid("elements.grinding.constant_torque=30 N*m:40 N*m:3")});
        ADD_FAILURE() << "a path swept twice was accepted";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "is swept twice: the first axis would never be used")) << e.formatted();
    }
    EXPECT_THROW(makeLatinHypercube({parseRange("a.b=0:1"), parseRange("a.b=2:3")}, 4, 1), SpecError);
}

TEST(SweepPaths, ASetOfASweptPathIsRefusedWithTheReason) {
    const auto plan = makeGrid({parseGrid("elements.grinding.constant_torque=10 N*m:20 N*m:2")});
    try {
        checkSweepPaths(plan.axes, {{"scenario.end_time", "1 s"}, {"elements.grinding.constant_torque", "5 N*m"}});
        ADD_FAILURE() << "a --set of a swept path was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "--set");
        EXPECT_TRUE(contains(e.what(), "is set and swept")) << e.formatted();
    }
    EXPECT_NO_THROW(checkSweepPaths(plan.axes, {{"scenario.end_time", "1 s"}}));
}

// ---- 29.4: value lists, log spacing, tied paths -----------------------------

TEST(SweepAxes, ValueListsAndLogSpacedGrids) {
    const SweepAxis list = parseGrid("elements.belt.damping=0.1 N*m*s/rad, 0.2 N*m*s/rad,0.5 N*m*s/rad");
    EXPECT_EQ(list.unit, "N*m*s/rad");
    EXPECT_EQ(list.values, (std::vector<double>{0.1, 0.2, 0.5}));
    const SweepAxis log = parseGrid("integrator.accuracy=1e-3:1e-7:5:log");
    ASSERT_EQ(log.values.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(log.values[i], std::pow(10.0, -3.0 - double(i)));
    // Each value is rounded to 12 digits, as a linear grid's.
    EXPECT_EQ(parseGrid("x=1:100:3:log").values, (std::vector<double>{1, 10, 100}));
    for (const std::string bad : {"x=0:1:3:log", "x=-1:1:3:log", "x=1:2:3:cubic", "x=1 rpm,2 s", "x=1,2 rpm"})
        EXPECT_THROW(parseGrid(bad), SpecError) << bad;
}

// Issue 26 item 7 (in the grid's reader): a bare number beside a unit was
// read in the other end's unit (`25 %:0.45` swept to 0.45 %).
TEST(SweepAxes, ABareEndBesideAUnitIsRefusedExceptZero) {
    for (const std::string bad : {"x=25 %:0.45:3", "x=1400 rpm:150:2", "x=10:30 N*m:3"}) {
        try {
            parseGrid(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const SpecError& e) {
            EXPECT_TRUE(contains(e.what(), "unit")) << e.formatted();
        }
    }
    const SweepAxis zero = parseGrid("x=0:30 N*m:4");
    EXPECT_EQ(zero.unit, "N*m");
    EXPECT_EQ(zero.values.back(), 30);
    EXPECT_THROW(parseRange("x=25 %:0.45"), SpecError);
}

TEST(SweepAxes, TiedPathsMoveTogetherAsOneDimension) {
    auto tied = parseGridAxes("elements.motor.synchronous_speed=1000 rpm:1500 rpm:3;"
                              "elements.motor.rated_speed=990 rpm:1485 rpm:3");
    ASSERT_EQ(tied.size(), 2u);
    EXPECT_FALSE(tied[0].tiedToPrevious);
    EXPECT_TRUE(tied[1].tiedToPrevious);
    tied.push_back(parseGrid("scenario.end_time=1 s:2 s:2"));
    const SweepPlan plan = makeGrid(tied);
    EXPECT_EQ(plan.count, 6u);  // 3 x 2, not 3 x 3 x 2
    for (std::size_t p = 0; p < plan.count; ++p) {
        const auto o = plan.overrides(p);
        ASSERT_EQ(o.size(), 3u);
        EXPECT_EQ(plan.valueIndex(p, 0), plan.valueIndex(p, 1));
        EXPECT_EQ(plan.valueIndex(p, 0), p / 2);
        EXPECT_EQ(plan.valueIndex(p, 2), p % 2);
    }
    EXPECT_EQ(plan.overrides(5)[0].value, "1500 rpm");
    EXPECT_EQ(plan.overrides(5)[1].value, "1485 rpm");
    EXPECT_THROW(parseGridAxes("a.b=1:2:3;c.d=1:2:4"), SpecError);  // counts differ
    // Tied ranges of a hypercube take the same stratum and position.
    const SweepPlan lhs = makeLatinHypercube(parseRangeAxes("a.b=0:1;c.d=10:20"), 8, 3);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_NEAR(lhs.axes[1].values[i], 10 + 10 * lhs.axes[0].values[i], 1e-12);
}

// ---- 26.8: staging directories of dead processes ----------------------------

TEST(StaleStaging, DirectoriesOfDeadProcessesAreRemovedOthersKept) {
    const fs::path dir = fs::temp_directory_path() / ("milldyn-stale-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // A process id that is certainly dead: a child that has exited and been reaped.
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    int status = 0;
    ::waitpid(child, &status, 0);
    const fs::path dead = dir / (".milldyn-staging." + std::to_string(child) + ".0");
    const fs::path mine = dir / (".milldyn-staging." + std::to_string(::getpid()) + ".7");
    const fs::path other = dir / ".milldyn-staging.notapid.1";
    for (const auto& d : {dead, mine, other}) {
        fs::create_directories(d / ".previous");
        std::ofstream(d / "timeseries.csv") << "time[s]\n0\n";
    }
    // A point file's temporary of the dead process, one of this process,
    // and a file whose name only looks alike.
    const fs::path deadTmp = dir / ("000003.json.tmp." + std::to_string(child) + ".12");
    const fs::path myTmp = dir / ("000004.json.tmp." + std::to_string(::getpid()) + ".1");
    const fs::path notTmp = dir / ("notes.tmp." + std::to_string(child) + ".txt");
    for (const auto& f : {deadTmp, myTmp, notTmp}) std::ofstream(f) << "{}";
    auto removed = removeStaleStaging(dir.string());
    std::sort(removed.begin(), removed.end());
    ASSERT_EQ(removed.size(), 2u);
    EXPECT_EQ(removed[0], dead.filename().string());
    EXPECT_EQ(removed[1], deadTmp.filename().string());
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(mine));
    EXPECT_TRUE(fs::exists(other));
    EXPECT_TRUE(fs::exists(myTmp));
    EXPECT_TRUE(fs::exists(notTmp));
    // A new set in the directory does the same on its own.
    fs::create_directories(dead);
    { OutputSet set(dir.string()); }
    EXPECT_FALSE(fs::exists(dead));
    fs::remove_all(dir);
}

// ---- 26.9: the schema from the reader's key lists, against every model ------

/// A YAML node as JSON the way a YAML 1.2 editor reads it: plain scalars
/// that are booleans or numbers become such, everything else text.
json toJson(const YAML::Node& n) {
    if (n.IsMap()) {
        json j = json::object();
        for (const auto& kv : n) j[kv.first.Scalar()] = toJson(kv.second);
        return j;
    }
    if (n.IsSequence()) {
        json j = json::array();
        for (const auto& x : n) j.push_back(toJson(x));
        return j;
    }
    if (n.IsNull()) return nullptr;
    const std::string s = n.Scalar();
    if (n.Tag() == "?") {
        if (s == "true" || s == "false") return s == "true";
        static const std::regex number(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
        if (std::regex_match(s, number)) {
            if (s.find_first_of(".eE") == std::string::npos) return std::stoll(s);
            return std::stod(s);
        }
    }
    return s;
}

/// The JSON Schema keywords `milldyn schema` uses, checked: type, enum,
/// const, pattern, properties, additionalProperties, required, items,
/// minItems, maxItems, anyOf, allOf, if/then. Appends what fails to `why`.
bool valid(const json& v, const json& schema, const std::string& at, std::vector<std::string>& why);

bool typeIs(const json& v, const std::string& t) {
    if (t == "object") return v.is_object();
    if (t == "array") return v.is_array();
    if (t == "string") return v.is_string();
    if (t == "number") return v.is_number();
    if (t == "integer") return v.is_number_integer();
    if (t == "boolean") return v.is_boolean();
    if (t == "null") return v.is_null();
    return false;
}

bool valid(const json& v, const json& schema, const std::string& at, std::vector<std::string>& why) {
    const std::size_t before = why.size();
    if (schema.contains("type")) {
        bool ok = false;
        if (schema["type"].is_array())
            for (const auto& t : schema["type"]) ok = ok || typeIs(v, t);
        else
            ok = typeIs(v, schema["type"]);
        if (!ok) why.push_back(at + ": not of type " + schema["type"].dump());
    }
    if (schema.contains("const") && v != schema["const"]) why.push_back(at + ": not " + schema["const"].dump());
    if (schema.contains("enum") && std::find(schema["enum"].begin(), schema["enum"].end(), v) == schema["enum"].end())
        why.push_back(at + ": " + v.dump() + " not one of the enum");
    if (schema.contains("pattern") && v.is_string() &&
        !std::regex_search(v.get<std::string>(), std::regex(schema["pattern"].get<std::string>())))
        why.push_back(at + ": " + v.dump() + " does not match " + schema["pattern"].dump());
    if (v.is_object()) {
        if (schema.contains("required"))
            for (const auto& r : schema["required"])
                if (!v.contains(r.get<std::string>())) why.push_back(at + ": missing " + r.get<std::string>());
        for (auto it = v.begin(); it != v.end(); ++it) {
            if (schema.contains("properties") && schema["properties"].contains(it.key())) {
                valid(it.value(), schema["properties"][it.key()], at + "." + it.key(), why);
            } else if (schema.contains("additionalProperties")) {
                const json& extra = schema["additionalProperties"];
                if (extra.is_boolean() && !extra.get<bool>())
                    why.push_back(at + ": key " + it.key() + " not allowed");
                else if (extra.is_object())
                    valid(it.value(), extra, at + "." + it.key(), why);
            }
        }
    }
    if (v.is_array()) {
        if (schema.contains("minItems") && v.size() < schema["minItems"].get<std::size_t>())
            why.push_back(at + ": too few items");
        if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<std::size_t>())
            why.push_back(at + ": too many items");
        if (schema.contains("items"))
            for (std::size_t i = 0; i < v.size(); ++i) valid(v[i], schema["items"], at + "[" + std::to_string(i) + "]", why);
    }
    if (schema.contains("anyOf")) {
        bool any = false;
        std::vector<std::string> all;
        for (const auto& s : schema["anyOf"]) {
            std::vector<std::string> w;
            if (valid(v, s, at, w)) any = true;
            all.insert(all.end(), w.begin(), w.end());
        }
        if (!any) why.push_back(at + ": none of anyOf (" + (all.empty() ? "" : all.front()) + ")");
    }
    if (schema.contains("allOf"))
        for (const auto& s : schema["allOf"]) {
            if (s.contains("if")) {
                std::vector<std::string> w;
                if (valid(v, s["if"], at, w) && s.contains("then")) valid(v, s["then"], at, why);
            } else {
                valid(v, s, at, why);
            }
        }
    return why.size() == before;
}

TEST(ModelSchema, EveryShippedModelIsValidAgainstTheSchema) {
    const json schema = modelJsonSchema(defaultModelReader());
    int models = 0;
    for (const auto& e : fs::directory_iterator(kModels)) {
        if (e.path().extension() != ".yaml") continue;
        std::vector<std::string> why;
        EXPECT_TRUE(valid(toJson(YAML::LoadFile(e.path().string())), schema, e.path().filename().string(), why))
            << why.front();
        ++models;
    }
    EXPECT_GE(models, 40);
}

TEST(ModelSchema, TakesTheDocumentedPeaksAndIncludeOnlyModelsRefusesUnknownKeys) {
    const json schema = modelJsonSchema(defaultModelReader());
    std::vector<std::string> why;
    const json includeOnly = toJson(YAML::Load(
        "format_version: 1\nname: m\ninclude: parts/x.yaml\nscenario: {analysis: transient, end_time: 1 s}\n"
        "outputs: {peaks: [motor.torque], columns: motor.torque, plots: false}\n"));
    EXPECT_TRUE(valid(includeOnly, schema, "doc", why)) << why.front();
    why.clear();
    EXPECT_FALSE(valid(toJson(YAML::Load("format_version: 1\nname: m\nincude: x.yaml\n")), schema, "doc", why));
    why.clear();
    EXPECT_FALSE(valid(toJson(YAML::Load("format_version: 1\nname: m\ninclude: x.yaml\noutputs: {peak: a}\n")), schema,
                       "doc", why));
    // Every key the reader takes has its schema: the sections are built
    // from the reader's lists (modelFileKeys).
    const ModelFileKeys& keys = modelFileKeys();
    for (const auto& k : keys.document) EXPECT_TRUE(schema["properties"].contains(k)) << k;
    for (const auto& k : keys.outputs) EXPECT_TRUE(schema["properties"]["outputs"]["properties"].contains(k)) << k;
    for (const auto& k : keys.body) EXPECT_TRUE(schema["properties"]["bodies"]["items"]["properties"].contains(k)) << k;
}

// ---- 26.9: the reduced inertia, not cubic in the bodies ---------------------

/// A chain of n shafts, shaft k coupled to k+1 through a TorsionalCoupling
/// of speed ratio 1.5 for k even and 1/1.5 for k odd (n = ω_from/ω_to).
std::string chainModel(int n) {
    std::ostringstream m;
    m << "format_version: 1\nname: chain\nbodies:\n";
    for (int k = 0; k < n; ++k) m << "  - {name: s" << k << ", inertia: " << 1 + k % 7 << " kg*m^2, joint: {type: pin}}\n";
    m << "elements:\n";
    for (int k = 0; k + 1 < n; ++k)
        m << "  - {type: TorsionalCoupling, name: c" << k << ", bodies: [s" << k << ", s" << k + 1
          << "], ratio: " << (k % 2 ? "0.6666666666666666" : "1.5") << ", stiffness: 1e5 N*m/rad}\n";
    m << "scenario: {analysis: transient, initial_state: rest, end_time: 0.01 s}\noutputs: {plots: false}\n";
    return m.str();
}

double derived(const Scene& scene, const std::string& name) {
    for (const auto& d : scene.derivedValues())
        if (d.name == name) return d.value;
    ADD_FAILURE() << "no derived value " << name;
    return NAN;
}

TEST(ReducedInertia, ChainAgainstItsClosedFormAndWorkGrowingLinearly) {
    ReducedInertiaWork small, large;
    for (int n : {200, 2000}) {
        const ModelSpec spec = readModelText(chainModel(n), "chain.yaml", defaultModelReader());
        auto scene = buildScene(spec);
        // Closed form: J_ref(s0) = Σ J_k (ω_k/ω_0)², ω_{k+1} = ω_k / ratio_k.
        double speed = 1, sum = 0;
        for (int k = 0; k < n; ++k) {
            sum += (1 + k % 7) * speed * speed;
            speed /= (k % 2 ? 0.6666666666666666 : 1.5);
        }
        EXPECT_NEAR(derived(*scene, "s0.reduced_inertia"), sum, 1e-9 * sum) << n;
        ReducedInertiaWork& work = n == 200 ? small : large;
        addReducedInertias(*scene, &work);
        EXPECT_FALSE(work.dense) << n;
    }
    // Operation counts, not times: the dense LU factor was n² entries and
    // n³ work (100x and 1000x from 200 to 2000 bodies); the sparse factor
    // and the realizations grow tenfold.
    EXPECT_LE(large.factorNonzeros, 15 * small.factorNonzeros) << small.factorNonzeros << " " << large.factorNonzeros;
    EXPECT_LE(large.realizations, 11 * small.realizations);
    EXPECT_LE(large.matrixNonzeros, 11 * small.matrixNonzeros);
}

}  // namespace
}  // namespace milldyn
