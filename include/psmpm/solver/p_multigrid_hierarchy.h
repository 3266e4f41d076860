// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_p_multigrid_hierarchy_h
#define psmpm_solver_p_multigrid_hierarchy_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <psmpm/solver/p_multigrid.h>

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
     * Mass matrix/Preconditioner = pmg: the two-level p-multigrid of
     * GridSystem's consistent mass matrix on a Powell-Sabin space (one
     * process), CG with one PMultigrid V-cycle per iteration as its
     * preconditioner. The coarse level is P1 on the same triangulation,
     * whose affine pieces the Powell-Sabin space reproduces through its
     * control points: the prolongation P maps a P1 vertex field to the
     * Powell-Sabin DoFs exactly for affine fields.
     *
     * Per component d the levels are serial deal.II matrices, as
     * PMultigrid takes them: the fine one a copy of GridSystem's Trilinos
     * matrix of component d, the coarse one either the Galerkin product
     * P_d^T M_d P_d or the P1 particle mass matrix formed cell by cell
     * from the same cell blocks (Parameters::coarse).
     */
    template <int dim>
    class PMultigridHierarchy
    {
    public:
      struct Parameters
      {
        /// "galerkin" (P_d^T M_d P_d of the assembled matrix) or
        /// "particles" (the P1 particle mass matrix; Mass
        /// matrix/Multigrid coarse matrix).
        std::string coarse = "galerkin";
        /// Smoother and sweeps of the Powell-Sabin level (Mass
        /// matrix/Multigrid smoother, .../Multigrid smoothing steps).
        PMultigrid::Parameters cycle;
      };

      explicit PMultigridHierarchy(const Parameters &parameters);

      /// Drop the levels and the prolongation (a reinit of the grid).
      void
      clear();

      /**
       * Refuse a space other than Powell-Sabin or more than one process,
       * then, for matrix strategies, P and the per-cell data of the
       * particle coarse matrix from @p grid's control points, cells and
       * Dirichlet constraints (after GridSystem::reinit() has set them).
       */
      void
      reinit(const GridSystem<dim> &grid);

      /**
       * The levels of component @p d from @p grid's assembled matrix of
       * that component; @p constrained flags its constrained DoFs (local
       * relevant numbering). Without a usable coarse factorisation (a
       * particle layout that leaves the P1 level singular) the component
       * has no cycle this step and solve() reports the failure.
       */
      void
      assemble(const GridSystem<dim>   &grid,
               const unsigned int       d,
               const std::vector<char> &constrained);

      /**
       * CG on the fine level's copy of component @p d's matrix with one
       * V-cycle from zero per iteration, stopped by @p control; @p x holds
       * the guess and receives the solution (owned entries, one process).
       * Raises @p condition_number to CG's estimate where it is larger.
       * Throws SolverFailure if assemble() left the component without a
       * cycle.
       */
      void
      solve(const unsigned int                   d,
            SolverControl                       &control,
            const TrilinosWrappers::MPI::Vector &rhs,
            TrilinosWrappers::MPI::Vector       &x,
            double                              &condition_number);

      /**
       * The prolongation P from the P1 space on the same triangulation
       * (column: vertex index) to the space (row: DoF), P_iv = the affine
       * piece of the hat function of v on a cell around DoF i's vertex,
       * evaluated at DoF i's control point; P reproduces every affine
       * function exactly. Empty unless reinit() built it.
       */
      const SparseMatrix<double> &
      prolongation() const
      {
        return prolongation_matrix;
      }
      /// The coarse (P1) matrix of component d after assemble(): P_d^T
      /// M_d P_d, P_d = P with the rows of constrained DoFs zero, or the
      /// P1 particle mass matrix (unit diagonal where a vertex has none).
      const SparseMatrix<double> &
      coarse_matrix(const unsigned int d) const
      {
        return coarse[d];
      }

    private:
      /// The rows of P: per DoF the vertices of one cell around its
      /// vertex and the barycentric coordinates of its control point.
      void
      build_prolongation(const GridSystem<dim> &grid);
      /// Per owned cell's DoF the barycentric coordinates of its control
      /// point in that cell, the cell's vertices, the P1 pattern and the
      /// vertices fixed per component (the particle coarse matrix).
      void
      build_cell_weights(const GridSystem<dim> &grid);
      /// Copy the values of @p grid's matrix of component d into fine[d],
      /// rebuilding the copy's pattern when the grid's sparsity generation
      /// has changed.
      void
      copy_fine_matrix(const GridSystem<dim> &grid, const unsigned int d);
      /// P_d: P with the rows of constrained DoFs (and, for the particle
      /// coarse matrix, the columns of fixed vertices) zero.
      void
      mask_transfer(const unsigned int d, const std::vector<char> &constrained);
      /// coarse[d] = the P1 particle mass matrix from the cell blocks.
      void
      assemble_particle_coarse(const GridSystem<dim> &grid,
                               const unsigned int     d);
      /// coarse[d] = P_d^T fine[d] P_d.
      void
      assemble_galerkin_coarse(const unsigned int d);
      /// Factorise coarse[d] and (re)build the cycle of component d.
      void
      set_up_cycle(const unsigned int d);

      const Parameters parameters;
      /// P (shared pattern) and per component P_d.
      SparsityPattern                       prolongation_pattern;
      SparseMatrix<double>                  prolongation_matrix;
      std::array<SparseMatrix<double>, dim> transfer;
      /// Per owned cell's DoF k the barycentric coordinates of its control
      /// point in that cell (coarse = particles: the cell's P1 hat
      /// functions in the cell's Powell-Sabin functions), the cells'
      /// vertices, the P1 pattern and which vertices are fixed for
      /// component d.
      std::vector<double>                cell_weights;
      std::vector<unsigned int>          cell_vertices;
      SparsityPattern                    p1_pattern;
      std::array<std::vector<char>, dim> fixed_vertex;
      /// The copy of the grid's matrix: its pattern and the value-array
      /// position in the Trilinos matrix of each of its entries, rebuilt
      /// when the sparsity generation changes (then every component's
      /// levels are rebuilt at their next assemble()).
      SparsityPattern                       fine_pattern;
      std::vector<int>                      fine_slots;
      unsigned int                          generation = 0;
      std::array<bool, dim>                 rebuild{};
      std::array<SparseMatrix<double>, dim> fine;
      /// M_d P_d, the coarse matrix, its factorisation and the cycle.
      std::array<SparsityPattern, dim>             product_pattern;
      std::array<SparseMatrix<double>, dim>        product;
      std::array<SparsityPattern, dim>             coarse_pattern;
      std::array<SparseMatrix<double>, dim>        coarse;
      std::array<SparseDirectUMFPACK, dim>         coarse_direct;
      std::array<std::unique_ptr<PMultigrid>, dim> cycle;
      /// Serial copies of solve()'s right-hand side and iterate.
      Vector<double> rhs_copy, solution_copy;
    };
  } // namespace Solver
} // namespace psmpm

#endif
