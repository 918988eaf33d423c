#pragma once
// The Open MPI mode of `milldyn sweep --mpi`: under `mpirun -np N`, rank r
// runs the deterministic slice r/N of the sweep (the --shard logic, with
// --jobs threads of its own), rank 0 gathers every rank's points and writes
// the one table, byte for byte the table of a single process.
//
// Built when CMake finds MPI (MILLDYN_MPI, ON by default then);
// SweepNoMpi.cpp stands in otherwise and refuses --mpi.

#include "driver/Sweep.h"

#include <cstdlib>
#include <functional>
#include <ostream>

namespace milldyn {

/// Whether this milldyn was built with MPI.
bool mpiAvailable();

/// True when this process was started by an MPI launcher as one of several
/// ranks (Open MPI's mpirun, or a PMI launcher: MPICH/Hydra, Slurm's srun).
inline bool launchedAsMpiRank() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        const char* v = std::getenv(name);
        if (v && std::atoi(v) > 1) return true;
    }
    return false;
}

struct MpiSweepResult {
    int rank = 0, size = 1;
    SweepSummary summary;  ///< the table's (rank 0); this rank's share elsewhere
};

/// Initialises MPI (if not yet), runs this rank's slice of `plan` and, on
/// rank 0, writes the table and the points of every rank into
/// options.outDir. options.shardIndex/shardCount are replaced by rank/size.
/// Every rank takes part in the gather even when its own slice failed, so
/// one failing rank cannot hang the others: rank 0 throws an OutputError
/// naming the rank, the others return normally (were they to exit non-zero,
/// mpirun would kill rank 0 before it reports). Finalises MPI before
/// returning.
MpiSweepResult runSweepMpi(const SweepPlan& plan, SweepOptions options,
                           const std::function<void(std::size_t, std::size_t, std::size_t)>& progress = {});

}  // namespace milldyn
