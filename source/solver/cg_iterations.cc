// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/index_set.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/solver/cg_iterations.h>

namespace psmpm
{
  namespace Solver
  {
    unsigned int
    cg_iterations(const SparseMatrix<double> &A,
                  const Vector<double>       &b,
                  const std::string          &preconditioner,
                  const double                tolerance,
                  const unsigned int          max_iterations,
                  Vector<double>             *solution)
    {
      AssertThrow(preconditioner == "none" || preconditioner == "jacobi" ||
                    preconditioner == "amg",
                  ExcMessage("cg_iterations: unknown preconditioner '" +
                             preconditioner + "'."));
      const double norm = b.l2_norm();
      if (norm == 0)
        {
          if (solution)
            solution->reinit(b.size());
          return 0;
        }
      // No history, no log: a run that does not converge is a result
      // (invalid_unsigned_int), not an error.
      SolverControl control(max_iterations, tolerance * norm, false, false);
      try
        {
          if (preconditioner == "amg")
            {
              TrilinosWrappers::SparseMatrix tA;
              tA.reinit(A);
              const IndexSet                all = complete_index_set(b.size());
              TrilinosWrappers::MPI::Vector tx(all, MPI_COMM_SELF),
                tb(all, MPI_COMM_SELF);
              for (unsigned int i = 0; i < b.size(); ++i)
                tb[i] = b[i];
              tb.compress(VectorOperation::insert);
              TrilinosWrappers::PreconditionAMG amg;
              amg.initialize(tA);
              SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
              cg.solve(tA, tx, tb, amg);
              if (solution)
                {
                  solution->reinit(b.size());
                  for (unsigned int i = 0; i < b.size(); ++i)
                    (*solution)[i] = tx[i];
                }
            }
          else
            {
              Vector<double>           x(b.size());
              SolverCG<Vector<double>> cg(control);
              if (preconditioner == "jacobi")
                {
                  PreconditionJacobi<SparseMatrix<double>> jacobi;
                  jacobi.initialize(A);
                  cg.solve(A, x, b, jacobi);
                }
              else
                cg.solve(A, x, b, PreconditionIdentity());
              if (solution)
                *solution = x;
            }
        }
      catch (const SolverControl::NoConvergence &)
        {
          return numbers::invalid_unsigned_int;
        }
      return control.last_step();
    }
  } // namespace Solver
} // namespace psmpm
