// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The equivalence Wobbes et al. (2019) derive between OTM and MPM, on
// the bar of prm/otm_bar_1d.prm:
// (a) eqs. 27-29: with a constant time step the OTM nodal increment
//     dt M^{-1} (l + (dt_old + dt) / 2 f) (Transfer/OTM update =
//     combined, one solve) equals the MPM one dt (M^{-1} l + dt M^{-1} f)
//     (split, two solves) on the same state, step after step; with a
//     changing step they differ.
// (b) In the first step OTM and the paper's MPM (usl, Algorithm 2) start
//     from the same basis N_a,0, so nodal increments, positions and
//     stresses agree to round-off; afterwards OTM's basis moves with the
//     grid and its velocities are v_p = (x_p,k+1 - x_p,k) / dt instead of
//     FLIP, so the two separate slowly.
#include "otm_tests.h"

using psmpm::Simulator::Simulator;

namespace
{
  const std::string scene = "prm/otm_bar_1d.prm";

  /// max_i |a_i - b_i| / max_i |a_i|
  double
  relative_difference(const std::vector<Tensor<1, 1>> &a,
                      const std::vector<Tensor<1, 1>> &b)
  {
    double diff = 0, size = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        diff = std::max(diff, (a[i] - b[i]).norm());
        size = std::max(size, a[i].norm());
      }
    return diff / size;
  }

  /// Largest relative difference of positions (displacements) and
  /// stresses between the particles of two runs.
  std::pair<double, double>
  particle_difference(const Simulator<1> &a, const Simulator<1> &b)
  {
    const auto &pa = a.get_particles(), &pb = b.get_particles();
    double      du = 0, u = 0, ds = 0, s = 0;
    for (std::size_t p = 0; p < pa.size(); ++p)
      {
        du = std::max(du, (pa.position[p] - pb.position[p]).norm());
        u  = std::max(u, pa.displacement[p].norm());
        ds = std::max(ds, std::abs(pa.stress[p][0][0] - pb.stress[p][0][0]));
        s  = std::max(s, std::abs(pa.stress[p][0][0]));
      }
    return {du / u, ds / s};
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const double                     dt = 1e-4;

  // (a) combined against split on the same trajectory.
  {
    auto combined = make_simulator<1>(scene, {"Transfer/OTM update=combined"});
    auto split    = make_simulator<1>(scene, {"Transfer/OTM update=split"});
    double worst  = 0;
    for (unsigned int k = 1; k <= 5; ++k)
      {
        combined->do_time_step(dt);
        split->do_time_step(dt);
        const double d =
          relative_difference(combined->get_state().grid_velocity,
                              split->get_state().grid_velocity);
        worst = std::max(worst, d);
        out << "constant dt, step " << k
            << ": nodal increments equal to 1e-12: "
            << (d < 1e-12 ? "yes" : "no") << std::endl;
      }
    PSMPM_CHECK(out, worst < 1e-12);
    const auto particles = particle_difference(*combined, *split);
    PSMPM_CHECK(out, particles.first < 1e-12 && particles.second < 1e-12);

    // A changing step: (dt_old + dt) / 2 against dt multiply the force.
    combined->do_time_step(2 * dt);
    split->do_time_step(2 * dt);
    const double d = relative_difference(combined->get_state().grid_velocity,
                                         split->get_state().grid_velocity);
    out << "dt doubled: nodal increments differ by more than 1e-6: "
        << (d > 1e-6 ? "yes" : "no") << std::endl;
  }

  // (b) OTM against the paper's MPM (usl).
  {
    auto otm = make_simulator<1>(scene, {});
    auto usl = make_simulator<1>(scene, {"Transfer/Scheme=usl"});
    for (unsigned int k = 1; k <= 5; ++k)
      {
        otm->do_time_step(dt);
        usl->do_time_step(dt);
        const double d = relative_difference(otm->get_state().grid_velocity,
                                             usl->get_state().grid_velocity);
        const auto   p = particle_difference(*otm, *usl);
        if (k == 1)
          {
            out << "step 1, otm against usl:" << std::endl;
            PSMPM_CHECK(out, d < 1e-12);
            PSMPM_CHECK(out, p.first < 1e-12 && p.second < 1e-12);
          }
        else
          out << "step " << k << ", otm against usl: nodal increments differ "
              << "by "
              << (d < 1e-12 ? "round-off" :
                  d < 1e-3  ? "between 1e-12 and 1e-3" :
                              "more than 1e-3")
              << std::endl;
      }
  }
}
