#pragma once
// Shared by the model-reader tests: read text, catch the SpecError, check
// its location, key, reason and one-line form.

#include "driver/analyses/Analysis.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace milldyn::test {

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// `text` with the one occurrence of `from` replaced by `to`.
inline std::string replacedIn(const std::string& text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    if (pos == std::string::npos || text.find(from, pos + 1) != std::string::npos) {
        ADD_FAILURE() << "'" << from << "' must occur exactly once in the test text";
        return text;
    }
    std::string out = text;
    out.replace(pos, from.size(), to);
    return out;
}

inline ModelSpec readText(const std::string& file, const std::string& text, const std::vector<Override>& overrides) {
    return readModelText(text, file, defaultModelReader(), overrides);
}

/// The SpecError reading `text` throws; a test failure if it throws none.
inline SpecError readErrorOf(const std::string& file, const std::string& text, const std::vector<Override>& overrides) {
    try {
        readText(file, text, overrides);
    } catch (const SpecError& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected SpecError, got std::exception: " << e.what();
        return SpecError({}, "", "<wrong exception>");
    }
    ADD_FAILURE() << "expected SpecError, the text was accepted";
    return SpecError({}, "", "<nothing thrown>");
}

/// Checks location, key, reason and the one-line formatted diagnostic.
inline void expectSpecError(const SpecError& e, const std::string& file, int line, int column, const std::string& key,
                            const std::string& reasonPart) {
    if (e.where().file.empty() && e.what()[0] == '<') return;  // readErrorOf reported the failure already
    EXPECT_EQ(e.where().file, file) << e.formatted();
    EXPECT_EQ(e.where().line, line) << e.formatted();
    EXPECT_EQ(e.where().column, column) << e.formatted();
    EXPECT_EQ(e.key(), key) << e.formatted();
    EXPECT_TRUE(contains(e.what(), reasonPart)) << "reason '" << e.what() << "' lacks '" << reasonPart << "'";
    const std::string expected = file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                 ": error: " + (key.empty() ? "<document>" : key) + ": " + e.what();
    EXPECT_EQ(e.formatted(), expected);
    EXPECT_FALSE(contains(e.formatted(), "\n"));
}

}  // namespace milldyn::test
