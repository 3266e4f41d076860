// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Solver::ComponentCG (the components' mass solves through one matrix):
// on M = M_Q1 (x) K, M_Q1 the Q1 mass matrix of a 6 x 5 grid and K an
// SPD 3 x 3 coupling (so every vertex block of 3 DoFs is coupled, as for
// Powell-Sabin), with column 0 fixed on all DoFs of the vertices at
// x = 0 and column 1 fixed on the first DoF of the vertices at y = 0,
// and a zero third column:
// (a) each column equals separate SolverCG solves with the constrained
//     matrix P_d M P_d + (I - P_d) and VertexBlockJacobi on it, to 1e-10
//     relative, with the same iteration count (+-1) and the same
//     condition-number estimate to 1e-6;
// (b) fixed entries are exactly zero, the zero column takes 0 iterations;
// (c) a column that needs more than Maximum iterations throws
//     SolverControl::NoConvergence;
// (d) after reinit() the rows are recognised as vertex triples and the
//     blocked product gives the same solution to 1e-12 relative and the
//     same iterations +-1;
// (e) a warm start from 0.99 x the solution (fixed rows zero) needs
//     fewer iterations, ends at the same solution to 1e-10, and the
//     stopping test stays relative to |b|: from the solution itself,
//     0 iterations;
// (f) with a step tolerance of 1e-4 the warm start of (e) ends once
//     ||r_d|| <= 1e-4 ||r_d(guess)|| (checked on b - M x recomputed),
//     in fewer iterations than (e); from a zero guess the step tolerance
//     changes nothing (same iterations as (a)).
#include <deal.II/base/function.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>

#include <psmpm/solver/component_cg.h>

#include "../tests.h"
#include "q1_mass.h"

#include <Epetra_MultiVector.h>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  return run_test([&out]() {
    const Q1Mass       q1(Point<2>(0, 0), Point<2>(1.2, 1));
    const auto        &Mq      = q1.matrix;
    const unsigned int nv      = Mq.m();
    const auto        &support = q1.support;

    const double           K[3][3] = {{2, 1, 0.5}, {1, 2, 1}, {0.5, 1, 2}};
    const unsigned int     n       = 3 * nv;
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < nv; ++i)
      for (auto e = Mq.begin(i); e != Mq.end(i); ++e)
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            dsp.add(3 * i + a, 3 * e->column() + b);
    // Fixed rows per column, and the constrained matrices of (a).
    std::vector<std::vector<unsigned int>> fixed(3);
    for (unsigned int i = 0; i < nv; ++i)
      {
        if (support[i][0] < 1e-12)
          for (unsigned int a = 0; a < 3; ++a)
            fixed[0].push_back(3 * i + a);
        if (support[i][1] < 1e-12)
          fixed[1].push_back(3 * i);
      }
    const auto is_fixed = [&fixed](const unsigned int d, const unsigned int i) {
      return std::binary_search(fixed[d].begin(), fixed[d].end(), i);
    };
    const auto assemble = [&](const int d) {
      TrilinosWrappers::SparseMatrix A;
      A.reinit(complete_index_set(n),
               complete_index_set(n),
               dsp,
               MPI_COMM_WORLD);
      for (unsigned int i = 0; i < nv; ++i)
        for (auto e = Mq.begin(i); e != Mq.end(i); ++e)
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              {
                const unsigned int r = 3 * i + a, c = 3 * e->column() + b;
                if (d >= 0 && (is_fixed(d, r) || is_fixed(d, c)))
                  continue;
                A.set(r, c, e->value() * K[a][b]);
              }
      if (d >= 0)
        for (const unsigned int r : fixed[d])
          A.set(r, r, 1.);
      A.compress(VectorOperation::insert);
      return A;
    };
    const TrilinosWrappers::SparseMatrix M = assemble(-1);

    const Epetra_Map  &map = M.trilinos_matrix().RowMap();
    Epetra_MultiVector b(map, 3), x(map, 3);
    for (unsigned int d = 0; d < 2; ++d)
      for (unsigned int i = 0; i < n; ++i)
        b[d][i] = is_fixed(d, i) ? 0. : std::sin(0.37 * i + d) + 0.3;
    std::vector<psmpm::Solver::VertexBlockJacobi>         masked(3);
    std::vector<const psmpm::Solver::VertexBlockJacobi *> preconditioners;
    for (unsigned int d = 0; d < 3; ++d)
      {
        masked[d].initialize(M, 3, fixed[d]);
        preconditioners.push_back(&masked[d]);
      }
    psmpm::Solver::ComponentCG cg;
    const auto                 result = cg.solve(M.trilinos_matrix(),
                                 preconditioners,
                                 fixed,
                                 x,
                                 b,
                                 1e-12,
                                 {0., 0., 0.},
                                 1000);

    out << "DoFs " << n << ", fixed " << fixed[0].size() << " / "
        << fixed[1].size() << ", iterations " << result.iterations[0] << " / "
        << result.iterations[1] << " / " << result.iterations[2] << std::endl;
    double max_condition = 0;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const TrilinosWrappers::SparseMatrix A = assemble(d);
        psmpm::Solver::VertexBlockJacobi     P;
        P.initialize(A, 3);
        TrilinosWrappers::MPI::Vector rhs(complete_index_set(n),
                                          MPI_COMM_WORLD),
          solution(rhs);
        for (unsigned int i = 0; i < n; ++i)
          rhs[i] = b[d][i];
        SolverControl control(1000, 1e-12 * rhs.l2_norm(), false, false);
        SolverCG<TrilinosWrappers::MPI::Vector> solver(control);
        double                                  condition = 0;
        solver.connect_condition_number_slot(
          [&condition](const double c) { condition = c; });
        solver.solve(A, solution, rhs, P);
        max_condition     = std::max(max_condition, condition);
        double difference = 0, fixed_max = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            difference = std::max(difference, std::abs(x[d][i] - solution[i]));
            if (is_fixed(d, i))
              fixed_max = std::max(fixed_max, std::abs(x[d][i]));
          }
        const int dit = int(result.iterations[d]) - int(control.last_step());
        out << "column " << d << ": SolverCG " << control.last_step()
            << " iterations" << std::endl;
        PSMPM_CHECK(out, difference <= 1e-10 * solution.linfty_norm());
        PSMPM_CHECK(out, std::abs(dit) <= 1);
        PSMPM_CHECK(out, fixed_max == 0);
      }
    PSMPM_CHECK(out,
                std::abs(result.condition_number - max_condition) <=
                  1e-6 * max_condition);
    PSMPM_CHECK(out, result.iterations[2] == 0);
    double zero_column = 0;
    for (unsigned int i = 0; i < n; ++i)
      zero_column = std::max(zero_column, std::abs(x[2][i]));
    PSMPM_CHECK(out, zero_column == 0);

    out << "triples before reinit: " << cg.uses_triples() << std::endl;
    cg.reinit(M.trilinos_matrix());
    out << "triples after reinit: " << cg.uses_triples() << std::endl;
    Epetra_MultiVector x_blocked(map, 3);
    const auto         blocked = cg.solve(M.trilinos_matrix(),
                                  preconditioners,
                                  fixed,
                                  x_blocked,
                                  b,
                                  1e-12,
                                  {0., 0., 0.},
                                  1000);
    for (unsigned int d = 0; d < 2; ++d)
      {
        double difference = 0, size = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            difference =
              std::max(difference, std::abs(x_blocked[d][i] - x[d][i]));
            size = std::max(size, std::abs(x[d][i]));
          }
        PSMPM_CHECK(out, difference <= 1e-12 * size);
        PSMPM_CHECK(out,
                    std::abs(int(blocked.iterations[d]) -
                             int(result.iterations[d])) <= 1);
      }

    Epetra_MultiVector x_warm(map, 3);
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int i = 0; i < n; ++i)
        x_warm[d][i] = 0.99 * x[d][i];
    const auto warm = cg.solve(M.trilinos_matrix(),
                               preconditioners,
                               fixed,
                               x_warm,
                               b,
                               1e-12,
                               {0., 0., 0.},
                               1000);
    out << "warm start iterations " << warm.iterations[0] << " / "
        << warm.iterations[1] << std::endl;
    for (unsigned int d = 0; d < 2; ++d)
      {
        double difference = 0, size = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            difference = std::max(difference, std::abs(x_warm[d][i] - x[d][i]));
            size       = std::max(size, std::abs(x[d][i]));
          }
        PSMPM_CHECK(out, difference <= 1e-10 * size);
        PSMPM_CHECK(out, warm.iterations[d] < result.iterations[d]);
      }
    const auto again = cg.solve(M.trilinos_matrix(),
                                preconditioners,
                                fixed,
                                x_warm,
                                b,
                                1e-6,
                                {0., 0., 0.},
                                1000);
    PSMPM_CHECK(out, again.iterations[0] == 0 && again.iterations[1] == 0);

    // (f) ||P_d (b_d - M x_d)|| for every column of X.
    const auto residuals = [&](const Epetra_MultiVector &X) {
      Epetra_MultiVector MX(map, 3);
      M.trilinos_matrix().Multiply(false, X, MX);
      std::vector<double> norms(3);
      for (unsigned int d = 0; d < 3; ++d)
        {
          double s = 0;
          for (unsigned int i = 0; i < n; ++i)
            if (!is_fixed(d, i))
              s += (b[d][i] - MX[d][i]) * (b[d][i] - MX[d][i]);
          norms[d] = std::sqrt(s);
        }
      return norms;
    };
    Epetra_MultiVector x_step(map, 3);
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int i = 0; i < n; ++i)
        x_step[d][i] = 0.99 * x[d][i];
    const std::vector<double> before = residuals(x_step);
    const auto                step   = cg.solve(M.trilinos_matrix(),
                               preconditioners,
                               fixed,
                               x_step,
                               b,
                               1e-12,
                               {1e-4, 1e-4, 1e-4},
                               1000);
    const std::vector<double> after  = residuals(x_step);
    out << "step tolerance iterations " << step.iterations[0] << " / "
        << step.iterations[1] << std::endl;
    for (unsigned int d = 0; d < 2; ++d)
      {
        PSMPM_CHECK(out, after[d] <= 1e-4 * before[d] * (1 + 1e-8));
        PSMPM_CHECK(out, step.iterations[d] < warm.iterations[d]);
      }
    Epetra_MultiVector x_zero(map, 3);
    const auto         cold = cg.solve(M.trilinos_matrix(),
                               preconditioners,
                               fixed,
                               x_zero,
                               b,
                               1e-12,
                               {1e-4, 1e-4, 1e-4},
                               1000);
    PSMPM_CHECK(out,
                cold.iterations[0] == blocked.iterations[0] &&
                  cold.iterations[1] == blocked.iterations[1]);

    bool thrown = false;
    x.PutScalar(0.);
    try
      {
        cg.solve(M.trilinos_matrix(),
                 preconditioners,
                 fixed,
                 x,
                 b,
                 1e-12,
                 {0., 0., 0.},
                 2);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        thrown = e.last_step == 2;
      }
    PSMPM_CHECK(out, thrown);
  });
}
