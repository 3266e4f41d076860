// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_cross_h
#define psmpm_base_cross_h

#include <deal.II/base/tensor.h>

namespace psmpm
{
  /// The scalar cross product a x b = a_0 b_1 - a_1 b_0 of two plane
  /// vectors (orientation tests, torques, line intersections).
  inline double
  cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b)
  {
    return a[0] * b[1] - a[1] * b[0];
  }
} // namespace psmpm

#endif
