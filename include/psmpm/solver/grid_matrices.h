// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_grid_matrices_h
#define psmpm_solver_grid_matrices_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <psmpm/solver/component_constraints.h>
#include <psmpm/solver/grid_dof_layout.h>
#include <psmpm/solver/patch_block.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The mass matrices of GridSystem's dim components on one sparsity
     * pattern, and their assembly from the owned cells' dense blocks
     * (CellArrays::mass) and the strategy's patch blocks. Where every
     * constraint of a component fixes its DoF to zero, blocks go straight
     * into the Epetra value array, cell blocks through positions computed
     * once per sparsity (the work of distribute_local_to_global, sorting,
     * map look-ups and a search per entry, cost more than the particle
     * loops); the same sums in the same order, so bit-identical. Other
     * constraints go through AffineConstraints.
     */
    template <int dim>
    class GridMatrices
    {
    public:
      /// Every component's matrix on the pattern @p dsp (distributed over
      /// the owned DoFs of @p layout) and the cell blocks' positions.
      void
      reinit(const DynamicSparsityPattern &dsp,
             const GridDofLayout<dim>     &layout,
             MPI_Comm                      comm);

      TrilinosWrappers::SparseMatrix &
      matrix(const unsigned int d)
      {
        return matrices[d];
      }
      const TrilinosWrappers::SparseMatrix &
      matrix(const unsigned int d) const
      {
        return matrices[d];
      }
      /// Changes with every change of the sparsity pattern.
      unsigned int
      generation() const
      {
        return sparsity_generation;
      }
      /// Whether the cell blocks' positions are known (Epetra gave its
      /// CRS arrays with sorted columns), so that blocks of components
      /// with homogeneous Dirichlet constraints only go straight in.
      bool
      direct_assembly() const
      {
        return !cell_slots.empty();
      }
      /// Value-array positions of the entries (k, l) of a dense block over
      /// the local relevant DoFs @p dofs (-1 where the row is another
      /// rank's) into @p slots (n x n); false, and @p slots untouched,
      /// without direct_assembly().
      bool
      patch_slots(const unsigned int *dofs,
                  const unsigned int  n,
                  int                *slots) const;

      /// Matrix of component @p d from the cell blocks @p mass and the
      /// @p patches under its active constraints; rows without particle
      /// mass (@p lumped zero in local relevant numbering) get a unit
      /// diagonal.
      void
      assemble(const unsigned int               d,
               const ComponentConstraints<dim> &constraints,
               const GridDofLayout<dim>        &layout,
               const std::vector<double>       &mass,
               const std::vector<PatchBlock>   &patches,
               const std::vector<double>       &lumped);
      /// Matrix 0 without any constraint (the components' shared M).
      void
      assemble_unconstrained(const GridDofLayout<dim>      &layout,
                             const std::vector<double>     &mass,
                             const std::vector<PatchBlock> &patches,
                             const std::vector<double>     &lumped);

    private:
      /// Positions of the cell blocks' entries in the matrices' value
      /// arrays, after every change of the sparsity.
      void
      compute_slots(const GridDofLayout<dim> &layout);
      /// Add the dense block @p values (row-major, n x n) over the local
      /// relevant DoFs @p dofs to @p target, as distribute_local_to_global
      /// with homogeneous Dirichlet constraints on the DoFs flagged in
      /// @p fixed (local relevant numbering; nullptr: none) does, through
      /// the value array (cell blocks with their precomputed @p slots,
      /// other blocks by a search of the row).
      void
      add_block(TrilinosWrappers::SparseMatrix             &target,
                const char                                 *fixed,
                const std::vector<types::global_dof_index> &global,
                const unsigned int                         *dofs,
                const unsigned int                          n,
                const double                               *values,
                const double                                weight,
                const int                                  *slots) const;
      /// add_block() of every owned cell's block and every patch block.
      void
      add_blocks(TrilinosWrappers::SparseMatrix &target,
                 const char                     *fixed,
                 const GridDofLayout<dim>       &layout,
                 const std::vector<double>      &mass,
                 const std::vector<PatchBlock>  &patches) const;
      /// Per-cell AffineConstraints::distribute_local_to_global, for
      /// constraints that tie DoFs to others (extrapolate).
      void
      add_blocks_with_constraints(const unsigned int               d,
                                  const AffineConstraints<double> &c,
                                  const GridDofLayout<dim>        &layout,
                                  const std::vector<double>       &mass,
                                  const std::vector<PatchBlock>   &patches);
      /// Compress @p target and give rows without particle mass and
      /// without a diagonal entry a unit diagonal.
      static void
      finish_assembly(TrilinosWrappers::SparseMatrix &target,
                      const GridDofLayout<dim>       &layout,
                      const std::vector<double>      &lumped);

      std::array<TrilinosWrappers::SparseMatrix, dim> matrices;
      /// The matrix row and column of a local relevant DoF (-1: row not
      /// owned), and per owned cell (in owned_cells() order) the
      /// value-array position of each entry (k, l) of its block (-1: row
      /// not owned).
      std::vector<int> matrix_row;
      std::vector<int> matrix_column;
      std::vector<int> cell_slots;
      unsigned int     sparsity_generation = 0;
    };
  } // namespace Solver
} // namespace psmpm

#endif
