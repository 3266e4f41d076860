// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Plastic flow gives the same energies, dissipation and front on one and
// on two MPI ranks (the .output and .mpirun=2.output files are
// identical): the vertical cut of prm/vertical_cut.prm at 1.3 H_c (Tresca
// from the geostatic stress, rough base), 0.3 s in fixed steps, with the
// linear basis (lumped, MUSL) and Powell-Sabin (lumped, APIC; also with
// Transfer/Volumetric strain = cell average): the plastic state moves
// between ranks with its particles.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  const double rho = 2000, g = 9.81, H = 1, c_u = rho * g * H / (3.78 * 1.3);
  // Powell-Sabin also with the cell-averaged volumetric strain, whose
  // cell sums stay on the rank that owns the cell.
  for (const std::string basis :
       {"linear", "powell-sabin", "powell-sabin, cell average"})
    {
      const bool average = basis.find("cell average") != std::string::npos;
      auto       solver =
        make_scene_solver("vertical_cut.prm",
                          {"Basis/Type=" + basis.substr(0, basis.find(',')),
                           std::string("Transfer/Volumetric strain=") +
                             (average ? "cell average" : "particle"),
                           "Mesh/Blocks x=24",
                           "Mesh/Blocks y=9",
                           "Material/Cohesion=" + std::to_string(c_u),
                           "Material/Young's modulus=" +
                             std::to_string(750 * c_u),
                           "Output/Interval=0"});
      for (unsigned int n = 0; n < 600; ++n)
        solver->do_time_step(5e-4);
      const auto e = solver->compute_energies();
      const auto n_p =
        Utilities::MPI::sum(solver->get_particles().size(), MPI_COMM_WORLD);
      out << std::setprecision(7) << basis << ": particles " << n_p
          << "\n  kinetic " << e.kinetic << "\n  strain " << e.strain
          << "\n  gravity " << e.gravity << "\n  dissipated " << e.dissipated
          << "\n  momentum " << e.momentum << std::endl;
      PSMPM_CHECK(out, e.dissipated > 1e-3 * std::abs(e.gravity));
    }
}
