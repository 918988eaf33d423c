// Issue 20 item 13: where a validation row's oracle is 0, `milldyn validate`
// prints (and `--json` writes) the absolute error, not a relative one of
// 1e+299; elsewhere the relative error as before.
#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace milldyn {
namespace {

TEST(ValidationTable, AbsoluteErrorWhereTheOracleIsZero) {
    const ValidationRow zero = compareRow("gear_pair_x", "net torque", "N*m", 2.9e-17, 0.0, 1e-9);
    const ValidationRow plain = compareRow("gear_pair_y", "torque", "N*m", 101.0, 100.0, 0.02);
    const std::string table = formatValidationTable({zero, plain});
    EXPECT_NE(table.find("abs 2.9e-17 N*m"), std::string::npos) << table;
    EXPECT_EQ(table.find("e+2"), std::string::npos) << table;  // no 1e+283-like relative error
    EXPECT_NE(table.find("rel 0.01"), std::string::npos) << table;

    const nlohmann::json j = nlohmann::json::parse(formatValidationJson({zero, plain}));
    ASSERT_TRUE(j[0].contains("abs_error")) << j.dump();
    EXPECT_DOUBLE_EQ(j[0]["abs_error"].get<double>(), 2.9e-17);
    EXPECT_FALSE(j[1].contains("abs_error")) << j.dump();
}

// Issue 26 item 5: the JSON kept rel_error 1.5e+299 beside abs_error; a
// relative error to 0 means nothing: null.
TEST(ValidationTable, JsonRelativeErrorIsNullWhereTheOracleIsZero) {
    const ValidationRow zero = compareRow("gear_pair_x", "net torque", "N*m", 2.9e-17, 0.0, 1e-9);
    const ValidationRow plain = compareRow("gear_pair_y", "torque", "N*m", 101.0, 100.0, 0.02);
    const nlohmann::json j = nlohmann::json::parse(formatValidationJson({zero, plain}));
    ASSERT_TRUE(j[0].contains("rel_error")) << j.dump();
    EXPECT_TRUE(j[0]["rel_error"].is_null()) << j.dump();
    EXPECT_NEAR(j[1]["rel_error"].get<double>(), 0.01, 1e-12) << j.dump();
}

TEST(ValidationTable, JudgedValueIsTheModelsElseThePapers) {
    ValidationRow r;
    r.paper = 3.0;
    EXPECT_EQ(judgedValue(r), 3.0);
    r.multibody = 2.0;
    EXPECT_EQ(judgedValue(r), 2.0);
}

// Issue 31 item 7: one status policy for every row, and every status can
// fail.
TEST(ValidationStatusPolicy, JudgedPassesWithinItsToleranceOnly) {
    EXPECT_EQ(compareRow("c", "q", "1", 1.0 + 1e-7, 1.0, 1e-6).status, "pass");
    EXPECT_EQ(compareRow("c", "q", "1", 1.0 + 1e-5, 1.0, 1e-6).status, "fail");
    EXPECT_EQ(compareRow("c", "q", "1", NAN, 1.0, 1e-6).status, "fail");
    // A case's own error measure goes through the same policy.
    EXPECT_EQ(withError(compareRow("c", "q", "1", 5.0, 1.0, 1e-6), 1e-9).status, "pass");
    EXPECT_EQ(withError(compareRow("c", "q", "1", 1.0, 1.0, 1e-6), 1e-3).status, "fail");
}

TEST(ValidationStatusPolicy, MisprintFailsWhenThePrintedValueAgrees) {
    EXPECT_EQ(asMisprint(compareRow("c", "q", "1", 1.1, 1.0, 1e-6)).status, "flagged");
    EXPECT_EQ(asMisprint(compareRow("c", "q", "1", 1.0, 1.0, 1e-6)).status, "fail");
    EXPECT_EQ(asMisprint(compareRow("c", "q", "1", NAN, 1.0, 1e-6)).status, "fail");
    EXPECT_EQ(paperRow("c", "q", "1", 18.1, 16.48, 0.05 / 18.1, RowPolicy::Misprint, "").status, "flagged");
    EXPECT_EQ(paperRow("c", "q", "1", 16.5, 16.48, 0.05 / 16.5, RowPolicy::Misprint, "").status, "fail");
    EXPECT_EQ(paperRow("c", "q", "1", 16.5, 16.48, 0.05 / 16.5, RowPolicy::Judged, "").status, "pass");
}

TEST(ValidationStatusPolicy, ObservationIsInfoInsideItsBandAndFailsOutside) {
    const ValidationRow inside = asObservation(compareRow("c", "q", "m/s", 0.0, 0.0, 0.0), {0.0, 0.0, "never slips"});
    EXPECT_EQ(inside.status, "info");
    EXPECT_NE(inside.note.find("expected [0, 0]: never slips"), std::string::npos) << inside.note;
    EXPECT_EQ(asObservation(compareRow("c", "q", "m/s", 1e-9, 0.0, 0.0), {0.0, 0.0, ""}).status, "fail");
    EXPECT_EQ(asObservation(compareRow("c", "q", "s", 4.88, 4.83, 0.01), {4.7, 5.0, ""}).status, "info");
    EXPECT_EQ(asObservation(compareRow("c", "q", "s", 5.2, 4.83, 0.01), {4.7, 5.0, ""}).status, "fail");
    EXPECT_EQ(asObservation(compareRow("c", "q", "s", NAN, 4.83, 0.01), {-INFINITY, INFINITY, ""}).status, "fail");
    // Without a band an observation cannot be judged: a failure.
    ValidationRow noBand = compareRow("c", "q", "s", 4.88, 4.83, 0.01);
    noBand.policy = RowPolicy::Observation;
    applyStatusPolicy(noBand);
    EXPECT_EQ(noBand.status, "fail");
    // --json carries the band (an open side as null).
    const nlohmann::json j = nlohmann::json::parse(
        formatValidationJson({asObservation(compareRow("c", "q", "s", 4.88, 4.83, 0.01), {4.7, INFINITY, ""})}));
    EXPECT_EQ(j[0]["status"], "info");
    EXPECT_DOUBLE_EQ(j[0]["band"][0].get<double>(), 4.7);
    EXPECT_TRUE(j[0]["band"][1].is_null());
}

TEST(ValidationStatusPolicy, CountsAndTheTableSayTheSame) {
    const std::vector<ValidationRow> rows = {
        compareRow("c", "a", "1", 1.0, 1.0, 1e-6), asMisprint(compareRow("c", "b", "1", 2.0, 1.0, 1e-6)),
        asObservation(compareRow("c", "d", "1", 2.0, 1.0, 0), {1.5, 2.5, ""}),
        compareRow("c", "e", "1", 2.0, 1.0, 1e-6)};
    EXPECT_EQ(formatStatusCounts(countStatuses(rows)), "1 pass, 1 flagged, 1 info, 1 fail");
    EXPECT_NE(formatValidationTable(rows).find("1 passed, 1 failed, 1 flagged, 1 info"), std::string::npos);
}

// docs/validation.md's totals line is the sum of its sections' headings
// (each heading pinned to its case group by that machine's validation test).
TEST(ValidationStatusPolicy, TheDocsTotalsAreTheSumOfTheSections) {
    std::ifstream in(std::string(MILLDYN_SOURCE_DIR) + "/docs/validation.md");
    const std::regex heading(R"(^## .*: (\d+) pass, (\d+) flagged, (\d+) info, (\d+) fail$)");
    const std::regex totals(R"(^Totals .*: (\d+) pass, (\d+) flagged, (\d+) info, (\d+) fail\b)");
    StatusCounts sum, stated;
    int sections = 0;
    bool found = false;
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, heading)) {
            ++sections;
            sum.pass += std::stoi(m[1]);
            sum.flagged += std::stoi(m[2]);
            sum.info += std::stoi(m[3]);
            sum.fail += std::stoi(m[4]);
        } else if (std::regex_search(line, m, totals)) {
            found = true;
            stated = {std::stoi(m[1]), std::stoi(m[4]), std::stoi(m[2]), std::stoi(m[3])};
        }
    }
    EXPECT_EQ(sections, 9);
    ASSERT_TRUE(found) << "no totals line";
    EXPECT_EQ(formatStatusCounts(stated), formatStatusCounts(sum));
}

}  // namespace
}  // namespace milldyn
