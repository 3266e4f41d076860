// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_triangle_geometry_h
#define psmpm_mesh_triangle_geometry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * Barycentric coordinates of a triangle as affine functions,
     * lambda_k(x) = constant[k] + gradient[k] . x. This closed-form inverse
     * of the affine triangle map replaces deal.II's generic (and, on
     * triangles in 9.4.1, unreliable) point inversion.
     */
    struct BarycentricMap
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
  } // namespace Mesh
} // namespace psmpm

#endif
