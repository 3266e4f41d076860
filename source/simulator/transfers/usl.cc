// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/transfer_scheme.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /**
       * The original update stress last scheme (Sulsky et al. 1994;
       * Algorithm 2 of Wobbes et al. 2019): grid acceleration a = M^{-1} f
       * and velocity v = M^{-1} l from the particles, v^{n+1} = v + dt a;
       * particle velocities by FLIP (v_p += dt sum_i N_i a_i), positions
       * and strain increments with v^{n+1} itself, without MUSL's second
       * projection. It is the MPM against which the paper compares OTM
       * (doc/otm.md); a nearly empty function's v^{n+1} enters the stress
       * unbounded (doc/transfers.md), which is why MUSL is the default.
       */
      template <int dim>
      class USL : public TransferScheme<dim>
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
          this->momentum_to_grid(state, timer);
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          for (unsigned int i = 0; i < state.grid_velocity.size(); ++i)
            state.grid_velocity[i] += state.dt * state.grid_acceleration[i];
          update_particles(state, monitor, timer);
          return true;
        }

      private:
        void
        update_particles(State<dim>       &state,
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
              Tensor<1, dim>        v, a;
              Tensor<2, dim>        L;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const unsigned int i = dofs[base + k];
                  v += phi[k] * state.grid_velocity[i];
                  a += phi[k] * state.grid_acceleration[i];
                  L += outer_product(state.grid_velocity[i], grad[k]);
                }
              particles.velocity[p] += dt * a;
              const Tensor<1, dim> du = dt * v;
              particles.displacement[p] += du;
              particles.position[p] += du;
              increments[p] = dt * L;
            }
          this->update_material(state, increments, volume_ratio, monitor);
        }

        // Per-step scratch, kept to avoid reallocation.
        std::vector<Tensor<2, dim>> increments;
        std::vector<double>         volume_ratio;
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, USL> register_usl(
      "usl",
      "update stress last without the second projection (Sulsky et al. "
      "1994; Algorithm 2 of Wobbes et al. 2019, the MPM compared with otm)");
  } // namespace Simulator
} // namespace psmpm
