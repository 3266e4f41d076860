// The cost of a material's batched update per particle, for the
// elastic model and the soil models on an elastic and on a yielding path
// (phi = 30 deg, c = 1 kPa: the main plane; Tresca and von Mises with
// c = 1e-6 Pa as in contrib/geomechanics/plastic_cost.sh: an edge):
// 320,000 particles (the throughput bar's count), their stress and state
// arrays streamed as in a step. A timing program, not a test:
//   build/benchmarks/material_update [--benchmark_repetitions=5]
// Reported: time per batch; items/s = particle updates per second.
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/hypoelastic.h>
#include <psmpm/material/mohr_coulomb.h>

#include <benchmark/benchmark.h>
#include <random>

using namespace psmpm;

namespace
{
  constexpr unsigned int n = 320000;

  template <typename Model>
  void
  constants(Model &m, const double cohesion, const double friction_angle)
  {
    m.youngs_modulus = 1e7;
    m.poisson_ratio  = 0.3;
    m.density        = 2000;
    if constexpr (!std::is_same_v<Model, Material::Hypoelastic<2>>)
      {
        m.friction_angle          = friction_angle;
        m.dilatancy_angle         = 0;
        m.cohesion                = cohesion;
        m.residual_cohesion       = cohesion;
        m.residual_friction_angle = friction_angle;
      }
  }

  /// @p yielding: increments of shear under compression that keep every
  /// particle on the yield surface after a first few updates; otherwise
  /// increments far inside it.
  template <typename Model>
  void
  update(benchmark::State &s,
         const double      cohesion,
         const bool        yielding,
         const double      friction_angle = 30)
  {
    Model m;
    constants(m, cohesion, friction_angle);
    std::vector<SymmetricTensor<2, 2>> stress(n);
    std::vector<Tensor<2, 2>>          dL(n);
    std::vector<double> state(std::size_t(n) * m.n_state()), ratio(n);
    m.initialize(n, state.data());
    std::mt19937                           rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    const double                           scale = yielding ? 1e-4 : 1e-8;
    for (auto &d : dL)
      {
        d[0][0] = -0.2 * scale * (1 + 0.1 * u(rng));
        d[1][1] = -0.3 * scale * (1 + 0.1 * u(rng));
        d[0][1] = scale * (1 + 0.1 * u(rng));
        d[1][0] = scale * (0.5 + 0.1 * u(rng));
      }
    for (unsigned int k = 0; k < (yielding ? 20 : 1); ++k)
      m.update(n, dL.data(), stress.data(), state.data(), ratio.data());
    for (auto _ : s)
      {
        m.update(n, dL.data(), stress.data(), state.data(), ratio.data());
        benchmark::ClobberMemory();
      }
    s.SetItemsProcessed(s.iterations() * n);
  }
} // namespace

namespace
{
  void
  hypoelastic(benchmark::State &s)
  {
    update<Material::Hypoelastic<2>>(s, 0, false);
  }
  void
  mohr_coulomb_elastic(benchmark::State &s)
  {
    update<Material::MohrCoulomb<2>>(s, 1e9, false);
  }
  void
  mohr_coulomb_yielding(benchmark::State &s)
  {
    update<Material::MohrCoulomb<2>>(s, 1e3, true);
  }
  /// The yielding case of contrib/geomechanics/plastic_cost.sh: Tresca
  /// with c = 1e-6 Pa, every particle on an edge of the surface.
  void
  tresca_yielding(benchmark::State &s)
  {
    update<Material::MohrCoulomb<2>>(s, 1e-6, true, 0);
  }
  void
  drucker_prager_elastic(benchmark::State &s)
  {
    update<Material::DruckerPrager<2>>(s, 1e9, false);
  }
  void
  drucker_prager_yielding(benchmark::State &s)
  {
    update<Material::DruckerPrager<2>>(s, 1e3, true);
  }
  /// The same for von Mises.
  void
  von_mises_yielding(benchmark::State &s)
  {
    update<Material::DruckerPrager<2>>(s, 1e-6, true, 0);
  }
} // namespace

BENCHMARK(hypoelastic)->Unit(benchmark::kMillisecond);
BENCHMARK(mohr_coulomb_elastic)->Unit(benchmark::kMillisecond);
BENCHMARK(mohr_coulomb_yielding)->Unit(benchmark::kMillisecond);
BENCHMARK(tresca_yielding)->Unit(benchmark::kMillisecond);
BENCHMARK(drucker_prager_elastic)->Unit(benchmark::kMillisecond);
BENCHMARK(drucker_prager_yielding)->Unit(benchmark::kMillisecond);
BENCHMARK(von_mises_yielding)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
