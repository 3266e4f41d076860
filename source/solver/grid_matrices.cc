// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/full_matrix.h>

#include <psmpm/solver/grid_matrices.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Value-array positions @p slots (n x n, row-major) of the entries
      /// of a dense block over the local relevant DoFs @p dofs, in a
      /// FillComplete'd Epetra matrix's CRS arrays @p offsets and
      /// @p columns (sorted per row); @p row and @p column map a local
      /// relevant DoF to its local row (-1: another rank's, slot -1) and
      /// column.
      void
      block_slots(const int              *offsets,
                  const int              *columns,
                  const std::vector<int> &row,
                  const std::vector<int> &column,
                  const unsigned int     *dofs,
                  const unsigned int      n,
                  int                    *slots)
      {
        for (unsigned int k = 0; k < n; ++k)
          {
            const int r = row[dofs[k]];
            for (unsigned int l = 0; l < n; ++l)
              {
                slots[k * n + l] = -1;
                if (r < 0)
                  continue;
                const int *begin = columns + offsets[r];
                const int *end   = columns + offsets[r + 1];
                const int *p = std::lower_bound(begin, end, column[dofs[l]]);
                AssertThrow(p != end && *p == column[dofs[l]],
                            ExcInternalError());
                slots[k * n + l] = static_cast<int>(p - columns);
              }
          }
      }
    } // namespace

    template <int dim>
    void
    GridMatrices<dim>::reinit(const DynamicSparsityPattern &dsp,
                              const GridDofLayout<dim>     &layout,
                              MPI_Comm                      comm)
    {
      for (unsigned int d = 0; d < dim; ++d)
        matrices[d].reinit(layout.owned_dofs(), layout.owned_dofs(), dsp, comm);
      compute_slots(layout);
    }

    template <int dim>
    void
    GridMatrices<dim>::compute_slots(const GridDofLayout<dim> &layout)
    {
      // All components share the sparsity pattern, hence (Epetra stores a
      // FillComplete'd matrix in one CRS array with sorted columns) the
      // positions of the entries.
      const Epetra_CrsMatrix &A = matrices[0].trilinos_matrix();
      int                    *offsets, *columns;
      double                 *values;
      ++sparsity_generation;
      cell_slots.clear();
      if (A.ExtractCrsDataPointers(offsets, columns, values) != 0)
        return;
      for (int r = 0; r < A.NumMyRows(); ++r)
        if (!std::is_sorted(columns + offsets[r], columns + offsets[r + 1]))
          return;
      const auto &global = layout.relevant_global();
      matrix_row.resize(global.size());
      matrix_column.resize(global.size());
      for (unsigned int l = 0; l < global.size(); ++l)
        {
          const auto g     = global[l];
          matrix_row[l]    = layout.owned_dofs().is_element(g) ?
                               A.RowMap().LID(static_cast<int>(g)) :
                               -1;
          matrix_column[l] = A.ColMap().LID(static_cast<int>(g));
        }
      const unsigned int n     = layout.n_cell_dofs();
      const auto        &owned = layout.owned_cells();
      cell_slots.resize(owned.size() * n * n);
      for (unsigned int o = 0; o < owned.size(); ++o)
        block_slots(offsets,
                    columns,
                    matrix_row,
                    matrix_column,
                    &layout.cell_dofs()[owned[o] * n],
                    n,
                    &cell_slots[o * n * n]);
    }

    template <int dim>
    bool
    GridMatrices<dim>::patch_slots(const unsigned int *dofs,
                                   const unsigned int  n,
                                   int                *slots) const
    {
      if (cell_slots.empty())
        return false;
      const Epetra_CrsMatrix &A = matrices[0].trilinos_matrix();
      int                    *offsets, *columns;
      double                 *values;
      A.ExtractCrsDataPointers(offsets, columns, values);
      block_slots(offsets, columns, matrix_row, matrix_column, dofs, n, slots);
      return true;
    }

    template <int dim>
    void
    GridMatrices<dim>::assemble(const unsigned int               d,
                                const ComponentConstraints<dim> &constraints,
                                const GridDofLayout<dim>        &layout,
                                const std::vector<double>       &mass,
                                const std::vector<PatchBlock>   &patches,
                                const std::vector<double>       &lumped)
    {
      const char *const fixed = constraints.constrained(d).data();
      matrices[d]             = 0;
      if (constraints.only_dirichlet(d) && !cell_slots.empty())
        add_blocks(matrices[d], fixed, layout, mass, patches);
      else
        add_blocks_with_constraints(d,
                                    constraints.active(d),
                                    layout,
                                    mass,
                                    patches);
      finish_assembly(matrices[d], layout, lumped);
    }

    template <int dim>
    void
    GridMatrices<dim>::assemble_unconstrained(
      const GridDofLayout<dim>      &layout,
      const std::vector<double>     &mass,
      const std::vector<PatchBlock> &patches,
      const std::vector<double>     &lumped)
    {
      TrilinosWrappers::SparseMatrix &M = matrices[0];
      M                                 = 0;
      add_blocks(M, nullptr, layout, mass, patches);
      finish_assembly(M, layout, lumped);
    }

    template <int dim>
    void
    GridMatrices<dim>::add_blocks(TrilinosWrappers::SparseMatrix &target,
                                  const char                     *fixed,
                                  const GridDofLayout<dim>       &layout,
                                  const std::vector<double>      &mass,
                                  const std::vector<PatchBlock>  &patches) const
    {
      // Straight into the value array: the per-cell work of
      // distribute_local_to_global (sorting, map look-ups, a search per
      // entry) cost more than the particle loops on small and medium
      // systems. Same sums in the same order: bit-identical.
      const unsigned int n      = layout.n_cell_dofs();
      const auto        &owned  = layout.owned_cells();
      const auto        &global = layout.relevant_global();
      for (unsigned int o = 0; o < owned.size(); ++o)
        {
          const unsigned int c = owned[o];
          add_block(target,
                    fixed,
                    global,
                    &layout.cell_dofs()[c * n],
                    n,
                    &mass[c * n * n],
                    1.,
                    &cell_slots[o * n * n]);
        }
      for (const auto &patch : patches)
        add_block(target,
                  fixed,
                  global,
                  patch.dofs,
                  patch.n,
                  patch.values,
                  patch.weight,
                  patch.slots);
    }

    template <int dim>
    void
    GridMatrices<dim>::finish_assembly(TrilinosWrappers::SparseMatrix &target,
                                       const GridDofLayout<dim>       &layout,
                                       const std::vector<double>      &lumped)
    {
      target.compress(VectorOperation::add);
      // A DoF whose support holds no particle has an empty row: give it
      // a unit diagonal so that its (zero) coefficient is well defined.
      // (Rows of patch blocks, e.g. the ghost penalty, may hold a DoF
      // without particle mass: it keeps its row.) Fixed DoFs too: CG
      // skips their rows, but the direct solver (DenseCholesky) factors
      // the whole matrix, which a zero row makes singular wherever a
      // fixed boundary reaches beyond the material (a column on a long
      // floor).
      const auto &global = layout.relevant_global();
      for (const unsigned int l : layout.owned_to_relevant())
        if (lumped[l] == 0 && target.diag_element(global[l]) == 0)
          target.set(global[l], global[l], 1.0);
      target.compress(VectorOperation::insert);
    }

    template <int dim>
    void
    GridMatrices<dim>::add_block(
      TrilinosWrappers::SparseMatrix             &target,
      const char                                 *fixed,
      const std::vector<types::global_dof_index> &global,
      const unsigned int                         *dofs,
      const unsigned int                          n,
      const double                               *values,
      const double                                weight,
      const int                                  *slots) const
    {
      Epetra_CrsMatrix &A =
        const_cast<Epetra_CrsMatrix &>(target.trilinos_matrix());
      int    *offsets, *columns;
      double *entries;
      A.ExtractCrsDataPointers(offsets, columns, entries);
      // The common block: a slot per entry, every row this rank's, no
      // fixed DoF. One add per nonzero entry in the order of the general
      // loop below (the same sums, bit for bit), without its tests per
      // entry, which took most of a ghost-penalty step's assembly.
      if (slots != nullptr)
        {
          bool plain = true;
          for (unsigned int k = 0; k < n; ++k)
            plain = plain && matrix_row[dofs[k]] >= 0 &&
                    (fixed == nullptr || !fixed[dofs[k]]);
          if (plain)
            {
              for (unsigned int kl = 0; kl < n * n; ++kl)
                {
                  const double v = weight * values[kl];
                  if (v != 0)
                    entries[slots[kl]] += v;
                }
              return;
            }
        }
      for (unsigned int k = 0; k < n; ++k)
        {
          const unsigned int row = dofs[k];
          if (fixed != nullptr && fixed[row])
            continue;
          const int r = matrix_row[row];
          for (unsigned int l = 0; l < n; ++l)
            {
              const double v = weight * values[k * n + l];
              if ((fixed != nullptr && fixed[dofs[l]]) || v == 0)
                continue;
              if (r < 0) // another rank's row: through Trilinos
                target.add(global[row], global[dofs[l]], v);
              else if (slots != nullptr)
                entries[slots[k * n + l]] += v;
              else
                {
                  const int *p = std::lower_bound(columns + offsets[r],
                                                  columns + offsets[r + 1],
                                                  matrix_column[dofs[l]]);
                  entries[p - columns] += v;
                }
            }
        }
      if (fixed == nullptr)
        return;
      // What distribute_local_to_global puts on the diagonal of a fixed
      // DoF (keeps the matrix invertible and of the right scale).
      double average = 0;
      for (unsigned int k = 0; k < n; ++k)
        average += std::abs(weight * values[k * n + k]);
      average /= n;
      for (unsigned int k = 0; k < n; ++k)
        if (fixed[dofs[k]])
          {
            const double v = weight * values[k * n + k] != 0 ?
                               std::abs(weight * values[k * n + k]) :
                               average;
            if (slots != nullptr && matrix_row[dofs[k]] >= 0)
              entries[slots[k * n + k]] += v;
            else
              target.add(global[dofs[k]], global[dofs[k]], v);
          }
    }

    template <int dim>
    void
    GridMatrices<dim>::add_blocks_with_constraints(
      const unsigned int               d,
      const AffineConstraints<double> &c,
      const GridDofLayout<dim>        &layout,
      const std::vector<double>       &mass,
      const std::vector<PatchBlock>   &patches)
    {
      const unsigned int                   n      = layout.n_cell_dofs();
      const auto                          &global = layout.relevant_global();
      FullMatrix<double>                   local(n, n);
      std::vector<types::global_dof_index> dofs(n);
      for (const unsigned int cell : layout.owned_cells())
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              dofs[k] = global[layout.cell_dofs()[cell * n + k]];
              for (unsigned int l = 0; l < n; ++l)
                local(k, l) = mass[(cell * n + k) * n + l];
            }
          c.distribute_local_to_global(local, dofs, matrices[d]);
        }
      for (const auto &patch : patches)
        {
          std::vector<types::global_dof_index> patch_dofs(patch.n);
          FullMatrix<double>                   block(patch.n, patch.n);
          for (unsigned int k = 0; k < patch.n; ++k)
            {
              patch_dofs[k] = global[patch.dofs[k]];
              for (unsigned int l = 0; l < patch.n; ++l)
                block(k, l) = patch.weight * patch.values[k * patch.n + l];
            }
          c.distribute_local_to_global(block, patch_dofs, matrices[d]);
        }
    }

    template class GridMatrices<1>;
    template class GridMatrices<2>;
  } // namespace Solver
} // namespace psmpm
