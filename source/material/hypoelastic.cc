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
      template <int dim>
      std::unique_ptr<Material<dim>>
      create_hypoelastic()
      {
        return std::make_unique<Hypoelastic<dim>>();
      }

      const char *const description =
        "hypoelastic linear elasticity with the Jaumann rate (plane strain "
        "in 2D, uniaxial strain in 1D)";

      const Registration<MaterialRegistry<1>> registration_1d(
        {"hypoelastic", description, create_hypoelastic<1>, {}});
      const Registration<MaterialRegistry<2>> registration_2d(
        {"hypoelastic", description, create_hypoelastic<2>, {}});
    } // namespace



    template <int dim>
    std::string
    Hypoelastic<dim>::name() const
    {
      return "hypoelastic";
    }



    template <int dim>
    std::vector<std::string>
    Hypoelastic<dim>::state_names() const
    {
      if constexpr (dim == 1)
        return {"stress_lateral", "strain_xx"};
      else
        return {"stress_zz", "strain_xx", "strain_yy", "strain_xy"};
    }



    template <int dim>
    void
    Hypoelastic<dim>::update(const unsigned int       n,
                             const Tensor<2, dim>    *dL,
                             SymmetricTensor<2, dim> *stress,
                             double                  *state,
                             double                  *volume_ratio) const
    {
      if constexpr (dim == 1)
        {
          // Closed forms rather than K - 2G/3 and K + 4G/3: with nu = 0
          // they give lambda = 0 and lambda + 2G = E exactly, so that the
          // update is bit for bit the 1D bar of the thesis.
          const double       nu     = this->poisson_ratio;
          const double       E      = this->youngs_modulus;
          const double       scale  = E / ((1 + nu) * (1 - 2 * nu));
          const double       lambda = scale * nu;
          const double       p_wave = scale * (1 - nu);
          const unsigned int stride = this->state_stride();
          for (unsigned int i = 0; i < n; ++i)
            {
              const double de      = dL[i][0][0];
              double      &sigma   = stress[i][0][0];
              double      &lateral = state[stride * i];
              sigma += p_wave * de - de * sigma;
              lateral += lambda * de - de * lateral;
              state[stride * i + 1] += de;
              volume_ratio[i] = 1 + de;
            }
        }
      else
        {
          // Hoisted out of the loop exactly as the old class computed them
          // per call: same operations, same rounding.
          const double lambda =
            this->bulk_modulus() - 2. / 3 * this->shear_modulus();
          const double       two_g  = 2 * this->shear_modulus();
          const unsigned int stride = this->state_stride();
          for (unsigned int i = 0; i < n; ++i)
            {
              this->request_ahead(n, stress, state, stride, i);
              const SymmetricTensor<2, 2> de = symmetrize(dL[i]);
              const double dw = 0.5 * (dL[i][0][1] - dL[i][1][0]); // w_xy
              const double tr = trace(de);
              SymmetricTensor<2, 2> &s         = stress[i];
              double *const          block     = state + stride * i;
              double                &stress_zz = block[0];

              SymmetricTensor<2, 2> ds;
              ds[0][0] = lambda * tr + two_g * de[0][0] - tr * s[0][0] +
                         2 * dw * s[0][1];
              ds[1][1] = lambda * tr + two_g * de[1][1] - tr * s[1][1] -
                         2 * dw * s[0][1];
              ds[0][1] =
                two_g * de[0][1] - tr * s[0][1] + dw * (s[1][1] - s[0][0]);
              stress_zz += lambda * tr - tr * stress_zz;
              s += ds;
              block[1] += de[0][0];
              block[2] += de[1][1];
              block[3] += de[0][1];
              volume_ratio[i] = 1 + tr;
            }
        }
    }



    template <int dim>
    void
    Hypoelastic<dim>::energy_density(const unsigned int             n,
                                     const SymmetricTensor<2, dim> *stress,
                                     const double                  *state,
                                     double *energy) const
    {
      const double       nu     = this->poisson_ratio;
      const double       E      = this->youngs_modulus;
      const unsigned int stride = this->state_stride();
      for (unsigned int i = 0; i < n; ++i)
        {
          const SymmetricTensor<2, dim> &s = stress[i];
          if constexpr (dim == 1)
            {
              // Normal stresses (sigma_xx, lateral, lateral), no shear.
              const double sxx = s[0][0];
              const double lat = state[stride * i];
              energy[i]        = (sxx * sxx + lat * lat + lat * lat -
                           2 * nu * (sxx * lat + lat * lat + lat * sxx)) /
                          (2 * E);
            }
          else
            {
              const double szz = state[stride * i];
              energy[i] =
                (s[0][0] * s[0][0] + s[1][1] * s[1][1] + szz * szz -
                 2 * nu * (s[0][0] * s[1][1] + s[1][1] * szz + szz * s[0][0]) +
                 2 * (1 + nu) * s[0][1] * s[0][1]) /
                (2 * E);
            }
        }
    }



    template class Hypoelastic<1>;
    template class Hypoelastic<2>;
  } // namespace Material
} // namespace psmpm
