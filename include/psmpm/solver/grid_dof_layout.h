// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_grid_dof_layout_h
#define psmpm_solver_grid_dof_layout_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/basis/space.h>
#include <psmpm/solver/ghost_exchange.h>

#include <utility>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The index layout of GridSystem: the owned and locally relevant DoFs,
     * the local relevant numbering (index l of relevant_dofs()) that every
     * grid array uses, the DoFs of each owned cell in it, and the moves of
     * values between cells, owners and ranks (scatter(), to_local()).
     * Owned vectors are read and written through their value arrays in
     * owned order, without Epetra's index maps.
     */
    template <int dim>
    class GridDofLayout
    {
    public:
      /**
       * Index sets, cell DoFs, ghost exchange and the space's ties for
       * @p dof_handler. With @p all_dofs every DoF is relevant (strategies
       * whose constraints reach two cells away on a replicated mesh).
       */
      void
      reinit(const DoFHandler<dim>   &dof_handler,
             const Basis::Space<dim> &space,
             const bool               all_dofs,
             MPI_Comm                 comm);

      /// Sum the per-cell values (value k of cell c at
      /// cell_values[(c * dofs_per_cell + k) * stride + offset]) into the
      /// owned vector @p target; with @p condense, apply the space's ties
      /// (C^T) first, as the lumped path needs.
      void
      scatter(const double                  *cell_values,
              const unsigned int             stride,
              const unsigned int             offset,
              TrilinosWrappers::MPI::Vector &target,
              const bool                     condense = false) const;
      /// The owned vector @p owned_vector in local relevant numbering.
      void
      to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
               std::vector<double>                 &local) const;

      const IndexSet &
      owned_dofs() const
      {
        return owned;
      }
      const IndexSet &
      relevant_dofs() const
      {
        return relevant;
      }
      /// Global index of local relevant index l.
      const std::vector<types::global_dof_index> &
      relevant_global() const
      {
        return global;
      }
      unsigned int
      n_relevant() const
      {
        return global.size();
      }
      /// Local relevant index of the j-th owned DoF.
      const std::vector<unsigned int> &
      owned_to_relevant() const
      {
        return owned_relevant;
      }
      /// Active indices of the locally owned cells.
      const std::vector<unsigned int> &
      owned_cells() const
      {
        return owned_cell_indices;
      }
      /// Local relevant index of DoF k of cell c at [c * dofs_per_cell + k]
      /// (owned cells only).
      const std::vector<unsigned int> &
      cell_dofs() const
      {
        return cell_dof_indices;
      }
      /// DoFs per cell: the stride of cell_dofs().
      unsigned int
      n_cell_dofs() const
      {
        return dofs_per_cell;
      }
      const GhostExchange &
      ghost_exchange() const
      {
        return exchange;
      }

    private:
      void
      number_cells(const DoFHandler<dim> &dof_handler);
      /// Space::make_space_constraints() in local relevant numbering.
      void
      build_ties(const DoFHandler<dim>   &dof_handler,
                 const Basis::Space<dim> &space);

      unsigned int                         dofs_per_cell = 0;
      IndexSet                             owned;
      IndexSet                             relevant;
      std::vector<types::global_dof_index> global;
      std::vector<unsigned int>            owned_relevant;
      std::vector<unsigned int>            owned_cell_indices;
      std::vector<unsigned int>            cell_dof_indices;
      /// One rank: relevant == owned, and vectors are copied as arrays.
      bool owned_is_relevant = false;
      /// Sums and ghost values between ranks (unused on one rank).
      GhostExchange exchange;
      /// Scratch of scatter() (no state between calls).
      mutable std::vector<double> scratch;
      /// A tied DoF and the DoFs and weights it is tied to (empty for
      /// spaces without ties, whose lumped path is then unchanged).
      struct Tie
      {
        unsigned int                                 dof;
        std::vector<std::pair<unsigned int, double>> targets;
      };
      std::vector<Tie> ties;
    };
  } // namespace Solver
} // namespace psmpm

#endif
