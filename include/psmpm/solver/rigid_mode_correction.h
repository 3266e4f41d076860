// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_rigid_mode_correction_h
#define psmpm_solver_rigid_mode_correction_h

#include <deal.II/base/point.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * Makes an inexact solution of the component solves M x_d = b_d
     * (one mass matrix M shared by the dim components) conserve what an
     * exact one conserves: afterwards R^T (b - M x) = 0 to round-off for
     * the rigid modes R of the free components: a uniform field per free
     * component (momentum) and, when every component of a 2d field is
     * free, the rotation (-y, x) (angular momentum). The correction is a
     * Galerkin step on those modes, x += R a with (R^T M R) a =
     * R^T (b - M x), a system of at most three unknowns.
     *
     * Why: a free body's momentum after the grid-to-particle transfer is
     * R^T M x (the rows of the consistent mass sum to the lumped masses,
     * and stabilisation blocks annihilate the affine fields the space
     * reproduces), so an exact solve conserves it and a solve stopped at
     * a fraction of the step's change leaves its residual in it. With the
     * correction the CG may stop at Mass matrix/Step tolerance on free
     * bodies too (doc/performance.md, "What the time step needs of the
     * mass solves").
     *
     * The modes are written with the coefficients of affine fields in
     * the space: 1 for a constant (partition of unity) and the control
     * points for x and y. A row whose off-diagonal entries are all zero
     * (a DoF without particles, or one whose only particles sit on its
     * vertex) is solved exactly instead and left out of the modes, so
     * that the correction does not move coefficients nothing reads. If
     * the matrix on the modes is singular (an empty grid, DoFs on one
     * line), the CG's solution is kept as it is.
     */
    template <int dim>
    class RigidModeCorrection
    {
    public:
      /// The global index and the control point of every row of the
      /// shared matrix, in the rows' (owned) order.
      void
      reinit(std::vector<long long>  &&row_indices,
             std::vector<Point<dim>> &&row_points);

      /// After each assembly of the matrix: the modes' products with it
      /// are recomputed at the next correct() (MUSL's two solves of a
      /// step share them).
      void
      matrix_changed();

      /**
       * Correct @p x (columns: components) for right-hand sides @p b on
       * the modes that @p free admits; does nothing if no component is
       * free. Collective over @p M's communicator.
       */
      void
      correct(const Epetra_CrsMatrix     &M,
              const std::array<bool, dim> free,
              const Epetra_MultiVector   &b,
              Epetra_MultiVector         &x);

    private:
      /// The modes' single-component columns 1, x (, y) with the
      /// decoupled rows zeroed, their products with M, and the decoupled
      /// rows with their diagonal entries.
      void
      set_modes(const Epetra_CrsMatrix &M);

      std::vector<long long>              indices;
      std::vector<Point<dim>>             points;
      std::unique_ptr<Epetra_MultiVector> modes, products, residual;
      std::vector<std::pair<int, double>> decoupled;
      bool                                modes_current = false;
    };
  } // namespace Solver
} // namespace psmpm

#endif
