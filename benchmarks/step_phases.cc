// ---------------------------------------------------------------------
// psmpm: the phases of one MPM step, each timed on its own, and the
// machine's memory bandwidth and flop rate for a roofline estimate
// (doc/performance.md, "Roofline per phase").
//
//   step_phases --benchmark_repetitions=3 --benchmark_report_aggregates_only
//   step_phases --benchmark_filter='^(p2g_accumulate|machine/triad)'
//
// Benchmark names are phase/configuration/blocks (p2g_accumulate/
// ps_consistent/250) and machine/... .
//
// Scene: prm/benchmark_throughput.prm (the vibrating bar, criss-cross
// mesh, 8 x 8 particles per block, hypoelastic) with Mesh/Blocks x = the
// benchmark argument (20 blocks in y: 1280 particles per block column;
// 50 = 64,000 particles, 250 = the 320,000 of the throughput table in
// doc/performance.md) and Transfer/Scheme = musl, in three
// configurations: P1 lumped, Powell-Sabin lumped and Powell-Sabin
// consistent mass. Each scene is set up once (Simulator::setup() and one
// do_time_step, so that stresses and grid fields are those of a running
// simulation) and kept for all benchmarks of its configuration and size.
//
// items/s = particles/s: the number of particle-steps per second the phase
// alone would allow. The counters "particles", "cells", "dofs" say what
// was timed.
//
// What each benchmark times, and how it reaches the code:
//  * p2g_accumulate: the particle loop of TransferScheme::particles_to_grid
//    (MUSL's forces to the grid: lumped mass, consistent cell mass if the
//    strategy uses a matrix, cell right-hand sides), zeroing included:
//    ParticleLoops::particles_to_cells, without the mass assembly;
//  * p2g_with_assembly: TransferScheme::particles_to_grid itself (the loop
//    above plus GridSystem::assemble_mass), through a class derived from
//    TransferScheme that makes the protected static public;
//  * assemble_mass: GridSystem::assemble_mass on the cell arrays of the
//    step (restored before every call, outside the timing);
//  * solve: GridSystem::solve for all components (lumped: a division per
//    DoF; consistent: Jacobi-CG, or the dense Cholesky below 600 DoFs);
//  * g2p_velocity: MUSL's first grid-to-particle loop (particle velocities
//    from the grid acceleration, momentum back into the cell right-hand
//    sides): ParticleLoops::accelerate_particles;
//  * g2p_gradient: MUSL's second one (velocity and velocity gradient at
//    the particle, positions): ParticleLoops::move_particles;
//  * material_update: TransferScheme::update_material (the material's
//    stress update of every particle, volumes and densities), through the
//    derived class;
//  * locate_hint: CellLocator::locate(position, old cell) for every
//    particle, as Simulator::locate_particles does after a step (the
//    walk; particles have moved by one step); locate_search without hint;
//  * evaluate: Space::evaluate for all particles in one batched call, as
//    State::evaluate_shape_functions does;
//  * do_time_step: Simulator::do_time_step (all of the above: transfer,
//    locate, basis evaluation; MUSL solves twice per step).
// Benchmarks that change particles (g2p, material update) restore them
// after the timing loop; do_time_step advances the scene.
//
// Machine (for the roofline): triad a = b + s c over arrays of argument
// doubles each (24 bytes per element counted, the write-allocate of a not
// counted: STREAM's convention), read (a sum, 8 bytes per element), and
// the flop rate: a dependent chain x = a x + b (latency: what one running
// sum in a kernel gets), 12 independent chains kept scalar and as this
// build compiles them (-O2, x86-64 baseline: SSE2 packed, no FMA; the
// library's loops are mostly scalar), and 12 independent AVX2 and AVX-512 FMA
// chains (the hardware's peak, not used by this build). items/s = flop/s there.
// ---------------------------------------------------------------------
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/base/mpi_session.h>
#include <psmpm/base/phase_timer.h>
#include <psmpm/simulator/particle_loops.h>
#include <psmpm/simulator/simulator.h>
#include <psmpm/simulator/transfer_scheme.h>

#include <array>
#include <benchmark/benchmark.h>
#include <immintrin.h>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using namespace dealii;
  using Simulator = psmpm::Simulator::Simulator<2>;
  using State     = psmpm::Simulator::State<2>;

  enum Config
  {
    p1_lumped,
    ps_lumped,
    ps_consistent
  };

  /// The protected statics of TransferScheme, public.
  struct Kernels : public psmpm::Simulator::TransferScheme<2>
  {
    using psmpm::Simulator::TransferScheme<2>::particles_to_grid;
    using psmpm::Simulator::TransferScheme<2>::update_material;
    bool
    step(State &,
         psmpm::Simulator::StabilityMonitor &,
         psmpm::PhaseTimer &) override
    {
      return true;
    }
  };

  const ConditionalOStream &
  quiet_stream()
  {
    static const ConditionalOStream stream(std::cout, false);
    return stream;
  }

  psmpm::PhaseTimer &
  phase_timer()
  {
    static psmpm::PhaseTimer timer(MPI_COMM_WORLD, quiet_stream());
    return timer;
  }

  /// Scenes by (configuration, Blocks x); cleared before MPI ends.
  std::map<std::pair<int, int>, std::unique_ptr<Simulator>> &
  scenes()
  {
    static std::map<std::pair<int, int>, std::unique_ptr<Simulator>> s;
    return s;
  }

  Simulator &
  scene(const Config config, const int blocks_x)
  {
    auto &cache = scenes();
    auto  it    = cache.find({config, blocks_x});
    if (it != cache.end())
      return *it->second;
    // Keep at most about 1.5 million particles set up (memory).
    std::size_t kept = 0;
    for (const auto &s : cache)
      kept += s.second->get_particles().size();
    if (kept + 1280 * std::size_t(blocks_x) > 1500000)
      cache.clear();

    ParameterHandler prm;
    psmpm::App::declare_parameters(prm);
    prm.parse_input(std::string(PSMPM_SOURCE_DIR) +
                    "/prm/benchmark_throughput.prm");
    const std::vector<std::string> overrides = {
      "Mesh/Blocks x=" + std::to_string(blocks_x),
      std::string("Basis/Type=") +
        (config == p1_lumped ? "linear" : "powell-sabin"),
      std::string("Mass matrix/Type=") +
        (config == ps_consistent ? "consistent" : "lumped"),
      "Transfer/Scheme=musl",
      "Time/End time=1"};
    for (const auto &o : overrides)
      psmpm::App::apply_override(prm, o);
    auto simulator   = std::make_unique<Simulator>(MPI_COMM_WORLD);
    simulator->quiet = true;
    simulator->parse_parameters(prm);
    simulator->setup();
    simulator->do_time_step(simulator->get_time_step());
    AssertThrow(simulator->get_failure() == psmpm::Simulator::Failure::none,
                ExcMessage("the benchmark scene failed its first step"));
    return *cache
              .emplace(std::make_pair(config, blocks_x), std::move(simulator))
              .first->second;
  }

  /// The simulator's state, to be changed: Simulator keeps it as a
  /// non-const member and hands out a const reference only.
  State &
  state_of(Simulator &simulator)
  {
    return const_cast<State &>(simulator.get_state());
  }

  void
  set_counters(benchmark::State &bm, const State &state)
  {
    const double n = state.particles.size();
    bm.SetItemsProcessed(bm.iterations() * state.particles.size());
    bm.counters["particles"]     = n;
    bm.counters["cells"]         = state.grid->n_cells;
    bm.counters["dofs"]          = state.dof_handler.n_dofs();
    bm.counters["dofs_per_cell"] = state.grid->dofs_per_cell;
    if (state.grid->uses_matrix())
      bm.counters["nnz"] = state.grid->mass_matrix(0).n_nonzero_elements();
  }

  void
  p2g_accumulate(benchmark::State &bm, const Config config)
  {
    State &state = state_of(scene(config, bm.range(0)));
    for (auto _ : bm)
      {
        psmpm::Simulator::ParticleLoops::particles_to_cells(state, 0., 1.);
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
  }

  void
  p2g_with_assembly(benchmark::State &bm, const Config config)
  {
    State &state = state_of(scene(config, bm.range(0)));
    for (auto _ : bm)
      {
        Kernels::particles_to_grid(state, phase_timer(), 0., 1.);
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
  }

  void
  assemble_mass(benchmark::State &bm, const Config config)
  {
    State &state = state_of(scene(config, bm.range(0)));
    psmpm::Simulator::ParticleLoops::particles_to_cells(state, 0., 1.);
    auto      &cells  = state.grid->cell_arrays();
    const auto mass   = cells.mass;
    const auto lumped = cells.lumped;
    for (auto _ : bm)
      {
        bm.PauseTiming();
        cells.mass   = mass;
        cells.lumped = lumped;
        bm.ResumeTiming();
        state.grid->assemble_mass();
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
  }

  void
  solve(benchmark::State &bm, const Config config)
  {
    State &state = state_of(scene(config, bm.range(0)));
    // The step's mass matrix and force right-hand sides, as MUSL's first
    // solve sees them.
    Kernels::particles_to_grid(state, phase_timer(), 0., 1.);
    std::vector<Tensor<1, 2>> solution;
    // CG iterations of one solve (the statistics add up every solve).
    const unsigned int before = state.grid->statistics().iterations;
    state.grid->solve(solution);
    const unsigned int iterations =
      state.grid->statistics().iterations - before;
    for (auto _ : bm)
      {
        // From zero, as the first solve: with the last solution as its
        // guess (Mass matrix/Warm start) the same system needs no
        // iteration.
        solution.clear();
        state.grid->solve(solution);
        benchmark::DoNotOptimize(solution.data());
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
    bm.counters["cg_iterations"] = iterations;
  }

  void
  g2p_velocity(benchmark::State &bm, const Config config)
  {
    State     &state = state_of(scene(config, bm.range(0)));
    const auto saved = state.particles;
    for (auto _ : bm)
      {
        // MUSL::update_particle_velocities without a reconstruction.
        psmpm::Simulator::ParticleLoops::accelerate_particles(state, true);
        benchmark::ClobberMemory();
      }
    state.particles = saved;
    set_counters(bm, state);
  }

  /// MUSL::update_particle_state without the material: velocity and its
  /// gradient at the particles, increments, positions.
  void
  interpolate_gradient(State &state, std::vector<Tensor<2, 2>> &increments)
  {
    using namespace psmpm::Simulator::ParticleLoops;
    move_particles<2, VelocityUpdate::keep>(state, increments);
  }

  void
  g2p_gradient(benchmark::State &bm, const Config config)
  {
    State                    &state = state_of(scene(config, bm.range(0)));
    const auto                saved = state.particles;
    std::vector<Tensor<2, 2>> increments;
    for (auto _ : bm)
      {
        interpolate_gradient(state, increments);
        benchmark::ClobberMemory();
      }
    state.particles = saved;
    set_counters(bm, state);
  }

  void
  material_update(benchmark::State &bm, const Config config)
  {
    State                    &state = state_of(scene(config, bm.range(0)));
    const auto                saved = state.particles;
    std::vector<Tensor<2, 2>> increments;
    interpolate_gradient(state, increments);
    state.particles = saved;
    std::vector<double>                volume_ratio;
    psmpm::Simulator::StabilityMonitor monitor;
    for (auto _ : bm)
      {
        Kernels::update_material(state, increments, volume_ratio, monitor);
        benchmark::ClobberMemory();
      }
    state.particles = saved;
    set_counters(bm, state);
  }

  void
  locate(benchmark::State &bm, const Config config, const bool hint)
  {
    State                    &state     = state_of(scene(config, bm.range(0)));
    const auto               &particles = state.particles;
    std::vector<unsigned int> cells(particles.size());
    for (auto _ : bm)
      {
        if (hint)
          for (std::size_t p = 0; p < particles.size(); ++p)
            cells[p] =
              state.locator.locate(particles.position[p], particles.cell[p]);
        else
          for (std::size_t p = 0; p < particles.size(); ++p)
            cells[p] = state.locator.locate(particles.position[p]);
        benchmark::DoNotOptimize(cells.data());
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
  }

  void
  evaluate(benchmark::State &bm, const Config config)
  {
    State                    &state     = state_of(scene(config, bm.range(0)));
    const auto               &particles = state.particles;
    const unsigned int        n         = state.space->dofs_per_cell();
    std::vector<double>       values(particles.size() * n);
    std::vector<Tensor<1, 2>> gradients(particles.size() * n);
    for (auto _ : bm)
      {
        state.space->evaluate(particles.size(),
                              particles.cell.data(),
                              particles.position.data(),
                              values.data(),
                              gradients.data());
        benchmark::DoNotOptimize(values.data());
        benchmark::DoNotOptimize(gradients.data());
        benchmark::ClobberMemory();
      }
    set_counters(bm, state);
  }

  void
  do_time_step(benchmark::State &bm, const Config config)
  {
    Simulator &simulator = scene(config, bm.range(0));
    for (auto _ : bm)
      simulator.do_time_step(simulator.get_time_step());
    if (simulator.get_failure() != psmpm::Simulator::Failure::none)
      bm.SkipWithError("the scene became unstable");
    set_counters(bm, simulator.get_state());
  }

  // ------------------------------------------------------------------
  // The machine.

  void
  triad(benchmark::State &bm)
  {
    const std::size_t   n = bm.range(0);
    std::vector<double> a(n, 0.), b(n, 1.), c(n, 2.);
    const double        s = 0.5;
    for (auto _ : bm)
      {
        double       *pa = a.data();
        const double *pb = b.data(), *pc = c.data();
        for (std::size_t i = 0; i < n; ++i)
          pa[i] = pb[i] + s * pc[i];
        benchmark::DoNotOptimize(a.data());
        benchmark::ClobberMemory();
      }
    bm.SetBytesProcessed(bm.iterations() * 3 * sizeof(double) * n);
  }

  void
  read(benchmark::State &bm)
  {
    const std::size_t   n = bm.range(0);
    std::vector<double> a(n, 1.);
    for (auto _ : bm)
      {
        // Eight running sums: a sum with one would be latency bound.
        double t[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (std::size_t i = 0; i + 7 < n; i += 8)
          for (unsigned int j = 0; j < 8; ++j)
            t[j] += a[i + j];
        double s = 0;
        for (unsigned int j = 0; j < 8; ++j)
          s += t[j];
        benchmark::DoNotOptimize(s);
      }
    bm.SetBytesProcessed(bm.iterations() * sizeof(double) * n);
  }

  constexpr unsigned int flop_loop = 4096;

  /// One chain x = x a + b: 2 flops per latency of a multiply and an add.
  void
  flops_dependent(benchmark::State &bm)
  {
    double x = 1, a = 0.999999, b = 1e-6;
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    for (auto _ : bm)
      {
        for (unsigned int i = 0; i < flop_loop; ++i)
          x = x * a + b;
        benchmark::DoNotOptimize(x);
      }
    bm.SetItemsProcessed(bm.iterations() * 2 * flop_loop);
  }

  /// Twelve independent chains, as this build compiles them (GCC 12 -O2
  /// packs them into SSE2 mulpd, addpd).
  void
  flops_independent_build(benchmark::State &bm)
  {
    double x[12], a = 0.999999, b = 1e-6;
    for (unsigned int j = 0; j < 12; ++j)
      x[j] = 1 + j;
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    for (auto _ : bm)
      {
        for (unsigned int i = 0; i < flop_loop; ++i)
          for (unsigned int j = 0; j < 12; ++j)
            x[j] = x[j] * a + b;
        benchmark::DoNotOptimize(x);
      }
    bm.SetItemsProcessed(bm.iterations() * 2 * 12 * flop_loop);
  }

  /// The same, kept scalar (mulsd, addsd): what the library's loops,
  /// which GCC -O2 leaves mostly scalar, can reach.
  __attribute__((optimize("no-tree-vectorize", "no-tree-slp-vectorize"))) void
  flops_independent_scalar(benchmark::State &bm)
  {
    double x[12], a = 0.999999, b = 1e-6;
    for (unsigned int j = 0; j < 12; ++j)
      x[j] = 1 + j;
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    for (auto _ : bm)
      {
        for (unsigned int i = 0; i < flop_loop; ++i)
          for (unsigned int j = 0; j < 12; ++j)
            x[j] = x[j] * a + b;
        benchmark::DoNotOptimize(x);
      }
    bm.SetItemsProcessed(bm.iterations() * 2 * 12 * flop_loop);
  }

  __attribute__((target("avx2,fma"))) void
  flops_avx2_fma(benchmark::State &bm)
  {
    __m256d x[12];
    for (unsigned int j = 0; j < 12; ++j)
      x[j] = _mm256_set1_pd(1. + j);
    __m256d a = _mm256_set1_pd(0.999999), b = _mm256_set1_pd(1e-6);
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    for (auto _ : bm)
      {
        for (unsigned int i = 0; i < flop_loop; ++i)
          for (unsigned int j = 0; j < 12; ++j)
            x[j] = _mm256_fmadd_pd(x[j], a, b);
        benchmark::DoNotOptimize(x);
      }
    bm.SetItemsProcessed(bm.iterations() * 2 * 4 * 12 * flop_loop);
  }

  __attribute__((target("avx512f"))) void
  flops_avx512_fma(benchmark::State &bm)
  {
    __m512d x[12];
    for (unsigned int j = 0; j < 12; ++j)
      x[j] = _mm512_set1_pd(1. + j);
    __m512d a = _mm512_set1_pd(0.999999), b = _mm512_set1_pd(1e-6);
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
    for (auto _ : bm)
      {
        for (unsigned int i = 0; i < flop_loop; ++i)
          for (unsigned int j = 0; j < 12; ++j)
            x[j] = _mm512_fmadd_pd(x[j], a, b);
        benchmark::DoNotOptimize(x);
      }
    bm.SetItemsProcessed(bm.iterations() * 2 * 8 * 12 * flop_loop);
  }

  // ------------------------------------------------------------------
  // Registration: per configuration every phase, then the whole step.

  // 64,000 particles: the particle arrays fit in the last-level cache
  // (P1); 320,000, the bar of prm/benchmark_throughput.prm: they do not.
  constexpr int default_blocks = 50;
  constexpr int large_blocks   = 250;

  void
  sizes(benchmark::internal::Benchmark *b)
  {
    b->Arg(default_blocks)->Arg(large_blocks)->Unit(benchmark::kMillisecond);
  }

  void
  locate_hint(benchmark::State &bm, const Config config)
  {
    locate(bm, config, true);
  }

  void
  locate_search(benchmark::State &bm, const Config config)
  {
    locate(bm, config, false);
  }

  /// Every phase of @p config as phase/name, in the order of the file's
  /// header, then the whole step.
  void
  register_phases(const char *name, const Config config)
  {
    using Phase = void (*)(benchmark::State &, Config);
    const std::array<std::pair<const char *, Phase>, 11> phases{
      {{"p2g_accumulate", p2g_accumulate},
       {"p2g_with_assembly", p2g_with_assembly},
       {"assemble_mass", assemble_mass},
       {"solve", solve},
       {"g2p_velocity", g2p_velocity},
       {"g2p_gradient", g2p_gradient},
       {"material_update", material_update},
       {"locate_hint", locate_hint},
       {"locate_search", locate_search},
       {"evaluate", evaluate},
       {"do_time_step", do_time_step}}};
    for (const auto &[phase, function] : phases)
      benchmark::RegisterBenchmark((std::string(phase) + "/" + name).c_str(),
                                   function,
                                   config)
        ->Apply(sizes);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);

  // Machine: 4 KiB (L1), 128 KiB (L2), 4 MiB (L3) and 64 MiB (memory) per
  // array.
  for (const long n : {1L << 9, 1L << 14, 1L << 19, 1L << 23})
    {
      benchmark::RegisterBenchmark("machine/triad", triad)->Arg(n);
      benchmark::RegisterBenchmark("machine/read", read)->Arg(n);
    }
  benchmark::RegisterBenchmark("machine/flops_dependent", flops_dependent);
  benchmark::RegisterBenchmark("machine/flops_independent_scalar",
                               flops_independent_scalar);
  benchmark::RegisterBenchmark("machine/flops_independent_build",
                               flops_independent_build);
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    benchmark::RegisterBenchmark("machine/flops_avx2_fma", flops_avx2_fma);
  if (__builtin_cpu_supports("avx512f"))
    benchmark::RegisterBenchmark("machine/flops_avx512_fma", flops_avx512_fma);

  register_phases("p1_lumped", p1_lumped);
  register_phases("ps_lumped", ps_lumped);
  register_phases("ps_consistent", ps_consistent);

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // Trilinos objects before MPI_Finalize.
  scenes().clear();
  return 0;
}
