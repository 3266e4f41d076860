// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/lac/solver_control.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_solver.h>

#include <algorithm>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    MassSolver<dim>::MassSolver(const Settings &settings)
      : settings(settings)
      , preconditioners(settings.preconditioner,
                        settings.dofs_per_vertex,
                        settings.multigrid)
    {
    }

    template <int dim>
    void
    MassSolver<dim>::reinit(const GridSystem<dim> &grid, const bool direct)
    {
      this->direct = direct;
      preconditioners.reinit(grid);
      if (grid.uses_matrix())
        {
          // The shared matrix' rows are the owned DoFs in ascending order.
          const auto all =
            grid.get_space().control_points(grid.get_dof_handler());
          std::vector<long long>  rows;
          std::vector<Point<dim>> points;
          for (const auto i : grid.locally_owned_dofs())
            {
              rows.push_back(i);
              points.push_back(all[i]);
            }
          rigid_modes.reinit(std::move(rows), std::move(points));
        }
    }

    template <int dim>
    void
    MassSolver<dim>::set_sparsity(const TrilinosWrappers::SparseMatrix &M)
    {
      component_cg.reinit(M.trilinos_matrix());
    }

    template <int dim>
    bool
    MassSolver<dim>::share_matrix(const ComponentConstraints<dim> &constraints,
                                  const GridDofLayout<dim>        &layout,
                                  const bool direct_assembly,
                                  MPI_Comm   comm) const
    {
      // One component has nothing to share; the direct solver, AMG and
      // p-multigrid work on the constrained matrix of a component. Decided
      // over all ranks (the solves are collective): a rank without cells
      // has no cell slots, and constraints are seen per rank.
      bool here = dim > 1 && !direct &&
                  (layout.owned_cells().empty() || direct_assembly) &&
                  preconditioners.works_on_shared_matrix();
      for (unsigned int d = 0; d < dim; ++d)
        here = here && constraints.only_dirichlet(d);
      return Utilities::MPI::min(static_cast<unsigned int>(here), comm) == 1;
    }

    template <int dim>
    void
    MassSolver<dim>::classify(const ComponentConstraints<dim> &constraints,
                              const GridDofLayout<dim>        &layout,
                              const bool                       direct_assembly,
                              MPI_Comm                         comm)
    {
      components_together =
        share_matrix(constraints, layout, direct_assembly, comm);
      // One reduction for all components: this runs every step.
      unsigned int here[2 * dim], everywhere[2 * dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          const std::vector<char> &constrained = constraints.constrained(d);
          here[d]                              = constraints.only_dirichlet(d);
          here[dim + d]                        = 1;
          for (const unsigned int l : layout.owned_to_relevant())
            {
              here[d]       = here[d] && constrained[l];
              here[dim + d] = here[dim + d] && !constrained[l];
            }
        }
      Utilities::MPI::min(here, comm, everywhere);
      for (unsigned int d = 0; d < dim; ++d)
        {
          fixed_everywhere[d] = everywhere[d] == 1;
          free_component[d]   = everywhere[dim + d] == 1;
        }
    }

    template <int dim>
    double
    MassSolver<dim>::step_tolerance(const unsigned int d) const
    {
      // A free component's exact solve conserves its momentum (and, if
      // all are free, the angular momentum) to round-off; a looser one
      // without the rigid-mode correction would lose 1e-9 of a spinning
      // block's angular momentum in a quarter turn (doc/performance.md).
      // Where DoFs are fixed, the boundary exchanges momentum anyway and
      // the step decides.
      return free_component[d] ? 0. : settings.step_tolerance;
    }

    template <int dim>
    void
    MassSolver<dim>::prepare_shared(
      const TrilinosWrappers::SparseMatrix &M,
      const ComponentConstraints<dim>      &constraints,
      const GridDofLayout<dim>             &layout,
      const unsigned int                    generation)
    {
      const auto &owned_to_relevant = layout.owned_to_relevant();
      rigid_modes.matrix_changed();
      fixed_rows.resize(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          const std::vector<char> &constrained = constraints.constrained(d);
          fixed_rows[d].clear();
          for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
            if (constrained[owned_to_relevant[j]])
              fixed_rows[d].push_back(j);
          // Components with the same fixed rows (all of a free body's)
          // have the same masked matrix: one preconditioner serves them.
          preconditioner_of[d] = d;
          if (d > 0 && fixed_rows[d] == fixed_rows[d - 1])
            preconditioner_of[d] = preconditioner_of[d - 1];
          else
            preconditioners.initialize_masked(d, M, fixed_rows[d], generation);
          factored[d] = false;
        }
    }

    template <int dim>
    void
    MassSolver<dim>::prepare(const unsigned int                    d,
                             const GridSystem<dim>                &grid,
                             const TrilinosWrappers::SparseMatrix &A,
                             const std::vector<char>              &constrained,
                             const unsigned int                    generation)
    {
      factored[d] = direct && dense[d].factorize(A);
      if (!factored[d])
        preconditioners.initialize(d, grid, A, constrained, generation);
    }

    template <int dim>
    void
    MassSolver<dim>::set_guess(
      const std::vector<Tensor<1, dim>> &solution,
      const Epetra_Map                  &map,
      const std::vector<unsigned int>   &owned_to_relevant)
    {
      if (!rhs_columns || !rhs_columns->Map().SameAs(map))
        {
          rhs_columns      = std::make_unique<Epetra_MultiVector>(map, dim);
          solution_columns = std::make_unique<Epetra_MultiVector>(map, dim);
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          double *const x = (*solution_columns)[d];
          for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
            x[j] = solution[owned_to_relevant[j]][d];
          for (const unsigned int j : fixed_rows[d])
            x[j] = 0;
        }
    }

    template <int dim>
    double *
    MassSolver<dim>::rhs_column(const unsigned int d)
    {
      return (*rhs_columns)[d];
    }

    template <int dim>
    const double *
    MassSolver<dim>::solution_column(const unsigned int d) const
    {
      return (*solution_columns)[d];
    }

    template <int dim>
    unsigned int
    MassSolver<dim>::solve_components(const TrilinosWrappers::SparseMatrix &M,
                                      double &condition_number)
    {
      std::vector<const VertexBlockJacobi *> blocks;
      std::vector<double>                    step_tolerances;
      for (unsigned int d = 0; d < dim; ++d)
        {
          step_tolerances.push_back(free_component[d] ?
                                      settings.free_step_tolerance :
                                      settings.step_tolerance);
          double *const b = (*rhs_columns)[d];
          for (const unsigned int j : fixed_rows[d])
            b[j] = 0;
          blocks.push_back(&preconditioners.block_jacobi(preconditioner_of[d]));
        }
      const ComponentCG::Result result =
        component_cg.solve(M.trilinos_matrix(),
                           blocks,
                           fixed_rows,
                           *solution_columns,
                           *rhs_columns,
                           settings.tolerance,
                           step_tolerances,
                           settings.max_iterations);
      rigid_modes.correct(M.trilinos_matrix(),
                          free_component,
                          *rhs_columns,
                          *solution_columns);
      condition_number = std::max(condition_number, result.condition_number);
      unsigned int iterations = 0;
      for (const unsigned int i : result.iterations)
        iterations += i;
      return iterations;
    }

    template <int dim>
    unsigned int
    MassSolver<dim>::solve(const unsigned int                    d,
                           const TrilinosWrappers::SparseMatrix &A,
                           const TrilinosWrappers::MPI::Vector  &rhs,
                           TrilinosWrappers::MPI::Vector        &x,
                           double &condition_number)
    {
      // x holds the guess (zero on constrained DoFs).
      const double norm = rhs.l2_norm();
      if (norm == 0)
        {
          x = 0;
          return 0;
        }
      if (factored[d])
        {
          dense[d].solve(rhs, x);
          return 0;
        }
      // From a warm start the residual may also drop by Step tolerance
      // from the guess' (ReductionControl: the larger of the two limits).
      const bool       warm = step_tolerance(d) > 0 && x.linfty_norm() > 0;
      ReductionControl control(settings.max_iterations,
                               settings.tolerance * norm,
                               warm ? step_tolerance(d) : 0.,
                               false,
                               false);
      preconditioners.solve(d, A, control, rhs, x, condition_number);
      return control.last_step();
    }

    template class MassSolver<1>;
    template class MassSolver<2>;
  } // namespace Solver
} // namespace psmpm
