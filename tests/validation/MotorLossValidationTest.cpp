// The motor-loss and converter-current-limit start cases
// (validation/cases/StartCases.cpp, oracle validation/oracles/StartOracle)
// as tests: every comparison passes, and each case ran with the rows it
// promises (the electrical input along a start, the efficiency at a part
// load and at the rated point, the energy balance; the current held at the
// limit, the time under M(I_lim), the slip, the bound, the balance).

#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace milldyn {
namespace {

void expectAllPass(const std::string& filter, const std::map<std::string, int>& rowsPerCase) {
    std::map<std::string, int> seen;
    for (const auto& r : startCases(filter)) {
        ++seen[r.caseName];
        EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN) << " vs "
                                    << r.oracle << " rel " << r.relError;
    }
    EXPECT_EQ(seen, rowsPerCase);
}

TEST(MotorLossValidation, EfficiencyCasesPass) {
    expectAllPass("start_motor_efficiency", {{"start_motor_efficiency", 3}, {"start_energy_balance_efficiency", 1}});
}

TEST(MotorLossValidation, ConverterCurrentLimitCasesPass) {
    expectAllPass("start_converter_current_limit",
                  {{"start_converter_current_limit", 4}, {"start_energy_balance_converter_current", 1}});
}

}  // namespace
}  // namespace milldyn
