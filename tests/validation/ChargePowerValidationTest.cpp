// The charge-power and frozen-charge validation cases
// (validation/cases/ChargePowerCases.cpp) as tests: every comparison with
// its oracle passes, and every case is there with all its rows.

#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>

#include <map>

namespace milldyn {
namespace {

TEST(ChargePowerValidation, EveryComparisonPassesAndEveryCaseIsThere) {
    const std::vector<ValidationRow> rows = chargePowerCases("");
    std::map<std::string, int> perCase;
    for (const auto& r : rows) {
        ++perCase[r.caseName];
        EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << (r.multibody ? *r.multibody : 0)
                                    << " vs oracle " << r.oracle << ", rel " << r.relError << " > " << r.tolerance;
    }
    // 5 fills x 11 speeds and the peak's speed; the frozen lift's 5 rows
    // (the peak torque at the located release among them).
    EXPECT_EQ(perCase["charge_power_bond"], 5 * 11 + 1);
    EXPECT_EQ(perCase["charge_power_morrell"], 5 * 11 + 1);
    EXPECT_EQ(perCase["charge_frozen_lift"], 5);
}

}  // namespace
}  // namespace milldyn
