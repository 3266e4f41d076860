// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// prm/ring_impact.prm, first 0.4 s, both bases with the defaults: a soft
// neo-Hookean ring read from a Gmsh geometry file (Body 1, Materials/
// Material 1) falls onto a stiff linear elastic block (Body 2, subsection
// Material, twice the density). The run completes with the particles'
// material ids {0, 1, 0} by body and both models' state columns, the mass
// is exact, the horizontal momentum stays zero, the total energy never
// rises more than 3 % above its start, the ring is stopped by the block
// (its centre comes down to below 0.45 m, where it would touch the block
// undeformed) and bounces (its centre rises again by more than 0.05 m),
// and the block stays on the floor (centre within 0.01 m of 0.125 m).
#include "../mpm_tests.h"

#include <algorithm>
#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      auto        solver = make_scene_solver("ring_impact.prm",
                                      {"Basis/Type=" + basis,
                                              "Bodies/Body 1/File=" +
                                                std::string(PSMPM_SOURCE_DIR) +
                                                "/prm/geometry/ring.msh",
                                              "Time/End time=0.4",
                                              "Output/Interval=0"});
      const auto &p      = solver->get_particles();
      double      m0     = 0;
      for (const double m : p.mass)
        m0 += m;
      const std::string dir = "run-" + basis;
      std::filesystem::create_directories(dir);
      const auto status = solver->run(dir);
      out << basis << ": " << psmpm::Simulator::status_name(status) << ", "
          << p.size() << " particles, state columns " << p.n_state()
          << std::endl;
      PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);
      PSMPM_CHECK(out, (p.body_material == std::vector<unsigned int>{0, 1, 0}));
      PSMPM_CHECK(out, p.n_state() == 8);
      double m = 0;
      for (const double mi : p.mass)
        m += mi;
      PSMPM_CHECK(out, m == m0);

      const StatisticsTable s(dir);
      const auto            y_ring  = s.column("body1_y");
      const auto            y_block = s.column("body2_y");
      const auto            px      = s.column("momentum_x");
      const auto            energy  = s.column("total_energy");
      PSMPM_CHECK(out, !y_ring.empty() && y_ring.size() == y_block.size());
      const auto   lowest = std::min_element(y_ring.begin(), y_ring.end());
      const double rise   = *std::max_element(lowest, y_ring.end()) - *lowest;
      double       px_max = 0, block_shift = 0, e_max = 0;
      for (std::size_t k = 0; k < px.size(); ++k)
        {
          px_max      = std::max(px_max, std::abs(px[k]));
          block_shift = std::max(block_shift, std::abs(y_block[k] - 0.125));
          e_max       = std::max(e_max, energy[k] / energy[0]);
        }
      out << "  ring centre: lowest " << (*lowest < 0.45 ? "< 0.45" : ">= 0.45")
          << ", rise after it " << (rise > 0.05 ? "> 0.05" : "<= 0.05")
          << std::endl;
      PSMPM_CHECK(out, *lowest < 0.45);
      PSMPM_CHECK(out, rise > 0.05);
      PSMPM_CHECK(out, block_shift < 0.01);
      // Ring mass ~94 kg at 1 m/s: 1e-8 of its momentum.
      PSMPM_CHECK(out, px_max < 1e-6);
      PSMPM_CHECK(out, e_max <= 1.03);
    }
}
