// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <psmpm/base/format.h>
#include <psmpm/basis/extrapolation.h>
#include <psmpm/solver/grid_system.h>

namespace psmpm
{
  namespace Solver
  {
    void
    GridSystem::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      prm.declare_entry(
        "Type",
        "partially lumped",
        Patterns::Selection(
          "consistent|lumped|partially lumped|deactivate|extrapolate"),
        "consistent: sparse matrix solved by CG; lumped: "
        "row-sum diagonal (no sparse matrix is built); "
        "partially lumped: couplings of free-boundary vertices "
        "moved to the diagonal; deactivate: functions with a "
        "particle diagonal below Threshold x their full-support "
        "diagonal set to zero; extrapolate: vertices with such "
        "a function follow the linear part of the nearest well "
        "supported vertex.");
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
      prm.declare_entry("Threshold",
                        "0.05",
                        Patterns::Double(0, 1),
                        "Relative bound M_ii / M_ii(full support) below which "
                        "a function counts as poorly supported (deactivate, "
                        "extrapolate).");
      prm.leave_subsection();
    }

    void
    GridSystem::Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      const std::string t = prm.get("Type");
      type                = t == "lumped"           ? MassType::lumped :
                            t == "partially lumped" ? MassType::partially_lumped :
                            t == "deactivate"       ? MassType::deactivate :
                            t == "extrapolate"      ? MassType::extrapolate :
                                                      MassType::consistent;
      threshold           = prm.get_double("Threshold");
      tolerance           = prm.get_double("Solver tolerance");
      max_iterations      = prm.get_integer("Maximum iterations");
      preconditioner      = prm.get("Preconditioner");
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
    GridSystem::reinit(const std::array<std::set<types::boundary_id>, 2> &fixed,
                       const double density)
    {
      owned = dof_handler.locally_owned_dofs();
      if (parameters.type == MassType::extrapolate)
        // Extrapolation may tie a vertex to one two cells away: keep every
        // DoF at hand (the mesh is replicated anyway).
        relevant = complete_index_set(dof_handler.n_dofs());
      else
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
          auto &c = dirichlet[d];
          c.clear();
          c.reinit(relevant);
          space.make_dirichlet_constraints(dof_handler,
                                           fixed[d],
                                           Functions::ZeroFunction<2>(),
                                           c);
          c.close();
          active_constraints[d].clear();
          active_constraints[d].copy_from(c);
        }

      lumped.reinit(owned, comm);
      writable.reinit(owned, relevant, comm, true);
      ghosted.reinit(owned, relevant, comm);
      cell_lumped.assign(n_cells * dofs_per_cell, 0.);
      cell_rhs.assign(n_cells * dofs_per_cell, Tensor<1, 2>());
      local_lumped.assign(relevant_global.size(), 0.);
      scratch.assign(relevant_global.size(), 0.);

      build_vertex_tables(fixed);
      previous_outer.clear();
      if (uses_matrix())
        {
          build_sparsity();
          cell_mass.assign(n_cells * dofs_per_cell * dofs_per_cell, 0.);
          compute_full_support_diagonal(density);
        }
      else
        cell_mass.clear();
    }

    void
    GridSystem::build_vertex_tables(
      const std::array<std::set<types::boundary_id>, 2> &fixed)
    {
      const auto &tria = dof_handler.get_triangulation();
      dofs_per_vertex  = space.dof_layout().n_dofs_per_vertex();
      vertex_dofs.assign(tria.n_vertices(), {});
      vertex_cells.assign(tria.n_vertices(), {});
      vertex_neighbors.assign(tria.n_vertices(), {});
      vertex_on_free_boundary.assign(tria.n_vertices(), false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int v = cell->vertex_index(k);
              vertex_cells[v].push_back(cell->active_cell_index());
              for (unsigned int l = 0; l < 3; ++l)
                if (l != k)
                  vertex_neighbors[v].push_back(cell->vertex_index(l));
              if (vertex_dofs[v].empty())
                for (unsigned int q = 0; q < dofs_per_vertex; ++q)
                  {
                    const auto g = cell->vertex_dof_index(k, q);
                    vertex_dofs[v].push_back(relevant.is_element(g) ?
                                               relevant.index_within_set(g) :
                                               numbers::invalid_unsigned_int);
                  }
            }
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                fixed[0].count(cell->face(f)->boundary_id()) == 0 &&
                fixed[1].count(cell->face(f)->boundary_id()) == 0)
              for (const auto v : cell->face(f)->vertex_indices())
                vertex_on_free_boundary[cell->face(f)->vertex_index(v)] = true;
        }
      for (auto &n : vertex_neighbors)
        {
          std::sort(n.begin(), n.end());
          n.erase(std::unique(n.begin(), n.end()), n.end());
        }
    }

    void
    GridSystem::build_sparsity()
    {
      DynamicSparsityPattern dsp(relevant);
      for (unsigned int d = 0; d < 2; ++d)
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        active_constraints[d],
                                        true);
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      for (unsigned int d = 0; d < 2; ++d)
        matrix[d].reinit(owned, owned, dsp, comm);
    }

    void
    GridSystem::compute_full_support_diagonal(const double density)
    {
      // int rho phi_i^2 over the whole support, by the centroids of a
      // uniform 8 x 8 split of each triangle: only a scale for the
      // relative thresholds, so a few per mille are good enough.
      const unsigned int  k = 8, n = dofs_per_cell;
      std::vector<double> cell_full(n_cells * n, 0.), values(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c  = cell->active_cell_index();
            const Point<2>     v0 = cell->vertex(0);
            const Tensor<1, 2> e1 = (cell->vertex(1) - v0) / k;
            const Tensor<1, 2> e2 = (cell->vertex(2) - v0) / k;
            const double       w  = density * cell->measure() / (k * k);
            for (unsigned int j = 0; j < k; ++j)
              for (unsigned int i = 0; i + j < k; ++i)
                for (const double s : {1. / 3, 2. / 3})
                  {
                    if (s > 0.5 && i + j + 1 >= k)
                      continue;
                    const Point<2> x = v0 + (i + s) * e1 + (j + s) * e2;
                    space.evaluate(c, x, values.data(), nullptr);
                    for (unsigned int l = 0; l < n; ++l)
                      cell_full[c * n + l] += w * values[l] * values[l];
                  }
          }
      scatter(cell_full.data(), 1, 0, writable);
      TrilinosWrappers::MPI::Vector full(owned, comm);
      full = writable;
      to_local(full, local_full_diagonal);
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

    std::vector<bool>
    GridSystem::poorly_supported_vertices(
      const std::vector<double> &diagonal) const
    {
      // Hysteresis: a vertex that was poorly supported stays so until its
      // support has doubled past the bound, so that particles hovering at
      // the bound do not switch the discrete space back and forth.
      std::vector<bool> outer(vertex_dofs.size(), false);
      for (unsigned int v = 0; v < vertex_dofs.size(); ++v)
        {
          const double bound =
            parameters.threshold *
            (!previous_outer.empty() && previous_outer[v] ? 2. : 1.);
          for (const unsigned int l : vertex_dofs[v])
            if (l != numbers::invalid_unsigned_int &&
                diagonal[l] < bound * local_full_diagonal[l])
              outer[v] = true;
        }
      return outer;
    }

    void
    GridSystem::lump_free_boundary_couplings()
    {
      // Filled cells, known on every rank.
      std::vector<int> filled(n_cells, 0);
      for (const unsigned int c : owned_cells)
        for (unsigned int k = 0; k < dofs_per_cell; ++k)
          filled[c] |= cell_lumped[c * dofs_per_cell + k] > 0;
      {
        std::vector<int> global(n_cells);
        Utilities::MPI::max(filled, comm, global);
        filled.swap(global);
      }

      std::vector<bool> boundary_dof(relevant_global.size(), false);
      unsigned int      n_treated = 0;
      for (unsigned int v = 0; v < vertex_cells.size(); ++v)
        {
          bool any_filled = false, any_empty = false;
          for (const unsigned int c : vertex_cells[v])
            (filled[c] ? any_filled : any_empty) = true;
          if (any_filled && (any_empty || vertex_on_free_boundary[v]))
            for (const unsigned int l : vertex_dofs[v])
              if (l != numbers::invalid_unsigned_int)
                {
                  boundary_dof[l] = true;
                  n_treated += owned.is_element(relevant_global[l]);
                }
        }
      stats.n_treated_dofs = Utilities::MPI::sum(n_treated, comm);

      // Move every coupling that involves a boundary function to both
      // diagonals: row sums are unchanged (momentum is conserved) and the
      // change, m (e_k - e_l)(e_k - e_l)^T with m >= 0, keeps the matrix
      // symmetric positive definite.
      const unsigned int n = dofs_per_cell;
      for (const unsigned int c : owned_cells)
        {
          double *M = &cell_mass[c * n * n];
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = k + 1; l < n; ++l)
              if (boundary_dof[cell_dofs[c * n + k]] ||
                  boundary_dof[cell_dofs[c * n + l]])
                {
                  const double m = M[k * n + l];
                  M[k * n + l] = M[l * n + k] = 0;
                  M[k * n + k] += m;
                  M[l * n + l] += m;
                }
        }
    }

    bool
    GridSystem::update_step_constraints(const std::vector<bool> &outer)
    {
      if (outer == previous_outer)
        return false;
      previous_outer = outer;

      const auto  &vertices  = dof_handler.get_triangulation().get_vertices();
      unsigned int n_treated = 0;
      for (unsigned int d = 0; d < 2; ++d)
        {
          AffineConstraints<double> step(relevant);
          for (unsigned int v = 0; v < outer.size(); ++v)
            {
              if (!outer[v])
                continue;
              // Nearest well supported vertex, searching ring by ring.
              unsigned int              from = numbers::invalid_unsigned_int;
              std::vector<unsigned int> ring = {v};
              std::set<unsigned int>    seen = {v};
              for (unsigned int layer = 0;
                   layer < 4 && from == numbers::invalid_unsigned_int &&
                   parameters.type == MassType::extrapolate;
                   ++layer)
                {
                  std::vector<unsigned int> next;
                  for (const unsigned int a : ring)
                    for (const unsigned int b : vertex_neighbors[a])
                      if (seen.insert(b).second)
                        next.push_back(b);
                  double best = std::numeric_limits<double>::max();
                  for (const unsigned int b : next)
                    if (!outer[b] && vertices[b].distance(vertices[v]) < best)
                      best = vertices[b].distance(vertices[v]), from = b;
                  ring = next;
                }
              FullMatrix<double> W;
              if (from != numbers::invalid_unsigned_int)
                W =
                  Basis::extrapolation_weights(space,
                                               dof_handler.get_triangulation(),
                                               from,
                                               v);
              for (unsigned int q = 0; q < dofs_per_vertex; ++q)
                {
                  const unsigned int l = vertex_dofs[v][q];
                  if (l == numbers::invalid_unsigned_int)
                    continue;
                  const auto g = relevant_global[l];
                  if (dirichlet[d].is_constrained(g) || step.is_constrained(g))
                    continue;
                  step.add_line(g);
                  ++n_treated;
                  if (from != numbers::invalid_unsigned_int)
                    for (unsigned int r = 0; r < dofs_per_vertex; ++r)
                      if (std::abs(W(q, r)) > 1e-14)
                        step.add_entry(g,
                                       relevant_global[vertex_dofs[from][r]],
                                       W(q, r));
                }
            }
          step.merge(dirichlet[d],
                     AffineConstraints<double>::left_object_wins,
                     true);
          step.close();
          active_constraints[d].clear();
          active_constraints[d].copy_from(step);
        }
      stats.n_treated_dofs = n_treated / 2;
      return true;
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
          else if (!dirichlet[0].is_constrained(i) ||
                   !dirichlet[1].is_constrained(i))
            ++n_empty;
        }
      stats.min_diagonal     = Utilities::MPI::min(dmin, comm);
      stats.max_diagonal     = Utilities::MPI::max(dmax, comm);
      stats.n_empty_dofs     = Utilities::MPI::sum(n_empty, comm);
      stats.iterations       = 0;
      stats.condition_number = 0;

      if (!uses_matrix())
        return;

      // Particle diagonal M_ii relative to the full-support one.
      const unsigned int  n = dofs_per_cell;
      std::vector<double> cell_diagonal(n_cells * n, 0.);
      for (const unsigned int c : owned_cells)
        for (unsigned int k = 0; k < n; ++k)
          cell_diagonal[c * n + k] = cell_mass[(c * n + k) * n + k];
      scatter(cell_diagonal.data(), 1, 0, writable);
      TrilinosWrappers::MPI::Vector diagonal_vector(owned, comm);
      diagonal_vector = writable;
      std::vector<double> diagonal;
      to_local(diagonal_vector, diagonal);
      double rmin = std::numeric_limits<double>::max();
      for (const auto i : owned)
        {
          const unsigned int l = relevant.index_within_set(i);
          if (local_full_diagonal[l] > 0 && diagonal[l] > 0)
            rmin = std::min(rmin, diagonal[l] / local_full_diagonal[l]);
        }
      stats.min_relative_diagonal = Utilities::MPI::min(rmin, comm);

      if (parameters.type == MassType::partially_lumped)
        lump_free_boundary_couplings();
      else if (parameters.type == MassType::deactivate ||
               parameters.type == MassType::extrapolate)
        {
          if (update_step_constraints(poorly_supported_vertices(diagonal)))
            build_sparsity();
        }

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
              active_constraints[d].distribute_local_to_global(local,
                                                               dofs,
                                                               matrix[d]);
            }
          matrix[d].compress(VectorOperation::add);
          // A DoF whose support holds no particle has an empty row: give it
          // a unit diagonal so that its (zero) coefficient is well defined.
          for (const auto i : owned)
            if (lumped[i] == 0 && !active_constraints[d].is_constrained(i))
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
          active_constraints[d].distribute_local_to_global(local_rhs,
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
      cg.connect_condition_number_slot([this](const double c) {
        stats.condition_number = std::max(stats.condition_number, c);
      });
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
          if (uses_matrix())
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
          active_constraints[d].distribute(x);
          to_local(x, local);
          for (unsigned int l = 0; l < local.size(); ++l)
            solution[l][d] = local[l];
        }
    }
  } // namespace Solver
} // namespace psmpm
