// Issue 31 item 3. The registry of analyses
// (driver/analyses/AnalysisRegistry.h) is the one list the reader, the
// dispatch, `milldyn info`, the scene builder and --schematic read: each
// of them gives, for every analysis, what it gave when it named the
// analysis (the texts and instants below are those of the code before the
// move).

#include "driver/Api.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "driver/outputs/Schematic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn {
namespace {

const std::string kModels = std::string(MILLDYN_SOURCE_DIR) + "/models/";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The burr mill (an InductionMotor on a Kloss curve, a transient) with its
/// scenario replaced by `kind`'s defaults (a transient keeps the file's).
ModelSpec burrMillWith(const std::string& kind) {
    ModelSpec spec = readModel(kModels + "burr_mill_3p2kW_idle.yaml", {});
    if (kind != "transient") spec.scenario = defaultScenario(kind);
    return spec;
}

TEST(AnalysisRegistry, TheReaderAndTheRegistryListTheSameKinds) {
    const std::vector<std::string> names = analysisKinds();
    const std::vector<const AnalysisKind*> kinds = analysisKindList();
    ASSERT_EQ(names.size(), kinds.size());
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(kinds[i]->schema.type, names[i]);
        EXPECT_TRUE(kinds[i]->run) << names[i];
        EXPECT_EQ(findAnalysisKind(names[i]), kinds[i]);
        EXPECT_EQ(findAnalysisSchema(names[i]), &kinds[i]->schema);
    }
    EXPECT_EQ(defaultModelReader().analysisKinds, names);
    // The seven analyses of main before the move, all still there.
    for (const char* kind : {"coastdown_identify", "frequency_response", "kinetostatic", "linearize", "resonance_map",
                             "static_deflection", "transient"})
        EXPECT_NE(findAnalysisKind(kind), nullptr) << kind;
    EXPECT_EQ(findAnalysisKind("transients"), nullptr);
    EXPECT_EQ(findAnalysisSchema("transients"), nullptr);
}

TEST(AnalysisRegistry, InfoSaysHowEachAnalysisIntegratesInTime) {
    EXPECT_EQ(describeModel(burrMillWith("coastdown_identify")).timeIntegration,
              "integrated (run-outs after a switch-off)");
    EXPECT_EQ(describeModel(burrMillWith("frequency_response")).timeIntegration,
              "only the optional time-domain check of the linear response");
    for (const char* kind : {"linearize", "static_deflection", "kinetostatic", "resonance_map"})
        EXPECT_EQ(describeModel(burrMillWith(kind)).timeIntegration, std::string("none (") + kind + " analysis)");
    // The transient asks its built scene: the burr mill has free degrees of freedom.
    EXPECT_TRUE(contains(describeModel(burrMillWith("transient")).timeIntegration, "integrated"))
        << describeModel(burrMillWith("transient")).timeIntegration;
}

TEST(AnalysisRegistry, OnlyAnalysesThatReportAnEnergyBalanceGetTheMeter) {
    for (const AnalysisKind* kind : analysisKindList()) {
        const ModelInfo info = describeModel(burrMillWith(kind->schema.type));
        bool built = false, omitted = false;
        for (const auto& n : info.built) built = built || contains(n.what, "energy meter");
        for (const auto& n : info.notBuilt) omitted = omitted || contains(n.what, "energy meter");
        const bool balance = kind->schema.type == "transient" || kind->schema.type == "coastdown_identify";
        EXPECT_EQ(built, balance) << kind->schema.type;
        EXPECT_EQ(omitted, !balance) << kind->schema.type;
        EXPECT_EQ(kind->reportsEnergyBalance, balance) << kind->schema.type;
    }
}

TEST(AnalysisRegistry, ASchematicSpansTransientsInTimeAndKinetostaticsInAngle) {
    bool angles = true;
    // The burr mill's transient runs to 7 s: t = 0, 1/4, 1/2 and all of it.
    const ModelSpec burr = burrMillWith("transient");
    const double end = burr.scenario.number("end_time");
    EXPECT_EQ(parseSchematicInstants(burr, "", angles), (std::vector<double>{0, end / 4, end / 2, end}));
    EXPECT_FALSE(angles);
    EXPECT_EQ(parseSchematicInstants(burr, "1 s,2", angles), (std::vector<double>{1, 2}));
    EXPECT_THROW(parseSchematicInstants(burr, "1000 s", angles), std::invalid_argument);

    // A kinetostatic turn: the first angle and three more a quarter apart.
    const ModelSpec turn = readModel(kModels + "planetary_gear_100x200.yaml",
                                     {{"scenario.angle_points", "5"}, {"scenario.angle_to", "360 deg"}});
    const std::vector<double> at = parseSchematicInstants(turn, "", angles);
    EXPECT_TRUE(angles);
    ASSERT_EQ(at.size(), 4u);
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(at[k], k * M_PI / 2);
    // One angle: that one.
    const ModelSpec start = readModel(kModels + "planetary_gear_100x200.yaml", {});
    EXPECT_EQ(parseSchematicInstants(start, "", angles), (std::vector<double>{0.0}));

    // Any other analysis draws none, and the error names those that do.
    try {
        parseSchematicInstants(burrMillWith("linearize"), "", angles);
        FAIL() << "linearize has no instants to draw";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--schematic draws kinetostatic and transient scenarios; this one is 'linearize'");
    }
}

}  // namespace
}  // namespace milldyn
