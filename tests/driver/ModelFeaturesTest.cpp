// Model-file features beyond the basic format (tests/driver/ModelFileTest.cpp
// covers that): fidelity levels, element names shared across levels, named
// scenarios, list-valued keys (QuantityList, BodyList) and --set through YAML
// aliases.
//
// As in ModelFileTest, each error test changes one token of a base text and
// expects the SpecError at the line and column of that token (1-based), with
// the key and the reason; the line maps above each base text are there to
// read the expectations.

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"

#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace milldyn {
namespace {

// SI conversions are a multiplication or two: a few roundings of a double.
constexpr double kConversionRelTol = 1e-12;

constexpr const char* kFile = "features.yaml";

// Two fidelity levels: `coarse` (motor + rotor) and `fine` (motor + rowA +
// rowB); `link` exists once per level, `drive` belongs to both.
//  3 fidelity        5 motor     8 rotor (coarse)   12 rowA (fine)
// 16 rowB (fine)    21 drive    28 link (coarse)    33 link (fine)
// 38 shaft (fine)   43 scenario 46 speed_body
const std::string kLevels = R"(format_version: 1
name: features
fidelity: {level: fine, levels: [coarse, fine]}
bodies:
  - name: motor
    inertia: 1 kg*m^2
    joint: {type: pin, parent: ground}
  - name: rotor
    inertia: 10 kg*m^2
    joint: {type: pin, parent: ground}
    fidelity: [coarse]
  - name: rowA
    inertia: 5 kg*m^2
    joint: {type: pin, parent: ground}
    fidelity: [fine]
  - name: rowB
    inertia: 5 kg*m^2
    joint: {type: pin, parent: ground}
    fidelity: [fine]
elements:
  - type: InductionMotor
    name: drive
    body: motor
    law: linear
    rated_torque: 100 N*m
    rated_speed: 1440 rpm
    synchronous_speed: 1500 rpm
  - type: TorsionalCoupling
    name: link
    bodies: [motor, rotor]
    stiffness: 1000 N*m/rad
    fidelity: [coarse]
  - type: TorsionalCoupling
    name: link
    bodies: [motor, rowA]
    stiffness: 2000 N*m/rad
    fidelity: [fine]
  - type: TorsionalCoupling
    name: shaft
    bodies: [rowA, rowB]
    stiffness: 5000 N*m/rad
    fidelity: [fine]
scenario:
  analysis: transient
  end_time: 1 s
  speed_body: motor
)";

// One shaft, two named scenarios, `run` selected.
//  4 shaft  12 scenarios  13 modes  15 run  17 end_time  18 speed_body  19 use_scenario
const std::string kScenarios = R"(format_version: 1
name: scenarios
bodies:
  - name: shaft
    inertia: 1 kg*m^2
    joint: {type: pin, parent: ground}
elements:
  - type: ResistanceTorque
    name: load
    body: shaft
    constant_torque: 1 N*m
scenarios:
  modes:
    analysis: linearize
  run:
    analysis: transient
    end_time: 2 s
    speed_body: shaft
use_scenario: run
)";

// A PeriodicLoad of three rows, one body each.
// 16 bodies  17 rows  19 amplitudes: '[' at column 17, items at 18, 25, 33
const std::string kLists = R"(format_version: 1
name: lists
bodies:
  - name: row1
    inertia: 1 kg*m^2
    joint: {type: pin, parent: ground}
  - name: row2
    inertia: 1 kg*m^2
    joint: {type: pin, parent: ground}
  - name: row3
    inertia: 1 kg*m^2
    joint: {type: pin, parent: ground}
elements:
  - type: PeriodicLoad
    name: crushing
    bodies: [row1, row2, row3]
    rows: 3
    mean_torque: 10 N*m
    amplitudes: [1 N*m, 2 kN*m, 0.5 N*m]
    fundamental_frequency: 4 rad/s
scenario:
  analysis: transient
  end_time: 1 s
)";

// Values shared through anchors and aliases: a scalar (&J, &k), a mapping
// (&pin) and a whole scenario (&s).
const std::string kAliases = R"(format_version: 1
name: aliases
bodies:
  - name: a
    inertia: &J 2 kg*m^2
    joint: &pin {type: pin, parent: ground}
  - name: b
    inertia: *J
    joint: *pin
  - name: c
    inertia: *J
    joint: *pin
elements:
  - type: TorsionalCoupling
    name: c1
    bodies: [a, b]
    stiffness: &k 1000 N*m/rad
  - type: TorsionalCoupling
    name: c2
    bodies: [b, c]
    stiffness: *k
scenarios:
  one: &s {analysis: transient, end_time: 1 s}
  two: *s
use_scenario: one
)";

/// `text` with the one occurrence of `from` replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
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

std::vector<std::string> bodyNames(const ModelSpec& spec) {
    std::vector<std::string> names;
    for (const auto& b : spec.bodies) names.push_back(b.name);
    return names;
}

std::vector<std::string> elementNames(const ModelSpec& spec) {
    std::vector<std::string> names;
    for (const auto& e : spec.elements) names.push_back(e.name);
    return names;
}

using Names = std::vector<std::string>;

// ------------------------------------------------------------------ fidelity

TEST(ModelFeaturesFidelity, SelectedLevelKeepsItsBodiesAndElementsAndDropsTheOthers) {
    const ModelSpec spec = read(kLevels);
    EXPECT_EQ(spec.fidelityLevels, (Names{"coarse", "fine"}));
    EXPECT_EQ(spec.fidelity, "fine");
    EXPECT_EQ(bodyNames(spec), (Names{"motor", "rowA", "rowB"}));
    EXPECT_EQ(elementNames(spec), (Names{"drive", "link", "shaft"}));
    // The `link` kept is the fine one (its own bodies and stiffness).
    const ElementSpec* link = spec.findElement("link");
    ASSERT_NE(link, nullptr);
    EXPECT_EQ(link->names("bodies"), (Names{"motor", "rowA"}));
    EXPECT_EQ(link->number("stiffness"), 2000.0);
    EXPECT_EQ(link->fidelity, (Names{"fine"}));
    EXPECT_EQ(link->where.line, 33);
    // A body or element without a list belongs to every level.
    EXPECT_TRUE(spec.bodies[0].fidelity.empty());
    EXPECT_TRUE(spec.elements[0].fidelity.empty());
    EXPECT_EQ(spec.bodies[1].fidelity, (Names{"fine"}));
}

TEST(ModelFeaturesFidelity, SetFidelityLevelSwitchesToTheOtherLevel) {
    const ModelSpec spec = read(kLevels, {{"fidelity.level", "coarse"}});
    EXPECT_EQ(spec.fidelity, "coarse");
    EXPECT_EQ(bodyNames(spec), (Names{"motor", "rotor"}));
    EXPECT_EQ(elementNames(spec), (Names{"drive", "link"}));
    const ElementSpec* link = spec.findElement("link");
    ASSERT_NE(link, nullptr);
    EXPECT_EQ(link->names("bodies"), (Names{"motor", "rotor"}));
    EXPECT_EQ(link->number("stiffness"), 1000.0);
    EXPECT_EQ(link->where.line, 28);
    EXPECT_DOUBLE_EQ(spec.findBody("rotor")->inertia, 10.0);
}

TEST(ModelFeaturesFidelity, UnknownSelectedLevelSuggestsTheNearestLevel) {
    // fidelity: {level: fien, ...}: the value at column 19.
    expectError(readError(replaced(kLevels, "level: fine", "level: fien")), 3, 19, "fidelity.level",
                "unknown fidelity level 'fien' (expected one of coarse, fine) (did you mean 'fine'?)");
    // The same through --set, located at the command line.
    expectError(readError(kLevels, {{"fidelity.level", "corse"}}), "<--set fidelity.level>", 1, 1, "fidelity.level",
                "unknown fidelity level 'corse' (expected one of coarse, fine) (did you mean 'coarse'?)");
}

TEST(ModelFeaturesFidelity, UnknownLevelInABodyOrElementListIsLocatedAtTheItem) {
    // rotor's `fidelity: [coarce]`: '[' at column 15, the item at 16.
    const std::string rotorList = "10 kg*m^2\n    joint: {type: pin, parent: ground}\n    fidelity: [coarse]";
    expectError(readError(replaced(kLevels, rotorList,
                                   "10 kg*m^2\n    joint: {type: pin, parent: ground}\n    fidelity: [coarce]")),
                11, 16, "rotor.fidelity",
                "unknown fidelity level 'coarce' (expected one of coarse, fine) (did you mean 'coarse'?)");
    // The fine link's `fidelity: [fine, fin]`: the second item at column 22.
    expectError(readError(replaced(kLevels, "2000 N*m/rad\n    fidelity: [fine]",
                                   "2000 N*m/rad\n    fidelity: [fine, fin]")),
                37, 22, "link.fidelity",
                "unknown fidelity level 'fin' (expected one of coarse, fine) (did you mean 'fine'?)");
}

TEST(ModelFeaturesFidelity, MemberFidelityWithoutDeclaredLevelsIsRefused) {
    // Without the top-level `fidelity:` the lines move up by one: rotor's
    // list is on line 10, its '[' at column 15.
    const std::string noLevels = replaced(kLevels, "fidelity: {level: fine, levels: [coarse, fine]}\n", "");
    expectError(readError(noLevels), 10, 15, "rotor.fidelity",
                "the model declares no fidelity levels (top-level 'fidelity:')");

    // On an element (the only list left in the file): the fine link's.
    std::string onlyElement = replaced(noLevels, "    fidelity: [coarse]\n  - name: rowA", "  - name: rowA");
    onlyElement = replaced(onlyElement, "    fidelity: [fine]\n  - name: rowB", "  - name: rowB");
    onlyElement = replaced(onlyElement, "    fidelity: [fine]\nelements:", "elements:");
    onlyElement = replaced(onlyElement, "1000 N*m/rad\n    fidelity: [coarse]\n", "1000 N*m/rad\n");
    // Five lines fewer above it: the fine link's list is on line 32. The
    // coarse link is renamed, the two now sharing every level.
    onlyElement = replaced(onlyElement, "    name: link\n    bodies: [motor, rotor]",
                           "    name: link0\n    bodies: [motor, rotor]");
    expectError(readError(onlyElement), 32, 15, "link.fidelity",
                "the model declares no fidelity levels (top-level 'fidelity:')");
}

TEST(ModelFeaturesFidelity, ElementReferringToABodyDroppedAtTheLevelIsLocatedAtTheReference) {
    // A load for every level on the coarse-only rotor: at `fine` it refers
    // to a dropped body. Lines 43-46 are the new element, its body at 45:11.
    const std::string load =
        "  - type: ResistanceTorque\n    name: load\n    body: rotor\n    constant_torque: 10 N*m\nscenario:\n";
    const std::string text = replaced(kLevels, "scenario:\n", load);
    expectError(readError(text), 45, 11, "load.body", "body 'rotor' is not part of fidelity level 'fine'");
    // At `coarse` it is fine.
    const ModelSpec coarse = read(text, {{"fidelity.level", "coarse"}});
    EXPECT_EQ(elementNames(coarse), (Names{"drive", "link", "load"}));

    // A scenario key naming a body of the other level (speed_body: rowA at
    // `coarse`): located at the value, 46:15.
    expectError(readError(replaced(kLevels, "speed_body: motor", "speed_body: rowA"), {{"fidelity.level", "coarse"}}),
                46, 15, "scenario.speed_body", "body 'rowA' is not part of fidelity level 'coarse'");
}

TEST(ModelFeaturesFidelity, BodyPairReferringToADroppedBodyIsLocatedAtThatItem) {
    // `shaft` made part of both levels, coupling motor to the fine-only rowB:
    // at `coarse` its second body is dropped. "[motor, rowB]" on line 40:
    // '[' at column 13, rowB at 21. Like an unknown body in a pair
    // (ModelFileTest), the error belongs at the item.
    std::string text = replaced(kLevels, "bodies: [rowA, rowB]", "bodies: [motor, rowB]");
    text = replaced(text, "5000 N*m/rad\n    fidelity: [fine]", "5000 N*m/rad\n    fidelity: [coarse, fine]");
    EXPECT_NO_THROW(read(text));
    expectError(readError(text, {{"fidelity.level", "coarse"}}), 40, 21, "shaft.bodies",
                "body 'rowB' is not part of fidelity level 'coarse'");
}

TEST(ModelFeaturesFidelity, ParentDroppedWhileItsChildIsKeptIsRefused) {
    // rowB (every level) hangs on rowA (fine only): at `coarse` its parent is
    // dropped. The body's joint records one location, that of its mapping
    // `{type: pin, parent: rowA}` on line 18 ('{' at column 12).
    const std::string text = replaced(kLevels,
                                      "5 kg*m^2\n    joint: {type: pin, parent: ground}\n    fidelity: [fine]\nelements:",
                                      "5 kg*m^2\n    joint: {type: pin, parent: rowA}\nelements:");
    const ModelSpec fine = read(text);
    EXPECT_EQ(fine.findBody("rowB")->joint.parent, "rowA");
    expectError(readError(text, {{"fidelity.level", "coarse"}}), 18, 12, "rowB.joint.parent",
                "body 'rowA' is not part of fidelity level 'coarse'");
}

TEST(ModelFeaturesFidelity, LevelWithoutAnyBodyIsRefused) {
    std::string text = replaced(kLevels, "levels: [coarse, fine]", "levels: [coarse, fine, bare]");
    text = replaced(text, "1 kg*m^2\n    joint: {type: pin, parent: ground}\n",
                    "1 kg*m^2\n    joint: {type: pin, parent: ground}\n    fidelity: [coarse, fine]\n");
    EXPECT_NO_THROW(read(text));
    // The reader keeps no location for the level it checks here: the error
    // is at the start of the file, under the key fidelity.level.
    expectError(readError(text, {{"fidelity.level", "bare"}}), 1, 1, "fidelity.level",
                "no body belongs to level 'bare'");
}

// --------------------------------------------------------------------- names

TEST(ModelFeaturesNames, SameElementNameInDisjointLevelsIsAccepted) {
    // kLevels has `link` at coarse and at fine.
    EXPECT_NO_THROW(read(kLevels));
    EXPECT_NO_THROW(read(kLevels, {{"fidelity.level", "coarse"}}));
}

TEST(ModelFeaturesNames, SameElementNameInOverlappingLevelsExistsAlready) {
    // Both links at `fine`: the second name (34:11) is the duplicate.
    expectError(readError(replaced(kLevels, "1000 N*m/rad\n    fidelity: [coarse]",
                                   "1000 N*m/rad\n    fidelity: [coarse, fine]")),
                34, 11, "name", "an element named 'link' exists already");
    // The first in every level (no list; the lines below move up by one).
    expectError(readError(replaced(kLevels, "1000 N*m/rad\n    fidelity: [coarse]\n", "1000 N*m/rad\n")), 33, 11,
                "name", "an element named 'link' exists already");
    // The second in every level.
    expectError(readError(replaced(kLevels, "2000 N*m/rad\n    fidelity: [fine]\n", "2000 N*m/rad\n")), 34, 11,
                "name", "an element named 'link' exists already");
    // A name of an element without a list (drive) is taken in every level.
    expectError(readError(replaced(kLevels, "    name: shaft\n", "    name: drive\n")), 39, 11, "name",
                "an element named 'drive' exists already");
}

TEST(ModelFeaturesNames, SetOnASharedNameChangesTheElementOfEveryLevel) {
    const Override stiffer{"elements.link.stiffness", "3 kN*m/rad"};
    const Override damped{"elements.link.damping", "0.25 N*m*s/rad"};  // a key neither link gives
    const ModelSpec fine = read(kLevels, {stiffer, damped});
    const ModelSpec coarse = read(kLevels, {{"fidelity.level", "coarse"}, stiffer, damped});
    for (const ModelSpec* spec : {&fine, &coarse}) {
        SCOPED_TRACE(spec->fidelity);
        const ElementSpec* link = spec->findElement("link");
        ASSERT_NE(link, nullptr);
        EXPECT_NEAR(link->number("stiffness"), 3000.0, kConversionRelTol * 3000);
        EXPECT_DOUBLE_EQ(link->number("damping"), 0.25);
        EXPECT_TRUE(link->has("damping"));
        EXPECT_EQ(link->whereOf("stiffness").file, "<--set elements.link.stiffness>");
    }
    EXPECT_EQ(fine.findElement("link")->names("bodies"), (Names{"motor", "rowA"}));
    EXPECT_EQ(coarse.findElement("link")->names("bodies"), (Names{"motor", "rotor"}));

    // A bad value reaches the dropped level's element too, and is reported.
    expectError(readError(kLevels, {{"elements.link.stiffness", "-1 N*m/rad"}}), "<--set elements.link.stiffness>", 1,
                1, "link.stiffness", "must be >= 0 N*m/rad");
}

// ----------------------------------------------------------------- scenarios

TEST(ModelFeaturesScenarios, UseScenarioSelectsANamedScenario) {
    const ModelSpec run = read(kScenarios);
    EXPECT_EQ(run.scenario.type, "transient");
    EXPECT_EQ(run.scenario.name, "scenario");
    EXPECT_DOUBLE_EQ(run.scenario.number("end_time"), 2.0);
    EXPECT_EQ(run.scenario.text("speed_body"), "shaft");
    EXPECT_EQ(run.scenario.whereOf("end_time").line, 17);

    // `--scenario modes` is the override use_scenario=modes.
    const ModelSpec modes = read(kScenarios, {{"use_scenario", "modes"}});
    EXPECT_EQ(modes.scenario.type, "linearize");
    EXPECT_EQ(modes.scenario.text("operating_point"), "steady");
    EXPECT_EQ(modes.scenario.where.line, 14);
}

TEST(ModelFeaturesScenarios, UseScenarioOverrideSelectsOverTheDefaultScenario) {
    // scenario: (the default) and scenarios: without use_scenario.
    const std::string text =
        replaced(kScenarios, "use_scenario: run\n", "scenario:\n  analysis: transient\n  end_time: 5 s\n");
    const ModelSpec plain = read(text);
    EXPECT_EQ(plain.scenario.type, "transient");
    EXPECT_DOUBLE_EQ(plain.scenario.number("end_time"), 5.0);
    const ModelSpec modes = read(text, {{"use_scenario", "modes"}});
    EXPECT_EQ(modes.scenario.type, "linearize");
    const ModelSpec run = read(text, {{"use_scenario", "run"}});
    EXPECT_DOUBLE_EQ(run.scenario.number("end_time"), 2.0);
}

TEST(ModelFeaturesScenarios, EveryNamedScenarioIsCheckedEvenWhenNotSelected) {
    // `run` is not selected; its negative end_time (17:15) is still refused.
    expectError(readError(replaced(kScenarios, "end_time: 2 s", "end_time: -2 s"), {{"use_scenario", "modes"}}), 17,
                15, "scenarios.run.end_time", "must be > 0 s");
    // An unknown key in `modes` while `run` is selected.
    expectError(readError(replaced(kScenarios, "    analysis: linearize\n",
                                   "    analysis: linearize\n    operating_pint: steady\n")),
                15, 5, "scenarios.modes.operating_pint",
                "unknown key 'operating_pint' (did you mean 'operating_point'?)");
    // An unknown body in `run` while `modes` is selected.
    expectError(readError(replaced(kScenarios, "speed_body: shaft", "speed_body: shaf"), {{"use_scenario", "modes"}}),
                18, 17, "scenarios.run.speed_body", "no body named 'shaf' (did you mean 'shaft'?)");
    // An unknown analysis in `modes`.
    expectError(readError(replaced(kScenarios, "analysis: linearize", "analysis: linearise")), 14, 15,
                "scenarios.modes.analysis", "unknown analysis 'linearise' (did you mean 'linearize'?)");
    // The default scenario: is checked too when a named one is selected
    // (appended: end_time 0 on line 22, at column 13).
    expectError(readError(kScenarios + "scenario:\n  analysis: transient\n  end_time: 0 s\n"), 22, 13,
                "scenario.end_time", "must be > 0 s");
}

TEST(ModelFeaturesScenarios, SetOfTheScenarioActsOnTheNamedScenarioThatRuns) {
    // `--scenario run --end-time 0.5` (use_scenario=run, scenario.end_time):
    // the override reaches the scenario that runs, not the default one,
    // whose values would have been silently without effect.
    const ModelSpec run = read(kScenarios, {{"use_scenario", "run"}, {"scenario.end_time", "0.5 s"}});
    EXPECT_EQ(run.scenario.type, "transient");
    EXPECT_DOUBLE_EQ(run.scenario.number("end_time"), 0.5);
    EXPECT_EQ(run.scenario.whereOf("end_time").file, "<--set scenario.end_time>");
    // use_scenario from the file: the same.
    EXPECT_DOUBLE_EQ(read(kScenarios, {{"scenario.end_time", "0.25 s"}}).scenario.number("end_time"), 0.25);
    // A key the named scenario does not write yet is added to it, and a bad
    // value is refused naming the user's path.
    EXPECT_DOUBLE_EQ(read(kScenarios, {{"scenario.hold_time", "0.1 s"}}).scenario.number("hold_time"), 0.1);
    expectError(readError(kScenarios, {{"scenario.end_time", "-1 s"}}), "<--set scenario.end_time>", 1, 1,
                "scenarios.run.end_time", "must be > 0 s");
    // With the default scenario running, scenario.KEY is that scenario's.
    const std::string text =
        replaced(kScenarios, "use_scenario: run\n", "scenario:\n  analysis: transient\n  end_time: 5 s\n");
    EXPECT_DOUBLE_EQ(read(text, {{"scenario.end_time", "3 s"}}).scenario.number("end_time"), 3.0);
}

TEST(ModelFeaturesScenarios, UnknownUseScenarioSuggestsTheNearestName) {
    expectError(readError(replaced(kScenarios, "use_scenario: run", "use_scenario: rn")), 19, 15, "use_scenario",
                "no scenario named 'rn' under scenarios: (did you mean 'run'?)");
    expectError(readError(kScenarios, {{"use_scenario", "mode"}}), "<--set use_scenario>", 1, 1, "use_scenario",
                "no scenario named 'mode' under scenarios: (did you mean 'modes'?)");
    // A file with only scenario: has no named scenario to use.
    const std::string plain = replaced(kScenarios,
                                       "scenarios:\n  modes:\n    analysis: linearize\n  run:\n",
                                       "scenario:\n");
    const std::string plainText = replaced(plain, "use_scenario: run\n", "");
    expectError(readError(plainText, {{"use_scenario", "run"}}), "<--set use_scenario>", 1, 1, "use_scenario",
                "no scenario named 'run' under scenarios:");
}

TEST(ModelFeaturesScenarios, NeitherScenarioNorUseScenarioListsTheNames) {
    // Located at the document (its first key).
    expectError(readError(replaced(kScenarios, "use_scenario: run\n", "")), 1, 1, "scenario",
                "missing required key 'scenario' (or use_scenario: one of modes, run)");
}

TEST(ModelFeaturesScenarios, DuplicateScenarioNameIsRefused) {
    // `run` renamed `modes`: the second key (15:3) is the duplicate.
    expectError(readError(replaced(kScenarios, "  run:\n", "  modes:\n")), 15, 3, "scenarios.modes",
                "duplicate scenario name");
}

TEST(ModelFeaturesScenarios, FileWithOnlyScenarioWorksAsBefore) {
    std::string text = replaced(kScenarios, "scenarios:\n  modes:\n    analysis: linearize\n  run:\n", "scenario:\n");
    text = replaced(text, "use_scenario: run\n", "");
    text = replaced(text, "    analysis: transient\n    end_time: 2 s\n    speed_body: shaft\n",
                    "  analysis: transient\n  end_time: 2 s\n  speed_body: shaft\n");
    const ModelSpec spec = read(text);
    EXPECT_EQ(spec.scenario.type, "transient");
    EXPECT_DOUBLE_EQ(spec.scenario.number("end_time"), 2.0);
    EXPECT_EQ(spec.scenario.whereOf("end_time").line, 14);
    EXPECT_EQ(spec.scenario.whereOf("end_time").column, 13);
    // And its errors are keyed as before.
    expectError(readError(replaced(text, "end_time: 2 s", "end_time: 2 rmp")), 14, 15, "scenario.end_time",
                "unknown unit 'rmp'");
}

// --------------------------------------------------------------------- lists

TEST(ModelFeaturesLists, QuantityListConvertsEveryItemToSi) {
    const ModelSpec spec = read(kLists);
    const ElementSpec* load = spec.findElement("crushing");
    ASSERT_NE(load, nullptr);
    const std::vector<double>& b = load->numbers("amplitudes");
    ASSERT_EQ(b.size(), 3u);
    EXPECT_DOUBLE_EQ(b[0], 1.0);
    EXPECT_NEAR(b[1], 2000.0, kConversionRelTol * 2000);  // kN*m
    EXPECT_DOUBLE_EQ(b[2], 0.5);
    EXPECT_EQ(load->whereOf("amplitudes").line, 19);
    EXPECT_EQ(load->whereOf("amplitudes").column, 17);
    EXPECT_EQ(load->names("bodies"), (Names{"row1", "row2", "row3"}));
    EXPECT_EQ(load->number("rows"), 3.0);
    // An empty list is allowed (0 to 100 harmonics): only the mean.
    const ModelSpec meanOnly = read(replaced(kLists, "[1 N*m, 2 kN*m, 0.5 N*m]", "[]"));
    EXPECT_TRUE(meanOnly.findElement("crushing")->numbers("amplitudes").empty());
}

TEST(ModelFeaturesLists, QuantityListItemOfTheWrongUnitIsLocatedAtThatItem) {
    // The second item "2 N*m/rad" starts at column 25; its unit at 27.
    expectError(readError(replaced(kLists, "2 kN*m", "2 N*m/rad")), 19, 27, "crushing.amplitudes",
                "incompatible unit 'N*m/rad': expected a quantity in N*m");
    // An unknown unit in the third item (at 33, its unit at 37).
    expectError(readError(replaced(kLists, "0.5 N*m]", "0.5 Nm]")), 19, 37, "crushing.amplitudes",
                "unknown unit");
    // A list where an item should be a single value.
    expectError(readError(replaced(kLists, "2 kN*m", "[2 kN*m]")), 19, 25, "crushing.amplitudes",
                "expected a single value, got a list");
}

TEST(ModelFeaturesLists, NegativeQuantityListItemIsRefusedAtThatItem) {
    expectError(readError(replaced(kLists, "2 kN*m", "-2 kN*m")), 19, 25, "crushing.amplitudes",
                "must be >= 0 N*m, got -2000 N*m");
}

TEST(ModelFeaturesLists, ListLengthsAreEnforced) {
    // 101 harmonics: more than the 100 allowed; located at the list.
    std::string many = "[";
    for (int k = 0; k < 101; ++k) many += (k ? ", " : "") + std::string("1 N*m");
    many += "]";
    expectError(readError(replaced(kLists, "[1 N*m, 2 kN*m, 0.5 N*m]", many)), 19, 17, "crushing.amplitudes",
                "expected 0 to 100 items, got 101");
    // No body at all: at least one.
    expectError(readError(replaced(kLists, "[row1, row2, row3]", "[]")), 16, 13, "crushing.bodies",
                "expected 1 to 1000 items, got 0");
    // A single value where a list is expected.
    expectError(readError(replaced(kLists, "[1 N*m, 2 kN*m, 0.5 N*m]", "1 N*m")), 19, 17, "crushing.amplitudes",
                "expected a list, got a scalar");
    // A scenario's QuantityList: frequency_response's check_frequencies, 0 to 20.
    std::string checks = "[";
    for (int k = 0; k < 21; ++k) checks += (k ? ", " : "") + std::to_string(k + 1) + " rad/s";
    checks += "]";
    const std::string response = replaced(kLists, "  analysis: transient\n  end_time: 1 s\n",
                                          "  analysis: frequency_response\n  load: crushing\n  frequency_min: 1 rad/s\n"
                                          "  frequency_max: 100 rad/s\n  check_frequencies: " + checks + "\n");
    expectError(readError(response), 26, 22, "scenario.check_frequencies", "expected 0 to 20 items, got 21");
}

TEST(ModelFeaturesLists, BodyListChecksEveryName) {
    // rov3: the third item, column 26.
    expectError(readError(replaced(kLists, "[row1, row2, row3]", "[row1, row2, rov3]")), 16, 26, "crushing.bodies",
                "no body named 'rov3' (did you mean 'row3'?)");
    expectError(readError(replaced(kLists, "[row1, row2, row3]", "[rwo1, row2, row3]")), 16, 14, "crushing.bodies",
                "no body named 'rwo1'");
    expectError(readError(replaced(kLists, "[row1, row2, row3]", "[row1, ground, row3]")), 16, 20, "crushing.bodies",
                "no body named 'ground'");
}

TEST(ModelFeaturesLists, PeriodicLoadCrossChecksRowsAndBodies) {
    expectError(readError(replaced(kLists, "rows: 3", "rows: 2.5")), 17, 11, "crushing.rows", "must be a whole number");
    // Two bodies for three rows; located at the list.
    expectError(readError(replaced(kLists, "[row1, row2, row3]", "[row1, row2]")), 16, 13, "crushing.bodies",
                "give one body per row (3) or one body for all rows, got 2");
    // One body carries all rows.
    const ModelSpec one = read(replaced(kLists, "[row1, row2, row3]", "[row2]"));
    EXPECT_EQ(one.findElement("crushing")->names("bodies"), (Names{"row2"}));
    // The cross-check sees --set values too, located at the command line.
    expectError(readError(kLists, {{"elements.crushing.rows", "4"}}), kFile, 16, 13, "crushing.bodies",
                "give one body per row (4) or one body for all rows, got 3");
    expectError(readError(kLists, {{"elements.crushing.rows", "3.5"}}), "<--set elements.crushing.rows>", 1, 1,
                "crushing.rows", "must be a whole number");
}

// ------------------------------------------------------------ --set, aliases

TEST(ModelFeaturesAliases, AliasedValuesReadAsTheirAnchor) {
    const ModelSpec spec = read(kAliases);
    for (const auto& b : spec.bodies) {
        EXPECT_DOUBLE_EQ(b.inertia, 2.0) << b.name;
        EXPECT_EQ(b.joint.parent, "ground") << b.name;
    }
    EXPECT_DOUBLE_EQ(spec.findElement("c1")->number("stiffness"), 1000.0);
    EXPECT_DOUBLE_EQ(spec.findElement("c2")->number("stiffness"), 1000.0);
    EXPECT_DOUBLE_EQ(spec.scenario.number("end_time"), 1.0);
}

TEST(ModelFeaturesAliases, SetOnAnAliasedScalarChangesOnlyWhereItPoints) {
    // At the anchor's use...
    const ModelSpec first = read(kAliases, {{"elements.c1.stiffness", "2000 N*m/rad"}});
    EXPECT_DOUBLE_EQ(first.findElement("c1")->number("stiffness"), 2000.0);
    EXPECT_DOUBLE_EQ(first.findElement("c2")->number("stiffness"), 1000.0);
    // ...and at the alias.
    const ModelSpec second = read(kAliases, {{"elements.c2.stiffness", "3000 N*m/rad"}});
    EXPECT_DOUBLE_EQ(second.findElement("c1")->number("stiffness"), 1000.0);
    EXPECT_DOUBLE_EQ(second.findElement("c2")->number("stiffness"), 3000.0);
    // A body's aliased inertia, in the middle of three uses.
    const ModelSpec middle = read(kAliases, {{"bodies.b.inertia", "3 kg*m^2"}});
    EXPECT_DOUBLE_EQ(middle.findBody("a")->inertia, 2.0);
    EXPECT_DOUBLE_EQ(middle.findBody("b")->inertia, 3.0);
    EXPECT_DOUBLE_EQ(middle.findBody("c")->inertia, 2.0);
    // A bad value is reported at the command line, once.
    expectError(readError(kAliases, {{"bodies.c.inertia", "0 kg*m^2"}}), "<--set bodies.c.inertia>", 1, 1,
                "c.inertia", "must be > 0");
}

// An anchored block used through aliases is one node in yaml-cpp, and it
// cannot be copied without losing the source locations every diagnostic
// needs. So --set refuses to reach into one (changing it would change every
// use), located at the command line and naming the reason.
TEST(ModelFeaturesAliases, SetInsideAnAliasedMappingIsRefusedAtTheCommandLine) {
    try {
        read(kAliases, {{"bodies.b.joint.parent", "a"}});
        FAIL() << "an override into an aliased mapping was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, "<--set bodies.b.joint.parent>");
        EXPECT_EQ(e.key(), "bodies.b.joint.parent");
        EXPECT_NE(std::string(e.what()).find("aliases"), std::string::npos) << e.what();
    }
    // Without the override the file reads as written.
    const ModelSpec spec = read(kAliases, {});
    EXPECT_EQ(spec.findBody("b")->joint.parent, "ground");
}

TEST(ModelFeaturesAliases, SetInsideAnAliasedScenarioIsRefusedAtTheCommandLine) {
    try {
        read(kAliases, {{"scenarios.two.end_time", "5 s"}});
        FAIL() << "an override into an aliased scenario was accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.where().file, "<--set scenarios.two.end_time>");
        EXPECT_NE(std::string(e.what()).find("aliases"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace milldyn
