// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/transfer_scheme.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /**
       * The modified update of thesis Fig. 2.5 (Sulsky's MUSL): particle
       * momentum and internal force to the grid, grid acceleration,
       * particle velocities, then the grid velocity projected again from
       * the updated particle momentum for the stress and position update.
       * Every particle loop reads the basis cache of the state; the
       * material updates all particles in one call.
       */
      template <int dim>
      class MUSL : public TransferScheme<dim>
      {
      public:
        bool
        step(State<dim>       &state,
             StabilityMonitor &monitor,
             PhaseTimer       &timer) override
        {
          this->particles_to_grid(state, timer, 0., 1.);
          if (!this->solve_acceleration(state, monitor, timer))
            return false;
          update_particle_velocities(state, timer);
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          update_particle_state(state, monitor, timer);
          return true;
        }

      private:
        static void
        update_particle_velocities(State<dim> &state, PhaseTimer &timer)
        {
          // A reconstruction that fits the momentum maps it itself.
          const bool fitted =
            state.reconstruction && state.reconstruction->fits_momentum();
          {
            PhaseTimer::Scope t(timer, "grid to particle");
            accelerate_particles(state, !fitted);
          }
          if (fitted)
            TransferScheme<dim>::momentum_to_grid(state, timer);
        }

        /// v_p += dt sum_i a_i N_i(x_p), and, if @p momentum_to_grid, the
        /// cell right-hand sides of the updated momentum m_p v_p N_i in the
        /// same pass.
        static void
        accelerate_particles(State<dim> &state, const bool momentum_to_grid)
        {
          auto &grid = *state.grid;
          if (momentum_to_grid)
            grid.zero_cell_rhs();
          auto               &particles = state.particles;
          const unsigned int  n         = grid.dofs_per_cell;
          const unsigned int *dofs      = grid.cell_dofs().data();
          Tensor<1, dim>     *rhs       = grid.cell_arrays().rhs.data();
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int base = particles.cell[p] * n;
              const double      *phi  = &state.shape_values[p * n];
              Tensor<1, dim>     a;
              for (unsigned int k = 0; k < n; ++k)
                a += phi[k] * state.grid_acceleration[dofs[base + k]];
              particles.velocity[p] += state.dt * a;
              if (!momentum_to_grid)
                continue;
              const Tensor<1, dim> momentum =
                particles.mass[p] * particles.velocity[p];
              for (unsigned int k = 0; k < n; ++k)
                rhs[base + k] += phi[k] * momentum;
            }
        }

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
          increments.resize(particles.size());
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int    base = particles.cell[p] * n;
              const double         *phi  = &state.shape_values[p * n];
              const Tensor<1, dim> *grad = &state.shape_gradients[p * n];
              Tensor<1, dim>        v;
              Tensor<2, dim>        L; // velocity gradient, L_ij = dv_i/dx_j
              for (unsigned int k = 0; k < n; ++k)
                {
                  const Tensor<1, dim> &vk =
                    state.grid_velocity[dofs[base + k]];
                  v += phi[k] * vk;
                  L += outer_product(vk, grad[k]);
                }
              increments[p]           = dt * L;
              const Tensor<1, dim> du = dt * v;
              particles.displacement[p] += du;
              particles.position[p] += du;
            }
          this->update_material(state, increments, volume_ratio, monitor);
        }

        // Per-step scratch, kept to avoid reallocation.
        std::vector<Tensor<2, dim>> increments;
        std::vector<double>         volume_ratio;
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, MUSL>
      register_musl("musl", "modified update stress last (thesis Fig. 2.5)");
  } // namespace Simulator
} // namespace psmpm
