// formatNumber (plugins/scene/Format.h): messages and labels.
#include <gtest/gtest.h>

#include "plugins/scene/Format.h"

namespace milldyn {
namespace {

TEST(FormatNumber, ShortestFormAtTheGivenDigitsAndNoNegativeZero) {
    EXPECT_EQ(formatNumber(0.1 + 0.2), "0.3");
    EXPECT_EQ(formatNumber(46.2357, 3), "46.2");
    EXPECT_EQ(formatNumber(1.5e-7, 4), "1.5e-07");
    EXPECT_EQ(formatNumber(-0.0), "0");  // a stalled drive's "-0 N*m"
    EXPECT_EQ(formatNumber(-2.5), "-2.5");
}

}  // namespace
}  // namespace milldyn
