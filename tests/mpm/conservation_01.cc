// A free body (no boundary conditions, no gravity) with a non-uniform
// initial velocity: total mass is conserved exactly, the lumped grid mass
// equals the particle mass, and linear momentum is conserved to round-off
// (consistent mass: to the CG tolerance), for both mass matrix types.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string type : {"lumped", "consistent"})
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(
        solver,
        {"Mesh/Blocks x=6",
         "Mesh/Blocks y=2",
         "Geometry/Height=4",
         "Particles/Per block x=4",
         "Particles/Per block y=4",
         "Mass matrix/Type=" + type,
         "Mass matrix/Solver tolerance=1e-14",
         "Boundary conditions/Fixed x=",
         "Boundary conditions/Fixed y=",
         "Reference solution/Type=none",
         "Initial conditions/Velocity=1 + 0.5*sin(x/3)*y; -0.3*x/25 + 0.2",
         "Material/Poisson's ratio=0.3"});
      const auto e0      = solver.compute_energies();
      double     drift_p = 0, drift_m = 0;
      for (unsigned int n = 0; n < 200; ++n)
        {
          solver.do_time_step(2e-3);
          const auto e = solver.compute_energies();
          drift_p =
            std::max(drift_p,
                     (e.momentum - e0.momentum).norm() / e0.momentum.norm());
          drift_m = std::max(drift_m, std::abs(e.mass - e0.mass));
        }
      const auto e = solver.compute_energies();
      out << type << ": momentum (" << e0.momentum[0] << ", " << e0.momentum[1]
          << ")" << std::endl;
      PSMPM_CHECK(out, drift_m == 0);
      PSMPM_CHECK(out, drift_p < 1e-11);
      // The body moved: strain energy was generated from kinetic energy.
      PSMPM_CHECK(out, e.strain > 1e-6 * e0.kinetic);
    }
}
