// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A free block spinning at omega = 1 rad/s (prm/rotating_block.prm made
// short: the block fills a 4 x 4 criss-cross mesh, 3 x 3 particles per
// block, P1 with the consistent mass, which reproduces the rigid velocity
// field exactly, dt = 1e-3 to t = 0.08, as far as the corner particles
// stay in the mesh), for the neo-Hookean and the hypoelastic law:
// - after the first step the velocity gradient is exactly skew and an
//   objective update leaves the body stress-free (below 1e-10 E);
// - after that the particles, which move along straight lines until a
//   stress turns them, stretch the body by about (omega t)^2 / 2: the
//   stress stays of the centripetal order, below 2 rho omega^2 R^2
//   (R^2 = 0.5 at the corners; a sixth of E (omega t)^2);
// - angular momentum is conserved to 1e-6 (consistent mass).
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../tests.h"

namespace
{
  using namespace psmpm;

  double
  angular_momentum(const Particles::ParticleSet<2> &p)
  {
    double h = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      h += p.mass[i] * ((p.position[i][0] - 0.5) * p.velocity[i][1] -
                        (p.position[i][1] - 0.5) * p.velocity[i][0]);
    return h;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const double rho = 1000, omega = 1, R2 = 0.5, end_time = 0.08;
  const double centripetal = rho * omega * omega * R2;
  const double E           = 1e6;
  for (const std::string model : {"neo-hookean", "hypoelastic"})
    {
      ParameterHandler prm;
      psmpm::App::declare_parameters(prm);
      prm.parse_input(std::string(PSMPM_SOURCE_DIR) +
                      "/prm/rotating_block.prm");
      for (const std::string o : {"Material/Model=" + model,
                                  std::string("Mesh/Blocks x=4"),
                                  std::string("Mesh/Blocks y=4"),
                                  std::string("Particles/Per block x=3"),
                                  std::string("Particles/Per block y=3"),
                                  std::string("Particles/Region="),
                                  std::string("Mass matrix/Type=consistent")})
        psmpm::App::apply_override(prm, o);
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      solver.quiet = true;
      solver.parse_parameters(prm);
      solver.setup();
      const auto  &p              = solver.get_particles();
      const double h0             = angular_momentum(p);
      const auto   largest_stress = [&p]() {
        double s = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
          s = std::max(s, p.stress[i].norm());
        return s;
      };
      solver.do_time_step(1e-3);
      PSMPM_CHECK(out, largest_stress() < 1e-10 * E);
      while (solver.get_time() < end_time * (1 - 1e-12))
        solver.do_time_step(1e-3);
      const double stress = largest_stress();
      out << model
          << ": max |stress| / (rho omega^2 R^2) = " << std::setprecision(2)
          << stress / centripetal << std::endl;
      PSMPM_CHECK(out, stress < 2 * centripetal);
      PSMPM_CHECK(out, std::abs(angular_momentum(p) / h0 - 1) < 1e-6);
    }
}
