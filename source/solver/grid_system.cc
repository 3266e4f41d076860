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
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/component_cg.h>
#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/solver_failure.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Preconditioner = block jacobi on a space with several DoFs per
      /// vertex (Powell-Sabin). With one DoF per vertex the blocks are the
      /// diagonal: Trilinos' point Jacobi then, as before the option
      /// existed (bit-identical results for P1 and B-splines).
      template <int dim>
      bool
      vertex_blocks(const std::string       &preconditioner,
                    const Basis::Space<dim> &space)
      {
        return preconditioner == "block jacobi" && space.dofs_per_vertex() > 1;
      }

      /// Mass matrix/Sampling stabilization: a number >= 0, or
      /// "automatic" (-1, resolved by the simulator).
      double
      parse_sampling_stabilization(const std::string &value)
      {
        if (value == "automatic")
          return -1;
        std::size_t end  = 0;
        double      beta = -1;
        try
          {
            beta = std::stod(value, &end);
          }
        catch (...)
          {
            end = 0;
          }
        AssertThrow(
          end > 0 && value.find_first_not_of(" \t", end) == std::string::npos &&
            std::isfinite(beta) && beta >= 0,
          ExcMessage("Mass matrix/Sampling stabilization = '" + value +
                     "': must be automatic or a number >= 0."));
        return beta;
      }

      /// Preconditioner = pmg: the hierarchy's share of Mass matrix.
      template <int dim>
      typename PMultigridHierarchy<dim>::Parameters
      multigrid_parameters(const std::string &coarse,
                           const std::string &smoother,
                           const unsigned int smoothing_steps)
      {
        typename PMultigridHierarchy<dim>::Parameters p;
        p.coarse               = coarse;
        p.cycle.smoother       = smoother;
        p.cycle.pre_smoothing  = smoothing_steps;
        p.cycle.post_smoothing = smoothing_steps;
        return p;
      }
    } // namespace

    template <int dim>
    void
    GridSystem<dim>::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      prm.declare_entry(
        "Type",
        "automatic",
        Patterns::Selection("automatic|" +
                            MassStrategyRegistry<dim>::instance().selection()),
        "automatic: the basis' measured default (lumped for powell-sabin, "
        "consistent for bspline (doc/chapter.md), "
        "ghost penalty for linear, partially lumped for linear with a "
        "moving grid (otm); doc/transfers.md); " +
          MassStrategyRegistry<dim>::instance().documentation());
      prm.declare_entry("Solver tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Relative residual reduction for CG.");
      prm.declare_entry(
        "Step tolerance",
        "1e-6",
        Patterns::Double(0),
        "A CG solve that starts from the last step's field (Warm start) "
        "also ends once its residual is this fraction of the residual of "
        "that guess, which measures what the step changes: the solve's "
        "error is then about this fraction of the step's change instead of "
        "Solver tolerance times the whole field. Solves from zero use "
        "Solver tolerance alone, and so do components without any fixed "
        "DoF (a free body: exact solves conserve its momentum and angular "
        "momentum to round-off). 0: Solver tolerance alone, always "
        "(doc/performance.md, \"What the time step needs of the mass "
        "solves\").");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "CG iteration limit; reaching it stops the run as "
                        "unstable.");
      prm.declare_entry(
        "Preconditioner",
        "block jacobi",
        Patterns::Selection("jacobi|block jacobi|amg|pmg"),
        "Preconditioner for CG. block jacobi: the inverse of each vertex's "
        "diagonal block (Powell-Sabin: the 3 x 3 block of the three "
        "functions of a vertex, which overlap most; 1.5-3x fewer iterations "
        "than jacobi on filled meshes); for spaces with one DoF per vertex "
        "(P1, B-splines) the same as jacobi (point Jacobi). pmg: one "
        "p-multigrid V-cycle, Powell-Sabin "
        "level smoothed, coarse level the P1 space on the same "
        "triangulation (Galerkin P^T M P, exact prolongation of affine "
        "functions through the control points, direct coarse solve); "
        "Basis/Type = powell-sabin and one MPI process only "
        "(doc/solver_study.md, part 2).");
      prm.declare_entry("Multigrid smoother",
                        "gauss-seidel",
                        Patterns::Selection("gauss-seidel|jacobi"),
                        "Preconditioner = pmg: smoother on the Powell-Sabin "
                        "level (gauss-seidel: forward sweeps before, "
                        "backward after the coarse correction, so that the "
                        "cycle is symmetric as CG needs; jacobi: damped by "
                        "2/3).");
      prm.declare_entry(
        "Multigrid coarse matrix",
        "galerkin",
        Patterns::Selection("galerkin|particles"),
        "Preconditioner = pmg: the P1 level's matrix. galerkin: P^T M P "
        "of the assembled matrix (constrained rows of P zero); particles: "
        "the P1 particle mass matrix, formed per cell from the same "
        "particle blocks (a P1 hat is, on one cell, exactly a combination "
        "of the cell's Powell-Sabin functions), P1 vertices on a fixed "
        "boundary constrained.");
      prm.declare_entry("Multigrid smoothing steps",
                        "1",
                        Patterns::Integer(1),
                        "Preconditioner = pmg: sweeps before and after the "
                        "coarse correction.");
      prm.declare_entry("Warm start",
                        "true",
                        Patterns::Bool(),
                        "CG starts from the last step's solution of the same "
                        "system (the grid velocity or acceleration, kept in "
                        "checkpoints) instead of zero; the stopping test is "
                        "relative to the right-hand side either way "
                        "(doc/performance.md: 24 % fewer iterations on the "
                        "closed Powell-Sabin throughput bar).");
      prm.declare_entry("Direct solver size",
                        "600",
                        Patterns::Integer(0),
                        "Mass systems with at most this many DoFs are solved "
                        "by a Cholesky factorization (in the matrix' envelope) "
                        "instead "
                        "of CG when the run has one MPI process: exact, and "
                        "cheaper than CG's fixed cost on small meshes "
                        "(doc/performance.md: faster up to 582 DoFs on a "
                        "bar, slower at 841 on a square; storage n^2 doubles, "
                        "2.9 MB at 600). The statistics then show 0 "
                        "CG iterations and no condition estimate (0). A "
                        "matrix that is not positive definite falls back to "
                        "CG. 0: always CG.");
      prm.declare_entry("Threshold",
                        "0.05",
                        Patterns::Double(0, 1),
                        "Relative bound M_ii / M_ii(full support) below which "
                        "a function counts as poorly supported ("
                        "extrapolate).");
      prm.declare_entry(
        "Sampling stabilization",
        "automatic",
        Patterns::Anything(),
        "Target t of the sampling stabilisation, for every matrix "
        "strategy: on each cell c whose particles give the cell's "
        "non-polynomial modes less than t of their exact mass (smallest "
        "eigenvalue lambda), add rho_c (t - lambda) int_c (u - P u)(v - P v), "
        "P the L2 projection onto the polynomials of the space's degree on "
        "c, rho_c the particle mass over |c|. It vanishes for those "
        "polynomials (momentum, affine and quadratic fields are kept). "
        "Where the particles leave a quadratic mode of c (orthogonal to the "
        "affine fields) below t of its exact mass (particles on two lines "
        "do not see the quadratic that vanishes on both), that mode alone "
        "is lifted to t as well; affine fields and momentum are still kept. "
        "Together they keep the matrix definite when a sparse particle "
        "layout leaves fields that vanish at every particle "
        "(doc/stability.md, \"Sparse particle layouts\"). Powell-Sabin "
        "and quadratic tensor B-splines. On P1 with Type = ghost penalty "
        "the same t caps each cell's fill at lambda / t (lambda: the "
        "smallest eigenvalue of the cell's particle mass relative to the "
        "exact one), so a cell whose particles leave a linear field unseen "
        "(one particle, particles on a line) gets the penalty of a partly "
        "filled cell (doc/stability.md, \"Sampling of P1 cells\"). "
        "A number >= 0 (0: off) or automatic: 0.5 with "
        "Type = automatic on a grid that does not move, 0 otherwise.");
      prm.declare_entry("Stabilization",
                        "1",
                        Patterns::Double(0),
                        "Weight of the stabilised consistent strategies: "
                        "gamma of 'ghost penalty' (gamma rho (1 - fill) "
                        "int (u - Pu)^2 on face patches next to cells that "
                        "are not filled), alpha of 'fictitious mass' (alpha "
                        "rho (1 - fill) int N_k N_l on every cell); fill: "
                        "particle mass over rho |cell|, at most 1.");
      MassStrategyRegistry<dim>::instance().declare_parameters(prm);
      prm.leave_subsection();
    }

    template <int dim>
    void
    GridSystem<dim>::Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      type           = prm.get("Type");
      threshold      = prm.get_double("Threshold");
      tolerance      = prm.get_double("Solver tolerance");
      step_tolerance = prm.get_double("Step tolerance");
      max_iterations = prm.get_integer("Maximum iterations");
      direct_size    = prm.get_integer("Direct solver size");
      warm_start     = prm.get_bool("Warm start");
      preconditioner = prm.get("Preconditioner");
      stabilization  = prm.get_double("Stabilization");
      sampling_stabilization =
        parse_sampling_stabilization(prm.get("Sampling stabilization"));
      multigrid_smoother        = prm.get("Multigrid smoother");
      multigrid_smoothing_steps = prm.get_integer("Multigrid smoothing steps");
      multigrid_coarse          = prm.get("Multigrid coarse matrix");
      prm.leave_subsection();
      AssertThrow(tolerance > 0 && tolerance < 1,
                  ExcMessage("Mass matrix/Solver tolerance = " +
                             prm_value(tolerance) + ": must lie in (0, 1)."));
      AssertThrow(step_tolerance >= 0 && step_tolerance < 1,
                  ExcMessage("Mass matrix/Step tolerance = " +
                             prm_value(step_tolerance) +
                             ": must lie in [0, 1)."));
    }

    template <int dim>
    GridSystem<dim>::GridSystem(const Parameters        &parameters,
                                const Basis::Space<dim> &space,
                                const DoFHandler<dim>   &dof_handler,
                                MPI_Comm                 comm)
      : parameters(parameters)
      , dofs_per_cell(space.dofs_per_cell())
      , n_cells(dof_handler.get_triangulation().n_active_cells())
      , mass_strategy(
          MassStrategyRegistry<dim>::instance().create(parameters.type,
                                                       "Mass matrix/Type",
                                                       parameters.threshold))
      , sampling(parameters.sampling_stabilization)
      , space(space)
      , dof_handler(dof_handler)
      , comm(comm)
      , pmg(multigrid_parameters<dim>(parameters.multigrid_coarse,
                                      parameters.multigrid_smoother,
                                      parameters.multigrid_smoothing_steps))
    {
    }

    template <int dim>
    void
    GridSystem<dim>::reinit(
      const std::array<std::set<types::boundary_id>, dim> &fixed,
      const double                                         density)
    {
      this->density = density;
      owned         = dof_handler.locally_owned_dofs();
      if (mass_strategy->needs_all_dofs())
        // Constraints may tie a vertex to one two cells away: keep every
        // DoF at hand (the mesh is replicated anyway).
        relevant = complete_index_set(dof_handler.n_dofs());
      else
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      relevant_global.resize(relevant.n_elements());
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        relevant_global[l] = relevant.nth_index_in_set(l);
      owned_to_relevant.clear();
      for (const auto i : owned)
        owned_to_relevant.push_back(relevant.index_within_set(i));
      // The same on every rank: an owner must take part in the exchange
      // whenever another rank holds its DoFs as ghosts, even if it has
      // no ghosts itself.
      owned_is_relevant =
        Utilities::MPI::min(relevant == owned ? 1U : 0U, comm) == 1;

      cells_exchange.reinit(dof_handler.get_triangulation());
      owned_cell_indices.clear();
      cell_dof_indices.assign(n_cells * dofs_per_cell, 0);
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

      for (unsigned int d = 0; d < dim; ++d)
        {
          auto &c = dirichlet[d];
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
          update_constraint_flags(d);
        }

      lumped.reinit(owned, comm);
      rhs_vector.reinit(owned, comm);
      solution_vector.reinit(owned, comm);
      writable.reinit(owned, relevant, comm, true);
      // owned_is_relevant is the same on every rank, so every rank builds
      // the pattern (which may be collective), also one without ghosts.
      if (!owned_is_relevant)
        exchange.reinit(owned, relevant, comm);
      cells.lumped.assign(n_cells * dofs_per_cell, 0.);
      cells.rhs.assign(n_cells * dofs_per_cell, Tensor<1, dim>());
      local_lumped.assign(relevant_global.size(), 0.);
      scratch.assign(relevant_global.size(), 0.);

      build_ties();
      build_vertex_tables(fixed);
      direct = uses_matrix() &&
               dof_handler.n_dofs() <= parameters.direct_size &&
               Utilities::MPI::n_mpi_processes(comm) == 1;
      if (uses_matrix())
        {
          build_sparsity();
          cells.mass.assign(n_cells * dofs_per_cell * dofs_per_cell, 0.);
          compute_full_support_diagonal(density);
          sampling.reinit(*this);
        }
      else
        cells.mass.clear();

      pmg.clear();
      if (parameters.preconditioner == "pmg")
        pmg.reinit(*this);
    }

    template <int dim>
    void
    GridSystem<dim>::build_ties()
    {
      // The space's own constraints in local relevant numbering, for the
      // lumped path, which condenses vectors without AffineConstraints.
      AffineConstraints<double> c(relevant);
      space.make_space_constraints(dof_handler, c);
      c.close();
      ties.clear();
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        if (c.is_constrained(relevant_global[l]))
          {
            Tie         tie{l, {}};
            const auto *entries = c.get_constraint_entries(relevant_global[l]);
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
    GridSystem<dim>::build_vertex_tables(
      const std::array<std::set<types::boundary_id>, dim> &fixed)
    {
      const auto &tria         = dof_handler.get_triangulation();
      vertices.dofs_per_vertex = space.dofs_per_vertex();
      vertices.dofs.assign(tria.n_vertices(), {});
      vertices.cells.assign(tria.n_vertices(), {});
      vertices.neighbors.assign(tria.n_vertices(), {});
      vertices.on_free_boundary.assign(tria.n_vertices(), false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          for (const unsigned int k : cell->vertex_indices())
            {
              const unsigned int v = cell->vertex_index(k);
              vertices.cells[v].push_back(cell->active_cell_index());
              for (const unsigned int l : cell->vertex_indices())
                if (l != k)
                  vertices.neighbors[v].push_back(cell->vertex_index(l));
              if (vertices.dofs[v].empty())
                for (unsigned int q = 0; q < vertices.dofs_per_vertex; ++q)
                  {
                    const auto g = cell->vertex_dof_index(k, q);
                    vertices.dofs[v].push_back(relevant.is_element(g) ?
                                                 relevant.index_within_set(g) :
                                                 numbers::invalid_unsigned_int);
                  }
            }
          // The outer faces of a distributed mesh's ghost layer are no
          // boundary of the mesh.
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() != Mesh::rim_boundary_id)
              {
                bool free = true;
                for (unsigned int d = 0; d < dim; ++d)
                  free =
                    free && fixed[d].count(cell->face(f)->boundary_id()) == 0;
                if (free)
                  for (const auto v : cell->face(f)->vertex_indices())
                    vertices.on_free_boundary[cell->face(f)->vertex_index(v)] =
                      true;
              }
        }
      for (auto &n : vertices.neighbors)
        {
          std::sort(n.begin(), n.end());
          n.erase(std::unique(n.begin(), n.end()), n.end());
        }
    }

    template <int dim>
    void
    GridSystem<dim>::build_sparsity()
    {
      DynamicSparsityPattern dsp(relevant);
      for (unsigned int d = 0; d < dim; ++d)
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        active_constraints[d],
                                        true);
      if (mass_strategy->needs_neighbor_couplings())
        {
          // Every DoF of the cells around a vertex with every other: the
          // couplings of patch blocks over two cells that share a vertex.
          std::vector<types::global_dof_index>              dofs(dofs_per_cell);
          std::vector<std::vector<types::global_dof_index>> cell_dofs(n_cells);
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(dofs);
              cell_dofs[cell->active_cell_index()] = dofs;
            }
          for (const auto &around : vertices.cells)
            {
              std::vector<types::global_dof_index> patch;
              for (const unsigned int c : around)
                patch.insert(patch.end(),
                             cell_dofs[c].begin(),
                             cell_dofs[c].end());
              std::sort(patch.begin(), patch.end());
              patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
              for (const auto i : patch)
                if (relevant.is_element(i))
                  dsp.add_entries(i, patch.begin(), patch.end(), true);
              // And through the constraints, as the cells' couplings: a
              // patch block over DoFs tied to others (the B-splines'
              // C^{p-1} ties) is distributed to their targets, which
              // couple across the two cells although no single cell
              // couples them; without these entries the assembly of a
              // B-spline ghost penalty adds outside the pattern. (With
              // Dirichlet constraints only, nothing new; patch blocks are
              // over relevant DoFs.)
              patch.erase(std::remove_if(patch.begin(),
                                         patch.end(),
                                         [this](const auto i) {
                                           return !relevant.is_element(i);
                                         }),
                          patch.end());
              for (unsigned int d = 0; d < dim; ++d)
                active_constraints[d].add_entries_local_to_global(patch,
                                                                  dsp,
                                                                  true);
            }
        }
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      for (unsigned int d = 0; d < dim; ++d)
        matrix[d].reinit(owned, owned, dsp, comm);
      compute_matrix_slots();
      component_cg.reinit(matrix[0].trilinos_matrix());
    }

    template <int dim>
    void
    GridSystem<dim>::update_constraint_flags(const unsigned int d)
    {
      const auto &c = active_constraints[d];
      constrained[d].assign(relevant_global.size(), 0);
      only_dirichlet[d] = true;
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        if (c.is_constrained(relevant_global[l]))
          {
            constrained[d][l]   = 1;
            const auto *entries = c.get_constraint_entries(relevant_global[l]);
            only_dirichlet[d]   = only_dirichlet[d] &&
                                (entries == nullptr || entries->empty()) &&
                                c.get_inhomogeneity(relevant_global[l]) == 0;
          }
    }

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
    GridSystem<dim>::compute_matrix_slots()
    {
      // All components share the sparsity pattern, hence (Epetra stores a
      // FillComplete'd matrix in one CRS array with sorted columns) the
      // positions of the entries.
      const Epetra_CrsMatrix &A = matrix[0].trilinos_matrix();
      int                    *offsets, *columns;
      double                 *values;
      ++generation;
      cell_slots.clear();
      if (A.ExtractCrsDataPointers(offsets, columns, values) != 0)
        return;
      for (int r = 0; r < A.NumMyRows(); ++r)
        if (!std::is_sorted(columns + offsets[r], columns + offsets[r + 1]))
          return;
      matrix_row.resize(relevant_global.size());
      matrix_column.resize(relevant_global.size());
      for (unsigned int l = 0; l < relevant_global.size(); ++l)
        {
          const auto g = relevant_global[l];
          matrix_row[l] =
            owned.is_element(g) ? A.RowMap().LID(static_cast<int>(g)) : -1;
          matrix_column[l] = A.ColMap().LID(static_cast<int>(g));
        }
      const unsigned int n = dofs_per_cell;
      cell_slots.resize(owned_cell_indices.size() * n * n);
      for (unsigned int o = 0; o < owned_cell_indices.size(); ++o)
        block_slots(offsets,
                    columns,
                    matrix_row,
                    matrix_column,
                    &cell_dof_indices[owned_cell_indices[o] * n],
                    n,
                    &cell_slots[o * n * n]);
    }

    template <int dim>
    void
    GridSystem<dim>::patch_slots(const unsigned int *dofs,
                                 const unsigned int  n,
                                 std::vector<int>   &slots) const
    {
      slots.clear();
      if (cell_slots.empty())
        return;
      const Epetra_CrsMatrix &A = matrix[0].trilinos_matrix();
      int                    *offsets, *columns;
      double                 *values;
      A.ExtractCrsDataPointers(offsets, columns, values);
      slots.resize(n * n);
      block_slots(offsets,
                  columns,
                  matrix_row,
                  matrix_column,
                  dofs,
                  n,
                  slots.data());
    }

    namespace
    {
      /// Points and weights (fractions of the cell measure) of a uniform
      /// split of the reference cell: 8 x 8 similar triangles with the
      /// two centroids of each parallelogram in 2D, 8 midpoints in 1D.
      template <int dim>
      std::vector<std::pair<Point<dim>, double>>
      uniform_cell_points(const std::vector<Point<dim>> &v);

      template <>
      std::vector<std::pair<Point<1>, double>>
      uniform_cell_points<1>(const std::vector<Point<1>> &v)
      {
        const unsigned int                       k = 8;
        std::vector<std::pair<Point<1>, double>> r;
        for (unsigned int i = 0; i < k; ++i)
          r.emplace_back(v[0] + (i + 0.5) / k * (v[1] - v[0]), 1. / k);
        return r;
      }

      template <>
      std::vector<std::pair<Point<2>, double>>
      uniform_cell_points<2>(const std::vector<Point<2>> &v)
      {
        const unsigned int                       k  = 8;
        const Tensor<1, 2>                       e1 = (v[1] - v[0]) / k;
        const Tensor<1, 2>                       e2 = (v[2] - v[0]) / k;
        std::vector<std::pair<Point<2>, double>> r;
        for (unsigned int j = 0; j < k; ++j)
          for (unsigned int i = 0; i + j < k; ++i)
            for (const double s : {1. / 3, 2. / 3})
              {
                if (s > 0.5 && i + j + 1 >= k)
                  continue;
                r.emplace_back(v[0] + (i + s) * e1 + (j + s) * e2,
                               1. / (k * k));
              }
        return r;
      }
    } // namespace

    template <int dim>
    void
    GridSystem<dim>::compute_full_support_diagonal(const double density)
    {
      // int rho phi_i^2 over the whole support by a uniform split of each
      // cell: only a scale for the relative thresholds, so a few per mille
      // are good enough.
      const unsigned int  n = dofs_per_cell;
      std::vector<double> cell_full(n_cells * n, 0.), values(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int      c = cell->active_cell_index();
            std::vector<Point<dim>> v;
            for (const unsigned int k : cell->vertex_indices())
              v.push_back(cell->vertex(k));
            const double m = density * cell->measure();
            for (const auto &[x, fraction] : uniform_cell_points<dim>(v))
              {
                space.evaluate(c, x, values.data(), nullptr);
                for (unsigned int l = 0; l < n; ++l)
                  cell_full[c * n + l] +=
                    (m * fraction) * values[l] * values[l];
              }
          }
      scatter(cell_full.data(), 1, 0, writable);
      TrilinosWrappers::MPI::Vector full(owned, comm);
      full = writable;
      to_local(full, local_full_diagonal);
    }

    template <int dim>
    void
    GridSystem<dim>::zero_cell_mass()
    {
      const unsigned int n = dofs_per_cell;
      for (const unsigned int c : owned_cell_indices)
        {
          std::fill_n(cells.lumped.begin() + c * n, n, 0.);
          if (!cells.mass.empty())
            std::fill_n(cells.mass.begin() + c * n * n, n * n, 0.);
        }
    }

    template <int dim>
    void
    GridSystem<dim>::zero_cell_rhs()
    {
      for (const unsigned int c : owned_cell_indices)
        std::fill_n(cells.rhs.begin() + c * dofs_per_cell,
                    dofs_per_cell,
                    Tensor<1, dim>());
    }

    template <int dim>
    void
    GridSystem<dim>::scatter(const double                  *cell_values,
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
    GridSystem<dim>::to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
                              std::vector<double>                 &local) const
    {
      local.resize(relevant_global.size());
      if (owned_is_relevant)
        {
          std::copy(owned_vector.begin(), owned_vector.end(), local.begin());
          return;
        }
      exchange.owned_to_relevant(owned_vector.begin(), local);
    }

    namespace
    {
      /// The owned entries of @p ghosted (owned + writable ghosts, after
      /// compress) into the owned vector @p owned: the copy that
      /// owned = ghosted makes, without the re-initialisation it does
      /// first (which cost more than a small system's whole solve).
      void
      copy_owned(const TrilinosWrappers::MPI::Vector &ghosted,
                 TrilinosWrappers::MPI::Vector       &owned)
      {
        AssertDimension(ghosted.locally_owned_size(),
                        owned.locally_owned_size());
        std::copy(ghosted.begin(), ghosted.end(), owned.begin());
      }
    } // namespace

    template <int dim>
    const std::vector<double> &
    GridSystem<dim>::particle_diagonal()
    {
      // Member scratch, no Trilinos vector constructed per step: that cost
      // more than the whole assembly of a small system. solution_vector is
      // free here (solve() overwrites it).
      const unsigned int n = dofs_per_cell;
      cell_scratch.resize(n_cells * n);
      for (const unsigned int c : owned_cell_indices)
        for (unsigned int k = 0; k < n; ++k)
          cell_scratch[c * n + k] = cells.mass[(c * n + k) * n + k];
      scatter(cell_scratch.data(), 1, 0, writable);
      copy_owned(writable, solution_vector);
      to_local(solution_vector, diagonal_scratch);
      return diagonal_scratch;
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_mass()
    {
      // Row sums of the condensed matrix C^T M C are C^T (M 1) (C 1 = 1:
      // the ties are convex combinations), the lumped mass of the space.
      scatter(cells.lumped.data(), 1, 0, writable, true);
      copy_owned(writable, lumped);
      to_local(lumped, local_lumped);

      // Statistics of the diagonal over supported DoFs.
      double       dmin = std::numeric_limits<double>::max(), dmax = 0;
      unsigned int n_empty = 0;
      for (const unsigned int l : owned_to_relevant)
        {
          const double m = local_lumped[l];
          if (m > 0)
            dmin = std::min(dmin, m), dmax = std::max(dmax, m);
          else
            {
              bool all_fixed = true;
              for (unsigned int d = 0; d < dim; ++d)
                all_fixed =
                  all_fixed && dirichlet[d].is_constrained(relevant_global[l]);
              n_empty += !all_fixed;
            }
        }
      stats.min_diagonal     = Utilities::MPI::min(dmin, comm);
      stats.max_diagonal     = Utilities::MPI::max(dmax, comm);
      stats.n_empty_dofs     = Utilities::MPI::sum(n_empty, comm);
      stats.iterations       = 0;
      stats.condition_number = 0;

      if (!uses_matrix())
        return;

      // Particle diagonal M_ii relative to the full-support one.
      const std::vector<double> &diagonal = particle_diagonal();
      double                     rmin     = std::numeric_limits<double>::max();
      for (const unsigned int l : owned_to_relevant)
        {
          if (local_full_diagonal[l] > 0 && diagonal[l] > 0)
            rmin = std::min(rmin, diagonal[l] / local_full_diagonal[l]);
        }
      stats.min_relative_diagonal = Utilities::MPI::min(rmin, comm);

      patches.clear();
      stats.n_stabilized_cells =
        sampling.acts_on(*this) ?
          Utilities::MPI::sum(sampling.weigh(*this), comm) :
          0;
      if (mass_strategy->prepare(*this, diagonal))
        build_sparsity();
      sampling.apply(*this);
      together = components_together();
      // One reduction for all components: this runs every step.
      unsigned int here[2 * dim], everywhere[2 * dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          here[d]       = only_dirichlet[d];
          here[dim + d] = 1;
          for (const unsigned int l : owned_to_relevant)
            {
              here[d]       = here[d] && constrained[d][l];
              here[dim + d] = here[dim + d] && !constrained[d][l];
            }
        }
      Utilities::MPI::min(here, comm, everywhere);
      for (unsigned int d = 0; d < dim; ++d)
        {
          fully_fixed[d]    = everywhere[d] == 1;
          free_component[d] = everywhere[dim + d] == 1;
        }
      if (together)
        assemble_shared_matrix();
      else
        for (unsigned int d = 0; d < dim; ++d)
          if (fully_fixed[d])
            factored[d] = false;
          else
            assemble_matrix(d);
    }

    template <int dim>
    double
    GridSystem<dim>::step_tolerance(const unsigned int d) const
    {
      // A free component's exact solve conserves its momentum (and, if
      // all are free, the angular momentum) to round-off; a looser one
      // would lose 1e-9 of a spinning block's angular momentum in a
      // quarter turn (doc/performance.md). Where DoFs are fixed, the
      // boundary exchanges momentum anyway and the step decides.
      return free_component[d] ? 0. : parameters.step_tolerance;
    }

    template <int dim>
    bool
    GridSystem<dim>::components_together() const
    {
      // One component has nothing to share; the direct solver, AMG and
      // p-multigrid work on the constrained matrix of a component. Decided
      // over all ranks (the solves are collective): a rank without cells
      // has no cell slots, and constraints are seen per rank.
      bool here = dim > 1 && !direct &&
                  (owned_cell_indices.empty() || !cell_slots.empty()) &&
                  (parameters.preconditioner == "jacobi" ||
                   parameters.preconditioner == "block jacobi");
      for (unsigned int d = 0; d < dim; ++d)
        here = here && only_dirichlet[d];
      return Utilities::MPI::min(static_cast<unsigned int>(here), comm) == 1;
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_shared_matrix()
    {
      // matrix[0] holds M without constraints; ComponentCG applies P_d.
      TrilinosWrappers::SparseMatrix &M = matrix[0];
      M                                 = 0;
      add_blocks(M, nullptr);
      finish_assembly(M, nullptr);
      const unsigned int block =
        vertex_blocks(parameters.preconditioner, space) ?
          space.dofs_per_vertex() :
          1;
      fixed_rows.resize(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          fixed_rows[d].clear();
          for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
            if (constrained[d][owned_to_relevant[j]])
              fixed_rows[d].push_back(j);
          block_jacobi[d].initialize(M, block, fixed_rows[d], generation);
          factored[d] = false;
        }
    }

    template <int dim>
    void
    GridSystem<dim>::set_guess(const std::vector<Tensor<1, dim>> &solution)
    {
      const Epetra_Map &map = matrix[0].trilinos_matrix().RowMap();
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
    unsigned int
    GridSystem<dim>::solve_components()
    {
      const Epetra_CrsMatrix                &M = matrix[0].trilinos_matrix();
      std::vector<const VertexBlockJacobi *> preconditioners;
      std::vector<double>                    step_tolerances;
      for (unsigned int d = 0; d < dim; ++d)
        {
          step_tolerances.push_back(step_tolerance(d));
          // Tensor<1,dim> stores its components contiguously.
          scatter(&cells.rhs[0][0], dim, d, writable);
          double *const b = (*rhs_columns)[d];
          std::copy(writable.begin(), writable.end(), b);
          for (const unsigned int j : fixed_rows[d])
            b[j] = 0;
          preconditioners.push_back(&block_jacobi[d]);
        }
      const ComponentCG::Result result =
        component_cg.solve(M,
                           preconditioners,
                           fixed_rows,
                           *solution_columns,
                           *rhs_columns,
                           parameters.tolerance,
                           step_tolerances,
                           parameters.max_iterations);
      stats.condition_number =
        std::max(stats.condition_number, result.condition_number);
      unsigned int iterations = 0;
      for (const unsigned int i : result.iterations)
        iterations += i;
      return iterations;
    }

    template <int dim>
    void
    GridSystem<dim>::add_blocks(TrilinosWrappers::SparseMatrix &target,
                                const char                     *fixed)
    {
      // Straight into the value array: the per-cell work of
      // distribute_local_to_global (sorting, map look-ups, a search per
      // entry) cost more than the particle loops on small and medium
      // systems. Same sums in the same order: bit-identical.
      const unsigned int n = dofs_per_cell;
      for (unsigned int o = 0; o < owned_cell_indices.size(); ++o)
        {
          const unsigned int c = owned_cell_indices[o];
          add_block(target,
                    fixed,
                    &cell_dof_indices[c * n],
                    n,
                    &cells.mass[c * n * n],
                    1.,
                    &cell_slots[o * n * n]);
        }
      for (const auto &patch : patches)
        add_block(target,
                  fixed,
                  patch.dofs,
                  patch.n,
                  patch.values,
                  patch.weight,
                  patch.slots);
    }

    template <int dim>
    void
    GridSystem<dim>::finish_assembly(TrilinosWrappers::SparseMatrix &target,
                                     const char                     *fixed)
    {
      target.compress(VectorOperation::add);
      // A DoF whose support holds no particle has an empty row: give it
      // a unit diagonal so that its (zero) coefficient is well defined.
      // (Rows of patch blocks, e.g. the ghost penalty, may hold a DoF
      // without particle mass: it keeps its row.)
      for (const unsigned int l : owned_to_relevant)
        if (local_lumped[l] == 0 && (fixed == nullptr || !fixed[l]) &&
            target.diag_element(relevant_global[l]) == 0)
          target.set(relevant_global[l], relevant_global[l], 1.0);
      target.compress(VectorOperation::insert);
    }

    template <int dim>
    void
    GridSystem<dim>::add_block(TrilinosWrappers::SparseMatrix &target,
                               const char                     *fixed,
                               const unsigned int             *dofs,
                               const unsigned int              n,
                               const double                   *values,
                               const double                    weight,
                               const int                      *slots)
    {
      Epetra_CrsMatrix &A =
        const_cast<Epetra_CrsMatrix &>(target.trilinos_matrix());
      int    *offsets, *columns;
      double *entries;
      A.ExtractCrsDataPointers(offsets, columns, entries);
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
                target.add(relevant_global[row], relevant_global[dofs[l]], v);
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
              target.add(relevant_global[dofs[k]], relevant_global[dofs[k]], v);
          }
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_matrix_with_constraints(const unsigned int d)
    {
      const unsigned int                   n = dofs_per_cell;
      FullMatrix<double>                   local(n, n);
      std::vector<types::global_dof_index> dofs(n);
      for (const unsigned int c : owned_cell_indices)
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              dofs[k] = relevant_global[cell_dof_indices[c * n + k]];
              for (unsigned int l = 0; l < n; ++l)
                local(k, l) = cells.mass[(c * n + k) * n + l];
            }
          active_constraints[d].distribute_local_to_global(local,
                                                           dofs,
                                                           matrix[d]);
        }
      for (const auto &patch : patches)
        {
          std::vector<types::global_dof_index> patch_dofs(patch.n);
          FullMatrix<double>                   block(patch.n, patch.n);
          for (unsigned int k = 0; k < patch.n; ++k)
            {
              patch_dofs[k] = relevant_global[patch.dofs[k]];
              for (unsigned int l = 0; l < patch.n; ++l)
                block(k, l) = patch.weight * patch.values[k * patch.n + l];
            }
          active_constraints[d].distribute_local_to_global(block,
                                                           patch_dofs,
                                                           matrix[d]);
        }
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_matrix(const unsigned int d)
    {
      matrix[d] = 0;
      if (only_dirichlet[d] && !cell_slots.empty())
        add_blocks(matrix[d], constrained[d].data());
      else
        assemble_matrix_with_constraints(d);
      finish_assembly(matrix[d], constrained[d].data());
      factored[d] = direct && dense[d].factorize(matrix[d]);
      if (!factored[d])
        {
          if (parameters.preconditioner == "amg")
            amg[d].initialize(matrix[d]);
          else if (parameters.preconditioner == "pmg")
            pmg.assemble(*this, d, constrained[d]);
          else if (vertex_blocks(parameters.preconditioner, space))
            block_jacobi[d].initialize(matrix[d],
                                       space.dofs_per_vertex(),
                                       {},
                                       generation);
          else
            jacobi[d].initialize(matrix[d]);
        }
    }

    template <int dim>
    unsigned int
    GridSystem<dim>::solve_consistent(const unsigned int             d,
                                      TrilinosWrappers::MPI::Vector &x)
    {
      // Kept between calls: constructing a Trilinos vector costs more than
      // the whole solve of a small system.
      TrilinosWrappers::MPI::Vector &rhs = rhs_vector;
      if (only_dirichlet[d])
        {
          // Tensor<1,dim> stores its components contiguously.
          scatter(&cells.rhs[0][0], dim, d, writable);
          copy_owned(writable, rhs);
          double *const values = rhs.begin();
          for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
            if (constrained[d][owned_to_relevant[j]])
              values[j] = 0;
        }
      else
        {
          const unsigned int n = dofs_per_cell;
          writable             = 0;
          Vector<double>                       local_rhs(n);
          std::vector<types::global_dof_index> dofs(n);
          for (const unsigned int c : owned_cell_indices)
            {
              for (unsigned int k = 0; k < n; ++k)
                {
                  dofs[k]      = relevant_global[cell_dof_indices[c * n + k]];
                  local_rhs[k] = cells.rhs[c * n + k][d];
                }
              active_constraints[d].distribute_local_to_global(local_rhs,
                                                               dofs,
                                                               writable);
            }
          writable.compress(VectorOperation::add);
          copy_owned(writable, rhs);
        }
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
      ReductionControl control(parameters.max_iterations,
                               parameters.tolerance * norm,
                               warm ? step_tolerance(d) : 0.,
                               false,
                               false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.connect_condition_number_slot([this](const double c) {
        stats.condition_number = std::max(stats.condition_number, c);
      });
      if (parameters.preconditioner == "amg")
        cg.solve(matrix[d], x, rhs, amg[d]);
      else if (parameters.preconditioner == "pmg")
        pmg.solve(d, control, rhs, x, stats.condition_number);
      else if (vertex_blocks(parameters.preconditioner, space))
        cg.solve(matrix[d], x, rhs, block_jacobi[d]);
      else
        cg.solve(matrix[d], x, rhs, jacobi[d]);
      return control.last_step();
    }

    template <int dim>
    void
    GridSystem<dim>::solve(std::vector<Tensor<1, dim>> &solution,
                           const bool                   lumped_only)
    {
      const bool warm =
        parameters.warm_start && solution.size() == relevant_global.size();
      if (!warm)
        solution.assign(relevant_global.size(), Tensor<1, dim>());
      TrilinosWrappers::MPI::Vector &x     = solution_vector;
      std::vector<double>           &local = local_solution;
      if (uses_matrix() && !lumped_only && together)
        {
          set_guess(solution);
          stats.iterations += solve_components();
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (uses_matrix() && !lumped_only && together)
            {
              const double *const column = (*solution_columns)[d];
              std::copy(column, column + owned_to_relevant.size(), x.begin());
            }
          else if (uses_matrix() && !lumped_only && fully_fixed[d])
            x = 0;
          else if (uses_matrix() && !lumped_only)
            {
              double *const v = x.begin();
              for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
                {
                  const unsigned int l = owned_to_relevant[j];
                  v[j] = constrained[d][l] ? 0. : solution[l][d];
                }
              stats.iterations += solve_consistent(d, x);
            }
          else
            {
              // Tensor<1,dim> stores its components contiguously.
              // The owned entries of all three vectors, in owned order.
              scatter(&cells.rhs[0][0], dim, d, writable, true);
              const double *const b = writable.begin();
              const double *const m = lumped.begin();
              double *const       v = x.begin();
              for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
                v[j] = m[j] > 0 ? b[j] / m[j] : 0.;
            }
          if (only_dirichlet[d])
            {
              // Homogeneous Dirichlet rows only: what distribute() does,
              // without the ghosted copy of x it builds for a parallel
              // vector (on small systems that copy cost more than the
              // solve).
              double *const v = x.begin();
              for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
                if (constrained[d][owned_to_relevant[j]])
                  v[j] = 0;
            }
          else
            active_constraints[d].distribute(x);
          to_local(x, local);
          for (unsigned int l = 0; l < local.size(); ++l)
            solution[l][d] = local[l];
        }
    }

    template class GridSystem<1>;
    template class GridSystem<2>;
  } // namespace Solver
} // namespace psmpm
