// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/prefetch.h>
#include <psmpm/simulator/particle_loops.h>
#include <psmpm/simulator/point_accumulation.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace ParticleLoops
    {
      // Loops over a cell's functions with the common counts as
      // compile-time constants (point_accumulation.h).
      using internal::with_functions_per_cell;

      template <int dim>
      void
      particles_to_cells(const State<dim> &state,
                         const double      momentum_weight,
                         const double      force_weight)
      {
        state.grid->zero_cell_mass();
        state.grid->zero_cell_rhs();
        add_particles_to_cells(state,
                               momentum_weight,
                               force_weight,
                               0,
                               state.particles.size());
        finish_particles_to_cells(state);
      }



      template <int dim>
      void
      add_particles_to_cells(const State<dim> &state,
                             const double      momentum_weight,
                             const double      force_weight,
                             const std::size_t first,
                             const std::size_t last)
      {
        auto              &grid       = *state.grid;
        const auto        &particles  = state.particles;
        const unsigned int n          = grid.dofs_per_cell;
        auto              &cells      = grid.cell_arrays();
        const bool         consistent = !cells.mass.empty();
        double            *lumped     = cells.lumped.data();
        double            *mass_mat   = cells.mass.data();
        Tensor<1, dim>    *rhs        = cells.rhs.data();
        const SymmetricTensor<2, dim> *stress = state.stress_for_forces();
        for (std::size_t p = first; p < last; ++p)
          {
            const unsigned int             cell = particles.cell[p];
            const unsigned int             base = cell * n;
            const double                   m    = particles.mass[p];
            const SymmetricTensor<2, dim> &s    = stress[p];
            // Forces alone: no 0 * v term (which would carry a non-finite
            // velocity into the forces).
            const Tensor<1, dim> momentum =
              momentum_weight != 0 ?
                momentum_weight * m * particles.velocity[p] :
                Tensor<1, dim>();
            const Tensor<1, dim> external = force_weight * m * state.gravity;
            const double         volume   = force_weight * particles.volume[p];
            add_point<dim, true>(n,
                                 m,
                                 momentum + external,
                                 volume,
                                 s,
                                 &state.shape_values[p * n],
                                 state.gradients(p, cell),
                                 lumped + base,
                                 consistent ? mass_mat + base * n : nullptr,
                                 rhs + base);
          }
      }



      template <int dim>
      void
      finish_particles_to_cells(const State<dim> &state)
      {
        auto              &cells = state.grid->cell_arrays();
        const unsigned int n     = state.grid->dofs_per_cell;
        if (!cells.mass.empty())
          symmetrize_cell_mass(cells.mass.data(),
                               cells.mass.size() / (n * n),
                               n);
      }



      namespace
      {
        /// The basis values at particle @p p (prefetch.h). @p n is the
        /// number of functions per cell: a std::integral_constant for the
        /// common bases (with_functions_per_cell()), else a run-time
        /// count, whose first line alone is requested.
        template <int dim, typename N>
        DEAL_II_ALWAYS_INLINE inline void
        prefetch_basis_values(const State<dim> &state,
                              const std::size_t p,
                              const N           n)
        {
          if constexpr (std::is_integral_v<N>)
            prefetch_lines(&state.shape_values[p * n]);
          else
            prefetch_lines<N::value * sizeof(double)>(
              &state.shape_values[p * n]);
        }

        /// The same for the basis gradients, if stored per particle.
        template <int dim, typename N>
        DEAL_II_ALWAYS_INLINE inline void
        prefetch_basis_gradients(const State<dim> &state,
                                 const std::size_t p,
                                 const N           n)
        {
          if (state.gradients_per_cell)
            return;
          if constexpr (std::is_integral_v<N>)
            prefetch_lines(&state.shape_gradients[p * n]);
          else
            prefetch_lines<N::value * sizeof(Tensor<1, dim>)>(
              &state.shape_gradients[p * n]);
        }

        /// What move_particles() reads of particle @p p first in a step.
        template <int dim, VelocityUpdate velocity_update, typename N>
        DEAL_II_ALWAYS_INLINE inline void
        prefetch_particle(const State<dim> &state,
                          const std::size_t p,
                          const N           n)
        {
          prefetch_basis_values(state, p, n);
          prefetch_basis_gradients(state, p, n);
          const auto &particles = state.particles;
          prefetch_lines(&particles.cell[p]);
          prefetch_lines(&particles.position[p]);
          prefetch_lines(&particles.displacement[p]);
          if constexpr (velocity_update == VelocityUpdate::flip)
            prefetch_lines(&particles.velocity[p]);
        }
      } // namespace



      template <int dim>
      void
      accelerate_particles(State<dim> &state, const bool momentum_to_grid)
      {
        auto &grid = *state.grid;
        if (momentum_to_grid)
          grid.zero_cell_rhs();
        auto               &particles = state.particles;
        const unsigned int *dofs      = grid.cell_dofs().data();
        Tensor<1, dim>     *rhs       = grid.cell_arrays().rhs.data();
        with_functions_per_cell(grid.dofs_per_cell, [&](const auto n) {
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              // One pass over all particles, but its streams (five arrays
              // and the grid's) are too many for the hardware prefetcher
              // alone: 0.55 -> 0.37 s of 100 Powell-Sabin steps on the
              // throughput bar (doc/performance.md, "Prefetching the chunks'
              // arrays").
              if (p + prefetch_distance < particles.size())
                {
                  const std::size_t ahead = p + prefetch_distance;
                  prefetch_basis_values(state, ahead, n);
                  prefetch_lines(&particles.cell[ahead]);
                  prefetch_lines(&particles.velocity[ahead]);
                  prefetch_lines(&particles.mass[ahead]);
                }
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
        });
      }



      template <int dim, VelocityUpdate velocity_update>
      void
      move_particles(State<dim> &state, std::vector<Tensor<2, dim>> &increments)
      {
        Particles::resize_per_particle(increments, state.particles);
        move_particles<dim, velocity_update>(state,
                                             0,
                                             state.particles.size(),
                                             increments.data());
      }



      /**
       * The part of the velocity gradient at a particle that grid points
       * without mass leave out. A C0 function (P1) that vanishes at the
       * particle (the particle lies on the face opposite its grid point,
       * or round-off outside it: the locator accepts 1e-12) still has a
       * gradient there; if no particle gives that grid point a positive
       * mass, its velocity is not defined by the particles: the lumped
       * solve sets it to 0, which strains a body that only translates
       * (measured: a P1 block sliding at (2, 0.5) m/s across criss-cross
       * cells, lumped mass, gained 0.45 % of its kinetic energy as strain
       * energy in one step). Such a grid point takes the particle's own
       * interpolated velocity @p v instead, in each component that no
       * constraint fixes and that the solve left at exactly 0 (a matrix
       * strategy's extension, a prescribed velocity, stay). Only called
       * for particles with a basis value <= 0, so other particles keep
       * their bits; C1 functions (Powell-Sabin) vanish with their
       * gradient and never need it.
       */
      template <int dim>
      Tensor<2, dim>
      massless_point_gradient(const State<dim>     &state,
                              const unsigned int   *cell_dofs,
                              const double         *phi,
                              const Tensor<1, dim> *grad,
                              const unsigned int    n,
                              const Tensor<1, dim> &v)
      {
        Tensor<2, dim>             L;
        const std::vector<double> &mass = state.grid->lumped_mass();
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int i = cell_dofs[k];
            if (phi[k] > 0. || mass[i] > 0.)
              continue;
            for (unsigned int d = 0; d < dim; ++d)
              if (state.grid_velocity[i][d] == 0. &&
                  !state.grid->constrained_dofs(d)[i])
                for (unsigned int j = 0; j < dim; ++j)
                  L[d][j] += v[d] * grad[k][j];
          }
        return L;
      }



      template <int dim, VelocityUpdate velocity_update>
      void
      move_particles(State<dim>       &state,
                     const std::size_t first,
                     const std::size_t last,
                     Tensor<2, dim>   *increments)
      {
        auto               &particles = state.particles;
        const unsigned int *dofs      = state.grid->cell_dofs().data();
        const double        dt        = state.dt;
        with_functions_per_cell(state.grid->dofs_per_cell, [&](const auto n) {
          for (std::size_t p = first; p < last; ++p)
            {
              // The first loop of a chunk to read these (prefetch.h),
              // also past the chunk's end: the next chunk follows soon.
              const std::size_t ahead = p + prefetch_distance;
              if (ahead < particles.size())
                prefetch_particle<dim, velocity_update>(state, ahead, n);
              const unsigned int    cell = particles.cell[p];
              const unsigned int    base = cell * n;
              const double         *phi  = &state.shape_values[p * n];
              const Tensor<1, dim> *grad = state.gradients(p, cell);
              Tensor<1, dim>        v, a;
              Tensor<2, dim>        L; // velocity gradient, L_ij = dv_i/dx_j
              bool                  on_face = false;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const unsigned int    i  = dofs[base + k];
                  const Tensor<1, dim> &vi = state.grid_velocity[i];
                  v += phi[k] * vi;
                  if constexpr (velocity_update == VelocityUpdate::flip)
                    a += phi[k] * state.grid_acceleration[i];
                  L += outer_product(vi, grad[k]);
                  on_face = on_face || !(phi[k] > 0.);
                }
              if (__builtin_expect(on_face, 0))
                L +=
                  massless_point_gradient(state, &dofs[base], phi, grad, n, v);
              if constexpr (velocity_update == VelocityUpdate::flip)
                particles.velocity[p] += dt * a;
              else if constexpr (velocity_update == VelocityUpdate::grid)
                particles.velocity[p] = v;
              // OTM: sum_a x_a,k+1 N_a,k(x_p) = x_p + dt sum_a u_a N_a,k(x_p)
              // (the functions reproduce x); the increment form keeps the
              // round-off relative to the step.
              increments[p - first]   = dt * L;
              const Tensor<1, dim> du = dt * v;
              particles.displacement[p] += du;
              particles.position[p] += du;
            }
        });
      }



      template void
      add_particles_to_cells(const State<1> &,
                             const double,
                             const double,
                             const std::size_t,
                             const std::size_t);
      template void
      add_particles_to_cells(const State<2> &,
                             const double,
                             const double,
                             const std::size_t,
                             const std::size_t);
      template void
      finish_particles_to_cells(const State<1> &);
      template void
      finish_particles_to_cells(const State<2> &);
      template void
      particles_to_cells(const State<1> &, const double, const double);
      template void
      particles_to_cells(const State<2> &, const double, const double);
      template void
      accelerate_particles(State<1> &, const bool);
      template void
      accelerate_particles(State<2> &, const bool);
#define PSMPM_INSTANTIATE(DIM, UPDATE)                                         \
  template void move_particles<DIM, VelocityUpdate::UPDATE>(                   \
    State<DIM> &,                                                              \
    std::vector<Tensor<2, DIM>> &);                                            \
  template void move_particles<DIM, VelocityUpdate::UPDATE>(State<DIM> &,      \
                                                            const std::size_t, \
                                                            const std::size_t, \
                                                            Tensor<2, DIM> *);
      PSMPM_FOR_VELOCITY_UPDATES(PSMPM_INSTANTIATE)
#undef PSMPM_INSTANTIATE
    } // namespace ParticleLoops
  }   // namespace Simulator
} // namespace psmpm
