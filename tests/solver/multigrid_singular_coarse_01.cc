// Mass matrix/Preconditioner = pmg with a particle layout that leaves the
// P1 coarse level singular (one particle per block, two in the whole
// Powell-Sabin bar): UMFPACK's failure to factor the coarse matrix used to
// escape as an internal error (exit 1, no summary.json). Now a run whose
// singular component has a right-hand side stops as unstable with the
// solver's exit code and a reason naming the preconditioner, and a run
// whose singular component is never solved (zero right-hand side) goes on
// to whatever the layout does next: never an internal error.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string prm =
    std::string(PSMPM_SOURCE_DIR) + "/prm/vibrating_bar_small_ps.prm";
  const std::vector<std::string> common = {prm,
                                           "--set",
                                           "Output directory=run",
                                           "--set",
                                           "Output/Test output=true",
                                           "--set",
                                           "Time/End time=0.002",
                                           "--set",
                                           "Mass matrix/Type=consistent",
                                           "--set",
                                           "Mass matrix/Preconditioner=pmg",
                                           "--set",
                                           "Mass matrix/Direct solver size=0",
                                           "--set",
                                           "Particles/Per block x=1",
                                           "--set",
                                           "Particles/Per block y=1"};

  // y fixed on every side, x free, a velocity in y: the y component's
  // coarse matrix is singular and its right-hand side is not zero.
  {
    auto args = common;
    args.insert(args.end(),
                {"--set",
                 "Boundary conditions/Fixed x=",
                 "--set",
                 "Initial conditions/Velocity=v0*sin(pi*x/L); v0*cos(pi*x/L)"});
    std::filesystem::remove_all("run");
    std::string       screen, errors;
    const int         code    = run_app(args, screen, errors);
    const std::string summary = read_file("run/summary.json");
    out << "singular component solved: exit code " << code << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::unstable_solver);
    PSMPM_CHECK(out,
                summary.find("\"status\": \"unstable\"") != std::string::npos);
    PSMPM_CHECK(out,
                summary.find("p-multigrid preconditioner is singular") !=
                  std::string::npos);
    PSMPM_CHECK(out, errors.find("internal error") == std::string::npos);
  }

  // The scene's own boundaries: the singular component (y, fixed on every
  // side) has no right-hand side, so no V-cycle is needed for it.
  {
    std::filesystem::remove_all("run");
    std::string       screen, errors;
    const int         code    = run_app(common, screen, errors);
    const std::string summary = read_file("run/summary.json");
    out << "singular component not solved: internal error "
        << (code == psmpm::App::internal ? "yes" : "no") << std::endl;
    PSMPM_CHECK(out, code != psmpm::App::internal);
    PSMPM_CHECK(out, summary.find("\"status\": ") != std::string::npos);
    PSMPM_CHECK(out, errors.find("internal error") == std::string::npos);
  }
}
