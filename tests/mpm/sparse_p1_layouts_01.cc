// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// P1 with the automatic mass matrix (ghost penalty) on free bodies with
// 2 x 2 particles per block. On a criss-cross mesh those particles sit on
// the cells' diagonals: a cell is filled by volume but its particles leave
// a linear field unseen. Counted as filled, such cells got no penalty and
// the rotating block, the two disks and the neo-Hookean spreading block
// blew up within 4 steps. With the fill capped by the particles' sampling
// (doc/stability.md, "Sampling of P1 cells") each run completes, and the
// penalty, zero on affine fields, keeps the rotating block's angular
// momentum to round-off.
#include "../app_tests.h"

#include <filesystem>

namespace
{
  /// The number after "key": in summary.json (NaN if absent).
  double
  summary_value(const std::string &summary, const std::string &key)
  {
    const auto at = summary.find("\"" + key + "\":");
    if (at == std::string::npos)
      return std::numeric_limits<double>::quiet_NaN();
    return std::stod(summary.substr(at + key.size() + 3));
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  struct Scene
  {
    std::string name, end_time;
  };
  for (const Scene &scene : {Scene{"rotating_block", "0.5"},
                             Scene{"two_disks", "0.5"},
                             Scene{"spreading_block_neo_hookean", "1"}})
    {
      std::vector<std::string> args = {std::string(PSMPM_SOURCE_DIR) + "/prm/" +
                                       scene.name + ".prm"};
      for (const char *s : {"Output directory=run",
                            "Output/Interval=0",
                            "Basis/Type=linear",
                            "Mass matrix/Type=automatic",
                            "Transfer/Scheme=automatic",
                            "Particles/Per block x=2",
                            "Particles/Per block y=2"})
        args.insert(args.end(), {"--set", s});
      args.insert(args.end(), {"--set", "Time/End time=" + scene.end_time});
      std::filesystem::remove_all("run");
      std::string       screen, errors;
      const int         code    = run_app(args, screen, errors);
      const std::string summary = read_file("run/summary.json");
      out << scene.name << ", 2 x 2 particles per block:" << std::endl;
      PSMPM_CHECK(out, code == 0);
      PSMPM_CHECK(out,
                  summary.find("\"status\": \"completed\"") !=
                    std::string::npos);
      PSMPM_CHECK(out,
                  summary.find("\"mass_matrix\": \"ghost penalty\"") !=
                    std::string::npos);
      if (scene.name == "rotating_block")
        PSMPM_CHECK(
          out,
          std::abs(summary_value(summary, "angular_momentum_relative_change")) <
            1e-10);
    }
}
