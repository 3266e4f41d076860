// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Disk full at each kind of write (PSMPM_FAIL_WRITE_AT with
// PSMPM_FAIL_WRITE_MATCH): statistics.txt, a particle VTU, an HDF5
// particle file, a checkpoint and summary.json. Every rank exits with
// write_failed (8), none waits for another; the message names the file;
// the last complete checkpoint is kept and the run resumes from it to its
// end. Run on one rank and on two (mpirun=2).
#include <psmpm/simulator/checkpoint.h>

#include "../app_tests.h"

#include <cstdlib>
#include <filesystem>

namespace
{
  struct Case
  {
    std::string name;
    /// PSMPM_FAIL_WRITE_MATCH and PSMPM_FAIL_WRITE_AT.
    std::string match;
    std::string at;
    /// The file the message must name.
    std::string              file;
    std::vector<std::string> settings;
  };

  /// The embedded default scene for 50 steps, output and checkpoints
  /// every 10 steps, in directory @p dir.
  std::vector<std::string>
  scene(const std::string &dir, const std::string &end_time)
  {
    return {"--set",
            "Output directory=" + dir,
            "--set",
            "Time/End time=" + end_time,
            "--set",
            "Output/Interval=10",
            "--set",
            "Checkpoint/Interval=10"};
  }

  void
  check(std::ostream &out, const Case &c)
  {
    const std::string dir = "fail_" + c.name;
    if (is_root_rank())
      std::filesystem::remove_all(dir);
    MPI_Barrier(MPI_COMM_WORLD);

    setenv("PSMPM_FAIL_WRITE_MATCH", c.match.c_str(), 1);
    setenv("PSMPM_FAIL_WRITE_AT", c.at.c_str(), 1);
    auto args = scene(dir, "0.0005");
    args.insert(args.end(), c.settings.begin(), c.settings.end());
    std::string screen, message;
    int         code = run_app(args, screen, message);
    unsetenv("PSMPM_FAIL_WRITE_MATCH");
    unsetenv("PSMPM_FAIL_WRITE_AT");
    out << c.name << ": exit codes "
        << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
        << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
    PSMPM_CHECK(out,
                Utilities::MPI::min(code, MPI_COMM_WORLD) ==
                    psmpm::App::write_failed &&
                  Utilities::MPI::max(code, MPI_COMM_WORLD) ==
                    psmpm::App::write_failed);
    if (is_root_rank())
      {
        const bool names =
          message.find(dir + "/" + c.file) != std::string::npos;
        PSMPM_CHECK(out, names);
        if (!names)
          out << message;
        const auto kept = psmpm::Simulator::Checkpoint::list(dir);
        out << c.name << ": newest checkpoint kept: "
            << (kept.empty() ?
                  "none" :
                  std::filesystem::path(kept[0]).filename().string())
            << std::endl;
      }

    // The run goes on from the newest checkpoint kept.
    args = scene(dir, "0.0006");
    args.insert(args.end(), c.settings.begin(), c.settings.end());
    args.push_back("--resume");
    code = run_app(args, screen, message);
    out << c.name << ": resumed: exit codes "
        << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
        << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
    if (is_root_rank())
      {
        if (code != psmpm::App::success)
          out << message;
        PSMPM_CHECK(
          out,
          read_file(dir + "/summary.json").find("\"status\": \"completed\"") !=
            std::string::npos);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();

  const std::vector<std::string> hdf5 = {"--set",
                                         "Output/Particle format=hdf5"};
  check(out, {"statistics", "statistics.txt", "3", "statistics.txt", {}});
  check(out,
        {"vtu", "particles-00020.000.vtu", "1", "particles-00020.000.vtu", {}});
  check(out, {"hdf5", "particles-00020.h5", "1", "particles-00020.h5", hdf5});
  check(
    out,
    {"checkpoint", "checkpoint-00000030", "1", "checkpoint-00000030.h5", {}});
  check(out, {"summary", "summary.json", "1", "summary.json", {}});
}
