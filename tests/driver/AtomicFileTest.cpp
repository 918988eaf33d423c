// Output files are written completely or not at all.

#include "driver/outputs/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace milldyn {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("milldyn-atomic-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

int filesIn(const fs::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

TEST(AtomicFileTest, WritesTheWholeContentUnderTheFinalName) {
    const fs::path dir = freshDir("ok");
    writeFileAtomically((dir / "a.csv").string(), "x[1]\n1\n");
    std::ifstream in(dir / "a.csv");
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), "x[1]\n1\n");
    EXPECT_EQ(filesIn(dir), 1);  // no temporary left beside it
}

TEST(AtomicFileTest, ReplacesAnOldFileInOneStep) {
    const fs::path dir = freshDir("replace");
    writeFileAtomically((dir / "a.json").string(), "old");
    writeFileAtomically((dir / "a.json").string(), "new content");
    std::ifstream in(dir / "a.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "new content");
    EXPECT_EQ(filesIn(dir), 1);
}

TEST(AtomicFileTest, FailingFinalStepLeavesNoPartialFile) {
    // The final name is taken by a non-empty directory: the data is written
    // and flushed, but the rename fails. Nothing may be left behind.
    const fs::path dir = freshDir("fail");
    fs::create_directories(dir / "summary.json" / "occupied");
    EXPECT_THROW(writeFileAtomically((dir / "summary.json").string(), "{}"), OutputError);
    EXPECT_EQ(filesIn(dir), 1);  // only the directory that was there
    EXPECT_TRUE(fs::is_directory(dir / "summary.json"));
}

TEST(AtomicFileTest, MissingDirectoryIsAnOutputErrorNamingThePath) {
    const fs::path dir = freshDir("missing");
    try {
        writeFileAtomically((dir / "no" / "such" / "a.csv").string(), "x");
        FAIL() << "wrote into a missing directory";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("a.csv"), std::string::npos) << e.what();
    }
    EXPECT_EQ(filesIn(dir), 0);
}

}  // namespace
}  // namespace milldyn
