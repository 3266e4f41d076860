// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Solver::DenseCholesky (the direct solver of small mass systems):
// (a) on SPD sparse matrices with a narrow envelope (a 1D chain) and a
//     wide one (a 2D grid numbered column by column, with random
//     perturbations of the entries), its solution has a residual below
//     1e-13 of |b| and agrees with Jacobi-CG to 1e-9;
// (b) a matrix with a zero row and a symmetric indefinite one are refused
//     (factorize() returns false) rather than giving a wrong answer;
// (c) the large vibrating bar (78 DoFs, consistent mass) with the direct
//     solver (the default for its size) and with CG (Direct solver size
//     = 0) ends with the same displacement error to 1e-8 relative, and
//     the direct run reports no CG iterations;
// (d) the thesis bar on a diagonal mesh one block high, P1 and
//     Powell-Sabin: every vertex lies on the boundary, so the Dirichlet
//     conditions fix every y DoF of P1 and that component is neither
//     assembled nor solved. The direct run (with that short cut) and the
//     CG run (the components solved together, no short cut) end with the
//     same displacement error to 1e-8 relative, and P1's y momentum stays
//     exactly zero in both;
// (e) numberings with a wide envelope are factored in Cuthill-McKee
//     order: a chain numbered at random and a 40 x 3 strip numbered
//     across its length give the residual and agreement of (a), and the
//     factor's envelope is the chain's n - 1 and at most a quarter of the
//     strip's as numbered.
#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <psmpm/solver/dense_cholesky.h>

#include "../mpm_tests.h"

#include <algorithm>
#include <filesystem>
#include <random>

namespace
{
  /// Symmetric matrix with the given off-diagonal pairs, diagonal d.
  TrilinosWrappers::SparseMatrix
  make_matrix(const unsigned int                                        n,
              const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
              const std::vector<double>                                &off,
              const std::vector<double> &diagonal)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      dsp.add(i, i);
    for (const auto &[i, j] : pairs)
      {
        dsp.add(i, j);
        dsp.add(j, i);
      }
    TrilinosWrappers::SparseMatrix A;
    A.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      A.set(i, i, diagonal[i]);
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        A.set(pairs[k].first, pairs[k].second, off[k]);
        A.set(pairs[k].second, pairs[k].first, off[k]);
      }
    A.compress(VectorOperation::insert);
    return A;
  }

  /// Solves an SPD matrix with the given off-diagonal pattern and checks
  /// the solution; returns the envelope of the factor.
  std::size_t
  check_spd(std::ostream                                             &out,
            const std::string                                        &name,
            const unsigned int                                        n,
            const std::vector<std::pair<unsigned int, unsigned int>> &pairs)
  {
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::vector<double>                    off(pairs.size()), diagonal(n, 0.);
    // Diagonally dominant with random entries: SPD.
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        off[k] = -u(random);
        diagonal[pairs[k].first] -= off[k];
        diagonal[pairs[k].second] -= off[k];
      }
    for (auto &d : diagonal)
      d += u(random);
    const auto A = make_matrix(n, pairs, off, diagonal);

    TrilinosWrappers::MPI::Vector b(complete_index_set(n), MPI_COMM_WORLD),
      x(b), y(b), r(b);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(0.1 * i) + 0.3;
    b.compress(VectorOperation::insert);
    psmpm::Solver::DenseCholesky dense;
    const bool                   ok = dense.factorize(A);
    dense.solve(b, x);
    A.vmult(r, x);
    r -= b;
    SolverControl                           control(1000, 1e-14 * b.l2_norm());
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    TrilinosWrappers::PreconditionJacobi    jacobi;
    jacobi.initialize(A);
    cg.solve(A, y, b, jacobi);
    y -= x;
    out << name << ": n = " << n << std::endl;
    PSMPM_CHECK(out, ok);
    PSMPM_CHECK(out, r.l2_norm() <= 1e-13 * b.l2_norm());
    PSMPM_CHECK(out, y.l2_norm() <= 1e-9 * x.l2_norm());
    return dense.envelope();
  }

  /// Sum over the rows of i - (the first column j <= i of row i): the
  /// envelope of @p pairs as numbered.
  std::size_t
  envelope(const unsigned int                                        n,
           const std::vector<std::pair<unsigned int, unsigned int>> &pairs)
  {
    std::vector<unsigned int> first(n);
    for (unsigned int i = 0; i < n; ++i)
      first[i] = i;
    for (const auto &[i, j] : pairs)
      first[std::max(i, j)] = std::min(first[std::max(i, j)], std::min(i, j));
    std::size_t sum = 0;
    for (unsigned int i = 0; i < n; ++i)
      sum += i - first[i];
    return sum;
  }
  /// Runs @p scene with @p overrides into @p directory, checks that it
  /// completes, and returns its statistics.
  StatisticsTable
  run_scene(std::ostream                   &out,
            const std::string              &scene,
            const std::vector<std::string> &overrides,
            const std::string              &directory)
  {
    auto solver = make_scene_solver(scene, overrides);
    std::filesystem::create_directories(directory);
    const auto status = solver->run(directory);
    PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);
    return StatisticsTable(directory);
  }

  /// The last displacement error of a run.
  double
  final_error(const StatisticsTable &s)
  {
    const auto e = s.column("displacement_L2");
    return e.empty() ? std::nan("") : e.back();
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");

  out << "(a) SPD matrices" << std::endl;
  std::vector<std::pair<unsigned int, unsigned int>> chain, grid;
  for (unsigned int i = 0; i + 1 < 60; ++i)
    chain.emplace_back(i, i + 1);
  check_spd(out, "chain", 60, chain);
  const unsigned int m = 15; // 15 x 15 grid, column-major numbering
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < m; ++j)
      {
        if (i + 1 < m)
          grid.emplace_back(i * m + j, (i + 1) * m + j);
        if (j + 1 < m)
          grid.emplace_back(i * m + j, i * m + j + 1);
        if (i + 1 < m && j + 1 < m)
          grid.emplace_back(i * m + j, (i + 1) * m + j + 1);
      }
  check_spd(out, "grid", m * m, grid);

  out << "(b) refused matrices" << std::endl;
  {
    psmpm::Solver::DenseCholesky dense;
    const auto zero_row = make_matrix(3, {{0, 1}}, {0.5}, {2., 1., 0.});
    PSMPM_CHECK(out, !dense.factorize(zero_row));
    const auto indefinite = make_matrix(2, {{0, 1}}, {2.}, {1., 1.});
    PSMPM_CHECK(out, !dense.factorize(indefinite));
  }

  out << "(c) large vibrating bar, direct against CG" << std::endl;
  double error[2];
  for (const unsigned int size : {1000u, 0u})
    {
      const StatisticsTable s =
        run_scene(out,
                  "vibrating_bar_large.prm",
                  {"Time/End time=0.5",
                   "Output/Interval=0",
                   "Mass matrix/Direct solver size=" + std::to_string(size)},
                  "run-" + std::to_string(size));
      double total = 0;
      for (const double c : s.column("cg_iterations"))
        total += c;
      out << "direct solver size " << size << ": CG iterations "
          << (total > 0 ? "> 0" : "0") << std::endl;
      PSMPM_CHECK(out, (size > 0) == (total == 0));
      error[size > 0 ? 0 : 1] = final_error(s);
    }
  PSMPM_CHECK(out, std::abs(error[0] / error[1] - 1) < 1e-8);

  out << "(d) thesis bar on a diagonal mesh, y fixed everywhere" << std::endl;
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      double bar_error[2];
      for (const unsigned int size : {1000u, 0u})
        {
          const StatisticsTable s =
            run_scene(out,
                      "vibrating_bar_small.prm",
                      {"Mesh/Type=diagonal",
                       "Mesh/Blocks x=8",
                       "Basis/Type=" + basis,
                       "Time/End time=0.005",
                       "Output/Interval=0",
                       "Mass matrix/Direct solver size=" +
                         std::to_string(size)},
                      "bar-" + basis + "-" + std::to_string(size));
          double largest = 0;
          for (const double m : s.column("momentum_y"))
            largest = std::max(largest, std::abs(m));
          out << basis << ", direct solver size " << size << std::endl;
          // Powell-Sabin's inner control points are free: its y is solved.
          if (basis == "linear")
            PSMPM_CHECK(out, largest == 0);
          bar_error[size > 0 ? 0 : 1] = final_error(s);
        }
      PSMPM_CHECK(out, std::abs(bar_error[0] / bar_error[1] - 1) < 1e-8);
    }

  out << "(e) wide numberings, factored in Cuthill-McKee order" << std::endl;
  {
    std::vector<unsigned int> label(60);
    for (unsigned int i = 0; i < 60; ++i)
      label[i] = i;
    std::shuffle(label.begin(), label.end(), std::mt19937(11));
    std::vector<std::pair<unsigned int, unsigned int>> shuffled;
    for (const auto &[i, j] : chain)
      shuffled.emplace_back(label[i], label[j]);
    const std::size_t factored = check_spd(out, "shuffled chain", 60, shuffled);
    out << "envelope as numbered " << envelope(60, shuffled) << ", factored "
        << factored << std::endl;
    PSMPM_CHECK(out, factored == 59);

    // 40 x 3 nodes, numbered along the long side first: a row reaches 40
    // back.
    const unsigned int                                 nx = 40, ny = 3;
    std::vector<std::pair<unsigned int, unsigned int>> strip;
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          if (i + 1 < nx)
            strip.emplace_back(j * nx + i, j * nx + i + 1);
          if (j + 1 < ny)
            strip.emplace_back(j * nx + i, (j + 1) * nx + i);
          if (i + 1 < nx && j + 1 < ny)
            strip.emplace_back(j * nx + i, (j + 1) * nx + i + 1);
        }
    const std::size_t as_numbered    = envelope(nx * ny, strip);
    const std::size_t strip_factored = check_spd(out, "strip", nx * ny, strip);
    out << "envelope as numbered " << as_numbered << ", factored "
        << strip_factored << std::endl;
    PSMPM_CHECK(out, 4 * strip_factored <= as_numbered);
  }
}
