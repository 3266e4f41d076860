// ---------------------------------------------------------------------
// psmpm: cost of evaluating the non-zero basis functions of a cell (values
// and gradients) at a point: the 9 Powell-Sabin functions against the 3
// linear ones. Points are random, in random cells of a 32 x 32 diagonal
// mesh of the unit square (2048 cells), as particles would be.
//
//   basis_evaluation --benchmark_counters_tabular=true
//
// The counter "time_per_point" is the wall time per point. "batch" uses
// the one-call-per-batch interface; "sorted_by_cell" orders the points by
// cell as an MPM loop over cells would, so cell data stays in cache.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>

#include <algorithm>
#include <benchmark/benchmark.h>
#include <memory>
#include <random>
#include <vector>

namespace
{
  using namespace dealii;

  struct Setup
  {
    Triangulation<2>                        tria;
    std::unique_ptr<DoFHandler<2>>          dof_handler;
    std::unique_ptr<psmpm::Basis::Space<2>> space;
    std::vector<unsigned int>               cells;
    std::vector<Point<2>>                   points;

    Setup(const std::string &name,
          const unsigned int n_points,
          const bool         sorted = false)
    {
      psmpm::Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(1, 1),
        32,
        32,
        psmpm::Mesh::MeshGenerator<2>::Type::diagonal);
      space       = psmpm::Basis::create_space<2>(name);
      dof_handler = std::make_unique<DoFHandler<2>>(tria);
      dof_handler->distribute_dofs(space->dof_layout());
      space->reinit(*dof_handler);

      std::mt19937                           rng(42);
      std::uniform_real_distribution<double> u(0, 1);
      std::vector<std::array<Point<2>, 3>>   vertices;
      for (const auto &cell : tria.active_cell_iterators())
        vertices.push_back(
          {{cell->vertex(0), cell->vertex(1), cell->vertex(2)}});
      for (unsigned int i = 0; i < n_points; ++i)
        {
          const unsigned int c = rng() % vertices.size();
          double             a = u(rng), b = u(rng);
          if (a + b > 1)
            {
              a = 1 - a;
              b = 1 - b;
            }
          const auto &v = vertices[c];
          cells.push_back(c);
          points.push_back(
            Point<2>(v[0] + a * (v[1] - v[0]) + b * (v[2] - v[0])));
        }
      if (sorted)
        {
          // As an MPM loop over cells sees its particles.
          std::vector<unsigned int> order(n_points);
          for (unsigned int i = 0; i < n_points; ++i)
            order[i] = i;
          std::sort(order.begin(), order.end(), [this](unsigned a, unsigned b) {
            return cells[a] < cells[b];
          });
          std::vector<unsigned int> c2;
          std::vector<Point<2>>     p2;
          for (const unsigned int i : order)
            {
              c2.push_back(cells[i]);
              p2.push_back(points[i]);
            }
          cells.swap(c2);
          points.swap(p2);
        }
    }
  };

  void
  evaluate_single(benchmark::State &state, const std::string &name)
  {
    const unsigned int        n = 4096;
    Setup                     s(name, n);
    const unsigned int        m = s.space->dofs_per_cell();
    std::vector<double>       values(m);
    std::vector<Tensor<1, 2>> gradients(m);
    for (auto _ : state)
      for (unsigned int i = 0; i < n; ++i)
        {
          s.space->evaluate(s.cells[i],
                            s.points[i],
                            values.data(),
                            gradients.data());
          benchmark::DoNotOptimize(values.data());
          benchmark::DoNotOptimize(gradients.data());
        }
    state.counters["time_per_point"] =
      benchmark::Counter(double(n),
                         benchmark::Counter::kIsIterationInvariantRate |
                           benchmark::Counter::kInvert);
  }

  void
  evaluate_batch(benchmark::State  &state,
                 const std::string &name,
                 const bool         sorted)
  {
    const unsigned int        n = 4096;
    Setup                     s(name, n, sorted);
    const unsigned int        m = s.space->dofs_per_cell();
    std::vector<double>       values(m * n);
    std::vector<Tensor<1, 2>> gradients(m * n);
    for (auto _ : state)
      {
        s.space->evaluate(n,
                          s.cells.data(),
                          s.points.data(),
                          values.data(),
                          gradients.data());
        benchmark::DoNotOptimize(values.data());
        benchmark::DoNotOptimize(gradients.data());
      }
    state.counters["time_per_point"] =
      benchmark::Counter(double(n),
                         benchmark::Counter::kIsIterationInvariantRate |
                           benchmark::Counter::kInvert);
  }
} // namespace

BENCHMARK_CAPTURE(evaluate_single, powell_sabin, std::string("powell-sabin"));
BENCHMARK_CAPTURE(evaluate_single, linear, std::string("linear"));
BENCHMARK_CAPTURE(evaluate_batch,
                  powell_sabin,
                  std::string("powell-sabin"),
                  false);
BENCHMARK_CAPTURE(evaluate_batch, linear, std::string("linear"), false);
BENCHMARK_CAPTURE(evaluate_batch,
                  powell_sabin_sorted_by_cell,
                  std::string("powell-sabin"),
                  true);
BENCHMARK_CAPTURE(evaluate_batch,
                  linear_sorted_by_cell,
                  std::string("linear"),
                  true);

BENCHMARK_MAIN();
