// The tumbling-mill validation cases (validation/cases/TumblingMillCases.cpp)
// as tests: every comparison of the girth-gear drive with its oracle
// passes, and every case is there (a case that silently stopped producing
// rows would otherwise pass).

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <map>

namespace milldyn {
namespace {

TEST(TumblingMillValidation, EveryComparisonPassesAndEveryCaseIsThere) {
    const std::vector<ValidationRow> rows = tumblingMillCases("");
    std::map<std::string, int> perCase;
    for (const auto& r : rows) {
        ++perCase[r.caseName];
        EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << (r.multibody ? *r.multibody : 0)
                                    << " vs oracle " << r.oracle << ", rel " << r.relError << " > " << r.tolerance;
    }
    // Mesh: 3 forces; trunnions and pinion: 2 bearings x 2 components each;
    // helical also both thrusts. 4 elastic modes. 2 tooth counts. 1 energy balance.
    EXPECT_EQ(perCase["tumbling_mill_girth_gear_statics_spur"], 3 + 8);
    EXPECT_EQ(perCase["tumbling_mill_girth_gear_statics_helical"], 3 + 8 + 2);
    EXPECT_EQ(perCase["tumbling_mill_chain_frequencies"], 4);
    EXPECT_EQ(perCase["tumbling_mill_girth_gear_teeth"], 2);
    EXPECT_EQ(perCase["tumbling_mill_start_energy"], 1);
    test::expectSectionCounts(rows, "Tumbling ball mill with girth-gear drive (issue 19)", {31, 0, 0, 0});
}


}  // namespace
}  // namespace milldyn
