// The vibrating bar on 8 blocks gives the same errors and energies on one
// and on two MPI ranks (up to the solver tolerance): the .output and
// .mpirun=2.output files are identical.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const std::string type : {"consistent", "lumped"})
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(solver,
                {"Mesh/Blocks x=8",
                 "Mass matrix/Type=" + type,
                 "Mass matrix/Solver tolerance=1e-14",
                 "Particles/Per block x=8",
                 "Particles/Per block y=6",
                 "Initial conditions/Function constants=v0=1, L=25",
                 "Reference solution/Velocity amplitude=1"});
      for (unsigned int n = 0; n < 300; ++n)
        solver.do_time_step(2e-3);
      const auto e  = solver.compute_errors();
      const auto en = solver.compute_energies();
      const auto n_p =
        Utilities::MPI::sum(solver.get_particles().size(), MPI_COMM_WORLD);
      out << std::setprecision(7) << type << ": particles " << n_p
          << "\n  displacement_L2 " << e.displacement << "\n  velocity_L2 "
          << e.velocity << "\n  stress_L2 " << e.stress << "\n  kinetic "
          << en.kinetic << "\n  strain " << en.strain << std::endl;
    }
}
