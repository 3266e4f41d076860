// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_grid_system_h
#define psmpm_solver_grid_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/basis/space.h>
#include <psmpm/solver/cell_exchange.h>
#include <psmpm/solver/component_constraints.h>
#include <psmpm/solver/ghost_exchange.h>
#include <psmpm/solver/grid_dof_layout.h>
#include <psmpm/solver/grid_matrices.h>
#include <psmpm/solver/mass_solver.h>
#include <psmpm/solver/mass_strategy.h>
#include <psmpm/solver/p_multigrid_hierarchy.h>
#include <psmpm/solver/patch_block.h>
#include <psmpm/solver/sampling_stabilization.h>

#include <array>
#include <memory>
#include <set>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The grid side of MPM: the mass matrix and the solution of M x = b for
     * the dim velocity components with their own Dirichlet constraints.
     * Particle loops accumulate into plain per-cell arrays (CellArrays: no
     * searching, no Trilinos calls per particle); this class turns those
     * into distributed systems and returns the solution in a local array
     * over the locally relevant DoFs (index l of relevant_dofs()). How the
     * mass matrix is formed is the MassStrategy's business.
     *
     * Its parts: GridDofLayout (index sets, the local relevant numbering,
     * cell DoFs, the sums and ghost values between ranks),
     * ComponentConstraints (Dirichlet and active constraints per
     * component), GridMatrices (the matrices, their sparsity and the
     * assembly of cell and patch blocks) and MassSolver (shared or
     * per-component CG, direct solves, preconditioners with the
     * p-multigrid). GridSystem holds the per-cell arrays and the step's
     * order: reinit(), assemble_mass(), solve().
     */
    template <int dim>
    class GridSystem
    {
    public:
      /// Subsection "Mass matrix": Type (from MassStrategyRegistry), the
      /// solver's entries and the strategies' (MassStrategyParameters).
      struct Parameters : MassStrategyParameters
      {
        /// All entries of subsection "Mass matrix", the strategies' too.
        static void
        declare_parameters(ParameterHandler &prm);
        void
        parse_parameters(ParameterHandler &prm);

        std::string type      = "partially lumped";
        double      tolerance = 1e-12;
        /// Mass matrix/Step tolerance: a solve warm-started from the
        /// last step's field also ends once its residual has dropped by
        /// this factor from the guess' (0: off), for components with
        /// constrained DoFs.
        double step_tolerance = 1e-6;
        /// Mass matrix/Free body step tolerance: the same for components
        /// that no DoF constrains, solved together (their momentum kept
        /// by RigidModeCorrection).
        double       free_step_tolerance = 1e-8;
        unsigned int max_iterations      = 1000;
        std::string  preconditioner      = "block jacobi";
        /// Serial systems with at most this many DoFs are solved by a
        /// dense Cholesky factorization instead of CG (0: never).
        unsigned int direct_size = 600;
        /// Mass matrix/Warm start: CG starts from the caller's field.
        bool warm_start = true;
        /// Preconditioner = pmg: smoother of the Powell-Sabin level
        /// ("gauss-seidel": forward sweeps before, backward after the
        /// coarse correction; "jacobi": damped Jacobi) and its sweeps
        /// before and after (Mass matrix/Multigrid smoother, .../Multigrid
        /// smoothing steps).
        std::string  multigrid_smoother        = "gauss-seidel";
        unsigned int multigrid_smoothing_steps = 1;
        /// Preconditioner = pmg: "galerkin" (P_d^T M_d P_d of the
        /// assembled matrix) or "particles" (the P1 particle mass
        /// matrix, cell by cell from the same cell blocks; Mass
        /// matrix/Multigrid coarse matrix).
        std::string multigrid_coarse = "galerkin";
      };

      struct SolveStatistics
      {
        unsigned int iterations   = 0;
        double       min_diagonal = 0; ///< of the lumped mass, active DoFs
        double       max_diagonal = 0;
        double       min_relative_diagonal = 0; ///< min M_ii / full M_ii
        double       condition_number = 0; ///< CG estimate, largest of the step
        unsigned int n_empty_dofs     = 0; ///< DoFs with no particle support
        unsigned int n_treated_dofs =
          0; ///< lumped, deactivated or extrapolated
        /// cells given the sampling stabilisation (SamplingStabilization)
        unsigned int n_stabilized_cells = 0;
      };

      /// Per owned cell: consistent mass dofs_per_cell^2 (row-major; only
      /// if the strategy uses a matrix), lumped row sums, right-hand sides
      /// (index c * dofs_per_cell + k). The transfer scheme fills them.
      struct CellArrays
      {
        std::vector<double>         mass;
        std::vector<double>         lumped;
        std::vector<Tensor<1, dim>> rhs;
      };

      /// A dense block a strategy adds to the matrix of every component.
      using PatchBlock = Solver::PatchBlock;

      /// The vertex view of the DoFs, for vertex-wise strategies.
      struct VertexTables
      {
        unsigned int                           dofs_per_vertex = 1;
        std::vector<std::vector<unsigned int>> dofs;  ///< local relevant
        std::vector<std::vector<unsigned int>> cells; ///< active indices
        std::vector<std::vector<unsigned int>> neighbors;
        std::vector<bool>                      on_free_boundary;
      };

      GridSystem(const Parameters        &parameters,
                 const Basis::Space<dim> &space,
                 const DoFHandler<dim>   &dof_handler,
                 MPI_Comm                 comm);

      /**
       * Index sets, constraints (component d fixed on fixed[d]) and, for
       * matrix strategies, sparsity and matrices. @p density is the
       * material density for the full-support diagonal of the relative
       * thresholds; boundaries not in @p fixed are free surfaces.
       */
      void
      reinit(const std::array<std::set<types::boundary_id>, dim> &fixed,
             const double                                         density);

      /// Zero the per-cell accumulators of the owned cells.
      void
      zero_cell_mass();
      void
      zero_cell_rhs();

      /// Build the mass matrix (or lumped diagonal) from the per-cell data.
      void
      assemble_mass();

      /// Solve M x_d = b_d for every component d with b from the cell
      /// right-hand sides; result in @p solution (local relevant numbering).
      /// With Warm start, CG starts from @p solution if it has the
      /// relevant size (the last step's field of the same solve; entries
      /// of constrained DoFs are taken as zero), otherwise from zero; the
      /// stopping test is relative to |b| either way.
      /// With @p lumped, M is the lumped mass (the row sums of the cell
      /// arrays) whatever the strategy: Taylor least squares' acceleration
      /// of the chapter (Wobbes et al. 2019, eq. 4.8 with the lumped mass
      /// of eq. 4.5) beside a consistent velocity mapping.
      void
      solve(std::vector<Tensor<1, dim>> &solution, const bool lumped = false);

      const MassStrategy<dim> &
      strategy() const
      {
        return *mass_strategy;
      }
      /// For checkpoints (MassStrategy::restore_history()).
      MassStrategy<dim> &
      strategy()
      {
        return *mass_strategy;
      }
      bool
      uses_matrix() const
      {
        return mass_strategy->uses_matrix();
      }
      /// The entries of Mass matrix that strategies read.
      const MassStrategyParameters &
      strategy_parameters() const
      {
        return parameters;
      }

      CellArrays &
      cell_arrays()
      {
        return cells;
      }
      const CellArrays &
      cell_arrays() const
      {
        return cells;
      }
      /// Local relevant index of DoF k of cell c at [c * dofs_per_cell + k]
      /// (owned cells only).
      const std::vector<unsigned int> &
      cell_dofs() const
      {
        return layout.cell_dofs();
      }
      /// Patch blocks of the step: cleared before MassStrategy::prepare(),
      /// assembled after the cell blocks.
      std::vector<PatchBlock> &
      patch_blocks()
      {
        return patches;
      }
      /// Changes with every change of the sparsity pattern: positions from
      /// patch_slots() stay valid while it does not.
      unsigned int
      sparsity_generation() const
      {
        return matrices.generation();
      }
      /// Value-array positions of the entries (k, l) of a dense block over
      /// the local relevant DoFs @p dofs (-1 where the row is another
      /// rank's), for PatchBlock::slots, into @p slots (n x n); false if
      /// the matrices are not assembled directly.
      bool
      patch_slots(const unsigned int *dofs,
                  const unsigned int  n,
                  int                *slots) const
      {
        return matrices.patch_slots(dofs, n, slots);
      }
      const std::vector<unsigned int> &
      owned_cells() const
      {
        return layout.owned_cells();
      }
      const VertexTables &
      vertex_tables() const
      {
        return vertices;
      }
      /// Whether the mass strategy needs every rank to hold the whole
      /// mesh (MassStrategy::needs_replicated_mesh()).
      bool
      needs_replicated_mesh() const
      {
        return mass_strategy->needs_replicated_mesh();
      }
      /// Owners' per-cell values to the cells sharing a vertex with an
      /// owned cell.
      const CellExchange &
      cell_exchange() const
      {
        return cells_exchange;
      }
      /// The halo exchanges of arrays in local relevant numbering.
      const GhostExchange &
      ghost_exchange() const
      {
        return layout.ghost_exchange();
      }

      const SolveStatistics &
      statistics() const
      {
        return stats;
      }
      void
      set_n_treated_dofs(const unsigned int n)
      {
        stats.n_treated_dofs = n;
      }

      const IndexSet &
      locally_owned_dofs() const
      {
        return layout.owned_dofs();
      }
      const IndexSet &
      relevant_dofs() const
      {
        return layout.relevant_dofs();
      }
      /// Global index of local relevant index l.
      const std::vector<types::global_dof_index> &
      relevant_global_indices() const
      {
        return layout.relevant_global();
      }
      const AffineConstraints<double> &
      dirichlet_constraints(const unsigned int d) const
      {
        return component_constraints.dirichlet(d);
      }
      const AffineConstraints<double> &
      constraints(const unsigned int d) const
      {
        return component_constraints.active(d);
      }
      /// Replace the step's constraints of component d (closed, already
      /// merged with the Dirichlet ones).
      void
      set_constraints(const unsigned int d, AffineConstraints<double> &c)
      {
        component_constraints.set(d, c, layout.relevant_global());
      }
      /// The assembled mass matrix of component d (matrix strategies,
      /// after assemble_mass; rows of DoFs without particle mass carry a
      /// unit diagonal). When the components are solved together (more
      /// than one component, Dirichlet constraints only, (block) Jacobi
      /// CG), matrix 0 is the matrix without constraints that they share
      /// and the others are not assembled; nor is the matrix of a
      /// component that Dirichlet conditions fix everywhere.
      const TrilinosWrappers::SparseMatrix &
      mass_matrix(const unsigned int d) const
      {
        return matrices.matrix(d);
      }
      /// Preconditioner = pmg (one process, Powell-Sabin): the levels of
      /// the p-multigrid, assembled with the matrices.
      const PMultigridHierarchy<dim> &
      multigrid() const
      {
        return mass_solver.multigrid();
      }
      /// Lumped mass in local relevant numbering (after assemble_mass).
      const std::vector<double> &
      lumped_mass() const
      {
        return local_lumped;
      }
      /// Per local relevant DoF: 1 where component @p d is constrained
      /// (Dirichlet or tied).
      const std::vector<char> &
      constrained_dofs(const unsigned int d) const
      {
        return component_constraints.constrained(d);
      }
      /// Full-support diagonal in local relevant numbering.
      const std::vector<double> &
      full_support_diagonal() const
      {
        return local_full_diagonal;
      }
      /// The material density given to reinit() (rho of the fictitious
      /// mass and of the full-support diagonal).
      double
      reference_density() const
      {
        return density;
      }
      const Basis::Space<dim> &
      get_space() const
      {
        return space;
      }

      /// The sampling target where it acts on this space and strategy (the
      /// sampling stabilisation; the ghost penalty's sampled fill on P1),
      /// else 0 (summary.json).
      double
      sampling_target() const
      {
        const bool p1_ghost_penalty =
          parameters.type == "ghost penalty" && dofs_per_cell == dim + 1;
        return sampling.acts_on(*this) || p1_ghost_penalty ?
                 parameters.sampling_stabilization :
                 0.;
      }
      const DoFHandler<dim> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      MPI_Comm
      get_communicator() const
      {
        return comm;
      }

      const Parameters   parameters;
      const unsigned int dofs_per_cell;
      const unsigned int n_cells;

    private:
      /// Index sets and cell DoFs, constraints, the per-cell and owned
      /// vectors of reinit().
      void
      reinit_vectors();
      /// int rho phi_i^2 over each DoF's whole support.
      void
      compute_full_support_diagonal(const double density);
      void
      build_vertex_tables(
        const std::array<std::set<types::boundary_id>, dim> &fixed);
      /// The matrices' sparsity from the cells' couplings under the
      /// active constraints (and the strategy's neighbour couplings).
      void
      build_sparsity();
      /// Every DoF of the cells around a vertex with every other: the
      /// couplings of patch blocks over two cells that share a vertex.
      void
      add_neighbor_couplings(DynamicSparsityPattern &dsp) const;
      /// The particle mass matrix' diagonal in local relevant numbering
      /// (a member's reference, valid until the next call).
      const std::vector<double> &
      particle_diagonal();
      /// The lumped mass from the cell arrays and the statistics of its
      /// diagonal.
      void
      assemble_lumped_mass();
      /// The statistics of the particle diagonal, the strategy's and the
      /// sampling stabilisation's share, then the matrices.
      void
      assemble_matrices();
      /// rhs_vector = b of component @p d under its active constraints.
      void
      assemble_rhs(const unsigned int d);
      /// All components through the shared matrix, from @p solution's
      /// guess (owned entries; MassSolver::set_guess()).
      void
      solve_together(const std::vector<Tensor<1, dim>> &solution);
      /// x of component @p d from its own matrix, from @p solution's guess.
      void
      solve_component(const unsigned int                 d,
                      const std::vector<Tensor<1, dim>> &solution,
                      TrilinosWrappers::MPI::Vector     &x);
      /// x = b / m of component @p d with the lumped mass m.
      void
      solve_lumped(const unsigned int d, TrilinosWrappers::MPI::Vector &x);
      /// The active constraints of component @p d on @p x.
      void
      distribute_constraints(const unsigned int             d,
                             TrilinosWrappers::MPI::Vector &x) const;

      std::unique_ptr<MassStrategy<dim>> mass_strategy;
      SamplingStabilization<dim>         sampling;
      const Basis::Space<dim>           &space;
      const DoFHandler<dim>             &dof_handler;
      MPI_Comm                           comm;
      /// The local relevant numbering and the moves of values in it.
      GridDofLayout<dim>        layout;
      ComponentConstraints<dim> component_constraints;
      CellArrays                cells;
      std::vector<PatchBlock>   patches;
      VertexTables              vertices;
      /// Owners' per-cell values to the cells around their vertices.
      CellExchange cells_exchange;
      /// The components' matrices (matrix strategies), their sparsity and
      /// the assembly of the cell and patch blocks.
      GridMatrices<dim> matrices;
      /// The solves with those matrices and their preconditioners.
      MassSolver<dim> mass_solver;
      /// Scratch of solve() (solution_vector also of particle_diagonal()):
      /// constructing a Trilinos vector costs more than the whole solve of
      /// a small system.
      TrilinosWrappers::MPI::Vector rhs_vector, solution_vector;
      std::vector<double>           local_solution;
      TrilinosWrappers::MPI::Vector lumped;   // owned
      TrilinosWrappers::MPI::Vector writable; // owned + writable ghosts
      /// Per-cell scratch of particle_diagonal() and its result.
      std::vector<double> cell_scratch, diagonal_scratch;
      std::vector<double> local_lumped;
      std::vector<double> local_full_diagonal;
      SolveStatistics     stats;
      double              density = 0;
    };
  } // namespace Solver
} // namespace psmpm

#endif
