// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/mpi_session.h>

#include <cstdlib>

namespace psmpm
{
  bool
  launched_by_process_manager()
  {
    // Open MPI's mpirun, PMIx launchers (Open MPI 5, srun --mpi=pmix),
    // PMI-1/2 launchers (MPICH's hydra, srun --mpi=pmi2) and Slurm's
    // srun in general.
    for (const char *name : {"OMPI_COMM_WORLD_SIZE",
                             "OMPI_COMM_WORLD_RANK",
                             "PMIX_RANK",
                             "PMI_RANK",
                             "PMI_SIZE",
                             "PMI_FD",
                             "SLURM_PROCID"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  namespace internal
  {
    SingletonStartUp::SingletonStartUp()
    {
      if (launched_by_process_manager())
        return;
      // The last argument 0: an explicit setting in the environment wins.
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
    }
  } // namespace internal

  MPISession::MPISession(int &argc, char **&argv)
    : SingletonStartUp()
    , MPI_InitFinalize(argc, argv, 1)
  {
  }
} // namespace psmpm
