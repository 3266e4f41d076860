// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/material/hypoelastic.h>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      /**
       * Small-strain linear elasticity, registered as "linear elastic":
       * sigma += lambda tr(de) I + 2 G de with de = sym(dt grad v), no
       * volumetric or spin terms (in 1D sigma += E de for nu = 0). The
       * law of the linear-elastic bar of Wobbes et al. (2019) and of every
       * small-deformation analytic reference; it differs from
       * "hypoelastic" by terms of order de sigma, which matter at the
       * fourth digit of the bar's 20-step stress error (doc/otm.md).
       * State, energy and wave speed are those of Hypoelastic.
       */
      template <int dim>
      class LinearElastic : public Hypoelastic<dim>
      {
      public:
        std::string
        name() const override
        {
          return "linear elastic";
        }

        void
        update(const unsigned int       n,
               const Tensor<2, dim>    *dL,
               SymmetricTensor<2, dim> *stress,
               double                  *state,
               double                  *volume_ratio) const override
        {
          const double       nu     = this->poisson_ratio;
          const double       E      = this->youngs_modulus;
          const double       scale  = E / ((1 + nu) * (1 - 2 * nu));
          const double       lambda = scale * nu;
          const double       two_g  = E / (1 + nu);
          const unsigned int stride = this->state_stride();
          for (unsigned int i = 0; i < n; ++i)
            {
              this->request_ahead(n, stress, state, stride, i);
              const SymmetricTensor<2, dim> de = symmetrize(dL[i]);
              const double                  tr = trace(de);
              if constexpr (dim == 1)
                {
                  stress[i][0][0] += (lambda + two_g) * de[0][0];
                  state[stride * i] += lambda * tr; // lateral stresses
                  state[stride * i + 1] += de[0][0];
                }
              else
                {
                  stress[i] +=
                    lambda * tr * unit_symmetric_tensor<dim>() + two_g * de;
                  double *const block = state + stride * i;
                  block[0] += lambda * tr; // sigma_zz (plane strain)
                  block[1] += de[0][0];
                  block[2] += de[1][1];
                  block[3] += de[0][1];
                }
              volume_ratio[i] = 1 + tr;
            }
        }
      };

      template <int dim>
      std::unique_ptr<Material<dim>>
      create_linear_elastic()
      {
        return std::make_unique<LinearElastic<dim>>();
      }

      const char *const description =
        "small-strain linear elasticity, sigma += lambda tr(de) I + 2G de "
        "(no rate terms; plane strain in 2D, uniaxial strain in 1D)";

      const Registration<MaterialRegistry<1>> registration_1d(
        {"linear elastic", description, create_linear_elastic<1>, {}});
      const Registration<MaterialRegistry<2>> registration_2d(
        {"linear elastic", description, create_linear_elastic<2>, {}});
    } // namespace
  }   // namespace Material
} // namespace psmpm
