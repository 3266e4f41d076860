// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/transfer_scheme.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      enum class AffineMatrix
      {
        control_points,
        velocity_gradient,
        rotation,
        none
      };

      /**
       * Affine particle-in-cell (Jiang et al. 2015) for any space, with the
       * space's control points X_i (sum_i N_i(x) X_i = x) in place of grid
       * nodes. Each particle carries the velocity field
       * v(x) = v_p + C_p (x - x_p).
       *
       * Particle to grid. The grid momentum is the mass matrix applied to
       * the particles' affine fields: per particle, sum_j M^p_ij (v_p +
       * C_p (X_j - x_p)). For a consistent row this is m_p N_i v_p (the
       * affine part integrates to zero: sum_j N_j (X_j - x_p) = 0), for a
       * lumped row m_p N_i (v_p + C_p (X_i - x_p)) (APIC). Mass strategies
       * change the per-cell matrices (partial lumping), so the momentum is
       * the consistent one plus the strategy's change Delta of the cell
       * matrix applied to the cell's lumped-APIC values u_k = q_k / w_k. An
       * affine field is then carried exactly by every strategy (M v = M u
       * with v_i = A X_i + b), and momentum is kept (Delta has zero column
       * sums).
       *
       * Grid update. v_i^n from the momentum, a_i from the forces,
       * v_i^{n+1} = v_i^n + dt a_i. Internal forces of a symmetric stress
       * exert no torque on the control points (sum_i X_i (x) grad N_i = I),
       * so the grid keeps angular momentum.
       *
       * Grid to particle. v_p = sum_i N_i v_i^{n+1} and the new affine
       * matrix, either
       *  - control points: C_p = B_p D_p^{-1}, B_p = sum_i N_i v_i (X_i -
       *    x_p)^T, D_p = sum_i N_i (X_i - x_p)(X_i - x_p)^T; exactly APIC,
       *    angular momentum conserving. Bounded where functions carry
       *    little mass only if D_p is well conditioned with weights spread
       *    over many control points (Powell-Sabin); directions in which D_p
       *    has no support keep the old C_p;
       *  - velocity gradient: C_p = grad v of the projected field below
       *    (Taylor PIC); bounded for every space, exact for affine fields.
       *    P1 needs it: its D_p is singular on edges and D_p^{-1} grows as
       *    1 / N_k, so B_p D_p^{-1} (= sum_i v_i grad N_i^T) carries the
       *    acceleration f_k / m_k of a function with little mass undamped.
       *    Fed back through the next projection, the full gradient is
       *    amplified step by step on P1 (its symmetric part: the strain
       *    rate of element-wise noise);
       *  - rotation: the skew part of that gradient (rotational PIC, RPIC
       *    of Jiang et al. 2015): a rigid rotation is carried exactly and
       *    angular momentum is kept, without the symmetric feedback. The
       *    default for P1 (free block: angular momentum to 1e-4, where the
       *    full gradient fails after 100 steps, doc/transfers.md).
       *
       * Stress and positions (MUSL's second projection, for the same
       * reason as MUSL): the particles' new affine fields are projected
       * again, and the gradient of that field drives the material update;
       * positions move with v_p.
       */
      template <int dim>
      class APIC : public TransferScheme<dim>
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.declare_entry(
            "Affine matrix",
            "automatic",
            Patterns::Selection(
              "automatic|control points|velocity gradient|rotation|none"),
            "How the apic scheme forms each particle's affine velocity "
            "matrix C_p from the grid: 'control points' = B_p D_p^{-1} over "
            "the space's control points (APIC proper, angular momentum "
            "conserving), 'velocity gradient' = the gradient of the "
            "re-projected velocity (Taylor PIC), 'rotation' = the skew part "
            "of that gradient (rotational PIC: carries rigid rotations and "
            "angular momentum, not the strain rate), 'automatic' = control "
            "points for quadratic spaces, rotation for linear ones (whose "
            "D_p is singular on element edges and whose full gradient "
            "feedback is unstable), 'none' = C_p = 0 "
            "(plain PIC with the same projections, for comparison).");
          prm.declare_entry(
            "FLIP fraction",
            "0",
            Patterns::Double(0, 1),
            "Particle velocity update of the apic scheme: v_p = (1 - a) "
            "sum_i N_i v_i^{n+1} + a (v_p + dt sum_i N_i a_i), a = this "
            "fraction. 0 = PIC (APIC proper: the affine matrix carries what "
            "the projection cannot).");
          prm.declare_entry(
            "FLIP affine matrix",
            "false",
            Patterns::Bool(),
            "Whether the FLIP fraction a of the apic scheme also blends the "
            "affine matrix: C_p = (1 - a) C(v^{n+1}) + a (C_p + C(dt a)), "
            "C(w) the affine matrix of the grid field w (affine FLIP).");
          prm.declare_entry(
            "XPIC order",
            "1",
            Patterns::Integer(1, 8),
            "Order m of the extended particle-in-cell update (XPIC(m), "
            "Hammerquist and Nairn 2017) of the apic scheme with the "
            "control-point affine matrix: the particles take the affine "
            "fields of v^{n+1} + sum_{k=1}^{m-1} (I - Q)^k v^n, Q = the "
            "round trip grid -> particles -> grid. A grid mode that Q "
            "keeps by a factor q loses 1 - q per step with 1 (APIC), "
            "(1 - q)^m with m; each order above 1 costs one more round "
            "trip per step.");
          prm.declare_entry(
            "Position update",
            "particle velocity",
            Patterns::Selection("particle velocity|grid velocity"),
            "What the apic scheme moves the particles with: their new "
            "velocity v_p, or the re-projected grid velocity at the "
            "particle (the field of the stress update, as musl does).");
        }

        bool
        carries_affine() const override
        {
          return true;
        }

        /// @p prm is inside subsection "Transfer".
        explicit APIC(ParameterHandler &prm)
          : matrix_choice(prm.get("Affine matrix"))
          , flip_fraction(prm.get_double("FLIP fraction"))
          , flip_affine(prm.get_bool("FLIP affine matrix"))
          , xpic_order(prm.get_integer("XPIC order"))
          , move_with_grid(prm.get("Position update") == "grid velocity")
        {
        }

        void
        initialize(const State<dim> &state) override
        {
          setup(state);
          AssertThrow(xpic_order == 1 || mode == AffineMatrix::control_points,
                      ExcMessage(
                        "Transfer/XPIC order = " + std::to_string(xpic_order) +
                        " needs the control-point affine matrix (Transfer/"
                        "Affine matrix = control points, or automatic with a "
                        "quadratic space); the affine matrix here is '" +
                        matrix_choice + "' with a space of degree " +
                        std::to_string(state.space->degree()) + "."));
          AssertThrow(!flip_affine || mode == AffineMatrix::control_points,
                      ExcMessage(
                        "Transfer/FLIP affine matrix = true needs the "
                        "control-point affine matrix (Transfer/Affine matrix "
                        "= control points, or automatic with a quadratic "
                        "space); the affine matrix here is '" +
                        matrix_choice + "' with a space of degree " +
                        std::to_string(state.space->degree()) + "."));
        }

        bool
        step(State<dim>       &state,
             StabilityMonitor &monitor,
             PhaseTimer       &timer) override
        {
          setup(state);
          {
            PhaseTimer::Scope t(timer, "particle to grid");
            mass_to_grid(state);
            affine_momentum_to_grid(state);
          }
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          if (xpic_order > 1 && !xpic_correction(state, monitor, timer))
            return false;
          forces_to_grid(state, timer);
          if (!this->solve(state, state.grid_acceleration, monitor, timer))
            return false;
          if (state.boundary_conditions)
            state.boundary_conditions->after_acceleration(state);
          for (std::size_t l = 0; l < state.grid_velocity.size(); ++l)
            state.grid_velocity[l] += state.dt * state.grid_acceleration[l];
          if (state.boundary_conditions)
            state.boundary_conditions->impose_velocity(state);
          if (xpic_order > 1)
            {
              for (std::size_t l = 0; l < state.grid_velocity.size(); ++l)
                state.grid_velocity[l] += correction[l];
              if (state.boundary_conditions)
                state.boundary_conditions->impose_velocity(state);
            }
          velocities_to_particles(state, timer);
          {
            PhaseTimer::Scope t(timer, "particle to grid");
            affine_momentum_to_grid(state);
          }
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          if (state.boundary_conditions)
            state.boundary_conditions->impose_velocity(state);
          update_particle_state(state, monitor, timer);
          return true;
        }

      private:
        /// Control points in local relevant numbering (they depend only on
        /// the mesh and the DoF numbering) and the mode.
        void
        setup(const State<dim> &state)
        {
          if (matrix_choice == "none")
            mode = AffineMatrix::none;
          else if (matrix_choice == "control points" ||
                   (matrix_choice == "automatic" && state.space->degree() > 1))
            mode = AffineMatrix::control_points;
          else if (matrix_choice == "rotation" || matrix_choice == "automatic")
            mode = AffineMatrix::rotation;
          else
            mode = AffineMatrix::velocity_gradient;
          const auto &global = state.grid->relevant_global_indices();
          if (control_points.size() == global.size() && !global.empty())
            return;
          const std::vector<Point<dim>> all =
            state.space->control_points(state.dof_handler);
          control_points.resize(global.size());
          for (std::size_t l = 0; l < global.size(); ++l)
            control_points[l] = all[global[l]];
        }

        /// Per-cell particle mass (lumped and, for matrix strategies,
        /// consistent), then the strategy; Delta = its change of the cell
        /// matrices.
        void
        mass_to_grid(State<dim> &state)
        {
          auto &grid = *state.grid;
          grid.zero_cell_mass();
          const auto        &particles  = state.particles;
          const unsigned int n          = grid.dofs_per_cell;
          auto              &cells      = grid.cell_arrays();
          const bool         consistent = !cells.mass.empty();
          double            *lumped     = cells.lumped.data();
          double            *mass_mat   = cells.mass.data();
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int base = particles.cell[p] * n;
              const double       m    = particles.mass[p];
              const double      *phi  = &state.shape_values[p * n];
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double mk = m * phi[k];
                  lumped[base + k] += mk;
                  if (consistent)
                    {
                      double *row = mass_mat + (base + k) * n;
                      for (unsigned int l = 0; l < n; ++l)
                        row[l] += mk * phi[l];
                    }
                }
            }
          particle_mass = cells.lumped;
          if (consistent)
            delta = cells.mass;
          grid.assemble_mass();
          if (consistent)
            for (std::size_t i = 0; i < delta.size(); ++i)
              delta[i] = cells.mass[i] - delta[i];
        }

        /// The grid momentum of the particles' affine fields into the cell
        /// right-hand sides (see the class documentation).
        void
        affine_momentum_to_grid(State<dim> &state)
        {
          const auto &particles = state.particles;
          affine_momentum_to_grid(state,
                                  [&](const std::size_t p,
                                      Tensor<1, dim>   &v,
                                      Tensor<2, dim>   &C) {
                                    v = particles.velocity[p];
                                    C = particles.affine[p];
                                  });
        }

        /// The same for the affine fields that @p field(p, v, C) gives at
        /// the particles' positions (a template: the loop calls no
        /// function per particle).
        template <typename AffineField>
        void
        affine_momentum_to_grid(State<dim> &state, const AffineField &field)
        {
          auto &grid = *state.grid;
          grid.zero_cell_rhs();
          const auto         &particles  = state.particles;
          const unsigned int  n          = grid.dofs_per_cell;
          const unsigned int *dofs       = grid.cell_dofs().data();
          auto               &cells      = grid.cell_arrays();
          const bool          consistent = !cells.mass.empty();
          Tensor<1, dim>     *rhs        = cells.rhs.data();
          affine_momentum.assign(cells.rhs.size(), Tensor<1, dim>());
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int base = particles.cell[p] * n;
              const double       m    = particles.mass[p];
              const Point<dim>  &x    = particles.position[p];
              Tensor<1, dim>     v;
              Tensor<2, dim>     C;
              field(p, v, C);
              const double *phi = &state.shape_values[p * n];
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double mk = m * phi[k];
                  affine_momentum[base + k] +=
                    mk * (v + C * (control_points[dofs[base + k]] - x));
                  if (consistent)
                    rhs[base + k] += mk * v;
                }
            }
          if (!consistent)
            {
              cells.rhs.swap(affine_momentum);
              return;
            }
          // rhs += Delta u per cell, u_k = q_k / w_k.
          for (const unsigned int c : grid.owned_cells())
            {
              const unsigned int base = c * n;
              for (unsigned int l = 0; l < n; ++l)
                if (particle_mass[base + l] > 0)
                  {
                    const Tensor<1, dim> u =
                      affine_momentum[base + l] / particle_mass[base + l];
                    const double *D = &delta[base * n];
                    for (unsigned int k = 0; k < n; ++k)
                      if (D[k * n + l] != 0)
                        rhs[base + k] += D[k * n + l] * u;
                  }
            }
        }

        /**
         * XPIC(m) through the APIC transfers: with T the grid-to-particle
         * map (v_p and C_p = B_p D_p^{-1} of a grid field) and G the
         * particle-to-grid map (the grid momentum of the affine fields,
         * solved), Q = G T is symmetric and 0 <= Q <= I in the lumped mass
         * norm (T is the adjoint of G, and a particle's weighted least
         * squares fit has no more energy than the grid values it fits). APIC
         * replaces the particles by T v^{n+1}, so a grid mode that Q keeps
         * by q loses 1 - q of its amplitude every step: the damping of
         * resolved modes with lumped mass. With v^n = G s^n the particles
         * here take T (v^{n+1} + c), c = sum_{k=1}^{m-1} r_k, r_0 = v^n,
         * r_k = r_{k-1} - Q r_{k-1}: their new fields are (1 - (I - T G)^m)
         * s^n + T dt a, which loses (1 - q)^m per step, still removes
         * what the grid cannot see (q = 0) and is non-expansive. An affine
         * field is a fixed point of Q (c = 0), and both maps keep angular
         * momentum (c carries none), so both stay carried exactly.
         * c goes to `correction`; returns false on a failed solve.
         */
        bool
        xpic_correction(State<dim>       &state,
                        StabilityMonitor &monitor,
                        PhaseTimer       &timer)
        {
          residual = state.grid_velocity;
          correction.assign(residual.size(), Tensor<1, dim>());
          for (unsigned int k = 1; k < xpic_order; ++k)
            {
              {
                PhaseTimer::Scope t(timer, "particle to grid");
                // r_0 is a velocity: directions of D_p without support keep
                // the particle's C_p, as in the update itself; r_k, k > 0,
                // are differences of velocities, which keep nothing there.
                const bool keep_affine = k == 1;
                affine_momentum_to_grid(
                  state,
                  [&](const std::size_t p,
                      Tensor<1, dim>   &v,
                      Tensor<2, dim>   &C) {
                    affine_field(state, residual, p, keep_affine, v, C);
                  });
              }
              if (!this->solve(state, round_trip, monitor, timer))
                return false;
              for (std::size_t l = 0; l < residual.size(); ++l)
                {
                  residual[l] -= round_trip[l];
                  correction[l] += residual[l];
                }
            }
          return true;
        }

        /// T @p field at particle @p p: v = sum_i N_i w_i, C = B_p D_p^{-1}.
        void
        affine_field(const State<dim>                  &state,
                     const std::vector<Tensor<1, dim>> &field,
                     const std::size_t                  p,
                     const bool                         keep_affine,
                     Tensor<1, dim>                    &v,
                     Tensor<2, dim>                    &C) const
        {
          const auto             &particles = state.particles;
          const unsigned int      n         = state.grid->dofs_per_cell;
          const unsigned int     *dofs      = state.grid->cell_dofs().data();
          const unsigned int      base      = particles.cell[p] * n;
          const Point<dim>       &x         = particles.position[p];
          const double           *phi       = &state.shape_values[p * n];
          Tensor<2, dim>          B;
          SymmetricTensor<2, dim> D;
          v = Tensor<1, dim>();
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int    l  = dofs[base + k];
              const Tensor<1, dim> &vk = field[l];
              const Tensor<1, dim>  r  = control_points[l] - x;
              v += phi[k] * vk;
              B += phi[k] * outer_product(vk, r);
              D += phi[k] * symmetrize(outer_product(r, r));
            }
          C =
            affine_matrix(B,
                          D,
                          keep_affine ? particles.affine[p] : Tensor<2, dim>());
        }

        static void
        forces_to_grid(State<dim> &state, PhaseTimer &timer)
        {
          PhaseTimer::Scope t(timer, "particle to grid");
          auto             &grid = *state.grid;
          grid.zero_cell_rhs();
          const auto     &particles = state.particles;
          const unsigned  n         = grid.dofs_per_cell;
          Tensor<1, dim> *rhs       = grid.cell_arrays().rhs.data();
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int             base = particles.cell[p] * n;
              const double                   V    = particles.volume[p];
              const SymmetricTensor<2, dim> &s    = particles.stress[p];
              const Tensor<1, dim> external = particles.mass[p] * state.gravity;
              const double        *phi      = &state.shape_values[p * n];
              const Tensor<1, dim> *grad =
                state.gradients(p, particles.cell[p]);
              for (unsigned int k = 0; k < n; ++k)
                rhs[base + k] += phi[k] * external - V * (s * grad[k]);
            }
        }

        /// C = B D^{-1} on the eigendirections of D with support (relative
        /// to its trace: scale-free), the old C on the others. Closed form
        /// (no iterative eigensolver that could throw on a non-finite D of
        /// a run going unstable: NaN passes to the stability monitor).
        static Tensor<2, dim>
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
              // |(0.5 (a - c), b)| relative to the trace, so that no
              // square can overflow or underflow: std::hypot does the same
              // scaling per call at several times the cost (3.5 % of the
              // free Powell-Sabin throughput bar, perf).
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

        void
        velocities_to_particles(State<dim> &state, PhaseTimer &timer) const
        {
          PhaseTimer::Scope   t(timer, "grid to particle");
          auto               &particles = state.particles;
          const unsigned int  n         = state.grid->dofs_per_cell;
          const unsigned int *dofs      = state.grid->cell_dofs().data();
          const bool          fit       = mode == AffineMatrix::control_points;
          const bool affine_increment = fit && flip_affine && flip_fraction > 0;
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int      base = particles.cell[p] * n;
              const Point<dim>       &x    = particles.position[p];
              const double           *phi  = &state.shape_values[p * n];
              Tensor<1, dim>          v;
              Tensor<2, dim>          B, B_increment;
              SymmetricTensor<2, dim> D;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const unsigned int    l  = dofs[base + k];
                  const Tensor<1, dim> &vk = state.grid_velocity[l];
                  v += phi[k] * vk;
                  if (fit)
                    {
                      const Tensor<1, dim> r = control_points[l] - x;
                      B += phi[k] * outer_product(vk, r);
                      D += phi[k] * symmetrize(outer_product(r, r));
                      if (affine_increment)
                        B_increment +=
                          phi[k] * outer_product(state.grid_acceleration[l], r);
                    }
                }
              if (flip_fraction > 0)
                {
                  Tensor<1, dim> a;
                  for (unsigned int k = 0; k < n; ++k)
                    a += phi[k] * state.grid_acceleration[dofs[base + k]];
                  particles.velocity[p] =
                    (1 - flip_fraction) * v +
                    flip_fraction * (particles.velocity[p] + state.dt * a);
                }
              else
                particles.velocity[p] = v;
              if (affine_increment)
                particles.affine[p] =
                  (1 - flip_fraction) *
                    affine_matrix(B, D, particles.affine[p]) +
                  flip_fraction *
                    (particles.affine[p] +
                     state.dt *
                       affine_matrix(B_increment, D, Tensor<2, dim>()));
              else if (fit)
                particles.affine[p] = affine_matrix(B, D, particles.affine[p]);
              else if (mode == AffineMatrix::none)
                particles.affine[p] = Tensor<2, dim>();
            }
        }

        /// Stress from the gradient of the projected field, positions with
        /// v_p, and, for the velocity-gradient mode, the new C_p.
        void
        update_particle_state(State<dim>       &state,
                              StabilityMonitor &monitor,
                              PhaseTimer       &timer)
        {
          PhaseTimer::Scope   t(timer, "update");
          auto               &particles = state.particles;
          const unsigned int  n         = state.grid->dofs_per_cell;
          const unsigned int *dofs      = state.grid->cell_dofs().data();
          const double        dt        = state.dt;
          const bool gradient = mode == AffineMatrix::velocity_gradient;
          const bool rotation = mode == AffineMatrix::rotation;
          Particles::resize_per_particle(increments, particles);
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int    base = particles.cell[p] * n;
              const Tensor<1, dim> *grad =
                state.gradients(p, particles.cell[p]);
              Tensor<2, dim> L; // L_ij = dv_i/dx_j
              for (unsigned int k = 0; k < n; ++k)
                L +=
                  outer_product(state.grid_velocity[dofs[base + k]], grad[k]);
              Tensor<1, dim> velocity = particles.velocity[p];
              if (move_with_grid)
                {
                  const double *phi = &state.shape_values[p * n];
                  velocity          = Tensor<1, dim>();
                  for (unsigned int k = 0; k < n; ++k)
                    velocity += phi[k] * state.grid_velocity[dofs[base + k]];
                }
              if (gradient)
                particles.affine[p] = L;
              else if (rotation)
                particles.affine[p] = 0.5 * (L - transpose(L));
              increments[p]           = dt * L;
              const Tensor<1, dim> du = dt * velocity;
              particles.displacement[p] += du;
              particles.position[p] += du;
            }
          this->update_material(state, increments, volume_ratio, monitor);
        }

        std::string             matrix_choice;
        double                  flip_fraction = 0;
        bool                    flip_affine   = false;
        AffineMatrix            mode          = AffineMatrix::control_points;
        bool                    flip          = false; ///< FLIP velocity update
        std::vector<Point<dim>> control_points; ///< local relevant numbering
        // Per-step arrays, kept to avoid reallocation.
        std::vector<double>         particle_mass; ///< w_k per cell DoF
        std::vector<double>         delta; ///< strategy's change, per cell
        std::vector<Tensor<1, dim>> affine_momentum; ///< q_k per cell DoF
        std::vector<Tensor<2, dim>> increments;
        std::vector<double>         volume_ratio;
        // XPIC(m): grid fields in local relevant numbering.
        unsigned int                xpic_order     = 1;
        bool                        move_with_grid = false;
        std::vector<Tensor<1, dim>> residual, round_trip, correction;
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, APIC> register_apic(
      "apic",
      "affine particle-in-cell (Jiang et al. 2015) through the space's "
      "control points: carries affine velocity fields, keeps angular "
      "momentum with lumped and partially lumped mass",
      &APIC<2>::declare_parameters);
  } // namespace Simulator
} // namespace psmpm
