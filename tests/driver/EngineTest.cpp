// Which engine runs: `milldyn --version` and summary.json's run section name
// the Simbody version and build type, and they are the engine CMake chose
// (MILLDYN_EXPECTED_ENGINE comes from cmake/Engine.cmake's choice, not from
// the NDEBUG macro the binary reads; docs/building.md).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct Output {
    int code = -1;
    std::string text;
};

Output runMilldyn(const std::string& args, const std::string& environment = "") {
    Output o;
    const std::string command = (environment.empty() ? "" : "env " + environment + " ") + MILLDYN_BINARY + " " + args;
    FILE* p = ::popen((command + " 2>&1").c_str(), "r");
    if (!p) return o;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), p)) > 0) o.text.append(buffer.data(), n);
    const int status = ::pclose(p);
    o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return o;
}

}  // namespace

TEST(EngineTest, VersionNamesTheSimbodyVersionAndBuildType) {
    const Output o = runMilldyn("--version");
    ASSERT_EQ(o.code, 0) << o.text;
    EXPECT_NE(o.text.find(std::string("\n") + MILLDYN_EXPECTED_ENGINE + "\n"), std::string::npos) << o.text;
}

TEST(EngineTest, SummaryRunSectionNamesTheEngine) {
    const fs::path out = fs::temp_directory_path() / ("milldyn_engine_test_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const Output o = runMilldyn("run " + std::string(MILLDYN_SOURCE_DIR) +
                                "/models/burr_mill_5p5kW_idle.yaml --end-time 0.2 --set outputs.plots=false --quiet"
                                " --out " + out.string());
    ASSERT_EQ(o.code, 0) << o.text;
    std::ifstream in(out / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    EXPECT_EQ(s["run"]["engine"], MILLDYN_EXPECTED_ENGINE);
    fs::remove_all(out);
}

// The other engine's library, loaded through LD_LIBRARY_PATH (it has the same
// soname), is refused before anything runs: exit 1, one line naming both.
TEST(EngineTest, TheOtherEnginesLibraryIsRefusedAtStartUp) {
    const std::string other = MILLDYN_OTHER_SIMBODY_LIBDIR;
    if (other.empty() || !fs::exists(other + "/libSimTKcommon.so.3.7"))
        GTEST_SKIP() << "no other engine's library on this machine";
    const Output o = runMilldyn("--version", "LD_LIBRARY_PATH=" + other);
    EXPECT_EQ(o.code, 1) << o.text;
    EXPECT_NE(o.text.find("milldyn: error: loaded Simbody library " + other), std::string::npos) << o.text;
    EXPECT_NE(o.text.find(std::string("built against ") + MILLDYN_EXPECTED_ENGINE), std::string::npos) << o.text;
}
