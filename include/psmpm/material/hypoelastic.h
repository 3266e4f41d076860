// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_hypoelastic_h
#define psmpm_material_hypoelastic_h

#include <psmpm/material/material.h>

namespace psmpm
{
  namespace Material
  {
    /**
     * Hypoelastic linear elasticity (thesis eqs. 2.4-2.7, 2.41), registered
     * as "hypoelastic": the Hooke increment, the volumetric term
     * -d(eps_kk) sigma and the Jaumann spin terms.
     *
     * 2D (plane strain): the arithmetic is the old LinearElastic::update,
     * operation by operation, so that results agree bit for bit. The
     * out-of-plane stress sigma_zz is carried because it is non-zero in
     * plane strain when nu > 0. State: {"stress_zz", "strain_xx",
     * "strain_yy", "strain_xy"} (tensor, not engineering, shear strain).
     *
     * 1D (uniaxial strain, the lateral strains are zero): d(sigma) =
     * (lambda + 2G) de - de sigma, no spin; the two equal lateral stresses
     * sigma_yy = sigma_zz are carried as "stress_lateral" with the update
     * of sigma_zz in 2D. State: {"stress_lateral", "strain_xx"}. With
     * nu = 0 this is exactly the 1D bar sigma += E de - de sigma.
     *
     * In both, volume_ratio = 1 + d(eps_kk) (eq. 2.44).
     */
    template <int dim>
    class Hypoelastic : public Material<dim>
    {
    public:
      std::string
      name() const override;

      std::vector<std::string>
      state_names() const override;

      void
      update(const unsigned int       n,
             const Tensor<2, dim>    *dL,
             SymmetricTensor<2, dim> *stress,
             double                  *state,
             double                  *volume_ratio) const override;

      bool
      accepts_initial_stress() const override
      {
        return true;
      }

      /// The out-of-plane (2D) or lateral (1D) stress into the state's
      /// first column; the strains stay zero (the initial stress is
      /// the reference state).
      void
      set_initial_stress(const unsigned int             n,
                         const SymmetricTensor<2, dim> *stress,
                         const double                  *out_of_plane,
                         double                        *state) const override
      {
        (void)stress;
        const unsigned int s = this->state_stride();
        for (unsigned int i = 0; i < n; ++i)
          state[i * s] = out_of_plane[i];
      }

      /// Complementary energy of isotropic Hooke's law with all three
      /// normal stresses (sigma_zz or the lateral stresses included).
      void
      energy_density(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state,
                     double                        *energy) const override;

      /// Small-strain law: the p-wave speed, whatever the state.
      double
      max_wave_speed(const unsigned int,
                     const SymmetricTensor<2, dim> *,
                     const double *) const override
      {
        return this->p_wave_speed();
      }
    };
  } // namespace Material
} // namespace psmpm

#endif
