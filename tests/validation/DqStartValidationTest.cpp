// The dq machine's start cases (validation/cases/DqStartCases.cpp) as a
// test: milldyn's DqInductionMotor against the independent fifth-order
// oracle over whole DOL, star–delta and soft starts, its starters held at a
// slip against the equivalent circuit, the oracle against MSL IMC_DOL's
// documented nominal speed, and the starter benches' energy balance.

#include "validation/cases/ValidationCases.h"

#include "SectionCounts.h"

#include <gtest/gtest.h>

#include <cmath>

namespace milldyn {
namespace {

TEST(DqStartValidation, EveryCasePasses) {
    const auto rows = dqStartCases("");
    // 3 benches × (4 as shipped + 4 at 1e-9) + 2 balances + 4 star–delta + 2 soft start + 1 MSL, ...;
    // linearize_dq_belt_mode 4 (flux states 2, static slope 2).
    EXPECT_EQ(rows.size(), 83u);
    for (const auto& r : rows)
        EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN) << " vs "
                                    << r.oracle << " rel " << r.relError << " tol " << r.tolerance;
    test::expectSectionCounts(rows, "The dq machine against an independent transient oracle (issue 15)", {83, 0, 0, 0});
}


}  // namespace
}  // namespace milldyn
