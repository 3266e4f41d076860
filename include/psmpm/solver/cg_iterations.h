// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_cg_iterations_h
#define psmpm_solver_cg_iterations_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The number of CG iterations that reduce the residual of A x = b from
     * the zero start below @p tolerance times ||b|| (Wobbes et al. 2019
     * eq. 4.53), with the preconditioner "none", "jacobi" or "amg"
     * (Trilinos ML through TrilinosWrappers::PreconditionAMG with
     * deal.II's defaults for a symmetric scalar operator, as
     * Mass matrix/Preconditioner = amg of the MPM runs; the serial matrix
     * is copied to Trilinos on MPI_COMM_SELF). Returns
     * numbers::invalid_unsigned_int if @p max_iterations did not suffice.
     * The solution is returned in @p x when it is not nullptr.
     */
    unsigned int
    cg_iterations(const SparseMatrix<double> &A,
                  const Vector<double>       &b,
                  const std::string          &preconditioner,
                  const double                tolerance,
                  const unsigned int          max_iterations,
                  Vector<double>             *x = nullptr);
  } // namespace Solver
} // namespace psmpm

#endif
