// ModelFile: a good model file becomes a ModelSpec in SI units with the
// defaults filled in; every class of bad input becomes one SpecError that
// names the file, the line and column of the offending token, the key, and
// the reason, and formats as ONE line `file:line:col: error: key: reason`.
//
// Most tests take kBase (a two-shaft burr mill written so that its line
// numbers are easy to follow) and change one token in it; the expected line
// and column are those of the changed token in kBase's text.

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

// SI conversions are a multiplication or two: a few roundings of a double.
constexpr double kConversionRelTol = 1e-12;
constexpr double kPi = 3.14159265358979323846;

constexpr const char* kFile = "test.yaml";

// Line numbers, for reading the expectations below:
//  1 format_version   4 body motor_shaft  7 body millstone  12 motor
// 17 rated_speed     19 belt             22 stiffness       23 grinding
// 27 scenario        30 integrator       32 accuracy
const std::string kBase = R"(format_version: 1
name: test rig
bodies:
  - name: motor_shaft
    inertia: 190.7e-4 kg*m^2
    joint: {type: pin, parent: ground}
  - name: millstone
    inertia: 982.4e-4 kg*m^2
    mass: 12 kg
    joint: {type: pin, parent: ground}
elements:
  - type: InductionMotor
    name: motor
    body: motor_shaft
    law: kloss
    rated_torque: 36.3 N*m
    rated_speed: 1446 rpm
    synchronous_speed: 1500 rpm
  - type: TorsionalCoupling
    name: belt
    bodies: [motor_shaft, millstone]
    stiffness: 537 N*m/rad
  - type: ResistanceTorque
    name: grinding
    body: millstone
    constant_torque: 16.2 N*m
scenario:
  analysis: transient
  end_time: 7 s
integrator:
  name: CPodes
  accuracy: 1e-6
)";

/// kBase (or `text`) with the one occurrence of `from` replaced by `to`.
std::string replaced(const std::string& from, const std::string& to, const std::string& text = kBase) {
    return test::replacedIn(text, from, to);
}

ModelSpec read(const std::string& text, const std::vector<Override>& overrides = {}) {
    return test::readText(kFile, text, overrides);
}

/// The SpecError reading `text` throws; a test failure if it throws none.
SpecError readError(const std::string& text, const std::vector<Override>& overrides = {}) {
    return test::readErrorOf(kFile, text, overrides);
}

using test::contains;

/// Checks location, key, reason and the one-line formatted diagnostic.
void expectError(const SpecError& e, const std::string& file, int line, int column, const std::string& key,
                 const std::string& reasonPart) {
    test::expectSpecError(e, file, line, column, key, reasonPart);
}

void expectError(const SpecError& e, int line, int column, const std::string& key, const std::string& reasonPart) {
    expectError(e, kFile, line, column, key, reasonPart);
}

std::string sourceDir() { return MILLDYN_SOURCE_DIR; }

// ---------------------------------------------------------------- good input

TEST(ModelFileRead, GoodTextGivesSiValuesAndFillsDefaults) {
    const ModelSpec spec = read(kBase);
    EXPECT_EQ(spec.file, kFile);
    EXPECT_EQ(spec.formatVersion, 1);
    EXPECT_EQ(spec.name, "test rig");
    EXPECT_EQ(spec.description, "");

    ASSERT_EQ(spec.bodies.size(), 2u);
    const BodySpec& shaft = spec.bodies[0];
    EXPECT_EQ(shaft.name, "motor_shaft");
    EXPECT_NEAR(shaft.inertia, 190.7e-4, kConversionRelTol * 190.7e-4);
    EXPECT_EQ(shaft.mass, 0.0);  // default
    EXPECT_EQ(shaft.joint.type, "pin");
    EXPECT_EQ(shaft.joint.parent, "ground");
    EXPECT_EQ(shaft.joint.location, (std::array<double, 3>{{0, 0, 0}}));
    EXPECT_EQ(shaft.initialAngle, 0.0);
    EXPECT_EQ(shaft.initialSpeed, 0.0);
    EXPECT_EQ(shaft.where.line, 4);
    EXPECT_EQ(shaft.where.column, 5);
    EXPECT_NEAR(spec.bodies[1].inertia, 982.4e-4, kConversionRelTol * 982.4e-4);
    EXPECT_EQ(spec.bodies[1].mass, 12.0);

    ASSERT_EQ(spec.elements.size(), 3u);
    const ElementSpec& motor = spec.elements[0];
    EXPECT_EQ(motor.type, "InductionMotor");
    EXPECT_EQ(motor.name, "motor");
    // By hand: 1446 rpm = 1446 * 2*pi/60 rad/s = 48.2*pi rad/s = 151.42476590302803 rad/s.
    EXPECT_NEAR(motor.number("rated_speed"), 151.42476590302803, kConversionRelTol * 151.4);
    EXPECT_NEAR(motor.number("synchronous_speed"), 50 * kPi, kConversionRelTol * 157.1);
    EXPECT_DOUBLE_EQ(motor.number("rated_torque"), 36.3);
    EXPECT_EQ(motor.text("law"), "kloss");
    EXPECT_EQ(motor.text("body"), "motor_shaft");
    EXPECT_TRUE(motor.has("rated_speed"));
    EXPECT_EQ(motor.whereOf("rated_speed").line, 17);
    EXPECT_EQ(motor.whereOf("rated_speed").column, 18);
    // Defaults of the InductionMotor schema, not given in the text.
    EXPECT_FALSE(motor.has("breakdown_ratio"));
    EXPECT_DOUBLE_EQ(motor.number("breakdown_ratio"), 2.2);
    EXPECT_EQ(motor.number("linear_slope"), 0.0);
    EXPECT_TRUE(std::isinf(motor.number("switch_off_time")));
    EXPECT_EQ(motor.whereOf("breakdown_ratio").line, 12);  // a defaulted key is located at its element

    const ElementSpec& belt = spec.elements[1];
    EXPECT_EQ(belt.names("bodies"), (std::vector<std::string>{"motor_shaft", "millstone"}));
    EXPECT_DOUBLE_EQ(belt.number("stiffness"), 537.0);
    EXPECT_EQ(belt.number("damping"), 0.0);
    EXPECT_EQ(belt.number("ratio"), 1.0);
    EXPECT_EQ(belt.whereOf("stiffness").line, 22);
    EXPECT_EQ(belt.whereOf("stiffness").column, 16);

    const ElementSpec& grinding = spec.elements[2];
    EXPECT_DOUBLE_EQ(grinding.number("constant_torque"), 16.2);
    EXPECT_EQ(grinding.text("law"), "speed_linear");
    EXPECT_DOUBLE_EQ(grinding.number("smoothing_speed"), 0.01);
    EXPECT_EQ(grinding.number("viscous_coefficient"), 0.0);

    EXPECT_EQ(spec.scenario.type, "transient");
    EXPECT_EQ(spec.scenario.name, "scenario");
    EXPECT_EQ(spec.scenario.number("end_time"), 7.0);
    EXPECT_EQ(spec.scenario.text("initial_state"), "rest");
    EXPECT_EQ(spec.scenario.text("speed_body"), "");

    EXPECT_EQ(spec.integrator.name, "CPodes");
    EXPECT_EQ(spec.integrator.accuracy, 1e-6);
    EXPECT_EQ(spec.integrator.maxStep, 0.0);
    EXPECT_EQ(spec.outputs.sampleInterval, 1e-3);  // no outputs: section
    EXPECT_TRUE(spec.outputs.plots);

    EXPECT_EQ(spec.findBody("millstone"), &spec.bodies[1]);
    EXPECT_EQ(spec.findBody("ground"), nullptr);
    EXPECT_EQ(spec.findElement("belt"), &spec.elements[1]);
}

TEST(ModelFileRead, GoodMinimalFileReadsFromDiskWithDefaults) {
    const std::string path = sourceDir() + "/tests/testdata/good_minimal.yaml";
    const ModelSpec spec = readModelFile(path, defaultModelReader());
    EXPECT_EQ(spec.file, path);
    ASSERT_EQ(spec.bodies.size(), 1u);
    EXPECT_EQ(spec.bodies[0].joint.parent, "ground");
    EXPECT_DOUBLE_EQ(spec.bodies[0].inertia, 0.05);
    ASSERT_EQ(spec.elements.size(), 2u);
    EXPECT_EQ(spec.elements[0].text("law"), "kloss");
    EXPECT_EQ(spec.integrator.name, "CPodes");
    EXPECT_EQ(spec.integrator.accuracy, 1e-6);
    EXPECT_DOUBLE_EQ(spec.scenario.number("end_time"), 0.2);
}

TEST(ModelFileRead, EveryShippedModelReads) {
    int read = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir() + "/models")) {
        if (entry.path().extension() != ".yaml") continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW(readModelFile(entry.path().string(), defaultModelReader()));
        ++read;
    }
    EXPECT_GT(read, 0);
}

// ----------------------------------------------------------------- bad input

TEST(ModelFileErrors, MalformedYamlIsLocatedAtTheOffendingToken) {
    const SpecError e = readError(replaced("  end_time: 7 s", "  end_time: ]"));
    expectError(e, 29, 13, "", "malformed YAML");
}

TEST(ModelFileErrors, EmptyFileIsReportedAtLineOneColumnOne) {
    expectError(readError(""), 1, 1, "", "empty");
    expectError(readError("# nothing but a comment\n\n"), 1, 1, "", "empty");
}

TEST(ModelFileErrors, UnknownTopLevelKeySuggestsTheNearestKey) {
    const SpecError e = readError(replaced("integrator:\n", "intergrator:\n"));
    expectError(e, 30, 1, "intergrator", "unknown key 'intergrator' (did you mean 'integrator'?)");
}

TEST(ModelFileErrors, UnknownBodyKeySuggestsTheNearestKey) {
    const SpecError e = readError(replaced("    inertia: 982.4e-4", "    inertai: 982.4e-4"));
    EXPECT_EQ(e.where().line, 8);
    EXPECT_EQ(e.where().column, 5);
    EXPECT_TRUE(contains(e.what(), "unknown key 'inertai' (did you mean 'inertia'?)")) << e.what();
    EXPECT_EQ(e.formatted().rfind("test.yaml:8:5: error: ", 0), 0u) << e.formatted();
}

TEST(ModelFileErrors, UnknownElementKeySuggestsTheNearestKey) {
    const SpecError e = readError(replaced("    stiffness:", "    stifness:"));
    expectError(e, 22, 5, "belt.stifness", "unknown key 'stifness' (did you mean 'stiffness'?)");
}

TEST(ModelFileErrors, UnknownElementTypeSuggestsTheNearestType) {
    const SpecError e = readError(replaced("type: TorsionalCoupling", "type: TorsionalCoupler"));
    expectError(e, 19, 11, "belt.type",
                "unknown element type 'TorsionalCoupler' (did you mean 'TorsionalCoupling'?)");
}

TEST(ModelFileErrors, UnknownAnalysisKindSuggestsTheNearestKind) {
    const SpecError e = readError(replaced("analysis: transient", "analysis: transiant"));
    expectError(e, 28, 13, "scenario.analysis", "unknown analysis 'transiant' (did you mean 'transient'?)");
}

TEST(ModelFileErrors, ListWhereANumberIsExpectedIsAWrongType) {
    const SpecError e = readError(replaced("stiffness: 537 N*m/rad", "stiffness: [537, 600]"));
    expectError(e, 22, 16, "belt.stiffness", "expected a single value, got a list");
}

TEST(ModelFileErrors, MappingWhereAListIsExpectedIsAWrongType) {
    const SpecError e =
        readError(replaced("bodies: [motor_shaft, millstone]", "bodies: {from: motor_shaft, to: millstone}"));
    expectError(e, 21, 13, "belt.bodies", "expected a list, got a mapping");

    // The top-level bodies as a block mapping: located at its first key.
    const std::string text = "format_version: 1\nname: x\nbodies:\n  name: rotor\n  inertia: 1\n"
                             "scenario: {analysis: transient, end_time: 1}\n";
    expectError(readError(text), 4, 3, "bodies", "expected a list, got a mapping");
}

TEST(ModelFileErrors, MissingRequiredElementKeyIsLocatedAtTheElement) {
    const SpecError e = readError(replaced("    stiffness: 537 N*m/rad\n", ""));
    expectError(e, 19, 5, "belt.stiffness", "missing required key 'stiffness'");
}

TEST(ModelFileErrors, MissingBodyInertiaIsLocatedAtTheBody) {
    const SpecError e = readError(replaced("    inertia: 982.4e-4 kg*m^2\n", ""));
    expectError(e, 7, 5, "millstone.inertia", "missing required key 'inertia'");
}

TEST(ModelFileErrors, MissingScenarioAnalysisIsLocatedAtTheScenario) {
    const SpecError e = readError(replaced("  analysis: transient\n", ""));
    expectError(e, 28, 3, "scenario.analysis", "missing required key 'analysis'");
}

TEST(ModelFileErrors, MissingFormatVersionIsLocatedAtTheDocument) {
    // Comment lines first: the document (its first key) starts on line 3.
    const SpecError e = readError("# a model\n\n" + replaced("format_version: 1\n", ""));
    expectError(e, 3, 1, "format_version", "missing required key 'format_version'");
}

TEST(ModelFileErrors, UnsupportedFormatVersionIsRefused) {
    const SpecError e = readError(replaced("format_version: 1", "format_version: 2"));
    expectError(e, 1, 17, "format_version", "unsupported format version 2");
}

TEST(ModelFileErrors, FractionalFormatVersionIsRefused) {
    // A version is a whole number; 1.5 must not be read as version 1.
    const SpecError e = readError(replaced("format_version: 1", "format_version: 1.5"));
    expectError(e, 1, 17, "format_version", "1.5");
}

TEST(ModelFileErrors, ZeroInertiaIsRefused) {
    const SpecError e = readError(replaced("190.7e-4 kg*m^2", "0 kg*m^2"));
    expectError(e, 5, 14, "motor_shaft.inertia", "must be > 0 kg*m^2");
}

TEST(ModelFileErrors, BareNumberOnADimensionalKeyIsRefusedWithAUnitHint) {
    // issue 20 item 7: `rated_speed: 1490` beside `synchronous_speed: 1500 rpm`
    // was taken as 1490 rad/s (a 14,300 rpm motor).
    const SpecError e = readError(replaced("rated_speed: 1446 rpm", "rated_speed: 1490"));
    expectError(e, 17, 22, "motor.rated_speed", "a bare number needs a unit here (did you mean 1490 rpm or 1490 rad/s?)");
}

TEST(ModelFileErrors, BareNumberThroughSetIsRefusedToo) {
    const SpecError e = readError(kBase, {{"elements.belt.stiffness", "600"}});
    EXPECT_EQ(e.where().file, "<--set elements.belt.stiffness>");
    EXPECT_TRUE(contains(e.what(), "did you mean 600 N*m/rad?")) << e.what();
}

TEST(ModelFileRead, BareZeroAndDimensionlessNumbersNeedNoUnit) {
    const ModelSpec m = read(kBase, {{"elements.belt.stiffness", "0"}, {"integrator.accuracy", "1e-7"}});
    EXPECT_EQ(m.findElement("belt")->params.at("stiffness").number, 0.0);
    EXPECT_EQ(m.integrator.accuracy, 1e-7);
}

TEST(ModelFileErrors, NegativeInertiaIsRefused) {
    const SpecError e = readError(replaced("190.7e-4 kg*m^2", "-190.7e-4 kg*m^2"));
    expectError(e, 5, 14, "motor_shaft.inertia", "must be > 0 kg*m^2, got -0.01907");
}

TEST(ModelFileErrors, NegativeMassIsRefused) {
    const SpecError e = readError(replaced("mass: 12 kg", "mass: -12 kg"));
    expectError(e, 9, 11, "millstone.mass", "mass must be >= 0 kg, got -12");
}

TEST(ModelFileErrors, RatedSpeedAtSynchronousSpeedIsRefusedByTheCrossCheck) {
    const SpecError e = readError(replaced("rated_speed: 1446 rpm", "rated_speed: 1500 rpm"));
    expectError(e, 17, 18, "motor.rated_speed", "rated speed must be below the synchronous speed");
}

TEST(ModelFileErrors, RatedSpeedAboveSynchronousSpeedIsRefusedByTheCrossCheck) {
    // In other units than the synchronous speed: the check compares SI values.
    const SpecError e = readError(replaced("rated_speed: 1446 rpm", "rated_speed: 26 Hz*rev"));
    expectError(e, 17, 18, "motor.rated_speed", "rated speed must be below the synchronous speed");
}

TEST(ModelFileErrors, UnknownUnitSuggestsTheNearestUnitAndPointsAtIt) {
    const SpecError e = readError(replaced("rated_speed: 1446 rpm", "rated_speed: 1446 rmp"));
    expectError(e, 17, 23, "motor.rated_speed", "unknown unit 'rmp' (did you mean 'rpm'?)");
}

TEST(ModelFileErrors, IncompatibleUnitNamesTheExpectedUnit) {
    const SpecError e = readError(replaced("stiffness: 537 N*m/rad", "stiffness: 537 N*m"));
    expectError(e, 22, 20, "belt.stiffness", "incompatible unit 'N*m': expected a quantity in N*m/rad");
}

TEST(ModelFileErrors, NanAndInfinityTextIsRefused) {
    for (const std::string value : {"nan", "NaN N*m/rad", "inf", "-inf N*m/rad", "infinity", "1e999 N*m/rad"}) {
        SCOPED_TRACE(value);
        const SpecError e = readError(replaced("stiffness: 537 N*m/rad", "stiffness: " + value));
        expectError(e, 22, 16, "belt.stiffness", "");
        EXPECT_TRUE(contains(e.what(), "finite") || contains(e.what(), "out of range")) << e.what();
    }
}

TEST(ModelFileErrors, NegativeStiffnessIsOutOfRange) {
    const SpecError e = readError(replaced("stiffness: 537 N*m/rad", "stiffness: -537 N*m/rad"));
    expectError(e, 22, 16, "belt.stiffness", "must be >= 0 N*m/rad, got -537 N*m/rad");
}

TEST(ModelFileErrors, AccuracyZeroIsOutOfRange) {
    const SpecError e = readError(replaced("accuracy: 1e-6", "accuracy: 0"));
    expectError(e, 32, 13, "integrator.accuracy", "must lie in (0, 1) (Simbody refuses 1 and above), got 0");
}

TEST(ModelFileErrors, AccuracyAboveOneIsOutOfRange) {
    const SpecError e = readError(replaced("accuracy: 1e-6", "accuracy: 1.5"));
    expectError(e, 32, 13, "integrator.accuracy", "must lie in (0, 1) (Simbody refuses 1 and above), got 1.5");
}

TEST(ModelFileErrors, UnknownBodyReferenceSuggestsTheNearestBody) {
    expectError(readError(replaced("body: millstone", "body: milstone")), 25, 11, "grinding.body",
                "no body named 'milstone' (did you mean 'millstone'?)");
    // In a body pair the error points at the item, not at the list.
    expectError(readError(replaced("[motor_shaft, millstone]", "[motor_shaft, milstone]")), 21, 27, "belt.bodies",
                "no body named 'milstone' (did you mean 'millstone'?)");
}

TEST(ModelFileErrors, DuplicateBodyNameIsRefused) {
    const SpecError e = readError(replaced("  - name: millstone", "  - name: motor_shaft"));
    expectError(e, 7, 11, "name", "a body named 'motor_shaft' exists already");
}

TEST(ModelFileErrors, DuplicateElementNameIsRefused) {
    const SpecError e = readError(replaced("    name: grinding", "    name: belt"));
    expectError(e, 24, 11, "name", "an element named 'belt' exists already");
}

TEST(ModelFileErrors, DuplicateKeyIsRefusedAtItsSecondOccurrence) {
    expectError(readError(replaced("    stiffness: 537 N*m/rad\n", "    stiffness: 537 N*m/rad\n    stiffness: 1 N*m/rad\n")),
                23, 5, "belt.stiffness", "duplicate key");
    expectError(readError(kBase + "name: again\n"), 33, 1, "name", "duplicate key");
}

TEST(ModelFileErrors, BodyNamedGroundIsRefused) {
    const SpecError e = readError(replaced("  - name: millstone", "  - name: ground"));
    expectError(e, 7, 11, "name", "'ground' is reserved");
}

TEST(ModelFileErrors, ParentDefinedAfterChildIsRefused) {
    const SpecError e = readError(replaced("kg*m^2\n    joint: {type: pin, parent: ground}\n  - name: millstone",
                                           "kg*m^2\n    joint: {type: pin, parent: millstone}\n  - name: millstone"));
    expectError(e, 6, 32, "motor_shaft.joint.parent", "no body named 'millstone' defined above this one");
}

TEST(ModelFileErrors, CouplingWithOneBodyIsAListOfTheWrongLength) {
    const SpecError e = readError(replaced("bodies: [motor_shaft, millstone]", "bodies: [motor_shaft]"));
    expectError(e, 21, 13, "belt.bodies", "expected a list of two body names, got 1 items");
}

TEST(ModelFileErrors, UnknownChoiceValueSuggestsTheNearestChoice) {
    const SpecError e = readError(replaced("law: kloss", "law: klos"));
    expectError(e, 15, 10, "motor.law", "unknown value 'klos' (expected one of kloss, linear, catalogue, table, kloss_modified) (did you mean 'kloss'?)");
}

TEST(ModelFileErrors, UnknownIntegratorSuggestsTheNearestName) {
    const SpecError e = readError(replaced("name: CPodes", "name: CPodez"));
    expectError(e, 31, 9, "integrator.name", "unknown integrator 'CPodez' (did you mean 'CPodes'?)");
}

TEST(ModelFileErrors, FormattedIsOneLineEvenWhenTheKeyHoldsANewline) {
    const SpecError e = readError(kBase + "\"two\\nlines\": 1\n");
    EXPECT_EQ(e.where().line, 33);
    EXPECT_FALSE(contains(e.formatted(), "\n")) << e.formatted();
    EXPECT_EQ(e.formatted().rfind("test.yaml:33:1: error: two lines: unknown key", 0), 0u) << e.formatted();
}

TEST(ModelFileErrors, MissingFileIsReportedWithItsPath) {
    const std::string path = sourceDir() + "/tests/testdata/no_such_model.yaml";
    try {
        readModelFile(path, defaultModelReader());
        FAIL() << "a missing file was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, path);
        EXPECT_TRUE(contains(e.what(), "cannot open")) << e.what();
        EXPECT_EQ(e.formatted().rfind(path + ":", 0), 0u);
    }
}

// Every file in tests/testdata/bad/ says in a comment where its error is:
// "# expect: LINE:COL KEY" (KEY as printed, "<document>" for none).
TEST(ModelFileErrors, EveryBadTestdataFileFailsWhereItsCommentSays) {
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir() + "/tests/testdata/bad")) {
        if (entry.path().extension() != ".yaml") continue;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        std::ifstream in(path);
        std::string line, expect;
        while (std::getline(in, line))
            if (line.rfind("# expect: ", 0) == 0) expect = line.substr(10);
        ASSERT_FALSE(expect.empty()) << "no '# expect: LINE:COL KEY' comment";
        int expLine = 0, expCol = 0;
        char colon = 0;
        std::string key;
        std::istringstream(expect) >> expLine >> colon >> expCol >> key;
        try {
            readModelFile(path, defaultModelReader());
            ADD_FAILURE() << "accepted";
        } catch (const SpecError& e) {
            EXPECT_EQ(e.where().file, path);
            EXPECT_EQ(e.where().line, expLine) << e.formatted();
            EXPECT_EQ(e.where().column, expCol) << e.formatted();
            EXPECT_EQ(e.key(), key == "<document>" ? "" : key) << e.formatted();
        }
        ++checked;
    }
    EXPECT_GE(checked, 30);
}

// ------------------------------------------------------------ --set overrides

TEST(ModelFileOverride, OverrideOfAScenarioKeyChangesTheValueWithUnits) {
    const ModelSpec spec = read(kBase, {{"scenario.end_time", "300 ms"}, {"integrator.accuracy", "1e-4"}});
    EXPECT_NEAR(spec.scenario.number("end_time"), 0.3, kConversionRelTol);
    EXPECT_EQ(spec.integrator.accuracy, 1e-4);
    // A key the file leaves out is added, with units.
    const ModelSpec added = read(kBase, {{"integrator.max_step", "0.1 ms"}});
    EXPECT_NEAR(added.integrator.maxStep, 1e-4, kConversionRelTol * 1e-4);
}

TEST(ModelFileOverride, OverrideOfAnElementKeyByItemNameChangesTheValue) {
    const ModelSpec spec = read(kBase, {{"elements.grinding.constant_torque", "20 N*m"},
                                        {"elements.motor.rated_speed", "1400 rpm"}});
    EXPECT_DOUBLE_EQ(spec.findElement("grinding")->number("constant_torque"), 20.0);
    EXPECT_NEAR(spec.findElement("motor")->number("rated_speed"), 1400 * kPi / 30, kConversionRelTol * 150);
}

TEST(ModelFileOverride, OverrideByListIndexAndOfAnOmittedElementKeyChangesTheValue) {
    const ModelSpec spec = read(kBase, {{"bodies.1.mass", "5 kg"}, {"elements.belt.damping", "0.3 N*m*s/rad"}});
    EXPECT_EQ(spec.bodies[1].mass, 5.0);
    EXPECT_DOUBLE_EQ(spec.findElement("belt")->number("damping"), 0.3);
    EXPECT_TRUE(spec.findElement("belt")->has("damping"));
}

TEST(ModelFileOverride, BadPathIsLocatedAtTheCommandLine) {
    // A missing mapping on the path is created (so --integrator works on a
    // file without an integrator: section); the reader then rejects an
    // unknown section, located at the --set that made it.
    expectError(readError(kBase, {{"nothere.stiffness", "1"}}), "<--set nothere.stiffness>", 1, 1, "nothere",
                "unknown key 'nothere'");
    expectError(readError(kBase, {{"elements.nothere.stiffness", "1"}}), "<--set elements.nothere.stiffness>", 1,
                1, "elements.nothere.stiffness", "no list item named 'nothere'");
}

TEST(ModelFileOverride, PathThroughASingleValueNamesThatValue) {
    // "name" holds a single value, so the path cannot go on to "first".
    expectError(readError(kBase, {{"name.first.x", "1"}}), "<--set name.first.x>", 1, 1, "name.first.x",
                "'name' is a single value");
}

TEST(ModelFileOverride, BadValueIsLocatedAtTheCommandLine) {
    const SpecError e = readError(kBase, {{"scenario.end_time", "7 rmp"}});
    EXPECT_EQ(e.where().file, "<--set scenario.end_time>");
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.key(), "scenario.end_time");
    EXPECT_TRUE(contains(e.what(), "unknown unit 'rmp'")) << e.what();
    EXPECT_EQ(e.formatted().rfind("<--set scenario.end_time>:1:", 0), 0u) << e.formatted();

    const SpecError range = readError(kBase, {{"integrator.accuracy", "2"}});
    expectError(range, "<--set integrator.accuracy>", 1, 1, "integrator.accuracy", "must lie in (0, 1)");
}

TEST(ModelFileOverride, UnknownKeyAddedByAnOverrideIsLocatedAtTheCommandLine) {
    const SpecError e = readError(kBase, {{"integrator.nmae", "CPodes"}});
    expectError(e, "<--set integrator.nmae>", 1, 1, "integrator.nmae", "unknown key 'nmae' (did you mean 'name'?)");
}

TEST(ModelFileOverride, OverridingAMappingIsRefused) {
    expectError(readError(kBase, {{"scenario", "transient"}}), "<--set scenario>", 1, 1, "scenario",
                "replaces single values only");
    expectError(readError(kBase, {{"integrator", "RungeKutta3"}}), "<--set integrator>", 1, 1, "integrator",
                "replaces single values only");
}

TEST(ModelFileOverride, ParseOverrideSplitsAtTheFirstEqualsSign) {
    const Override o = parseOverride("elements.grinding.constant_torque=20 N*m");
    EXPECT_EQ(o.path, "elements.grinding.constant_torque");
    EXPECT_EQ(o.value, "20 N*m");
    EXPECT_EQ(parseOverride("name=a=b").value, "a=b");
}

TEST(ModelFileOverride, ParseOverrideRefusesMalformedText) {
    for (const std::string text : {"no_equals_sign", "=1", ".a=1", "a.=1", "a..b=1"}) {
        SCOPED_TRACE(text);
        try {
            parseOverride(text);
            ADD_FAILURE() << "accepted";
        } catch (const SpecError& e) {
            EXPECT_EQ(e.where().file, "<--set>");
            EXPECT_FALSE(contains(e.formatted(), "\n"));
        }
    }
}

}  // namespace
}  // namespace milldyn
