// On two ranks: an output directory that cannot be created (its parent is
// a file) is reported by rank 0 and every rank exits with bad_input (no
// rank waits for the others); a file that only rank 1 cannot write ends
// the run on every rank with write_failed, the message naming the file.
#include "../app_tests.h"

#include <filesystem>

namespace fs = std::filesystem;

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();
  if (root)
    {
      std::ofstream("a_file") << "not a directory\n";
      fs::remove_all("full");
      fs::create_directories("full");
      fs::create_symlink("/dev/full", "full/particles-00000.001.vtu");
    }
  MPI_Barrier(MPI_COMM_WORLD);

  std::string screen, message;
  int         code = run_app(
    {"--set", "Output directory=a_file/sub", "--set", "Time/End time=0.0001"},
    screen,
    message);
  out << "output directory inside a file: exit codes "
      << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  PSMPM_CHECK(out,
              Utilities::MPI::max(code, MPI_COMM_WORLD) == 2 &&
                Utilities::MPI::min(code, MPI_COMM_WORLD) == 2);
  PSMPM_CHECK(out, message.find("a_file/sub") != std::string::npos);

  code =
    run_app({"--set", "Output directory=full", "--set", "Time/End time=0.0001"},
            screen,
            message);
  out << "rank 1 cannot write: exit codes "
      << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  PSMPM_CHECK(out,
              Utilities::MPI::max(code, MPI_COMM_WORLD) == 8 &&
                Utilities::MPI::min(code, MPI_COMM_WORLD) == 8);
  PSMPM_CHECK(out,
              message.find("full/particles-00000.001.vtu") !=
                std::string::npos);
}
