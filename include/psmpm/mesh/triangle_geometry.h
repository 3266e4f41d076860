// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_triangle_geometry_h
#define psmpm_mesh_triangle_geometry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * Barycentric coordinates lambda_0, ..., lambda_dim of a simplex
     * (a line in 1D, a triangle in 2D) as affine functions of x. These
     * closed-form inverses of the affine cell map replace deal.II's generic
     * (and, on triangles in 9.4.1, unreliable) point inversion.
     */
    template <int dim>
    struct SimplexMap;

    /**
     * Triangle: lambda_k(x) = constant[k] + gradient[k] . x.
     */
    template <>
    struct SimplexMap<2>
    {
      std::array<double, 3>       constant;
      std::array<Tensor<1, 2>, 3> gradient;

      std::array<double, 3>
      operator()(const Point<2> &p) const
      {
        return {{constant[0] + gradient[0] * p,
                 constant[1] + gradient[1] * p,
                 constant[2] + gradient[2] * p}};
      }
    };

    /**
     * Line [vertex[0], vertex[1]]: lambda_k(x) = gradient[k] (x - vertex[1-k]).
     * Measuring from the opposite vertex rather than from the origin keeps
     * the round-off relative to the element length: lambda_k vanishes
     * exactly at the opposite vertex however far the mesh is from x = 0.
     */
    template <>
    struct SimplexMap<1>
    {
      std::array<Point<1>, 2>     vertex;
      std::array<Tensor<1, 1>, 2> gradient;

      std::array<double, 2>
      operator()(const Point<1> &p) const
      {
        return {{gradient[0] * (p - vertex[1]), gradient[1] * (p - vertex[0])}};
      }
    };

    /// The triangle map under its historical name.
    using BarycentricMap = SimplexMap<2>;

    /// Signed area of the triangle (positive when counter-clockwise).
    inline double
    signed_area(const std::array<Point<2>, 3> &v)
    {
      return 0.5 * ((v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) -
                    (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]));
    }

    inline BarycentricMap
    barycentric_map(const std::array<Point<2>, 3> &v)
    {
      const double twice_area = 2 * signed_area(v);
      Assert(twice_area != 0, ExcMessage("degenerate triangle"));
      BarycentricMap m;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Point<2> &a = v[(k + 1) % 3];
          const Point<2> &b = v[(k + 2) % 3];
          // lambda_k vanishes on edge (a, b) and is 1 at v[k].
          m.gradient[k][0] = (a[1] - b[1]) / twice_area;
          m.gradient[k][1] = (b[0] - a[0]) / twice_area;
          m.constant[k]    = (a[0] * b[1] - b[0] * a[1]) / twice_area;
        }
      return m;
    }

    /// Signed length of the line (positive when vertex 1 is right of 0).
    inline double
    signed_length(const std::array<Point<1>, 2> &v)
    {
      return v[1][0] - v[0][0];
    }

    /// Signed measure of a simplex: length in 1D, area in 2D.
    inline double
    signed_measure(const std::array<Point<1>, 2> &v)
    {
      return signed_length(v);
    }

    inline double
    signed_measure(const std::array<Point<2>, 3> &v)
    {
      return signed_area(v);
    }

    /// Smallest height of the triangle (over any of its edges), from the
    /// absolute area: the length scale of the time step bound.
    inline double
    minimum_height(const std::array<Point<2>, 3> &v)
    {
      const double area = std::abs(signed_area(v));
      double       h    = std::numeric_limits<double>::max();
      for (unsigned int k = 0; k < 3; ++k)
        h = std::min(h, 2 * area / v[(k + 1) % 3].distance(v[(k + 2) % 3]));
      return h;
    }

    /// A line's "height" over either end is its length.
    inline double
    minimum_height(const std::array<Point<1>, 2> &v)
    {
      return std::abs(signed_length(v));
    }

    inline SimplexMap<1>
    barycentric_map(const std::array<Point<1>, 2> &v)
    {
      const double length = signed_length(v);
      Assert(length != 0, ExcMessage("degenerate line"));
      SimplexMap<1> m;
      m.vertex         = v;
      m.gradient[0][0] = -1 / length;
      m.gradient[1][0] = 1 / length;
      return m;
    }

    /**
     * The 7-point rule of degree 5 on a triangle (Radon/Dunavant; the same
     * as QGaussSimplex<2>(3) up to the order of the points) in barycentric
     * coordinates, weights summing to 1: the Powell-Sabin cell quadrature
     * and the L2 projection use it on the PS sub-triangles (the order and
     * form are kept so that their results stay as they were).
     */
    struct TriangleRule
    {
      std::array<std::array<double, 3>, 7> points;
      std::array<double, 7>                weights;
      TriangleRule()
      {
        const double s  = std::sqrt(15.);
        const double a1 = (6 - s) / 21, b1 = (9 + 2 * s) / 21;
        const double a2 = (6 + s) / 21, b2 = (9 - 2 * s) / 21;
        const double w1 = (155 - s) / 1200, w2 = (155 + s) / 1200;
        points  = {{{{1. / 3, 1. / 3, 1. / 3}},
                    {{a1, a1, b1}},
                    {{a1, b1, a1}},
                    {{b1, a1, a1}},
                    {{a2, a2, b2}},
                    {{a2, b2, a2}},
                    {{b2, a2, a2}}}};
        weights = {{9. / 40, w1, w1, w1, w2, w2, w2}};
      }
    };
  } // namespace Mesh
} // namespace psmpm

#endif
