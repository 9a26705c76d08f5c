#pragma once
// The reduction seam across MPI ranks (communicator.hpp), over Open MPI: its own library target
// (sqdem_mpi), so that mpi.h reaches only src/distributed/mpi_communicator.cpp. Exact sums are
// reduced limb by limb as 64-bit integers (ExactSum::limbs), which is exact and so independent
// of the order in which MPI combines the ranks.

#include <memory>

#include "sqdem/distributed/communicator.hpp"

namespace sqdem {

/// MPI_COMM_WORLD, after MPI_Init_thread at the first call (MPI_THREAD_FUNNELED: only the main
/// thread calls MPI; OpenMP threads work between the calls); MPI is finalised at exit.
/// Under a launcher (mpirun, srun) the ranks are the launched processes; started alone, a
/// process is a world of one rank.
std::shared_ptr<Communicator> worldCommunicator();

/// The ranks of a launched run: under a launcher (mpirun or srun: OMPI_COMM_WORLD_SIZE,
/// PMIX_RANK or PMI_RANK set) the launched processes (worldCommunicator); started alone, one
/// process by itself, MPI not initialised (the CLI's `sqdem run` and the Python module).
std::shared_ptr<const Communicator> launchedRanks();

}  // namespace sqdem
