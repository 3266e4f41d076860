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
     * The grid side of MPM: the mass matrix (consistent Trilinos matrix or
     * lumped diagonal) and the solution of M x = b for the two velocity
     * components with their own Dirichlet constraints. Particle loops
     * accumulate into plain per-cell arrays (no searching, no Trilinos
     * calls per particle); this class turns those into distributed
     * systems and returns the solution in a local array over the locally
     * relevant DoFs (index l of relevant_dofs()).
     */
    class GridSystem
    {
    public:
      enum class MassType
      {
        consistent,
        lumped
      };

      struct Parameters
      {
        static void
        declare_parameters(ParameterHandler &prm);
        void
        parse_parameters(ParameterHandler &prm);

        MassType     type           = MassType::consistent;
        double       tolerance      = 1e-12;
        unsigned int max_iterations = 1000;
        std::string  preconditioner = "jacobi";
      };

      struct SolveStatistics
      {
        unsigned int iterations   = 0;
        double       min_diagonal = 0; ///< of the lumped mass, active DoFs
        double       max_diagonal = 0;
        unsigned int n_empty_dofs = 0; ///< DoFs with no particle support
      };

      GridSystem(const Parameters    &parameters,
                 const Basis::Space  &space,
                 const DoFHandler<2> &dof_handler,
                 MPI_Comm             comm);

      /// Index sets, constraints (component d fixed on fixed[d]) and, for
      /// consistent mass, the sparsity pattern and matrices.
      void
      reinit(const std::array<std::set<types::boundary_id>, 2> &fixed);

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
        return component_constraints[d];
      }
      /// Lumped mass in local relevant numbering (after assemble_mass).
      const std::vector<double> &
      lumped_mass() const
      {
        return local_lumped;
      }

      const Parameters   parameters;
      const unsigned int dofs_per_cell;
      const unsigned int n_cells;

      /// Local relevant index of DoF k of cell c at [c * dofs_per_cell + k]
      /// (owned cells only).
      std::vector<unsigned int> cell_dofs;
      /// Per owned cell: consistent mass dofs_per_cell^2 (row-major; only
      /// when consistent), lumped row sums and right-hand sides.
      std::vector<double>       cell_mass;
      std::vector<double>       cell_lumped;
      std::vector<Tensor<1, 2>> cell_rhs;
      /// Indices of the locally owned cells.
      std::vector<unsigned int> owned_cells;

    private:
      void
      scatter(const double                  *cell_values,
              const unsigned int             stride,
              const unsigned int             offset,
              TrilinosWrappers::MPI::Vector &target) const;
      void
      to_local(const TrilinosWrappers::MPI::Vector &owned_vector,
               std::vector<double>                 &local) const;
      unsigned int
      solve_consistent(const unsigned int d, TrilinosWrappers::MPI::Vector &x);

      const Basis::Space                                 &space;
      const DoFHandler<2>                                &dof_handler;
      MPI_Comm                                            comm;
      IndexSet                                            owned;
      IndexSet                                            relevant;
      std::vector<types::global_dof_index>                relevant_global;
      std::array<AffineConstraints<double>, 2>            component_constraints;
      std::array<TrilinosWrappers::SparseMatrix, 2>       matrix;
      std::array<TrilinosWrappers::PreconditionJacobi, 2> jacobi;
      std::array<TrilinosWrappers::PreconditionAMG, 2>    amg;
      TrilinosWrappers::MPI::Vector                       lumped; // owned
      TrilinosWrappers::MPI::Vector writable; // owned + writable ghosts
      TrilinosWrappers::MPI::Vector ghosted;  // owned + readable ghosts
      std::vector<double>           local_lumped;
      std::vector<double>           scratch;
      SolveStatistics               stats;
    };
  } // namespace Solver
} // namespace psmpm

#endif
