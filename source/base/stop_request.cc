// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/stop_request.h>

#include <csignal>

namespace psmpm
{
  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;
    struct sigaction           previous_int, previous_term, previous_usr1;

    extern "C" void
    record_signal(int signal)
    {
      if (received_signal != 0)
        {
          // The second signal: stop now.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received_signal = signal;
    }
  } // namespace

  StopRequest::StopRequest()
  {
    received_signal         = 0;
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
    // mpirun (Open MPI) kills the ranks on SIGINT/SIGTERM but forwards
    // SIGUSR1 to all of them.
    sigaction(SIGUSR1, &action, &previous_usr1);
  }

  StopRequest::~StopRequest()
  {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGUSR1, &previous_usr1, nullptr);
  }

  int
  StopRequest::received()
  {
    return received_signal;
  }

  int
  StopRequest::agreed(MPI_Comm comm)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return received_signal;
    return dealii::Utilities::MPI::max(static_cast<int>(received_signal), comm);
  }
} // namespace psmpm
