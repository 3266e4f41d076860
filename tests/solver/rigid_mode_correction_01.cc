// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Solver::RigidModeCorrection on M = the Q1 mass matrix of a 6 x 5 grid
// (it reproduces 1, x and y with the vertices as control points) plus one
// row coupled to no other (diagonal 2), components x and y, right-hand
// sides b, and a guess x = the exact solution plus a smooth error:
// (a) both components free: afterwards R^T (b - M x) vanishes to 1e-13
//     of R^T b for the translations and the rotation (before: not), the
//     decoupled row holds b / 2 exactly, and the error in the M norm does
//     not grow (the correction is the M-orthogonal projection of the
//     error onto the modes);
// (b) only x free: the y column is left bit for bit, and x's
//     translation residual vanishes;
// (c) no component free: nothing changes;
// (d) every control point at one place (the rotation is a combination of
//     the translations, the modes' matrix singular): nothing changes.
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <psmpm/solver/rigid_mode_correction.h>

#include "../tests.h"
#include "q1_mass.h"

#include <Epetra_MultiVector.h>

namespace
{
  /// R^T (b - M x) for the modes (1, 0), (0, 1), (-y, x).
  std::array<double, 3>
  mode_residuals(const Epetra_CrsMatrix      &M,
                 const std::vector<Point<2>> &points,
                 const Epetra_MultiVector    &b,
                 const Epetra_MultiVector    &x)
  {
    Epetra_MultiVector Mx(M.RowMap(), 2);
    M.Multiply(false, x, Mx);
    std::array<double, 3> g{};
    for (unsigned int j = 0; j < points.size(); ++j)
      {
        const double rx = b[0][j] - Mx[0][j], ry = b[1][j] - Mx[1][j];
        g[0] += rx;
        g[1] += ry;
        g[2] += -points[j][1] * rx + points[j][0] * ry;
      }
    return g;
  }

  /// sqrt(e^T M e) over both columns, e = x - y.
  double
  error_norm(const Epetra_CrsMatrix   &M,
             const Epetra_MultiVector &x,
             const Epetra_MultiVector &y)
  {
    Epetra_MultiVector e(x), Me(M.RowMap(), 2);
    e.Update(-1., y, 1.);
    M.Multiply(false, e, Me);
    double s = 0;
    for (int d = 0; d < 2; ++d)
      for (int j = 0; j < e.MyLength(); ++j)
        s += e[d][j] * Me[d][j];
    return std::sqrt(s);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  return run_test([&out]() {
    const Q1Mass          q1(Point<2>(0.3, -0.2), Point<2>(1.5, 0.8));
    const auto           &Mq = q1.matrix;
    const unsigned int    nv = Mq.m(), n = nv + 1;
    std::vector<Point<2>> points = q1.support;
    points.emplace_back(2.0, 3.0); // the decoupled row's

    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < nv; ++i)
      for (auto e = Mq.begin(i); e != Mq.end(i); ++e)
        dsp.add(i, e->column());
    dsp.add(nv, nv);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < nv; ++i)
      for (auto e = Mq.begin(i); e != Mq.end(i); ++e)
        A.set(i, e->column(), e->value());
    A.set(nv, nv, 2.);
    A.compress(VectorOperation::insert);
    const Epetra_CrsMatrix &M = A.trilinos_matrix();

    // Exact solution, its right-hand side and a guess with a smooth error.
    Epetra_MultiVector exact(M.RowMap(), 2), b(M.RowMap(), 2),
      guess(M.RowMap(), 2);
    for (unsigned int j = 0; j < n; ++j)
      for (int d = 0; d < 2; ++d)
        {
          exact[d][j] = std::sin(1.3 * points[j][0] + d) * points[j][1] + 0.7;
          guess[d][j] = exact[d][j] + 1e-3 * std::cos(2.1 * points[j][0] -
                                                      0.4 * d + points[j][1]);
        }
    M.Multiply(false, exact, b);

    std::vector<long long> rows(n);
    for (unsigned int j = 0; j < n; ++j)
      rows[j] = j;
    const auto correction = [&](const std::vector<Point<2>> &p) {
      psmpm::Solver::RigidModeCorrection<2> c;
      c.reinit(std::vector<long long>(rows), std::vector<Point<2>>(p));
      return c;
    };

    {
      const auto before = mode_residuals(M, points, b, guess);
      double     scale  = 0;
      for (const double g : mode_residuals(M, points, b, b))
        scale = std::max(scale, std::abs(g));
      Epetra_MultiVector x(guess);
      auto               c = correction(points);
      c.correct(M, {{true, true}}, b, x);
      const auto after = mode_residuals(M, points, b, x);
      for (unsigned int k = 0; k < 3; ++k)
        {
          PSMPM_CHECK(out, std::abs(before[k]) > 1e-8 * scale);
          PSMPM_CHECK(out, std::abs(after[k]) < 1e-13 * scale);
        }
      PSMPM_CHECK(out, x[0][nv] == b[0][nv] / 2 && x[1][nv] == b[1][nv] / 2);
      PSMPM_CHECK(out, error_norm(M, x, exact) <= error_norm(M, guess, exact));
    }
    {
      Epetra_MultiVector x(guess);
      auto               c = correction(points);
      c.correct(M, {{true, false}}, b, x);
      bool y_kept = true;
      for (unsigned int j = 0; j < nv; ++j)
        y_kept = y_kept && x[1][j] == guess[1][j];
      PSMPM_CHECK(out, y_kept);
      PSMPM_CHECK(out,
                  std::abs(mode_residuals(M, points, b, x)[0]) <
                    1e-13 * std::abs(mode_residuals(M, points, b, b)[0]));
    }
    const auto unchanged = [&](const std::vector<Point<2>> &p,
                               const std::array<bool, 2>    free) {
      Epetra_MultiVector x(guess);
      auto               c = correction(p);
      c.correct(M, free, b, x);
      bool same = true;
      for (int d = 0; d < 2; ++d)
        for (unsigned int j = 0; j < nv; ++j)
          same = same && x[d][j] == guess[d][j];
      return same;
    };
    PSMPM_CHECK(out, unchanged(points, {{false, false}}));
    PSMPM_CHECK(out,
                unchanged(std::vector<Point<2>>(n, Point<2>(0.5, 0.5)),
                          {{true, true}}));
  });
}
