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

      /// Where MohrCoulomb::prepare() puts the constants of the return in
      /// Strength::derived (once per batch, or per softened particle, so
      /// that a yielding particle divides by nothing): k = 2 c cos phi, the
      /// Lame constants, the main plane's D b and 1 / (a . D b), and per
      /// edge e = 1, 2 (at edge_block + edge_size (e - 1)) the D b of its
      /// second plane, the matrix a_i . D b_j of the two planes (row-wise)
      /// and the inverse of its determinant (0: singular, no edge return).
      enum DerivedIndex : unsigned int
      {
        k_index      = 0,
        lambda_index = 1,
        two_g_index  = 2,
        main_db      = 3,
        main_inverse = 6,
        edge_block   = 7,
        edge_size    = 8,
        /// After the edges: sqrt(2/3) |dev b| of the main plane's flow
        /// direction b (the equivalent plastic strain per unit
        /// multiplier), 1 / E and nu (the compliance).
        main_equivalent = 23,
        inv_e_index     = 24,
        nu_index        = 25,
        /// 2/3 dev b_main : dev b_edge for edge 1 and 2 (the cross term
        /// of an edge return's equivalent plastic strain).
        edge_equivalent = 26,
      };

      /// The constants of one return: sin phi, sin psi, k = 2 c cos phi,
      /// the cutoff t, the cohesion c and the Lame constants.
      struct ReturnConstants
      {
        double sp, ss, k, t, cohesion, lambda, two_g;
      };

      template <typename Strength>
      ReturnConstants
      return_constants(const Strength &s)
      {
        return {s.sin_phi,
                s.sin_psi,
                s.derived[k_index],
                s.tension_cutoff,
                s.cohesion,
                s.derived[lambda_index],
                s.derived[two_g_index]};
      }

      /// Whether the returned stress @p y violates no plane by more than
      /// round-off relative to the result.
      DEAL_II_ALWAYS_INLINE inline bool
      acceptable(const std::array<double, 3> &y,
                 const double                 sp,
                 const double                 k,
                 const double                 t,
                 const double                 cohesion)
      {
        return violation(y, sp, k, t) <=
               1e-13 *
                 (std::abs(y[0]) + std::abs(y[1]) + std::abs(y[2]) + cohesion);
      }

      DEAL_II_ALWAYS_INLINE inline bool
      acceptable(const std::array<double, 3> &y, const ReturnConstants &c)
      {
        return acceptable(y, c.sp, c.k, c.t, c.cohesion);
      }

      /// The return of the sorted principal stresses @p x onto the main
      /// plane alone, in closed form (the answer for most yielding
      /// particles): true and @p y if it is the answer; otherwise @p y is
      /// the main plane's result (@p x if its multiplier is not positive),
      /// which tells which edge to try. This and the edge returns are
      /// forced inline into the particle loop; the general active sets,
      /// rarely reached, stay out of line.
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_to_main_plane(const std::array<double, 3> &x,
                           const Strength              &s,
                           std::array<double, 3>       &y,
                           double                      &multiplier)
      {
        const double *const Db = &s.derived[main_db];
        const double        a0 = 1 + s.sin_phi, a2 = -(1 - s.sin_phi);
        const double        k               = s.derived[k_index];
        const double        inv_denominator = s.derived[main_inverse];
        const double        dl = (a0 * x[0] + a2 * x[2] - k) * inv_denominator;
        if (!(dl > 0))
          {
            // Element by element: a copy of the whole array is a 16-byte
            // load of values just stored as 8-byte ones, which the
            // processor cannot forward (a stall on every particle).
            y[0] = x[0];
            y[1] = x[1];
            y[2] = x[2];
            return false;
          }
        y = {{x[0] - dl * Db[0], x[1] - dl * Db[1], x[2] - dl * Db[2]}};
        multiplier = dl;
        if (acceptable(y, s.sin_phi, k, s.tension_cutoff, s.cohesion))
          return true;
        // Refined once where the result is not acceptable (see
        // return_to_active_set()).
        const double d2 = (a0 * y[0] + a2 * y[2] - k) * inv_denominator;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] -= d2 * Db[d];
        multiplier += d2;
        return acceptable(y, s.sin_phi, k, s.tension_cutoff, s.cohesion);
      }

      DEAL_II_ALWAYS_INLINE inline double
      dot(const std::array<double, 3> &u, const std::array<double, 3> &v)
      {
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      }

      /// The return of @p x onto an edge in closed form (Cramer's rule):
      /// the main plane with that of the neighbouring sextant where
      /// sigma_1 = sigma_2 (@p e = 1) or sigma_2 = sigma_3 (@p e = 2).
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_to_edge(const std::array<double, 3> &x,
                     const Strength              &s,
                     const unsigned int           e,
                     std::array<double, 3>       &y,
                     double                      &main_multiplier,
                     double                      &edge_multiplier)
      {
        const double *const E   = &s.derived[edge_block + edge_size * (e - 1)];
        const double        inv = E[7];
        if (inv == 0)
          return false;
        const double        a0 = 1 + s.sin_phi, a2 = -(1 - s.sin_phi);
        const double        k   = s.derived[k_index];
        const double *const Dm  = &s.derived[main_db];
        const double        A00 = E[3], A01 = E[4], A10 = E[5], A11 = E[6];
        // The second plane's normal is (0, a0, a2) or (a0, a2, 0): its
        // residual is the main plane's with z_0 or z_2 replaced by z_1.
        const auto solve =
          [&](const std::array<double, 3> &z, double &d0, double &d1) {
            const double r0 = a0 * z[0] + a2 * z[2] - k;
            const double r1 =
              e == 1 ? a0 * z[1] + a2 * z[2] - k : a0 * z[0] + a2 * z[1] - k;
            d0 = (r0 * A11 - A01 * r1) * inv;
            d1 = (A00 * r1 - A10 * r0) * inv;
          };
        double d0, d1;
        solve(x, d0, d1);
        if (!(d0 >= 0 && d1 >= 0))
          return false;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] = x[d] - d0 * Dm[d] - d1 * E[d];
        main_multiplier = d0;
        edge_multiplier = d1;
        if (acceptable(y, s.sin_phi, k, s.tension_cutoff, s.cohesion))
          return true;
        // Refined once, as in return_to_active_set(), where the residual's
        // round-off of the trial stress' size is not round-off of y's
        // (near the apex).
        double r0, r1;
        solve(y, r0, r1);
        for (unsigned int d = 0; d < 3; ++d)
          y[d] -= r0 * Dm[d] + r1 * E[d];
        main_multiplier += r0;
        edge_multiplier += r1;
        return acceptable(y, s.sin_phi, k, s.tension_cutoff, s.cohesion);
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
      /// The returns that few particles need: every active set in turn,
      /// then the apex (out of line).
      template <typename Strength>
      __attribute__((noinline)) bool
      return_by_active_sets_or_apex(const std::array<double, 3> &x,
                                    const Strength              &strength,
                                    std::array<double, 3>       &y)
      {
        const ReturnConstants c = return_constants(strength);
        if (return_by_active_sets(x, c, y))
          return true;
        // No active set satisfies the conditions: the apex of a
        // non-associated potential, where the stress is the apex itself.
        const double apex =
          c.sp > 0 ?
            std::min(c.t, strength.cohesion * strength.cos_phi / c.sp) :
            std::min(c.t, (x[0] + x[1] + x[2]) / 3);
        y = {{apex, apex, apex}};
        return true;
      }

      /// How return_sorted() ended: on the main plane (edge 0, multiplier
      /// main) or on edge 1 or 2 (the multipliers main and second of its
      /// two planes), or elsewhere (edge -1).
      struct ReturnPath
      {
        int    edge = -1;
        double main = 0, second = 0;
      };

      /// The return of the sorted principal stresses @p x (x_1 >= x_2 >=
      /// x_3) for the prepared @p strength: false if they are inside the
      /// surface; otherwise true, the returned ones in @p y and how in
      /// @p path. The main plane, then the edge its result points to (y_2
      /// < y_3: sigma_2 = sigma_3; else sigma_1 = sigma_2), then the other
      /// edge, all in closed form (what most yielding particles need: the
      /// main plane, or an edge in uniaxial and triaxial states), then
      /// every active set. Where the main plane's result would be
      /// unsorted by more than round-off (known from its multiplier
      /// alone: y_1 - y_2 and y_2 - y_3 are linear in it), it is not the
      /// answer and the edge it points to comes first; the main plane is
      /// then tried after both edges, before the active sets (which leave
      /// it out).
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_sorted(const Strength              &strength,
                    const std::array<double, 3> &x,
                    std::array<double, 3>       &y,
                    ReturnPath                  &path)
      {
        const double sp = strength.sin_phi;
        const auto  &d  = strength.derived;
        path.edge       = -1;
        const double f  = (1 + sp) * x[0] - (1 - sp) * x[2] - d[k_index];
        if (f <= 0 && x[0] <= strength.tension_cutoff)
          return false;
        const double dl  = f * d[main_inverse];
        const double g01 = (x[0] - x[1]) - dl * (d[main_db] - d[main_db + 1]);
        const double g12 =
          (x[1] - x[2]) - dl * (d[main_db + 1] - d[main_db + 2]);
        const double tolerance  = 1e-12 * (std::abs(x[0]) + std::abs(x[1]) +
                                          std::abs(x[2]) + strength.cohesion);
        const bool   main_first = std::min(g01, g12) >= -tolerance;
        unsigned int first      = 1 + static_cast<unsigned int>(g12 < 0);
        if (main_first)
          {
            if (return_to_main_plane(x, strength, y, path.main))
              {
                path.edge = 0;
                return true;
              }
            first = 1 + static_cast<unsigned int>(y[1] < y[2]);
          }
        if (return_to_edge(x, strength, first, y, path.main, path.second))
          path.edge = first;
        else if (return_to_edge(x,
                                strength,
                                3 - first,
                                y,
                                path.main,
                                path.second))
          path.edge = 3 - first;
        else if (!main_first && return_to_main_plane(x, strength, y, path.main))
          path.edge = 0;
        else
          return_by_active_sets_or_apex(x, strength, y);
        return true;
      }

      /// return_sorted() of the principal stresses @p sigma (any order):
      /// false if they are inside the surface (unchanged).
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_principal(const Strength &strength, std::array<double, 3> &sigma)
      {
        // Sorted frame: x[0] >= x[1] >= x[2] are sigma[o[0]], ...
        std::array<unsigned int, 3> o = {{0, 1, 2}};
        if (sigma[o[0]] < sigma[o[1]])
          std::swap(o[0], o[1]);
        if (sigma[o[1]] < sigma[o[2]])
          std::swap(o[1], o[2]);
        if (sigma[o[0]] < sigma[o[1]])
          std::swap(o[0], o[1]);
        const std::array<double, 3> x = {
          {sigma[o[0]], sigma[o[1]], sigma[o[2]]}};
        std::array<double, 3> y;
        ReturnPath            path;
        if (!return_sorted(strength, x, y, path))
          return false;
        for (unsigned int d = 0; d < 3; ++d)
          sigma[o[d]] = y[d];
        return true;
      }

      /// The return of the plane-strain stress t = (xx, yy, xy, zz) in
      /// its own frame: false if it is inside the surface (t unchanged);
      /// otherwise t returned and the plastic strain @p ep = C^-1 (trial
      /// - t) (tensor shear) and its equivalent @p d_kappa. The sorted
      /// principal frame by min and max, the place of sigma_zz in it by
      /// two comparisons (the frame of return_principal()'s sort, ties
      /// included); the rotation back with the in-plane eigenvector's
      /// cos and sin of 2 theta from t. On the main plane (most yielding
      /// particles) the plastic strain is the multiplier times the flow
      /// direction and its equivalent the multiplier times a constant:
      /// no second square root; on an edge the two multipliers times the
      /// two planes' flow directions, the equivalent a quadratic form in
      /// them (constants prepared once per batch); elsewhere C^-1 (trial -
      /// sigma).
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_plane_strain(const Strength        &strength,
                          std::array<double, 4> &t,
                          std::array<double, 4> &ep,
                          double                &d_kappa)
      {
        const double centre = 0.5 * (t[0] + t[1]);
        const double half   = 0.5 * (t[0] - t[1]);
        const double radius = std::sqrt(half * half + t[2] * t[2]);
        const double a = centre + radius, b = centre - radius, z = t[3];
        const std::array<double, 3> x = {
          {std::max(a, z), std::max(b, std::min(a, z)), std::min(b, z)}};
        std::array<double, 3> y, e;
        ReturnPath            path;
        if (!return_sorted(strength, x, y, path))
          return false;
        const auto  &d  = strength.derived;
        const double b0 = 1 + strength.sin_psi, b2 = -(1 - strength.sin_psi);
        if (path.edge == 0)
          {
            const double dl = path.main;
            e               = {{dl * b0, 0, dl * b2}};
            d_kappa         = dl * d[main_equivalent];
          }
        else if (path.edge > 0)
          {
            // M b_main + S b_edge, b_edge = (0, b0, b2) or (b0, b2, 0);
            // the equivalent strain a quadratic form in (M, S).
            const double m = path.main, s = path.second;
            const bool   one = path.edge == 1;
            e                = {{m * b0 + (one ? 0 : s * b0),
                                 s * (one ? b0 : b2),
                                 m * b2 + (one ? s * b2 : 0)}};
            const double q   = d[main_equivalent] * d[main_equivalent];
            const double cross =
              one ? d[edge_equivalent] : d[edge_equivalent + 1];
            d_kappa = std::sqrt(q * (m * m + s * s) + 2 * cross * m * s);
          }
        else
          {
            const double inv_e = d[inv_e_index], nu = d[nu_index];
            const std::array<double, 3> c = {
              {x[0] - y[0], x[1] - y[1], x[2] - y[2]}};
            e              = {{(c[0] - nu * (c[1] + c[2])) * inv_e,
                               (c[1] - nu * (c[0] + c[2])) * inv_e,
                               (c[2] - nu * (c[0] + c[1])) * inv_e}};
            const double m = (e[0] + e[1] + e[2]) * (1. / 3);
            d_kappa =
              std::sqrt(2. / 3 *
                        ((e[0] - m) * (e[0] - m) + (e[1] - m) * (e[1] - m) +
                         (e[2] - m) * (e[2] - m)));
          }
        // Back to (a, b, z): z's place in the sorted frame.
        // By flags, not branches: where sigma_zz lies varies from particle
        // to particle near a hydrostatic state.
        const unsigned int z_place =
          static_cast<unsigned int>(z <= a) + static_cast<unsigned int>(z <= b);
        const unsigned int ia = static_cast<unsigned int>(z_place == 0),
                           ib = 2 - static_cast<unsigned int>(z_place == 2);
        const double inv      = radius > 0 ? 1 / radius : 0;
        const double cos2     = radius > 0 ? half * inv : 1;
        const double sin2     = t[2] * inv;
        const double p = 0.5 * (y[ia] + y[ib]), q = 0.5 * (y[ia] - y[ib]);
        t               = {{p + q * cos2, p - q * cos2, q * sin2, y[z_place]}};
        const double ea = 0.5 * (e[ia] + e[ib]), eb = 0.5 * (e[ia] - e[ib]);
        ep = {{ea + eb * cos2, ea - eb * cos2, eb * sin2, e[z_place]}};
        return true;
      }



      /// The constants of the returns in Lanes, both lanes alike, made
      /// once per batch from a prepared Strength: the constants of
      /// return_common_pair() and inside_plane_lanes() as the scalar
      /// functions compute them, each edge's constants as edge 1's and
      /// the bits in which edge 2's differ (for Lanes::pick()).
      struct LaneConstants
      {
        template <typename Strength>
        explicit LaneConstants(const Strength &s)
        {
          using Lanes::broadcast;
          const auto  &d  = s.derived;
          const double sp = s.sin_phi;
          one_plus_sp     = broadcast(1 + sp);
          one_minus_sp    = broadcast(1 - sp);
          a2              = broadcast(-(1 - sp));
          k               = broadcast(d[k_index]);
          cutoff          = broadcast(s.tension_cutoff);
          cohesion        = broadcast(s.cohesion);
          main_inverse    = broadcast(d[DerivedIndex::main_inverse]);
          for (unsigned int i = 0; i < 3; ++i)
            Db[i] = broadcast(d[main_db + i]);
          Db01 = broadcast(d[main_db] - d[main_db + 1]);
          Db12 = broadcast(d[main_db + 1] - d[main_db + 2]);
          for (unsigned int i = 0; i < 8; ++i)
            {
              edge[i]      = broadcast(d[edge_block + i]);
              edge_two[i]  = broadcast(d[edge_block + edge_size + i]);
              edge_bits[i] = Lanes::differing_bits(edge[i], edge_two[i]);
            }
          b0              = broadcast(1 + s.sin_psi);
          b2              = broadcast(-(1 - s.sin_psi));
          b_bits          = Lanes::differing_bits(b0, b2);
          main_equivalent = broadcast(d[DerivedIndex::main_equivalent]);
          q               = broadcast(d[DerivedIndex::main_equivalent] *
                        d[DerivedIndex::main_equivalent]);
          cross           = broadcast(d[edge_equivalent]);
          cross_two       = broadcast(d[edge_equivalent + 1]);
          cross_bits      = Lanes::differing_bits(cross, cross_two);
        }

        Lanes::Value one_plus_sp, one_minus_sp, a2, k, cutoff, cohesion,
          main_inverse, Db[3], Db01, Db12, edge[8], edge_two[8], edge_bits[8],
          b0, b2, b_bits, main_equivalent, q, cross, cross_two, cross_bits;
      };

      /// The sorted principal stresses @p x of the plane-strain stress t
      /// (in-plane Mohr circle centre -+ @p radius and t[3]) in Lanes, as
      /// in return_plane_strain().
      DEAL_II_ALWAYS_INLINE inline void
      sorted_pair(const Lanes::Value t[4],
                  const Lanes::Value radius,
                  Lanes::Value       x[3])
      {
        const Lanes::Value centre = 0.5 * (t[0] + t[1]);
        const Lanes::Value a = centre + radius, b = centre - radius, z = t[3];
        x[0] = Lanes::max(a, z);
        x[1] = Lanes::max(b, Lanes::min(a, z));
        x[2] = Lanes::min(b, z);
      }

      /// acceptable() in Lanes.
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      acceptable_pair(const Lanes::Value y[3], const LaneConstants &c)
      {
        using Lanes::Value;
        const Value s1 = Lanes::max(Lanes::max(y[0], y[1]), y[2]);
        const Value s3 = Lanes::min(Lanes::min(y[0], y[1]), y[2]);
        const Value v =
          Lanes::max(c.one_plus_sp * s1 - c.one_minus_sp * s3 - c.k,
                     s1 - c.cutoff);
        return v <= 1e-13 * (Lanes::abs(y[0]) + Lanes::abs(y[1]) +
                             Lanes::abs(y[2]) + c.cohesion);
      }

      /// return_to_main_plane() of @p x in Lanes, unrefined (a0 x0 + a2
      /// x2 with a2 = -(1 - sin phi)): the lanes where its multiplier is
      /// positive and its result accepted, with @p y, the plastic strain
      /// @p e and its equivalent @p d_kappa as return_plane_strain() has
      /// them.
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      main_plane_pair(const LaneConstants &c,
                      const Lanes::Value   x[3],
                      Lanes::Value         y[3],
                      Lanes::Value         e[3],
                      Lanes::Value        &d_kappa)
      {
        const Lanes::Value dm =
          (c.one_plus_sp * x[0] + c.a2 * x[2] - c.k) * c.main_inverse;
        for (unsigned int i = 0; i < 3; ++i)
          y[i] = x[i] - dm * c.Db[i];
        e[0]    = dm * c.b0;
        e[1]    = Lanes::broadcast(0);
        e[2]    = dm * c.b2;
        d_kappa = dm * c.main_equivalent;
        return Lanes::both(dm > 0, acceptable_pair(y, c));
      }

      /// return_to_edge() of @p x in Lanes, unrefined: the lanes where
      /// both multipliers are non-negative and the result accepted, with
      /// @p y, @p e and @p d_kappa as return_plane_strain() has them. On
      /// edge @p which (1 or 2) in both lanes, or with @p which = 0 on
      /// edge 2 where @p two, else edge 1 (constants picked lane by lane:
      /// a dozen instructions a constant, which the uniform cases save;
      /// pick() and select() give the same values, bit for bit, as the
      /// constants of one edge).
      template <int which>
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      edge_pair(const LaneConstants &c,
                const Lanes::Value   x[3],
                const Lanes::Mask    two,
                Lanes::Value         y[3],
                Lanes::Value         e[3],
                Lanes::Value        &d_kappa)
      {
        using Lanes::select;
        using Lanes::Value;
        // a on edge 1, b on edge 2.
        const auto either_edge = [two](const Value a, const Value b) {
          if constexpr (which == 0)
            return select(two, b, a);
          else
            return which == 1 ? a : b;
        };
        // One edge's constants in place (a copy is a dozen stores and
        // loads through the stack).
        Value        picked[8];
        const Value *E = which == 1 ? c.edge : c.edge_two;
        if constexpr (which == 0)
          {
            for (unsigned int i = 0; i < 8; ++i)
              picked[i] = Lanes::pick(two, c.edge[i], c.edge_bits[i]);
            E = picked;
          }
        const Value a0x0 = c.one_plus_sp * x[0], a2x2 = c.a2 * x[2];
        const Value r0 = a0x0 + a2x2 - c.k;
        const Value r1 = either_edge(c.one_plus_sp * x[1] + a2x2 - c.k,
                                     a0x0 + c.a2 * x[1] - c.k);
        const Value d0 = (r0 * E[6] - E[4] * r1) * E[7];
        const Value d1 = (E[3] * r1 - E[5] * r0) * E[7];
        for (unsigned int i = 0; i < 3; ++i)
          y[i] = x[i] - d0 * c.Db[i] - d1 * E[i];
        // The sums with zero as in return_plane_strain() (-0 + 0 is +0).
        const Value zero  = Lanes::broadcast(0);
        e[0]              = d0 * c.b0 + either_edge(zero, d1 * c.b0);
        e[1]              = d1 * either_edge(c.b0, c.b2);
        e[2]              = d0 * c.b2 + either_edge(d1 * c.b2, zero);
        const Value cross = which == 0 ?
                              Lanes::pick(two, c.cross, c.cross_bits) :
                              either_edge(c.cross, c.cross_two);
        d_kappa = Lanes::sqrt(c.q * (d0 * d0 + d1 * d1) + 2. * cross * d0 * d1);
        return Lanes::both(Lanes::both(E[7] != 0, d0 >= 0),
                           Lanes::both(d1 >= 0, acceptable_pair(y, c)));
      }

      /// edge_pair() for the lanes @p need (as bits), on the edge of each
      /// (edge 2 where @p two): the constants of one edge where all of
      /// these lanes return to it (the other lanes' results are not used).
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      edge_pair_of(const LaneConstants &c,
                   const Lanes::Value   x[3],
                   const Lanes::Mask    two,
                   const int            need,
                   Lanes::Value         y[3],
                   Lanes::Value         e[3],
                   Lanes::Value        &d_kappa)
      {
        const int on_two = Lanes::lane_bits(two) & need;
        if (on_two == 0)
          return edge_pair<1>(c, x, two, y, e, d_kappa);
        if (on_two == need)
          return edge_pair<2>(c, x, two, y, e, d_kappa);
        return edge_pair<0>(c, x, two, y, e, d_kappa);
      }

      /**
       * return_sorted() of the sorted principal stresses @p x of two
       * particles in Lanes on its common paths only: the main plane where
       * it comes first and its unrefined result is accepted, or the edge
       * that comes first where that one's is. Returns the lanes where one
       * of these is the answer (the others leave return_sorted() another
       * way), with the returned @p y, the plastic strain @p e (sorted
       * frame) and its equivalent @p d_kappa as return_plane_strain()
       * computes them.
       */
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      return_common_pair(const LaneConstants &c,
                         const Lanes::Value   x[3],
                         Lanes::Value         y[3],
                         Lanes::Value         e[3],
                         Lanes::Value        &d_kappa)
      {
        using Lanes::Mask;
        using Lanes::select;
        using Lanes::Value;
        const Value f = c.one_plus_sp * x[0] - c.one_minus_sp * x[2] - c.k;
        const Mask  plastic =
          Lanes::and_not(Lanes::both(f <= 0, x[0] <= c.cutoff),
                         Lanes::true_mask());
        const Value dl         = f * c.main_inverse;
        const Value g01        = (x[0] - x[1]) - dl * c.Db01;
        const Value g12        = (x[1] - x[2]) - dl * c.Db12;
        const Value tolerance  = 1e-12 * (Lanes::abs(x[0]) + Lanes::abs(x[1]) +
                                         Lanes::abs(x[2]) + c.cohesion);
        const Mask  main_first = Lanes::min(g01, g12) >= -tolerance;
        const Mask  two        = g12 < 0;
        // Each path only if a lane may take it.
        Mask main_ok = {}, edge_ok = {};
        // Masks combined with Lanes::both(), either(), and_not(): see
        // both().
        if (Lanes::any(Lanes::both(main_first, plastic)))
          main_ok =
            Lanes::both(main_first, main_plane_pair(c, x, y, e, d_kappa));
        const int need = Lanes::lane_bits(Lanes::and_not(main_first, plastic));
        if (need != 0 && !Lanes::any(main_ok))
          edge_ok =
            Lanes::and_not(main_first,
                           edge_pair_of(c, x, two, need, y, e, d_kappa));
        else if (need != 0)
          {
            Value ye[3], ee[3], ke;
            edge_ok = Lanes::and_not(main_first,
                                     edge_pair_of(c, x, two, need, ye, ee, ke));
            for (unsigned int i = 0; i < 3; ++i)
              {
                y[i] = select(main_ok, y[i], ye[i]);
                e[i] = select(main_ok, e[i], ee[i]);
              }
            d_kappa = select(main_ok, d_kappa, ke);
          }
        return Lanes::both(plastic, Lanes::either(main_ok, edge_ok));
      }

      /// return_plane_strain() of Lanes::width particles' stresses @p t in
      /// Lanes on return_common_pair()'s paths: the lanes where it is the
      /// answer, with @p t, @p ep and @p d_kappa there.
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      return_plane_strain_pair(const LaneConstants &constants,
                               Lanes::Value         t[4],
                               Lanes::Value         ep[4],
                               Lanes::Value        &d_kappa)
      {
        using Lanes::Mask;
        using Lanes::select;
        using Lanes::Value;
        const Value half   = 0.5 * (t[0] - t[1]);
        const Value radius = Lanes::sqrt(half * half + t[2] * t[2]);
        Value       x[3], y[3], e[3];
        sorted_pair(t, radius, x);
        const Mask done = return_common_pair(constants, x, y, e, d_kappa);
        if (!Lanes::any(done))
          return done;
        // Back to (a, b, z), z's place by flags as in
        // return_plane_strain().
        const Value centre = 0.5 * (t[0] + t[1]);
        const Value a = centre + radius, b = centre - radius, z = t[3];
        const Mask  za = z <= a, zb = z <= b;
        // Where z has the same place in every lane that returned (two
        // neighbours in similar states), the values by that place: no
        // selects.
        const int done_bits   = Lanes::lane_bits(done);
        const int za_bits     = Lanes::lane_bits(za),
                  zb_bits     = Lanes::lane_bits(zb);
        const int  first_bits = ~(za_bits | zb_bits) & done_bits;
        const int  last_bits  = za_bits & zb_bits & done_bits;
        Value      ya, yb, yz, ea, eb, ez;
        const auto place = [&](const unsigned int ia,
                               const unsigned int ib,
                               const unsigned int iz) {
          ya = y[ia];
          yb = y[ib];
          yz = y[iz];
          ea = e[ia];
          eb = e[ib];
          ez = e[iz];
        };
        if (first_bits == 0 && last_bits == 0)
          place(0, 2, 1);
        else if (first_bits == done_bits)
          place(1, 2, 0);
        else if (last_bits == done_bits)
          place(0, 1, 2);
        else
          {
            const Mask first = ~za & ~zb, last = za & zb;
            ya = select(first, y[1], y[0]);
            yb = select(last, y[1], y[2]);
            yz = select(first, y[0], select(last, y[2], y[1]));
            ea = select(first, e[1], e[0]);
            eb = select(last, e[1], e[2]);
            ez = select(first, e[0], select(last, e[2], e[1]));
          }
        const Mask  round = radius > 0;
        const Value inv   = select(round, 1 / radius, Lanes::broadcast(0));
        const Value cos2  = select(round, half * inv, Lanes::broadcast(1));
        const Value sin2  = t[2] * inv;
        const Value p = 0.5 * (ya + yb), q = 0.5 * (ya - yb);
        t[0]           = p + q * cos2;
        t[1]           = p - q * cos2;
        t[2]           = q * sin2;
        t[3]           = yz;
        const Value pa = 0.5 * (ea + eb), pb = 0.5 * (ea - eb);
        ep[0] = pa + pb * cos2;
        ep[1] = pa - pb * cos2;
        ep[2] = pb * sin2;
        ep[3] = ez;
        return done;
      }

      /// MohrCoulombReturn::inside_plane() in Lanes, operation by
      /// operation.
      DEAL_II_ALWAYS_INLINE inline Lanes::Mask
      inside_plane_lanes(const LaneConstants &k,
                         const Lanes::Value   c,
                         const Lanes::Value   r2,
                         const Lanes::Value   z)
      {
        const Lanes::Value radius = Lanes::sqrt(r2);
        const Lanes::Value s1     = Lanes::max(c + radius, z);
        const Lanes::Value s3     = Lanes::min(c - radius, z);
        return Lanes::both(k.one_plus_sp * s1 - k.one_minus_sp * s3 - k.k <= 0,
                           s1 <= k.cutoff);
      }



      template <int dim>
      struct MohrCoulombReturn
      {
        const MohrCoulomb<dim> &model;

        /// in_plane() maps a plane-strain stress in its own frame.
        static constexpr bool returns_in_plane = true;

        /// in_plane_pair() and inside_plane_pair() for Lanes::width particles,
        /// with the constants lane_constants() makes once per batch.
        static constexpr bool returns_pairs = true;

        bool
        in_plane(const typename PlasticHypoelastic<dim>::Strength &s,
                 std::array<double, 4>                            &t,
                 std::array<double, 4>                            &ep,
                 double &d_kappa) const
        {
          return return_plane_strain(s, t, ep, d_kappa);
        }

        static LaneConstants
        lane_constants(const typename PlasticHypoelastic<dim>::Strength &s)
        {
          return LaneConstants(s);
        }

        Lanes::Mask
        in_plane_pair(const LaneConstants &c,
                      Lanes::Value         t[4],
                      Lanes::Value         ep[4],
                      Lanes::Value        &d_kappa) const
        {
          return return_plane_strain_pair(c, t, ep, d_kappa);
        }

        Lanes::Mask
        inside_plane_pair(const LaneConstants &k,
                          const Lanes::Value   c,
                          const Lanes::Value   r2,
                          const Lanes::Value   z) const
        {
          return inside_plane_lanes(k, c, r2, z);
        }

        void
        prepare(typename PlasticHypoelastic<dim>::Strength &s) const
        {
          model.prepare(s);
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
        /// = z: return_sorted()'s test, operation by operation as
        /// return_plane_strain() forms sigma_1 and sigma_3, so that a
        /// stress is returned exactly where that test finds it outside
        /// (one square root, which the inlined return of a pair computes
        /// once with the test; a test without it, by the place of z,
        /// takes three times the instructions and differs from the
        /// return's at round-off).
        bool
        inside_plane(const typename PlasticHypoelastic<dim>::Strength &s,
                     const double                                      c,
                     const double                                      r2,
                     const double                                      z) const
        {
          const double radius = std::sqrt(r2);
          const double s1     = std::max(c + radius, z);
          const double s3     = std::min(c - radius, z);
          return (1 + s.sin_phi) * s1 - (1 - s.sin_phi) * s3 -
                     s.derived[k_index] <=
                   0 &&
                 s1 <= s.tension_cutoff;
        }

        bool
        operator()(const typename PlasticHypoelastic<dim>::Strength &s,
                   std::array<double, 3> &sigma) const
        {
          return return_principal(s, sigma);
        }
      };
    } // namespace



    template <int dim>
    void
    MohrCoulomb<dim>::prepare(
      typename PlasticHypoelastic<dim>::Strength &s) const
    {
      const double lambda = this->lame_lambda();
      const double two_g  = 2 * this->shear_modulus();
      const double b0 = 1 + s.sin_psi, b2 = -(1 - s.sin_psi),
                   a0 = 1 + s.sin_phi, a2 = -(1 - s.sin_phi);
      const double                l  = lambda * (b0 + b2);
      const std::array<double, 3> Dm = {{l + two_g * b0, l, l + two_g * b2}};
      const std::array<double, 3> am = {{a0, 0, a2}};
      auto                       &d  = s.derived;
      d[k_index]                     = 2 * s.cohesion * s.cos_phi;
      d[lambda_index]                = lambda;
      d[two_g_index]                 = two_g;
      for (unsigned int i = 0; i < 3; ++i)
        d[main_db + i] = Dm[i];
      d[main_inverse]    = 1 / (a0 * Dm[0] + a2 * Dm[2]);
      const double mb    = (b0 + b2) * (1. / 3);
      d[main_equivalent] = std::sqrt(
        2. / 3 * ((b0 - mb) * (b0 - mb) + mb * mb + (b2 - mb) * (b2 - mb)));
      // dev b_main : dev b_edge = b_main . b_edge - 3 mb^2, b_main . b_edge
      // = b2^2 (edge 1: b_edge = (0, b0, b2)) or b0^2 (edge 2: (b0, b2, 0)).
      d[edge_equivalent]     = 2. / 3 * (b2 * b2 - 3 * mb * mb);
      d[edge_equivalent + 1] = 2. / 3 * (b0 * b0 - 3 * mb * mb);
      d[inv_e_index]         = 1 / this->youngs_modulus;
      d[nu_index]            = this->poisson_ratio;
      for (const unsigned int e : {1u, 2u})
        {
          const std::array<double, 3> ae =
            e == 1 ? std::array<double, 3>{{0, a0, a2}} :
                     std::array<double, 3>{{a0, a2, 0}};
          const std::array<double, 3> De =
            e == 1 ?
              std::array<double, 3>{{l, l + two_g * b0, l + two_g * b2}} :
              std::array<double, 3>{{l + two_g * b0, l + two_g * b2, l}};
          const double A00 = dot(am, Dm), A01 = dot(am, De), A10 = dot(ae, Dm),
                       A11  = dot(ae, De);
          const double  det = A00 * A11 - A01 * A10;
          double *const E   = &d[edge_block + edge_size * (e - 1)];
          for (unsigned int i = 0; i < 3; ++i)
            E[i] = De[i];
          E[3] = A00;
          E[4] = A01;
          E[5] = A10;
          E[6] = A11;
          E[7] = std::abs(det) > 1e-10 * std::abs(A00 * A11) ? 1 / det : 0;
        }
    }



    template <int dim>
    bool
    MohrCoulomb<dim>::return_stress(
      const typename PlasticHypoelastic<dim>::Strength &strength,
      std::array<double, 3>                            &sigma) const
    {
      // The particle loop calls return_principal() with the strength
      // prepared once per batch; here it is prepared for this call.
      typename PlasticHypoelastic<dim>::Strength prepared = strength;
      prepare(prepared);
      return return_principal(prepared, sigma);
    }



    template <int dim>
    void
    MohrCoulomb<dim>::update(const unsigned int       n,
                             const Tensor<2, dim>    *dL,
                             SymmetricTensor<2, dim> *stress,
                             double                  *state,
                             double                  *volume_ratio) const
    {
      // Two loops, chosen once per batch: the one without the option
      // compiles as if the option did not exist.
      if (this->recoverable_apex_dilation)
        this->update_with_recoverable(MohrCoulombReturn<dim>{*this},
                                      n,
                                      dL,
                                      stress,
                                      state,
                                      volume_ratio);
      else
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
