// The bead mill validation cases (validation/cases/BeadMillCases.cpp) as
// tests: every multibody-vs-oracle comparison passes, the text's diameter
// ranges hold under the resolved reading of Table 1, and the flagged rows
// are exactly the literal reading and the paper's unreproducible deflections.

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allRows() {
    static const std::vector<ValidationRow> rows = beadMillCases("");
    return rows;
}

TEST(BeadMillValidation, EveryMultibodyComparisonPasses) {
    int compared = 0;
    for (const auto& r : allRows())
        if (r.multibody) {
            ++compared;
            EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << *r.multibody << " vs "
                                        << r.oracle << " rel " << r.relError;
        }
    EXPECT_EQ(compared, 4 + 4 + 6 + 4 + 12 + 4);  // static, critical speed, drag, convergence, span, whirl
}

TEST(BeadMillValidation, AllCasesRan) {
    std::set<std::string> cases;
    for (const auto& r : allRows()) cases.insert(r.caseName);
    EXPECT_EQ(cases, (std::set<std::string>{
                         "bead_mill_static_5disc_0p1m", "bead_mill_static_8disc_0p3m",
                         "bead_mill_critical_speed_5disc_0p1m", "bead_mill_critical_speed_8disc_0p3m",
                         "bead_mill_drag_power_5disc_0p1m", "bead_mill_drag_power_8disc_0p3m",
                         "bead_mill_unbalance_whirl_5disc_0p1m", "bead_mill_unbalance_whirl_8disc_0p3m",
                         "bead_mill_convergence", "bead_mill_span_sweep", "bead_mill_eq2_fit",
                         "bead_mill_paper_deflection"}));
}

TEST(BeadMillValidation, FlaggedRowsAreTheLiteralReadingAndThePapersDeflections) {
    int resolved = 0, flagged = 0;
    for (const auto& r : allRows()) {
        if (r.quantity.find("resolved") != std::string::npos) {
            ++resolved;
            EXPECT_EQ(r.status, "pass") << r.quantity;
        }
        if (r.status == "flagged") {
            ++flagged;
            EXPECT_FALSE(r.multibody.has_value());
            EXPECT_TRUE(r.quantity.find("literal") != std::string::npos ||
                        r.caseName == "bead_mill_paper_deflection")
                << r.quantity;
        }
    }
    EXPECT_EQ(resolved, 4);
    EXPECT_EQ(flagged, 4 + 2);
}


TEST(BeadMillValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allRows(), "Bead mill rotor (seed 001)", {38, 0, 6, 0});
}

}  // namespace
}  // namespace milldyn
