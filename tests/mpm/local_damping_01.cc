// Local (Cundall) damping (Boundary conditions/Local damping): a block put
// on the floor without its geostatic stress vibrates under its own weight.
// With alpha = 0.2 its mean kinetic energy over the last quarter of the
// 0.5 s run is below 5 % of the undamped one (measured 2.0 % P1, 3.3 %
// Powell-Sabin), the floor reaction's largest deviation from the weight
// there below a quarter (17 %, 3 %), and kinetic + strain + gravity energy
// - damping work stays at its initial value as well as without damping
// (the damping work is the energy the damping took). P1 and Powell-Sabin,
// lumped mass, MUSL.
#include <psmpm/simulator/boundary_conditions.h>

#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      std::array<double, 2> kinetic{}, reaction_error{};
      double                weight = 0;
      for (const unsigned int damped : {0, 1})
        {
          psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
          configure(solver,
                    {"Geometry/Length=1",
                     "Geometry/Height=2",
                     "Mesh/Blocks x=2",
                     "Mesh/Blocks y=4",
                     "Basis/Type=" + basis,
                     "Mass matrix/Type=lumped",
                     "Transfer/Scheme=musl",
                     "Particles/Per block x=4",
                     "Particles/Per block y=5",
                     "Boundary conditions/Fixed x=left, right",
                     "Boundary conditions/Fixed y=bottom",
                     "Boundary conditions/Local damping=" +
                       std::string(damped ? "0.2" : "0"),
                     "Boundary conditions/Report reactions=true",
                     "Reference solution/Type=none",
                     "Initial conditions/Velocity=0; 0",
                     "Body force/Gravity=0, -10",
                     "Material/Density=2000",
                     "Material/Young's modulus=1e7",
                     "Material/Poisson's ratio=0",
                     "Time/Time step=0"});
          const auto &particles = solver.get_particles();
          weight                = 0;
          for (std::size_t p = 0; p < particles.size(); ++p)
            weight += particles.mass[p] * 10;
          const auto  *bc     = solver.get_state().boundary_conditions;
          const auto   names  = bc->column_names();
          unsigned int bottom = 0;
          for (unsigned int c = 0; c < names.size(); ++c)
            bottom = names[c] == "reaction_bottom_y" ? c : bottom;
          const double       dt    = solver.next_time_step();
          const unsigned int steps = std::ceil(0.5 / dt);
          const double       e0    = solver.compute_energies().total();
          double             drift = 0, scale = 0;
          for (unsigned int step = 0; step < steps; ++step)
            {
              solver.do_time_step(dt);
              const auto e = solver.compute_energies();
              scale        = std::max(scale, e.strain);
              drift =
                std::max(drift, std::abs(e.total() - bc->damping_work() - e0));
              if (4 * step >= 3 * steps)
                {
                  kinetic[damped] += e.kinetic / (steps - 3 * steps / 4);
                  reaction_error[damped] =
                    std::max(reaction_error[damped],
                             std::abs(bc->reaction(bottom) - weight) / weight);
                }
            }
          std::cout << basis << " alpha " << (damped ? 0.2 : 0)
                    << ": mean kinetic energy " << kinetic[damped]
                    << ", largest |R - W| / W " << reaction_error[damped]
                    << ", energy drift " << drift / scale << ", damping work "
                    << bc->damping_work() << std::endl;
          out << basis << ", alpha = " << (damped ? 0.2 : 0) << std::endl;
          // MUSL itself loses about 2 % of the largest strain energy
          // here; with damping the book closes to the same level, far
          // below the damping work.
          if (damped)
            PSMPM_CHECK(out, drift < 0.1 * std::abs(bc->damping_work()));
          PSMPM_CHECK(out, drift < 3e-2 * scale);
        }
      PSMPM_CHECK(out, kinetic[1] < 0.05 * kinetic[0]);
      PSMPM_CHECK(out, reaction_error[1] < 0.25 * reaction_error[0]);
    }
}
