// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/dense_cholesky.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    bool
    DenseCholesky::factorize(const TrilinosWrappers::SparseMatrix &A)
    {
      n = A.m();
      // Only the envelope (row i from first[i] to i) is ever read, so only
      // it is zeroed: zeroing all n^2 entries every step cost more than
      // the factorization on a few hundred DoFs.
      L.resize(std::size_t(n) * n);
      first.assign(n, n);
      y.resize(n);
      const Epetra_CrsMatrix &crs = A.trilinos_matrix();
      int                    *offsets, *columns;
      double                 *entries;
      crs.ExtractCrsDataPointers(offsets, columns, entries);
      // The maps' global indices looked up once, not per entry (GCID per
      // entry was a third of the instructions of a factorization).
      row_gid.resize(n);
      for (unsigned int r = 0; r < n; ++r)
        row_gid[r] = crs.GRID(r);
      column_gid.resize(crs.NumMyCols());
      for (int c = 0; c < crs.NumMyCols(); ++c)
        column_gid[c] = crs.GCID(c);
      for (unsigned int r = 0; r < n; ++r)
        {
          const unsigned int i = row_gid[r];
          for (int k = offsets[r]; k < offsets[r + 1]; ++k)
            {
              const unsigned int j = column_gid[columns[k]];
              if (j <= i && entries[k] != 0)
                first[i] = std::min(first[i], j);
            }
          first[i] = std::min(first[i], i);
        }
      for (unsigned int i = 0; i < n; ++i)
        std::fill(L.begin() + std::size_t(i) * n + first[i],
                  L.begin() + std::size_t(i) * n + i + 1,
                  0.);
      for (unsigned int r = 0; r < n; ++r)
        {
          const unsigned int i = row_gid[r];
          for (int k = offsets[r]; k < offsets[r + 1]; ++k)
            {
              const unsigned int j = column_gid[columns[k]];
              if (j <= i && entries[k] != 0)
                L[std::size_t(i) * n + j] = entries[k];
            }
        }
      // Cholesky-Banachiewicz, row by row, inside the envelope.
      for (unsigned int i = 0; i < n; ++i)
        {
          double *const Li = &L[std::size_t(i) * n];
          for (unsigned int j = first[i]; j <= i; ++j)
            {
              const double *const Lj = &L[std::size_t(j) * n];
              double              s  = Li[j];
              for (unsigned int k = std::max(first[i], first[j]); k < j; ++k)
                s -= Li[k] * Lj[k];
              if (j < i)
                Li[j] = s / Lj[j];
              else if (s > 0)
                Li[i] = std::sqrt(s);
              else
                return false;
            }
        }
      return true;
    }



    void
    DenseCholesky::solve(const TrilinosWrappers::MPI::Vector &b,
                         TrilinosWrappers::MPI::Vector       &x) const
    {
      // L y = b, then L^T x = y (column sweep, so that the rows of L are
      // read contiguously). Direct solves run on one rank: the owned
      // entries are all entries, read and written through the value array
      // (operator[] maps each index through Epetra, which cost more than
      // the sweeps on small systems).
      AssertDimension(b.locally_owned_size(), n);
      AssertDimension(x.locally_owned_size(), n);
      const double *const bv = b.begin();
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *const Li = &L[std::size_t(i) * n];
          double              s  = bv[i];
          for (unsigned int k = first[i]; k < i; ++k)
            s -= Li[k] * y[k];
          y[i] = s / Li[i];
        }
      for (unsigned int i = n; i-- > 0;)
        {
          const double *const Li = &L[std::size_t(i) * n];
          y[i] /= Li[i];
          for (unsigned int k = first[i]; k < i; ++k)
            y[k] -= Li[k] * y[i];
        }
      std::copy(y.begin(), y.begin() + n, x.begin());
    }
  } // namespace Solver
} // namespace psmpm
