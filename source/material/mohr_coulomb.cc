// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/material/mohr_coulomb.h>
#include <psmpm/material/plastic_hypoelastic.templates.h>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      template <int dim>
      std::unique_ptr<Material<dim>>
      create_mohr_coulomb()
      {
        return std::make_unique<MohrCoulomb<dim>>();
      }

      const char *const description =
        "Mohr-Coulomb plasticity (Friction angle, Dilatancy angle, Cohesion, "
        "Tension cutoff, optional linear softening) with the exact return in "
        "principal stress space; Friction angle 0 is Tresca";

      const Registration<MaterialRegistry<1>>
        registration_1d({"mohr-coulomb",
                         description,
                         create_mohr_coulomb<1>,
                         PlasticHypoelastic<1>::declare_entries});
      const Registration<MaterialRegistry<2>>
        registration_2d({"mohr-coulomb",
                         description,
                         create_mohr_coulomb<2>,
                         PlasticHypoelastic<2>::declare_entries});

      /// A plane in principal stress space (sorted frame): a . sigma <= k,
      /// with the flow direction b.
      struct Plane
      {
        std::array<double, 3> a, b;
        double                k;
      };

      /// Solve the m x m system A x = r (m <= 3) by Gaussian elimination
      /// with partial pivoting; false if it is singular against @p scale.
      bool
      solve_small(const unsigned int m,
                  double             A[3][3],
                  double             r[3],
                  double             x[3])
      {
        double norm = 0;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            norm = std::max(norm, std::abs(A[i][j]));
        for (unsigned int c = 0; c < m; ++c)
          {
            unsigned int p = c;
            for (unsigned int i = c + 1; i < m; ++i)
              if (std::abs(A[i][c]) > std::abs(A[p][c]))
                p = i;
            if (!(std::abs(A[p][c]) > 1e-10 * norm))
              return false;
            if (p != c)
              {
                for (unsigned int j = 0; j < m; ++j)
                  std::swap(A[p][j], A[c][j]);
                std::swap(r[p], r[c]);
              }
            for (unsigned int i = c + 1; i < m; ++i)
              {
                const double l = A[i][c] / A[c][c];
                for (unsigned int j = c; j < m; ++j)
                  A[i][j] -= l * A[c][j];
                r[i] -= l * r[c];
              }
          }
        for (int i = int(m) - 1; i >= 0; --i)
          {
            double s = r[i];
            for (unsigned int j = i + 1; j < m; ++j)
              s -= A[i][j] * x[j];
            x[i] = s / A[i][i];
          }
        return true;
      }

      /// The largest violation of the Mohr-Coulomb planes and the cutoff
      /// by the principal stresses @p s (any order).
      DEAL_II_ALWAYS_INLINE inline double
      violation(const std::array<double, 3> &s,
                const double                 sin_phi,
                const double                 k,
                const double                 t)
      {
        const double s1 = std::max(std::max(s[0], s[1]), s[2]);
        const double s3 = std::min(std::min(s[0], s[1]), s[2]);
        return std::max((1 + sin_phi) * s1 - (1 - sin_phi) * s3 - k, s1 - t);
      }

      template <int dim>
      struct MohrCoulombReturn
      {
        const MohrCoulomb<dim> &model;

        void
        prepare(typename PlasticHypoelastic<dim>::Strength &s) const
        {
          s.derived[0] = 2 * s.cohesion * s.cos_phi;
        }

        /// The elastic test: sigma_1 and sigma_3 by max/min, no sort.
        bool
        inside(const typename PlasticHypoelastic<dim>::Strength &s,
               const std::array<double, 3>                      &sigma) const
        {
          const double s1 = std::max(std::max(sigma[0], sigma[1]), sigma[2]);
          const double s3 = std::min(std::min(sigma[0], sigma[1]), sigma[2]);
          return (1 + s.sin_phi) * s1 - (1 - s.sin_phi) * s3 - s.derived[0] <=
                   0 &&
                 s1 <= s.tension_cutoff;
        }

        /// The elastic test of a plane-strain stress from the centre c
        /// and squared radius r^2 of its in-plane Mohr circle and sigma_zz
        /// = z, without the square root: by where z lies against c -+ r,
        /// f <= 0 is alpha r <= beta with alpha >= 0.
        bool
        inside_plane(const typename PlasticHypoelastic<dim>::Strength &s,
                     const double                                      c,
                     const double                                      r2,
                     const double                                      z) const
        {
          const double sp = s.sin_phi, k = s.derived[0], t = s.tension_cutoff;
          const auto   at_most = [r2](const double alpha, const double beta) {
            return beta >= 0 && alpha * alpha * r2 <= beta * beta;
          };
          const double dz = z - c;
          bool         inside;
          if (dz >= 0 && dz * dz >= r2) // z = sigma_1
            inside = at_most(1 - sp, k + (1 - sp) * c - (1 + sp) * z);
          else if (dz <= 0 && dz * dz >= r2) // z = sigma_3
            inside = at_most(1 + sp, k + (1 - sp) * z - (1 + sp) * c);
          else
            inside = at_most(2, k - 2 * sp * c);
          return inside && z <= t && at_most(1, t - c);
        }

        bool
        operator()(const typename PlasticHypoelastic<dim>::Strength &s,
                   std::array<double, 3> &sigma) const
        {
          return model.return_stress(s, sigma);
        }
      };

      /// The active sets over @p n_planes planes (3 or 6) as bit masks:
      /// those with the main plane (bit 0) first, then the others, each by
      /// size (1 to 3) and then by number; without the main plane alone,
      /// which the closed form before them tries. The classical order
      /// (edges, then apex), and the edges of the uniaxial and triaxial
      /// states come second and third instead of after every single plane
      /// (3.5x less time for a bar yielding on an edge in every step).
      /// Built once.
      struct ActiveSets
      {
        explicit ActiveSets(const unsigned int n_planes)
        {
          for (const bool main : {true, false})
            for (unsigned int size = 1; size <= 3; ++size)
              for (unsigned int m = 2; m < (1u << n_planes); ++m)
                if (__builtin_popcount(m) == int(size) && bool(m & 1u) == main)
                  masks[n_masks++] = m;
        }
        unsigned int masks[64];
        unsigned int n_masks = 0;
      };

      /// The constants of one return: sin phi, sin psi, k = 2 c cos phi,
      /// the cutoff t, the cohesion c and the Lame constants.
      struct ReturnConstants
      {
        double sp, ss, k, t, cohesion, lambda, two_g;
      };

      /// Whether the returned stress @p y violates no plane by more than
      /// round-off relative to the result.
      DEAL_II_ALWAYS_INLINE inline bool
      acceptable(const std::array<double, 3> &y, const ReturnConstants &c)
      {
        return violation(y, c.sp, c.k, c.t) <=
               1e-13 * (std::abs(y[0]) + std::abs(y[1]) + std::abs(y[2]) +
                        c.cohesion);
      }

      /// The return of the sorted principal stresses @p x onto the main
      /// plane alone, in closed form (the answer for most yielding
      /// particles): true and @p y if it is the answer. This and the edge
      /// returns are forced inline into return_stress() (called out of
      /// line, they cost a yielding bar 10 % of its update); the general
      /// active sets below, rarely reached, stay out of line.
      DEAL_II_ALWAYS_INLINE inline bool
      return_to_main_plane(const std::array<double, 3> &x,
                           const ReturnConstants       &c,
                           std::array<double, 3>       &y)
      {
        const double                b0 = 1 + c.ss, b2 = -(1 - c.ss);
        const double                tr = b0 + b2;
        const std::array<double, 3> Db = {{c.lambda * tr + c.two_g * b0,
                                           c.lambda * tr,
                                           c.lambda * tr + c.two_g * b2}};
        const double                a0 = 1 + c.sp, a2 = -(1 - c.sp);
        const double inv_denominator = 1 / (a0 * Db[0] + a2 * Db[2]);
        const double dl = (a0 * x[0] + a2 * x[2] - c.k) * inv_denominator;
        if (!(dl > 0))
          return false;
        y = {{x[0] - dl * Db[0], x[1] - dl * Db[1], x[2] - dl * Db[2]}};
        // Refined once (see return_to_active_set()).
        const double d2 = (a0 * y[0] + a2 * y[2] - c.k) * inv_denominator;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] -= d2 * Db[d];
        return acceptable(y, c);
      }

      DEAL_II_ALWAYS_INLINE inline double
      dot(const std::array<double, 3> &u, const std::array<double, 3> &v)
      {
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      }

      /// The return of @p x onto an edge in closed form (Cramer's rule):
      /// the main plane with that of the neighbouring sextant where
      /// sigma_1 = sigma_2 (@p e = 1) or sigma_2 = sigma_3 (@p e = 2).
      DEAL_II_ALWAYS_INLINE inline bool
      return_to_edge(const std::array<double, 3> &x,
                     const ReturnConstants       &c,
                     const unsigned int           e,
                     std::array<double, 3>       &y)
      {
        const double b0 = 1 + c.ss, b2 = -(1 - c.ss), a0 = 1 + c.sp,
                     a2                = -(1 - c.sp);
        const double                l  = c.lambda * (b0 + b2);
        const std::array<double, 3> Dm = {
          {l + c.two_g * b0, l, l + c.two_g * b2}};
        const std::array<double, 3> am = {{a0, 0, a2}};
        const std::array<double, 3> ae = e == 1 ?
                                           std::array<double, 3>{{0, a0, a2}} :
                                           std::array<double, 3>{{a0, a2, 0}};
        const std::array<double, 3> De =
          e == 1 ?
            std::array<double, 3>{{l, l + c.two_g * b0, l + c.two_g * b2}} :
            std::array<double, 3>{{l + c.two_g * b0, l + c.two_g * b2, l}};
        const double A00 = dot(am, Dm), A01 = dot(am, De), A10 = dot(ae, Dm),
                     A11 = dot(ae, De);
        const double det = A00 * A11 - A01 * A10;
        if (!(std::abs(det) > 1e-10 * std::abs(A00 * A11)))
          return false;
        const double inv = 1 / det;
        const auto   solve =
          [&](const std::array<double, 3> &z, double &d0, double &d1) {
            const double r0 = dot(am, z) - c.k, r1 = dot(ae, z) - c.k;
            d0 = (r0 * A11 - A01 * r1) * inv;
            d1 = (A00 * r1 - A10 * r0) * inv;
          };
        double d0, d1;
        solve(x, d0, d1);
        if (!(d0 >= 0 && d1 >= 0))
          return false;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] = x[d] - d0 * Dm[d] - d1 * De[d];
        solve(y, d0, d1); // refined once, as in return_to_active_set()
        for (unsigned int d = 0; d < 3; ++d)
          y[d] -= d0 * Dm[d] + d1 * De[d];
        return acceptable(y, c);
      }

      /// The planes of the sorted frame: the main plane, the two edge
      /// planes of the sextant and, with a finite cutoff, the three cutoff
      /// planes; with D b for each (D = lambda 1 1^T + 2 G I in principal
      /// space). Returns their number (3 or 6).
      inline unsigned int
      make_planes(const ReturnConstants &c,
                  Plane                  planes[6],
                  std::array<double, 3>  Db[6])
      {
        const double sp = c.sp, ss = c.ss;
        unsigned int n_planes = 0;
        planes[n_planes++]    = {{{1 + sp, 0, -(1 - sp)}},
                                 {{1 + ss, 0, -(1 - ss)}},
                                 c.k};
        planes[n_planes++]    = {{{0, 1 + sp, -(1 - sp)}},
                                 {{0, 1 + ss, -(1 - ss)}},
                                 c.k};
        planes[n_planes++]    = {{{1 + sp, -(1 - sp), 0}},
                                 {{1 + ss, -(1 - ss), 0}},
                                 c.k};
        if (std::isfinite(c.t))
          for (unsigned int d = 0; d < 3; ++d)
            {
              Plane p{{{0, 0, 0}}, {{0, 0, 0}}, c.t};
              p.a[d] = p.b[d]    = 1;
              planes[n_planes++] = p;
            }
        for (unsigned int j = 0; j < n_planes; ++j)
          {
            const double tr = planes[j].b[0] + planes[j].b[1] + planes[j].b[2];
            for (unsigned int d = 0; d < 3; ++d)
              Db[j][d] = c.lambda * tr + c.two_g * planes[j].b[d];
          }
        return n_planes;
      }

      /// The return of @p x onto the @p m planes @p active of @p planes
      /// together: true and @p y if the multipliers are non-negative and
      /// the result violates no plane.
      inline bool
      return_to_active_set(const std::array<double, 3> &x,
                           const ReturnConstants       &c,
                           const Plane                  planes[6],
                           const std::array<double, 3>  Db[6],
                           const unsigned int           active[3],
                           const unsigned int           m,
                           std::array<double, 3>       &y)
      {
        double A[3][3], A0[3][3], r[3], dl[3];
        for (unsigned int i = 0; i < m; ++i)
          {
            const Plane &pi = planes[active[i]];
            r[i] = pi.a[0] * x[0] + pi.a[1] * x[1] + pi.a[2] * x[2] - pi.k;
            for (unsigned int j = 0; j < m; ++j)
              {
                const auto &d = Db[active[j]];
                A[i][j]       = A0[i][j] =
                  pi.a[0] * d[0] + pi.a[1] * d[1] + pi.a[2] * d[2];
              }
          }
        if (!solve_small(m, A, r, dl))
          return false;
        double sum      = 0;
        bool   positive = true;
        for (unsigned int j = 0; j < m; ++j)
          sum += std::abs(dl[j]);
        for (unsigned int j = 0; j < m; ++j)
          positive = positive && dl[j] >= -1e-12 * sum;
        if (!positive)
          return false;
        y = x;
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int d = 0; d < 3; ++d)
            y[d] -= dl[j] * Db[active[j]][d];
        // One step of iterative refinement: the residual of y is round-off
        // of the trial stress' size, which near the apex can be large
        // against y itself; recomputed from y it is of y's size.
        double r2[3], d2[3];
        for (unsigned int i = 0; i < m; ++i)
          {
            const Plane &pi = planes[active[i]];
            r2[i] = pi.a[0] * y[0] + pi.a[1] * y[1] + pi.a[2] * y[2] - pi.k;
          }
        if (solve_small(m, A0, r2, d2))
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int d = 0; d < 3; ++d)
              y[d] -= d2[j] * Db[active[j]][d];
        // Relative to the result: near the apex a set whose result
        // violates another plane by round-off of the trial stress is not
        // the answer (the apex is).
        return acceptable(y, c);
      }

      /// The first active set (in the order of ActiveSets) that is the
      /// answer for @p x: true and @p y, false if none is.
      inline bool
      return_by_active_sets(const std::array<double, 3> &x,
                            const ReturnConstants       &c,
                            std::array<double, 3>       &y)
      {
        Plane                   planes[6];
        std::array<double, 3>   Db[6];
        const unsigned int      n_planes = make_planes(c, planes, Db);
        static const ActiveSets three(3), six(6);
        const ActiveSets       &sets = n_planes == 3 ? three : six;
        for (unsigned int q = 0; q < sets.n_masks; ++q)
          {
            unsigned int active[3], m = 0;
            for (unsigned int j = 0; j < n_planes; ++j)
              if (sets.masks[q] & (1u << j))
                active[m++] = j;
            if (return_to_active_set(x, c, planes, Db, active, m, y))
              return true;
          }
        return false;
      }
    } // namespace



    template <int dim>
    bool
    MohrCoulomb<dim>::return_stress(
      const typename PlasticHypoelastic<dim>::Strength &strength,
      std::array<double, 3>                            &sigma) const
    {
      const ReturnConstants c = {strength.sin_phi,
                                 strength.sin_psi,
                                 2 * strength.cohesion * strength.cos_phi,
                                 strength.tension_cutoff,
                                 strength.cohesion,
                                 this->lame_lambda(),
                                 2 * this->shear_modulus()};
      // Sorted frame: x[0] >= x[1] >= x[2] are sigma[o[0]], ...
      std::array<unsigned int, 3> o = {{0, 1, 2}};
      if (sigma[o[0]] < sigma[o[1]])
        std::swap(o[0], o[1]);
      if (sigma[o[1]] < sigma[o[2]])
        std::swap(o[1], o[2]);
      if (sigma[o[0]] < sigma[o[1]])
        std::swap(o[0], o[1]);
      const std::array<double, 3> x = {{sigma[o[0]], sigma[o[1]], sigma[o[2]]}};
      if ((1 + c.sp) * x[0] - (1 - c.sp) * x[2] - c.k <= 0 && x[0] <= c.t)
        return false;

      // The main plane, then the two edges in closed form (what most
      // particles that are not on the main plane return to: a body in
      // uniaxial or triaxial states), then every active set.
      std::array<double, 3> y;
      if (return_to_main_plane(x, c, y) || return_to_edge(x, c, 1, y) ||
          return_to_edge(x, c, 2, y) || return_by_active_sets(x, c, y))
        {
          for (unsigned int d = 0; d < 3; ++d)
            sigma[o[d]] = y[d];
          return true;
        }

      // No active set satisfies the conditions: the apex of a
      // non-associated potential, where the stress is the apex itself.
      const double apex =
        c.sp > 0 ? std::min(c.t, strength.cohesion * strength.cos_phi / c.sp) :
                   std::min(c.t, (x[0] + x[1] + x[2]) / 3);
      sigma = {{apex, apex, apex}};
      return true;
    }



    template <int dim>
    void
    MohrCoulomb<dim>::update(const unsigned int       n,
                             const Tensor<2, dim>    *dL,
                             SymmetricTensor<2, dim> *stress,
                             double                  *state,
                             double                  *volume_ratio) const
    {
      this->update_with(MohrCoulombReturn<dim>{*this},
                        n,
                        dL,
                        stress,
                        state,
                        volume_ratio);
    }



    template class MohrCoulomb<1>;
    template class MohrCoulomb<2>;
  } // namespace Material
} // namespace psmpm
