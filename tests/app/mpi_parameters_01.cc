// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// On two ranks, the ranks must read the same scene: rank 1 given another
// --set (as an MPMD launch can) ends both ranks with bad input, the
// message naming the entry; a parameter file that only rank 1 cannot
// read ends both ranks with bad input naming the rank and the file, never
// a wait; the same scene on both ranks runs.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();
  if (root)
    {
      std::filesystem::remove_all("agree");
      std::ofstream("scene.prm") << "subsection Time\n"
                                    "  set End time = 0.0001\n"
                                    "end\n";
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const std::vector<std::string> base = {"--set", "Output directory=agree"};

  const auto exit_codes = [&](const std::string &name, const int code) {
    const int low  = Utilities::MPI::min(code, MPI_COMM_WORLD);
    const int high = Utilities::MPI::max(code, MPI_COMM_WORLD);
    out << name << ": exit codes " << low << " to " << high << std::endl;
    return std::make_pair(low, high);
  };

  std::string screen, message;
  auto        args = base;
  args.insert(args.begin(), "scene.prm");
  if (!root)
    args.insert(args.end(), {"--set", "Mesh/Blocks x=8"});
  auto codes =
    exit_codes("another --set on rank 1", run_app(args, screen, message));
  PSMPM_CHECK(out,
              codes.first == psmpm::App::bad_input &&
                codes.second == psmpm::App::bad_input);
  if (root)
    {
      PSMPM_CHECK(out,
                  message.find("the parameters differ between ranks") !=
                      std::string::npos &&
                    message.find("Mesh/Blocks x: '4' -> '8'") !=
                      std::string::npos);
      out << "  " << message;
    }
  PSMPM_CHECK(out, !std::filesystem::exists("agree"));

  args = base;
  args.insert(args.begin(), root ? "scene.prm" : "no_such_scene.prm");
  codes = exit_codes("parameter file missing on rank 1",
                     run_app(args, screen, message));
  PSMPM_CHECK(out,
              codes.first == psmpm::App::bad_input &&
                codes.second == psmpm::App::bad_input);
  if (root)
    PSMPM_CHECK(out,
                message.find("on rank 1") != std::string::npos &&
                  message.find("no_such_scene.prm") != std::string::npos);
  PSMPM_CHECK(out, !std::filesystem::exists("agree"));

  args = base;
  args.insert(args.begin(), "scene.prm");
  codes = exit_codes("the same scene", run_app(args, screen, message));
  PSMPM_CHECK(out, codes.first == 0 && codes.second == 0);
}
