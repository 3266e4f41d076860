// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>

#include <psmpm/solver/component_constraints.h>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    void
    ComponentConstraints<dim>::reinit(
      const Basis::Space<dim>                             &space,
      const DoFHandler<dim>                               &dof_handler,
      const std::array<std::set<types::boundary_id>, dim> &fixed,
      const IndexSet                                      &relevant,
      const std::vector<types::global_dof_index>          &global)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          auto &c = dirichlet_constraints[d];
          c.clear();
          c.reinit(relevant);
          space.make_dirichlet_constraints(dof_handler,
                                           fixed[d],
                                           Functions::ZeroFunction<dim>(),
                                           c);
          space.make_space_constraints(dof_handler, c);
          c.close();
          active_constraints[d].clear();
          active_constraints[d].copy_from(c);
          update_flags(d, global);
        }
    }

    template <int dim>
    void
    ComponentConstraints<dim>::set(
      const unsigned int                          d,
      AffineConstraints<double>                  &c,
      const std::vector<types::global_dof_index> &global)
    {
      active_constraints[d].clear();
      active_constraints[d].copy_from(c);
      update_flags(d, global);
    }

    template <int dim>
    void
    ComponentConstraints<dim>::update_flags(
      const unsigned int                          d,
      const std::vector<types::global_dof_index> &global)
    {
      const auto &c = active_constraints[d];
      constrained_dofs[d].assign(global.size(), 0);
      dirichlet_only[d] = true;
      for (unsigned int l = 0; l < global.size(); ++l)
        if (c.is_constrained(global[l]))
          {
            constrained_dofs[d][l] = 1;
            const auto *entries    = c.get_constraint_entries(global[l]);
            dirichlet_only[d]      = dirichlet_only[d] &&
                                (entries == nullptr || entries->empty()) &&
                                c.get_inhomogeneity(global[l]) == 0;
          }
    }

    template class ComponentConstraints<1>;
    template class ComponentConstraints<2>;
  } // namespace Solver
} // namespace psmpm
