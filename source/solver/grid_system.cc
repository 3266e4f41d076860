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

      /// Mass matrix/Type.
      template <int dim>
      void
      declare_type(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Type",
          "automatic",
          Patterns::Selection(
            "automatic|" + MassStrategyRegistry<dim>::instance().selection()),
          "automatic: the basis' measured default (lumped for powell-sabin, "
          "consistent for bspline (doc/chapter.md), "
          "ghost penalty for linear, partially lumped for linear with a "
          "moving grid (otm); doc/transfers.md); " +
            MassStrategyRegistry<dim>::instance().documentation());
      }

      /// The CG's stopping tests.
      void
      declare_cg_entries(ParameterHandler &prm)
      {
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
          "Solver tolerance alone. Components without any fixed DoF (free "
          "bodies) use Free body step tolerance instead when solved "
          "together, and Solver tolerance alone when solved one by one. 0: "
          "Solver tolerance alone (doc/performance.md, \"What the time step "
          "needs of the mass solves\").");
        prm.declare_entry(
          "Free body step tolerance",
          "1e-8",
          Patterns::Double(0),
          "Step tolerance for the components that no DoF constrains on any "
          "rank (free bodies), when the components are solved together "
          "(block jacobi or jacobi, Dirichlet conditions only). After the "
          "CG a Galerkin correction on the rigid modes (a uniform velocity "
          "per free component, and the rotation when every component is "
          "free) makes the residual orthogonal to them, so that momentum "
          "stays conserved to round-off at any value; the angular momentum "
          "keeps the part of the residual that MUSL's position update "
          "carries (doc/performance.md, \"What the time step needs of the "
          "mass solves\"). 0: Solver tolerance alone.");
        prm.declare_entry("Maximum iterations",
                          "1000",
                          Patterns::Integer(1),
                          "CG iteration limit; reaching it stops the run as "
                          "unstable.");
      }

      /// Preconditioner and the p-multigrid's entries.
      void
      declare_preconditioner_entries(ParameterHandler &prm)
      {
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
      }

      /// Where a solve starts, and when it is direct.
      void
      declare_start_entries(ParameterHandler &prm)
      {
        prm.declare_entry("Warm start",
                          "true",
                          Patterns::Bool(),
                          "CG starts from the last step's solution of the same "
                          "system (the grid velocity or acceleration, kept in "
                          "checkpoints) instead of zero; the stopping test is "
                          "relative to the right-hand side either way "
                          "(doc/performance.md: 24 % fewer iterations on the "
                          "closed Powell-Sabin throughput bar).");
        prm.declare_entry(
          "Direct solver size",
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
      }

      /// The strategies' and the sampling stabilisation's entries.
      void
      declare_strategy_entries(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Threshold",
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
      }
    } // namespace

    template <int dim>
    void
    GridSystem<dim>::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      declare_type<dim>(prm);
      declare_cg_entries(prm);
      declare_preconditioner_entries(prm);
      declare_start_entries(prm);
      declare_strategy_entries(prm);
      MassStrategyRegistry<dim>::instance().declare_parameters(prm);
      prm.leave_subsection();
    }

    template <int dim>
    void
    GridSystem<dim>::Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix");
      type                = prm.get("Type");
      threshold           = prm.get_double("Threshold");
      tolerance           = prm.get_double("Solver tolerance");
      step_tolerance      = prm.get_double("Step tolerance");
      free_step_tolerance = prm.get_double("Free body step tolerance");
      max_iterations      = prm.get_integer("Maximum iterations");
      direct_size         = prm.get_integer("Direct solver size");
      warm_start          = prm.get_bool("Warm start");
      preconditioner      = prm.get("Preconditioner");
      stabilization       = prm.get_double("Stabilization");
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
      AssertThrow(free_step_tolerance >= 0 && free_step_tolerance < 1,
                  ExcMessage("Mass matrix/Free body step tolerance = " +
                             prm_value(free_step_tolerance) +
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
      , mass_solver(typename MassSolver<dim>::Settings{
          parameters.tolerance,
          parameters.step_tolerance,
          parameters.free_step_tolerance,
          parameters.max_iterations,
          parameters.preconditioner,
          space.dofs_per_vertex(),
          multigrid_parameters<dim>(parameters.multigrid_coarse,
                                    parameters.multigrid_smoother,
                                    parameters.multigrid_smoothing_steps)})
    {
    }

    template <int dim>
    void
    GridSystem<dim>::reinit(
      const std::array<std::set<types::boundary_id>, dim> &fixed,
      const double                                         density)
    {
      this->density = density;
      layout.reinit(dof_handler, space, mass_strategy->needs_all_dofs(), comm);
      cells_exchange.reinit(dof_handler.get_triangulation());
      component_constraints.reinit(space,
                                   dof_handler,
                                   fixed,
                                   layout.relevant_dofs(),
                                   layout.relevant_global());
      reinit_vectors();
      build_vertex_tables(fixed);
      const bool direct = uses_matrix() &&
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
      mass_solver.reinit(*this, direct);
    }

    template <int dim>
    void
    GridSystem<dim>::reinit_vectors()
    {
      const IndexSet &owned = layout.owned_dofs();
      lumped.reinit(owned, comm);
      rhs_vector.reinit(owned, comm);
      solution_vector.reinit(owned, comm);
      writable.reinit(owned, layout.relevant_dofs(), comm, true);
      cells.lumped.assign(n_cells * dofs_per_cell, 0.);
      cells.rhs.assign(n_cells * dofs_per_cell, Tensor<1, dim>());
      local_lumped.assign(layout.n_relevant(), 0.);
    }

    template <int dim>
    void
    GridSystem<dim>::build_vertex_tables(
      const std::array<std::set<types::boundary_id>, dim> &fixed)
    {
      const IndexSet &relevant = layout.relevant_dofs();
      const auto     &tria     = dof_handler.get_triangulation();
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
      DynamicSparsityPattern dsp(layout.relevant_dofs());
      for (unsigned int d = 0; d < dim; ++d)
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        component_constraints.active(d),
                                        true);
      if (mass_strategy->needs_neighbor_couplings())
        add_neighbor_couplings(dsp);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 layout.owned_dofs(),
                                                 comm,
                                                 layout.relevant_dofs());
      matrices.reinit(dsp, layout, comm);
      mass_solver.set_sparsity(matrices.matrix(0));
    }

    template <int dim>
    void
    GridSystem<dim>::add_neighbor_couplings(DynamicSparsityPattern &dsp) const
    {
      const IndexSet                      &relevant = layout.relevant_dofs();
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
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
            patch.insert(patch.end(), cell_dofs[c].begin(), cell_dofs[c].end());
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
                                     [&relevant](const auto i) {
                                       return !relevant.is_element(i);
                                     }),
                      patch.end());
          for (unsigned int d = 0; d < dim; ++d)
            component_constraints.active(d).add_entries_local_to_global(patch,
                                                                        dsp,
                                                                        true);
        }
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
      layout.scatter(cell_full.data(), 1, 0, writable);
      TrilinosWrappers::MPI::Vector full(layout.owned_dofs(), comm);
      full = writable;
      layout.to_local(full, local_full_diagonal);
    }

    template <int dim>
    void
    GridSystem<dim>::zero_cell_mass()
    {
      const unsigned int n = dofs_per_cell;
      for (const unsigned int c : layout.owned_cells())
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
      for (const unsigned int c : layout.owned_cells())
        std::fill_n(cells.rhs.begin() + c * dofs_per_cell,
                    dofs_per_cell,
                    Tensor<1, dim>());
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
      for (const unsigned int c : layout.owned_cells())
        for (unsigned int k = 0; k < n; ++k)
          cell_scratch[c * n + k] = cells.mass[(c * n + k) * n + k];
      layout.scatter(cell_scratch.data(), 1, 0, writable);
      copy_owned(writable, solution_vector);
      layout.to_local(solution_vector, diagonal_scratch);
      return diagonal_scratch;
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_mass()
    {
      assemble_lumped_mass();
      stats.iterations       = 0;
      stats.condition_number = 0;
      if (uses_matrix())
        assemble_matrices();
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_lumped_mass()
    {
      // Row sums of the condensed matrix C^T M C are C^T (M 1) (C 1 = 1:
      // the ties are convex combinations), the lumped mass of the space.
      layout.scatter(cells.lumped.data(), 1, 0, writable, true);
      copy_owned(writable, lumped);
      layout.to_local(lumped, local_lumped);

      // Statistics of the diagonal over supported DoFs.
      const auto  &global = layout.relevant_global();
      double       dmin = std::numeric_limits<double>::max(), dmax = 0;
      unsigned int n_empty = 0;
      for (const unsigned int l : layout.owned_to_relevant())
        {
          const double m = local_lumped[l];
          if (m > 0)
            dmin = std::min(dmin, m), dmax = std::max(dmax, m);
          else
            {
              bool all_fixed = true;
              for (unsigned int d = 0; d < dim; ++d)
                all_fixed =
                  all_fixed &&
                  component_constraints.dirichlet(d).is_constrained(global[l]);
              n_empty += !all_fixed;
            }
        }
      stats.min_diagonal = Utilities::MPI::min(dmin, comm);
      stats.max_diagonal = Utilities::MPI::max(dmax, comm);
      stats.n_empty_dofs = Utilities::MPI::sum(n_empty, comm);
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_matrices()
    {
      // Particle diagonal M_ii relative to the full-support one.
      const std::vector<double> &diagonal = particle_diagonal();
      double                     rmin     = std::numeric_limits<double>::max();
      for (const unsigned int l : layout.owned_to_relevant())
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
      mass_solver.classify(component_constraints,
                           layout,
                           matrices.direct_assembly(),
                           comm);
      if (mass_solver.together())
        {
          matrices.assemble_unconstrained(layout,
                                          cells.mass,
                                          patches,
                                          local_lumped);
          mass_solver.prepare_shared(matrices.matrix(0),
                                     component_constraints,
                                     layout,
                                     matrices.generation());
        }
      else
        for (unsigned int d = 0; d < dim; ++d)
          if (mass_solver.fully_fixed(d))
            mass_solver.skip(d);
          else
            {
              matrices.assemble(d,
                                component_constraints,
                                layout,
                                cells.mass,
                                patches,
                                local_lumped);
              mass_solver.prepare(d,
                                  *this,
                                  matrices.matrix(d),
                                  component_constraints.constrained(d),
                                  matrices.generation());
            }
    }

    template <int dim>
    void
    GridSystem<dim>::assemble_rhs(const unsigned int d)
    {
      TrilinosWrappers::MPI::Vector &rhs = rhs_vector;
      if (component_constraints.only_dirichlet(d))
        {
          // Tensor<1,dim> stores its components contiguously.
          layout.scatter(&cells.rhs[0][0], dim, d, writable);
          copy_owned(writable, rhs);
          const std::vector<char> &constrained =
            component_constraints.constrained(d);
          const auto   &owned_to_relevant = layout.owned_to_relevant();
          double *const values            = rhs.begin();
          for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
            if (constrained[owned_to_relevant[j]])
              values[j] = 0;
          return;
        }
      const unsigned int n      = dofs_per_cell;
      const auto        &global = layout.relevant_global();
      writable                  = 0;
      Vector<double>                       local_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const unsigned int c : layout.owned_cells())
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              dofs[k]      = global[layout.cell_dofs()[c * n + k]];
              local_rhs[k] = cells.rhs[c * n + k][d];
            }
          component_constraints.active(d).distribute_local_to_global(local_rhs,
                                                                     dofs,
                                                                     writable);
        }
      writable.compress(VectorOperation::add);
      copy_owned(writable, rhs);
    }

    template <int dim>
    void
    GridSystem<dim>::solve_together(const std::vector<Tensor<1, dim>> &solution)
    {
      const TrilinosWrappers::SparseMatrix &M = matrices.matrix(0);
      mass_solver.set_guess(solution,
                            M.trilinos_matrix().RowMap(),
                            layout.owned_to_relevant());
      for (unsigned int d = 0; d < dim; ++d)
        {
          // Tensor<1,dim> stores its components contiguously.
          layout.scatter(&cells.rhs[0][0], dim, d, writable);
          std::copy(writable.begin(),
                    writable.end(),
                    mass_solver.rhs_column(d));
        }
      stats.iterations +=
        mass_solver.solve_components(M, stats.condition_number);
    }

    template <int dim>
    void
    GridSystem<dim>::solve_component(
      const unsigned int                 d,
      const std::vector<Tensor<1, dim>> &solution,
      TrilinosWrappers::MPI::Vector     &x)
    {
      const std::vector<char> &constrained =
        component_constraints.constrained(d);
      const auto   &owned_to_relevant = layout.owned_to_relevant();
      double *const v                 = x.begin();
      for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
        {
          const unsigned int l = owned_to_relevant[j];
          v[j]                 = constrained[l] ? 0. : solution[l][d];
        }
      assemble_rhs(d);
      stats.iterations += mass_solver.solve(d,
                                            matrices.matrix(d),
                                            rhs_vector,
                                            x,
                                            stats.condition_number);
    }

    template <int dim>
    void
    GridSystem<dim>::solve_lumped(const unsigned int             d,
                                  TrilinosWrappers::MPI::Vector &x)
    {
      // Tensor<1,dim> stores its components contiguously.
      // The owned entries of all three vectors, in owned order.
      layout.scatter(&cells.rhs[0][0], dim, d, writable, true);
      const double *const b = writable.begin();
      const double *const m = lumped.begin();
      double *const       v = x.begin();
      for (unsigned int j = 0; j < layout.owned_to_relevant().size(); ++j)
        v[j] = m[j] > 0 ? b[j] / m[j] : 0.;
    }

    template <int dim>
    void
    GridSystem<dim>::distribute_constraints(
      const unsigned int             d,
      TrilinosWrappers::MPI::Vector &x) const
    {
      if (!component_constraints.only_dirichlet(d))
        {
          component_constraints.active(d).distribute(x);
          return;
        }
      // Homogeneous Dirichlet rows only: what distribute() does, without
      // the ghosted copy of x it builds for a parallel vector (on small
      // systems that copy cost more than the solve).
      const std::vector<char> &constrained =
        component_constraints.constrained(d);
      const auto   &owned_to_relevant = layout.owned_to_relevant();
      double *const v                 = x.begin();
      for (unsigned int j = 0; j < owned_to_relevant.size(); ++j)
        if (constrained[owned_to_relevant[j]])
          v[j] = 0;
    }

    template <int dim>
    void
    GridSystem<dim>::solve(std::vector<Tensor<1, dim>> &solution,
                           const bool                   lumped_only)
    {
      const unsigned int n_relevant = layout.n_relevant();
      const bool warm = parameters.warm_start && solution.size() == n_relevant;
      if (!warm)
        solution.assign(n_relevant, Tensor<1, dim>());
      const bool                     consistent = uses_matrix() && !lumped_only;
      TrilinosWrappers::MPI::Vector &x          = solution_vector;
      std::vector<double>           &local      = local_solution;
      if (consistent && mass_solver.together())
        solve_together(solution);
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (consistent && mass_solver.together())
            {
              const double *const column = mass_solver.solution_column(d);
              std::copy(column,
                        column + layout.owned_to_relevant().size(),
                        x.begin());
            }
          else if (consistent && mass_solver.fully_fixed(d))
            x = 0;
          else if (consistent)
            solve_component(d, solution, x);
          else
            solve_lumped(d, x);
          distribute_constraints(d, x);
          layout.to_local(x, local);
          for (unsigned int l = 0; l < local.size(); ++l)
            solution[l][d] = local[l];
        }
    }

    template class GridSystem<1>;
    template class GridSystem<2>;
  } // namespace Solver
} // namespace psmpm
