// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_solver_h
#define psmpm_solver_mass_solver_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/solver/component_cg.h>
#include <psmpm/solver/component_constraints.h>
#include <psmpm/solver/dense_cholesky.h>
#include <psmpm/solver/grid_dof_layout.h>
#include <psmpm/solver/mass_preconditioners.h>
#include <psmpm/solver/rigid_mode_correction.h>

#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    template <int dim>
    class GridSystem;

    /**
     * The linear solves M x_d = b_d of GridSystem's dim components with
     * their assembled matrices: per step, whether the components share
     * one unconstrained matrix and one ComponentCG (more than one
     * component, homogeneous Dirichlet constraints only, (block) Jacobi,
     * no direct solver), which components Dirichlet conditions fix
     * everywhere or nowhere, the dense Cholesky factors of small serial
     * systems (Mass matrix/Direct solver size) and the preconditioners.
     */
    template <int dim>
    class MassSolver
    {
    public:
      /// The entries of Mass matrix the solves read.
      struct Settings
      {
        double                                        tolerance;
        double                                        step_tolerance;
        double                                        free_step_tolerance;
        unsigned int                                  max_iterations;
        std::string                                   preconditioner;
        unsigned int                                  dofs_per_vertex;
        typename PMultigridHierarchy<dim>::Parameters multigrid;
      };

      explicit MassSolver(const Settings &settings);

      /// After GridSystem::reinit() has set its layout and constraints:
      /// whether this run may factor its matrices (@p direct), and the
      /// preconditioners' set-up that depends on @p grid only.
      void
      reinit(const GridSystem<dim> &grid, const bool direct);
      /// After every change of the sparsity pattern of @p M.
      void
      set_sparsity(const TrilinosWrappers::SparseMatrix &M);

      /**
       * Decide the step's way of solving from the step's constraints
       * (collective): components together, and per component fully fixed
       * (every DoF on every rank) or free (none). @p direct_assembly:
       * GridMatrices::direct_assembly() on this rank.
       */
      void
      classify(const ComponentConstraints<dim> &constraints,
               const GridDofLayout<dim>        &layout,
               const bool                       direct_assembly,
               MPI_Comm                         comm);
      bool
      together() const
      {
        return components_together;
      }
      bool
      fully_fixed(const unsigned int d) const
      {
        return fixed_everywhere[d];
      }

      /// The shared matrix @p M is assembled: the fixed rows of each
      /// component and its preconditioner with them masked.
      void
      prepare_shared(const TrilinosWrappers::SparseMatrix &M,
                     const ComponentConstraints<dim>      &constraints,
                     const GridDofLayout<dim>             &layout,
                     const unsigned int                    generation);
      /// Component @p d's constrained matrix @p A is assembled: its
      /// factorization (direct solves) or else its preconditioner.
      void
      prepare(const unsigned int                    d,
              const GridSystem<dim>                &grid,
              const TrilinosWrappers::SparseMatrix &A,
              const std::vector<char>              &constrained,
              const unsigned int                    generation);
      /// Component @p d is not solved this step (fully fixed).
      void
      skip(const unsigned int d)
      {
        factored[d] = false;
      }

      /// Together: the columns (allocated for @p map, the shared matrix'
      /// rows) with @p solution's owned entries as the guess, zero on
      /// fixed rows.
      void
      set_guess(const std::vector<Tensor<1, dim>> &solution,
                const Epetra_Map                  &map,
                const std::vector<unsigned int>   &owned_to_relevant);
      /// Together: the right-hand side column of component @p d (owned
      /// order), to be filled before solve_components().
      double *
      rhs_column(const unsigned int d);
      /// Together: component @p d's solution after solve_components().
      const double *
      solution_column(const unsigned int d) const;
      /// Together: all components by ComponentCG from the guess, with
      /// the fixed rows of the right-hand sides zeroed, then the rigid
      /// modes of the free components corrected (RigidModeCorrection),
      /// so that free components may stop at Free body step tolerance;
      /// returns the sum of their iterations.
      unsigned int
      solve_components(const TrilinosWrappers::SparseMatrix &M,
                       double                               &condition_number);

      /// Component @p d alone: A x = rhs, @p x holding the guess (zero on
      /// constrained DoFs); returns CG's iterations (0 for a direct solve
      /// or a zero right-hand side).
      unsigned int
      solve(const unsigned int                    d,
            const TrilinosWrappers::SparseMatrix &A,
            const TrilinosWrappers::MPI::Vector  &rhs,
            TrilinosWrappers::MPI::Vector        &x,
            double                               &condition_number);

      const PMultigridHierarchy<dim> &
      multigrid() const
      {
        return preconditioners.multigrid();
      }

    private:
      /// Mass matrix/Step tolerance for component @p d solved alone: 0
      /// (off) for a free component, which has no rigid-mode correction
      /// on that path.
      double
      step_tolerance(const unsigned int d) const;
      bool
      share_matrix(const ComponentConstraints<dim> &constraints,
                   const GridDofLayout<dim>        &layout,
                   const bool                       direct_assembly,
                   MPI_Comm                         comm) const;

      const Settings           settings;
      MassPreconditioners<dim> preconditioners;
      /// Direct solves: whether this run may use them, and per component
      /// whether this step's matrix was factored.
      bool                           direct = false;
      std::array<DenseCholesky, dim> dense;
      std::array<bool, dim>          factored{};
      /// Components solved together (decided in every classify()).
      bool components_together = false;
      /// Per component, whether Dirichlet conditions fix every DoF on
      /// every rank (e.g. y of a bar between rollers): its solution is
      /// zero, and its matrix is neither assembled nor solved.
      std::array<bool, dim> fixed_everywhere{};
      /// Per component, whether no DoF is constrained on any rank (a free
      /// body): momentum (and, with every component free, angular
      /// momentum) must stay conserved to round-off. Solved together,
      /// the rigid-mode correction sees to it; solved alone, the
      /// component keeps Solver tolerance.
      std::array<bool, dim>    free_component{};
      RigidModeCorrection<dim> rigid_modes;
      /// Together: per component the locally owned rows (owned order) it
      /// fixes, the solver and its columns.
      std::vector<std::vector<unsigned int>> fixed_rows;
      /// Together: the component whose preconditioner component d uses
      /// (the first one with the same fixed rows).
      std::array<unsigned int, dim>       preconditioner_of{};
      ComponentCG                         component_cg;
      std::unique_ptr<Epetra_MultiVector> rhs_columns, solution_columns;
    };
  } // namespace Solver
} // namespace psmpm

#endif
