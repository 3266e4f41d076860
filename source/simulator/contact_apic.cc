// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The particle side of multi-velocity contact with the apic transfer
// (doc/contact.md, "With the defaults"): each particle near a contact DoF
// takes its own body's corrected field, velocity and affine matrix.
#include <psmpm/simulator/apic_particle_loops.h>
#include <psmpm/simulator/contact_coupling.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    ContactCoupling<dim>::correct_affine_momentum(
      State<dim>       &state,
      const Point<dim> *control_points)
    {
      affine_points = control_points;
      correct(state);
      if (!any_contact)
        return;
      // correct() leaves MUSL's v_bi' - p_bi / m_bi - dt a_i; apic's
      // particles take the grid velocity itself (PIC), so the increments
      // are v_bi' - v_i^{n+1} (fields.velocity: v_bi').
      for (unsigned int i = 0; i < contact_dofs.size(); ++i)
        for (unsigned int b = 0; b < n_bodies; ++b)
          {
            const unsigned int ib = i * n_bodies + b;
            if (fields.mass[ib] > 0)
              velocity_increment[ib] =
                fields.velocity[ib] - state.grid_velocity[contact_dofs[i]];
          }
      clear_fixed(state, velocity_increment);
    }

    template <int dim>
    void
    ContactCoupling<dim>::add_affine_increments(State<dim> &state,
                                                const bool  fit)
    {
      if (!any_contact)
        {
          driven_bodies.set_velocities(state, true, affine_points, true);
          return;
        }
      auto               &particles = state.particles;
      const unsigned int  n         = state.grid->dofs_per_cell;
      const unsigned int *dofs      = state.grid->cell_dofs().data();
      Tensor<1, dim>     *rhs       = state.grid->cell_arrays().rhs.data();
      for (const std::size_t p : near_particles)
        {
          const unsigned int      cell = particles.cell[p];
          const unsigned int      b    = particles.body_id[p] - 1;
          const double           *phi  = &state.shape_values[p * n];
          const Point<dim>       &x    = particles.position[p];
          Tensor<1, dim>          dv;
          Tensor<2, dim>          dB;
          SymmetricTensor<2, dim> D;
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int   l = dofs[cell * n + k];
              const Tensor<1, dim> r = affine_points[l] - x;
              D += phi[k] * symmetrize(outer_product(r, r));
              const unsigned int i = dof_index[l];
              if (i == numbers::invalid_unsigned_int)
                continue;
              const Tensor<1, dim> &u = velocity_increment[i * n_bodies + b];
              dv += phi[k] * u;
              dB += phi[k] * outer_product(u, r);
            }
          // B D^{-1} is linear in B for a given D: the increment of the
          // body's field alone, with nothing kept where D has no support.
          const Tensor<2, dim> dC =
            fit ? ApicLoops::affine_matrix(dB, D, Tensor<2, dim>()) :
                  Tensor<2, dim>();
          particles.velocity[p] += dv;
          particles.affine[p] += dC;
          const double m = particles.mass[p];
          for (unsigned int k = 0; k < n; ++k)
            rhs[cell * n + k] +=
              (phi[k] * m) *
              (dv + dC * (affine_points[dofs[cell * n + k]] - x));
        }
      driven_bodies.set_velocities(state, true, affine_points, true);
    }

    template <int dim>
    void
    ContactCoupling<dim>::move_affine(State<dim>       &state,
                                      const std::size_t first,
                                      const std::size_t last,
                                      Tensor<2, dim>   *increments,
                                      const bool        positions,
                                      const bool        gradient,
                                      const bool        rotation) const
    {
      if (!moving_increment.empty())
        move_near_contact(state,
                          first,
                          last,
                          increments,
                          positions,
                          gradient,
                          rotation);
      // The driven particles' own motion, whatever the grid gave them.
      if (driven_bodies.any())
        driven_bodies.move(state, first, last, increments);
    }

    template <int dim>
    void
    ContactCoupling<dim>::move_near_contact(State<dim>       &state,
                                            const std::size_t first,
                                            const std::size_t last,
                                            Tensor<2, dim>   *increments,
                                            const bool        positions,
                                            const bool        gradient,
                                            const bool        rotation) const
    {
      auto               &particles = state.particles;
      const unsigned int  n         = state.grid->dofs_per_cell;
      const unsigned int *dofs      = state.grid->cell_dofs().data();
      const double        dt        = state.dt;
      for (std::size_t p = first; p < last; ++p)
        {
          const unsigned int cell = particles.cell[p];
          if (!contact_cell[cell])
            continue;
          const unsigned int    b    = particles.body_id[p] - 1;
          const double         *phi  = &state.shape_values[p * n];
          const Tensor<1, dim> *grad = state.gradients(p, cell);
          Tensor<1, dim>        dv;
          Tensor<2, dim>        dL;
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int i = dof_index[dofs[cell * n + k]];
              if (i == numbers::invalid_unsigned_int)
                continue;
              const Tensor<1, dim> &u = moving_increment[i * n_bodies + b];
              dv += phi[k] * u;
              dL += outer_product(u, grad[k]);
            }
          if (positions)
            {
              particles.position[p] += dt * dv;
              particles.displacement[p] += dt * dv;
            }
          increments[p - first] += dt * dL;
          if (gradient)
            particles.affine[p] += dL;
          else if (rotation)
            particles.affine[p] += 0.5 * (dL - transpose(dL));
        }
    }

// clang-format off
#define PSMPM_INSTANTIATE(DIM)                                               \
  template void ContactCoupling<DIM>::correct_affine_momentum(               \
    State<DIM> &, const Point<DIM> *);                                       \
  template void ContactCoupling<DIM>::add_affine_increments(State<DIM> &,    \
                                                            const bool);     \
  template void ContactCoupling<DIM>::move_affine(State<DIM> &,              \
                                                  const std::size_t,         \
                                                  const std::size_t,         \
                                                  Tensor<2, DIM> *,          \
                                                  const bool,                \
                                                  const bool,                \
                                                  const bool) const;
    PSMPM_INSTANTIATE(1)
    PSMPM_INSTANTIATE(2)
    // clang-format on
#undef PSMPM_INSTANTIATE
  } // namespace Simulator
} // namespace psmpm
