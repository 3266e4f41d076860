// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_bspline_1d_h
#define psmpm_basis_bspline_1d_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace psmpm
{
  namespace Basis
  {
    using namespace dealii;

    /**
     * Univariate B-splines of degree p with maximal continuity C^{p-1} on
     * the open uniform knot vector of [0, 1] with n elements
     * {0, ..., 0, 1/n, ..., (n-1)/n, 1, ..., 1} (first and last knot
     * repeated p + 1 times): n + p functions, the first and the last
     * interpolatory at the end points (Wobbes et al. 2019, section 4.3).
     * Functions are evaluated by the Cox-de Boor recursion (eqs. 4.19,
     * 4.20) in the triangular form of Piegl and Tiller's BasisFuns.
     *
     * Tensor-product spaces on the unit square are built from these by the
     * solver study (Solver::MassMatrixStudy): their mass matrices are
     * Kronecker products of the univariate ones.
     */
    class BSpline1D
    {
    public:
      BSpline1D(const unsigned int degree, const unsigned int n_elements);

      unsigned int
      degree() const
      {
        return p;
      }

      unsigned int
      n_elements() const
      {
        return n;
      }

      /// n + p.
      unsigned int
      n_functions() const
      {
        return n + p;
      }

      /// Knot k = 0, ..., n + 2p of the open uniform knot vector.
      double
      knot(const unsigned int k) const;

      /**
       * The p + 1 functions that do not vanish on element @p element
       * (functions element, ..., element + p), at @p x in that element's
       * closed interval, into @p values.
       */
      void
      values(const unsigned int element, const double x, double *values) const;

      /**
       * Mass matrix M_ij = int_0^1 phi_i phi_j of this space (rows) against
       * @p other (columns) on the same elements, with the Gauss rule exact
       * for the product: the consistent mass matrix when @p other is this
       * space, the mixed matrix of the L2 projection between degrees
       * otherwise. Rows and columns of all n + p functions.
       */
      FullMatrix<double>
      mass_matrix(const BSpline1D &other) const;

      /// The integrals int_0^1 phi_i of the n + p functions (the load
      /// vector of a unit constant).
      Vector<double>
      integrals() const;

    private:
      unsigned int p;
      unsigned int n;
    };
  } // namespace Basis
} // namespace psmpm

#endif
