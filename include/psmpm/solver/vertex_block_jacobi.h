// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_vertex_block_jacobi_h
#define psmpm_solver_vertex_block_jacobi_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstdint>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * Block-Jacobi preconditioner whose blocks are the DoFs of one vertex:
     * dst = D_b^{-1} src on each block b, D_b the b x b diagonal block of
     * the matrix. For Powell-Sabin the three functions of a vertex overlap
     * almost completely (they share their support, the molecule of the
     * vertex), so the mass matrix is far from diagonally dominant within a
     * vertex and point Jacobi leaves that coupling to CG; inverting the
     * 3 x 3 blocks removes it (closed Powell-Sabin throughput bar: 3.1x
     * fewer CG iterations, doc/performance.md).
     *
     * Written here rather than taken from Trilinos: Ifpack's block
     * relaxation (TrilinosWrappers::PreconditionBlockJacobi) gave the same
     * iterations at 1.7x the CPU time of point Jacobi on that scene (a
     * dense container and a LAPACK factorisation per block at every
     * set-up, a gather and scatter per block and application), while the
     * application here is one small dense product per block, about what a
     * point Jacobi costs.
     *
     * The blocks are the locally owned rows in runs of @p block_size
     * consecutive DoFs (FESystem numbers a vertex's DoFs consecutively and
     * gives all of them to one owner; checked). A block that is not
     * numerically positive definite (a row of a nearly empty vertex)
     * falls back to its diagonal. Storage is kept between set-ups.
     */
    class VertexBlockJacobi
    {
    public:
      /// Invert the diagonal blocks of @p A (its locally owned rows).
      /// The owned rows listed in @p fixed (local row indices, sorted)
      /// are masked: their rows and columns of the inverse are zero, as
      /// for a matrix P A P whose fixed DoFs are projected out
      /// (ComponentCG).
      ///
      /// A non-zero @p pattern names A's sparsity pattern (GridSystem
      /// counts its patterns): while it is that of the last call, the
      /// positions of the blocks' entries in A's value array are those
      /// found then, and the set-up only gathers and inverts (the map
      /// look-ups and the search through the rows cost 2-3 % of a
      /// Powell-Sabin step on the throughput bar; doc/performance.md,
      /// "Block Jacobi"). 0: they are found again.
      void
      initialize(const TrilinosWrappers::SparseMatrix &A,
                 const unsigned int                    block_size,
                 const std::vector<unsigned int>      &fixed   = {},
                 const std::uint64_t                   pattern = 0);

      /// dst = D^{-1} src (owned entries).
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const;

      /// The same on the owned value arrays.
      void
      vmult(double *dst, const double *src) const;

      /// The same, and the products src . src and src . dst that CG needs
      /// next, in the same pass (ComponentCG).
      void
      vmult(double       *dst,
            const double *src,
            double       &src_src,
            double       &src_dst) const;

      /// Blocks that fell back to their diagonal at the last set-up.
      unsigned int
      n_diagonal_fallbacks() const
      {
        return fallbacks;
      }

    private:
      /// Positions of each block's entries in the value array
      /// (block_entries, -1 where the pattern has none); false if a row
      /// holds a column twice, which one position cannot represent.
      bool
      find_block_entries(const Epetra_CrsMatrix &crs);

      /// The block of the rows from @p first_row, summed from a search
      /// through the rows (where find_block_entries() failed).
      void
      add_block_by_search(const Epetra_CrsMatrix &crs,
                          unsigned int            first_row,
                          double                 *block) const;

      unsigned int        block_size = 1;
      unsigned int        n_rows     = 0;
      unsigned int        fallbacks  = 0;
      std::vector<double> inverse; ///< row-major block inverses
      std::vector<int>    block_entries;
      bool                entries_found   = false;
      std::uint64_t       entries_pattern = 0;
    };
  } // namespace Solver
} // namespace psmpm

#endif
