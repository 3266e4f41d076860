// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_lanes_h
#define psmpm_material_lanes_h

#include <cmath>

#ifdef __SSE2__
#  include <emmintrin.h>
#endif

namespace psmpm
{
  namespace Material
  {
    /**
     * Two particles' values side by side (GCC's vector extension: packed
     * SSE2 instructions in the default x86-64 build, plain pairs of
     * scalar operations elsewhere), for the returns that update two
     * yielding particles with one instruction stream. Every operation is
     * the IEEE operation of the scalar code lane by lane (no contraction,
     * no reassociation), so that a pair's result is bit for bit the
     * result of the scalar update of each particle; the helpers below
     * keep the scalar functions' semantics where packed instructions
     * differ (std::max and std::min at ties and signed zeros).
     *
     * Not deal.II's VectorizedArray<double, 2>: its max and min are the
     * packed instructions (another result than std::max/std::min for
     * signed zeros, which would break the bit-identity with the scalar
     * return), and its compare_and_apply_mask yields values, not masks
     * that the returns combine (and, or) before one blend.
     */
    namespace Lanes
    {
      using Value = double __attribute__((vector_size(16)));
      /// A comparison's result: all bits set in a lane where it holds.
      using Mask = decltype(Value{} < Value{});

      inline Value
      broadcast(const double x)
      {
        return Value{x, x};
      }

      inline Value
      pair(const double x0, const double x1)
      {
        return Value{x0, x1};
      }

      /// m ? a : b lane by lane.
      inline Value
      select(const Mask m, const Value a, const Value b)
      {
#ifdef __SSE2__
        // andpd, andnpd, orpd: GCC 12 compiles m ? a : b with a mask
        // combined by both() or either() into a branch per lane.
        const __m128d mm = reinterpret_cast<__m128d>(m);
        return _mm_or_pd(_mm_and_pd(mm, a), _mm_andnot_pd(mm, b));
#else
        return m ? a : b;
#endif
      }

      /// The bits in which @p a and @p b differ, for pick().
      inline Value
      differing_bits(const Value a, const Value b)
      {
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) ^
                                       reinterpret_cast<Mask>(b));
      }

      /// m ? b : a lane by lane with @p bits = differing_bits(a, b)
      /// (prepared once per batch for constants): two instructions where
      /// select() takes three.
      inline Value
      pick(const Mask m, const Value a, const Value bits)
      {
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) ^
                                       (m & reinterpret_cast<Mask>(bits)));
      }

      /// std::max(a, b) lane by lane: a unless a < b.
      inline Value
      max(const Value a, const Value b)
      {
        return a < b ? b : a;
      }

      /// std::min(a, b) lane by lane: a unless b < a.
      inline Value
      min(const Value a, const Value b)
      {
        return b < a ? b : a;
      }

      inline Value
      abs(const Value a)
      {
        const Mask sign = {0x7fffffffffffffff, 0x7fffffffffffffff};
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) & sign);
      }

      inline Value
      sqrt(const Value a)
      {
#ifdef __SSE2__
        return _mm_sqrt_pd(a);
#else
        return Value{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
      }

      /// The lanes where @p m holds as bits 0 and 1 (one movmskpd: a
      /// test of m[0] and m[1] element by element goes through two
      /// general-purpose registers and a dozen instructions).
      inline int
      lane_bits(const Mask m)
      {
#ifdef __SSE2__
        return _mm_movemask_pd(reinterpret_cast<__m128d>(m));
#else
        return (m[0] != 0 ? 1 : 0) | (m[1] != 0 ? 2 : 0);
#endif
      }

      /// a & b lane by lane. The operators on two comparisons' results
      /// are right inside an expression (select()), but GCC 12 turns
      /// their result into a Mask value (lane_bits(), pick(), a function's
      /// result) lane by lane through general registers, a dozen
      /// instructions; andpd is one.
      inline Mask
      both(const Mask a, const Mask b)
      {
#ifdef __SSE2__
        return reinterpret_cast<Mask>(_mm_and_pd(reinterpret_cast<__m128d>(a),
                                                 reinterpret_cast<__m128d>(b)));
#else
        return a & b;
#endif
      }

      /// a | b lane by lane (orpd), see both().
      inline Mask
      either(const Mask a, const Mask b)
      {
#ifdef __SSE2__
        return reinterpret_cast<Mask>(_mm_or_pd(reinterpret_cast<__m128d>(a),
                                                reinterpret_cast<__m128d>(b)));
#else
        return a | b;
#endif
      }

      /// ~a & b lane by lane (andnpd), see both().
      inline Mask
      and_not(const Mask a, const Mask b)
      {
#ifdef __SSE2__
        return reinterpret_cast<Mask>(
          _mm_andnot_pd(reinterpret_cast<__m128d>(a),
                        reinterpret_cast<__m128d>(b)));
#else
        return ~a & b;
#endif
      }

      inline bool
      any(const Mask m)
      {
        return lane_bits(m) != 0;
      }

      inline bool
      all(const Mask m)
      {
        return lane_bits(m) == 3;
      }

      /// a where m does not hold, +0 where it does (bitwise: the bits of
      /// the scalar assignment x = 0).
      inline Value
      zero_where(const Mask m, const Value a)
      {
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) & ~m);
      }

      /// Two adjacent doubles at @p p (any alignment).
      inline Value
      load(const double *p)
      {
        Value v;
        __builtin_memcpy(&v, p, sizeof(v));
        return v;
      }

      /// @p v to two adjacent doubles at @p p (any alignment).
      inline void
      store(double *p, const Value v)
      {
        __builtin_memcpy(p, &v, sizeof(v));
      }

      /// (a[i], b[j]) for lane indices i, j in {0, 1}.
      template <int i, int j>
      inline Value
      combine(const Value a, const Value b)
      {
        return __builtin_shuffle(a, b, Mask{i, 2 + j});
      }
    } // namespace Lanes
  }   // namespace Material
} // namespace psmpm

#endif
