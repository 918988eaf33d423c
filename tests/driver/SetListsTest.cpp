// issue 20 item 3: --set on lists and vectors (with units), on one item of a
// list, switching the analysis, and on one fidelity level's copy alone.
#include "driver/analyses/Analysis.h"
#include "tests/driver/ReaderTestHelpers.h"

#include <gtest/gtest.h>

#include <string>

namespace milldyn {
namespace {

const std::string kCrusher = std::string(MILLDYN_SOURCE_DIR) + "/models/roll_crusher.yaml";
const std::string kBurr = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";

ModelSpec readFile(const std::string& file, const std::vector<Override>& o) {
    return readModelFile(file, defaultModelReader(), o);
}

SpecError errorOf(const std::string& file, const std::vector<Override>& o) {
    try {
        readFile(file, o);
    } catch (const SpecError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted";
    return SpecError({}, "", "");
}

TEST(SetLists, GravityAsAListWithUnitsAndOneItemByIndex) {
    const ModelSpec m = readFile(kBurr, {{"gravity", "[0, -981 cm/s^2, 0 m/s^2]"}});
    EXPECT_EQ(m.gravity[0], 0.0);
    EXPECT_NEAR(m.gravity[1], -9.81, 1e-15);
    const ModelSpec one = readFile(kBurr, {{"gravity", "[0, 0, 0]"}, {"gravity.2", "-9.81 m/s^2"}});
    EXPECT_EQ(one.gravity[2], -9.81);
    // Units are required inside lists too, located at the --set.
    const SpecError e = errorOf(kBurr, {{"gravity", "[0, -9.81, 0]"}});
    EXPECT_EQ(e.where().file, "<--set gravity>");
    EXPECT_TRUE(test::contains(e.what(), "did you mean -9.81 m/s^2?")) << e.what();
    EXPECT_EQ(errorOf(kBurr, {{"gravity", "[0, 0"}}).where().file, "<--set gravity>");
}

TEST(SetLists, JointLocationAndQuantityListsOfElements) {
    const ModelSpec m = readFile(kBurr, {{"bodies.millstone.joint.location", "[10 mm, 0 m, 0]"}});
    EXPECT_NEAR(m.findBody("millstone")->joint.location[0], 0.01, 1e-17);
    const ModelSpec c = readFile(kCrusher, {{"elements.crushing.amplitudes", "[1 kN*m, 500 N*m]"}});
    EXPECT_EQ(c.findElement("crushing")->numbers("amplitudes"), (std::vector<double>{1000, 500}));
    // A list key given a single value says how to set it.
    EXPECT_TRUE(test::contains(errorOf(kBurr, {{"bodies.millstone.joint.location", "[1 m]"}}).what(), "[x, y, z]"));
}

TEST(SetLists, SwitchingTheAnalysisDropsKeysItDoesNotTakeWithANote) {
    const ModelSpec m = readFile(kCrusher, {{"scenario.analysis", "linearize"}});
    EXPECT_EQ(m.scenario.type, "linearize");
    ASSERT_EQ(m.readNotes.size(), 1u);
    EXPECT_TRUE(test::contains(m.readNotes[0], "scenario.analysis set to linearize: dropped initial_state, end_time"))
        << m.readNotes[0];
    // Written in the file, an unknown key stays an error.
    const std::string text = "format_version: 1\nname: x\nbodies:\n  - {name: r, inertia: 1 kg*m^2, joint: {type: pin}}\n"
                             "scenario: {analysis: linearize, end_time: 1 s}\n";
    EXPECT_THROW(readModelText(text, "x.yaml", defaultModelReader(), {}), SpecError);
}

TEST(SetLists, OneFidelityLevelsCopyAlone) {
    const std::vector<Override> o = {{"elements.crushing@2-mass.mean_torque", "8000 N*m"}};
    const ModelSpec two = readFile(kCrusher, [&] { auto v = o; v.push_back({"fidelity.level", "2-mass"}); return v; }());
    const ModelSpec ten = readFile(kCrusher, o);
    EXPECT_EQ(two.findElement("crushing")->number("mean_torque"), 8000);
    EXPECT_EQ(ten.findElement("crushing")->number("mean_torque"), 7440);
    // Without @level both copies change.
    const ModelSpec both = readFile(kCrusher, {{"elements.crushing.mean_torque", "8000 N*m"}});
    EXPECT_EQ(both.findElement("crushing")->number("mean_torque"), 8000);
    const SpecError e = errorOf(kCrusher, {{"elements.crushing@3-mass.mean_torque", "1 N*m"}});
    EXPECT_TRUE(test::contains(e.what(), "no list item named 'crushing' of fidelity level '3-mass'")) << e.what();
}

}  // namespace
}  // namespace milldyn
