// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_polynomial_complement_h
#define psmpm_solver_polynomial_complement_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/basis/space.h>

#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * S(u, v) = int_{patch} (u - P u)(v - P v) over the functions of the
     * cells of a patch, P the L2 projection onto the polynomials of degree
     * @p degree on the patch, as S = M - B^T G^-1 B (M: the functions'
     * mass matrix, B: their moments against the monomials, G: the
     * monomials' Gram matrix; monomials in (x - @p x0) / @p h, for
     * conditioning). Local function a of cells[s] is patch function
     * to_patch[s][a]; the patch has @p n_patch functions.
     *
     * S is symmetric positive semi-definite and vanishes on every
     * polynomial of that degree that the space reproduces, whatever the
     * quadrature: with the space's partition of unity its row sums are
     * exactly zero. Mesh data only; the mass strategies weight it per step
     * (ghost penalty on pairs of cells, the sampling stabilisation on
     * single cells). If @p mass is given, it receives M (computed on the
     * way). If @p lower is given, it receives the complement of the
     * polynomials of degree @p lower_degree (< @p degree) from the same
     * quadrature: the same values as a separate call with that degree.
     */
    template <int dim>
    FullMatrix<double>
    polynomial_complement(
      const Basis::Space<dim>                      &space,
      const DoFHandler<dim>                        &dof_handler,
      const std::vector<unsigned int>              &cells,
      const std::vector<std::vector<unsigned int>> &to_patch,
      const unsigned int                            n_patch,
      const unsigned int                            degree,
      const Point<dim>                             &x0,
      const double                                  h,
      FullMatrix<double>                           *mass         = nullptr,
      const unsigned int                            lower_degree = 0,
      FullMatrix<double>                           *lower        = nullptr);

    /// Number of monomials of degree at most @p degree in dim variables.
    template <int dim>
    unsigned int
    n_monomials(const unsigned int degree);
  } // namespace Solver
} // namespace psmpm

#endif
