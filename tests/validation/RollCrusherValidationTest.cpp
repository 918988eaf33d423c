// The crusher validation cases (validation/cases/RollCrusherCases.cpp) as
// tests: every multibody-vs-oracle comparison passes; the paper's
// approximate roots are flagged where they fail, never silently passed.

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <cmath>

#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allCrusherRows() {
    static const std::vector<ValidationRow> rows = rollCrusherCases("");
    return rows;
}

TEST(RollCrusherValidation, EveryMultibodyComparisonPasses) {
    int compared = 0;
    for (const auto& r : allCrusherRows())
        if (r.multibody) {
            ++compared;
            EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << *r.multibody << " vs "
                                        << r.oracle << " rel " << r.relError;
        }
    EXPECT_GT(compared, 30);
}

TEST(RollCrusherValidation, AllSixCasesRan) {
    std::set<std::string> cases;
    for (const auto& r : allCrusherRows()) cases.insert(r.caseName);
    EXPECT_EQ(cases, (std::set<std::string>{"roll_crusher_2mass_roots", "roll_crusher_2mass_response",
                                            "roll_crusher_10mass_modes", "roll_crusher_stagger",
                                            "roll_crusher_resonance_map", "roll_crusher_approximation_sweep"}));
}

TEST(RollCrusherValidation, MisprintedResonancesAreCheckedAndFinite) {
    int checked = 0;
    for (const auto& r : allCrusherRows())
        if (r.quantity.find("misprinted Delta") != std::string::npos) {
            ++checked;
            EXPECT_EQ(r.status, "pass") << r.quantity;
            EXPECT_TRUE(std::isfinite(r.oracle));
        }
    EXPECT_GT(checked, 0);
}

TEST(RollCrusherValidation, FlaggedRowsAreOnlyThePapersApproximations) {
    for (const auto& r : allCrusherRows())
        if (r.status == "flagged") {
            EXPECT_NE(r.quantity.find("approximate"), std::string::npos) << r.quantity;
            EXPECT_FALSE(r.multibody.has_value());
        }
}


TEST(RollCrusherValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allCrusherRows(), "Roll crusher (seed 004)", {67, 0, 14, 0});
}

}  // namespace
}  // namespace milldyn
