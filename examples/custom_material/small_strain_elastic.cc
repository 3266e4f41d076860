// ---------------------------------------------------------------------
// custom_material: a material model defined outside psmpm.
// ---------------------------------------------------------------------
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/registry.h>
#include <psmpm/material/material.h>

#include <memory>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  /**
   * Small-strain linear elasticity in plane strain: sigma = lambda tr(eps)
   * I + 2 G eps with eps the sum of the strain increments. Unlike psmpm's
   * hypoelastic model it has no Jaumann (rotation) and no volumetric
   * (-d(eps_kk) sigma) terms, so it is only right for small deformation,
   * which is what the vibrating bar of bar.prm is.
   */
  class SmallStrainElastic : public psmpm::Material::Material<2>
  {
  public:
    std::string
    name() const override
    {
      return "small-strain elastic";
    }

    std::vector<std::string>
    state_names() const override
    {
      return {"strain_xx", "strain_yy", "strain_xy"};
    }

    void
    update(const unsigned int     n,
           const Tensor<2, 2>    *dL,
           SymmetricTensor<2, 2> *stress,
           double                *state,
           double                *volume_ratio) const override
    {
      const double lambda = lame_lambda();
      const double two_g  = 2 * shear_modulus();
      // A particle's state block starts at state + i * state_stride(), not
      // at state + 3 * i: in a scene whose bodies use several models, each
      // model owns its own columns of a wider shared array (MaterialSet).
      const unsigned int stride = state_stride();
      for (unsigned int i = 0; i < n; ++i)
        {
          const SymmetricTensor<2, 2> de = symmetrize(dL[i]);
          const double                tr = trace(de);
          stress[i] += lambda * tr * unit_symmetric_tensor<2>() + two_g * de;
          double *eps = state + stride * i;
          eps[0] += de[0][0];
          eps[1] += de[1][1];
          eps[2] += de[0][1];
          volume_ratio[i] = 1 + tr;
        }
    }

    /// W = 1/2 sigma : eps. In plane strain sigma_zz = lambda tr(eps) is
    /// not zero, but eps_zz is, so it adds nothing: W = lambda/2 tr(eps)^2
    /// + G eps : eps, computed from the strain so that an initial stress
    /// (there is none here) would not count as stored energy.
    void
    energy_density(const unsigned int n,
                   const SymmetricTensor<2, 2> * /*stress*/,
                   const double *state,
                   double       *energy) const override
    {
      const unsigned int stride = state_stride();
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *eps = state + stride * i;
          const double  tr  = eps[0] + eps[1];
          const double  eps_eps =
            eps[0] * eps[0] + eps[1] * eps[1] + 2 * eps[2] * eps[2];
          energy[i] = 0.5 * lame_lambda() * tr * tr + shear_modulus() * eps_eps;
        }
    }
  };

  // The one line that makes "Material/Model = small-strain elastic" valid.
  static psmpm::Registration<psmpm::Material::MaterialRegistry<2>>
    reg({"small-strain elastic",
         "plane-strain linear elasticity without rotation and volume terms "
         "(examples/custom_material)",
         [] { return std::make_unique<SmallStrainElastic>(); },
         nullptr});
} // namespace
