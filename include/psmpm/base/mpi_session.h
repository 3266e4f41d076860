// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_mpi_session_h
#define psmpm_base_mpi_session_h

#include <deal.II/base/mpi.h>

namespace psmpm
{
  /**
   * True if a process manager (mpirun, mpiexec, srun) started this
   * process: it left its rank in the environment.
   */
  bool
  launched_by_process_manager();

  namespace internal
  {
    /**
     * Settings that a singleton, a process no process manager started
     * (`psmpm scene.prm`), needs before MPI_Init; constructed before
     * MPI_InitFinalize as MPISession's first base.
     *
     * Open MPI starts a singleton by spawning a helper daemon (orted),
     * there only to serve a later MPI_Comm_spawn, and by opening every
     * network transport it was built with (the PSM component alone probes
     * devices for 0.2 s). MPI_Init took 0.47 s of wall time on this
     * machine, half of the start-up of every run; with the daemon left
     * out (ess_singleton_isolated) and the point-to-point layer that
     * needs no probing (pml ob1) it takes 0.06 s. A singleton never
     * spawns and talks only to itself, so neither setting can change
     * what it computes. Both are set only where the environment does not
     * already set them (an explicit OMPI_MCA_... wins), and never under a
     * process manager, whose configuration is the user's. Other MPI
     * libraries ignore the variables.
     */
    struct SingletonStartUp
    {
      SingletonStartUp();
    };
  } // namespace internal

  /**
   * MPI for a psmpm program: deal.II's MPI_InitFinalize with one thread
   * per process, preceded by internal::SingletonStartUp.
   */
  class MPISession : private internal::SingletonStartUp,
                     public dealii::Utilities::MPI::MPI_InitFinalize
  {
  public:
    MPISession(int &argc, char **&argv);
  };
} // namespace psmpm

#endif
