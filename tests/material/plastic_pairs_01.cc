// The batched update() of Mohr-Coulomb and Drucker-Prager in plane strain
// without softening updates two particles at a time (Lanes: the trial
// stresses, the elastic test and the return's common path for both, a
// particle off that path by the one-particle return): the stresses and
// every state column after each step must be bit for bit those of the
// same particles updated one at a time (update(1, ...): the one-particle
// loop), over random paths of an odd number of particles (the last one
// alone) through the elastic region, the main plane, the edges, the apex
// and the cutoff, with a particle's neighbour in the pair on another path
// in many steps.
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/mohr_coulomb.h>

#include "../tests.h"

#include <cstring>
#include <random>

using namespace psmpm;

namespace
{
  template <typename Model>
  void
  set_constants(Model       &m,
                const double phi,
                const double psi,
                const double c,
                const double t = HUGE_VAL)
  {
    m.youngs_modulus          = 2e7;
    m.poisson_ratio           = 0.3;
    m.density                 = 2000;
    m.friction_angle          = phi;
    m.dilatancy_angle         = psi;
    m.cohesion                = c;
    m.tension_cutoff          = t;
    m.residual_cohesion       = c;
    m.residual_friction_angle = phi;
    m.softening_strain        = 0;
  }

  /// @p n particles on random paths, each step updated as one batch and,
  /// from the same stresses and states, one particle at a time.
  template <typename Model>
  void
  check(std::ostream      &out,
        const std::string &label,
        const Model       &m,
        const double       drift)
  {
    const unsigned int                 n = 65, n_steps = 300, ns = m.n_state();
    std::vector<SymmetricTensor<2, 2>> stress(n), single_stress(n);
    std::vector<Tensor<2, 2>>          dL(n);
    std::vector<double> state(n * ns), single_state(n * ns), ratio(n),
      single_ratio(n);
    m.initialize(n, state.data());
    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    unsigned int                           differing = 0, plastic = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              // Some particles at rest: elastic beside yielding ones.
              dL[p][i][j] =
                (p % 5 == 3 ? 1e-7 : 5e-4) * u(rng) + (i == j ? drift : 0);
        single_stress                    = stress;
        single_state                     = state;
        const std::vector<double> before = state;
        m.update(n, dL.data(), stress.data(), state.data(), ratio.data());
        for (unsigned int p = 0; p < n; ++p)
          m.update(1,
                   &dL[p],
                   &single_stress[p],
                   &single_state[p * ns],
                   &single_ratio[p]);
        for (unsigned int p = 0; p < n; ++p)
          {
            // Column 5: the equivalent plastic strain.
            plastic += state[p * ns + 5] > before[p * ns + 5] ? 1 : 0;
            differing +=
              std::memcmp(&stress[p], &single_stress[p], sizeof(stress[p])) !=
                0 ||
              std::memcmp(&state[p * ns],
                          &single_state[p * ns],
                          ns * sizeof(double)) != 0 ||
              std::memcmp(&ratio[p], &single_ratio[p], sizeof(double)) != 0;
          }
      }
    out << label << ": plastic particle-steps "
        << (plastic > 1000 ? "> 1000" : "few")
        << ", differing from the one-particle update " << differing
        << std::endl;
    PSMPM_CHECK(out, plastic > 1000);
    PSMPM_CHECK(out, differing == 0);
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    const double  inf = HUGE_VAL;
    struct Case
    {
      const char *label;
      double      phi, psi, c, t, drift;
    };
    for (const Case &k :
         {Case{"MC phi 30 psi 0 c 1 kPa", 30, 0, 1e3, inf, 0},
          Case{"MC phi 35 psi 35 c 0", 35, 35, 0, inf, 1e-4},
          Case{"MC phi 20 psi 5 c 5 kPa t 2 kPa", 20, 5, 5e3, 2e3, 2e-4},
          Case{"MC Tresca c 1e-6 Pa", 0, 0, 1e-6, inf, -2e-4}})
      {
        Material::MohrCoulomb<2> m;
        set_constants(m, k.phi, k.psi, k.c, k.t);
        check(out, k.label, m, k.drift);
      }
    for (const Case &k :
         {Case{"DP phi 30 psi 0 c 1 kPa", 30, 0, 1e3, inf, 0},
          Case{"DP phi 35 psi 35 c 0", 35, 35, 0, inf, 1e-4},
          Case{"DP von Mises c 1e-6 Pa", 0, 0, 1e-6, inf, -2e-4}})
      {
        Material::DruckerPrager<2> m;
        set_constants(m, k.phi, k.psi, k.c);
        check(out, k.label, m, k.drift);
      }
  });
}
