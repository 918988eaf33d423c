// Regressions of issue 16 ("Reliability, round two"): each test fails on
// the code before its fix.

#include "ReaderTestHelpers.h"

#include "driver/SceneBuilder.h"
#include "driver/Sweep.h"
#include "driver/outputs/AtomicFile.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

#include <sys/stat.h>

namespace milldyn {
namespace {

namespace fs = std::filesystem;
using test::contains;

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";
const std::string kMinimal = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata/good_minimal.yaml";

std::string freshDir(const std::string& name) {
    const std::string dir = fs::temp_directory_path().string() + "/milldyn-reliability-" + name;
    fs::remove_all(dir);
    return dir;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

SweepOptions sweepOptions(const std::string& model, const std::string& dir) {
    SweepOptions o;
    o.model = kModels + model;
    o.baseOverrides = {{"scenario.end_time", "0.2 s"}, {"outputs.plots", "false"}};
    o.jobs = 2;
    o.outDir = dir;
    return o;
}

SweepPlan torqueGrid() { return makeGrid({parseGrid("elements.grinding.constant_torque=10:20:2")}); }

SpecError sweepError(const SweepPlan& plan, const SweepOptions& o) {
    try {
        runSweep(plan, o);
    } catch (const SpecError& e) {
        return e;
    }
    ADD_FAILURE() << "the sweep into " << o.outDir << " was accepted";
    return SpecError({}, "", "<nothing thrown>");
}

// Item 1: the 3.2 kW model swept into the 5.5 kW model's directory got
// "0 run, 2 resumed" and the 5.5 kW numbers.
TEST(StaleSweepResume, AnotherModelIntoTheSameDirectoryIsRefusedWithTheReason) {
    const std::string d = freshDir("stale-model");
    const SweepSummary first = runSweep(torqueGrid(), sweepOptions("burr_mill_5p5kW_idle.yaml", d));
    EXPECT_EQ(first.run, 2u);
    const std::string table = slurp(d + "/sweep.csv");
    const SpecError e = sweepError(torqueGrid(), sweepOptions("burr_mill_3p2kW_idle.yaml", d));
    EXPECT_EQ(e.where().file, d + "/sweep-plan.json");
    EXPECT_TRUE(contains(e.what(), "holds another sweep")) << e.formatted();
    EXPECT_TRUE(contains(e.what(), "burr_mill_5p5kW_idle.yaml")) << e.formatted();
    EXPECT_EQ(slurp(d + "/sweep.csv"), table);  // untouched
    // The same sweep again resumes everything.
    const SweepSummary again = runSweep(torqueGrid(), sweepOptions("burr_mill_5p5kW_idle.yaml", d));
    EXPECT_EQ(again.resumed, 2u);
    EXPECT_EQ(again.run, 0u);
}

TEST(StaleSweepResume, OtherSetScenarioOrIntegratorIsAnotherSweep) {
    const std::string d = freshDir("stale-set");
    runSweep(torqueGrid(), sweepOptions("burr_mill_5p5kW_idle.yaml", d));
    for (const Override& extra : std::vector<Override>{{"elements.belt.damping", "0.3 N*m*s/rad"},
                                                        {"integrator.accuracy", "1e-5"},
                                                        {"scenario.end_time", "0.25 s"}}) {
        SCOPED_TRACE(extra.path);
        SweepOptions o = sweepOptions("burr_mill_5p5kW_idle.yaml", d);
        o.baseOverrides.push_back(extra);
        const SpecError e = sweepError(torqueGrid(), o);
        EXPECT_TRUE(contains(e.what(), "--set")) << e.formatted();
    }
}

TEST(StaleSweepResume, ChangedModelContentIsDetectedThroughTheDigest) {
    const std::string d = freshDir("stale-content");
    const std::string model = d + "-model.yaml";
    fs::copy_file(kModels + "burr_mill_5p5kW_idle.yaml", model, fs::copy_options::overwrite_existing);
    SweepOptions o = sweepOptions("burr_mill_5p5kW_idle.yaml", d);
    o.model = model;
    runSweep(torqueGrid(), o);
    // A comment changes nothing a point depends on; a value does.
    std::ofstream(model, std::ios::app) << "# a comment\n";
    EXPECT_EQ(runSweep(torqueGrid(), o).resumed, 2u);
    std::string text = slurp(model);
    text.replace(text.find("damping: 0.293 N*m*s/rad"), 24, "damping: 0.300 N*m*s/rad");
    std::ofstream(model, std::ios::trunc) << text;
    const SpecError e = sweepError(torqueGrid(), o);
    EXPECT_TRUE(contains(e.what(), "other model content")) << e.formatted();
}

TEST(StaleSweepResume, PointOfAnotherSweepIsRecomputedNotReused) {
    const std::string d = freshDir("stale-point");
    runSweep(torqueGrid(), sweepOptions("burr_mill_5p5kW_idle.yaml", d));
    // A point file carried over from elsewhere (another digest) is not trusted.
    std::string text = slurp(d + "/points/000001.json");
    const auto at = text.find("\"digest\": \"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at + 11, 16, "0123456789abcdef");
    writeFileAtomically(d + "/points/000001.json", text);
    const SweepSummary s = runSweep(torqueGrid(), sweepOptions("burr_mill_5p5kW_idle.yaml", d));
    EXPECT_EQ(s.resumed, 1u);
    EXPECT_EQ(s.run, 1u);
}

TEST(StaleSweepResume, TwoConcurrentSweepsIntoOneDirectoryNeverMix) {
    const std::string d = freshDir("concurrent");
    SweepOptions a = sweepOptions("burr_mill_5p5kW_idle.yaml", d), b = a;
    b.baseOverrides.push_back({"elements.belt.damping", "0.3"});
    std::atomic<int> refused{0}, done{0};
    auto run = [&](const SweepOptions& o) {
        try {
            runSweep(torqueGrid(), o);
            ++done;
        } catch (const SpecError&) {
            ++refused;
        }
    };
    std::thread ta(run, a), tb(run, b);
    ta.join();
    tb.join();
    EXPECT_EQ(done.load(), 1);
    EXPECT_EQ(refused.load(), 1);
}

// Item 6: merge of an incomplete set of shards exited 0 with a short table.
TEST(SweepMerge, IncompleteShardsAreRefusedNamingTheMissingPoints) {
    const std::string s0 = freshDir("merge-s0"), out = freshDir("merge-out");
    SweepOptions o = sweepOptions("burr_mill_5p5kW_idle.yaml", s0);
    o.shardIndex = 0;
    o.shardCount = 2;
    runSweep(torqueGrid(), o);
    try {
        mergeSweeps({s0}, out);
        ADD_FAILURE() << "merged an incomplete sweep";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "1 of the sweep's 2 points are missing (1)")) << e.formatted();
    }
    EXPECT_FALSE(fs::exists(out + "/sweep.csv"));
}

TEST(SweepMerge, PartsOfDifferentSweepsAreRefused) {
    const std::string s0 = freshDir("merge-a"), s1 = freshDir("merge-b"), out = freshDir("merge-ab");
    SweepOptions o0 = sweepOptions("burr_mill_5p5kW_idle.yaml", s0), o1 = sweepOptions("burr_mill_3p2kW_idle.yaml", s1);
    o0.shardIndex = 0;
    o0.shardCount = 2;
    o1.shardIndex = 1;
    o1.shardCount = 2;
    runSweep(torqueGrid(), o0);
    runSweep(torqueGrid(), o1);
    try {
        mergeSweeps({s0, s1}, out);
        ADD_FAILURE() << "merged two different sweeps";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "another sweep")) << e.formatted();
    }
}

// Item 9: three 100,000-value axes reached 3.7 GB before anything ran.
TEST(SweepBounds, OversizedGridIsRefusedUpFrontWithItsSize) {
    const SweepAxis a = parseGrid("elements.belt.damping=0.1:0.5:100000");
    try {
        makeGrid({a, a, a});
        ADD_FAILURE() << "accepted a grid of 1e15 points";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "1e+15 points (100000 x 100000 x 100000)")) << e.formatted();
    }
}

// Item 9: sample_interval 1e-9 s or max_step 1e-12 s ran until memory or
// patience ran out; now refused with the estimate.
TEST(RunBounds, TinySampleIntervalOrMaxStepIsRefusedWithTheEstimate) {
    const std::string model = kModels + "burr_mill_5p5kW_idle.yaml";
    try {
        readModelFile(model, defaultModelReader(), {{"outputs.sample_interval", "1e-9 s"}});
        ADD_FAILURE() << "accepted 7e9 rows";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.end_time") << e.formatted();
        EXPECT_TRUE(contains(e.what(), "would write 7000000000 rows")) << e.formatted();
    }
    try {
        readModelFile(model, defaultModelReader(), {{"integrator.max_step", "1e-12 s"}});
        ADD_FAILURE() << "accepted 7e12 steps";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "needs at least 7e+12 steps")) << e.formatted();
    }
}

// Item 2: accuracy 1 passed the reader and Simbody's assert aborted (134).
TEST(ReaderRefusesWhatSimbodyWould, AccuracyOneIsASpecError) {
    const std::string text = slurp(kMinimal);
    const SpecError e = test::readErrorOf("m.yaml", text, {{"integrator.accuracy", "1"}});
    EXPECT_EQ(e.key(), "integrator.accuracy");
    EXPECT_TRUE(contains(e.what(), "must lie in (0, 1)")) << e.formatted();
}

// Items 7 and 12: files that never end, NUL bytes, a second document,
// bytes that are not UTF-8.
TEST(ModelFileReading, DeviceAndFifoAreRefusedWithoutBlocking) {
    const std::string fifo = freshDir("fifo") + ".yaml";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const std::string& path : {std::string("/dev/zero"), fifo}) {
        SCOPED_TRACE(path);
        try {
            readModelFile(path, defaultModelReader());
            ADD_FAILURE() << "read " << path;
        } catch (const SpecError& e) {
            EXPECT_TRUE(contains(e.what(), "not a regular file")) << e.formatted();
        }
    }
    fs::remove(fifo);
}

TEST(ModelFileReading, NulByteIsRefusedAtItsLineAndColumn) {
    std::string text = slurp(kMinimal);
    const auto nl = text.find('\n');
    text.insert(nl + 3, 1, '\0');
    test::expectSpecError(test::readErrorOf("m.yaml", text, {}), "m.yaml", 2, 3, "<text>", "NUL byte");
}

TEST(ModelFileReading, NonUtf8IsRefusedAtTheByte) {
    for (const std::string& bad : {std::string("\xff"), std::string("\xc3("), std::string("\xed\xa0\x80"),
                                  std::string("\xc0\xaf")}) {
        const std::string text = "format_version: 1\nname: mill" + bad + "\n";
        test::expectSpecError(test::readErrorOf("m.yaml", text, {}), "m.yaml", 2, 11, "<text>", "is not UTF-8");
    }
    // Valid multi-byte text still reads (the error then is about the model).
    const SpecError ok = test::readErrorOf("m.yaml", "format_version: 1\nname: мельница γ\n", {});
    EXPECT_FALSE(contains(ok.what(), "UTF-8")) << ok.formatted();
}

TEST(ModelFileReading, SecondYamlDocumentIsRefused) {
    const std::string text = slurp(kMinimal) + "---\nname: second\n";
    const SpecError e = test::readErrorOf("m.yaml", text, {});
    EXPECT_EQ(e.key(), "<document>");
    EXPECT_TRUE(contains(e.what(), "a second YAML document")) << e.formatted();
}

// Item 8: 1 kB of nested aliases plus any --set took exponential time in
// the alias check (3^30 paths here: without the fix this never ends).
TEST(ModelFileReading, AliasBombWithASetIsCheckedInLinearTime) {
    std::string text = slurp(kMinimal) + "x0: &a0 [1, 2]\n";
    for (int i = 1; i < 30; ++i)
        text += "x" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
                std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + "]\n";
    const SpecError e = test::readErrorOf("bomb.yaml", text, {{"scenario.end_time", "1 s"}});
    EXPECT_TRUE(contains(e.what(), "unknown key 'x0'")) << e.formatted();
}

// The same bomb in an included part: every node of a part is registered
// for its location, once per node now, not once per path to it.
TEST(ModelFileReading, AliasBombInAPartFileIsRegisteredInLinearTime) {
    const std::string dir = freshDir("bomb-part");
    fs::create_directories(dir);
    std::string part = "format_version: 1\nx0: &a0 [1, 2]\n";
    for (int i = 1; i < 30; ++i)
        part += "x" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
                std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + "]\n";
    std::ofstream(dir + "/part.yaml") << part;
    std::ofstream(dir + "/top.yaml") << "format_version: 1\nname: x\ninclude: part.yaml\nscenario: {analysis: linearize}\n";
    try {
        readModelFile(dir + "/top.yaml", defaultModelReader());
        ADD_FAILURE() << "accepted a part with unknown keys";
    } catch (const SpecError& e) {
        EXPECT_TRUE(contains(e.what(), "unknown key 'x0'")) << e.formatted();
    }
}

// Item 10: one part included N times with prefixes took O(N^2) (N = 1000:
// 26.7 s): yaml-cpp re-merged whole node memories at every join, and a
// node's file of origin was looked up among every inclusion's node at its
// byte offset. The work of a read is counted (not timed): per inclusion it
// must be the same for N = 2000 as for N = 250.
TEST(ModelFileReading, IncludeExpansionCostsTheSamePerInclusion) {
    const std::string dir = freshDir("include-growth");
    fs::create_directories(dir);
    std::ofstream(dir + "/part.yaml")
        << "format_version: 1\nbodies:\n"
           "  - {name: a, inertia: 1 kg*m^2, joint: {type: pin}}\n"
           "  - {name: b, inertia: 2 kg*m^2, joint: {type: pin}}\n"
           "elements:\n"
           "  - {type: TorsionalCoupling, name: c, bodies: [a, b], stiffness: 1000 N*m/rad, damping: 1 N*m*s/rad}\n";
    auto readWith = [&](int n) {
        std::ostringstream top;
        top << "format_version: 1\nname: many\ninclude:\n";
        for (int i = 0; i < n; ++i) top << "  - {file: part.yaml, prefix: p" << i << "_, set: {elements.c.damping: 2 N*m*s/rad}}\n";
        top << "scenario: {analysis: linearize}\n";
        const std::string file = dir + "/top_" + std::to_string(n) + ".yaml";
        std::ofstream(file) << top.str();
        ReaderWork work;
        ModelFileReader reader = defaultModelReader();
        reader.work = &work;
        const ModelSpec spec = readModelFile(file, reader);
        EXPECT_EQ(spec.elements.size(), static_cast<std::size_t>(n));
        EXPECT_EQ(spec.bodies.size(), static_cast<std::size_t>(2 * n));
        EXPECT_EQ(spec.elements.back().name, "p" + std::to_string(n - 1) + "_c");
        EXPECT_EQ(spec.elements.back().params.at("damping").number, 2.0);
        // The model, each part, and the two lists assembled.
        EXPECT_EQ(work.documentsAdopted, n + 3);
        return work;
    };
    const ReaderWork small = readWith(250), large = readWith(2000);
    EXPECT_EQ(large.nodesRegistered, 8 * small.nodesRegistered);
    const double perSmall = static_cast<double>(small.originComparisons) / 250;
    const double perLarge = static_cast<double>(large.originComparisons) / 2000;
    EXPECT_GT(perSmall, 0);
    // Linear: the same per inclusion (a quadratic lookup grows 8-fold here).
    EXPECT_LE(perLarge, 1.1 * perSmall) << small.originComparisons << " vs " << large.originComparisons;

    // A bad value in the last inclusion is still located in the part file.
    std::ofstream(dir + "/bad.yaml") << "format_version: 1\nname: many\ninclude:\n"
                                     << "  - {file: part.yaml, prefix: q_}\n"
                                     << "  - {file: part.yaml, prefix: r_, set: {elements.c.stiffness: -1 N*m/rad}}\n"
                                     << "scenario: {analysis: linearize}\n";
    try {
        readModelFile(dir + "/bad.yaml", defaultModelReader());
        ADD_FAILURE() << "accepted a negative stiffness";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, dir + "/bad.yaml") << e.formatted();
        EXPECT_EQ(e.where().line, 5) << e.formatted();
    }
    // A set: path that names no key of the part created a key the reader
    // then never looked at: the value was silently ignored.
    std::ofstream(dir + "/unknown.yaml") << "format_version: 1\nname: x\ninclude:\n"
                                         << "  - {file: part.yaml, prefix: q_, set: {c.damping: 2 N*m*s/rad}}\n"
                                         << "scenario: {analysis: linearize}\n";
    try {
        readModelFile(dir + "/unknown.yaml", defaultModelReader());
        ADD_FAILURE() << "accepted a set: path that names nothing";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, dir + "/unknown.yaml") << e.formatted();
        EXPECT_EQ(e.where().line, 4) << e.formatted();
        EXPECT_TRUE(contains(e.what(), "unknown key 'c'")) << e.formatted();
    }
}

// scene_build_fuzz finding: on this malformed text YAML::LoadAll (used to
// detect a second document) never returned, adding empty documents until
// memory ran out. It must end in a SpecError.
TEST(ModelFileReading, FuzzFindingLoadAllHangIsASpecError) {
    const std::string file = std::string(MILLDYN_SOURCE_DIR) + "/tests/fuzz/findings/loadall_never_returns.yaml";
    try {
        readModelFile(file, defaultModelReader());
        ADD_FAILURE() << "accepted " << file;
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, file) << e.formatted();
    }
}

// Item 3: half_angle 1e-7 rad and fill 1e-300 gave "internal error"
// (a negative central inertia from cancellation) when the scene was built.
// Built, the segment holds what its closed form says: the filled fraction
// (2γ − sin 2γ)/(2π), the mass ρ l r² (2γ − sin 2γ)/2, and the centroid,
// 4 r sin³γ/(3 (2γ − sin 2γ)), at the wall (→ r as γ → 0); 2γ − sin 2γ by
// its series (x³/6 − x⁵/120, x = 2γ) so the expectation itself does not
// cancel.
TEST(TinyChargeSegments, BuildAtTinyHalfAnglesAndFills) {
    const double rho = 4800, l = 0.2, r = 0.05;  // charge1 of the model file
    struct Case {
        Override set;
        double fill;  ///< the filled fraction it asks for
    };
    auto fillOf = [](double gamma) {
        const double x = 2 * gamma;
        return (x * x * x / 6 - x * x * x * x * x / 120) / (2 * M_PI);
    };
    for (const Case& c : std::vector<Case>{{{"elements.charge1.half_angle", "1e-6 rad"}, fillOf(1e-6)},
                                           {{"elements.charge1.half_angle", "1e-7 rad"}, fillOf(1e-7)},
                                           {{"elements.charge1.half_angle", "1e-8 rad"}, fillOf(1e-8)},
                                           {{"elements.charge1.fill", "1e-300"}, 1e-300}}) {
        SCOPED_TRACE(c.set.path + "=" + c.set.value);
        const ModelSpec spec = readModelFile(kModels + "planetary_gear_100x200.yaml", defaultModelReader(), {c.set});
        std::unique_ptr<Scene> scene;
        ASSERT_NO_THROW(scene = buildScene(spec));
        std::map<std::string, double> derived;
        for (const auto& d : scene->derivedValues()) derived[d.name] = d.value;
        EXPECT_NEAR(derived.at("charge1.fill") / c.fill, 1.0, 1e-6);
        EXPECT_NEAR(derived.at("charge1.mass") / (rho * l * r * r * M_PI * c.fill), 1.0, 1e-6);
        EXPECT_NEAR(derived.at("charge1.centroid_radius") / r, 1.0, 1e-6);
        const double inertia = derived.at("charge1.axis_inertia");
        EXPECT_TRUE(std::isfinite(inertia) && inertia >= 0) << inertia;
    }
}

}  // namespace
}  // namespace milldyn
