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
                                           const BatchConstants        &c,
                                           const std::array<double, 3> &trial,
                                           std::array<double, 3>       &sigma,
                                           double                      *block,
                                           std::array<double, 3> &plastic) const
    {
      const double inv_E = c.inv_e;
      const double nu    = c.nu;
      // The plastic strain of a stress correction: C^-1 (trial - sigma).
      const auto correction_strain = [&](const std::array<double, 3> &s) {
        const std::array<double, 3> d = {
          {trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]}};
        return std::array<double, 3>{{(d[0] - nu * (d[1] + d[2])) * inv_E,
                                      (d[1] - nu * (d[0] + d[2])) * inv_E,
                                      (d[2] - nu * (d[0] + d[1])) * inv_E}};
      };
      const auto equivalent = [](const std::array<double, 3> &e) {
        // A product, not a division: this is on the latency chain of a
        // yielding particle's update.
        const double m = (e[0] + e[1] + e[2]) * (1. / 3);
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
    DEAL_II_ALWAYS_INLINE inline const typename PlasticHypoelastic<
      dim>::Strength &
    PlasticHypoelastic<dim>::particle_strength(const Return   &ret,
                                               const Strength &base,
                                               const double   *block,
                                               Strength       &softened) const
    {
      if (softens() && block[kappa_column] > 0)
        {
          softened = strength(block[kappa_column]);
          ret.prepare(softened);
          return softened;
        }
      return base;
    }



    template <int dim>
    template <typename Return>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::update_uniaxial(const Return         &ret,
                                             const Strength       &s,
                                             const BatchConstants &c,
                                             const double          de,
                                             double               &stress_xx,
                                             double               *block,
                                             double &volume_ratio) const
    {
      // Uniaxial strain: the principal stresses are the axial one and the
      // two equal lateral ones; nothing rotates.
      std::array<double, 3> sigma = {{stress_xx + (c.lambda + c.two_g) * de,
                                      block[out_of_plane] + c.lambda * de,
                                      block[out_of_plane] + c.lambda * de}};
      double               &J     = block[ratio_column];
      J *= 1 + de;
      volume_ratio = 1 + de;
      // Disconnected grains: as in update_plane_strain().
      if (J > c.disconnected_ratio)
        {
          stress_xx           = 0;
          block[out_of_plane] = 0;
          return;
        }
      const std::array<double, 3> trial = sigma;
      if (!ret.inside(s, sigma) && ret(s, sigma))
        {
          std::array<double, 3> ep;
          finish_return(ret, c, trial, sigma, block, ep);
          block[plastic_xx] += ep[0];
          block[2] += 0.5 * (ep[1] + ep[2]);
          block[work_column] +=
            J * (sigma[0] * ep[0] + sigma[1] * ep[1] + sigma[2] * ep[2]) /
            c.rho0;
        }
      stress_xx           = sigma[0];
      block[out_of_plane] = 0.5 * (sigma[1] + sigma[2]);
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::plane_strain_trial(const BatchConstants        &c,
                                                const Tensor<2, 2>          &dL,
                                                const SymmetricTensor<2, 2> &st,
                                                const double           szz,
                                                double                &tr,
                                                std::array<double, 4> &t)
    {
      const SymmetricTensor<2, 2> de = symmetrize(dL);
      tr                             = trace(de);
      // Hughes-Winget rotation of the spin increment w = W_xy.
      const double w = 0.5 * (dL[0][1] - dL[1][0]);
      const double u = 0.25 * w * w;
      // 1 / (1 + u): below u = 1e-6 the series 1 - u + u^2 is the same to
      // round-off (c^2 + s^2 = 1 + 2 u^3) and saves the division in every
      // particle's update.
      const double q   = u < 1e-6 ? 1 - u + u * u : 1 / (1 + u);
      const double cr  = (1 - u) * q;
      const double sn  = w * q;
      const double sxx = st[0][0], syy = st[1][1], sxy = st[0][1];
      const double cc = cr * cr, ss = sn * sn, cs = cr * sn;
      t[0] =
        cc * sxx + 2 * cs * sxy + ss * syy + c.lambda * tr + c.two_g * de[0][0];
      t[1] =
        ss * sxx - 2 * cs * sxy + cc * syy + c.lambda * tr + c.two_g * de[1][1];
      t[2] = -cs * sxx + (cc - ss) * sxy + cs * syy + c.two_g * de[0][1];
      t[3] = szz + c.lambda * tr;
    }



    template <int dim>
    template <typename Return>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::plane_strain_return(
      const Return                &ret,
      const BatchConstants        &c,
      const std::array<double, 3> &trial,
      std::array<double, 3>       &sigma,
      const double                 half,
      const double                 radius,
      double                      *block,
      std::array<double, 4>       &t) const
    {
      std::array<double, 3> ep;
      finish_return(ret, c, trial, sigma, block, ep);
      const double inv  = radius > 0 ? 1 / radius : 0;
      const double cos2 = radius > 0 ? half * inv : 1;
      const double sin2 = t[2] * inv;
      const double a    = 0.5 * (sigma[0] + sigma[1]),
                   b    = 0.5 * (sigma[0] - sigma[1]);
      t[0]              = a + b * cos2;
      t[1]              = a - b * cos2;
      t[2]              = b * sin2;
      t[3]              = sigma[2];
      const double ea = 0.5 * (ep[0] + ep[1]), eb = 0.5 * (ep[0] - ep[1]);
      block[plastic_xx] += ea + eb * cos2;
      block[2] += ea - eb * cos2;
      block[3] += eb * sin2;
      block[4] += ep[2];
      block[work_column] +=
        block[ratio_column] *
        (sigma[0] * ep[0] + sigma[1] * ep[1] + sigma[2] * ep[2]) / c.rho0;
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::add_plastic_increment(
      const BatchConstants        &c,
      const std::array<double, 4> &t,
      const std::array<double, 4> &ep,
      const double                 d_kappa,
      double                      *block)
    {
      block[plastic_xx] += ep[0];
      block[2] += ep[1];
      block[3] += ep[2];
      block[4] += ep[3];
      block[kappa_column] += d_kappa;
      block[work_column] +=
        block[ratio_column] *
        (t[0] * ep[0] + t[1] * ep[1] + 2 * t[2] * ep[2] + t[3] * ep[3]) *
        c.inv_rho0;
    }



    template <int dim>
    template <typename Return>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::update_plane_strain(const Return          &ret,
                                                 const Strength        &s,
                                                 const BatchConstants  &c,
                                                 const Tensor<2, 2>    &dL,
                                                 SymmetricTensor<2, 2> &st,
                                                 double                *block,
                                                 double &volume_ratio) const
    {
      double                tr;
      std::array<double, 4> t;
      plane_strain_trial(c, dL, st, block[out_of_plane], tr, t);
      block[ratio_column] *= 1 + tr;
      volume_ratio = 1 + tr;
      // Grains out of contact (J above the disconnected ratio) carry no
      // stress and neither yield nor dissipate until compacted again;
      // without this, a dilated particle that is compressed again takes
      // the dense material's stress, and its force J V0 sigma grad(phi)
      // acts on a stiffness J times the dense one (a local Courant
      // number sqrt(J) times the step's).
      if (block[ratio_column] > c.disconnected_ratio)
        {
          st                  = SymmetricTensor<2, 2>();
          block[out_of_plane] = 0;
          return;
        }

      const double centre  = 0.5 * (t[0] + t[1]);
      const double half    = 0.5 * (t[0] - t[1]);
      const double radius2 = half * half + t[2] * t[2];
      // A model whose return keeps the deviator's direction maps t
      // itself: no eigenvalues, no rotation back, the plastic strain in
      // closed form (with softening, the iteration on kappa of
      // finish_return() in the principal frame below).
      bool in_plane = false;
      if constexpr (Return::returns_in_plane)
        in_plane = !softens();
      // The Return's elastic test inline (most particles, most steps;
      // from the circle's squared radius, so that a test without the
      // square root needs none); the return out of line.
      if (ret.inside_plane(s, centre, radius2, t[3]))
        ;
      else if (in_plane)
        {
          if constexpr (Return::returns_in_plane)
            {
              std::array<double, 4> ep;
              double                d_kappa;
              if (ret.in_plane(s, t, ep, d_kappa))
                add_plastic_increment(c, t, ep, d_kappa, block);
            }
        }
      else
        {
          const double                radius = std::sqrt(radius2);
          const std::array<double, 3> trial  = {
             {centre + radius, centre - radius, t[3]}};
          std::array<double, 3> sigma = trial;
          if (ret(s, sigma))
            plane_strain_return(ret, c, trial, sigma, half, radius, block, t);
        }
      st[0][0]            = t[0];
      st[1][1]            = t[1];
      st[0][1]            = t[2];
      block[out_of_plane] = t[3];
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::plane_strain_trial_pair(
      const BatchConstants        &c,
      const Tensor<2, 2>          *dL,
      const SymmetricTensor<2, 2> *st,
      const Lanes::Value           szz,
      Lanes::Value                &tr,
      Lanes::Value                 t[4])
    {
      using namespace Lanes;
      // plane_strain_trial(), operation by operation.
      // Tensor<2, 2> stores its rows one after the other.
      static_assert(sizeof(Tensor<2, 2>) == 4 * sizeof(double));
      Value d[4];
      load_columns<4>(&dL[0][0][0], d);
      const Value de00 = d[0], l01 = d[1], l10 = d[2], de11 = d[3];
      const Value de01 = (l01 + l10) * 0.5;
      tr               = de00 + de11;
      const Value w    = 0.5 * (l01 - l10);
      const Value u    = 0.25 * w * w;
      // The division only where a lane needs it: select() waits for both
      // operands, and a division's latency would be on every pair's
      // chain.
      const Mask  small  = u < 1e-6;
      const Value series = 1 - u + u * u;
      const Value q  = all(small) ? series : select(small, series, 1 / (1 + u));
      const Value cr = (1 - u) * q;
      const Value sn = w * q;
      // SymmetricTensor<2, 2> stores xx, yy, xy.
      static_assert(sizeof(SymmetricTensor<2, 2>) == 3 * sizeof(double));
      Value s[3];
      load_columns<3>(reinterpret_cast<const double *>(st), s);
      const Value sxx = s[0], syy = s[1], sxy = s[2];
      const Value cc = cr * cr, ss = sn * sn, cs = cr * sn;
      t[0] =
        cc * sxx + 2. * cs * sxy + ss * syy + c.lambda * tr + c.two_g * de00;
      t[1] =
        ss * sxx - 2. * cs * sxy + cc * syy + c.lambda * tr + c.two_g * de11;
      t[2] = -cs * sxx + (cc - ss) * sxy + cs * syy + c.two_g * de01;
      t[3] = szz + c.lambda * tr;
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::add_plastic_increment_pair(
      const BatchConstants &c,
      const Lanes::Value    J,
      const Lanes::Value    t[4],
      const Lanes::Value    ep[4],
      const Lanes::Value    d_kappa,
      double *const         block[Lanes::width])
    {
      using namespace Lanes;
      static_assert(plastic_xx == 1 && work_column == kappa_column + 1);
      const Value dot =
        t[0] * ep[0] + t[1] * ep[1] + 2. * t[2] * ep[2] + t[3] * ep[3];
      double *rows[width];
      for (unsigned int l = 0; l < width; ++l)
        rows[l] = block[l] + plastic_xx;
      add_transposed(rows, ep);
      for (unsigned int l = 0; l < width; ++l)
        rows[l] = block[l] + kappa_column;
      add_interleaved(rows, d_kappa, J * dot * c.inv_rho0);
    }



    template <int dim>
    template <typename Return, typename LaneConstants>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::update_plane_strain_pair(
      const Return          &ret,
      const Strength        &s,
      const LaneConstants   &lanes,
      const BatchConstants  &c,
      const Tensor<2, 2>    *dL,
      SymmetricTensor<2, 2> *stress,
      double                *block0,
      const unsigned int     stride,
      double                *volume_ratio) const
    {
      using namespace Lanes;
      double *block[width];
      for (unsigned int l = 0; l < width; ++l)
        block[l] = block0 + l * stride;
      Value tr, t[4];
      plane_strain_trial_pair(c,
                              dL,
                              stress,
                              lanes_of([&block](std::size_t l) {
                                return block[l][out_of_plane];
                              }),
                              tr,
                              t);
      const Value ratio = 1 + tr;
      const Value J =
        lanes_of([&block](std::size_t l) { return block[l][ratio_column]; }) *
        ratio;
      for (unsigned int l = 0; l < width; ++l)
        block[l][ratio_column] = J[l];
      store(volume_ratio, ratio);
      const Value centre  = 0.5 * (t[0] + t[1]);
      const Value half    = 0.5 * (t[0] - t[1]);
      const Value radius2 = half * half + t[2] * t[2];
      // Disconnected grains (update_plane_strain()): no return, no stress.
      const Mask disconnected = J > c.disconnected_ratio;
      // The lanes as bits: the complement of a Mask is not one
      // instruction in SSE2 (GCC goes through general registers).
      const int outside =
        ~(lane_bits(ret.inside_plane_pair(lanes, centre, radius2, t[3])) |
          lane_bits(disconnected)) &
        all_bits;
      // The stresses are adjacent values, xx, yy, xy of each
      // (SymmetricTensor<2, 2> stores its diagonal first), stored as
      // vectors. The values by value: the elastic path's t stays in
      // registers.
      static_assert(sizeof(SymmetricTensor<2, 2>) == 3 * sizeof(double));
      const auto write = [&](Value xx, Value yy, Value xy, Value zz) {
        if (any(disconnected))
          {
            xx = zero_where(disconnected, xx);
            yy = zero_where(disconnected, yy);
            xy = zero_where(disconnected, xy);
            zz = zero_where(disconnected, zz);
          }
        store_columns(&stress[0][0][0], xx, yy, xy);
        for (unsigned int l = 0; l < width; ++l)
          block[l][out_of_plane] = zz[l];
      };
      if (outside == 0)
        {
          write(t[0], t[1], t[2], t[3]);
          return;
        }
      // The returns read and write r, not t.
      Value     r[4] = {t[0], t[1], t[2], t[3]}, ep[4], d_kappa = {};
      const int done =
        outside & lane_bits(ret.in_plane_pair(lanes, r, ep, d_kappa));
      if (done == all_bits)
        {
          add_plastic_increment_pair(c, J, r, ep, d_kappa, block);
        }
      else
        for (unsigned int l = 0; l < width; ++l)
          {
            std::array<double, 4> tl = {{r[0][l], r[1][l], r[2][l], r[3][l]}};
            if ((done >> l) & 1)
              add_plastic_increment(c,
                                    tl,
                                    {{ep[0][l], ep[1][l], ep[2][l], ep[3][l]}},
                                    d_kappa[l],
                                    block[l]);
            else
              {
                tl = {{t[0][l], t[1][l], t[2][l], t[3][l]}};
                std::array<double, 4> epl;
                double                dkl;
                // Off the common path: the one-particle return.
                if (((outside >> l) & 1) && ret.in_plane(s, tl, epl, dkl))
                  add_plastic_increment(c, tl, epl, dkl, block[l]);
              }
            for (unsigned int k = 0; k < 4; ++k)
              r[k][l] = tl[k];
          }
      write(r[0], r[1], r[2], r[3]);
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
      const BatchConstants c      = batch_constants();
      const unsigned int   stride = this->state_stride();
      Strength             base   = strength(0);
      ret.prepare(base);
      // Outside the loop: Strength is 33 values, not to be initialised
      // for every particle.
      Strength     softened;
      unsigned int i = 0;
      // In plane strain without softening Lanes::width particles at a
      // time.
      if constexpr (dim == 2 && Return::returns_pairs)
        if (!softens())
          for (const auto lanes = Return::lane_constants(base);
               i + Lanes::width <= n;
               i += Lanes::width)
            {
              for (unsigned int l = 0; l < Lanes::width; ++l)
                this->request_ahead(n, stress, state, stride, i + l);
              update_plane_strain_pair(ret,
                                       base,
                                       lanes,
                                       c,
                                       dL + i,
                                       stress + i,
                                       state + stride * i,
                                       stride,
                                       volume_ratio + i);
            }
      for (; i < n; ++i)
        {
          this->request_ahead(n, stress, state, stride, i);
          double *const   block = state + stride * i;
          const Strength &s     = particle_strength(ret, base, block, softened);
          if constexpr (dim == 1)
            update_uniaxial(ret,
                            s,
                            c,
                            dL[i][0][0],
                            stress[i][0][0],
                            block,
                            volume_ratio[i]);
          else
            update_plane_strain(ret,
                                s,
                                c,
                                dL[i],
                                stress[i],
                                block,
                                volume_ratio[i]);
        }
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline double
    PlasticHypoelastic<dim>::stored_energy(const BatchConstants          &c,
                                           const SymmetricTensor<2, dim> &st,
                                           const double                   zz)
    {
      // As energy_density(); in 1D both lateral stresses are zz.
      const double xx = st[0][0];
      const double yy = dim == 1 ? zz : st[1 % dim][1 % dim];
      const double xy = dim == 1 ? 0 : st[0][1 % dim];
      return (xx * xx + yy * yy + zz * zz -
              2 * c.nu * (xx * yy + yy * zz + zz * xx) +
              2 * (1 + c.nu) * xy * xy) *
             (0.5 * c.inv_e);
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline double
    PlasticHypoelastic<dim>::close_gap(const double             tr,
                                       const Tensor<2, dim>    &dL,
                                       SymmetricTensor<2, dim> &st,
                                       double                  *block)
    {
      double &gap = block[apex_column];
      // The fraction of the increment spent in the gap: all of it while
      // the gap stays open (also under extension, which widens it).
      const bool   open    = gap + tr > 0;
      const double closing = open ? 1 : -gap / tr;
      block[plastic_xx] += closing * dL[0][0];
      if constexpr (dim == 2)
        {
          block[2] += closing * dL[1][1];
          block[3] += closing * 0.5 * (dL[0][1] + dL[1][0]);
        }
      st                  = SymmetricTensor<2, dim>();
      block[out_of_plane] = 0;
      gap                 = open ? gap + tr : 0;
      return open ? 0 : 1 - closing;
    }



    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    PlasticHypoelastic<dim>::separate_at_apex(const BatchConstants &c,
                                              const double volumetric_before,
                                              const double stored,
                                              SymmetricTensor<2, dim> &st,
                                              double                  *block)
    {
      const double dilation = plastic_volumetric(block) - volumetric_before;
      if (!(dilation > 0))
        return;
      // At the apex of a cohesionless surface the returned stress is zero
      // (exactly for Drucker-Prager and a non-associated Mohr-Coulomb, to
      // round-off of the trial stress for an associated one): a stress
      // that small against the stress of the plastic increment is the
      // apex.
      const double limit   = 1e-10 * dilation / c.inv_e;
      double       largest = std::abs(block[out_of_plane]);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          largest = std::max(largest, std::abs(st[i][j]));
      if (largest > limit)
        return;
      block[apex_column] = dilation;
      block[work_column] += stored;
      st                  = SymmetricTensor<2, dim>();
      block[out_of_plane] = 0;
    }



    template <int dim>
    template <typename Return>
    void
    PlasticHypoelastic<dim>::update_separated(const Return            &ret,
                                              const BatchConstants    &c,
                                              const Tensor<2, dim>    &dL,
                                              SymmetricTensor<2, dim> &st,
                                              double                  *block,
                                              double &volume_ratio) const
    {
      const double tr   = trace(dL);
      const double left = close_gap(tr, dL, st, block);
      const double J    = block[ratio_column] * (1 + tr);
      if (left > 0)
        {
          // The rest of the increment after the gap has closed: the
          // update of a dense particle from zero stress, with the volume
          // ratio of the whole increment (its plastic work uses it).
          const Tensor<2, dim> rest   = left * dL;
          const double         before = plastic_volumetric(block);
          block[ratio_column]         = J / (1 + trace(rest));
          update_with(ret, 1, &rest, &st, block, &volume_ratio);
          separate_at_apex(c, before, 0, st, block);
        }
      block[ratio_column] = J;
      volume_ratio        = 1 + tr;
    }



    template <int dim>
    template <typename Return>
    void
    PlasticHypoelastic<dim>::update_with_recoverable(
      const Return            &ret,
      const unsigned int       n,
      const Tensor<2, dim>    *dL,
      SymmetricTensor<2, dim> *stress,
      double                  *state,
      double                  *volume_ratio) const
    {
      // Disconnected volume ratio is refused with recoverable: none.
      const BatchConstants      c      = batch_constants();
      const unsigned int        stride = this->state_stride();
      constexpr unsigned int    chunk  = 64;
      std::array<double, chunk> before, stored;
      for (unsigned int i = 0; i < n;)
        {
          if (state[stride * i + apex_column] > 0)
            {
              update_separated(ret,
                               c,
                               dL[i],
                               stress[i],
                               state + stride * i,
                               volume_ratio[i]);
              ++i;
              continue;
            }
          // A run of dense particles: the update without the option (two
          // at a time where it can), then which of them reached the apex.
          unsigned int k = 0;
          for (; k < chunk && i + k < n; ++k)
            {
              const double *const block = state + stride * (i + k);
              if (block[apex_column] > 0)
                break;
              before[k] = plastic_volumetric(block);
              stored[k] = block[ratio_column] * c.inv_rho0 *
                          stored_energy(c, stress[i + k], block[out_of_plane]);
            }
          update_with(ret,
                      k,
                      dL + i,
                      stress + i,
                      state + stride * i,
                      volume_ratio + i);
          for (unsigned int j = 0; j < k; ++j)
            separate_at_apex(c,
                             before[j],
                             stored[j],
                             stress[i + j],
                             state + stride * (i + j));
          i += k;
        }
    }
  } // namespace Material
} // namespace psmpm

#endif
