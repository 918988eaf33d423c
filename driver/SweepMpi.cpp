// The Open MPI mode of `milldyn sweep` (see SweepMpi.h). The C API: the
// C++ bindings are gone from MPI 3.

#include "driver/SweepMpi.h"

#include "driver/outputs/AtomicFile.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn {
namespace {

/// MPI_Finalize on every way out, so mpirun sees a clean end.
struct MpiSession {
    MpiSession() {
        int initialized = 0;
        MPI_Initialized(&initialized);
        if (!initialized) {
            int provided = 0;
            // Only the main thread calls MPI; the worker threads never do.
            MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        }
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
    }
    ~MpiSession() {
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (!finalized) MPI_Finalize();
    }
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank = 0, size = 1;
};

/// Every rank's bytes on rank 0 (empty elsewhere): sizes first, then the
/// bytes. MPI counts are int: when the total would exceed 2 GiB, rank 0
/// says so to all (every rank then sends nothing, so none is left waiting)
/// and throws.
std::vector<std::string> gatherToRoot(const std::string& mine, const MpiSession& mpi) {
    const int myCount = mine.size() > 0x7fffffffu ? -1 : static_cast<int>(mine.size());
    std::vector<int> counts(mpi.rank == 0 ? mpi.size : 0);
    MPI_Gather(&myCount, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> displs(counts.size());
    long long total = 0;
    int fits = 1;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        displs[r] = static_cast<int>(std::min<long long>(total, 0x7fffffff));
        if (counts[r] < 0) fits = 0;
        total += std::max(0, counts[r]);
    }
    if (total > 0x7fffffff) fits = 0;
    MPI_Bcast(&fits, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (!fits) std::fill(counts.begin(), counts.end(), 0);
    std::string all(fits ? static_cast<std::size_t>(total) : 0, '\0');
    MPI_Gatherv(mine.data(), fits ? myCount : 0, MPI_CHAR, &all[0], counts.data(), displs.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    if (!fits) throw OutputError("the sweep's points exceed 2 GiB, more than one MPI gather can carry");
    std::vector<std::string> parts;
    for (std::size_t r = 0; r < counts.size(); ++r) parts.push_back(all.substr(displs[r], counts[r]));
    return parts;
}

/// A rank's share as one message: "ok RUN RESUMED\n" then the point texts,
/// each ended by '\0'; or "error\n" and the reason.
std::string pack(const SweepPart& part) {
    std::string out = "ok " + std::to_string(part.summary.run) + " " + std::to_string(part.summary.resumed) + "\n";
    for (const auto& p : part.points) out += p + '\0';
    return out;
}

}  // namespace

bool mpiAvailable() { return true; }

MpiSweepResult runSweepMpi(const SweepPlan& plan, SweepOptions options,
                           const std::function<void(std::size_t, std::size_t, std::size_t)>& progress) {
    MpiSession mpi;
    options.shardIndex = static_cast<std::size_t>(mpi.rank);
    options.shardCount = static_cast<std::size_t>(mpi.size);
    MpiSweepResult result;
    result.rank = mpi.rank;
    result.size = mpi.size;

    std::string message;
    SweepPart part;
    try {
        part = runSweepPart(plan, options, progress);
        message = pack(part);
    } catch (const std::exception& e) {
        message = std::string("error\n") + e.what();
    }
    const std::vector<std::string> parts = gatherToRoot(message, mpi);
    if (mpi.rank != 0) {
        // Rank 0 reports this rank's failure: exiting non-zero here would
        // make mpirun kill rank 0 before it could say what went wrong.
        result.summary = part.summary;
        result.summary.total = part.points.size();
        return result;
    }

    std::vector<std::string> points;
    SweepSummary summary;
    for (std::size_t r = 0; r < parts.size(); ++r) {
        const std::string& p = parts[r];
        if (p.rfind("error\n", 0) == 0)
            throw OutputError("rank " + std::to_string(r) + " of " + std::to_string(mpi.size) +
                              " failed: " + p.substr(6));
        const std::size_t header = p.find('\n');
        unsigned long long run = 0, resumed = 0;
        if (header == std::string::npos || std::sscanf(p.c_str(), "ok %llu %llu", &run, &resumed) != 2)
            throw OutputError("rank " + std::to_string(r) + " sent a malformed share");
        summary.run += run;
        summary.resumed += resumed;
        for (std::size_t at = header + 1; at < p.size();) {
            const std::size_t end = p.find('\0', at);
            if (end == std::string::npos) throw OutputError("rank " + std::to_string(r) + " sent a truncated share");
            points.push_back(p.substr(at, end - at));
            at = end + 1;
        }
    }
    // The other ranks' points go into rank 0's directory too, so the
    // directory holds the whole sweep even without a shared file system.
    result.summary = writeSweepTable(options.outDir, points, summary, true);
    return result;
}

}  // namespace milldyn
