// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/basis/extrapolation.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/triangle_geometry.h>

namespace psmpm
{
  namespace Basis
  {
    FullMatrix<double>
    extrapolation_weights(const Space &space,
                          const Triangulation<2> &,
                          const unsigned int from,
                          const unsigned int to)
    {
      // Called when the set of poorly supported vertices changes, never
      // per particle, so a type test is fine here.
      if (const auto *ps = dynamic_cast<const PowellSabin *>(&space))
        {
          const auto  bary = Mesh::barycentric_map(ps->control_triangle(from));
          const auto &Q    = ps->control_triangle(to);
          FullMatrix<double> W(3, 3);
          for (unsigned int q = 0; q < 3; ++q)
            {
              const auto l = bary(Q[q]);
              for (unsigned int r = 0; r < 3; ++r)
                W(q, r) = l[r];
            }
          return W;
        }
      FullMatrix<double> W(1, 1);
      W(0, 0) = 1;
      return W;
    }
  } // namespace Basis
} // namespace psmpm
