// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_particle_loops_h
#define psmpm_simulator_particle_loops_h

#include <deal.II/base/tensor.h>

#include <psmpm/simulator/state.h>

#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * The particle loops of the transfer schemes, between the particles
     * and the per-cell arrays or grid fields of a State: one pass over
     * the particles each, reading the basis cache (state.shape_values,
     * state.gradients()) and the cell DoFs. The schemes call them,
     * and so does benchmarks/step_phases.cc, which times these very
     * loops. They allocate nothing per particle and call nothing virtual.
     */
    namespace ParticleLoops
    {
      /**
       * Zero the cell arrays, then add every particle's mass (lumped,
       * and consistent if the grid keeps cell mass matrices) and the cell
       * right-hand sides momentum_weight m_p v_p N_i + force_weight (m_p
       * g N_i - V_p sigma_p grad N_i) (add_point()): the particle loop of
       * TransferScheme::particles_to_grid, which then assembles the mass.
       * Writes the cell arrays of the state's grid, nothing else.
       */
      template <int dim>
      void
      particles_to_cells(const State<dim> &state,
                         const double      momentum_weight,
                         const double      force_weight);

      /**
       * The particle loop of particles_to_cells() for the particles
       * [@p first, @p last) alone, into cell arrays the caller has zeroed
       * (grid.zero_cell_mass() and zero_cell_rhs()). Ranges in particle
       * order from the first give the sums of particles_to_cells(), bit
       * for bit, once finish_particles_to_cells() has run.
       */
      template <int dim>
      void
      add_particles_to_cells(const State<dim> &state,
                             const double      momentum_weight,
                             const double      force_weight,
                             const std::size_t first,
                             const std::size_t last);

      /// After the last add_particles_to_cells(): the cell mass matrices'
      /// lower triangles (symmetrize_cell_mass()).
      template <int dim>
      void
      finish_particles_to_cells(const State<dim> &state);

      /**
       * v_p += dt sum_i a_i N_i(x_p) (MUSL's first grid-to-particle
       * pass), and, if @p momentum_to_grid, the cell right-hand sides of
       * the updated momentum m_p v_p N_i in the same pass (zeroed first).
       */
      template <int dim>
      void
      accelerate_particles(State<dim> &state, const bool momentum_to_grid);

      /// What move_particles() does to the particle velocity.
      enum class VelocityUpdate
      {
        /// Left as it is (MUSL: accelerate_particles() updated it).
        keep,
        /// FLIP: v_p += dt sum_i a_i N_i(x_p) (USL).
        flip,
        /// The grid velocity at the particle, v_p = sum_i v_i N_i(x_p)
        /// (OTM: the velocity of the transport map).
        grid
      };

/// Apply @p M(dim, update) to every dimension and VelocityUpdate: the
/// explicit instantiations of the templates on VelocityUpdate (here and
/// in TransferScheme) follow this one list.
#define PSMPM_FOR_VELOCITY_UPDATES(M) \
  M(1, keep)                          \
  M(2, keep)                          \
  M(1, flip)                          \
  M(2, flip)                          \
  M(1, grid)                          \
  M(2, grid)

      /**
       * The grid velocity v_i = state.grid_velocity at every particle:
       * positions and displacements advance by dt sum_i v_i N_i(x_p), the
       * strain increments dt L_p, L_p = sum_i v_i (x) grad N_i(x_p), go to
       * @p increments (resized to the number of particles), and the
       * velocity is updated as @p velocity_update says (a template
       * argument: the particle loop has no branch for it).
       */
      template <int dim, VelocityUpdate velocity_update>
      void
      move_particles(State<dim>                  &state,
                     std::vector<Tensor<2, dim>> &increments);

      /// The same for the particles [@p first, @p last): the increment of
      /// particle p goes to increments[p - first].
      template <int dim, VelocityUpdate velocity_update>
      void
      move_particles(State<dim>       &state,
                     const std::size_t first,
                     const std::size_t last,
                     Tensor<2, dim>   *increments);
    } // namespace ParticleLoops
  }   // namespace Simulator
} // namespace psmpm

#endif
