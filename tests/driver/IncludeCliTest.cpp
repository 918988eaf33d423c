// Model-file includes through the built binary: an assembled layout runs and
// sweeps by its prefixed names, and an error in a part exits 2 with one line
// that is located in the part and ends with the include chain.

#include "tests/driver/BinaryRunFixture.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata";

using Result = milldyn::test::BinaryResult;
using milldyn::test::slurp;

class CliInclude : public milldyn::test::BinaryRunFixture {
protected:
    CliInclude() : BinaryRunFixture("includecli") {}
    Result run(const std::string& args) const { return BinaryRunFixture::run("", args); }
};

TEST_F(CliInclude, AssembledLayoutSweepsOverAnIncludedValueByItsPrefixedName) {
    const Result r = run("sweep " + kData + "/include_two_drums.yaml --jobs 1 --out " + (m_dir / "s").string() +
                         " --grid 'elements.left_charge.constant_torque=20 N*m:60 N*m:2'");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string table = slurp(m_dir / "s" / "sweep.csv");
    EXPECT_NE(table.find("elements.left_charge.constant_torque[N*m]"), std::string::npos) << table;
    // The file's 0.2 s is the first part of a start: each point gives its
    // verdict (at 60 N*m the carrier crawls at 0.2 % of its speed and no
    // longer gains speed: a stall).
    EXPECT_NE(table.find("\n0,20,unfinished,"), std::string::npos) << table;
    EXPECT_NE(table.find("\n1,60,stalled,"), std::string::npos) << table;
}

TEST_F(CliInclude, ErrorInAPartExitsTwoWithOneLineEndingInTheChain) {
    const std::string top = kData + "/bad/include/cycle.yaml";
    const Result r = run("info " + top);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
    EXPECT_EQ(r.err.rfind(kData + "/bad/include/parts/cycle_b.yaml:4:5: error: include: include cycle: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(", included from " + top + ":7:10)\n"), std::string::npos) << r.err;
    const Result missing = run("run " + kData + "/bad/include_missing_file.yaml --out " + (m_dir / "m").string());
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("cannot open '"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(m_dir / "m" / "summary.json"));
}

}  // namespace
