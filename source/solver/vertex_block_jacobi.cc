// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/vertex_block_jacobi.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <array>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      constexpr unsigned int max_block = 8;

      /// In-place Gauss-Jordan inverse of the n x n row-major @p a without
      /// pivoting (the blocks are symmetric positive definite diagonal
      /// blocks of a mass matrix); false if a pivot is not positive
      /// relative to the block's largest diagonal entry.
      bool
      invert_in_place(double *a, const unsigned int n)
      {
        double scale = 0;
        for (unsigned int i = 0; i < n; ++i)
          scale = std::max(scale, std::abs(a[i * n + i]));
        for (unsigned int p = 0; p < n; ++p)
          {
            const double pivot = a[p * n + p];
            if (!(pivot > 1e-12 * scale))
              return false;
            const double inverse_pivot = 1. / pivot;
            for (unsigned int j = 0; j < n; ++j)
              a[p * n + j] *= inverse_pivot;
            a[p * n + p] = inverse_pivot;
            for (unsigned int i = 0; i < n; ++i)
              if (i != p)
                {
                  const double f = a[i * n + p];
                  for (unsigned int j = 0; j < n; ++j)
                    a[i * n + j] -= f * a[p * n + j];
                  a[i * n + p] = -f * inverse_pivot;
                }
          }
        for (unsigned int i = 0; i < n * n; ++i)
          if (!std::isfinite(a[i]))
            return false;
        return true;
      }
    } // namespace

    bool
    VertexBlockJacobi::find_block_entries(const Epetra_CrsMatrix &crs)
    {
      const unsigned int n = block_size;
      int               *offsets, *columns;
      double            *entries;
      crs.ExtractCrsDataPointers(offsets, columns, entries);
      block_entries.assign(std::size_t(n_rows) * n, -1);
      std::array<int, max_block> local_column;
      for (unsigned int b = 0; b < n_rows / n; ++b)
        {
          const unsigned int first_row = b * n;
          const int          first_gid = crs.GRID(first_row);
          for (unsigned int i = 0; i < n; ++i)
            {
              AssertThrow(crs.GRID(first_row + i) == first_gid + int(i),
                          ExcMessage("VertexBlockJacobi: the DoFs of a "
                                     "vertex are not numbered consecutively"));
              local_column[i] = crs.LCID(first_gid + int(i));
            }
          for (unsigned int i = 0; i < n; ++i)
            for (int k = offsets[first_row + i]; k < offsets[first_row + i + 1];
                 ++k)
              for (unsigned int j = 0; j < n; ++j)
                if (columns[k] == local_column[j])
                  {
                    int &entry =
                      block_entries[std::size_t(first_row + i) * n + j];
                    // A column twice in a row (not in a filled Epetra
                    // matrix): its entries are summed by the search.
                    if (entry >= 0)
                      return false;
                    entry = k;
                  }
        }
      return true;
    }



    void
    VertexBlockJacobi::add_block_by_search(const Epetra_CrsMatrix &crs,
                                           const unsigned int      first_row,
                                           double                 *block) const
    {
      const unsigned int n = block_size;
      int               *offsets, *columns;
      double            *entries;
      crs.ExtractCrsDataPointers(offsets, columns, entries);
      std::array<int, max_block> local_column;
      for (unsigned int j = 0; j < n; ++j)
        local_column[j] = crs.LCID(crs.GRID(first_row) + int(j));
      for (unsigned int i = 0; i < n; ++i)
        for (int k = offsets[first_row + i]; k < offsets[first_row + i + 1];
             ++k)
          for (unsigned int j = 0; j < n; ++j)
            if (columns[k] == local_column[j])
              block[i * n + j] += entries[k];
    }



    void
    VertexBlockJacobi::initialize(const TrilinosWrappers::SparseMatrix &A,
                                  const unsigned int block_size_in,
                                  const std::vector<unsigned int> &fixed,
                                  const std::uint64_t              pattern)
    {
      AssertThrow(block_size_in >= 1 && block_size_in <= max_block,
                  ExcMessage("VertexBlockJacobi: block size " +
                             std::to_string(block_size_in) + " outside 1.." +
                             std::to_string(max_block)));
      const Epetra_CrsMatrix &crs = A.trilinos_matrix();
      AssertThrow(crs.NumMyRows() % block_size_in == 0,
                  ExcMessage(
                    "VertexBlockJacobi: " + std::to_string(crs.NumMyRows()) +
                    " owned rows are not whole blocks of " +
                    std::to_string(block_size_in)));
      // Where the blocks' entries are in the value array depends on the
      // sparsity pattern alone: found once per pattern (the map look-ups
      // and the search through each row cost more than the inversions).
      const bool same_pattern =
        entries_found && pattern != 0 && pattern == entries_pattern &&
        block_size == block_size_in && n_rows == unsigned(crs.NumMyRows());
      block_size = block_size_in;
      n_rows     = crs.NumMyRows();
      if (!same_pattern)
        {
          entries_found   = find_block_entries(crs);
          entries_pattern = pattern;
        }
      const unsigned int n = block_size;
      inverse.assign(std::size_t(n_rows) * n, 0.);
      fallbacks = 0;
      int    *offsets, *columns;
      double *entries;
      crs.ExtractCrsDataPointers(offsets, columns, entries);
      std::array<double, max_block * max_block> block;
      std::array<bool, max_block>               masked;
      auto                                      next_fixed = fixed.begin();
      for (unsigned int b = 0; b < n_rows / n; ++b)
        {
          const unsigned int first_row = b * n;
          // 0 + a, as the sum over the row's entries gave (-0 becomes +0).
          // Only the block's n x n entries: filling all of max_block^2
          // cost more than the rest for P1's 1 x 1 blocks.
          std::fill_n(block.begin(), n * n, 0.);
          if (entries_found)
            {
              const int *at = &block_entries[std::size_t(first_row) * n];
              for (unsigned int ij = 0; ij < n * n; ++ij)
                if (at[ij] >= 0)
                  block[ij] += entries[at[ij]];
            }
          else
            add_block_by_search(crs, first_row, block.data());
          // Masked rows: a unit row and column for the inversion, zero
          // afterwards (the block of P A P on the free DoFs, inverted).
          bool any_masked = false;
          for (unsigned int i = 0; i < n; ++i)
            {
              while (next_fixed != fixed.end() && *next_fixed < first_row + i)
                ++next_fixed;
              masked[i] =
                next_fixed != fixed.end() && *next_fixed == first_row + i;
              any_masked |= masked[i];
              if (masked[i])
                for (unsigned int j = 0; j < n; ++j)
                  block[i * n + j] = block[j * n + i] = (i == j);
            }
          double *const out = &inverse[std::size_t(first_row) * n];
          std::copy(block.begin(), block.begin() + n * n, out);
          const bool inverted = invert_in_place(out, n);
          if (inverted && any_masked)
            for (unsigned int i = 0; i < n; ++i)
              if (masked[i])
                for (unsigned int j = 0; j < n; ++j)
                  out[i * n + j] = out[j * n + i] = 0;
          if (!inverted)
            {
              ++fallbacks;
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  out[i * n + j] =
                    (i != j || masked[i]  ? 0. :
                     block[i * n + i] > 0 ? 1. / block[i * n + i] :
                                            1.);
            }
        }
    }

    void
    VertexBlockJacobi::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
    {
      AssertDimension(src.locally_owned_size(), n_rows);
      AssertDimension(dst.locally_owned_size(), n_rows);
      vmult(dst.begin(), src.begin());
    }

    void
    VertexBlockJacobi::vmult(double *const d, const double *const s) const
    {
      const unsigned int n = block_size;
      const double      *a = inverse.data();
      if (n == 3)
        {
          // The Powell-Sabin case, unrolled.
          for (unsigned int r = 0; r < n_rows; r += 3, a += 9)
            {
              const double s0 = s[r], s1 = s[r + 1], s2 = s[r + 2];
              d[r]     = a[0] * s0 + a[1] * s1 + a[2] * s2;
              d[r + 1] = a[3] * s0 + a[4] * s1 + a[5] * s2;
              d[r + 2] = a[6] * s0 + a[7] * s1 + a[8] * s2;
            }
          return;
        }
      for (unsigned int r = 0; r < n_rows; r += n, a += n * n)
        for (unsigned int i = 0; i < n; ++i)
          {
            double v = 0;
            for (unsigned int j = 0; j < n; ++j)
              v += a[i * n + j] * s[r + j];
            d[r + i] = v;
          }
    }

    void
    VertexBlockJacobi::vmult(double *const       d,
                             const double *const s,
                             double             &src_src,
                             double             &src_dst) const
    {
      const unsigned int n  = block_size;
      const double      *a  = inverse.data();
      double             ss = 0, sd = 0;
      if (n == 3)
        {
          for (unsigned int r = 0; r < n_rows; r += 3, a += 9)
            {
              const double s0 = s[r], s1 = s[r + 1], s2 = s[r + 2];
              const double d0 = a[0] * s0 + a[1] * s1 + a[2] * s2;
              const double d1 = a[3] * s0 + a[4] * s1 + a[5] * s2;
              const double d2 = a[6] * s0 + a[7] * s1 + a[8] * s2;
              d[r] = d0, d[r + 1] = d1, d[r + 2] = d2;
              ss += s0 * s0 + s1 * s1 + s2 * s2;
              sd += s0 * d0 + s1 * d1 + s2 * d2;
            }
        }
      else
        {
          vmult(d, s);
          // Two partial sums each: a single running sum would be a
          // latency-bound chain.
          double       ss1 = 0, sd1 = 0;
          unsigned int i = 0;
          for (; i + 2 <= n_rows; i += 2)
            {
              ss += s[i] * s[i], sd += s[i] * d[i];
              ss1 += s[i + 1] * s[i + 1], sd1 += s[i + 1] * d[i + 1];
            }
          for (; i < n_rows; ++i)
            ss += s[i] * s[i], sd += s[i] * d[i];
          ss += ss1, sd += sd1;
        }
      src_src = ss, src_dst = sd;
    }
  } // namespace Solver
} // namespace psmpm
