// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_cg.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_preconditioners.h>

#include <algorithm>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    MassPreconditioners<dim>::MassPreconditioners(
      const std::string                                   &type,
      const unsigned int                                   dofs_per_vertex,
      const typename PMultigridHierarchy<dim>::Parameters &multigrid)
      : type(type)
      , block_size(
          type == "block jacobi" && dofs_per_vertex > 1 ? dofs_per_vertex : 1)
      , pmg(multigrid)
    {
    }

    template <int dim>
    void
    MassPreconditioners<dim>::reinit(const GridSystem<dim> &grid)
    {
      pmg.clear();
      if (type == "pmg")
        pmg.reinit(grid);
    }

    template <int dim>
    void
    MassPreconditioners<dim>::initialize(
      const unsigned int                    d,
      const GridSystem<dim>                &grid,
      const TrilinosWrappers::SparseMatrix &A,
      const std::vector<char>              &constrained,
      const unsigned int                    generation)
    {
      if (type == "amg")
        amg[d].initialize(A);
      else if (type == "pmg")
        pmg.assemble(grid, d, constrained);
      else if (block_size > 1)
        vertex_jacobi[d].initialize(A, block_size, {}, generation);
      else
        jacobi[d].initialize(A);
    }

    template <int dim>
    void
    MassPreconditioners<dim>::initialize_masked(
      const unsigned int                    d,
      const TrilinosWrappers::SparseMatrix &M,
      const std::vector<unsigned int>      &fixed,
      const unsigned int                    generation)
    {
      vertex_jacobi[d].initialize(M, block_size, fixed, generation);
    }

    template <int dim>
    void
    MassPreconditioners<dim>::solve(const unsigned int                    d,
                                    const TrilinosWrappers::SparseMatrix &A,
                                    SolverControl &control,
                                    const TrilinosWrappers::MPI::Vector &rhs,
                                    TrilinosWrappers::MPI::Vector       &x,
                                    double &condition_number)
    {
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.connect_condition_number_slot([&condition_number](const double c) {
        condition_number = std::max(condition_number, c);
      });
      if (type == "amg")
        cg.solve(A, x, rhs, amg[d]);
      else if (type == "pmg")
        pmg.solve(d, control, rhs, x, condition_number);
      else if (block_size > 1)
        cg.solve(A, x, rhs, vertex_jacobi[d]);
      else
        cg.solve(A, x, rhs, jacobi[d]);
    }

    template class MassPreconditioners<1>;
    template class MassPreconditioners<2>;
  } // namespace Solver
} // namespace psmpm
