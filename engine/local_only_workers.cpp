// JoinMpiJob of a build without MPI (SHOCKMAP_MPI off): every run is local.

#include <cstdlib>
#include <string>

#include "core/input_error.h"
#include "engine/mpi_job.h"

namespace shockmap {

std::unique_ptr<RemoteWorkers> JoinMpiJob(int, double) {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* size = std::getenv(variable);
    if (size != nullptr && std::string(size) != "1") {
      throw InputError(std::string("started on ") + size +
                       " MPI ranks, but this shockmap was built without MPI (SHOCKMAP_MPI=OFF); "
                       "install Open MPI (libopenmpi-dev) and build again, or run it alone");
    }
  }
  return nullptr;
}

}  // namespace shockmap
