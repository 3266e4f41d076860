// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/apic_particle_loops.h>
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/contact_coupling.h>
#include <psmpm/simulator/transfer_scheme.h>
#include <psmpm/simulator/transfer_scheme.templates.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      using ApicLoops::AffineMatrix;

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
       * again; the gradient of that field drives the material update and
       * the field itself moves the particles, so that a particle's
       * deformation gradient and its motion come from one velocity field.
       * Moving them with v_p instead (an option) lets material move where
       * the strain does not see it: an elastic column that should rock
       * on its floor flows out (doc/transfers.md).
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
            "grid velocity",
            Patterns::Selection("particle velocity|grid velocity"),
            "What the apic scheme moves the particles with: the "
            "re-projected grid velocity at the particle (the field whose "
            "gradient updates the stress, as musl does), or their new "
            "velocity v_p (APIC as published; motion the re-projected "
            "field does not carry then deforms no particle).");
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
          // Contact's increments are those of the PIC update v_p = sum_i
          // N_i v_i^{n+1}: no FLIP blend, no XPIC correction.
          AssertThrow(!state.contact || (xpic_order == 1 && flip_fraction == 0),
                      ExcMessage("Contact/Type = multi-velocity with "
                                 "Transfer/Scheme = apic: not available with "
                                 "Transfer/XPIC order = " +
                                 std::to_string(xpic_order) +
                                 " and Transfer/FLIP fraction = " +
                                 prm_value(flip_fraction) +
                                 " (1 and 0 are)."));
        }

        bool
        step(State<dim>       &state,
             StabilityMonitor &monitor,
             PhaseTimer       &timer) override
        {
          setup(state);
          {
            PhaseTimer::Scope t(timer, "particle to grid");
            // The last step's update summed the particles as they are now
            // (State::forces_in_cells); else one pass here.
            if (!state.forces_in_cells)
              {
                start_cells(state);
                add_to_cells(state, 0, state.particles.size());
              }
            state.forces_in_cells = false;
            state.cell_forces.add_to(forces.data(),
                                     state.grid->dofs_per_cell,
                                     1.);
            assemble_mass(state);
            finish_momentum(state);
          }
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          if (xpic_order > 1 && !xpic_correction(state, monitor, timer))
            return false;
          state.grid->cell_arrays().rhs.swap(forces);
          if (!this->solve(state, state.grid_acceleration, monitor, timer))
            return false;
          advance_grid_velocity(state);
          if (state.contact)
            state.contact->correct_affine_momentum(state,
                                                   control_points.data());
          {
            PhaseTimer::Scope t(timer, "grid to particle");
            accelerate_particles(state);
          }
          if (state.contact)
            state.contact->add_affine_increments(
              state, mode == AffineMatrix::control_points);
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          if (state.boundary_conditions)
            state.boundary_conditions->impose_velocity(state);
          if (state.contact)
            state.contact->correct_moving_velocity(state);
          // Move, material update, locate and the next step's sums, chunk
          // by chunk.
          Kernels kernels{*this};
          this->update_in_chunks(state, monitor, timer, kernels);
          return true;
        }

      private:
        /// The particle loops of update_in_chunks().
        struct Kernels
        {
          APIC &apic;

          void
          move(State<dim>       &state,
               const std::size_t first,
               const std::size_t last,
               Tensor<2, dim>   *increments) const
          {
            const ApicLoops::Move options{apic.move_with_grid,
                                          apic.mode ==
                                            AffineMatrix::velocity_gradient,
                                          apic.mode == AffineMatrix::rotation};
            ApicLoops::move(state,
                            apic.grid_view(state),
                            options,
                            first,
                            last,
                            increments);
            if (state.contact)
              state.contact->move_affine(state,
                                         first,
                                         last,
                                         increments,
                                         options.with_grid_velocity,
                                         options.gradient,
                                         options.rotation);
          }

          static bool
          accumulates(const State<dim> &)
          {
            return true;
          }

          void
          start_cells(State<dim> &state) const
          {
            apic.start_cells(state);
          }

          void
          add_to_cells(State<dim>       &state,
                       const std::size_t first,
                       const std::size_t last) const
          {
            apic.add_to_cells(state, first, last);
          }

          static void
          finish_cells(State<dim> &)
          {
          }
        };

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

        ApicLoops::Grid<dim>
        grid_view(const State<dim> &state) const
        {
          return {control_points.data(), state.grid->cell_dofs().data()};
        }

        /// Zero the sums of the start of a step: mass (cell arrays),
        /// affine momentum, consistent momentum (cell right-hand sides)
        /// and forces.
        void
        start_cells(State<dim> &state)
        {
          auto &grid = *state.grid;
          grid.zero_cell_mass();
          grid.zero_cell_rhs();
          const std::size_t size = grid.cell_arrays().rhs.size();
          affine_momentum.assign(size, Tensor<1, dim>());
          forces.assign(size, Tensor<1, dim>());
        }

        /// The particles [@p first, @p last) into those sums.
        void
        add_to_cells(State<dim>       &state,
                     const std::size_t first,
                     const std::size_t last)
        {
          auto                          &cells      = state.grid->cell_arrays();
          const bool                     consistent = !cells.mass.empty();
          const ApicLoops::CellSums<dim> sums{cells.lumped.data(),
                                              consistent ? cells.mass.data() :
                                                           nullptr,
                                              affine_momentum.data(),
                                              consistent ? cells.rhs.data() :
                                                           nullptr,
                                              forces.data()};
          ApicLoops::add_to_cells(state, grid_view(state), sums, first, last);
        }

        /// The strategy's mass from the particle mass in the cell arrays;
        /// Delta = its change of the cell matrices.
        void
        assemble_mass(State<dim> &state)
        {
          auto      &grid       = *state.grid;
          auto      &cells      = grid.cell_arrays();
          const bool consistent = !cells.mass.empty();
          particle_mass         = cells.lumped;
          if (consistent)
            delta = cells.mass;
          grid.assemble_mass();
          if (consistent)
            for (std::size_t i = 0; i < delta.size(); ++i)
              delta[i] = cells.mass[i] - delta[i];
        }

        /// Zero the momentum sums of a projection; returns where a pass
        /// adds them (the affine momentum, and the consistent momentum in
        /// the cell right-hand sides if the strategy has a matrix).
        ApicLoops::CellSums<dim>
        start_momentum(State<dim> &state)
        {
          state.grid->zero_cell_rhs();
          auto &cells = state.grid->cell_arrays();
          affine_momentum.assign(cells.rhs.size(), Tensor<1, dim>());
          const bool consistent = !cells.mass.empty();
          return {nullptr,
                  nullptr,
                  affine_momentum.data(),
                  consistent ? cells.rhs.data() : nullptr,
                  nullptr};
        }

        /// The grid momentum of the particles' affine fields into the cell
        /// right-hand sides (see the class documentation) from the sums
        /// of a projection: q_k with lumped mass, else the consistent
        /// momentum plus Delta u per cell, u_k = q_k / w_k.
        void
        finish_momentum(State<dim> &state)
        {
          auto              &grid  = *state.grid;
          auto              &cells = grid.cell_arrays();
          const unsigned int n     = grid.dofs_per_cell;
          if (cells.mass.empty())
            {
              cells.rhs.swap(affine_momentum);
              return;
            }
          Tensor<1, dim> *rhs = cells.rhs.data();
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

        /// The grid momentum of the affine fields that @p field(p, v, C)
        /// gives at the particles' positions (a template: the loop calls
        /// no function per particle).
        template <typename AffineField>
        void
        affine_momentum_to_grid(State<dim> &state, const AffineField &field)
        {
          const ApicLoops::CellSums<dim> sums      = start_momentum(state);
          const auto                    &particles = state.particles;
          const ApicLoops::Grid<dim>     grid      = grid_view(state);
          const unsigned int             n         = state.grid->dofs_per_cell;
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              Tensor<1, dim> v;
              Tensor<2, dim> C;
              field(p, v, C);
              ApicLoops::add_momentum<dim, false>(state,
                                                  grid,
                                                  sums,
                                                  p,
                                                  n,
                                                  v,
                                                  C);
            }
          finish_momentum(state);
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
          C = ApicLoops::affine_matrix(B,
                                       D,
                                       keep_affine ? particles.affine[p] :
                                                     Tensor<2, dim>());
        }

        /// v^{n+1} = v^n + dt a on the grid, with the boundary conditions
        /// and the XPIC correction.
        void
        advance_grid_velocity(State<dim> &state) const
        {
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
        }

        /// The particles' new velocities and affine matrices and, in the
        /// same pass, the grid momentum of their new affine fields.
        void
        accelerate_particles(State<dim> &state)
        {
          const ApicLoops::CellSums<dim> sums = start_momentum(state);
          const bool fit  = mode == AffineMatrix::control_points;
          const bool flip = flip_fraction > 0;
          const auto run  = [&](const auto fit_c, const auto flip_c) {
            const ApicLoops::
              Update<dim, decltype(fit_c)::value, decltype(flip_c)::value>
                update{flip_fraction,
                       fit && flip_affine && flip,
                       state.dt,
                       mode == AffineMatrix::none};
            ApicLoops::accelerate(state, grid_view(state), update, sums);
          };
          using Yes = std::true_type;
          using No  = std::false_type;
          if (fit && flip)
            run(Yes(), Yes());
          else if (fit)
            run(Yes(), No());
          else if (flip)
            run(No(), Yes());
          else
            run(No(), No());
          finish_momentum(state);
        }

        std::string             matrix_choice;
        double                  flip_fraction = 0;
        bool                    flip_affine   = false;
        AffineMatrix            mode          = AffineMatrix::control_points;
        std::vector<Point<dim>> control_points; ///< local relevant numbering
        // Per-step arrays, kept to avoid reallocation.
        std::vector<double>         particle_mass; ///< w_k per cell DoF
        std::vector<double>         delta; ///< strategy's change, per cell
        std::vector<Tensor<1, dim>> affine_momentum; ///< q_k per cell DoF
        std::vector<Tensor<1, dim>> forces;          ///< f_k per cell DoF
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
