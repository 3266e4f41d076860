// The batched update() of Mohr-Coulomb and Drucker-Prager in plane strain
// (two particles at a time) with a Disconnected volume ratio: paths that
// dilate past it and are compressed again, so that pairs have one, both
// or neither lane disconnected; stresses, all state columns and volume
// ratios bit for bit those of update(1, ...) of each particle.
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/mohr_coulomb.h>

#include "../material_tests.h"

#include <random>

using namespace psmpm;

namespace
{
  template <typename Model>
  void
  check(std::ostream &out, const std::string &label, Model &m)
  {
    m.disconnected_volume_ratio = 1.01;
    const unsigned int        n = 65, n_steps = 300, ns = m.n_state();
    BatchAndSingleUpdates     u2(m, n);
    std::vector<Tensor<2, 2>> dL(n);
    std::mt19937              rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    unsigned int differing = 0, disconnected = 0, plastic = 0, mixed = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        // Dilation, then compaction.
        const double drift = step < n_steps / 2 ? 2e-4 : -2e-4;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              dL[p][i][j] = 5e-4 * u(rng) + (i == j ? drift : 0);
        u2.update(dL);
        std::vector<bool> off(n);
        for (unsigned int p = 0; p < n; ++p)
          {
            off[p] = u2.stress[p].norm() == 0 && u2.state[p * ns] == 0;
            disconnected += off[p] ? 1 : 0;
            plastic += u2.state[p * ns + 5] > u2.before[p * ns + 5] ? 1 : 0;
            differing += u2.differs(p) ? 1 : 0;
          }
        for (unsigned int p = 0; p + 1 < n; p += 2)
          mixed += off[p] != off[p + 1] ? 1 : 0;
      }
    out << label << ": disconnected particle-steps "
        << (disconnected > 1000 ? "> 1000" : "few")
        << ", pairs with one lane disconnected "
        << (mixed > 100 ? "> 100" : "few") << ", plastic particle-steps "
        << (plastic > 1000 ? "> 1000" : "few")
        << ", differing from the one-particle update " << differing
        << std::endl;
    PSMPM_CHECK(out, disconnected > 1000);
    PSMPM_CHECK(out, mixed > 100);
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
    {
      Material::MohrCoulomb<2> m;
      set_soil_constants(m, 35, 35, 0, inf);
      check(out, "MC phi 35 psi 35 c 0", m);
    }
    {
      Material::DruckerPrager<2> m;
      set_soil_constants(m, 35, 35, 0);
      check(out, "DP phi 35 psi 35 c 0", m);
    }
  });
}
