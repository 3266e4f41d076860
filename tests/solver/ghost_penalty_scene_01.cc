// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// prm/rotating_block.prm (free neo-Hookean block spinning at 1 rad/s in
// a mesh twice its size, P1, MUSL, automatic time step) to t = 0.2 s:
// - consistent mass stops as unstable (energy growth at t ~ 0.097 s,
//   when the first particles cross into empty cells);
// - ghost penalty (Stabilization = 10) completes, turns the block by
//   omega t to 1e-3 (Procrustes fit of the particle positions), keeps
//   the total energy to 1 % and the angular momentum to 1e-3;
// - Mass matrix/Type = deactivate is an error naming the replacement.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../app_tests.h"

#include <filesystem>

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

  /// Rotation of the particle cloud about its centre of mass since the
  /// start (least-squares fit of x = R x0).
  double
  rotation_angle(const Particles::ParticleSet<2> &p)
  {
    Point<2> c, c0;
    double   m = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        c += p.mass[i] * p.position[i];
        c0 += p.mass[i] * (p.position[i] - p.displacement[i]);
        m += p.mass[i];
      }
    c /= m, c0 /= m;
    double cross = 0, dot = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const Tensor<1, 2> x  = p.position[i] - c;
        const Tensor<1, 2> x0 = p.position[i] - p.displacement[i] - c0;
        cross += p.mass[i] * (x0[0] * x[1] - x0[1] * x[0]);
        dot += p.mass[i] * (x0 * x);
      }
    return std::atan2(cross, dot);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const double                     end_time = 0.2;
  for (const std::string type : {"consistent", "ghost penalty"})
    {
      ParameterHandler prm;
      App::declare_parameters(prm);
      prm.parse_input(std::string(PSMPM_SOURCE_DIR) +
                      "/prm/rotating_block.prm");
      for (const std::string o : {"Mass matrix/Type=" + type,
                                  std::string("Mass matrix/Stabilization=10"),
                                  "Time/End time=" + std::to_string(end_time)})
        App::apply_override(prm, o);
      Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      solver.quiet = true;
      solver.parse_parameters(prm);
      solver.setup();
      const auto  &p  = solver.get_particles();
      const double h0 = angular_momentum(p);
      const double e0 = solver.compute_energies().total();
      std::filesystem::create_directories("run");
      const auto status = solver.run("run");
      out << type << ": "
          << (status == Simulator::Status::completed ? "completed" : "unstable")
          << std::endl;
      if (type == "consistent")
        {
          PSMPM_CHECK(out, status == Simulator::Status::unstable);
          PSMPM_CHECK(out, solver.get_time() < end_time);
        }
      else
        {
          PSMPM_CHECK(out, status == Simulator::Status::completed);
          const double angle = rotation_angle(p);
          out << "  angle / (omega t) = " << std::setprecision(4)
              << angle / solver.get_time() << std::endl;
          PSMPM_CHECK(out, std::abs(angle / solver.get_time() - 1) < 1e-3);
          PSMPM_CHECK(out,
                      std::abs(solver.compute_energies().total() / e0 - 1) <
                        1e-2);
          PSMPM_CHECK(out, std::abs(angular_momentum(p) / h0 - 1) < 1e-3);
        }
    }

  // The removed strategy: a clear error, not a run.
  std::string screen, errors;
  const int   code =
    run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/rotating_block.prm",
             "--set",
             "Output directory=run-deactivate",
             "--set",
             "Mass matrix/Type=deactivate"},
            screen,
            errors);
  out << "deactivate: exit code " << code << std::endl;
  PSMPM_CHECK(out, code != 0);
  PSMPM_CHECK(out,
              errors.find("removed") != std::string::npos &&
                errors.find("pins the material") != std::string::npos);
}
