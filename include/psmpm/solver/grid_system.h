// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_grid_system_h
#define psmpm_solver_grid_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
     * The grid side of MPM: the mass matrix and the solution of M x = b for
     * the two velocity components with their own Dirichlet constraints.
     * Particle loops accumulate into plain per-cell arrays (no searching,
     * no Trilinos calls per particle); this class turns those into
     * distributed systems and returns the solution in a local array over
     * the locally relevant DoFs (index l of relevant_dofs()).
     *
     * Mass matrix strategies (thesis chapter 5 and beyond):
     * - consistent: the particle-quadrature matrix, CG;
     * - lumped: row sums, no sparse matrix is built;
     * - partially lumped: couplings of the functions of vertices on the
     *   material's free boundary (touching a filled and an empty cell, or
     *   on a mesh boundary without Dirichlet condition) are moved to the
     *   diagonal, symmetrically, so row sums (momentum) and definiteness
     *   are kept (Sec. 5.4, symmetrised);
     * - deactivate: the functions of vertices with a particle diagonal
     *   M_ii below Threshold times its full-support diagonal are set to
     *   zero (Sec. 5.2 with a relative bound);
     * - extrapolate: the coefficients of vertices with a function below
     *   that bound follow the local linear part of the nearest well
     *   supported vertex (extended B-splines), as linear constraints.
     */
    class GridSystem
    {
    public:
      enum class MassType
      {
        consistent,
        lumped,
        partially_lumped,
        deactivate,
        extrapolate
      };

      struct Parameters
      {
        static void
        declare_parameters(ParameterHandler &prm);
        void
        parse_parameters(ParameterHandler &prm);

        MassType     type           = MassType::partially_lumped;
        double       tolerance      = 1e-12;
        unsigned int max_iterations = 1000;
        std::string  preconditioner = "jacobi";
        double       threshold      = 0.05;
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
      };

      GridSystem(const Parameters    &parameters,
                 const Basis::Space  &space,
                 const DoFHandler<2> &dof_handler,
                 MPI_Comm             comm);

      /**
       * Index sets, constraints (component d fixed on fixed[d]) and, for
       * matrix types, sparsity and matrices. @p density is the material
       * density for the full-support diagonal of the relative thresholds;
       * boundaries not in @p fixed are free surfaces for partial lumping.
       */
      void
      reinit(const std::array<std::set<types::boundary_id>, 2> &fixed,
             const double                                       density);

      /// Zero the per-cell accumulators of the owned cells.
      void
      zero_cell_mass();
      void
      zero_cell_rhs();

      /// Build the mass matrix (or lumped diagonal) from the per-cell data.
      void
      assemble_mass();

      /// Solve M x_d = b_d for d = 0, 1 with b from cell_rhs; result in
      /// @p solution (local relevant numbering).
      void
      solve(std::vector<Tensor<1, 2>> &solution);

      const SolveStatistics &
      statistics() const
      {
        return stats;
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
      const AffineConstraints<double> &
      constraints(const unsigned int d) const
      {
        return active_constraints[d];
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

      const Parameters   parameters;
      const unsigned int dofs_per_cell;
      const unsigned int n_cells;

      /// Local relevant index of DoF k of cell c at [c * dofs_per_cell + k]
      /// (owned cells only).
      std::vector<unsigned int> cell_dofs;
      /// Per owned cell: consistent mass dofs_per_cell^2 (row-major; only
      /// for matrix types), lumped row sums and right-hand sides.
      std::vector<double>       cell_mass;
      std::vector<double>       cell_lumped;
      std::vector<Tensor<1, 2>> cell_rhs;
      /// Indices of the locally owned cells.
      std::vector<unsigned int> owned_cells;

    private:
      bool
      uses_matrix() const
      {
        return parameters.type != MassType::lumped;
      }
      void
      scatter(const double                  *cell_values,
              const unsigned int             stride,
              const unsigned int             offset,
              TrilinosWrappers::MPI::Vector &target) const;
      void
      to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
               std::vector<double>                 &local) const;
      void
      compute_full_support_diagonal(const double density);
      void
      build_vertex_tables(
        const std::array<std::set<types::boundary_id>, 2> &fixed);
      void
      build_sparsity();
      std::vector<bool>
      poorly_supported_vertices(const std::vector<double> &diagonal) const;
      void
      lump_free_boundary_couplings();
      bool
      update_step_constraints(const std::vector<bool> &outer_vertices);
      unsigned int
      solve_consistent(const unsigned int d, TrilinosWrappers::MPI::Vector &x);

      const Basis::Space                                 &space;
      const DoFHandler<2>                                &dof_handler;
      MPI_Comm                                            comm;
      IndexSet                                            owned;
      IndexSet                                            relevant;
      std::vector<types::global_dof_index>                relevant_global;
      std::array<AffineConstraints<double>, 2>            dirichlet;
      std::array<AffineConstraints<double>, 2>            active_constraints;
      std::array<TrilinosWrappers::SparseMatrix, 2>       matrix;
      std::array<TrilinosWrappers::PreconditionJacobi, 2> jacobi;
      std::array<TrilinosWrappers::PreconditionAMG, 2>    amg;
      TrilinosWrappers::MPI::Vector                       lumped; // owned
      TrilinosWrappers::MPI::Vector writable; // owned + writable ghosts
      TrilinosWrappers::MPI::Vector ghosted;  // owned + readable ghosts
      std::vector<double>           local_lumped;
      std::vector<double>           local_full_diagonal;
      std::vector<double>           scratch;
      SolveStatistics               stats;

      // Vertex view of the DoFs (for vertex-wise strategies).
      unsigned int                           dofs_per_vertex = 1;
      std::vector<std::vector<unsigned int>> vertex_dofs;  // local relevant
      std::vector<std::vector<unsigned int>> vertex_cells; // active indices
      std::vector<std::vector<unsigned int>> vertex_neighbors;
      std::vector<bool>                      vertex_on_free_boundary;
      std::vector<bool>                      previous_outer;
    };
  } // namespace Solver
} // namespace psmpm

#endif
