// A body that only translates stays unstrained: a block sliding at
// (2, 0.5) m/s without gravity or walls across criss-cross cells, 4 x 4
// particles per block, so that particles cross the diagonals and come to
// lie on (or round-off beyond) a face whose opposite grid point no particle
// gives mass. With P1 that grid point's function still has a gradient at
// the particle; its velocity must then be the particle's own, not the 0 of
// an empty row (which strained one particle to 2.6e4 Pa and added 0.45 %
// of the kinetic energy as strain energy). Checked for lumped P1 with MUSL
// and for each basis's default (USL is left out: its v^{n+1} divides the
// round-off forces of a nearly empty function by its mass, see
// doc/transfers.md, and this block then goes unstable whatever the fix):
// stress, kinetic energy and displacement against the closed form, stress at
// every step.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                           mpi(argc, argv);
  std::ofstream                               out("output");
  const std::vector<std::vector<std::string>> cases = {
    {"Basis/Type=linear", "Mass matrix/Type=lumped", "Transfer/Scheme=musl"},
    {"Basis/Type=linear",
     "Mass matrix/Type=automatic",
     "Transfer/Scheme=automatic"},
    {"Basis/Type=powell-sabin",
     "Mass matrix/Type=automatic",
     "Transfer/Scheme=automatic"}};
  for (const auto &c : cases)
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      std::vector<std::string>       entries = {"Geometry/Length=4",
                                                "Geometry/Height=2",
                                                "Mesh/Type=criss-cross",
                                                "Mesh/Blocks x=8",
                                                "Mesh/Blocks y=4",
                                                "Particles/Per block x=4",
                                                "Particles/Per block y=4",
                                                "Particles/Region=0.5, 0.5, 1.0, 1.0",
                                                "Boundary conditions/Fixed x=",
                                                "Boundary conditions/Fixed y=",
                                                "Reference solution/Type=none",
                                                "Initial conditions/Velocity=2; 0.5",
                                                "Body force/Gravity=0, 0",
                                                "Material/Model=neo-hookean",
                                                "Material/Density=1800",
                                                "Material/Young's modulus=1e6",
                                                "Material/Poisson's ratio=0.3"};
      entries.insert(entries.end(), c.begin(), c.end());
      configure(solver, entries);
      const double       dt = 5e-3;
      const unsigned int n  = 100;
      double             ds = 0; // the largest stress over all steps
      for (unsigned int i = 0; i < n; ++i)
        {
          solver.do_time_step(dt);
          for (const auto &s : solver.get_particles().stress)
            ds = std::max(ds, s.norm());
        }
      const auto        &particles = solver.get_particles();
      const Tensor<1, 2> v({2, 0.5});
      double             dv = 0, du = 0, kinetic = 0, mass = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          dv = std::max(dv, (particles.velocity[p] - v).norm());
          du = std::max(du, (particles.displacement[p] - n * dt * v).norm());
          kinetic +=
            0.5 * particles.mass[p] * particles.velocity[p].norm_square();
          mass += particles.mass[p];
        }
      out << c[0] << ", " << c[1] << ", " << c[2] << std::endl;
      PSMPM_CHECK(out, dv < 1e-9);
      PSMPM_CHECK(out, du < 1e-9);
      PSMPM_CHECK(out, ds < 1e-6);
      PSMPM_CHECK(out,
                  std::abs(kinetic - 0.5 * mass * v.norm_square()) <
                    1e-12 * 0.5 * mass * v.norm_square());
    }
}
