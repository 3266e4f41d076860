// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_neo_hookean_h
#define psmpm_material_neo_hookean_h

#include <psmpm/material/material.h>

namespace psmpm
{
  namespace Material
  {
    /**
     * Compressible neo-Hookean hyperelasticity, registered as
     * "neo-hookean":
     *   W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2,
     *   sigma = (mu (b - I) + lambda ln J I) / J,
     * with mu = G and lambda the Lame constant of Young's modulus and
     * Poisson's ratio, b = F F^T, and the 3D deformation gradient extended
     * by ones on the diagonal (plane strain in 2D: F33 = 1; uniaxial
     * strain in 1D: F22 = F33 = 1). Only the in-plane part of sigma is
     * returned; the out-of-plane stresses follow from F when needed.
     *
     * State: the deformation gradient F, row by row (F_ij = dx_i/dX_j):
     * {"F_xx", "F_xy", "F_yx", "F_yy"} in 2D, {"F_xx"} in 1D; initialize()
     * sets the identity.
     *
     * F is updated with the midpoint (Cayley) increment
     *   dF = (I - dL/2)^{-1} (I + dL/2),  F <- dF F,
     * which is second-order accurate and exactly orthogonal for a skew dL,
     * so a rigid rotation stays stress-free up to round-off (no objective
     * rate needed). volume_ratio = det(dF). A step that is not invertible
     * (det(I - dL/2) <= 0) or inverts the material (det(dF) <= 0) leaves F
     * unchanged and writes NaN into the stress (and into volume_ratio when
     * det(dF) is undefined), so that the solver's monitors stop the run as
     * non-finite or non-positive volume; update() never throws.
     */
    template <int dim>
    class NeoHookean : public Material<dim>
    {
    public:
      std::string
      name() const override;

      std::vector<std::string>
      state_names() const override;

      /// F = I.
      void
      initialize(const unsigned int n, double *state) const override;

      void
      update(const unsigned int       n,
             const Tensor<2, dim>    *dL,
             SymmetricTensor<2, dim> *stress,
             double                  *state,
             double                  *volume_ratio) const override;

      /// W(F) / J: the stored energy per unit current volume (the solver
      /// multiplies by the current particle volume V = J V0).
      void
      energy_density(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state,
                     double                        *energy) const override;

      /**
       * Upper estimate of the largest wave speed at the current F. The
       * acoustic tensor of this law, per unit reference density rho0, has
       * the longitudinal eigenvalue lambda (1 - ln J) + mu (1 + b_nn) and
       * the transverse one mu b_nn (n the direction of propagation, in the
       * plane in 2D, x in 1D, since plane and uniaxial strain have no other
       * motion); with b_nn <= b_max, the largest eigenvalue of the in-plane
       * b, this gives
       *   c^2 = max(lambda (1 - ln J) + mu (1 + b_max), mu b_max) / rho0,
       * exact in 1D, and the p-wave speed sqrt((lambda + 2 mu) / rho0) at
       * F = I.
       * (Unlike sqrt((lambda + 2 mu) / rho_current), it grows under
       * compression, as the stiffness of the law does.)
       */
      double
      wave_speed(const SymmetricTensor<2, dim> &stress,
                 const double                  *state) const override;

      double
      max_wave_speed(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state) const override;
    };
  } // namespace Material
} // namespace psmpm

#endif
