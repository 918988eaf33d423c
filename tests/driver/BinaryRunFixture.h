#pragma once
// Shared by the tests that run the built milldyn binary: a scratch directory
// per test, and a run of the binary with its exit code, stdout and stderr.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace milldyn::test {

struct BinaryResult {
    int code = -1;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A fresh directory per test (named after the test and the process),
/// removed afterwards; run() executes `prefix milldyn args` in a shell.
class BinaryRunFixture : public ::testing::Test {
protected:
    explicit BinaryRunFixture(std::string tag) : m_tag(std::move(tag)) {}
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = std::filesystem::temp_directory_path() /
                ("milldyn-" + m_tag + "-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override {
        std::error_code ec;
        std::filesystem::remove_all(m_dir, ec);
    }
    BinaryResult run(const std::string& prefix, const std::string& args) const {
        const std::string out = (m_dir / "stdout").string(), err = (m_dir / "stderr").string();
        const std::string cmd = prefix + MILLDYN_BINARY + " " + args + " </dev/null >" + out + " 2>" + err;
        const int status = std::system(cmd.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
    }
    std::filesystem::path m_dir;

private:
    std::string m_tag;
};

}  // namespace milldyn::test
