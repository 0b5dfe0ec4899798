#pragma once
// Joining the MPI job a study runs in: the library shockmap_mpi (engine/mpi_workers.cpp with MPI,
// engine/local_only_workers.cpp without), the only one that links MPI; installed as the
// component mpi of the CMake package, so that programs using the other libraries need no MPI.

#include <memory>

#include "engine/remote_workers.h"

namespace shockmap {

// The workers of this process's MPI job when it was started by an MPI launcher (mpirun, srun)
// with more than one rank, else null (a local run). `threads` is the threads per worker rank,
// `rank_timeout_s` the silence after which rank 0 counts a worker rank as lost.
// Ends the job on every rank when the returned object is destroyed (rank 0 first tells the
// workers to quit; a worker rank finalizes only when rank 0 then says so). A job that lost a
// rank cannot end normally (MPI_Finalize would wait for it): once the live workers have quit (a
// worker rank silent for the rank timeout while rank 0 waits for its goodbye is lost too),
// rank 0 ends it with MPI_Abort, exit code 1 or the one set by SetExitCode, stdout and stderr
// flushed, while no rank waits in MPI_Finalize (Open MPI 4.1's mpirun may deadlock or crash
// after aborting such ranks); by then the caller has closed the database. Throws InputError
// when launched on several ranks by a build without MPI.
std::unique_ptr<RemoteWorkers> JoinMpiJob(int threads, double rank_timeout_s);

}  // namespace shockmap
