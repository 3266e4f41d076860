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
#include <psmpm/solver/component_cg.h>
#include <psmpm/solver/dense_cholesky.h>
#include <psmpm/solver/ghost_exchange.h>
#include <psmpm/solver/mass_strategy.h>
#include <psmpm/solver/p_multigrid_hierarchy.h>
#include <psmpm/solver/sampling_stabilization.h>
#include <psmpm/solver/vertex_block_jacobi.h>

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
        double       step_tolerance = 1e-6;
        unsigned int max_iterations = 1000;
        std::string  preconditioner = "block jacobi";
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

      /// A dense block over a set of DoFs (local relevant numbering) that a
      /// strategy adds, times @p weight, to the matrix of every component
      /// (e.g. a ghost penalty over the union of two cells). The block
      /// only points to data the strategy keeps (a step adds tens of
      /// thousands of blocks: no allocation per block and step).
      struct PatchBlock
      {
        const unsigned int *dofs = nullptr;
        unsigned int        n    = 0;
        /// n x n, row-major.
        const double *values = nullptr;
        double        weight = 1;
        /// Value-array positions from patch_slots() for the current
        /// sparsity_generation(), or nullptr (searched in the row).
        const int *slots = nullptr;
      };

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
        return cell_dof_indices;
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
        return generation;
      }
      /// Value-array positions of the entries (k, l) of a dense block over
      /// the local relevant DoFs @p dofs (-1 where the row is another
      /// rank's), for PatchBlock::slots; empty if the matrices are not
      /// assembled directly.
      void
      patch_slots(const unsigned int *dofs,
                  const unsigned int  n,
                  std::vector<int>   &slots) const;
      const std::vector<unsigned int> &
      owned_cells() const
      {
        return owned_cell_indices;
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
        return exchange;
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
        return owned;
      }
      const IndexSet &
      relevant_dofs() const
      {
        return relevant;
      }
      /// Global index of local relevant index l.
      const std::vector<types::global_dof_index> &
      relevant_global_indices() const
      {
        return relevant_global;
      }
      const AffineConstraints<double> &
      dirichlet_constraints(const unsigned int d) const
      {
        return dirichlet[d];
      }
      const AffineConstraints<double> &
      constraints(const unsigned int d) const
      {
        return active_constraints[d];
      }
      /// Replace the step's constraints of component d (closed, already
      /// merged with the Dirichlet ones).
      void
      set_constraints(const unsigned int d, AffineConstraints<double> &c)
      {
        active_constraints[d].clear();
        active_constraints[d].copy_from(c);
        update_constraint_flags(d);
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
        return matrix[d];
      }
      /// Preconditioner = pmg (one process, Powell-Sabin): the levels of
      /// the p-multigrid, assembled with the matrices.
      const PMultigridHierarchy<dim> &
      multigrid() const
      {
        return pmg;
      }
      /// Lumped mass in local relevant numbering (after assemble_mass).
      const std::vector<double> &
      lumped_mass() const
      {
        return local_lumped;
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
      /// Sum the per-cell values into @p target; with @p condense, apply
      /// the space's ties (C^T) first, as the lumped path needs.
      void
      scatter(const double                  *cell_values,
              const unsigned int             stride,
              const unsigned int             offset,
              TrilinosWrappers::MPI::Vector &target,
              const bool                     condense = false) const;
      void
      build_ties();
      void
      to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
               std::vector<double>                 &local) const;
      void
      compute_full_support_diagonal(const double density);
      void
      build_vertex_tables(
        const std::array<std::set<types::boundary_id>, dim> &fixed);
      void
      build_sparsity();
      /// The particle mass matrix' diagonal in local relevant numbering
      /// (a member's reference, valid until the next call).
      const std::vector<double> &
      particle_diagonal();
      void
      assemble_matrix(const unsigned int d);
      /// Per-cell AffineConstraints::distribute_local_to_global, for
      /// constraints that tie DoFs to others (extrapolate).
      void
      assemble_matrix_with_constraints(const unsigned int d);
      /// Positions of the cell blocks' entries in the matrices' value
      /// arrays, after every change of the sparsity.
      void
      compute_matrix_slots();
      /// Add the dense block @p values (row-major, n x n) over the local
      /// relevant DoFs @p dofs to @p target, as distribute_local_to_global
      /// with homogeneous Dirichlet constraints on the DoFs flagged in
      /// @p fixed (local relevant numbering; nullptr: none) does, through
      /// the value array (cell blocks with their precomputed @p slots,
      /// other blocks by a search of the row).
      void
      add_block(TrilinosWrappers::SparseMatrix &target,
                const char                     *fixed,
                const unsigned int             *dofs,
                const unsigned int              n,
                const double                   *values,
                const double                    weight,
                const int                      *slots);
      /// add_block() of every owned cell's block and every patch block.
      void
      add_blocks(TrilinosWrappers::SparseMatrix &target, const char *fixed);
      /// Compress @p target and give rows without particle mass (not
      /// flagged in @p fixed) a unit diagonal.
      void
      finish_assembly(TrilinosWrappers::SparseMatrix &target,
                      const char                     *fixed);
      /// Whether this step's components share one matrix and one CG
      /// (ComponentCG): more than one component, constraints that fix
      /// DoFs to zero only, (block) Jacobi CG, no direct solver.
      bool
      components_together() const;
      /// Mass matrix/Step tolerance for component @p d: 0 (off) for a
      /// free component (free_component).
      double
      step_tolerance(const unsigned int d) const;
      /// matrix[0] = M without constraints, the fixed rows of each
      /// component and its preconditioner with them masked.
      void
      assemble_shared_matrix();
      /// solution_columns (allocated for the matrix' rows) = @p solution's
      /// owned entries, zero on fixed rows: the guess of solve_components.
      void
      set_guess(const std::vector<Tensor<1, dim>> &solution);
      /// All components by ComponentCG into solution_columns, which holds
      /// the initial guess; returns the sum of their iterations.
      unsigned int
      solve_components();
      void
      update_constraint_flags(const unsigned int d);
      /// @p x holds the initial guess (owned entries).
      unsigned int
      solve_consistent(const unsigned int d, TrilinosWrappers::MPI::Vector &x);

      std::unique_ptr<MassStrategy<dim>>              mass_strategy;
      SamplingStabilization<dim>                      sampling;
      const Basis::Space<dim>                        &space;
      const DoFHandler<dim>                          &dof_handler;
      MPI_Comm                                        comm;
      IndexSet                                        owned;
      IndexSet                                        relevant;
      std::vector<types::global_dof_index>            relevant_global;
      std::vector<unsigned int>                       cell_dof_indices;
      std::vector<unsigned int>                       owned_cell_indices;
      CellArrays                                      cells;
      std::vector<PatchBlock>                         patches;
      VertexTables                                    vertices;
      std::array<AffineConstraints<double>, dim>      dirichlet;
      std::array<AffineConstraints<double>, dim>      active_constraints;
      std::array<TrilinosWrappers::SparseMatrix, dim> matrix;
      /// Direct assembly (assemble_matrix): for component d, whether every
      /// constraint fixes its DoF to zero (Dirichlet only), which DoFs are
      /// constrained (local relevant numbering), the matrix row and column
      /// of a local relevant DoF (-1: row not owned), and per owned cell
      /// (in owned_cell_indices order) the value-array position of each
      /// entry (k, l) of its block (-1: row not owned).
      std::array<bool, dim>                                 only_dirichlet{};
      std::array<std::vector<char>, dim>                    constrained;
      std::vector<int>                                      matrix_row;
      std::vector<int>                                      matrix_column;
      std::vector<int>                                      cell_slots;
      unsigned int                                          generation = 0;
      std::array<TrilinosWrappers::PreconditionJacobi, dim> jacobi;
      std::array<VertexBlockJacobi, dim>                    block_jacobi;
      std::array<TrilinosWrappers::PreconditionAMG, dim>    amg;
      /// Preconditioner = pmg: the p-multigrid's levels and cycles.
      PMultigridHierarchy<dim> pmg;
      /// Components solved together (components_together(), decided in
      /// every assemble_mass()): then matrix[0] is the unconstrained M and
      /// matrix[d > 0] is not assembled; per component the locally owned
      /// rows (owned order) it fixes, and the solver's columns.
      bool together = false;
      /// Per component, whether Dirichlet conditions fix every DoF on
      /// every rank (e.g. y of a bar between rollers): its solution is
      /// zero, and its matrix is neither assembled nor solved.
      std::array<bool, dim> fully_fixed{};
      /// Per component, whether no DoF is constrained on any rank (a free
      /// body): its solves keep Solver tolerance alone, so that momentum
      /// (and, with every component free, angular momentum) stays
      /// conserved to round-off; Step tolerance applies to the others.
      std::array<bool, dim>                  free_component{};
      std::vector<std::vector<unsigned int>> fixed_rows;
      ComponentCG                            component_cg;
      std::unique_ptr<Epetra_MultiVector>    rhs_columns, solution_columns;
      /// Direct solves (Parameters::direct_size): whether this run may use
      /// them, and per component whether this step's matrix was factored.
      bool direct = false;
      /// Scratch of solve() and solve_consistent().
      TrilinosWrappers::MPI::Vector  rhs_vector, solution_vector;
      std::vector<double>            local_solution;
      std::array<DenseCholesky, dim> dense;
      std::array<bool, dim>          factored{};
      TrilinosWrappers::MPI::Vector  lumped;   // owned
      TrilinosWrappers::MPI::Vector  writable; // owned + writable ghosts
      /// Scratch of const functions (no state between calls).
      mutable std::vector<double> scratch;
      /// Sums and ghost values between ranks (unused on one rank).
      GhostExchange exchange;
      CellExchange  cells_exchange;
      /// Per-cell scratch of particle_diagonal() and its result.
      std::vector<double> cell_scratch, diagonal_scratch;
      /// Local relevant index of the j-th owned DoF: owned vectors (the
      /// owned entries of writable ones) are read and written through
      /// their value arrays in this order, without Epetra's index maps.
      std::vector<unsigned int> owned_to_relevant;
      /// One rank: relevant == owned, and vectors are copied as arrays.
      bool                owned_is_relevant = false;
      std::vector<double> local_lumped;
      std::vector<double> local_full_diagonal;
      SolveStatistics     stats;
      double              density = 0;
      /// Space::make_space_constraints() in local relevant numbering: a
      /// tied DoF and the DoFs and weights it is tied to (empty for spaces
      /// without ties, whose lumped path is then unchanged).
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
