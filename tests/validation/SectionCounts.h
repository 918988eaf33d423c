#pragma once
// The counts of one section of docs/validation.md ("## TITLE: 72 pass,
// 4 flagged, 0 info, 0 fail") against the rows its case group gives: the
// docs' numbers come from the cases (issue 31 item 7), and each test pins
// its own section's numbers too, so a change shows in the test and in the
// docs together.

#include "validation/cases/ValidationCases.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn::test {

/// The heading line of the section whose title is `title`, "" if none.
inline std::string validationDocsHeading(const std::string& title) {
    std::ifstream in(std::string(MILLDYN_SOURCE_DIR) + "/docs/validation.md");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("## " + title + ": ", 0) == 0) return line;
    return "";
}

/// The rows' counts equal `pinned`, and the docs' heading says the same.
inline void expectSectionCounts(const std::vector<ValidationRow>& rows, const std::string& title,
                                const StatusCounts& pinned) {
    const StatusCounts c = countStatuses(rows);
    EXPECT_EQ(formatStatusCounts(c), formatStatusCounts(pinned)) << title;
    EXPECT_EQ(validationDocsHeading(title), "## " + title + ": " + formatStatusCounts(c))
        << "docs/validation.md's heading of " << title;
}

}  // namespace milldyn::test
