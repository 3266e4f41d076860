// The two-disk impact of prm/two_disks.prm (Sulsky et al. 1994) on a
// coarser grid, with the linear and the Powell-Sabin basis: the disks
// approach, meet through the common grid, bounce and separate (the
// distance of their centres of mass falls, then grows again, and their
// relative velocity has turned round), the mass is exact, the momentum
// stays at zero (to round-off and the solver tolerance),
// and the total energy stays bounded.
#include <psmpm/postprocess/energies.h>

#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      auto        solver = make_scene_solver("two_disks.prm",
                                      {"Basis/Type=" + basis,
                                              "Mesh/Blocks x=10",
                                              "Mesh/Blocks y=10",
                                              "Particles/Per block x=4",
                                              "Particles/Per block y=4"});
      const auto &p      = solver->get_particles();
      // Centre of mass and mean velocity of body b.
      const auto centre = [&p](const unsigned int b) {
        std::pair<Point<2>, Tensor<1, 2>> c;
        double                            m = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p.body_id[i] == b)
            {
              m += p.mass[i];
              c.first += p.mass[i] * p.position[i];
              c.second += p.mass[i] * p.velocity[i];
            }
        c.first /= m;
        c.second /= m;
        return c;
      };
      const auto   e0    = solver->compute_energies();
      const double d0    = centre(1).first.distance(centre(2).first);
      double       d_min = d0, e_max = e0.total(), p_max = 0, m_drift = 0;
      unsigned int n_steps = 0;
      while (solver->get_state().time < 3 * (1 - 1e-12))
        {
          ++n_steps;
          solver->do_time_step(solver->next_time_step());
          const auto e = solver->compute_energies();
          d_min   = std::min(d_min, centre(1).first.distance(centre(2).first));
          e_max   = std::max(e_max, e.total());
          p_max   = std::max(p_max, e.momentum.norm());
          m_drift = std::max(m_drift, std::abs(e.mass - e0.mass));
        }
      const auto   c1 = centre(1), c2 = centre(2);
      const double d = c1.first.distance(c2.first);
      const auto   e = solver->compute_energies();
      // |momentum| of one disk at the start: the scale of the momentum.
      const double scale = e0.mass / 2 * 0.1 * std::sqrt(2.);
      out << basis << ": " << p.size() << " particles, " << n_steps << " steps"
          << std::endl;
      // The measured figures, for the log (not compared).
      std::cout << basis << ": |p|max/scale " << p_max / scale << ", E_max/E_0 "
                << e_max / e0.total() << ", E_end/E_0 "
                << e.total() / e0.total() << ", K_end/K_0 "
                << e.kinetic / e0.kinetic << ", d0 " << d0 << ", d_min "
                << d_min << ", d_end " << d << std::endl;
      const bool linear = basis == "linear";
      PSMPM_CHECK(out, m_drift == 0);
      // Round-off and the solver tolerance, both bases (P1's ghost
      // penalty keeps row sums; with lumped mass P1 lost about 1e-4 of it,
      // doc/scenes.md).
      PSMPM_CHECK(out, p_max < 1e-8 * scale);
      // They came closer than their initial distance less 0.2 (the gap
      // between the disks is 0.307) and then moved apart again.
      PSMPM_CHECK(out, d_min < d0 - 0.2);
      PSMPM_CHECK(out, d > d_min + 0.1);
      PSMPM_CHECK(out, (c2.second - c1.second) * (c2.first - c1.first) > 0);
      // Powell-Sabin never gains energy; the linear basis gains a few
      // per cent in the impact (cell crossing of the squeezed disks).
      PSMPM_CHECK(out, e_max < (linear ? 1.1 : 1.0001) * e0.total());
      // A good part of the kinetic energy is kinetic again after the
      // impact (the rest is vibration and dissipation; Powell-Sabin keeps
      // 0.31 of it here, the linear basis 0.80).
      PSMPM_CHECK(out, e.kinetic > (linear ? 0.5 : 0.2) * e0.kinetic);
    }
}
