// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_linear_elastic_h
#define psmpm_material_linear_elastic_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace psmpm
{
  namespace Material
  {
    using namespace dealii;

    /**
     * Hypoelastic linear elasticity in plane strain (thesis eqs. 2.4-2.7,
     * 2.41): the Hooke increment, the volumetric term -d(eps_kk) sigma and
     * the Jaumann spin terms. The out-of-plane stress sigma_zz is carried
     * because it is non-zero in plane strain when nu > 0.
     */
    class LinearElastic
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      double
      bulk_modulus() const
      {
        return youngs_modulus / (3 * (1 - 2 * poisson_ratio));
      }
      double
      shear_modulus() const
      {
        return youngs_modulus / (2 * (1 + poisson_ratio));
      }
      /// p-wave (constrained) modulus K + 4G/3.
      double
      p_wave_modulus() const
      {
        return bulk_modulus() + 4. / 3 * shear_modulus();
      }
      double
      p_wave_speed() const
      {
        return std::sqrt(p_wave_modulus() / density);
      }

      /**
       * Update stress with the velocity gradient increment
       * @p dL = dt grad v (eq. 2.41). Returns the volumetric strain
       * increment d(eps_kk) used for the volume update (eq. 2.44).
       */
      double
      update(const Tensor<2, 2>    &dL,
             SymmetricTensor<2, 2> &stress,
             double                &stress_zz,
             SymmetricTensor<2, 2> &strain) const
      {
        const SymmetricTensor<2, 2> de = symmetrize(dL);
        const double dw = 0.5 * (dL[0][1] - dL[1][0]); // spin increment w_xy
        const double tr = trace(de);
        const double lambda = bulk_modulus() - 2. / 3 * shear_modulus();
        const double two_g  = 2 * shear_modulus();

        SymmetricTensor<2, 2> ds;
        ds[0][0] = lambda * tr + two_g * de[0][0] - tr * stress[0][0] +
                   2 * dw * stress[0][1];
        ds[1][1] = lambda * tr + two_g * de[1][1] - tr * stress[1][1] -
                   2 * dw * stress[0][1];
        ds[0][1] = two_g * de[0][1] - tr * stress[0][1] +
                   dw * (stress[1][1] - stress[0][0]);
        stress_zz += lambda * tr - tr * stress_zz;
        stress += ds;
        strain += de;
        return tr;
      }

      /// Elastic energy per unit volume from the stress (complementary
      /// energy of isotropic Hooke's law, including sigma_zz).
      double
      energy_density(const SymmetricTensor<2, 2> &s, const double szz) const
      {
        const double nu = poisson_ratio;
        return (s[0][0] * s[0][0] + s[1][1] * s[1][1] + szz * szz -
                2 * nu * (s[0][0] * s[1][1] + s[1][1] * szz + szz * s[0][0]) +
                2 * (1 + nu) * s[0][1] * s[0][1]) /
               (2 * youngs_modulus);
      }

      double density        = 1;
      double youngs_modulus = 100;
      double poisson_ratio  = 0;
    };
  } // namespace Material
} // namespace psmpm

#endif
