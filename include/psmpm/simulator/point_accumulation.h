// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_point_accumulation_h
#define psmpm_simulator_point_accumulation_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    namespace internal
    {
      /**
       * add_point() for @p N functions per cell, known at compile time:
       * fixed trip counts and restrict-qualified arrays let the compiler
       * unroll and vectorise the 81-entry block of a Powell-Sabin cell
       * (with a run-time count GCC keeps the scalar loop for so few
       * iterations). Every entry receives the same single addition as in
       * the generic loop, so the sums are bit-identical.
       */
      template <int dim, unsigned int N>
      inline void
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
        for (unsigned int k = 0; k < N; ++k)
          {
            lumped[k] += m * phi[k];
            rhs[k] += phi[k] * f - volume * (stress * grad[k]);
          }
        if (mass != nullptr)
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
     * at @p lumped, @p mass (row-major n x n) and @p rhs. Inline: called
     * once per particle in the hottest loop of a step; the common counts
     * (P1: 3, bilinear: 4, Powell-Sabin and biquadratic: 9) go to a
     * compile-time loop, the switch on @p n is the same branch for every
     * particle of a run.
     */
    template <int dim>
    inline void
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
      switch (n)
        {
          case 3:
            internal::add_point_fixed<dim, 3>(m,
                                              f,
                                              volume,
                                              stress,
                                              phi,
                                              grad,
                                              lumped,
                                              mass,
                                              rhs);
            return;
          case 4:
            internal::add_point_fixed<dim, 4>(m,
                                              f,
                                              volume,
                                              stress,
                                              phi,
                                              grad,
                                              lumped,
                                              mass,
                                              rhs);
            return;
          case 9:
            internal::add_point_fixed<dim, 9>(m,
                                              f,
                                              volume,
                                              stress,
                                              phi,
                                              grad,
                                              lumped,
                                              mass,
                                              rhs);
            return;
          default:
            break;
        }
      for (unsigned int k = 0; k < n; ++k)
        {
          lumped[k] += m * phi[k];
          rhs[k] += phi[k] * f - volume * (stress * grad[k]);
          if (mass != nullptr)
            {
              double      *row = mass + k * n;
              const double mk  = m * phi[k];
              for (unsigned int l = 0; l < n; ++l)
                row[l] += mk * phi[l];
            }
        }
    }
  } // namespace Simulator
} // namespace psmpm

#endif
