// Every write is checked: with a file of the run replaced by a symbolic
// link to /dev/full (a full disk), psmpm names the file and exits with
// write_failed (8), never 0; summary.json and statistics.txt are written
// atomically (a temporary file, then rename), so a failed write leaves
// the previous version whole.
#include "../app_tests.h"

#include <filesystem>

namespace fs = std::filesystem;

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<std::string>   base = {"--set",
                                           "Time/End time=0.0005",
                                           "--set",
                                           "Output/Interval=10",
                                           "--set",
                                           "Output directory=full"};
  struct Case
  {
    std::string name;
    std::string link; // the file that goes to /dev/full
  };
  const std::vector<Case> cases = {
    {"particle output at step 0", "particles-00000.000.vtu"},
    {"grid output at step 20", "grid-00020.000.vtu"},
    {"statistics", "statistics.txt.tmp"},
    {"parameters.prm", "parameters.prm.tmp"},
    {"summary.json", "summary.json.tmp"}};
  for (const auto &c : cases)
    {
      fs::remove_all("full");
      fs::create_directories("full");
      fs::create_symlink("/dev/full", "full/" + c.link);
      std::string       screen, message;
      const int         code = run_app(base, screen, message);
      const std::string file =
        c.link.substr(0,
                      c.link.size() -
                        (c.link.rfind(".tmp") == c.link.size() - 4 ? 4 : 0));
      const bool named =
        message.find("cannot write full/" + file) != std::string::npos &&
        message.find("No space left on device") != std::string::npos;
      out << c.name << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::write_failed);
      PSMPM_CHECK(out, named);
      if (!named)
        out << "  message: " << message;
      // The lock is released; the failed temporary file is gone, so the
      // summary of the failure itself could be written.
      PSMPM_CHECK(out, !fs::exists("full/psmpm.lock"));
      PSMPM_CHECK(out, !fs::exists("full/" + c.link));
      PSMPM_CHECK(out,
                  read_file("full/summary.json")
                      .find("\"status\": \"failed\"") != std::string::npos);
    }
}
