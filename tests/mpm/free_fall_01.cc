// Free fall without boundary conditions: every particle accelerates with
// g exactly (no stress builds up), and the displacement follows the
// semi-implicit Euler sum u_n = g dt^2 n (n + 1) / 2. Particles cross many
// cells, and must stay inside their triangles. Lumped mass: with a
// consistent mass matrix, cells that the falling body enters hold one or
// two particles and the matrix becomes singular (thesis chapter 5); that
// case is the subject of the stabilisation work, not of this test.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string basis_mass : {"lumped"})
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(solver,
                {"Geometry/Length=4",
                 "Geometry/Height=10",
                 "Mesh/Blocks x=4",
                 "Mesh/Blocks y=10",
                 "Particles/Per block x=3",
                 "Particles/Per block y=3",
                 "Particles/Region=1, 6, 3, 9.5",
                 "Mass matrix/Type=" + basis_mass,
                 "Boundary conditions/Fixed x=",
                 "Boundary conditions/Fixed y=",
                 "Reference solution/Type=none",
                 "Initial conditions/Velocity=0; 0",
                 "Body force/Gravity=0, -9.81",
                 "Material/Young's modulus=1e4"});
      const double       dt = 1e-3;
      const unsigned int n  = 800;
      for (unsigned int i = 0; i < n; ++i)
        solver.do_time_step(dt);
      const auto &particles = solver.get_particles();
      double      dv = 0, du = 0, ds = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          dv = std::max(
            dv,
            (particles.velocity[p] - Tensor<1, 2>({0, -9.81 * n * dt})).norm());
          du = std::max(du,
                        (particles.displacement[p] -
                         Tensor<1, 2>({0, -9.81 * dt * dt * n * (n + 1) / 2}))
                          .norm());
          ds = std::max(ds, particles.stress[p].norm());
        }
      out << basis_mass << ": fell " << particles.displacement[0][1]
          << std::endl;
      PSMPM_CHECK(out, dv < 1e-9);
      PSMPM_CHECK(out, du < 1e-9);
      PSMPM_CHECK(out, ds < 1e-9);
      const auto check = check_particles_in_cells(solver);
      PSMPM_CHECK(out, check.first <= 1e-12);
      PSMPM_CHECK(out, check.second);
    }
}
