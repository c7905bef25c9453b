#pragma once
// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun), read from the
// variables launchers set, before (and without) initialising MPI: a candela built without MPI
// uses it to refuse to run as N copies that would each render the whole image.
#include <optional>

namespace candela {

// The job's number of processes as the launcher's environment says (Open MPI:
// OMPI_COMM_WORLD_SIZE; MPICH and Slurm's PMI: PMI_SIZE; PMIx: PMIX_SIZE is not set by every
// launcher, so a PMIx rank counts as launched with size unknown = 0); nullopt when not launched
// by one.
std::optional<int> mpi_launch_size();

}  // namespace candela
