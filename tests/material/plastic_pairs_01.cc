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

#include "../material_tests.h"

#include <random>

using namespace psmpm;

namespace
{
  /// @p n particles on random paths, each step updated as one batch and,
  /// from the same stresses and states, one particle at a time.
  template <typename Model>
  void
  check(std::ostream      &out,
        const std::string &label,
        const Model       &m,
        const double       drift)
  {
    const unsigned int           n = 65, n_steps = 300, ns = m.n_state();
    BatchAndSingleUpdates<Model> updates(m, n);
    std::vector<Tensor<2, 2>>    dL(n);
    std::mt19937                 rng(11);
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
        updates.update(dL);
        for (unsigned int p = 0; p < n; ++p)
          {
            // Column 5: the equivalent plastic strain.
            plastic += updates.state[p * ns + 5] > updates.before[p * ns + 5];
            differing += updates.differs(p);
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
    for (const SoilCase &k : mohr_coulomb_paths())
      check(out, k.label, make_soil<Material::MohrCoulomb<2>>(k), k.drift);
    for (const SoilCase &k : drucker_prager_paths())
      check(out, k.label, make_soil<Material::DruckerPrager<2>>(k), k.drift);
  });
}
