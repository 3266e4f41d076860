// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <psmpm/base/format.h>
#include <psmpm/solver/grid_system.h>

namespace psmpm
{
  namespace Solver
  {
    void
    GridSystem::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      prm.declare_entry("Type",
                        "consistent",
                        Patterns::Selection("consistent|lumped"),
                        "consistent: sparse matrix solved by CG; lumped: "
                        "row-sum diagonal (no sparse matrix is built).");
      prm.declare_entry("Solver tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Relative residual reduction for CG.");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "CG iteration limit; reaching it stops the run as "
                        "unstable.");
      prm.declare_entry("Preconditioner",
                        "jacobi",
                        Patterns::Selection("jacobi|amg"),
                        "Preconditioner for CG.");
      prm.leave_subsection();
    }

    void
    GridSystem::Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      type =
        prm.get("Type") == "lumped" ? MassType::lumped : MassType::consistent;
      tolerance      = prm.get_double("Solver tolerance");
      max_iterations = prm.get_integer("Maximum iterations");
      preconditioner = prm.get("Preconditioner");
      prm.leave_subsection();
      AssertThrow(tolerance > 0 && tolerance < 1,
                  ExcMessage("Mass matrix/Solver tolerance = " +
                             prm_value(tolerance) + ": must lie in (0, 1)."));
    }

    GridSystem::GridSystem(const Parameters    &parameters,
                           const Basis::Space  &space,
                           const DoFHandler<2> &dof_handler,
                           MPI_Comm             comm)
      : parameters(parameters)
      , dofs_per_cell(space.dofs_per_cell())
      , n_cells(dof_handler.get_triangulation().n_active_cells())
      , space(space)
      , dof_handler(dof_handler)
      , comm(comm)
    {
    }

    void
    GridSystem::reinit(const std::array<std::set<types::boundary_id>, 2> &fixed)
    {
      owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      relevant_global.resize(relevant.n_elements());
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        relevant_global[l] = relevant.nth_index_in_set(l);

      owned_cells.clear();
      cell_dofs.assign(n_cells * dofs_per_cell, 0);
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c = cell->active_cell_index();
            owned_cells.push_back(c);
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dofs_per_cell; ++k)
              cell_dofs[c * dofs_per_cell + k] =
                relevant.index_within_set(dofs[k]);
          }

      for (unsigned int d = 0; d < 2; ++d)
        {
          auto &c = component_constraints[d];
          c.clear();
          c.reinit(relevant);
          space.make_dirichlet_constraints(dof_handler,
                                           fixed[d],
                                           Functions::ZeroFunction<2>(),
                                           c);
          c.close();
        }

      if (parameters.type == MassType::consistent)
        {
          DynamicSparsityPattern dsp(relevant);
          for (unsigned int d = 0; d < 2; ++d)
            DoFTools::make_sparsity_pattern(dof_handler,
                                            dsp,
                                            component_constraints[d],
                                            true);
          SparsityTools::distribute_sparsity_pattern(dsp,
                                                     owned,
                                                     comm,
                                                     relevant);
          for (unsigned int d = 0; d < 2; ++d)
            matrix[d].reinit(owned, owned, dsp, comm);
          cell_mass.assign(n_cells * dofs_per_cell * dofs_per_cell, 0.);
        }
      else
        cell_mass.clear();

      lumped.reinit(owned, comm);
      writable.reinit(owned, relevant, comm, true);
      ghosted.reinit(owned, relevant, comm);
      cell_lumped.assign(n_cells * dofs_per_cell, 0.);
      cell_rhs.assign(n_cells * dofs_per_cell, Tensor<1, 2>());
      local_lumped.assign(relevant_global.size(), 0.);
      scratch.assign(relevant_global.size(), 0.);
    }

    void
    GridSystem::zero_cell_mass()
    {
      const unsigned int n = dofs_per_cell;
      for (const unsigned int c : owned_cells)
        {
          std::fill_n(cell_lumped.begin() + c * n, n, 0.);
          if (!cell_mass.empty())
            std::fill_n(cell_mass.begin() + c * n * n, n * n, 0.);
        }
    }

    void
    GridSystem::zero_cell_rhs()
    {
      for (const unsigned int c : owned_cells)
        std::fill_n(cell_rhs.begin() + c * dofs_per_cell,
                    dofs_per_cell,
                    Tensor<1, 2>());
    }

    void
    GridSystem::scatter(const double                  *cell_values,
                        const unsigned int             stride,
                        const unsigned int             offset,
                        TrilinosWrappers::MPI::Vector &target) const
    {
      // Sum cell contributions locally first, then hand Trilinos one
      // vector: far cheaper than one add() per cell.
      std::vector<double> &local = const_cast<std::vector<double> &>(scratch);
      std::fill(local.begin(), local.end(), 0.);
      for (const unsigned int c : owned_cells)
        for (unsigned int k = 0; k < dofs_per_cell; ++k)
          local[cell_dofs[c * dofs_per_cell + k]] +=
            cell_values[(c * dofs_per_cell + k) * stride + offset];
      target = 0;
      target.add(relevant_global, local);
      target.compress(VectorOperation::add);
    }

    void
    GridSystem::to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
                         std::vector<double>                 &local) const
    {
      auto &g = const_cast<TrilinosWrappers::MPI::Vector &>(ghosted);
      g       = owned_vector;
      local.resize(relevant_global.size());
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        local[l] = g[relevant_global[l]];
    }

    void
    GridSystem::assemble_mass()
    {
      scatter(cell_lumped.data(), 1, 0, writable);
      lumped = writable;
      to_local(lumped, local_lumped);

      // Statistics of the diagonal over supported DoFs.
      double       dmin = std::numeric_limits<double>::max(), dmax = 0;
      unsigned int n_empty = 0;
      for (const auto i : owned)
        {
          const double m = lumped[i];
          if (m > 0)
            dmin = std::min(dmin, m), dmax = std::max(dmax, m);
          else if (!component_constraints[0].is_constrained(i) ||
                   !component_constraints[1].is_constrained(i))
            ++n_empty;
        }
      stats.min_diagonal = Utilities::MPI::min(dmin, comm);
      stats.max_diagonal = Utilities::MPI::max(dmax, comm);
      stats.n_empty_dofs = Utilities::MPI::sum(n_empty, comm);
      stats.iterations   = 0;

      if (parameters.type != MassType::consistent)
        return;

      const unsigned int                   n = dofs_per_cell;
      FullMatrix<double>                   local(n, n);
      std::vector<types::global_dof_index> dofs(n);
      for (unsigned int d = 0; d < 2; ++d)
        {
          matrix[d] = 0;
          for (const unsigned int c : owned_cells)
            {
              for (unsigned int k = 0; k < n; ++k)
                {
                  dofs[k] = relevant_global[cell_dofs[c * n + k]];
                  for (unsigned int l = 0; l < n; ++l)
                    local(k, l) = cell_mass[(c * n + k) * n + l];
                }
              component_constraints[d].distribute_local_to_global(local,
                                                                  dofs,
                                                                  matrix[d]);
            }
          matrix[d].compress(VectorOperation::add);
          // A DoF whose support holds no particle has an empty row: give it
          // a unit diagonal so that its (zero) coefficient is well defined.
          for (const auto i : owned)
            if (lumped[i] == 0 && !component_constraints[d].is_constrained(i))
              matrix[d].set(i, i, 1.0);
          matrix[d].compress(VectorOperation::insert);
          if (parameters.preconditioner == "amg")
            amg[d].initialize(matrix[d]);
          else
            jacobi[d].initialize(matrix[d]);
        }
    }

    unsigned int
    GridSystem::solve_consistent(const unsigned int             d,
                                 TrilinosWrappers::MPI::Vector &x)
    {
      const unsigned int n = dofs_per_cell;
      writable             = 0;
      Vector<double>                       local_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const unsigned int c : owned_cells)
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              dofs[k]      = relevant_global[cell_dofs[c * n + k]];
              local_rhs[k] = cell_rhs[c * n + k][d];
            }
          component_constraints[d].distribute_local_to_global(local_rhs,
                                                              dofs,
                                                              writable);
        }
      writable.compress(VectorOperation::add);
      TrilinosWrappers::MPI::Vector rhs(owned, comm);
      rhs               = writable;
      x                 = 0;
      const double norm = rhs.l2_norm();
      if (norm == 0)
        return 0;
      SolverControl                           control(parameters.max_iterations,
                            parameters.tolerance * norm,
                            false,
                            false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      if (parameters.preconditioner == "amg")
        cg.solve(matrix[d], x, rhs, amg[d]);
      else
        cg.solve(matrix[d], x, rhs, jacobi[d]);
      return control.last_step();
    }

    void
    GridSystem::solve(std::vector<Tensor<1, 2>> &solution)
    {
      solution.resize(relevant_global.size());
      TrilinosWrappers::MPI::Vector x(owned, comm);
      std::vector<double>           local;
      for (unsigned int d = 0; d < 2; ++d)
        {
          if (parameters.type == MassType::consistent)
            stats.iterations += solve_consistent(d, x);
          else
            {
              // Tensor<1,2> stores its two components contiguously.
              scatter(&cell_rhs[0][0], 2, d, writable);
              for (const auto i : owned)
                {
                  const double m = lumped[i];
                  x[i]           = m > 0 ? writable[i] / m : 0.;
                }
              x.compress(VectorOperation::insert);
            }
          component_constraints[d].distribute(x);
          to_local(x, local);
          for (unsigned int l = 0; l < local.size(); ++l)
            solution[l][d] = local[l];
        }
    }
  } // namespace Solver
} // namespace psmpm
