// The whole-machine start cases (validation/cases/MachineStartCases.cpp) as
// tests: the seed-000 planetary mill started by its motor through a slipping
// V-belt, and the burr mill started loaded. Every judged comparison passes;
// the rows that compare starts with different assumptions are observations
// inside their physical bands (info) or known disagreements (flagged),
// never silently passed.

#include "validation/cases/ValidationCases.h"
#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allRows() {
    static const std::vector<ValidationRow> rows = machineStartCases("");
    return rows;
}

TEST(MachineStartValidation, EveryJudgedComparisonPasses) {
    int judged = 0;
    for (const auto& r : allRows())
        if (r.policy == RowPolicy::Judged) {
            ++judged;
            EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN)
                                        << " vs " << r.oracle << " rel " << r.relError;
        }
    EXPECT_EQ(judged, 14);
}

TEST(MachineStartValidation, EveryCaseRanAndTheDifferentStartsAreFlagged) {
    std::set<std::string> cases;
    int flagged = 0;
    for (const auto& r : allRows()) {
        cases.insert(r.caseName);
        if (r.policy != RowPolicy::Judged) {
            EXPECT_EQ(r.status, r.policy == RowPolicy::Misprint ? "flagged" : "info")
                << r.quantity << ": " << r.note;
            ++flagged;
            // A flagged row says where the assumptions differ.
            EXPECT_TRUE(r.note.find("docs/validation.md") != std::string::npos) << r.quantity;
        }
        ASSERT_TRUE(r.multibody.has_value()) << r.quantity;
        EXPECT_TRUE(std::isfinite(*r.multibody) && std::isfinite(r.oracle)) << r.caseName << ": " << r.quantity;
    }
    EXPECT_EQ(cases, (std::set<std::string>{"planetary_motor_start_belt_capacity", "planetary_motor_start_steady",
                                            "planetary_motor_start_time", "planetary_motor_start_prescribed",
                                            "planetary_motor_start_energy_balance", "planetary_motor_start_bearings",
                                            "planetary_motor_start_bearings_prescribed", "burr_mill_loaded_start_time"}));
    EXPECT_EQ(flagged, 9);
}

// Item 7 of issue 31: the motor-started mill's start time with gravity
// (1.1 % behind the turn-averaged oracle) has an upper bound: the oracle's
// load plus the largest moment the charges' weight can put on the carrier.
TEST(MachineStartValidation, TheStartTimeWithGravityHasABand) {
    for (const auto& r : allRows())
        if (r.caseName == "planetary_motor_start_time" && r.quantity.find("with gravity") != std::string::npos) {
            ASSERT_TRUE(r.band.has_value()) << r.quantity;
            EXPECT_TRUE(std::isfinite(r.band->high)) << r.quantity;
            EXPECT_GT(r.band->high, r.oracle) << r.quantity;
            EXPECT_LT(r.band->low, r.oracle) << r.quantity;
        }
}

TEST(MachineStartValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allRows(), "Whole machines started by their motor (issue 15)", {14, 0, 3, 6});
}

}  // namespace
}  // namespace milldyn
