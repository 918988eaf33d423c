// Issue 20 item 13: where a validation row's oracle is 0, `milldyn validate`
// prints (and `--json` writes) the absolute error, not a relative one of
// 1e+299; elsewhere the relative error as before.
#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

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

}  // namespace
}  // namespace milldyn
