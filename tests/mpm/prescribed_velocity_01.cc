// Prescribed velocity on a boundary (Boundary conditions/Prescribed
// velocity): an elastic block confined by rollers on its sides and the
// floor is compressed by a rigid top plate moving down at v0 (both
// components prescribed: x = 0, y = -v0), lumped mass. The plate's reaction
// grows with its displacement d as the confined (oedometric) stiffness
// E_oed W / H, E_oed = E (1 - nu) / ((1 + nu) (1 - 2 nu)) in plane strain:
// the least-squares slope of reaction_top_y against d and its last value
// are checked within 3 %, the floor carries the same load (mean over the
// run), the plate's work equals the strain energy stored (plus the kinetic
// energy) within 3 %, and the particles' mean displacement is -d / 2. The same
// plate as a boundary part (Boundary parts = plate: top, -1, 2, all of top)
// gives the same numbers. P1 and Powell-Sabin.
#include <psmpm/simulator/boundary_conditions.h>

#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      E = 1e7, nu = 0.3, W = 1, H = 1, v0 = 8e-3, T = 0.6;
  const double      E_oed = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  struct Case
  {
    std::string basis, plate, parts;
  };
  const std::vector<Case> cases = {{"linear", "top", ""},
                                   {"linear", "plate", "plate: top, -1, 2"},
                                   {"powell-sabin", "top", ""}};
  for (const auto &c : cases)
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(solver,
                {"Geometry/Length=1",
                 "Geometry/Height=1",
                 "Mesh/Blocks x=4",
                 "Mesh/Blocks y=4",
                 "Basis/Type=" + c.basis,
                 "Mass matrix/Type=lumped",
                 "Transfer/Scheme=musl",
                 "Particles/Per block x=4",
                 "Particles/Per block y=5",
                 "Boundary conditions/Fixed x=left, right",
                 "Boundary conditions/Fixed y=bottom",
                 "Boundary conditions/Boundary parts=" + c.parts,
                 "Boundary conditions/Prescribed velocity=" + c.plate +
                   ": 0; -" + std::to_string(v0),
                 "Reference solution/Type=none",
                 "Initial conditions/Velocity=0; 0",
                 "Body force/Gravity=0, 0",
                 "Material/Density=2000",
                 "Material/Young's modulus=1e7",
                 "Material/Poisson's ratio=0.3",
                 "Time/Time step=0"});
      const auto  *bc    = solver.get_state().boundary_conditions;
      const auto   names = bc->column_names();
      unsigned int top = 0, bottom = 0;
      for (unsigned int i = 0; i < names.size(); ++i)
        {
          top    = names[i] == "reaction_" + c.plate + "_y" ? i : top;
          bottom = names[i] == "reaction_bottom_y" ? i : bottom;
        }
      const double       dt    = solver.next_time_step();
      const unsigned int steps = std::ceil(T / dt);
      double rd = 0, dd = 0, floor_sum = 0, top_sum = 0, last = 0, d = 0;
      for (unsigned int step = 0; step < steps; ++step)
        {
          solver.do_time_step(dt);
          d += v0 * dt;
          rd += bc->reaction(top) * d;
          dd += d * d;
          top_sum += bc->reaction(top);
          floor_sum += bc->reaction(bottom);
          last = bc->reaction(top);
        }
      // The block is compressed uniformly: mean displacement -d / 2.
      const auto &particles = solver.get_particles();
      double      mean_u = 0, mass = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          mean_u += particles.mass[p] * particles.displacement[p][1];
          mass += particles.mass[p];
        }
      mean_u /= mass;
      const auto   e        = solver.compute_energies();
      const double slope    = rd / dd;
      const double expected = -E_oed * W / H;
      const double work     = bc->prescribed_work();
      std::cout << c.basis << " " << c.plate << ": slope " << slope / expected
                << ", last " << last / (expected * d) << ", floor/top "
                << floor_sum / top_sum << ", work " << work
                << " strain + kinetic " << e.strain + e.kinetic
                << ", mean displacement " << mean_u / (-d / 2) << std::endl;
      out << c.basis << ", plate '" << c.plate << "', columns";
      for (const auto &n : names)
        out << ' ' << n;
      out << std::endl;
      PSMPM_CHECK(out, std::abs(slope / expected - 1) < 0.03);
      PSMPM_CHECK(out, std::abs(last / (expected * d) - 1) < 0.03);
      PSMPM_CHECK(out, std::abs(floor_sum / top_sum + 1) < 0.03);
      PSMPM_CHECK(out, std::abs(work - e.strain - e.kinetic) < 0.03 * work);
      PSMPM_CHECK(out, std::abs(mean_u / (-d / 2) - 1) < 0.03);
    }
}
