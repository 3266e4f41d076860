// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A velocity of t that is fine when the scene is read but not finite a
// few steps in stops the run as unstable (the exit code of non_finite),
// with a reason that names the entry, the boundary or body and the time,
// before the value reaches the grid: a prescribed boundary velocity
// (prm/biaxial_compression.prm) and a driven body's velocity
// (prm/strip_footing_body.prm), both sqrt(T - t) with T within the fourth
// of the fixed steps of 1e-4 s. summary.json records the reason.
#include "../app_tests.h"

#include <filesystem>

namespace
{
  void
  check(std::ofstream                  &out,
        const std::string              &name,
        const std::vector<std::string> &args,
        const std::vector<std::string> &must_mention)
  {
    std::filesystem::remove_all("run");
    std::string screen, errors;
    const int   code    = run_app(args, screen, errors);
    const auto  summary = read_file("run/summary.json");
    out << name << ": exit code " << code << std::endl;
    const int non_finite =
      psmpm::Simulator::failure_info(psmpm::Simulator::Failure::non_finite)
        .exit_code;
    PSMPM_CHECK(out, code == non_finite);
    PSMPM_CHECK(out, summary.find("\"unstable\"") != std::string::npos);
    for (const auto &m : must_mention)
      {
        const bool found = summary.find(m) != std::string::npos;
        out << "  names '" << m << "': " << (found ? "yes" : "no") << std::endl;
        PSMPM_CHECK(out, found);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string scenes = std::string(PSMPM_SOURCE_DIR) + "/prm/";
  const std::vector<std::string> common = {"--set",
                                           "Output directory=run",
                                           "--set",
                                           "Time/Time step=1e-4",
                                           "--set",
                                           "Time/End time=1e-3",
                                           "--set",
                                           "Output/Interval=0"};
  auto args = [&](const std::string &scene, const std::string &set) {
    std::vector<std::string> a = {scenes + scene, "--set", set};
    a.insert(a.end(), common.begin(), common.end());
    return a;
  };
  check(out,
        "prescribed velocity",
        args("biaxial_compression.prm",
             "Boundary conditions/Prescribed velocity=top: free; "
             "-0.05*sqrt(3.5e-4-t), right: 0; free"),
        {"Boundary conditions/Prescribed velocity",
         "'top'",
         "not finite at t ="});
  check(out,
        "driven body velocity",
        args("strip_footing_body.prm",
             "Bodies/Body 2/Velocity=0; -0.1*sqrt(3.25e-4-t)"),
        {"Bodies/Body 2/Velocity", "not finite at t ="});
}
