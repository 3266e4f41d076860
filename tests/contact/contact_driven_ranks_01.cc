// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A driven body gives the same run on one and on two MPI ranks (the
// .output and .mpirun=2.output files are identical), and a run with one
// resumed from its checkpoint repeats the run in one go bit for bit: the
// strip footing of prm/strip_footing_body.prm (the footing Body 2 driven
// down into the soil) on h = B/4 to t = 0.3 s, linear (musl) and
// Powell-Sabin (apic; with the scene's Transfer/Volumetric strain =
// cell average, whose cell sums stay on the cell's rank and which keeps
// nothing between steps), with Contact/Driven body nodes = particle mass
// and geometry (the nodes' shares are sums over the cells, added up
// over the ranks; the footing's displacement travels in the
// checkpoint). The driven particles are ordinary particles between the
// steps (checkpoints, ranks); their list, their start positions and the
// driven velocities are rebuilt each step, and the accumulated
// driven_work travels in the checkpoint. Printed: the last row's
// energies, contact force, floor reaction, driven work and the
// footing's height (7 digits).
#include "../app_tests.h"
#include "../checkpoint_tests.h"
#include "../mpm_tests.h"

#include <filesystem>
#include <iomanip>
#include <utility>
#include <vector>

namespace
{
  int
  run(const std::string &basis,
      const std::string &nodes,
      const std::string &directory,
      const std::string &end,
      const bool         resume)
  {
    std::vector<std::string> args = {std::string(PSMPM_SOURCE_DIR) +
                                       "/prm/strip_footing_body.prm",
                                     "--set",
                                     "Output directory=" + directory,
                                     "--set",
                                     "Basis/Type=" + basis,
                                     "--set",
                                     std::string("Transfer/Scheme=") +
                                       (basis == "linear" ? "musl" : "apic"),
                                     "--set",
                                     "Mesh/Blocks x=20",
                                     "--set",
                                     "Mesh/Blocks y=12",
                                     "--set",
                                     "Time/End time=" + end,
                                     "--set",
                                     "Contact/Driven body nodes=" + nodes};
    if (resume)
      args.push_back("--resume");
    std::string screen, errors;
    return run_app(args, screen, errors);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const auto &[basis, nodes] :
       std::vector<std::pair<std::string, std::string>>{
         {"linear", "particle mass"},
         {"powell-sabin", "particle mass"},
         {"linear", "geometry"},
         {"powell-sabin", "geometry"}})
    {
      const std::string tag = basis + (nodes == "geometry" ? "-geometry" : ""),
                        whole = "whole-" + tag, split = "split-" + tag;
      if (is_root_rank())
        for (const auto &d : {whole, split})
          std::filesystem::remove_all(d);
      MPI_Barrier(MPI_COMM_WORLD);
      const int code = run(basis, nodes, whole, "0.3", false);
      out << tag << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, run(basis, nodes, split, "0.15", false) == 0);
      PSMPM_CHECK(out, run(basis, nodes, split, "0.3", true) == 0);
      const auto a = statistics_rows(whole + "/statistics.txt"),
                 b = statistics_rows(split + "/statistics.txt");
      PSMPM_CHECK(out, a.size() > 100 && a == b);
      if (!is_root_rank())
        continue;
      const StatisticsTable table(whole);
      for (const char *printed : {"kinetic_energy",
                                  "strain_energy",
                                  "body2_y",
                                  "contact_force_1_2_y",
                                  "reaction_bottom_y",
                                  "driven_work"})
        out << "  " << printed << " " << std::setprecision(7)
            << table.column(printed).back() << std::endl;
      PSMPM_CHECK(out, table.column("contact_force_1_2_y").back() < 0);
    }
}
