// The driver's contract as users and scripts see it: the built `milldyn`
// binary is run through the shell with stdout and stderr captured, and its
// exit code (0 ok, 1 analysis or output failed, 2 bad input), its one-line
// diagnostics and its output files are checked. Every test works in its own
// temporary directory.

#include "driver/ModelSpec.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

namespace fs = std::filesystem;

// Away from standstill the load law's tanh(ω/ωs) is 1 to double precision,
// so the steady resistance torque equals constant_torque up to the
// integrator's relative accuracy (1e-6 in the burr-mill model).
constexpr double kSteadyTorqueRelTol = 1e-6;

const std::string kBinary = MILLDYN_BINARY;
const std::string kSourceDir = MILLDYN_SOURCE_DIR;
const std::string kBurrMill = kSourceDir + "/models/burr_mill_5p5kW_idle.yaml";
const std::string kGoodMinimal = kSourceDir + "/tests/testdata/good_minimal.yaml";
const std::string kBadDir = kSourceDir + "/tests/testdata/bad";

std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
    return fields;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Names of the entries of a directory (sorted), excluding the capture folder.
std::vector<std::string> entriesOf(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename() != ".capture") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

struct RunResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("milldyn-clitest-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / ".capture");
    }

    void TearDown() override {
        std::error_code ec;
        fs::remove_all(m_dir, ec);
    }

    /// Runs milldyn with these arguments (no shell interpretation of them).
    RunResult run(const std::vector<std::string>& args) const {
        const fs::path out = m_dir / ".capture" / "stdout", err = m_dir / ".capture" / "stderr";
        std::string cmd = shellQuote(kBinary);
        for (const auto& a : args) cmd += " " + shellQuote(a);
        cmd += " </dev/null >" + shellQuote(out.string()) + " 2>" + shellQuote(err.string());
        const int status = std::system(cmd.c_str());
        RunResult r;
        r.exitCode = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
        r.out = readFile(out);
        r.err = readFile(err);
        return r;
    }

    static nlohmann::json summaryOf(const fs::path& outDir) {
        return nlohmann::json::parse(readFile(outDir / "summary.json"));
    }

    fs::path m_dir;
};

// ------------------------------------------------------------ command line

TEST_F(CliTest, HelpExitsZeroAndPrintsUsage) {
    const RunResult r = run({"--help"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "milldyn run MODEL.yaml")) << r.out;
    EXPECT_TRUE(contains(r.out, "milldyn info MODEL.yaml")) << r.out;
}

TEST_F(CliTest, UnknownCommandExitsTwo) {
    const RunResult r = run({"frobnicate", kBurrMill});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(contains(r.err, "unknown command 'frobnicate'")) << r.err;
}

TEST_F(CliTest, MissingModelArgumentExitsTwo) {
    for (const std::string command : {"run", "info"}) {
        const RunResult r = run({command});
        EXPECT_EQ(r.exitCode, 2) << command;
        EXPECT_TRUE(contains(r.err, command + " needs a model file")) << r.err;
    }
    const RunResult noCommand = run({});
    EXPECT_EQ(noCommand.exitCode, 2);
}

TEST_F(CliTest, UnknownOptionAndMalformedSetExitTwo) {
    EXPECT_EQ(run({"run", kGoodMinimal, "--bogus"}).exitCode, 2);
    const RunResult r = run({"run", kGoodMinimal, "--set", "no_equals_sign", "--out", (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("<--set>:1:1: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(m_dir / "out"));
}

// --------------------------------------------------------------- bad input

// Every bad file says where its error is: "# expect: LINE:COL KEY".
TEST_F(CliTest, EveryBadModelFileExitsTwoWithOneLocatedDiagnosticLine) {
    int checked = 0;
    for (const auto& entry : fs::directory_iterator(kBadDir)) {
        if (entry.path().extension() != ".yaml") continue;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        std::string expect;
        for (const auto& line : splitLines(readFile(path)))
            if (line.rfind("# expect: ", 0) == 0) expect = line.substr(10);
        ASSERT_FALSE(expect.empty()) << "no '# expect: LINE:COL KEY' comment";
        const std::string location = expect.substr(0, expect.find(' '));
        const std::string key = expect.substr(expect.find(' ') + 1);

        const fs::path outDir = m_dir / entry.path().stem();
        const RunResult r = run({"run", path, "--out", outDir.string()});
        EXPECT_EQ(r.exitCode, 2) << r.err;
        ASSERT_FALSE(r.err.empty());
        EXPECT_EQ(r.err.back(), '\n');
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not exactly one line:\n" << r.err;
        EXPECT_EQ(r.err.rfind(path + ":" + location + ": error: " + key + ": ", 0), 0u) << r.err;
        EXPECT_TRUE(std::regex_search(r.err, std::regex("^.+:[0-9]+:[0-9]+: error: [^:]+: .+\n$"))) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(outDir)) << "bad input must not create the output directory";
        ++checked;
    }
    EXPECT_GE(checked, 30);
}

TEST_F(CliTest, MissingModelFileExitsTwoNamingThePath) {
    const std::string path = (m_dir / "no_such_model.yaml").string();
    const RunResult r = run({"run", path, "--out", (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind(path + ":", 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, "cannot open")) << r.err;
}

TEST_F(CliTest, DirectoryAsModelExitsTwoAndSaysItCannotBeRead) {
    const fs::path dir = m_dir / "a_directory.yaml";
    fs::create_directories(dir);
    const RunResult r = run({"run", dir.string(), "--out", (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind(dir.string() + ":", 0), 0u) << r.err;
    // A directory is not an empty model file: the message must not say so.
    EXPECT_FALSE(contains(r.err, "empty")) << r.err;
}

TEST_F(CliTest, UnreadableModelFileExitsTwo) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads files without read permission";
    const fs::path file = m_dir / "secret.yaml";
    fs::copy_file(kGoodMinimal, file);
    fs::permissions(file, fs::perms::none);
    const RunResult r = run({"run", file.string(), "--out", (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind(file.string() + ":", 0), 0u) << r.err;
}

// ------------------------------------------------------------------- runs

TEST_F(CliTest, RunWritesTimeseriesAndSummaryWithUnits) {
    const fs::path out = m_dir / "out";
    const RunResult r = run({"run", kBurrMill, "--end-time", "0.3", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const std::vector<std::string> lines = splitLines(readFile(out / "timeseries.csv"));
    ASSERT_GE(lines.size(), 3u);
    const std::vector<std::string> header = splitCommas(lines[0]);
    ASSERT_GE(header.size(), 2u);
    EXPECT_EQ(header[0], "time[s]");
    const std::regex column(R"(^[^\[\],]+\[[^\[\],]+\]$)");
    for (const auto& h : header) EXPECT_TRUE(std::regex_match(h, column)) << "column '" << h << "'";
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> fields = splitCommas(lines[i]);
        ASSERT_EQ(fields.size(), header.size()) << "row " << i;
        for (const auto& f : fields) {
            char* end = nullptr;
            const double v = std::strtod(f.c_str(), &end);
            ASSERT_TRUE(!f.empty() && *end == '\0' && std::isfinite(v)) << "row " << i << ": '" << f << "'";
        }
    }
    EXPECT_DOUBLE_EQ(std::strtod(splitCommas(lines.back())[0].c_str(), nullptr), 0.3);

    const nlohmann::json s = summaryOf(out);
    // 0.3 s is mid-start: an unfinished start reports its end speed, never a steady one.
    EXPECT_EQ(s["verdict"]["status"], "unfinished");
    EXPECT_FALSE(s["results"].contains("steady_speed"));
    EXPECT_EQ(s["results"]["speed_at_end"]["unit"], "rad/s");
    EXPECT_TRUE(s["results"]["speed_at_end"]["value"].is_number());
    EXPECT_EQ(s["settings"]["integrator"], "CPodes");
    EXPECT_GT(s["statistics"]["realizations"].get<long>(), 0);
    ASSERT_TRUE(s["run"].contains("wall_time"));
    EXPECT_TRUE(s["run"]["wall_time"].is_number());
    EXPECT_GE(s["run"]["wall_time"].get<double>(), 0.0);

    for (const auto& name : entriesOf(out)) EXPECT_FALSE(contains(name, ".tmp.")) << "leftover " << name;
}

TEST_F(CliTest, SetWithUnitsChangesTheSteadyResistanceTorque) {
    const fs::path out = m_dir / "out";
    const RunResult r = run({"run", kBurrMill, "--end-time", "3 s", "--set", "elements.grinding.constant_torque=20 N*m",
                             "--set", "outputs.plots=false", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double torque = summaryOf(out)["results"]["resistance_torque"]["value"].get<double>();
    EXPECT_NEAR(torque, 20.0, kSteadyTorqueRelTol * 20.0);
}

TEST_F(CliTest, SetWithUnitsChangesTheEndTime) {
    const fs::path out = m_dir / "out";
    const RunResult r =
        run({"run", kBurrMill, "--set", "scenario.end_time=40 ms", "--set", "outputs.plots=false", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<std::string> lines = splitLines(readFile(out / "timeseries.csv"));
    EXPECT_DOUBLE_EQ(std::strtod(splitCommas(lines.back())[0].c_str(), nullptr), 0.04);
}

TEST_F(CliTest, BadSetValueExitsTwoLocatedAtTheCommandLine) {
    const RunResult r = run({"run", kBurrMill, "--set", "elements.grinding.constant_torque=20 rmp", "--out",
                             (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("<--set elements.grinding.constant_torque>:1:", 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, "unknown unit 'rmp'")) << r.err;
}

TEST_F(CliTest, EveryIntegratorNameRunsAShortTransient) {
    for (const std::string& name : integratorNames()) {
        SCOPED_TRACE(name);
        const fs::path out = m_dir / name;
        const RunResult r = run({"run", kBurrMill, "--integrator", name, "--end-time", "0.05", "--set",
                                 "outputs.plots=false", "--quiet", "--out", out.string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(summaryOf(out)["settings"]["integrator"], name);
    }
}

TEST_F(CliTest, IntegratorAndAccuracyOptionsWorkForAModelWithoutAnIntegratorSection) {
    const fs::path out = m_dir / "out";
    const RunResult r = run({"run", kGoodMinimal, "--integrator", "RungeKutta3", "--accuracy", "1e-5", "--end-time",
                             "0.05", "--set", "outputs.plots=false", "--quiet", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json s = summaryOf(out);
    EXPECT_EQ(s["settings"]["integrator"], "RungeKutta3");
    EXPECT_EQ(s["settings"]["accuracy"].get<double>(), 1e-5);
}

TEST_F(CliTest, UnknownIntegratorOptionExitsTwo) {
    const RunResult r = run({"run", kBurrMill, "--integrator", "CPodez", "--out", (m_dir / "out").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(contains(r.err, "did you mean 'CPodes'?")) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(CliTest, OutputDirectoryUnderARegularFileExitsOneWithoutPartialFiles) {
    const fs::path file = m_dir / "xyz-file";
    std::ofstream(file) << "not a directory\n";
    const RunResult r = run({"run", kBurrMill, "--end-time", "0.05", "--out", (file / "out").string()});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(contains(r.err, (file / "out").string())) << r.err;
    EXPECT_EQ(entriesOf(m_dir), std::vector<std::string>{"xyz-file"});
    EXPECT_EQ(readFile(file), "not a directory\n");
}

TEST_F(CliTest, ReadOnlyOutputDirectoryExitsOneWithoutPartialFiles) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
    const fs::path out = m_dir / "readonly";
    fs::create_directories(out);
    fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec);
    const RunResult r = run({"run", kBurrMill, "--end-time", "0.05", "--out", out.string()});
    fs::permissions(out, fs::perms::owner_all);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(entriesOf(out).empty());
}

TEST_F(CliTest, InfoPrintsBodiesDegreesOfFreedomAndElements) {
    const RunResult r = run({"info", kBurrMill});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "bodies: 2")) << r.out;
    EXPECT_TRUE(contains(r.out, "(DOF): 2")) << r.out;
    for (const std::string name : {"body motor_shaft", "body millstone", "element motor", "element belt",
                                   "element grinding"})
        EXPECT_TRUE(contains(r.out, name)) << "'" << name << "' missing from:\n" << r.out;
}

TEST_F(CliTest, InfoSaysWhatWasNotBuiltAndWhetherTheRunIntegrates) {
    const std::string models = std::string(MILLDYN_SOURCE_DIR) + "/models/";
    // Roll crusher at its 2-mass level: the chain's rows are declared but
    // not built; two free mobilities are integrated.
    const RunResult roll = run({"info", models + "roll_crusher.yaml", "--set", "fidelity.level=2-mass"});
    ASSERT_EQ(roll.exitCode, 0) << roll.err;
    EXPECT_TRUE(contains(roll.out, "not built:")) << roll.out;
    EXPECT_TRUE(contains(roll.out, "body row5 — fidelity levels 10-mass")) << roll.out;
    EXPECT_TRUE(contains(roll.out, "time integration: integrated: 2 free degrees of freedom")) << roll.out;
    // Planetary gear start: carrier prescribed, drums geared, charges folded
    // into their drums: nothing to integrate.
    const RunResult gear = run({"info", models + "planetary_gear_100x200.yaml", "--set", "use_scenario=start"});
    ASSERT_EQ(gear.exitCode, 0) << gear.err;
    EXPECT_TRUE(contains(gear.out, "charge charge1 (SegmentCharge, with_drum) folded into drum1")) << gear.out;
    EXPECT_TRUE(contains(gear.out, "time integration: none: no free degrees of freedom")) << gear.out;
    EXPECT_TRUE(contains(gear.out, "energy meter (4 flows)")) << gear.out;
    // Its kinetostatic default builds no energy meter.
    const RunResult kinetostatic = run({"info", models + "planetary_gear_100x200.yaml"});
    EXPECT_TRUE(contains(kinetostatic.out, "energy meter — the kinetostatic analysis reports no energy balance"))
        << kinetostatic.out;
}

TEST_F(CliTest, TwoRunsWithTheSameSettingsGiveIdenticalOutputs) {
    const std::vector<std::string> settings = {"run", kBurrMill, "--end-time", "0.3", "--set", "outputs.plots=false",
                                               "--quiet", "--out"};
    std::vector<std::string> first = settings, second = settings;
    first.push_back((m_dir / "a").string());
    second.push_back((m_dir / "b").string());
    ASSERT_EQ(run(first).exitCode, 0);
    ASSERT_EQ(run(second).exitCode, 0);

    const std::string csvA = readFile(m_dir / "a" / "timeseries.csv");
    EXPECT_FALSE(csvA.empty());
    EXPECT_TRUE(csvA == readFile(m_dir / "b" / "timeseries.csv")) << "timeseries.csv differs between runs";
    nlohmann::json a = summaryOf(m_dir / "a"), b = summaryOf(m_dir / "b");
    a.erase("run");
    b.erase("run");
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace milldyn
