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

    /**
     * One quadrature point's share of the per-cell arrays of a
     * GridSystem (a particle in classical MPM, a Gauss point of a
     * reconstruction): lumped mass m phi_k, consistent mass m phi_k phi_l
     * (if @p mass is not null) and right-hand side phi_k f - V sigma
     * grad phi_k, for the @p n functions of the cell whose arrays start
     * at @p lumped, @p mass (row-major n x n) and @p rhs. Inline: called
     * once per particle in the hottest loop of a step.
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
