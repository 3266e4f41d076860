// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_dense_cholesky_h
#define psmpm_solver_dense_cholesky_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The mass system of a small mesh on one process, solved by a Cholesky
     * factorization A = L L^T in the envelope of A instead of by CG: for a
     * few dozen or hundred DoFs the factorization costs less than the
     * fixed cost of a preconditioned Trilinos CG (vector operations, a
     * Lanczos condition estimate, the preconditioner set-up), and the
     * solution is exact to round-off with no iteration limit. The large
     * vibrating bar (78 DoFs, 35,000 steps) is the case it was made for
     * (doc/performance.md).
     *
     * Row i of L is nonzero only from the first column of A's row i on
     * (Cholesky fills the envelope, never beyond), so the work is
     * n b^2 / 2 for half-bandwidth b rather than n^3 / 6. The rows are
     * factored in the (reverse) Cuthill-McKee order of the matrix'
     * pattern when that has the smaller envelope (computed once per
     * pattern). Written out here
     * rather than through LAPACK: Debian's reference dpotrf on a 78 x 78
     * matrix took 7x the instructions of this loop, and its condition
     * estimate (dpocon) as many again (callgrind, doc/performance.md).
     * Storage is kept between steps; nothing is allocated once the size is
     * known.
     */
    class DenseCholesky
    {
    public:
      /**
       * Copy and factor @p A (serial: every row is local). Returns false
       * if a pivot is not positive (A not positive definite, e.g. a row
       * without mass): the caller then uses CG, which reports what is
       * wrong.
       */
      bool
      factorize(const TrilinosWrappers::SparseMatrix &A);

      /// The number of entries of the last factor below its diagonal
      /// (the envelope: the work of a solve).
      std::size_t
      envelope() const;

      /// x = A^{-1} b with the last factor.
      void
      solve(const TrilinosWrappers::MPI::Vector &b,
            TrilinosWrappers::MPI::Vector       &x) const;

    private:
      /// The numbering of the rows with the smallest envelope among the
      /// given one and deal.II's Cuthill-McKee and its reverse, from the
      /// CRS pattern (@p offsets, @p columns) of the matrix.
      void
      order(const int *offsets, const int *columns);

      unsigned int                n = 0;
      std::vector<double>         L;     ///< row-major n x n, lower part
      std::vector<unsigned int>   first; ///< first column of row i's envelope
      mutable std::vector<double> y;
      /// Global index of each local row and column of the matrix.
      std::vector<unsigned int> row_gid, column_gid;
      /// Row i of the matrix is row permutation[i] of the factor, for a
      /// pattern of permutation.size() rows and this many stored entries.
      std::vector<unsigned int> permutation;
      int                       ordered_nonzeros = -1;
    };
  } // namespace Solver
} // namespace psmpm

#endif
