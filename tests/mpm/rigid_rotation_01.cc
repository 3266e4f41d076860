// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A free block in rigid rotation (prm/rotating_block_neo_hookean.prm: 1
// rad/s, no boundary conditions, P1 with the consistent mass, which
// reproduces the linear velocity field) stays stress-free up to the time
// discretisation error: forward Euler moves the particles along the
// tangent, which stretches the body by about omega^2 dt t / 2, so the
// largest stress over E is bounded by a few times that and halves with
// dt. For the neo-Hookean law and the hypoelastic one; the angular
// momentum is kept to the same order.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../tests.h"

struct Result
{
  double stress, angular_momentum_change;
};

double
angular_momentum(const psmpm::Particles::ParticleSet<2> &p)
{
  double h = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    h += p.mass[i] * ((p.position[i][0] - 0.5) * p.velocity[i][1] -
                      (p.position[i][1] - 0.5) * p.velocity[i][0]);
  return h;
}

Result
rotate(const std::string &model, const double dt, const double end_time)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input(std::string(PSMPM_SOURCE_DIR) +
                  "/prm/rotating_block_neo_hookean.prm");
  psmpm::App::apply_override(prm, "Material/Model=" + model);
  psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
  solver.quiet = true;
  solver.parse_parameters(prm);
  solver.setup();
  const double h0 = angular_momentum(solver.get_particles());
  while (solver.get_time() < end_time - 1e-12)
    solver.do_time_step(dt);
  const auto &p      = solver.get_particles();
  double      stress = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    stress = std::max(stress, p.stress[i].norm());
  return {stress / 1e6, std::abs(angular_momentum(p) / h0 - 1)};
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  const double                     omega = 1, end_time = 0.05;
  for (const std::string model : {"neo-hookean", "hypoelastic"})
    {
      const Result coarse = rotate(model, 1e-3, end_time);
      const Result fine   = rotate(model, 5e-4, end_time);
      out << model << ": |stress|/E " << std::setprecision(2) << coarse.stress
          << " -> " << fine.stress << ", angular momentum change "
          << coarse.angular_momentum_change << std::endl;
      const double stretch = omega * omega * 1e-3 * end_time / 2;
      PSMPM_CHECK(out, coarse.stress < 10 * stretch);
      PSMPM_CHECK(out, coarse.stress / fine.stress > 1.6);
      PSMPM_CHECK(out, coarse.angular_momentum_change < 10 * stretch);
    }
}
