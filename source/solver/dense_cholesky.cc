// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <psmpm/solver/dense_cholesky.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    void
    DenseCholesky::order(const int *offsets, const int *columns)
    {
      // deal.II's Cuthill-McKee on the stored pattern (every entry, zero
      // or not: the pattern is the grid system's, fixed between
      // reinitializations), and its reverse; the numbering with the
      // smallest envelope is kept. DoF numberings follow the cells, so
      // on a long mesh a row reaches across a whole layer of cells, and
      // the envelope and the work (n b^2 / 2) grow with the mesh's length
      // instead of its width.
      DynamicSparsityPattern pattern(n, n);
      for (unsigned int r = 0; r < n; ++r)
        for (int k = offsets[r]; k < offsets[r + 1]; ++k)
          pattern.add(row_gid[r], column_gid[columns[k]]);
      std::vector<DynamicSparsityPattern::size_type> cm(n);
      SparsityTools::reorder_Cuthill_McKee(pattern, cm);
      const auto profile = [&](const auto &number) {
        std::size_t sum = 0;
        for (unsigned int r = 0; r < n; ++r)
          {
            const unsigned int i  = number(row_gid[r]);
            unsigned int       lo = i;
            for (int k = offsets[r]; k < offsets[r + 1]; ++k)
              lo = std::min<unsigned int>(lo, number(column_gid[columns[k]]));
            sum += i - lo;
          }
        return sum;
      };
      const auto identity = [](const unsigned int i) { return i; };
      const auto forward  = [&](const unsigned int i) {
        return static_cast<unsigned int>(cm[i]);
      };
      const auto reverse = [&](const unsigned int i) {
        return static_cast<unsigned int>(n - 1 - cm[i]);
      };
      const std::size_t e[3] = {profile(identity),
                                profile(forward),
                                profile(reverse)};
      permutation.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        permutation[i] = e[2] <= e[1] && e[2] < e[0] ? reverse(i) :
                         e[1] < e[0]                 ? forward(i) :
                                                       i;
      ordered_nonzeros = offsets[n];
    }

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
      // Any numbering factors correctly; a stale one (another pattern of
      // the same size) would only cost time.
      if (permutation.size() != n || ordered_nonzeros != offsets[n])
        order(offsets, columns);
      // A = P^T L L^T P: row and column i of A are row and column
      // permutation[i] of the factored matrix.
      for (unsigned int r = 0; r < n; ++r)
        {
          const unsigned int i = permutation[row_gid[r]];
          for (int k = offsets[r]; k < offsets[r + 1]; ++k)
            {
              const unsigned int j = permutation[column_gid[columns[k]]];
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
          const unsigned int i = permutation[row_gid[r]];
          for (int k = offsets[r]; k < offsets[r + 1]; ++k)
            {
              const unsigned int j = permutation[column_gid[columns[k]]];
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

    std::size_t
    DenseCholesky::envelope() const
    {
      std::size_t sum = 0;
      for (unsigned int i = 0; i < n; ++i)
        sum += i - first[i];
      return sum;
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
        y[permutation[i]] = bv[i];
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *const Li = &L[std::size_t(i) * n];
          double              s  = y[i];
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
      double *const xv = x.begin();
      for (unsigned int i = 0; i < n; ++i)
        xv[i] = y[permutation[i]];
    }
  } // namespace Solver
} // namespace psmpm
