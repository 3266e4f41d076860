// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/base/prefetch.h>
#include <psmpm/simulator/contact_coupling.h>
#include <psmpm/simulator/particle_loops.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/transfer_scheme.h>
#include <psmpm/simulator/transfer_scheme.templates.h>
#include <psmpm/solver/solver_failure.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    TransferScheme<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Transfer");
      prm.declare_entry(
        "Scheme",
        "automatic",
        Patterns::Selection(
          "automatic|" + TransferSchemeRegistry<dim>::instance().selection()),
        "automatic: the basis' measured default (apic for powell-sabin with "
        "lumped mass, musl otherwise; doc/transfers.md); " +
          TransferSchemeRegistry<dim>::instance().documentation());
      prm.declare_entry(
        "Volumetric strain",
        "particle",
        Patterns::Selection("particle|cell average"),
        "particle: each particle's strain increment from the grid velocity "
        "gradient at the particle; cell average: its volumetric part "
        "replaced by its cell's volume change, and the internal forces "
        "take the cell's mean pressure (B-bar, against volumetric locking "
        "of isochoric plastic flow and nearly incompressible materials "
        "with Powell-Sabin; doc/geomechanics.md): in a cell inside one "
        "body (half filled or more, every cell around its functions "
        "holding that body alone) the volume change of the grid velocity "
        "integrated exactly over the cell and the pressure's force "
        "integrated exactly; elsewhere (free surfaces, cells shared by "
        "bodies or next to a contact, and with otm) the volume-weighted "
        "means over the particles of the same body in the same cell. The "
        "same on P1, whose gradients are constant on cells: the average "
        "is skipped there.");
      TransferSchemeRegistry<dim>::instance().declare_parameters(prm);
      Reconstruction<dim>::declare_parameters(prm);
      prm.leave_subsection();
    }

    namespace
    {
      template <int dim>
      bool
      solve_reported(State<dim>                  &state,
                     std::vector<Tensor<1, dim>> &solution,
                     StabilityMonitor            &monitor,
                     PhaseTimer                  &timer,
                     const bool                   lumped)
      {
        try
          {
            PhaseTimer::Scope t(timer, "solve");
            state.grid->solve(solution, lumped);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            monitor.report(Failure::solver,
                           "mass matrix solver did not converge (" +
                             std::to_string(e.last_step) +
                             " iterations, residual " +
                             prm_value(e.last_residual) + ")");
            return false;
          }
        catch (const Solver::SolverFailure &e)
          {
            monitor.report(Failure::solver,
                           std::string("mass matrix solver failed: ") +
                             e.what());
            return false;
          }
        return true;
      }
    } // namespace

    template <int dim>
    bool
    TransferScheme<dim>::solve(State<dim>                  &state,
                               std::vector<Tensor<1, dim>> &solution,
                               StabilityMonitor            &monitor,
                               PhaseTimer                  &timer)
    {
      return solve_reported(state, solution, monitor, timer, false);
    }

    template <int dim>
    bool
    TransferScheme<dim>::solve_acceleration(State<dim>       &state,
                                            StabilityMonitor &monitor,
                                            PhaseTimer       &timer)
    {
      const bool lumped =
        state.reconstruction && state.reconstruction->lumped_acceleration();
      return solve_reported(state,
                            state.grid_acceleration,
                            monitor,
                            timer,
                            lumped);
    }

    template <int dim>
    void
    TransferScheme<dim>::particles_to_grid(State<dim>  &state,
                                           PhaseTimer  &timer,
                                           const double momentum_weight,
                                           const double force_weight)
    {
      PhaseTimer::Scope t(timer, "particle to grid");
      auto             &grid = *state.grid;
      if (state.reconstruction)
        {
          grid.zero_cell_mass();
          grid.zero_cell_rhs();
          state.reconstruction->mass_and_forces(state,
                                                momentum_weight,
                                                force_weight);
        }
      else if (!(state.forces_in_cells && momentum_weight == 0 &&
                 force_weight == 1))
        ParticleLoops::particles_to_cells(state, momentum_weight, force_weight);
      state.forces_in_cells = false;
      state.cell_forces.add_to(grid.cell_arrays().rhs.data(),
                               grid.dofs_per_cell,
                               force_weight);
      grid.assemble_mass();
    }

    template <int dim>
    void
    TransferScheme<dim>::momentum_to_grid(State<dim> &state, PhaseTimer &timer)
    {
      PhaseTimer::Scope t(timer, "particle to grid");
      auto             &grid = *state.grid;
      grid.zero_cell_rhs();
      if (state.reconstruction && state.reconstruction->fits_momentum())
        {
          state.reconstruction->momentum(state);
          return;
        }
      const auto        &particles = state.particles;
      const unsigned int n         = grid.dofs_per_cell;
      Tensor<1, dim>    *rhs       = grid.cell_arrays().rhs.data();
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int   base = particles.cell[p] * n;
          const double        *phi  = &state.shape_values[p * n];
          const Tensor<1, dim> momentum =
            particles.mass[p] * particles.velocity[p];
          for (unsigned int k = 0; k < n; ++k)
            rhs[base + k] += phi[k] * momentum;
        }
    }

    template <int dim>
    void
    TransferScheme<dim>::update_material(
      State<dim>                        &state,
      const std::vector<Tensor<2, dim>> &increments,
      std::vector<double>               &volume_ratio,
      StabilityMonitor                  &monitor)
    {
      Particles::resize_per_particle(volume_ratio, state.particles);
      update_material(state,
                      0,
                      state.particles.size(),
                      increments.data(),
                      volume_ratio.data(),
                      monitor);
    }

    template <int dim>
    void
    TransferScheme<dim>::update_material(State<dim>           &state,
                                         const std::size_t     first,
                                         const std::size_t     last,
                                         const Tensor<2, dim> *increments,
                                         double               *volume_ratio,
                                         StabilityMonitor     &monitor)
    {
      auto &particles = state.particles;
      state.materials.update(particles, first, last, increments, volume_ratio);
      for (std::size_t p = first; p < last; ++p)
        {
          // The first loop of the update's chunks to read these
          // (prefetch.h).
          if (p + prefetch_distance < particles.size())
            {
              prefetch_lines(&particles.volume[p + prefetch_distance]);
              prefetch_lines(&particles.density[p + prefetch_distance]);
            }
          particles.volume[p] *= volume_ratio[p - first];
          particles.density[p] /= volume_ratio[p - first];
          if (!(particles.volume[p] > 0))
            monitor.report(Failure::non_positive_volume,
                           "non-positive particle volume (particle " +
                             std::to_string(particles.id[p]) + ")");
        }
    }

    namespace
    {
      /// The particle loops of move_and_update_material() for
      /// update_in_chunks(): the grid velocity moves the particles, and
      /// their mass and forces go to the cell arrays (particles_to_grid()
      /// with weights 0 and 1).
      template <int dim, ParticleLoops::VelocityUpdate velocity_update>
      struct GridVelocityKernels
      {
        static void
        move(State<dim>       &state,
             const std::size_t first,
             const std::size_t last,
             Tensor<2, dim>   *increments)
        {
          ParticleLoops::move_particles<dim, velocity_update>(state,
                                                              first,
                                                              last,
                                                              increments);
        }

        /// A reconstruction maps mass and forces itself.
        static bool
        accumulates(const State<dim> &state)
        {
          return !state.reconstruction;
        }

        static void
        start_cells(State<dim> &state)
        {
          state.grid->zero_cell_mass();
          state.grid->zero_cell_rhs();
        }

        static void
        add_to_cells(State<dim>       &state,
                     const std::size_t first,
                     const std::size_t last)
        {
          ParticleLoops::add_particles_to_cells(state, 0., 1., first, last);
        }

        static void
        finish_cells(State<dim> &state)
        {
          ParticleLoops::finish_particles_to_cells(state);
        }
      };

      /// GridVelocityKernels whose particles of each body near a contact
      /// then move with the body's own velocity (ContactCoupling::move(),
      /// once per chunk).
      template <int dim, ParticleLoops::VelocityUpdate velocity_update>
      struct ContactKernels : GridVelocityKernels<dim, velocity_update>
      {
        static void
        move(State<dim>       &state,
             const std::size_t first,
             const std::size_t last,
             Tensor<2, dim>   *increments)
        {
          GridVelocityKernels<dim, velocity_update>::move(state,
                                                          first,
                                                          last,
                                                          increments);
          state.contact->move(state, first, last, increments);
        }
      };
    } // namespace

    template <int dim>
    template <ParticleLoops::VelocityUpdate velocity_update>
    void
    TransferScheme<dim>::move_and_update_material(State<dim>       &state,
                                                  StabilityMonitor &monitor,
                                                  PhaseTimer       &timer)
    {
      if (state.contact)
        {
          ContactKernels<dim, velocity_update> kernels;
          update_in_chunks(state, monitor, timer, kernels);
          return;
        }
      GridVelocityKernels<dim, velocity_update> kernels;
      update_in_chunks(state, monitor, timer, kernels);
    }

    template class TransferScheme<1>;
    template class TransferScheme<2>;
#define PSMPM_INSTANTIATE(DIM, UPDATE)                         \
  template void TransferScheme<DIM>::move_and_update_material< \
    ParticleLoops::VelocityUpdate::UPDATE>(State<DIM> &,       \
                                           StabilityMonitor &, \
                                           PhaseTimer &);
    PSMPM_FOR_VELOCITY_UPDATES(PSMPM_INSTANTIATE)
#undef PSMPM_INSTANTIATE
  } // namespace Simulator
} // namespace psmpm
