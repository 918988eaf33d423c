// Stands in for SweepMpi.cpp in a build without MPI (see SweepMpi.h).

#include "driver/SweepMpi.h"

namespace milldyn {

bool mpiAvailable() { return false; }

MpiSweepResult runSweepMpi(const SweepPlan&, SweepOptions, const std::function<void(std::size_t, std::size_t, std::size_t)>&) {
    throw SpecError({"<--mpi>", 1, 1}, "--mpi",
                    "this milldyn was built without MPI (install libopenmpi-dev and reconfigure), "
                    "or use --shard i/N and milldyn merge");
}

}  // namespace milldyn
