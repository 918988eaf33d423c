// The belt-drive planetary mill's validation cases
// (validation/cases/PlanetaryBeltCases.cpp) as tests: every multibody-vs-oracle
// comparison passes at 1e-6; the model against the printed equations is
// flagged (and fails if they agree), the rows that report (the elastic belt,
// the start-up) are observations inside their physical bands; all finite.

#include "validation/cases/ValidationCases.h"
#include "SectionCounts.h"

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
    // Every row by its policy: judged rows pass, the printed equations'
    // rows are flagged, the observations lie in their bands.
    int judged = 0, printed = 0, observed = 0;
    for (const auto& r : allBeltRows()) {
        const std::string what = r.caseName + ": " + r.quantity + " " + std::to_string(r.multibody.value_or(NAN)) +
                                 " vs " + std::to_string(r.oracle) + " rel " + std::to_string(r.relError);
        switch (r.policy) {
        case RowPolicy::Judged:
            ++judged;
            EXPECT_EQ(r.status, "pass") << what;
            break;
        case RowPolicy::Misprint:
            ++printed;
            EXPECT_EQ(r.status, "flagged") << what;
            break;
        case RowPolicy::Observation:
            ++observed;
            EXPECT_EQ(r.status, "info") << what << " band " << r.note;
            break;
        }
    }
    // turn, paper form, c -> 1, Fig. 3, sensitivity, maps, elastic, start-up
    EXPECT_EQ(judged, 67);
    // (15)-(18) as printed: 2 turns, the Φ_r reading, 4 of Fig. 3, 20 of
    // the sensitivity, 24 map points
    EXPECT_EQ(printed, 2 + 1 + 4 + 20 + 24);
    // elastic belt 3, start-up 7, flat belt 3, the settled lag
    EXPECT_EQ(observed, 3 + 7 + 3 + 1);
}

TEST(PlanetaryBeltValidation, PeakBeltSlipIsJudgedAgainstZero) {
    // "the belt never slipped" must fail if a regression makes it slip.
    for (const auto& r : allBeltRows())
        if (r.quantity == "peak belt slip speed") {
            ASSERT_TRUE(r.band.has_value());
            EXPECT_EQ(r.band->low, 0.0);
            EXPECT_EQ(r.band->high, 0.0);
            ValidationRow slipped = r;
            slipped.multibody = 1e-6;
            applyStatusPolicy(slipped);
            EXPECT_EQ(slipped.status, "fail");
        }
}

TEST(PlanetaryBeltValidation, SectionCountsArePinnedAndInTheDocs) {
    test::expectSectionCounts(allBeltRows(), "Planetary mill with belt drive (seed 002)", {67, 0, 51, 14});
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
