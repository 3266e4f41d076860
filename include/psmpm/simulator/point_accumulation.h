// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_point_accumulation_h
#define psmpm_simulator_point_accumulation_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/pair.h>

#include <type_traits>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    namespace internal
    {
      /**
       * Call @p f with the number of functions per cell @p n as a
       * compile-time constant (an std::integral_constant) for the common
       * counts (P1: 3, bilinear: 4, Powell-Sabin and biquadratic: 9), else
       * with @p n itself: the loops over a cell's functions in @p f then
       * have fixed trip counts that the compiler unrolls. The same
       * operations in the same order either way (bit-identical results);
       * the switch is the same branch for every particle of a run.
       */
      template <typename F>
      DEAL_II_ALWAYS_INLINE inline void
      with_functions_per_cell(const unsigned int n, const F &f)
      {
        switch (n)
          {
            case 3:
              return f(std::integral_constant<unsigned int, 3>());
            case 4:
              return f(std::integral_constant<unsigned int, 4>());
            case 9:
              return f(std::integral_constant<unsigned int, 9>());
            default:
              return f(n);
          }
      }

      /**
       * add_point() for @p N functions per cell, known at compile time:
       * fixed trip counts and restrict-qualified arrays let the compiler
       * unroll and vectorise the 81-entry block of a Powell-Sabin cell
       * (with a run-time count GCC keeps the scalar loop for so few
       * iterations). Every entry receives the same single addition as in
       * the generic loop, so the sums are bit-identical. With @p upper
       * only the entries l >= k of the mass block are summed (the caller
       * copies them to the lower triangle, symmetrize_cell_mass()): 45
       * instead of 81 products per Powell-Sabin particle.
       */
      template <int dim, unsigned int N, bool upper>
      DEAL_II_ALWAYS_INLINE inline void
      add_point_fixed(const double                   m,
                      const Tensor<1, dim>          &f,
                      const double                   volume,
                      const SymmetricTensor<2, dim> &stress,
                      const double *__restrict phi,
                      const Tensor<1, dim> *__restrict grad,
                      double *__restrict lumped,
                      double *__restrict mass,
                      Tensor<1, dim> *__restrict rhs)
      {
        if constexpr (dim == 2)
          {
            // deal.II's SymmetricTensor * Tensor reads the stress through
            // its index accessors; here its products and sums, 0 + s00 g0
            // + s01 g1 and 0 + s01 g0 + s11 g1 (the 0 + drops out), in one
            // register for both components, then the same force terms: the
            // same bits in fewer instructions (doc/performance.md, "One pass per step").
            const Pair s0 = {stress[0][0], stress[0][1]};
            const Pair s1 = {stress[0][1], stress[1][1]};
            const Pair f2 = load_pair(f);
            for (unsigned int k = 0; k < N; ++k)
              {
                lumped[k] += m * phi[k];
                const Pair g0 = broadcast(grad[k][0]);
                const Pair g1 = broadcast(grad[k][1]);
                const Pair t  = s0 * g0 + s1 * g1;
                store_pair(rhs[k],
                           load_pair(rhs[k]) + (phi[k] * f2 - volume * t));
              }
          }
        else
          for (unsigned int k = 0; k < N; ++k)
            {
              lumped[k] += m * phi[k];
              rhs[k] += phi[k] * f - volume * (stress * grad[k]);
            }
        if (mass == nullptr)
          return;
        if constexpr (upper)
          {
            // In pairs of columns (two doubles per SSE2 register), from
            // the even column at or left of the diagonal, fully unrolled:
            // a triangular loop with a run-time start kept a loop with
            // remainder branches per row. The pair left of an odd row's
            // diagonal adds to a lower-triangle entry, which
            // symmetrize_cell_mass() overwrites; every upper entry gets
            // the same single addition as before (the same bits).
#pragma GCC unroll 16
            for (unsigned int k = 0; k < N; ++k)
              {
                double *__restrict row = mass + k * N;
                const double mk        = m * phi[k];
                const Pair   mk2       = broadcast(mk);
#pragma GCC unroll 16
                for (unsigned int l = k & ~1u; l + 1 < N; l += 2)
                  store_pair(row + l,
                             load_pair(row + l) + mk2 * load_pair(phi + l));
                if constexpr (N % 2 == 1)
                  row[N - 1] += mk * phi[N - 1];
              }
          }
        else
          for (unsigned int k = 0; k < N; ++k)
            {
              double *__restrict row = mass + k * N;
              const double mk        = m * phi[k];
              for (unsigned int l = 0; l < N; ++l)
                row[l] += mk * phi[l];
            }
      }
    } // namespace internal

    /**
     * One quadrature point's share of the per-cell arrays of a
     * GridSystem (a particle in classical MPM, a Gauss point of a
     * reconstruction): lumped mass m phi_k, consistent mass m phi_k phi_l
     * (if @p mass is not null) and right-hand side phi_k f - V sigma
     * grad phi_k, for the @p n functions of the cell whose arrays start
     * at @p lumped, @p mass (row-major n x n) and @p rhs. Always inline:
     * called once per particle in the hottest loop of a step (GCC kept it
     * out of line, and a shared library reaches an out-of-line template
     * through the PLT: two indirect calls per particle); the common counts
     * (P1: 3, bilinear: 4, Powell-Sabin and biquadratic: 9) go to a
     * compile-time loop, the switch on @p n is the same branch for every
     * particle of a run. With @p upper the mass block's lower triangle may
     * be left incomplete: the caller must call symmetrize_cell_mass() after
     * the last point.
     */
    template <int dim, bool upper = false>
    DEAL_II_ALWAYS_INLINE inline void
    add_point(const unsigned int             n,
              const double                   m,
              const Tensor<1, dim>          &f,
              const double                   volume,
              const SymmetricTensor<2, dim> &stress,
              const double                  *phi,
              const Tensor<1, dim>          *grad,
              double                        *lumped,
              double                        *mass,
              Tensor<1, dim>                *rhs)
    {
      // The lambda is always inline too: called per particle, an
      // out-of-line lambda cost 22 instructions per particle.
      internal::with_functions_per_cell(
        n,
        [&](const auto N) DEAL_II_ALWAYS_INLINE {
          if constexpr (std::is_integral_v<std::decay_t<decltype(N)>>)
            for (unsigned int k = 0; k < N; ++k)
              {
                lumped[k] += m * phi[k];
                rhs[k] += phi[k] * f - volume * (stress * grad[k]);
                if (mass != nullptr)
                  {
                    double      *row = mass + k * N;
                    const double mk  = m * phi[k];
                    for (unsigned int l = upper ? k : 0; l < N; ++l)
                      row[l] += mk * phi[l];
                  }
              }
          else
            internal::add_point_fixed<dim,
                                      std::decay_t<decltype(N)>::value,
                                      upper>(m,
                                             f,
                                             volume,
                                             stress,
                                             phi,
                                             grad,
                                             lumped,
                                             mass,
                                             rhs);
        });
    }

    /**
     * Copy the upper triangle of each of the @p n_blocks row-major
     * @p n x @p n blocks at @p mass to its lower triangle (after
     * add_point<dim, true>). The mass matrix is then exactly symmetric,
     * as the Cholesky and CG solves assume.
     */
    inline void
    symmetrize_cell_mass(double            *mass,
                         const std::size_t  n_blocks,
                         const unsigned int n)
    {
      for (std::size_t c = 0; c < n_blocks; ++c, mass += n * n)
        for (unsigned int k = 1; k < n; ++k)
          for (unsigned int l = 0; l < k; ++l)
            mass[k * n + l] = mass[l * n + k];
    }
  } // namespace Simulator
} // namespace psmpm

#endif
