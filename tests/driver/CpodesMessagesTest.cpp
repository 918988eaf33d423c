// Issue 31 item 6: CPodes' messages are kept for the thread that owns the
// integrator, and nothing another thread writes to stderr is swallowed
// while a CPodes integrator is being made (stderr used to be swapped
// process-wide for that moment, and text written then was lost).

#include "driver/CpodesMessages.h"

#include <Simbody.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

namespace milldyn {
namespace {

/// File descriptor 2 sent to a file for the test's lifetime.
class CapturedStderr {
public:
    CapturedStderr() : m_path(std::filesystem::temp_directory_path() / ("milldyn-cpodes-" + std::to_string(::getpid()))) {
        std::fflush(stderr);
        m_saved = ::dup(STDERR_FILENO);
        FILE* f = std::fopen(m_path.c_str(), "w");
        ::dup2(::fileno(f), STDERR_FILENO);
        std::fclose(f);
    }
    ~CapturedStderr() {
        restore();
        std::filesystem::remove(m_path);
    }
    std::string text() {
        restore();
        std::ifstream in(m_path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }

private:
    void restore() {
        if (m_saved < 0) return;
        std::fflush(stderr);
        ::dup2(m_saved, STDERR_FILENO);
        ::close(m_saved);
        m_saved = -1;
    }
    std::filesystem::path m_path;
    int m_saved = -1;
};

TEST(CpodesMessages, TextOfAThreadWithoutACpodesIntegratorReachesStderr) {
    // A fresh thread: it has made no CPodes integrator.
    std::string text;
    {
        CapturedStderr captured;
        std::thread([] {
            std::fputs("not from CPodes\n", cpodesMessageSink());
            EXPECT_EQ(takeCpodesError(), "");
        }).join();
        text = captured.text();
    }
    EXPECT_NE(text.find("not from CPodes"), std::string::npos);
}

TEST(CpodesMessages, TextOfAThreadThatMakesCpodesIntegratorsIsKeptForIt) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    system.realizeTopology();
    const auto integrator = makeCpodesIntegrator(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    CapturedStderr captured;
    std::fputs("\n[CPODES ERROR]  CPode\n  the step failed\n\n", cpodesMessageSink());
    EXPECT_NE(takeCpodesError().find("the step failed"), std::string::npos);
    EXPECT_EQ(captured.text().find("the step failed"), std::string::npos);
}

// One thread makes CPodes integrators over and over (each swaps stderr for
// a moment) while another writes numbered lines to stderr: every line
// arrives (before, a line written in the swap window was lost).
TEST(CpodesMessages, AnotherThreadsStderrIsNotSwallowedWhileIntegratorsAreMade) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    system.realizeTopology();
    const int lines = 3000;
    std::string text;
    {
        CapturedStderr captured;
        std::atomic<bool> done{false};
        std::thread maker([&] {
            while (!done) makeCpodesIntegrator(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
        });
        // A thread that makes no CPodes integrator of its own.
        std::thread([&] {
            for (int k = 0; k < lines; ++k) std::fprintf(stderr, "line %d\n", k);
        }).join();
        done = true;
        maker.join();
        text = captured.text();
    }
    int found = 0;
    for (int k = 0; k < lines; ++k)
        if (text.find("line " + std::to_string(k) + "\n") != std::string::npos) ++found;
    EXPECT_EQ(found, lines);
}

}  // namespace
}  // namespace milldyn
