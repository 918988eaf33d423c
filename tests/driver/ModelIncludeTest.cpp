// Model-file includes (docs/model-format.md, "Including parts"): parts are
// merged with their locations kept, prefixes rename a part's names and its
// references to its own bodies, set: and --set reach included values, and
// every error in a part is located in the part with the chain that led to it.

#include "driver/ModelFile.h"
#include "ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace milldyn {
namespace {

namespace fs = std::filesystem;
using test::contains;

const std::string kData = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata";

ModelSpec read(const std::string& path, const std::vector<Override>& overrides = {}) {
    return readModelFile(path, defaultModelReader(), overrides);
}

/// Two specs describe the same model: every body, element and scenario key
/// with the same value (locations and the file name aside).
void expectSameModel(const ModelSpec& a, const ModelSpec& b) {
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.bodies.size(), b.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        const BodySpec &x = a.bodies[i], &y = b.bodies[i];
        SCOPED_TRACE(x.name);
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.inertia, y.inertia);
        EXPECT_EQ(x.mass, y.mass);
        EXPECT_EQ(x.joint.parent, y.joint.parent);
        EXPECT_EQ(x.joint.location, y.joint.location);
        EXPECT_EQ(x.initialAngle, y.initialAngle);
        EXPECT_EQ(x.initialSpeed, y.initialSpeed);
        EXPECT_EQ(x.fidelity, y.fidelity);
    }
    auto sameElement = [](const ElementSpec& x, const ElementSpec& y) {
        SCOPED_TRACE(x.name);
        EXPECT_EQ(x.type, y.type);
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.fidelity, y.fidelity);
        ASSERT_EQ(x.params.size(), y.params.size());
        for (const auto& kv : x.params) {
            SCOPED_TRACE(kv.first);
            const ParamValue& v = kv.second;
            const ParamValue& w = y.params.at(kv.first);
            EXPECT_EQ(v.number, w.number);
            EXPECT_EQ(v.text, w.text);
            EXPECT_EQ(v.names, w.names);
            EXPECT_EQ(v.numbers, w.numbers);
            EXPECT_EQ(v.given, w.given);
        }
    };
    ASSERT_EQ(a.elements.size(), b.elements.size());
    for (std::size_t i = 0; i < a.elements.size(); ++i) sameElement(a.elements[i], b.elements[i]);
    sameElement(a.scenario, b.scenario);
    EXPECT_EQ(a.integrator.name, b.integrator.name);
    EXPECT_EQ(a.integrator.accuracy, b.integrator.accuracy);
    EXPECT_EQ(a.outputs.sampleInterval, b.outputs.sampleInterval);
    EXPECT_EQ(a.outputs.plots, b.outputs.plots);
}

TEST(ModelInclude, BurrMillsAssembledFromPartsReadToTheShippedModels) {
    // The 3.2 kW variant shares the mill side and changes two of its
    // values through set:.
    for (const std::string v : {"5p5kW", "3p2kW"}) {
        SCOPED_TRACE(v);
        expectSameModel(read(kData + "/include/burr_mill_" + v + "_idle_from_parts.yaml"),
                        read(std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_" + v + "_idle.yaml"));
    }
}

TEST(ModelInclude, PrefixesRenameAPartsNamesAndItsOwnBodyReferencesOnly) {
    const ModelSpec spec = read(kData + "/include_two_drums.yaml");
    ASSERT_EQ(spec.bodies.size(), 3u);
    EXPECT_EQ(spec.bodies[0].name, "carrier");
    EXPECT_EQ(spec.bodies[1].name, "left_drum");
    EXPECT_EQ(spec.bodies[2].name, "right_drum");
    EXPECT_EQ(spec.bodies[1].joint.parent, "carrier");  // not the part's: as written
    std::vector<std::string> names;
    for (const auto& e : spec.elements) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"motor", "left_drive", "left_charge", "right_drive", "right_charge"}));
    EXPECT_EQ(spec.findElement("left_drive")->names("bodies"), (std::vector<std::string>{"carrier", "left_drum"}));
    EXPECT_EQ(spec.findElement("right_charge")->text("body"), "right_drum");
    // set: changed the second inclusion only.
    EXPECT_EQ(spec.findElement("left_charge")->number("constant_torque"), 50);
    EXPECT_EQ(spec.findElement("right_charge")->number("constant_torque"), 80);
}

TEST(ModelInclude, IncludedValuesAreLocatedInTheirPartWithTheChain) {
    const std::string top = kData + "/include_two_drums.yaml";
    const std::string pair = kData + "/parts/drum_pair.yaml", drum = kData + "/parts/drum_with_charge.yaml";
    const ModelSpec spec = read(top);
    const SourceLocation inertia = spec.bodies[2].where;
    EXPECT_EQ(inertia.file, drum);
    EXPECT_EQ(inertia.line, 8);
    EXPECT_EQ(inertia.includedFrom, pair + ":5:12, included from " + top + ":7:5");  // at the file name
    // A value given by set: is located where set: wrote it.
    const SourceLocation torque = spec.findElement("right_charge")->whereOf("constant_torque");
    EXPECT_EQ(torque.file, pair);
    EXPECT_EQ(torque.line, 5);
    EXPECT_EQ(torque.includedFrom, top + ":7:5");
    EXPECT_EQ(spec.findElement("motor")->where.file, kData + "/parts/carrier.yaml");
    EXPECT_EQ(spec.scenario.where.file, top);
    EXPECT_TRUE(spec.scenario.where.includedFrom.empty());
}

TEST(ModelInclude, SetOverridesReachIncludedValuesByTheirPrefixedNames) {
    const ModelSpec spec = read(kData + "/include_two_drums.yaml",
                                {{"elements.left_charge.constant_torque", "60 N*m"}, {"bodies.right_drum.inertia", "3 kg*m^2"}});
    EXPECT_EQ(spec.findElement("left_charge")->number("constant_torque"), 60);
    EXPECT_EQ(spec.findElement("right_charge")->number("constant_torque"), 80);
    EXPECT_EQ(spec.findBody("right_drum")->inertia, 3);
    EXPECT_EQ(spec.findBody("left_drum")->inertia, 2.5);
    // The part's own name is gone.
    EXPECT_THROW(read(kData + "/include_two_drums.yaml", {{"elements.charge.constant_torque", "1"}}), SpecError);
    // The includes themselves are resolved before --set applies.
    try {
        read(kData + "/include_two_drums.yaml", {{"include.0", "other.yaml"}});
        ADD_FAILURE() << "--set include.0 accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, "<--set include.0>");
        EXPECT_TRUE(contains(e.what(), "includes are resolved before --set")) << e.what();
    }
}

TEST(ModelInclude, MisspelledIncludeKeySuggestsInclude) {
    const SpecError e = test::readErrorOf("t.yaml", "format_version: 1\nname: x\nincludes: [a.yaml]\n", {});
    test::expectSpecError(e, "t.yaml", 3, 1, "includes", "unknown key 'includes' (did you mean 'include'?)");
}

TEST(ModelInclude, AssembledLayoutRuns) {
    const ModelSpec spec = read(kData + "/include_two_drums.yaml");
    // The layout assembled: the carrier of parts/carrier.yaml, and the drum
    // part twice, each drum on the carrier, its coupling between the
    // carrier and its own drum, the right charge set to 80 N*m.
    std::vector<std::string> bodies;
    for (const auto& b : spec.bodies) bodies.push_back(b.name + " on " + b.joint.parent);
    EXPECT_EQ(bodies, (std::vector<std::string>{"carrier on ground", "left_drum on carrier", "right_drum on carrier"}));
    std::vector<std::string> elements;
    for (const auto& e : spec.elements) elements.push_back(e.name + ": " + e.type);
    EXPECT_EQ(elements, (std::vector<std::string>{"motor: InductionMotor", "left_drive: TorsionalCoupling",
                                                  "left_charge: ResistanceTorque", "right_drive: TorsionalCoupling",
                                                  "right_charge: ResistanceTorque"}));
    EXPECT_EQ(spec.findElement("left_drive")->names("bodies"), (std::vector<std::string>{"carrier", "left_drum"}));
    EXPECT_EQ(spec.findElement("right_drive")->names("bodies"), (std::vector<std::string>{"carrier", "right_drum"}));
    EXPECT_EQ(spec.findElement("left_charge")->number("constant_torque"), 50.0);
    EXPECT_EQ(spec.findElement("right_charge")->number("constant_torque"), 80.0);
    // It runs, and the heavier charge loads its own coupling more.
    const AnalysisResult r = runAnalysis(spec);
    const ResultScalar* left = r.find("peak.left_drive.torque");
    const ResultScalar* right = r.find("peak.right_drive.torque");
    ASSERT_NE(left, nullptr);
    ASSERT_NE(right, nullptr);
    EXPECT_TRUE(std::isfinite(left->value) && std::isfinite(right->value));
    EXPECT_GT(std::abs(right->value), std::abs(left->value));
}

/// Writes files into a fresh directory for the tests that need variations.
class IncludeFiles : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() / ("milldyn-include-" + std::string(info->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "parts");
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(m_dir, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(m_dir / name) << text;
        return (m_dir / name).string();
    }
    fs::path m_dir;
};

TEST_F(IncludeFiles, FidelityLevelsAndNamedScenariosWorkWithParts) {
    write("parts/loads.yaml",
          "elements:\n"
          "  - {type: ResistanceTorque, name: load, body: rotor, constant_torque: 5 N*m, fidelity: [light]}\n"
          "  - {type: ResistanceTorque, name: load, body: rotor, constant_torque: 9 N*m, fidelity: [heavy]}\n");
    const std::string top = write("top.yaml",
                                  "format_version: 1\nname: levels\n"
                                  "fidelity: {level: light, levels: [light, heavy]}\n"
                                  "include: {file: parts/loads.yaml}\n"
                                  "bodies:\n  - {name: rotor, inertia: 1 kg*m^2, joint: {type: pin}}\n"
                                  "scenario: {analysis: transient, end_time: 1 s}\n"
                                  "scenarios:\n  modes: {analysis: linearize}\n");
    EXPECT_EQ(read(top).findElement("load")->number("constant_torque"), 5);
    const ModelSpec heavy = read(top, {{"fidelity.level", "heavy"}, {"use_scenario", "modes"}});
    EXPECT_EQ(heavy.findElement("load")->number("constant_torque"), 9);
    EXPECT_EQ(heavy.scenario.type, "linearize");
    // A part's element may refer to a body of the including file: elements
    // are read after every body.
    EXPECT_EQ(heavy.findElement("load")->text("body"), "rotor");
}

TEST_F(IncludeFiles, DiamondIncludesAreNotCycles) {
    write("parts/shaft.yaml", "bodies:\n  - {name: shaft, inertia: 1 kg*m^2, joint: {type: pin}}\n");
    write("parts/a.yaml", "include: [{file: shaft.yaml, prefix: a_}]\n");
    write("parts/b.yaml", "include: [{file: shaft.yaml, prefix: b_}]\n");
    const std::string top = write("top.yaml", "format_version: 1\nname: diamond\ninclude: [parts/a.yaml, parts/b.yaml]\n"
                                              "scenario: {analysis: linearize}\n");
    const ModelSpec spec = read(top);
    ASSERT_EQ(spec.bodies.size(), 2u);
    EXPECT_EQ(spec.bodies[0].name, "a_shaft");
    EXPECT_EQ(spec.bodies[1].name, "b_shaft");
}

TEST_F(IncludeFiles, FormattedDiagnosticEndsWithTheIncludeChain) {
    write("parts/bad.yaml", "bodies:\n  - {name: r, inertia: -1 kg*m^2, joint: {type: pin}}\n");
    const std::string top = write("top.yaml", "format_version: 1\nname: x\ninclude:\n  - parts/bad.yaml\n"
                                              "scenario: {analysis: linearize}\n");
    try {
        read(top);
        FAIL() << "accepted";
    } catch (const SpecError& e) {
        const std::string part = (m_dir / "parts/bad.yaml").string();
        EXPECT_EQ(e.formatted(), part + ":2:24: error: r.inertia: moment of inertia must be > 0 kg*m^2, got -1"
                                 " (included from " + top + ":4:5)");
    }
}

TEST_F(IncludeFiles, PartWithoutBodiesOrElementsAddsNothingAndAnEmptyPartIsAnError) {
    write("parts/nothing.yaml", "description: only words\n");
    write("parts/empty.yaml", "");
    const std::string ok = write("ok.yaml", "format_version: 1\nname: x\ninclude: parts/nothing.yaml\n"
                                            "bodies:\n  - {name: r, inertia: 1 kg*m^2, joint: {type: pin}}\n"
                                            "scenario: {analysis: linearize}\n");
    EXPECT_EQ(read(ok).bodies.size(), 1u);
    const std::string bad = write("bad.yaml", "format_version: 1\nname: x\ninclude: parts/empty.yaml\n"
                                              "scenario: {analysis: linearize}\n");
    const SpecError e = test::readErrorOf(bad, "format_version: 1\nname: x\ninclude: parts/empty.yaml\n"
                                               "scenario: {analysis: linearize}\n", {});
    EXPECT_EQ(e.where().file, (m_dir / "parts/empty.yaml").string());
    EXPECT_TRUE(contains(e.what(), "the part file is empty")) << e.formatted();
    EXPECT_EQ(e.where().includedFrom, bad + ":3:10");
}

TEST_F(IncludeFiles, DeviceOrDirectoryIsRefusedAtTheIncludeNotRead) {
    fs::create_directories(m_dir / "parts/adir");
    for (const std::string target : {"/dev/zero", "parts/adir"}) {
        SCOPED_TRACE(target);
        const std::string text = "format_version: 1\nname: x\ninclude: " + target + "\nscenario: {analysis: linearize}\n";
        const std::string top = write("top.yaml", text);
        const SpecError e = test::readErrorOf(top, text, {});
        test::expectSpecError(e, top, 3, 10, "include", target == "/dev/zero" ? "not a regular file" : "is a directory");
    }
}

// Every file of tests/testdata/bad/include/ fails in a part, where its
// comments say: "# expect: PART:LINE:COL KEY" and "# included-from: CHAIN",
// paths relative to that directory.
TEST(ModelInclude, EveryBadIncludeTestdataFileFailsInThePartItsCommentNames) {
    const fs::path dir = kData + "/bad/include";
    auto resolve = [&](const std::string& relative) { return (dir / relative).lexically_normal().string(); };
    int checked = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".yaml") continue;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        std::ifstream in(path);
        std::string line, expect, chain;
        while (std::getline(in, line)) {
            if (line.rfind("# expect: ", 0) == 0) expect = line.substr(10);
            if (line.rfind("# included-from: ", 0) == 0) chain = line.substr(17);
        }
        ASSERT_FALSE(expect.empty() || chain.empty()) << "needs '# expect:' and '# included-from:' comments";
        std::istringstream e(expect);
        std::string where, key;
        e >> where >> key;
        const auto c2 = where.rfind(':'), c1 = where.rfind(':', c2 - 1);
        // The chain: "a.yaml:1:2, included from b.yaml:3:4", each path resolved.
        std::string expectedChain;
        std::istringstream links(chain);
        for (std::string link; std::getline(links, link, ',');) {
            link.erase(0, link.find_first_not_of(' '));
            if (link.rfind("included from ", 0) == 0) link = link.substr(14);
            const auto l2 = link.rfind(':'), l1 = link.rfind(':', l2 - 1);
            expectedChain += (expectedChain.empty() ? "" : ", included from ") + resolve(link.substr(0, l1)) +
                             link.substr(l1);
        }
        try {
            read(path);
            ADD_FAILURE() << "accepted";
        } catch (const SpecError& err) {
            EXPECT_EQ(err.where().file, resolve(where.substr(0, c1))) << err.formatted();
            EXPECT_EQ(err.where().line, std::stoi(where.substr(c1 + 1, c2 - c1 - 1))) << err.formatted();
            EXPECT_EQ(err.where().column, std::stoi(where.substr(c2 + 1))) << err.formatted();
            EXPECT_EQ(err.key(), key == "<document>" ? "" : key) << err.formatted();
            EXPECT_EQ(err.where().includedFrom, expectedChain) << err.formatted();
            EXPECT_TRUE(contains(err.formatted(), " (included from " + expectedChain + ")")) << err.formatted();
        }
        ++checked;
    }
    EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace milldyn
