// The burr-mill validation cases (validation/cases/BurrMillCases.cpp) as
// tests: every multibody-vs-oracle comparison passes, and the paper's
// inconsistent Table 1 row is flagged, not passed and not skipped.

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allBurrMillRows() {
    static const std::vector<ValidationRow> rows = burrMillCases("");
    return rows;
}

TEST(BurrMillValidation, EveryComparisonPassesOrIsAFlaggedMisprint) {
    const auto& rows = allBurrMillRows();
    ASSERT_FALSE(rows.empty());
    for (const auto& r : rows)
        EXPECT_NE(r.status, "fail") << r.caseName << ": " << r.quantity << " multibody/paper vs oracle " << r.oracle
                                    << ", rel " << r.relError << " > " << r.tolerance;
}

TEST(BurrMillValidation, CoastdownSpeedsMatchEquations10And11) {
    int compared = 0;
    for (const auto& r : allBurrMillRows())
        if (r.caseName.rfind("burr_mill_coastdown_", 0) == 0) {
            ++compared;
            ASSERT_TRUE(r.multibody.has_value());
            EXPECT_LE(r.relError, 1e-6) << r.quantity;
        }
    // Two motors, a steady speed and five instants of two speeds each.
    EXPECT_EQ(compared, 2 * (1 + 10));
}

TEST(BurrMillValidation, AllSixTableRowsAreCheckedAgainstTheMultibodyIdentification) {
    std::set<std::string> identified;
    for (const auto& r : allBurrMillRows())
        if (r.quantity.rfind("Mc identified (mean line)", 0) == 0) {
            identified.insert(r.caseName);
            EXPECT_EQ(r.status, "pass") << r.caseName;
        }
    EXPECT_EQ(identified.size(), 6u);
}

TEST(BurrMillValidation, InconsistentTable1RowIsFlaggedAndItsCorrectedReadingPasses) {
    int flagged = 0, corrected = 0;
    for (const auto& r : allBurrMillRows()) {
        if (r.status == "flagged") {
            ++flagged;
            EXPECT_EQ(r.caseName, "burr_mill_table1_5p5kW_feed50_70");
            EXPECT_FALSE(r.note.empty());
        }
        if (r.quantity.find("at t_v = 1.00 s") != std::string::npos) {
            ++corrected;
            EXPECT_EQ(r.status, "pass") << r.quantity;
        }
    }
    EXPECT_EQ(flagged, 4);    // Mc, omega, N_c, M_zh of that row
    EXPECT_EQ(corrected, 4);  // the same four at t_v = 1.00 s
}

TEST(BurrMillValidation, FilterSelectsCasesByName) {
    const auto rows = burrMillCases("burr_mill_coastdown_3p2kW");
    ASSERT_FALSE(rows.empty());
    for (const auto& r : rows) EXPECT_EQ(r.caseName, "burr_mill_coastdown_3p2kW");
    EXPECT_TRUE(burrMillCases("no_such_case").empty());
}


TEST(BurrMillValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allBurrMillRows(), "Burr mill (seed 003)", {72, 0, 4, 0});
}

}  // namespace
}  // namespace milldyn
