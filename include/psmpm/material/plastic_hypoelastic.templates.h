// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_plastic_hypoelastic_templates_h
#define psmpm_material_plastic_hypoelastic_templates_h

#include <psmpm/material/plastic_hypoelastic.h>

#include <algorithm>

namespace psmpm
{
  namespace Material
  {
    template <int dim>
    template <typename Return>
    void
    PlasticHypoelastic<dim>::finish_return(const Return                &ret,
                                           const std::array<double, 3> &trial,
                                           std::array<double, 3>       &sigma,
                                           double                      *block,
                                           std::array<double, 3> &plastic) const
    {
      const double inv_E = 1 / this->youngs_modulus;
      const double nu    = this->poisson_ratio;
      // The plastic strain of a stress correction: C^-1 (trial - sigma).
      const auto correction_strain = [&](const std::array<double, 3> &s) {
        const std::array<double, 3> d = {
          {trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]}};
        return std::array<double, 3>{{(d[0] - nu * (d[1] + d[2])) * inv_E,
                                      (d[1] - nu * (d[0] + d[2])) * inv_E,
                                      (d[2] - nu * (d[0] + d[1])) * inv_E}};
      };
      const auto equivalent = [](const std::array<double, 3> &e) {
        const double m = (e[0] + e[1] + e[2]) / 3;
        return std::sqrt(2. / 3 *
                         ((e[0] - m) * (e[0] - m) + (e[1] - m) * (e[1] - m) +
                          (e[2] - m) * (e[2] - m)));
      };

      plastic                = correction_strain(sigma);
      const double kappa_old = block[kappa_column];
      double       kappa     = kappa_old + equivalent(plastic);
      if (softens())
        // Implicit in kappa: each iterate is an exact return for the
        // strength at its kappa; with linear softening the map is a
        // contraction for softening moduli small against G (30 iterates
        // reach round-off in the scenes of doc/geomechanics.md).
        for (unsigned int it = 0; it < 30; ++it)
          {
            Strength s = strength(kappa);
            ret.prepare(s);
            sigma = trial;
            if (!ret(s, sigma))
              {
                plastic = {{0, 0, 0}};
                kappa   = kappa_old;
                break;
              }
            plastic                = correction_strain(sigma);
            const double kappa_new = kappa_old + equivalent(plastic);
            const bool   converged =
              std::abs(kappa_new - kappa) <= 1e-13 * (1 + kappa_new);
            kappa = kappa_new;
            if (converged)
              break;
          }
      block[kappa_column] = kappa;
    }



    template <int dim>
    template <typename Return>
    void
    PlasticHypoelastic<dim>::update_with(const Return            &ret,
                                         const unsigned int       n,
                                         const Tensor<2, dim>    *dL,
                                         SymmetricTensor<2, dim> *stress,
                                         double                  *state,
                                         double *volume_ratio) const
    {
      const double       lambda = this->lame_lambda();
      const double       two_g  = 2 * this->shear_modulus();
      const double       rho0   = this->density;
      const unsigned int stride = this->state_stride();
      Strength           base   = strength(0);
      ret.prepare(base);
      for (unsigned int i = 0; i < n; ++i)
        {
          this->request_ahead(n, stress, state, stride, i);
          double *const block = state + stride * i;
          // A softened particle's own strength; the batch's otherwise
          // (no copy per particle).
          Strength        softened;
          const Strength *strength_i = &base;
          if (softens() && block[kappa_column] > 0)
            {
              softened = strength(block[kappa_column]);
              ret.prepare(softened);
              strength_i = &softened;
            }
          const Strength &s = *strength_i;

          double &J = block[ratio_column];
          if constexpr (dim == 1)
            {
              const double de = dL[i][0][0];
              // Uniaxial strain: the principal stresses are the axial one
              // and the two equal lateral ones; nothing rotates.
              std::array<double, 3> sigma = {
                {stress[i][0][0] + (lambda + two_g) * de,
                 block[out_of_plane] + lambda * de,
                 block[out_of_plane] + lambda * de}};
              J *= 1 + de;
              volume_ratio[i]                   = 1 + de;
              const std::array<double, 3> trial = sigma;
              if (!ret.inside(s, sigma) && ret(s, sigma))
                {
                  std::array<double, 3> ep;
                  finish_return(ret, trial, sigma, block, ep);
                  block[plastic_xx] += ep[0];
                  block[2] += 0.5 * (ep[1] + ep[2]);
                  block[work_column] +=
                    J *
                    (sigma[0] * ep[0] + sigma[1] * ep[1] + sigma[2] * ep[2]) /
                    rho0;
                }
              stress[i][0][0]     = sigma[0];
              block[out_of_plane] = 0.5 * (sigma[1] + sigma[2]);
            }
          else
            {
              const SymmetricTensor<2, 2> de = symmetrize(dL[i]);
              const double                tr = trace(de);
              // Hughes-Winget rotation of the spin increment w = W_xy.
              const double w = 0.5 * (dL[i][0][1] - dL[i][1][0]);
              const double u = 0.25 * w * w;
              // 1 / (1 + u): below u = 1e-6 the series 1 - u + u^2 is the
              // same to round-off (c^2 + s^2 = 1 + 2 u^3) and saves the
              // division in every particle's update.
              const double           q = u < 1e-6 ? 1 - u + u * u : 1 / (1 + u);
              const double           c = (1 - u) * q;
              const double           sn = w * q;
              SymmetricTensor<2, 2> &st = stress[i];
              const double sxx = st[0][0], syy = st[1][1], sxy = st[0][1];
              const double cc = c * c, ss = sn * sn, cs = c * sn;
              double txx = cc * sxx + 2 * cs * sxy + ss * syy + lambda * tr +
                           two_g * de[0][0];
              double tyy = ss * sxx - 2 * cs * sxy + cc * syy + lambda * tr +
                           two_g * de[1][1];
              double txy =
                -cs * sxx + (cc - ss) * sxy + cs * syy + two_g * de[0][1];
              double tzz = block[out_of_plane] + lambda * tr;
              J *= 1 + tr;
              volume_ratio[i] = 1 + tr;

              const double centre  = 0.5 * (txx + tyy);
              const double half    = 0.5 * (txx - tyy);
              const double radius2 = half * half + txy * txy;
              // The elastic test inline and without the square root (most
              // particles, most steps); the return out of line.
              if (ret.inside_plane(s, centre, radius2, tzz))
                {
                  st[0][0]            = txx;
                  st[1][1]            = tyy;
                  st[0][1]            = txy;
                  block[out_of_plane] = tzz;
                  continue;
                }
              const double                radius = std::sqrt(radius2);
              const std::array<double, 3> trial  = {
                 {centre + radius, centre - radius, tzz}};
              std::array<double, 3> sigma = trial;
              if (ret(s, sigma))
                {
                  std::array<double, 3> ep;
                  finish_return(ret, trial, sigma, block, ep);
                  const double inv  = radius > 0 ? 1 / radius : 0;
                  const double cos2 = radius > 0 ? half * inv : 1;
                  const double sin2 = txy * inv;
                  const double a    = 0.5 * (sigma[0] + sigma[1]),
                               b    = 0.5 * (sigma[0] - sigma[1]);
                  txx               = a + b * cos2;
                  tyy               = a - b * cos2;
                  txy               = b * sin2;
                  tzz               = sigma[2];
                  const double ea   = 0.5 * (ep[0] + ep[1]),
                               eb   = 0.5 * (ep[0] - ep[1]);
                  block[plastic_xx] += ea + eb * cos2;
                  block[2] += ea - eb * cos2;
                  block[3] += eb * sin2;
                  block[4] += ep[2];
                  block[work_column] +=
                    J *
                    (sigma[0] * ep[0] + sigma[1] * ep[1] + sigma[2] * ep[2]) /
                    rho0;
                }
              st[0][0]            = txx;
              st[1][1]            = tyy;
              st[0][1]            = txy;
              block[out_of_plane] = tzz;
            }
        }
    }
  } // namespace Material
} // namespace psmpm

#endif
