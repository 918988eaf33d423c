// `milldyn sweep --mpi` under `mpirun -np 2`: the table rank 0 writes is the
// single-process table byte for byte, the directory holds every rank's
// points (so it resumes), and the mode cannot be mixed up with --shard or
// left out under mpirun. Skipped in a build without MPI.

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

#ifdef MILLDYN_MPIEXEC
const std::string kMpiexec = MILLDYN_MPIEXEC;
#else
const std::string kMpiexec;
#endif

const std::string kModel = std::string(MILLDYN_SOURCE_DIR) + "/models/burr_mill_5p5kW_idle.yaml";
// Six short points (the grid of SweepTest): 0.3 s of the start each.
const std::string kSweep = "sweep " + kModel +
                           " --grid 'elements.grinding.constant_torque=10 N*m:30 N*m:3'"
                           " --grid 'elements.belt.damping=0.1 N*m*s/rad:0.5 N*m*s/rad:2'"
                           " --set 'scenario.end_time=0.3 s' --set scenario.initial_state=steady --set outputs.plots=false";
// Root in a container needs the two ALLOW variables; 2 ranks on fewer cores
// need --oversubscribe. Both are harmless elsewhere.
const std::string kMpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " + kMpiexec +
                            " --oversubscribe -np 2 ";

using Result = milldyn::test::BinaryResult;
using milldyn::test::slurp;

class MpiSweepTest : public milldyn::test::BinaryRunFixture {
protected:
    MpiSweepTest() : BinaryRunFixture("mpitest") {}
    using BinaryRunFixture::run;
};

TEST_F(MpiSweepTest, TwoRanksWriteTheSingleProcessTableByteForByteAndResume) {
    if (kMpiexec.empty()) GTEST_SKIP() << "built without MPI";
    const fs::path single = m_dir / "single", mpi = m_dir / "mpi";
    const Result s = run("", kSweep + " --jobs 1 --out " + single.string());
    ASSERT_EQ(s.code, 0) << s.err;
    const Result m = run(kMpirun, kSweep + " --mpi --out " + mpi.string());
    ASSERT_EQ(m.code, 0) << m.out << m.err;
    const std::string table = slurp(single / "sweep.csv");
    ASSERT_NE(table.find("resistance_torque[N*m]"), std::string::npos) << table;
    EXPECT_EQ(slurp(mpi / "sweep.csv"), table);
    // Rank 0 alone reports, for all six points, three run by each rank.
    EXPECT_NE(m.out.find("6 points (6 run, 0 resumed)"), std::string::npos) << m.out;
    EXPECT_EQ(m.out.find("sweep of", m.out.find("sweep of") + 1), std::string::npos) << m.out;
    for (int i = 0; i < 6; ++i) {
        const std::string name = "00000" + std::to_string(i) + ".json";
        EXPECT_EQ(slurp(mpi / "points" / name), slurp(single / "points" / name)) << name;
    }
    // Run again: every point is read back, none recomputed, same table.
    const Result again = run(kMpirun, kSweep + " --mpi --out " + mpi.string());
    ASSERT_EQ(again.code, 0) << again.err;
    EXPECT_NE(again.out.find("6 points (0 run, 6 resumed)"), std::string::npos) << again.out;
    EXPECT_EQ(slurp(mpi / "sweep.csv"), table);
}

TEST_F(MpiSweepTest, FailingRanksAreReportedByRankZeroAndNothingHangs) {
    if (kMpiexec.empty()) GTEST_SKIP() << "built without MPI";
    std::ofstream(m_dir / "a_file") << "not a directory\n";  // no rank can write its points under it
    const Result r = run(kMpirun, kSweep + " --mpi --out " + (m_dir / "a_file").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("milldyn: output failed: rank 0 of 2 failed: cannot create output directory"),
              std::string::npos) << r.err;
}

TEST_F(MpiSweepTest, MpiWithShardIsABadCommandLine) {
    if (kMpiexec.empty()) GTEST_SKIP() << "built without MPI";
    const Result r = run("", kSweep + " --mpi --shard 0/2 --out " + (m_dir / "x").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--mpi gives each rank its slice: leave out --shard"), std::string::npos) << r.err;
}

TEST_F(MpiSweepTest, RankOfSeveralWithoutMpiFlagIsRefusedBeforeRunningAnything) {
    // What mpirun -np 2 sets for each rank; no MPI needed to check the refusal.
    const Result r = run("OMPI_COMM_WORLD_SIZE=2 ", kSweep + " --out " + (m_dir / "x").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("started as one of several MPI ranks: add --mpi"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(m_dir / "x" / "sweep.csv"));
}

}  // namespace
