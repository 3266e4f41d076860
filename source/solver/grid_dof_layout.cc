// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>

#include <psmpm/solver/grid_dof_layout.h>

#include <algorithm>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    void
    GridDofLayout<dim>::reinit(const DoFHandler<dim>   &dof_handler,
                               const Basis::Space<dim> &space,
                               const bool               all_dofs,
                               MPI_Comm                 comm)
    {
      dofs_per_cell = space.dofs_per_cell();
      owned         = dof_handler.locally_owned_dofs();
      if (all_dofs)
        // Constraints may tie a vertex to one two cells away: keep every
        // DoF at hand (the mesh is replicated anyway).
        relevant = complete_index_set(dof_handler.n_dofs());
      else
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      global.resize(relevant.n_elements());
      for (unsigned int l = 0; l < global.size(); ++l)
        global[l] = relevant.nth_index_in_set(l);
      owned_relevant.clear();
      for (const auto i : owned)
        owned_relevant.push_back(relevant.index_within_set(i));
      // The same on every rank: an owner must take part in the exchange
      // whenever another rank holds its DoFs as ghosts, even if it has
      // no ghosts itself.
      owned_is_relevant =
        Utilities::MPI::min(relevant == owned ? 1U : 0U, comm) == 1;
      number_cells(dof_handler);
      // owned_is_relevant is the same on every rank, so every rank builds
      // the pattern (which may be collective), also one without ghosts.
      if (!owned_is_relevant)
        exchange.reinit(owned, relevant, comm);
      scratch.assign(global.size(), 0.);
      build_ties(dof_handler, space);
    }

    template <int dim>
    void
    GridDofLayout<dim>::number_cells(const DoFHandler<dim> &dof_handler)
    {
      owned_cell_indices.clear();
      cell_dof_indices.assign(dof_handler.get_triangulation().n_active_cells() *
                                dofs_per_cell,
                              0);
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c = cell->active_cell_index();
            owned_cell_indices.push_back(c);
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dofs_per_cell; ++k)
              cell_dof_indices[c * dofs_per_cell + k] =
                relevant.index_within_set(dofs[k]);
          }
    }

    template <int dim>
    void
    GridDofLayout<dim>::build_ties(const DoFHandler<dim>   &dof_handler,
                                   const Basis::Space<dim> &space)
    {
      // The space's own constraints in local relevant numbering, for the
      // lumped path, which condenses vectors without AffineConstraints.
      AffineConstraints<double> c(relevant);
      space.make_space_constraints(dof_handler, c);
      c.close();
      ties.clear();
      for (unsigned int l = 0; l < global.size(); ++l)
        if (c.is_constrained(global[l]))
          {
            Tie         tie{l, {}};
            const auto *entries = c.get_constraint_entries(global[l]);
            bool        local   = true;
            for (const auto &[j, w] : *entries)
              if (relevant.is_element(j))
                tie.targets.emplace_back(relevant.index_within_set(j), w);
              else
                local = false;
            // A tie that reaches outside the relevant DoFs belongs to a
            // vertex of a ghost cell only, which no owned cell adds to.
            if (local)
              ties.push_back(std::move(tie));
          }
    }

    template <int dim>
    void
    GridDofLayout<dim>::scatter(const double                  *cell_values,
                                const unsigned int             stride,
                                const unsigned int             offset,
                                TrilinosWrappers::MPI::Vector &target,
                                const bool                     condense) const
    {
      // Sum cell contributions locally first, then hand Trilinos one
      // vector: far cheaper than one add() per cell.
      std::fill(scratch.begin(), scratch.end(), 0.);
      for (const unsigned int c : owned_cell_indices)
        for (unsigned int k = 0; k < dofs_per_cell; ++k)
          scratch[cell_dof_indices[c * dofs_per_cell + k]] +=
            cell_values[(c * dofs_per_cell + k) * stride + offset];
      if (condense)
        // C^T b: what a tied DoF collects goes to the DoFs it is tied to.
        for (const auto &tie : ties)
          {
            const double v   = scratch[tie.dof];
            scratch[tie.dof] = 0;
            for (const auto &[j, w] : tie.targets)
              scratch[j] += w * v;
          }
      if (owned_is_relevant)
        {
          // Nothing to send: the sums are the owned entries (0 + s, as
          // add() would give, so that -0 becomes +0 there too).
          double *const values = target.begin();
          for (unsigned int l = 0; l < scratch.size(); ++l)
            values[l] = 0. + scratch[l];
          return;
        }
      exchange.sum_to_owned(scratch, target.begin());
    }

    template <int dim>
    void
    GridDofLayout<dim>::to_local(
      const TrilinosWrappers::MPI::Vector &owned_vector,
      std::vector<double>                 &local) const
    {
      local.resize(global.size());
      if (owned_is_relevant)
        {
          std::copy(owned_vector.begin(), owned_vector.end(), local.begin());
          return;
        }
      exchange.owned_to_relevant(owned_vector.begin(), local);
    }

    template class GridDofLayout<1>;
    template class GridDofLayout<2>;
  } // namespace Solver
} // namespace psmpm
