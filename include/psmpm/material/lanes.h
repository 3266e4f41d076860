// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_lanes_h
#define psmpm_material_lanes_h

#include <cmath>
#include <utility>

#if defined(__AVX2__)
#  include <immintrin.h>
#elif defined(__SSE2__)
#  include <emmintrin.h>
#endif

namespace psmpm
{
  namespace Material
  {
    /**
     * The values of Lanes::width particles side by side (GCC's vector
     * extension: four lanes of packed AVX2 instructions where the build
     * enables AVX2, two of SSE2 in the default x86-64 build, scalar
     * operations elsewhere), for the returns that update several
     * yielding particles with one instruction stream (the functions
     * named "pair" take a group of Lanes::width particles). Every
     * operation is the IEEE operation of the scalar code lane by lane (no
     * contraction, no reassociation), so that a group's result is bit
     * for bit the result of the scalar update of each particle; the
     * helpers below keep the scalar functions' semantics where packed
     * instructions differ (std::max and std::min at ties and signed
     * zeros).
     *
     * Not deal.II's VectorizedArray<double>: its max and min are the
     * packed instructions (another result than std::max/std::min for
     * signed zeros, which would break the bit-identity with the scalar
     * return), and its compare_and_apply_mask yields values, not masks
     * that the returns combine (and, or) before one blend.
     */
    namespace Lanes
    {
#if defined(__AVX2__)
      /// Four particles side by side where the build enables AVX2 (packed
      /// 256-bit instructions: twice the particles in the same sixteen
      /// registers), else two.
      constexpr unsigned int width = 4;
#else
      constexpr unsigned int width = 2;
#endif
      /// lane_bits() of a mask that holds in every lane.
      constexpr int all_bits = (1 << width) - 1;

      using Value = double __attribute__((vector_size(8 * width)));
      /// A comparison's result: all bits set in a lane where it holds.
      using Mask = decltype(Value{} < Value{});

      namespace internal
      {
        template <typename F, std::size_t... l>
        inline Value
        lanes_of(F &&f, std::index_sequence<l...>)
        {
          return Value{f(l)...};
        }
      } // namespace internal

      /// The value f(l) in lane l.
      template <typename F>
      inline Value
      lanes_of(F &&f)
      {
        return internal::lanes_of(f, std::make_index_sequence<width>());
      }

      inline Value
      broadcast(const double x)
      {
        return lanes_of([x](std::size_t) { return x; });
      }

      /// A mask that holds in every lane.
      inline Mask
      true_mask()
      {
        return Value{} == Value{};
      }

      /// m ? a : b lane by lane.
      inline Value
      select(const Mask m, const Value a, const Value b)
      {
#if defined(__AVX2__)
        // One vblendvpd (GCC 12 compiles m ? a : b with a mask combined
        // by both() or either() into a branch per lane).
        return _mm256_blendv_pd(b, a, reinterpret_cast<__m256d>(m));
#elif defined(__SSE2__)
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
        const Mask sign = reinterpret_cast<Mask>(broadcast(-0.));
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) & ~sign);
      }

      inline Value
      sqrt(const Value a)
      {
#if defined(__AVX2__)
        return _mm256_sqrt_pd(a);
#elif defined(__SSE2__)
        return _mm_sqrt_pd(a);
#else
        return lanes_of([a](std::size_t l) { return std::sqrt(a[l]); });
#endif
      }

      /// The lanes where @p m holds as bits 0, 1, ... (one movmskpd: a
      /// test of m[0] and m[1] element by element goes through two
      /// general-purpose registers and a dozen instructions).
      inline int
      lane_bits(const Mask m)
      {
#if defined(__AVX2__)
        return _mm256_movemask_pd(reinterpret_cast<__m256d>(m));
#elif defined(__SSE2__)
        return _mm_movemask_pd(reinterpret_cast<__m128d>(m));
#else
        int bits = 0;
        for (unsigned int l = 0; l < width; ++l)
          bits |= (m[l] != 0 ? 1 : 0) << l;
        return bits;
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
#if defined(__AVX2__)
        return reinterpret_cast<Mask>(
          _mm256_and_pd(reinterpret_cast<__m256d>(a),
                        reinterpret_cast<__m256d>(b)));
#elif defined(__SSE2__)
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
#if defined(__AVX2__)
        return reinterpret_cast<Mask>(
          _mm256_or_pd(reinterpret_cast<__m256d>(a),
                       reinterpret_cast<__m256d>(b)));
#elif defined(__SSE2__)
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
#if defined(__AVX2__)
        return reinterpret_cast<Mask>(
          _mm256_andnot_pd(reinterpret_cast<__m256d>(a),
                           reinterpret_cast<__m256d>(b)));
#elif defined(__SSE2__)
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
        return lane_bits(m) == all_bits;
      }

      /// a where m does not hold, +0 where it does (bitwise: the bits of
      /// the scalar assignment x = 0).
      inline Value
      zero_where(const Mask m, const Value a)
      {
        return reinterpret_cast<Value>(reinterpret_cast<Mask>(a) & ~m);
      }

      /// width adjacent doubles at @p p (any alignment).
      inline Value
      load(const double *p)
      {
        Value v;
        __builtin_memcpy(&v, p, sizeof(v));
        return v;
      }

      /// @p v to width adjacent doubles at @p p (any alignment).
      inline void
      store(double *p, const Value v)
      {
        __builtin_memcpy(p, &v, sizeof(v));
      }

#if defined(__AVX2__)
      /// The 4 x 4 transposition out[k][l] = in[l][k] in registers.
      inline void
      transpose(const Value in[4], Value out[4])
      {
        const Value t0 = __builtin_shuffle(in[0], in[1], Mask{0, 4, 2, 6});
        const Value t1 = __builtin_shuffle(in[0], in[1], Mask{1, 5, 3, 7});
        const Value t2 = __builtin_shuffle(in[2], in[3], Mask{0, 4, 2, 6});
        const Value t3 = __builtin_shuffle(in[2], in[3], Mask{1, 5, 3, 7});
        out[0]         = __builtin_shuffle(t0, t2, Mask{0, 1, 4, 5});
        out[1]         = __builtin_shuffle(t1, t3, Mask{0, 1, 4, 5});
        out[2]         = __builtin_shuffle(t0, t2, Mask{2, 3, 6, 7});
        out[3]         = __builtin_shuffle(t1, t3, Mask{2, 3, 6, 7});
      }
#endif

      /// rows[l][k] += columns[k][l] for the four values k of each lane
      /// l, value by value (a transposition in registers and vector
      /// additions, where a lane at a time takes a load, an addition and
      /// a store per value).
      inline void
      add_transposed(double *const rows[width], const Value columns[4])
      {
#if defined(__AVX2__)
        Value r[4];
        transpose(columns, r);
        for (unsigned int l = 0; l < width; ++l)
          store(rows[l], load(rows[l]) + r[l]);
#elif defined(__SSE2__)
        // (xx, yy) and (xy, zz) of each lane.
        const Mask zero = {0, 2}, one = {1, 3};
        store(rows[0],
              load(rows[0]) + __builtin_shuffle(columns[0], columns[1], zero));
        store(rows[0] + 2,
              load(rows[0] + 2) +
                __builtin_shuffle(columns[2], columns[3], zero));
        store(rows[1],
              load(rows[1]) + __builtin_shuffle(columns[0], columns[1], one));
        store(rows[1] + 2,
              load(rows[1] + 2) +
                __builtin_shuffle(columns[2], columns[3], one));
#else
        for (unsigned int l = 0; l < width; ++l)
          for (unsigned int k = 0; k < 4; ++k)
            rows[l][k] += columns[k][l];
#endif
      }

      /// rows[l][0] += a[l] and rows[l][1] += b[l], value by value.
      inline void
      add_interleaved(double *const rows[width], const Value a, const Value b)
      {
#if defined(__AVX2__)
        using Half = double __attribute__((vector_size(16)));
        // (a0 b0 a2 b2) and (a1 b1 a3 b3): lanes 0 and 2, 1 and 3.
        const Value even = __builtin_shuffle(a, b, Mask{0, 4, 2, 6});
        const Value odd  = __builtin_shuffle(a, b, Mask{1, 5, 3, 7});
        for (unsigned int l = 0; l < width; ++l)
          {
            const Value &v    = l % 2 == 0 ? even : odd;
            const Half   pair = l < 2 ? Half{v[0], v[1]} : Half{v[2], v[3]};
            Half         row;
            __builtin_memcpy(&row, rows[l], sizeof(row));
            row += pair;
            __builtin_memcpy(rows[l], &row, sizeof(row));
          }
#elif defined(__SSE2__)
        store(rows[0], load(rows[0]) + __builtin_shuffle(a, b, Mask{0, 2}));
        store(rows[1], load(rows[1]) + __builtin_shuffle(a, b, Mask{1, 3}));
#else
        for (unsigned int l = 0; l < width; ++l)
          {
            rows[l][0] += a[l];
            rows[l][1] += b[l];
          }
#endif
      }

      /// The columns of width consecutive records of @p n doubles at @p p
      /// (any alignment): out[k][l] = p[n l + k], for n = 3 (a
      /// SymmetricTensor<2, 2>) or 4 (a Tensor<2, 2>). With four lanes
      /// n vector loads and a transposition in registers, where a lane at
      /// a time takes a load and an insertion per value.
      template <unsigned int n>
      inline void
      load_columns(const double *p, Value out[n])
      {
        static_assert(n == 3 || n == 4);
#if defined(__AVX2__)
        const Value a = load(p), b = load(p + 4), c = load(p + 8);
        if constexpr (n == 4)
          {
            const Value rows[4] = {a, b, c, load(p + 12)};
            transpose(rows, out);
          }
        else
          {
            // a = (x0 y0 z0 x1), b = (y1 z1 x2 y2), c = (z2 x3 y3 z3).
            out[0] =
              __builtin_shuffle(__builtin_shuffle(a, b, Mask{0, 3, 6, 7}),
                                c,
                                Mask{0, 1, 2, 5});
            out[1] =
              __builtin_shuffle(__builtin_shuffle(a, b, Mask{1, 4, 7, 4}),
                                c,
                                Mask{0, 1, 2, 6});
            out[2] =
              __builtin_shuffle(__builtin_shuffle(a, b, Mask{2, 5, 2, 5}),
                                c,
                                Mask{0, 1, 4, 7});
          }
#else
        for (unsigned int k = 0; k < n; ++k)
          out[k] = lanes_of([p, k](std::size_t l) { return p[n * l + k]; });
#endif
      }

      /// The inverse of load_columns<3>(): @p x, @p y, @p z to width
      /// consecutive records of three doubles at @p p.
      inline void
      store_columns(double *p, const Value x, const Value y, const Value z)
      {
#if defined(__AVX2__)
        store(p,
              __builtin_shuffle(__builtin_shuffle(x, y, Mask{0, 4, 1, 1}),
                                z,
                                Mask{0, 1, 4, 2}));
        store(p + 4,
              __builtin_shuffle(__builtin_shuffle(y, z, Mask{1, 5, 2, 2}),
                                x,
                                Mask{0, 1, 6, 2}));
        store(p + 8,
              __builtin_shuffle(__builtin_shuffle(z, x, Mask{2, 7, 3, 3}),
                                y,
                                Mask{0, 1, 7, 2}));
#elif defined(__SSE2__)
        // Three packed stores instead of six of single lanes.
        store(p, __builtin_shuffle(x, y, Mask{0, 2}));
        store(p + 2, __builtin_shuffle(z, x, Mask{0, 3}));
        store(p + 4, __builtin_shuffle(y, z, Mask{1, 3}));
#else
        for (unsigned int l = 0; l < width; ++l)
          {
            p[3 * l]     = x[l];
            p[3 * l + 1] = y[l];
            p[3 * l + 2] = z[l];
          }
#endif
      }

    } // namespace Lanes
  }   // namespace Material
} // namespace psmpm

#endif
