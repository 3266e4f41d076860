// A soil column at rest (prm/geostatic_column.prm: 1 m x 2 m, E = 1e7 Pa,
// nu = 0.3, rho = 2000 kg/m^3, smooth walls and floor, gravity) with
// Initial conditions/Stress = geostatic stays at rest: the largest particle
// speed over 0.1 <= t <= 0.3 s is two orders of magnitude below that of
// the same column started stress-free (which drops and oscillates), for
// the linear and the Powell-Sabin basis at their defaults, and sigma_yy at
// the particles stays within 3% of rho g H of -rho g depth. K0 is
// honoured: sigma_xx / sigma_yy and sigma_zz / sigma_yy start at K0 (the
// elastic nu / (1 - nu) with K0 = automatic, or the given 0.6) and stay
// within 2% of it, the column being laterally confined.
#include "../mpm_tests.h"

namespace
{
  struct Result
  {
    double max_speed    = 0; ///< over 0.1 <= t <= 0.3
    double stress_error = 0; ///< max |syy + rho g depth| / (rho g H), end
    double k0_start = 0, k0_end = 0, kz_start = 0, kz_end = 0;
  };

  /// sxx / syy and szz / syy, averaged over the particles deeper than
  /// 0.25 m (the top row's stresses are small).
  std::pair<double, double>
  ratios(const psmpm::Particles::ParticleSet<2> &particles)
  {
    double      sx = 0, sy = 0, sz = 0;
    const auto &names = particles.get_state_names();
    const auto  zz =
      std::find(names.begin(), names.end(), "stress_zz") - names.begin();
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (particles.position[p][1] < 1.75)
        {
          sx += particles.stress[p][0][0];
          sy += particles.stress[p][1][1];
          sz += particles.state_of(p)[zz];
        }
    return {sx / sy, sz / sy};
  }

  Result
  run(const std::vector<std::string> &overrides)
  {
    auto        solver = make_scene_solver("geostatic_column.prm", overrides);
    Result      r;
    const auto &particles            = solver->get_particles();
    std::tie(r.k0_start, r.kz_start) = ratios(particles);
    while (solver->get_time() < 0.3 - 1e-12)
      {
        solver->do_time_step(solver->next_time_step());
        if (solver->get_time() >= 0.1)
          for (std::size_t p = 0; p < particles.size(); ++p)
            r.max_speed = std::max(r.max_speed, particles.velocity[p].norm());
      }
    const double rho_g = 2000 * 9.81, top = 2;
    for (std::size_t p = 0; p < particles.size(); ++p)
      {
        // Depth below the top at the particle's initial place (the
        // column settles by less than a millimetre).
        const double depth = top - particles.initial_position[p][1];
        r.stress_error =
          std::max(r.stress_error,
                   std::abs(particles.stress[p][1][1] + rho_g * depth) /
                     (rho_g * top));
      }
    std::tie(r.k0_end, r.kz_end) = ratios(particles);
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  out << std::setprecision(2);
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      const std::string b  = "Basis/Type=" + basis;
      const Result at_rest = run({b, "Initial conditions/Stress=geostatic"});
      const Result free    = run({b, "Initial conditions/Stress=none"});
      const double ratio   = at_rest.max_speed / free.max_speed;
      std::cout << basis << ": max speed " << at_rest.max_speed
                << " (geostatic), " << free.max_speed
                << " (stress-free), ratio " << ratio << ", sigma_yy error "
                << at_rest.stress_error << std::endl;
      out << basis << ": stress-free max speed " << free.max_speed
          << " m/s (rounded)" << std::endl;
      PSMPM_CHECK(out, free.max_speed > 0.1);
      PSMPM_CHECK(out, ratio < 1e-2);
      PSMPM_CHECK(out, at_rest.stress_error < 0.03);

      const double elastic = 0.3 / 0.7;
      for (const double k0 : {0., 0.6})
        {
          const Result r        = k0 == 0. ?
                                    at_rest :
                                    run({b,
                                         "Initial conditions/Stress=geostatic",
                                         "Initial conditions/K0=0.6"});
          const double expected = k0 == 0. ? elastic : k0;
          std::cout << "  K0 " << expected << ": start " << r.k0_start << ' '
                    << r.kz_start << ", end " << r.k0_end << ' ' << r.kz_end
                    << std::endl;
          out << "  K0 = " << (k0 == 0. ? "automatic" : "0.6") << std::endl;
          PSMPM_CHECK(out, std::abs(r.k0_start / expected - 1) < 1e-12);
          PSMPM_CHECK(out, std::abs(r.kz_start / expected - 1) < 1e-12);
          PSMPM_CHECK(out, std::abs(r.k0_end / expected - 1) < 0.02);
          PSMPM_CHECK(out, std::abs(r.kz_end / expected - 1) < 0.02);
        }
    }
}
