// The seed-000 validation cases (validation/cases/PlanetaryGearCases.cpp) as
// tests: every multibody-vs-oracle comparison passes, the misprints and the
// paper's first-order friction are flagged (never silently passed), and
// every case ran for both drum sizes.

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allRows() {
    static const std::vector<ValidationRow> rows = planetaryGearCases("");
    return rows;
}

TEST(PlanetaryGearValidation, EveryMultibodyComparisonPasses) {
    int compared = 0;
    for (const auto& r : allRows())
        if (r.policy == RowPolicy::Judged) {
            ++compared;
            EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN)
                                        << " vs " << r.oracle << " rel " << r.relError;
        }
    EXPECT_GT(compared, 80);
}

TEST(PlanetaryGearValidation, MisprintAndFirstOrderFrictionAreFlagged) {
    // The J_pr misprint is flagged; the first-order friction is an
    // observation inside o1·(1 ± f).
    std::set<std::string> flagged, info;
    for (const auto& r : allRows()) {
        if (r.status == "flagged") flagged.insert(r.caseName + ": " + r.quantity);
        if (r.status == "info") info.insert(r.caseName + ": " + r.quantity);
    }
    EXPECT_EQ(flagged.size(), 2u);
    EXPECT_EQ(info.size(), 4u);
    for (const std::string size : {"100x200", "500x1000"}) {
        EXPECT_EQ(flagged.count("planetary_gear_" + size + "_start_up: J_pr as printed in (1), 2(J1 + ...)"), 1u);
        EXPECT_EQ(info.count("planetary_gear_" + size + "_start_friction: friction torque at B2, f = 0.01"), 1u);
        EXPECT_EQ(info.count("planetary_gear_" + size + "_steady_held_lag90: friction torque at B2, f = 0.01"), 1u);
    }
}

TEST(PlanetaryGearValidation, EveryCaseRanForBothSizes) {
    std::set<std::string> cases;
    for (const auto& r : allRows()) cases.insert(r.caseName);
    for (const std::string size : {"100x200", "500x1000"})
        for (const std::string c : {"start_up", "start_friction", "steady_rigid", "steady_held_lag90",
                                    "steady_held_lag45", "fig10_initial_torque_vs_tp", "fig10_start_history",
                                    "dynamic_lag"})
            EXPECT_EQ(cases.count("planetary_gear_" + size + "_" + c), 1u) << size << " " << c;
}


TEST(PlanetaryGearValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allRows(), "Planetary mill with external rolling (seed 000)", {100, 0, 2, 4});
}

}  // namespace
}  // namespace milldyn
