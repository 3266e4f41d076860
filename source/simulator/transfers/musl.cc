// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/contact_coupling.h>
#include <psmpm/simulator/particle_loops.h>
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
          if (state.boundary_conditions)
            state.boundary_conditions->after_acceleration(state);
          if (state.contact)
            state.contact->correct_momentum(state);
          update_particle_velocities(state, timer);
          if (state.contact)
            state.contact->add_velocity_increments(state, true);
          if (!this->solve(state, state.grid_velocity, monitor, timer))
            return false;
          if (state.boundary_conditions)
            {
              state.boundary_conditions->impose_velocity(state);
              state.boundary_conditions->stop_particles(state);
            }
          if (state.contact)
            state.contact->correct_moving_velocity(state);
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
            ParticleLoops::accelerate_particles(state, !fitted);
          }
          if (fitted)
            TransferScheme<dim>::momentum_to_grid(state, timer);
        }

        void
        update_particle_state(State<dim>       &state,
                              StabilityMonitor &monitor,
                              PhaseTimer       &timer)
        {
          this->template move_and_update_material<
            ParticleLoops::VelocityUpdate::keep>(state, monitor, timer);
        }
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, MUSL>
      register_musl("musl", "modified update stress last (thesis Fig. 2.5)");
  } // namespace Simulator
} // namespace psmpm
