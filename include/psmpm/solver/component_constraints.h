// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_component_constraints_h
#define psmpm_solver_component_constraints_h

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <psmpm/basis/space.h>

#include <array>
#include <set>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The constraints of the dim velocity components of GridSystem: per
     * component d the Dirichlet ones (fixed on the boundaries fixed[d],
     * with the space's ties), the step's active ones (the Dirichlet ones
     * or what a strategy set), and, in local relevant numbering, which
     * DoFs they constrain and whether every constraint fixes its DoF to
     * zero (then the matrices are assembled directly, without
     * AffineConstraints).
     */
    template <int dim>
    class ComponentConstraints
    {
    public:
      /// Dirichlet and active constraints of every component over the
      /// relevant DoFs @p relevant (local relevant index l is global
      /// index @p global[l]).
      void
      reinit(const Basis::Space<dim>                             &space,
             const DoFHandler<dim>                               &dof_handler,
             const std::array<std::set<types::boundary_id>, dim> &fixed,
             const IndexSet                                      &relevant,
             const std::vector<types::global_dof_index>          &global);

      /// Replace the active constraints of component @p d (closed, already
      /// merged with the Dirichlet ones).
      void
      set(const unsigned int                          d,
          AffineConstraints<double>                  &c,
          const std::vector<types::global_dof_index> &global);

      const AffineConstraints<double> &
      dirichlet(const unsigned int d) const
      {
        return dirichlet_constraints[d];
      }
      const AffineConstraints<double> &
      active(const unsigned int d) const
      {
        return active_constraints[d];
      }
      /// Per local relevant DoF: 1 where component @p d is constrained.
      const std::vector<char> &
      constrained(const unsigned int d) const
      {
        return constrained_dofs[d];
      }
      /// Whether every active constraint of component @p d fixes its DoF
      /// to zero (homogeneous Dirichlet only).
      bool
      only_dirichlet(const unsigned int d) const
      {
        return dirichlet_only[d];
      }

    private:
      void
      update_flags(const unsigned int                          d,
                   const std::vector<types::global_dof_index> &global);

      std::array<AffineConstraints<double>, dim> dirichlet_constraints;
      std::array<AffineConstraints<double>, dim> active_constraints;
      std::array<std::vector<char>, dim>         constrained_dofs;
      std::array<bool, dim>                      dirichlet_only{};
    };
  } // namespace Solver
} // namespace psmpm

#endif
