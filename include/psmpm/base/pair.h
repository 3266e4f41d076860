// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_pair_h
#define psmpm_base_pair_h

#include <deal.II/base/tensor.h>

#include <cstring>

namespace psmpm
{
  /**
   * Two doubles in one register (GCC and Clang vector extension; SSE2 on
   * every x86-64, NEON on ARM) for the per-particle loops: a plane vector,
   * a row of a 2 x 2 tensor, two neighbouring entries of a block. Debian's
   * deal.II is built without vectorization (no VectorizedArray<double,
   * 2>), and its Tensor arithmetic goes through index accessors that GCC
   * does not reduce to packed instructions. Lane-wise the operations are
   * those of the scalar code, so results are the same bits.
   */
  using Pair = double __attribute__((vector_size(16)));

  inline Pair
  load_pair(const double *p)
  {
    Pair v;
    std::memcpy(&v, p, sizeof(v));
    return v;
  }

  inline void
  store_pair(double *p, const Pair v)
  {
    std::memcpy(p, &v, sizeof(v));
  }

  /// The two components of a plane vector (contiguous in a Tensor).
  inline Pair
  load_pair(const dealii::Tensor<1, 2> &t)
  {
    return load_pair(&t[0]);
  }

  inline void
  store_pair(dealii::Tensor<1, 2> &t, const Pair v)
  {
    store_pair(&t[0], v);
  }

  inline Pair
  broadcast(const double x)
  {
    return Pair{x, x};
  }
} // namespace psmpm

#endif
