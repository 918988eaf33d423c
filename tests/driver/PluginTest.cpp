// `--plugin lib.so`: element types from a plugin library, through the same
// registry the built-ins use; libraries of another ABI are refused.

#include <gtest/gtest.h>
#include "plugins/scene/EngineTag.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace {

struct Result {
    int code;
    std::string err;
};

/// Runs milldyn; its standard output goes to `outFile` (discarded if empty).
Result runMilldyn(const std::string& args, const std::string& outFile = "") {
    const std::string errFile = std::filesystem::temp_directory_path().string() + "/milldyn-plugintest.err";
    const std::string cmd = std::string(MILLDYN_BINARY) + " " + args + " >" + (outFile.empty() ? "/dev/null" : outFile) +
                            " 2>" + errFile;
    const int status = std::system(cmd.c_str());
    std::ifstream in(errFile);
    std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err};
}

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/tests/testdata/plugin_constant_torque.yaml";

TEST(PluginTest, PluginElementRunsAndGivesTheClosedFormSpeed) {
    const std::string out = std::filesystem::temp_directory_path().string() + "/milldyn-plugintest-out";
    const Result r = runMilldyn("run " + kModel + " --plugin " + MILLDYN_EXAMPLE_PLUGIN + " --out " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(out + "/summary.json");
    const auto summary = nlohmann::json::parse(in);
    // ω(1 s) = M·t/J = 3·1/2 = 1.5 rad/s; RungeKuttaMerson is exact to
    // round-off on a constant acceleration. A shaft still accelerating is an
    // unfinished start: its speed is the end speed, not a steady one.
    EXPECT_EQ(summary["verdict"]["status"], "unfinished");
    EXPECT_NEAR(summary["results"]["speed_at_end"]["value"].get<double>(), 1.5, 1e-12);
    // Its energy flow is booked like a built-in's: W = ½·J·ω² = 2.25 J.
    EXPECT_NEAR(summary["results"]["energy_from_sources"]["value"].get<double>(), 2.25, 1e-9);
}

TEST(PluginTest, WithoutThePluginTheTypeIsUnknown) {
    const Result r = runMilldyn("run " + kModel);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("unknown element type 'ConstantTorque'"), std::string::npos) << r.err;
}

TEST(PluginTest, InfoListsThePluginElement) {
    // `info --json` names the plugin's element with its type, and lists the
    // outputs it registered (its torque probe), as for a built-in element.
    const std::string out = std::filesystem::temp_directory_path().string() + "/milldyn-plugintest-info.json";
    const Result r = runMilldyn("info " + kModel + " --json --plugin " + MILLDYN_EXAMPLE_PLUGIN, out);
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(out);
    const auto info = nlohmann::json::parse(in);
    ASSERT_TRUE(info["elements"].contains("push")) << info.dump();
    EXPECT_EQ(info["elements"]["push"], "ConstantTorque");
    EXPECT_TRUE(info["outputs"].contains("push.torque")) << info["outputs"].dump();
    // And the text form names it the same way.
    const std::string text = std::filesystem::temp_directory_path().string() + "/milldyn-plugintest-info.txt";
    ASSERT_EQ(runMilldyn("info " + kModel + " --plugin " + MILLDYN_EXAMPLE_PLUGIN, text).code, 0);
    std::ifstream t(text);
    const std::string printed((std::istreambuf_iterator<char>(t)), std::istreambuf_iterator<char>());
    EXPECT_NE(printed.find("element push: ConstantTorque"), std::string::npos) << printed;
}

TEST(PluginTest, LibraryOfAnotherAbiIsRefusedWithExitTwo) {
    const Result r = runMilldyn("run " + kModel + " --plugin " + MILLDYN_WRONG_ABI_PLUGIN);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("plugin ABI"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("<--plugin "), std::string::npos) << r.err;
}

TEST(PluginTest, LibraryOfTheOtherNdebugSettingIsRefusedWithExitTwo) {
    const Result r = runMilldyn("run " + kModel + " --plugin " + MILLDYN_WRONG_ENGINE_PLUGIN);
    EXPECT_EQ(r.code, 2);
    // Names both engine tags: the plugin's (the other NDEBUG setting) and this milldyn's.
    const std::string other = std::string(MILLDYN_SIMBODY_VERSION) +
                              (std::string(MILLDYN_SIMBODY_BUILD) == "Release" ? " checked" : " Release");
    EXPECT_NE(r.err.find("built against Simbody " + other), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::string("this milldyn uses Simbody ") + MILLDYN_ENGINE_TAG), std::string::npos)
        << r.err;
}

TEST(PluginTest, MissingLibraryIsRefusedWithExitTwo) {
    const Result r = runMilldyn("run " + kModel + " --plugin /nonexistent/libnothing.so");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("cannot load"), std::string::npos) << r.err;
}

TEST(PluginTest, LoadingTheSameTypeTwiceIsRefused) {
    const std::string p = MILLDYN_EXAMPLE_PLUGIN;
    const Result r = runMilldyn("run " + kModel + " --plugin " + p + " --plugin " + p);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("already registered"), std::string::npos) << r.err;
}

}  // namespace
