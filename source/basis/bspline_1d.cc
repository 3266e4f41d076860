// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <psmpm/basis/bspline_1d.h>

#include <algorithm>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    BSpline1D::BSpline1D(const unsigned int degree,
                         const unsigned int n_elements)
      : p(degree)
      , n(n_elements)
    {
      AssertThrow(degree >= 1 && n_elements >= 1,
                  ExcMessage("B-splines need degree >= 1 and at least one "
                             "element."));
    }

    double
    BSpline1D::knot(const unsigned int k) const
    {
      AssertIndexRange(k, n + 2 * p + 1);
      if (k <= p)
        return 0.;
      if (k >= n + p)
        return 1.;
      return double(k - p) / n;
    }

    void
    BSpline1D::values(const unsigned int element,
                      const double       x,
                      double            *N) const
    {
      AssertIndexRange(element, n);
      // Piegl and Tiller, The NURBS Book, algorithm A2.2 on knot span
      // i = element + p: N[r] is function element + r.
      const unsigned int  i = element + p;
      std::vector<double> left(p + 1), right(p + 1);
      N[0] = 1.;
      for (unsigned int j = 1; j <= p; ++j)
        {
          left[j]      = x - knot(i + 1 - j);
          right[j]     = knot(i + j) - x;
          double saved = 0.;
          for (unsigned int r = 0; r < j; ++r)
            {
              const double temp = N[r] / (right[r + 1] + left[j - r]);
              N[r]              = saved + right[r + 1] * temp;
              saved             = left[j - r] * temp;
            }
          N[j] = saved;
        }
    }

    FullMatrix<double>
    BSpline1D::mass_matrix(const BSpline1D &other) const
    {
      AssertThrow(other.n == n,
                  ExcMessage("mass_matrix: both spaces need the same "
                             "elements."));
      // Degree p + q on each element: (p + q) / 2 + 1 Gauss points are
      // exact.
      const QGauss<1>     gauss((p + other.p) / 2 + 1);
      FullMatrix<double>  M(n_functions(), other.n_functions());
      std::vector<double> a(p + 1), b(other.p + 1);
      const double        h = 1. / n;
      for (unsigned int e = 0; e < n; ++e)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double x = (e + gauss.point(q)[0]) * h;
            const double w = gauss.weight(q) * h;
            values(e, x, a.data());
            other.values(e, x, b.data());
            for (unsigned int i = 0; i <= p; ++i)
              for (unsigned int j = 0; j <= other.p; ++j)
                M(e + i, e + j) += w * a[i] * b[j];
          }
      return M;
    }

    Vector<double>
    BSpline1D::integrals() const
    {
      // Each B-spline integrates to (knot span of its support) / (p + 1).
      Vector<double> v(n_functions());
      for (unsigned int i = 0; i < n_functions(); ++i)
        v(i) = (knot(i + p + 1) - knot(i)) / (p + 1);
      return v;
    }
  } // namespace Basis
} // namespace psmpm
