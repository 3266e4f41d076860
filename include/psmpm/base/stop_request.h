// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_stop_request_h
#define psmpm_base_stop_request_h

#include <mpi.h>

namespace psmpm
{
  /**
   * SIGINT, SIGTERM and SIGUSR1 (which mpirun forwards to every rank,
   * while it kills them on SIGINT and SIGTERM) ask a run to stop: while a
   * StopRequest exists, the
   * handlers only record the signal; the time loop asks for it after each
   * step (all ranks agree with one reduction), finishes the step, writes
   * its output and summary.json ("status": "interrupted") and psmpm exits
   * with 128 + the signal number. A second signal ends the process at
   * once. The destructor restores the previous handlers.
   */
  class StopRequest
  {
  public:
    StopRequest();
    ~StopRequest();
    StopRequest(const StopRequest &) = delete;
    StopRequest &
    operator=(const StopRequest &) = delete;

    /// The signal this process received (0: none).
    static int
    received();

    /// The largest signal number any rank of @p comm received (0: none);
    /// collective.
    static int
    agreed(MPI_Comm comm);
  };
} // namespace psmpm

#endif
