// The jaw crusher's validation cases (validation/cases/JawCrusherCases.cpp)
// as a test: the crushing pulse's harmonics and work per stroke against the
// half-sine's closed form, the flywheel's speed fluctuation against the
// slip-damped harmonic balance and below the textbook energy method, the
// loaded restart's breakaway passed and not passed.

#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>

#include <cmath>

namespace milldyn {
namespace {

TEST(JawCrusherValidation, EveryCasePasses) {
    const auto rows = jawCrusherCases("");
    // 9 Fourier rows + 2 work per stroke + 3 mean power + 2 speed fluctuation
    // + 2 breakaway.
    EXPECT_EQ(rows.size(), 18u);
    for (const auto& r : rows)
        EXPECT_EQ(r.status, "pass") << r.caseName << ": " << r.quantity << " " << r.multibody.value_or(NAN) << " vs "
                                    << r.oracle << " rel " << r.relError << " tol " << r.tolerance << " (" << r.note
                                    << ")";
}

}  // namespace
}  // namespace milldyn
