// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_symmetric_3x3_h
#define psmpm_solver_symmetric_3x3_h

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    /// The closed form of the eigenvalues of the symmetric 3 x 3 matrix
    /// @p A (upper triangle read; Smith 1961): q + 2 p cos(phi + 2 pi
    /// k / 3), k = 0 the largest, k = 2 the smallest; p = 0: all are q.
    /// Per-cell tests of the mass strategies (the sampling stabilisation,
    /// the ghost penalty's sampled fill) call it every step on every cell:
    /// no iteration, no allocation.
    struct ClosedForm
    {
      double q, p, phi;
    };

    inline ClosedForm
    closed_form(const double (&A)[3][3])
    {
      const double a00 = A[0][0], a11 = A[1][1], a22 = A[2][2], a01 = A[0][1],
                   a02 = A[0][2], a12 = A[1][2];
      const double q  = (a00 + a11 + a22) / 3;
      const double p1 = a01 * a01 + a02 * a02 + a12 * a12;
      const double p2 = (a00 - q) * (a00 - q) + (a11 - q) * (a11 - q) +
                        (a22 - q) * (a22 - q) + 2 * p1;
      if (!(p2 > 0))
        return {q, 0., 0.};
      const double p   = std::sqrt(p2 / 6);
      const double b00 = (a00 - q) / p, b11 = (a11 - q) / p,
                   b22 = (a22 - q) / p, b01 = a01 / p, b02 = a02 / p,
                   b12 = a12 / p;
      const double r =
        (b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) +
         b02 * (b01 * b12 - b11 * b02)) /
        2;
      return {q, p, std::acos(std::clamp(r, -1., 1.)) / 3};
    }

    /// Smallest eigenvalue of the symmetric 3 x 3 matrix @p A.
    inline double
    smallest_eigenvalue(const double (&A)[3][3])
    {
      const auto c = closed_form(A);
      return c.p > 0 ? c.q + 2 * c.p * std::cos(c.phi + 2 * M_PI / 3) : c.q;
    }

    /// Whether the symmetric 3 x 3 matrix @p A (upper triangle read)
    /// has an eigenvalue below @p s: A - s I is
    /// not positive definite (its LDL^T factorization). A screen that
    /// spares the well-sampled cells smallest_eigenvalue()'s acos and
    /// cos (the sampling stabilisation, the ghost penalty's sampled fill).
    inline bool
    has_eigenvalue_below(const double (&A)[3][3], const double s)
    {
      const double a00 = A[0][0], a11 = A[1][1], a22 = A[2][2], a01 = A[0][1],
                   a02 = A[0][2], a12 = A[1][2];
      const double d0 = a00 - s;
      if (!(d0 > 0))
        return true;
      const double l10 = a01 / d0, l20 = a02 / d0;
      const double d1 = a11 - s - l10 * a01;
      if (!(d1 > 0))
        return true;
      const double l21 = (a12 - l20 * a01) / d1;
      return !(a22 - s - l20 * a02 - l21 * l21 * d1 > 0);
    }
  } // namespace Solver
} // namespace psmpm

#endif
