// The belt-drive planetary mill's validation cases
// (validation/cases/PlanetaryBeltCases.cpp) as tests: every multibody-vs-oracle
// comparison passes at 1e-6; the rows that only report (the paper's printed
// values, maps, start-up) are flagged, never silently passed, and are finite.

#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace milldyn {
namespace {

const std::vector<ValidationRow>& allBeltRows() {
    static const std::vector<ValidationRow> rows = planetaryBeltCases("");
    return rows;
}

TEST(PlanetaryBeltValidation, EveryJudgedComparisonPasses) {
    int judged = 0;
    for (const auto& r : allBeltRows())
        if (r.status != "flagged") {
            ++judged;
            EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN)
                                        << " vs " << r.oracle << " rel " << r.relError;
        }
    EXPECT_GT(judged, 60);
}

TEST(PlanetaryBeltValidation, EveryCaseRan) {
    std::set<std::string> cases;
    for (const auto& r : allBeltRows()) cases.insert(r.caseName);
    EXPECT_EQ(cases, (std::set<std::string>{
                         "planetary_belt_fig3_turn_c_r0_over_rA", "planetary_belt_fig3_turn_c_rA_over_r0",
                         "planetary_belt_paper_form_alpha0", "planetary_belt_paper_form_alpha50_g0",
                         "planetary_belt_paper_form_alpha90_g0_phi_r", "planetary_belt_paper_form_phi_r_reading",
                         "planetary_belt_c_to_1", "planetary_belt_fig3_printed", "planetary_belt_map_omega",
                         "planetary_belt_map_gamma", "planetary_belt_map_k", "planetary_belt_map_b",
                         "planetary_belt_map_c", "planetary_belt_elastic_kinetostatic", "planetary_belt_start_up"}));
}

TEST(PlanetaryBeltValidation, EveryValueIsFinite) {
    for (const auto& r : allBeltRows()) {
        ASSERT_TRUE(r.multibody.has_value()) << r.quantity;
        EXPECT_TRUE(std::isfinite(*r.multibody)) << r.caseName << ": " << r.quantity;
        EXPECT_TRUE(std::isfinite(r.oracle)) << r.caseName << ": " << r.quantity;
    }
}

TEST(PlanetaryBeltValidation, DrumThatDoesNotTurnIsReportedOnlyAtCEqualOne) {
    int flags = 0;
    for (const auto& r : allBeltRows())
        if (r.quantity.find("drum_turns") != std::string::npos) {
            ++flags;
            const bool atOne = r.quantity.rfind("c = 1:", 0) == 0;
            EXPECT_EQ(*r.multibody, atOne ? 0.0 : 1.0) << r.quantity;
        }
    EXPECT_EQ(flags, 4);
}

}  // namespace
}  // namespace milldyn
