// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Solver::VertexBlockJacobi (Mass matrix/Preconditioner = block jacobi):
// (a) on a block-diagonal SPD matrix of 3 x 3 blocks it is the exact
//     inverse: A P b = b to 1e-14;
// (b) a block that is not positive definite falls back to its diagonal
//     (counted), the other blocks stay exact;
// (c) owned rows that are not whole blocks are refused with a message;
// (d) the thesis bar (Powell-Sabin, consistent mass, 8 blocks, every
//     system through CG: Direct solver size = 0) with point and block
//     Jacobi: block Jacobi needs at most 0.6 of the CG iterations and
//     ends with the same displacement error to 1e-8 relative;
// (e) the entry positions kept for a numbered sparsity pattern: on a
//     matrix that couples the blocks, a set-up after new values with the
//     same pattern number, and one for another pattern under a new
//     number, give bit for bit the inverse of a set-up that searches
//     afresh (pattern 0), and the new values are seen.
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <psmpm/solver/vertex_block_jacobi.h>

#include "../mpm_tests.h"

#include <cstring>
#include <filesystem>

namespace
{
  /// Block-diagonal matrix of 3 x 3 blocks: block b is B_b (row-major).
  TrilinosWrappers::SparseMatrix
  block_matrix(const std::vector<std::array<double, 9>> &blocks)
  {
    const unsigned int     n = 3 * blocks.size();
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          dsp.add(3 * b + i, 3 * b + j);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          A.set(3 * b + i, 3 * b + j, blocks[b][3 * i + j]);
    A.compress(VectorOperation::insert);
    return A;
  }

  /// 3 x 3 blocks on the diagonal, coupled to their neighbours at
  /// distance @p reach blocks (a pattern with entries outside the
  /// blocks, at positions that depend on @p reach), the values a function
  /// of the indices and @p scale (diagonally dominant).
  TrilinosWrappers::SparseMatrix
  coupled_matrix(const unsigned int n_blocks,
                 const unsigned int reach,
                 const double       scale)
  {
    const unsigned int     n = 3 * n_blocks;
    DynamicSparsityPattern dsp(n, n);
    const auto coupled = [&](const unsigned int i, const unsigned int j) {
      const unsigned int bi = i / 3, bj = j / 3;
      return bi == bj || bi == bj + reach || bj == bi + reach;
    };
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (coupled(i, j))
          dsp.add(i, j);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (coupled(i, j))
          A.set(i,
                j,
                i == j ? 8 * scale :
                         scale * 0.3 * std::cos(0.37 * (i + 1) * (j + 1)));
    A.compress(VectorOperation::insert);
    return A;
  }

  TrilinosWrappers::MPI::Vector
  vector(const unsigned int n)
  {
    TrilinosWrappers::MPI::Vector v(complete_index_set(n), MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      v[i] = std::sin(0.7 * i) + 0.2;
    v.compress(VectorOperation::insert);
    return v;
  }

  /// Total CG iterations and final displacement error of the thesis bar.
  std::pair<double, double>
  thesis_bar(const std::string &preconditioner)
  {
    auto solver =
      make_scene_solver("vibrating_bar_small_ps.prm",
                        {"Mesh/Blocks x=8",
                         "Time/End time=0.002",
                         "Output/Interval=0",
                         "Mass matrix/Direct solver size=0",
                         "Mass matrix/Preconditioner=" + preconditioner});
    const std::string dir = "run-" + preconditioner.substr(0, 5);
    std::filesystem::create_directories(dir);
    AssertThrow(solver->run(dir) == psmpm::Simulator::Status::completed,
                ExcMessage("thesis bar did not complete"));
    const StatisticsTable s(dir);
    double                total = 0;
    for (const double c : s.column("cg_iterations"))
      total += c;
    return {total, s.column("displacement_L2").back()};
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  using psmpm::Solver::VertexBlockJacobi;

  out << "(a) exact inverse of a block-diagonal matrix" << std::endl;
  const std::array<double, 9> spd1 = {4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2};
  const std::array<double, 9> spd2 = {2, -0.9, 0, -0.9, 1, 0.3, 0, 0.3, 5};
  {
    const auto        A = block_matrix({spd1, spd2, spd1});
    VertexBlockJacobi P;
    P.initialize(A, 3);
    const auto b = vector(9);
    auto       x = b, r = b;
    P.vmult(x, b);
    A.vmult(r, x);
    r -= b;
    PSMPM_CHECK(out, r.l2_norm() <= 1e-14 * b.l2_norm());
    PSMPM_CHECK(out, P.n_diagonal_fallbacks() == 0);
  }

  out << "(b) a block that is not positive definite" << std::endl;
  {
    const std::array<double, 9> singular = {1, 1, 0, 1, 1, 0, 0, 0, 2};
    const auto                  A        = block_matrix({spd1, singular, spd2});
    VertexBlockJacobi           P;
    P.initialize(A, 3);
    const auto b = vector(9);
    auto       x = b, r = b;
    P.vmult(x, b);
    PSMPM_CHECK(out, P.n_diagonal_fallbacks() == 1);
    PSMPM_CHECK(out, std::abs(x[3] - b[3] / 1.) < 1e-15);
    PSMPM_CHECK(out, std::abs(x[5] - b[5] / 2.) < 1e-15);
    A.vmult(r, x);
    double first = 0, last = 0;
    for (unsigned int i = 0; i < 3; ++i)
      {
        first = std::max(first, std::abs(r[i] - b[i]));
        last  = std::max(last, std::abs(r[6 + i] - b[6 + i]));
      }
    PSMPM_CHECK(out, first < 1e-14 && last < 1e-14);
  }

  out << "(c) rows that are not whole blocks" << std::endl;
  {
    const auto        A = block_matrix({spd1, spd2});
    VertexBlockJacobi P;
    std::string       message;
    try
      {
        P.initialize(A, 4);
      }
    catch (const ExceptionBase &e)
      {
        message = e.get_exc_name() + std::string(e.what());
      }
    PSMPM_CHECK(out,
                message.find("not whole blocks of 4") != std::string::npos);
  }

  out << "(d) thesis bar, point against block Jacobi" << std::endl;
  const auto point = thesis_bar("jacobi");
  const auto block = thesis_bar("block jacobi");
  out << "CG iterations block / point = " << std::setprecision(2)
      << block.first / point.first << std::endl;
  PSMPM_CHECK(out, block.first <= 0.6 * point.first);
  PSMPM_CHECK(out, std::abs(block.second / point.second - 1) < 1e-8);

  out << "(e) entry positions kept per sparsity pattern" << std::endl;
  {
    const auto b     = vector(30);
    const auto apply = [&](const VertexBlockJacobi &P) {
      auto x = b;
      P.vmult(x, b);
      return x;
    };
    const auto fresh = [&](const TrilinosWrappers::SparseMatrix &A) {
      VertexBlockJacobi Q;
      Q.initialize(A, 3, {1, 14});
      return apply(Q);
    };
    const auto same_bits = [](const TrilinosWrappers::MPI::Vector &x,
                              const TrilinosWrappers::MPI::Vector &y) {
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const double a = x[i], c = y[i];
          if (std::memcmp(&a, &c, sizeof(double)) != 0)
            return false;
        }
      return true;
    };
    VertexBlockJacobi P;
    const auto        A1 = coupled_matrix(10, 1, 1.);
    P.initialize(A1, 3, {1, 14}, 7);
    const auto x1 = apply(P);
    PSMPM_CHECK(out, same_bits(x1, fresh(A1)));
    // New values, same pattern and number: the kept positions.
    const auto A2 = coupled_matrix(10, 1, 2.);
    P.initialize(A2, 3, {1, 14}, 7);
    const auto x2 = apply(P);
    PSMPM_CHECK(out, same_bits(x2, fresh(A2)));
    PSMPM_CHECK(out, !same_bits(x2, x1));
    // Another pattern (couplings at distance 2: other positions) under a
    // new number.
    const auto A3 = coupled_matrix(10, 2, 3.);
    P.initialize(A3, 3, {1, 14}, 8);
    PSMPM_CHECK(out, same_bits(apply(P), fresh(A3)));
  }
}
