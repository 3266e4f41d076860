// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Transfer/Scheme = otm moves the grid with the material. In
// prm/otm_tangling.prm the two halves of a soft block collide, cells of
// the moving grid turn inside out, and the run stops with status
// "unstable", exit code 9 and a reason that names the cell; the output
// written before stays complete. In 1D a bar compressed faster than its
// cells are long stops the same way, and with the automatic step (which
// shrinks with the cell) once the cell has collapsed to round-off. A
// basis other than P1 is bad input naming the entries, and so is a mass
// strategy computed on the shape of the initial cells (ghost penalty);
// the strategies that read only the cells' measure, or no geometry, are
// accepted.
#include "../app_tests.h"

#include <filesystem>

namespace
{
  void
  expect_inverted(std::ofstream                  &out,
                  const std::string              &prm,
                  const std::vector<std::string> &sets)
  {
    std::vector<std::string> args = {std::string(PSMPM_SOURCE_DIR) + "/" + prm,
                                     "--set",
                                     "Output directory=run",
                                     "--set",
                                     "Output/Test output=true"};
    for (const auto &s : sets)
      args.insert(args.end(), {"--set", s});
    std::filesystem::remove_all("run");
    std::string       screen, errors;
    const int         code    = run_app(args, screen, errors);
    const std::string summary = read_file("run/summary.json");
    out << prm << ": exit code " << code << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::unstable_inverted_cell);
    PSMPM_CHECK(out,
                summary.find("\"status\": \"unstable\"") != std::string::npos);
    // "otm: cell <n> of the moving grid inverted (signed area ..."
    const auto at     = summary.find("\"reason\": \"otm: cell ");
    const bool reason = at != std::string::npos;
    PSMPM_CHECK(out, reason);
    if (reason)
      {
        const std::string r = summary.substr(at + 11);
        out << "reason: " << r.substr(0, r.find(" (signed")) << std::endl;
      }
    const auto step = summary.find("\"failed_step\": ");
    if (step != std::string::npos)
      out << "failed step: "
          << summary.substr(step + 15,
                            summary.find_first_of(",\n", step) - step - 15)
          << std::endl;
    PSMPM_CHECK(out,
                read_file("run/particles.pvd").find("</VTKFile>") !=
                  std::string::npos);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");

  expect_inverted(out, "prm/otm_tangling.prm", {});
  // 1D: v = -10 x^2 on [0, 1], fixed at the left, squeezes the last
  // cell (the fastest closing one) shut at t ~ 0.05 s.
  expect_inverted(out,
                  "prm/otm_bar_1d.prm",
                  {"Initial conditions/Velocity=-10*x*x",
                   "Boundary conditions/Fixed x=left",
                   "Reference solution/Type=none",
                   "Time/End time=0.2",
                   "Time/Time step=1e-3",
                   "Material/Young's modulus=1"});

  // The same bar with the automatic step: the step follows the closing
  // cell's length down (otm_time_step_01), so the cell never inverts;
  // it is stopped as collapsed once its length is round-off, instead of
  // being approached in ever smaller steps.
  expect_inverted(out,
                  "prm/otm_bar_1d.prm",
                  {"Initial conditions/Velocity=-10*x*x",
                   "Boundary conditions/Fixed x=left",
                   "Reference solution/Type=none",
                   "Time/End time=0.2",
                   "Time/Time step=0",
                   "Material/Young's modulus=1"});

  // Powell-Sabin with otm is rejected before the run.
  std::filesystem::remove_all("run");
  std::string screen, errors;
  const int   code =
    run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/otm_tangling.prm",
             "--set",
             "Output directory=run",
             "--set",
             "Basis/Type=powell-sabin"},
            screen,
            errors);
  out << "powell-sabin: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out,
              errors.find("Transfer/Scheme = otm needs Basis/Type = linear") !=
                std::string::npos);

  // Mass strategies: checked in setup (--validate runs it, writes
  // nothing).
  for (const std::string type : {"ghost penalty",
                                 "consistent",
                                 "lumped",
                                 "partially lumped",
                                 "blended lumping",
                                 "fictitious mass",
                                 "extrapolate"})
    {
      const int c =
        run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/otm_tangling.prm",
                 "--set",
                 "Output directory=run",
                 "--set",
                 "Mass matrix/Type=" + type,
                 "--validate"},
                screen,
                errors);
      out << type << ": exit code " << c << std::endl;
      if (type == "ghost penalty")
        {
          PSMPM_CHECK(out, c == psmpm::App::bad_input);
          PSMPM_CHECK(out,
                      errors.find("Mass matrix/Type = ghost penalty with "
                                  "Transfer/Scheme = otm is not supported") !=
                        std::string::npos);
          PSMPM_CHECK(out,
                      errors.find("prm/otm_tangling.prm") != std::string::npos);
        }
      else
        PSMPM_CHECK(out, c == psmpm::App::success);
    }
}
