// On two ranks, a stop request that only rank 1 receives (SIGTERM to its
// process) stops both ranks after the same step: status "interrupted",
// exit code 143 on both, the lock released.
#include "../app_tests.h"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>
#include <unistd.h>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();
  if (root)
    std::filesystem::remove_all("stop");
  MPI_Barrier(MPI_COMM_WORLD);

  // Rank 1 signals itself once the time loop runs (a progress line is in
  // the log); no MPI in this thread.
  std::thread sender;
  if (!root)
    sender = std::thread([] {
      for (unsigned int i = 0; i < 1200; ++i)
        {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
          if (read_file("stop/log.txt").find("ETA") != std::string::npos)
            {
              kill(getpid(), SIGTERM);
              return;
            }
        }
    });
  std::string screen, message;
  const int   code = run_app({"--set",
                              "Output directory=stop",
                              "--set",
                              "Time/End time=1000",
                              "--set",
                              "Limits/Allow large runs=true",
                              "--set",
                              "Output/Progress interval=0.2"},
                           screen,
                           message);
  if (sender.joinable())
    sender.join();
  out << "exit codes " << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  if (root)
    {
      const std::string summary = read_file("stop/summary.json");
      PSMPM_CHECK(out,
                  summary.find("\"status\": \"interrupted\"") !=
                    std::string::npos);
      PSMPM_CHECK(out, summary.find("\"signal\": 15") != std::string::npos);
      PSMPM_CHECK(out, !std::filesystem::exists("stop/psmpm.lock"));
    }
}
