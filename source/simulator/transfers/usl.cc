// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/particle_loops.h>
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
          if (state.boundary_conditions)
            state.boundary_conditions->after_acceleration(state);
          this->momentum_to_grid(state, timer);
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          for (unsigned int i = 0; i < state.grid_velocity.size(); ++i)
            state.grid_velocity[i] += state.dt * state.grid_acceleration[i];
          if (state.boundary_conditions)
            state.boundary_conditions->impose_velocity(state);
          update_particles(state, monitor, timer);
          return true;
        }

      private:
        void
        update_particles(State<dim>       &state,
                         StabilityMonitor &monitor,
                         PhaseTimer       &timer)
        {
          this->template move_and_update_material<
            ParticleLoops::VelocityUpdate::flip>(state, monitor, timer);
        }
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, USL> register_usl(
      "usl",
      "update stress last without the second projection (Sulsky et al. "
      "1994; Algorithm 2 of Wobbes et al. 2019, the MPM compared with otm)");
  } // namespace Simulator
} // namespace psmpm
