// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_apic_particle_loops_h
#define psmpm_simulator_apic_particle_loops_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/pair.h>
#include <psmpm/base/prefetch.h>
#include <psmpm/simulator/point_accumulation.h>
#include <psmpm/simulator/state.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * The particle loops of the apic transfer scheme (its class
     * documentation in source/simulator/transfers/apic.cc has the
     * formulas): the particles' mass, affine momentum and forces into
     * cell arrays, the grid-to-particle update of velocities and affine
     * matrices fused with the momentum of the updated fields, and the
     * move. Inline templates on the number of functions per cell
     * (internal::with_functions_per_cell(): fixed trip counts, the same
     * operations in the same order as with a run-time count), so that a
     * scheme calls them per chunk or per step and the loops allocate
     * nothing and call nothing virtual per particle.
     */
    namespace ApicLoops
    {
      using internal::with_functions_per_cell;

      /// How the affine matrix C_p is formed (Transfer/Affine matrix).
      enum class AffineMatrix
      {
        control_points,
        velocity_gradient,
        rotation,
        none
      };

      /// What the loops read of the grid beyond the state.
      template <int dim>
      struct Grid
      {
        /// Control points X_i in local relevant numbering.
        const Point<dim> *control_points;
        /// Local relevant index of DoF k of cell c at [c * n + k].
        const unsigned int *dofs;
      };

      /// Per cell DoF sums of particle quantities.
      template <int dim>
      struct CellSums
      {
        /// w_k = sum_p m_p N_k(x_p).
        double *lumped;
        /// Consistent cell matrices sum_p m_p N_k N_l, full rows
        /// (nullptr: lumped mass only).
        double *mass;
        /// q_k = sum_p m_p N_k (v_p + C_p (X_k - x_p)).
        Tensor<1, dim> *affine_momentum;
        /// sum_p m_p N_k v_p, the consistent rows' momentum (nullptr with
        /// lumped mass).
        Tensor<1, dim> *momentum;
        /// f_k = sum_p (m_p g N_k - V_p sigma_p grad N_k).
        Tensor<1, dim> *forces;
      };

      /**
       * C = B D^{-1} on the eigendirections of D with support (relative
       * to its trace: scale-free), the old C on the others. Closed form
       * (no iterative eigensolver that could throw on a non-finite D of a
       * run going unstable: NaN passes to the stability monitor).
       */
      template <int dim>
      inline Tensor<2, dim>
      affine_matrix(const Tensor<2, dim>          &B,
                    const SymmetricTensor<2, dim> &D,
                    const Tensor<2, dim>          &C_old)
      {
        const double scale = trace(D);
        if (!(scale > 0))
          return C_old;
        Tensor<2, dim> C;
        if constexpr (dim == 1)
          C[0][0] = B[0][0] / D[0][0];
        else
          {
            const double a = D[0][0], b = D[0][1], c = D[1][1];
            const double mean = 0.5 * (a + c);
            // |(0.5 (a - c), b)| relative to the trace, so that no square
            // can overflow or underflow: std::hypot does the same scaling
            // per call at several times the cost (3.5 % of the free
            // Powell-Sabin throughput bar, perf).
            const double inverse = 1. / scale;
            const double p = 0.5 * (a - c) * inverse, q = b * inverse;
            const double r = scale * std::sqrt(p * p + q * q);
            Tensor<1, 2> e1;
            if (std::abs(a - c) + std::abs(b) <= 1e-14 * scale)
              e1[0] = 1; // D = lambda I
            else if (a >= c)
              e1[0] = mean + r - c, e1[1] = b;
            else
              e1[0] = b, e1[1] = mean + r - a;
            e1 /= e1.norm();
            const Tensor<1, 2> e2({-e1[1], e1[0]});
            for (const auto &[lambda, e] :
                 {std::make_pair(mean + r, e1), std::make_pair(mean - r, e2)})
              {
                const Tensor<1, 2> Ce =
                  lambda > 1e-3 * scale ? (B * e) / lambda : C_old * e;
                C += outer_product(Ce, e);
              }
          }
        return C;
      }

      /**
       * The affine momentum m N_k (v + C (X_k - x)) of a particle in the
       * plane into @p q[k] (and m N_k v into @p w[k] unless nullptr) for
       * its @p n functions, in pairs (base/pair.h): lane-wise the
       * operations of the Tensor expressions of add_momentum(), C r =
       * (C00 r0 + C01 r1, C10 r0 + C11 r1) as deal.II contracts. The
       * restrict-qualified arrays let the compiler keep the particle's
       * data in registers across the stores.
       */
      template <typename N>
      DEAL_II_ALWAYS_INLINE inline void
      momentum_pairs(const N             n,
                     const double        m,
                     const Point<2>     &x,
                     const Tensor<1, 2> &v,
                     const Tensor<2, 2> &C,
                     const double *__restrict phi,
                     const unsigned int *__restrict dofs,
                     const Point<2> *__restrict control_points,
                     Tensor<1, 2> *__restrict q,
                     Tensor<1, 2> *__restrict w)
      {
        const Pair x2 = load_pair(x);
        const Pair v2 = load_pair(v);
        const Pair c0 = {C[0][0], C[1][0]};
        const Pair c1 = {C[0][1], C[1][1]};
        for (unsigned int k = 0; k < n; ++k)
          {
            const Pair mk = broadcast(m * phi[k]);
            const Pair r  = load_pair(control_points[dofs[k]]) - x2;
            const Pair Cr = c0 * broadcast(r[0]) + c1 * broadcast(r[1]);
            store_pair(q[k], load_pair(q[k]) + mk * (v2 + Cr));
            if (w != nullptr)
              store_pair(w[k], load_pair(w[k]) + mk * v2);
          }
      }

      /// The forces m g N_k - V sigma grad N_k of a particle in the plane
      /// into @p f[k], as add_point() sums them (the same bits as the
      /// Tensor expression).
      template <typename N>
      DEAL_II_ALWAYS_INLINE inline void
      forces_pairs(const N                      n,
                   const Tensor<1, 2>          &external,
                   const double                 V,
                   const SymmetricTensor<2, 2> &s,
                   const double *__restrict phi,
                   const Tensor<1, 2> *__restrict grad,
                   Tensor<1, 2> *__restrict f)
      {
        const Pair f2 = load_pair(external);
        const Pair s0 = {s[0][0], s[0][1]};
        const Pair s1 = {s[0][1], s[1][1]};
        const Pair V2 = broadcast(V);
        for (unsigned int k = 0; k < n; ++k)
          {
            const Pair t =
              s0 * broadcast(grad[k][0]) + s1 * broadcast(grad[k][1]);
            store_pair(f[k], load_pair(f[k]) + (phi[k] * f2 - V2 * t));
          }
      }

      /**
       * Particle @p p's mass, affine momentum (velocity @p v, affine
       * matrix @p C) and, if @p forces, its forces into @p sums, @p n
       * functions per cell.
       */
      template <int dim, bool forces, typename N>
      DEAL_II_ALWAYS_INLINE inline void
      add_momentum(const State<dim>     &state,
                   const Grid<dim>      &grid,
                   const CellSums<dim>  &sums,
                   const std::size_t     p,
                   const N               n,
                   const Tensor<1, dim> &v,
                   const Tensor<2, dim> &C)
      {
        const auto        &particles = state.particles;
        const unsigned int cell      = particles.cell[p];
        const unsigned int base      = cell * n;
        const double       m         = particles.mass[p];
        const Point<dim>  &x         = particles.position[p];
        const double      *phi       = &state.shape_values[p * n];
        if constexpr (dim == 2)
          {
            momentum_pairs(n,
                           m,
                           x,
                           v,
                           C,
                           phi,
                           grid.dofs + base,
                           grid.control_points,
                           sums.affine_momentum + base,
                           sums.momentum != nullptr ? sums.momentum + base :
                                                      nullptr);
            if constexpr (forces)
              forces_pairs(n,
                           m * state.gravity,
                           particles.volume[p],
                           state.stress_for_forces()[p],
                           phi,
                           state.gradients(p, cell),
                           sums.forces + base);
          }
        else
          {
            for (unsigned int k = 0; k < n; ++k)
              {
                const double mk = m * phi[k];
                sums.affine_momentum[base + k] +=
                  mk * (v + C * (grid.control_points[grid.dofs[base + k]] - x));
                if (sums.momentum != nullptr)
                  sums.momentum[base + k] += mk * v;
              }
            if constexpr (forces)
              {
                const double                   V        = particles.volume[p];
                const SymmetricTensor<2, dim> &s        = state.stress_for_forces()[p];
                const Tensor<1, dim>           external = m * state.gravity;
                const Tensor<1, dim>          *grad = state.gradients(p, cell);
                for (unsigned int k = 0; k < n; ++k)
                  sums.forces[base + k] +=
                    phi[k] * external - V * (s * grad[k]);
              }
          }
      }

      /**
       * The mass, the momentum of the affine fields and the forces of
       * the particles [@p first, @p last) into @p sums (zeroed by the
       * caller), in particle order: the sums of the start of an apic
       * step.
       */
      template <int dim>
      void
      add_to_cells(const State<dim>    &state,
                   const Grid<dim>     &grid,
                   const CellSums<dim> &sums,
                   const std::size_t    first,
                   const std::size_t    last)
      {
        const auto &particles = state.particles;
        with_functions_per_cell(state.grid->dofs_per_cell, [&](const auto n) {
          for (std::size_t p = first; p < last; ++p)
            {
              const unsigned int base = particles.cell[p] * n;
              const double       m    = particles.mass[p];
              const double      *phi  = &state.shape_values[p * n];
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double mk = m * phi[k];
                  sums.lumped[base + k] += mk;
                  if (sums.mass != nullptr)
                    {
                      double *row = sums.mass + (base + k) * n;
                      for (unsigned int l = 0; l < n; ++l)
                        row[l] += mk * phi[l];
                    }
                }
              add_momentum<dim, true>(state,
                                      grid,
                                      sums,
                                      p,
                                      n,
                                      particles.velocity[p],
                                      particles.affine[p]);
            }
        });
      }

      /// The grid-to-particle update of accelerate(), with the affine
      /// matrix and the FLIP parts chosen at compile time.
      template <int dim, bool fit, bool flip>
      struct Update
      {
        double flip_fraction;
        bool   affine_increment;
        double dt;
        bool   zero_affine;
      };

      /**
       * v = sum_i N_i v_i and, with @p fit, B = sum_i N_i v_i (X_i -
       * x)^T and D = sum_i N_i (X_i - x)(X_i - x)^T for a particle in
       * cell DoFs from @p base in the plane: in pairs (base/pair.h), lane
       * by lane the operations of the Tensor expressions of
       * gather() (sums from zero, N_i (v_i r_j), D01 += N_i
       * ((r0 r1 + r1 r0) / 2) as symmetrize() forms it).
       */
      template <bool fit, typename N>
      DEAL_II_ALWAYS_INLINE inline void
      fit_pairs(const State<2>        &state,
                const Grid<2>         &grid,
                const unsigned int     base,
                const Point<2>        &x,
                const double          *phi,
                const N                n,
                Tensor<1, 2>          &v,
                Tensor<2, 2>          &B,
                SymmetricTensor<2, 2> &D)
      {
        const Pair x2  = load_pair(x);
        Pair       v2  = {0., 0.};
        Pair       B0  = {0., 0.};
        Pair       B1  = {0., 0.};
        Pair       Dd  = {0., 0.};
        double     D01 = 0.;
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int l    = grid.dofs[base + k];
            const Pair         vk   = load_pair(state.grid_velocity[l]);
            const Pair         phik = broadcast(phi[k]);
            v2 += phik * vk;
            if constexpr (fit)
              {
                const Pair r = load_pair(grid.control_points[l]) - x2;
                B0 += phik * (broadcast(vk[0]) * r);
                B1 += phik * (broadcast(vk[1]) * r);
                Dd += phik * (r * r);
                D01 += phi[k] * ((r[0] * r[1] + r[1] * r[0]) * 0.5);
              }
          }
        store_pair(v, v2);
        if constexpr (fit)
          {
            store_pair(B[0], B0);
            store_pair(B[1], B1);
            D[0][0] = Dd[0];
            D[1][1] = Dd[1];
            D[0][1] = D01;
          }
      }

      /// The grid sums of one particle: v = sum_i N_i v_i, B and D (and
      /// the B of the acceleration for the affine FLIP increment).
      template <int dim>
      struct Fit
      {
        Tensor<1, dim>          v;
        Tensor<2, dim>          B, B_increment;
        SymmetricTensor<2, dim> D;
      };

      /// Particle @p p's grid sums (see the apic scheme) into @p fit.
      template <int dim, bool fit, bool flip, typename N>
      DEAL_II_ALWAYS_INLINE inline void
      gather(const State<dim>             &state,
             const Grid<dim>              &grid,
             const Update<dim, fit, flip> &update,
             const std::size_t             p,
             const N                       n,
             Fit<dim>                     &sums)
      {
        const auto        &particles = state.particles;
        const unsigned int base      = particles.cell[p] * n;
        const Point<dim>  &x         = particles.position[p];
        const double      *phi       = &state.shape_values[p * n];
        sums                         = Fit<dim>();
        if constexpr (dim == 2 && !flip)
          fit_pairs<fit>(state, grid, base, x, phi, n, sums.v, sums.B, sums.D);
        else
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int    l  = grid.dofs[base + k];
              const Tensor<1, dim> &vk = state.grid_velocity[l];
              sums.v += phi[k] * vk;
              if constexpr (fit)
                {
                  const Tensor<1, dim> r = grid.control_points[l] - x;
                  sums.B += phi[k] * outer_product(vk, r);
                  sums.D += phi[k] * symmetrize(outer_product(r, r));
                  if (flip && update.affine_increment)
                    sums.B_increment +=
                      phi[k] * outer_product(state.grid_acceleration[l], r);
                }
            }
      }

      /**
       * Particle @p p's new velocity and affine matrix from its grid sums
       * @p fit (see the apic scheme): v_p = sum_i N_i v_i (or the FLIP
       * blend), with @p fit C_p = B_p D_p^{-1}.
       */
      template <int dim, bool fit, bool flip, typename N>
      DEAL_II_ALWAYS_INLINE inline void
      set_velocity(State<dim>                   &state,
                   const Grid<dim>              &grid,
                   const Update<dim, fit, flip> &update,
                   const std::size_t             p,
                   const N                       n,
                   const Fit<dim>               &sums)
      {
        auto &particles = state.particles;
        if constexpr (flip)
          {
            const unsigned int base = particles.cell[p] * n;
            const double      *phi  = &state.shape_values[p * n];
            Tensor<1, dim>     a;
            for (unsigned int k = 0; k < n; ++k)
              a += phi[k] * state.grid_acceleration[grid.dofs[base + k]];
            const double f = update.flip_fraction;
            particles.velocity[p] =
              (1 - f) * sums.v + f * (particles.velocity[p] + update.dt * a);
          }
        else
          particles.velocity[p] = sums.v;
        Tensor<2, dim> &C = particles.affine[p];
        if constexpr (fit)
          {
            if (flip && update.affine_increment)
              {
                const double f = update.flip_fraction;
                C              = (1 - f) * affine_matrix(sums.B, sums.D, C) +
                    f * (C + update.dt * affine_matrix(sums.B_increment,
                                                       sums.D,
                                                       Tensor<2, dim>()));
              }
            else
              C = affine_matrix(sums.B, sums.D, C);
          }
        else if (update.zero_affine)
          C = Tensor<2, dim>();
      }

      /**
       * Every particle's new velocity and affine matrix (gather() and
       * set_velocity()) and, in the same pass, the momentum of its new
       * affine field into @p sums (affine momentum and, with consistent
       * rows, momentum; the caller zeroes them).
       *
       * In batches of particles, a loop over the batch per stage: the
       * affine matrix of a particle is a chain of divisions and square
       * roots, which the processor overlaps with those of the next
       * particles of its loop, not with the long grid sums of a fused
       * loop. The same operations per particle, so the same results.
       */
      template <int dim, bool fit, bool flip>
      void
      accelerate(State<dim>                   &state,
                 const Grid<dim>              &grid,
                 const Update<dim, fit, flip> &update,
                 const CellSums<dim>          &sums)
      {
        auto                       &particles = state.particles;
        constexpr std::size_t       batch     = 32;
        std::array<Fit<dim>, batch> fits;
        with_functions_per_cell(state.grid->dofs_per_cell, [&](const auto n) {
          for (std::size_t first = 0; first < particles.size(); first += batch)
            {
              const std::size_t last =
                std::min(particles.size(), first + batch);
              for (std::size_t p = first; p < last; ++p)
                {
                  // One pass over all particles, too many streams for the
                  // hardware prefetcher alone (prefetch.h).
                  if (p + prefetch_distance < particles.size())
                    {
                      const std::size_t ahead = p + prefetch_distance;
                      prefetch_lines<sizeof(double) * 9>(
                        &state.shape_values[ahead * n]);
                      prefetch_lines(&particles.cell[ahead]);
                      prefetch_lines(&particles.position[ahead]);
                      prefetch_lines(&particles.mass[ahead]);
                      prefetch_lines<sizeof(Tensor<2, dim>)>(
                        &particles.affine[ahead]);
                      if constexpr (flip)
                        prefetch_lines(&particles.velocity[ahead]);
                    }
                  gather(state, grid, update, p, n, fits[p - first]);
                }
              for (std::size_t p = first; p < last; ++p)
                set_velocity(state, grid, update, p, n, fits[p - first]);
              for (std::size_t p = first; p < last; ++p)
                add_momentum<dim, false>(state,
                                         grid,
                                         sums,
                                         p,
                                         n,
                                         particles.velocity[p],
                                         particles.affine[p]);
            }
        });
      }

      /// What move() does beside moving the particles.
      struct Move
      {
        /// Move with the re-projected grid velocity instead of v_p.
        bool with_grid_velocity;
        /// C_p = L_p (velocity gradient) ...
        bool gradient;
        /// ... or its skew part (rotation).
        bool rotation;
      };

      /**
       * The particles [@p first, @p last) move by dt times the grid
       * velocity at the particle (or v_p), their strain increments dt L_p, L_p
       * = sum_i v_i (x) grad N_i(x_p), go to increments[p - first], and the
       * velocity-gradient modes take their C_p from L_p.
       */
      template <int dim>
      void
      move(State<dim>       &state,
           const Grid<dim>  &grid,
           const Move       &options,
           const std::size_t first,
           const std::size_t last,
           Tensor<2, dim>   *increments)
      {
        auto        &particles = state.particles;
        const double dt        = state.dt;
        with_functions_per_cell(state.grid->dofs_per_cell, [&](const auto n) {
          for (std::size_t p = first; p < last; ++p)
            {
              // The first loop of a chunk to read these (prefetch.h),
              // also past the chunk's end: the next chunk follows soon.
              if (p + prefetch_distance < particles.size())
                {
                  const std::size_t ahead = p + prefetch_distance;
                  prefetch_lines(&particles.cell[ahead]);
                  prefetch_lines(&particles.position[ahead]);
                  prefetch_lines(&particles.displacement[ahead]);
                  prefetch_lines(&particles.velocity[ahead]);
                  if (!state.gradients_per_cell)
                    prefetch_lines<sizeof(Tensor<1, dim>) * 9>(
                      &state.shape_gradients[ahead * n]);
                  if (options.with_grid_velocity)
                    prefetch_lines<sizeof(double) * 9>(
                      &state.shape_values[ahead * n]);
                }
              const unsigned int    cell = particles.cell[p];
              const unsigned int    base = cell * n;
              const Tensor<1, dim> *grad = state.gradients(p, cell);
              const double         *phi  = &state.shape_values[p * n];
              Tensor<2, dim>        L; // L_ij = dv_i/dx_j
              Tensor<1, dim>        grid_velocity;
              if constexpr (dim == 2)
                {
                  // Rows in pairs: L_i += v_i grad N, as outer_product(),
                  // and v += N v_i in the same pass over the grid values.
                  Pair L0 = {0., 0.}, L1 = {0., 0.}, v = {0., 0.};
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const Tensor<1, 2> &vi =
                        state.grid_velocity[grid.dofs[base + k]];
                      const Pair g = load_pair(grad[k]);
                      L0 += broadcast(vi[0]) * g;
                      L1 += broadcast(vi[1]) * g;
                      if (options.with_grid_velocity)
                        v += broadcast(phi[k]) * load_pair(vi);
                    }
                  store_pair(L[0], L0);
                  store_pair(L[1], L1);
                  store_pair(grid_velocity, v);
                }
              else
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const Tensor<1, dim> &vi =
                      state.grid_velocity[grid.dofs[base + k]];
                    L += outer_product(vi, grad[k]);
                    grid_velocity += phi[k] * vi;
                  }
              const Tensor<1, dim> velocity = options.with_grid_velocity ?
                                                grid_velocity :
                                                particles.velocity[p];
              if (options.gradient)
                particles.affine[p] = L;
              else if (options.rotation)
                particles.affine[p] = 0.5 * (L - transpose(L));
              increments[p - first]   = dt * L;
              const Tensor<1, dim> du = dt * velocity;
              particles.displacement[p] += du;
              particles.position[p] += du;
            }
        });
      }
    } // namespace ApicLoops
  }   // namespace Simulator
} // namespace psmpm

#endif
