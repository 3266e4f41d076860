// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/dof_body_masks.h>
#include <psmpm/simulator/volumetric_averaging.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    VolumetricAveraging<dim>::VolumetricAveraging(const bool exact_cells)
      : exact_cells(exact_cells)
    {
    }

    template <int dim>
    template <typename T>
    void
    VolumetricAveraging<dim>::sum_traces(const State<dim> &state,
                                         const T          *values)
    {
      const auto &particles = state.particles;
      // Body ids are 1, 2, ... (0 without Bodies).
      by_body = particles.body_id.size() == particles.size();
      n_ids   = particles.n_bodies + 1;
      const std::size_t n_slots =
        std::size_t(state.triangulation->n_active_cells()) * n_ids;
      volume.assign(n_slots, 0.);
      trace.assign(n_slots, 0.);
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const std::size_t s = slot(state, p);
          volume[s] += particles.volume[p];
          trace[s] += particles.volume[p] * dealii::trace(values[p]);
        }
    }

    template <int dim>
    template <typename T>
    void
    VolumetricAveraging<dim>::replace_mean_trace(const State<dim> &state,
                                                 T                *values)
    {
      sum_traces(state, values);
      for (std::size_t p = 0; p < state.particles.size(); ++p)
        {
          const std::size_t s = slot(state, p);
          const double      shift =
            (trace[s] / volume[s] - dealii::trace(values[p])) / dim;
          for (unsigned int d = 0; d < dim; ++d)
            values[p][d][d] += shift;
        }
    }

    template <int dim>
    void
    VolumetricAveraging<dim>::find_exact_cells(const State<dim> &state)
    {
      const unsigned int n_cells = state.triangulation->n_active_cells();
      exact.clear();
      exact_slot.clear();
      exact_index.assign(n_cells, numbers::invalid_unsigned_int);
      if (!exact_cells)
        return;
      if (integrals.empty())
        {
          integrals.reinit(*state.triangulation, *state.space);
          owned_cells.resize(n_cells);
          for (unsigned int c = 0; c < n_cells; ++c)
            owned_cells[c] = integrals.measure(c) > 0;
        }
      if (state.particles.n_bodies >= 31)
        return;
      // A cell counts as filled by its body only inside it: every cell
      // around its functions holds that body's particles and no other
      // body's. At a free surface the cell's velocity field reaches
      // into the empty space beside it (the whole-cell volume change
      // then includes flow into the void), and at a contact DoF each
      // body moves with its own velocity, not the grid's.
      dof_body_masks(state, cell_mask, dof_mask, &owned_cells);
      const unsigned int  n    = state.grid->dofs_per_cell;
      const unsigned int *dofs = state.grid->cell_dofs().data();
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          unsigned int bodies = 0;
          std::size_t  s      = 0;
          for (unsigned int b = 0; b < n_ids; ++b)
            if (volume[std::size_t(c) * n_ids + b] > 0)
              {
                ++bodies;
                s = std::size_t(c) * n_ids + b;
              }
          if (bodies != 1 || volume[s] < min_fill * integrals.measure(c))
            continue;
          bool inside = true;
          for (unsigned int k = 0; inside && k < n; ++k)
            inside = dof_mask[dofs[c * n + k]] == cell_mask[c];
          if (!inside)
            continue;
          exact_index[c] = exact.size();
          exact.push_back(c);
          exact_slot.push_back(s);
        }
    }

    template <int dim>
    void
    VolumetricAveraging<dim>::prepare(State<dim> &state)
    {
      const auto &particles = state.particles;
      sum_traces(state, particles.stress.data());
      find_exact_cells(state);
      state.force_stress = particles.stress;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const std::size_t s   = slot(state, p);
          const double      own = dealii::trace(particles.stress[p]);
          const double      mean =
            exact_index[particles.cell[p]] == numbers::invalid_unsigned_int ?
                   trace[s] / volume[s] :
                   0.;
          const double shift = (mean - own) / dim;
          for (unsigned int d = 0; d < dim; ++d)
            state.force_stress[p][d][d] += shift;
        }
      // The exact cells' pressure m_c acts through G_{c,k}: the force
      // -int_c m_c I grad N_k.
      const unsigned int n    = state.grid->dofs_per_cell;
      state.cell_forces.cells = exact;
      state.cell_forces.forces.resize(exact.size() * n);
      for (std::size_t i = 0; i < exact.size(); ++i)
        {
          const std::size_t     s    = exact_slot[i];
          const double          mean = trace[s] / volume[s] / dim;
          const Tensor<1, dim> *G    = integrals.integrals(exact[i]);
          for (unsigned int k = 0; k < n; ++k)
            state.cell_forces.forces[i * n + k] = -mean * G[k];
        }
    }

    template <int dim>
    void
    VolumetricAveraging<dim>::apply(const State<dim> &state,
                                    Tensor<2, dim>   *increments)
    {
      replace_mean_trace(state, increments);
      if (exact.empty())
        return;
      const unsigned int  n    = state.grid->dofs_per_cell;
      const unsigned int *dofs = state.grid->cell_dofs().data();
      change.resize(exact.size());
      for (std::size_t i = 0; i < exact.size(); ++i)
        {
          const unsigned int    c = exact[i];
          const Tensor<1, dim> *G = integrals.integrals(c);
          double                d = 0;
          for (unsigned int k = 0; k < n; ++k)
            d += state.grid_velocity[dofs[c * n + k]] * G[k];
          change[i] = state.dt * d / volume[exact_slot[i]];
        }
      const auto &particles = state.particles;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int i = exact_index[particles.cell[p]];
          if (i == numbers::invalid_unsigned_int)
            continue;
          const double shift = (change[i] - dealii::trace(increments[p])) / dim;
          for (unsigned int d = 0; d < dim; ++d)
            increments[p][d][d] += shift;
        }
    }

    template class VolumetricAveraging<1>;
    template class VolumetricAveraging<2>;
  } // namespace Simulator
} // namespace psmpm
