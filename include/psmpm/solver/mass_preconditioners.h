// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_preconditioners_h
#define psmpm_solver_mass_preconditioners_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/solver/p_multigrid_hierarchy.h>
#include <psmpm/solver/vertex_block_jacobi.h>

#include <array>
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
     * The CG preconditioners of GridSystem's component matrices
     * (Mass matrix/Preconditioner): point Jacobi, vertex block Jacobi,
     * AMG, or the p-multigrid hierarchy, one per component.
     */
    template <int dim>
    class MassPreconditioners
    {
    public:
      /// @p type: jacobi, block jacobi, amg or pmg. @p dofs_per_vertex:
      /// the space's; block jacobi with one DoF per vertex (P1,
      /// B-splines) is Trilinos' point Jacobi, as before the option
      /// existed (bit-identical results).
      MassPreconditioners(
        const std::string                                   &type,
        const unsigned int                                   dofs_per_vertex,
        const typename PMultigridHierarchy<dim>::Parameters &multigrid);

      /// Drop the p-multigrid's levels and, for pmg, rebuild its
      /// prolongation from @p grid (after its constraints are set).
      void
      reinit(const GridSystem<dim> &grid);

      /// The preconditioner of component @p d from its assembled,
      /// constrained matrix @p A (@p constrained: its constrained DoFs in
      /// local relevant numbering; @p generation: of the sparsity).
      void
      initialize(const unsigned int                    d,
                 const GridSystem<dim>                &grid,
                 const TrilinosWrappers::SparseMatrix &A,
                 const std::vector<char>              &constrained,
                 const unsigned int                    generation);
      /// (Block) Jacobi of component @p d from the unconstrained matrix
      /// @p M that the components share, its @p fixed rows masked.
      void
      initialize_masked(const unsigned int                    d,
                        const TrilinosWrappers::SparseMatrix &M,
                        const std::vector<unsigned int>      &fixed,
                        const unsigned int                    generation);

      /// Preconditioned CG on A x = rhs for component @p d, stopped by
      /// @p control, from the guess in @p x; raises @p condition_number to
      /// CG's estimate where it is larger.
      void
      solve(const unsigned int                    d,
            const TrilinosWrappers::SparseMatrix &A,
            SolverControl                        &control,
            const TrilinosWrappers::MPI::Vector  &rhs,
            TrilinosWrappers::MPI::Vector        &x,
            double                               &condition_number);

      /// Whether the preconditioner is (block) Jacobi, which
      /// initialize_masked() builds for a shared matrix.
      bool
      works_on_shared_matrix() const
      {
        return type == "jacobi" || type == "block jacobi";
      }
      const VertexBlockJacobi &
      block_jacobi(const unsigned int d) const
      {
        return vertex_jacobi[d];
      }
      const PMultigridHierarchy<dim> &
      multigrid() const
      {
        return pmg;
      }

    private:
      const std::string type;
      /// Block size of (block) Jacobi: the DoFs per vertex for block
      /// jacobi on a space with several (Powell-Sabin), else 1.
      const unsigned int                                    block_size;
      std::array<TrilinosWrappers::PreconditionJacobi, dim> jacobi;
      std::array<VertexBlockJacobi, dim>                    vertex_jacobi;
      std::array<TrilinosWrappers::PreconditionAMG, dim>    amg;
      PMultigridHierarchy<dim>                              pmg;
    };
  } // namespace Solver
} // namespace psmpm

#endif
