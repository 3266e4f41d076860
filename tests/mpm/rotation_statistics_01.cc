// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The angular momentum that Postprocess::RotationStatistics reports for
// the spinning block of prm/rotating_block.prm (v = omega x (x - c), so
// the initial velocity gradient is not zero):
// - transfers that do not carry affine matrices (musl, usl, otm) report
//   the particle sum sum_p m_p (x_p - c) x v_p, at the start and after
//   five steps, to round-off. The initial conditions set C_p = grad v for
//   the affine transfers; a scheme that never updates C_p must not have
//   that stale matrix added to its angular momentum (it was, up to this
//   test: +23 % on this 4 x 4 mesh, +5.6 % on the scene's own);
// - apic reports more than the particle sum at the start: the affine part
//   of the rigid rotation, sum_p m_p sum_i N_i |X_i - x_p|^2 omega > 0.
#include <psmpm/base/cross.h>
#include <psmpm/postprocess/rotation_statistics.h>

#include "../mpm_tests.h"

namespace
{
  using namespace psmpm;

  double
  particle_sum(const Particles::ParticleSet<2> &p)
  {
    // The centre of mass of the initial configuration, as the statistic.
    double       mass = 0;
    Tensor<1, 2> first;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        mass += p.mass[i];
        first += p.mass[i] * p.initial_position[i];
      }
    const Point<2> c(first / mass);
    double         h = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      h += p.mass[i] * cross(p.position[i] - c, p.velocity[i]);
    return h;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string scheme : {"musl", "usl", "otm", "apic"})
    {
      auto solver = make_scene_solver<2>("rotating_block.prm",
                                         {"Transfer/Scheme=" + scheme,
                                          "Mesh/Blocks x=4",
                                          "Mesh/Blocks y=4"});
      Postprocess::RotationStatistics<2> rotation;
      const auto                        &particles = solver->get_particles();
      const double h0 = rotation.compute(solver->get_state()).angular_momentum;
      const double p0 = particle_sum(particles);
      out << scheme
          << ": reported / particle sum at the start = " << std::setprecision(4)
          << h0 / p0 << std::endl;
      if (scheme == "apic")
        {
          PSMPM_CHECK(out, h0 > p0 * (1 + 1e-3));
          continue;
        }
      PSMPM_CHECK(out, std::abs(h0 - p0) <= 1e-13 * std::abs(p0));
      for (unsigned int step = 0; step < 5; ++step)
        solver->do_time_step(1e-3);
      const double h = rotation.compute(solver->get_state()).angular_momentum;
      const double p = particle_sum(particles);
      PSMPM_CHECK(out, std::abs(h - p) <= 1e-13 * std::abs(p0));
    }
}
