// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/volumetric_averaging.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    std::size_t
    VolumetricAveraging<dim>::start_sums(const State<dim> &state)
    {
      const auto &particles = state.particles;
      // Body ids are 1, 2, ... (0 without Bodies).
      by_body = particles.body_id.size() == particles.size();
      n_ids   = particles.n_bodies + 1;
      const std::size_t n_slots =
        std::size_t(state.triangulation->n_active_cells()) * n_ids;
      volume.assign(n_slots, 0.);
      trace.assign(n_slots, 0.);
      return particles.size();
    }

    template <int dim>
    template <typename T>
    void
    VolumetricAveraging<dim>::replace_mean_trace(const State<dim> &state,
                                                 T                *values)
    {
      const auto       &particles = state.particles;
      const std::size_t n         = start_sums(state);
      for (std::size_t p = 0; p < n; ++p)
        {
          const std::size_t s = slot(state, p);
          volume[s] += particles.volume[p];
          trace[s] += particles.volume[p] * dealii::trace(values[p]);
        }
      for (std::size_t p = 0; p < n; ++p)
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
    VolumetricAveraging<dim>::apply(const State<dim> &state,
                                    Tensor<2, dim>   *increments)
    {
      replace_mean_trace(state, increments);
    }

    template <int dim>
    void
    VolumetricAveraging<dim>::average_stress(
      const State<dim>                     &state,
      std::vector<SymmetricTensor<2, dim>> &averaged)
    {
      averaged = state.particles.stress;
      replace_mean_trace(state, averaged.data());
    }

    template class VolumetricAveraging<1>;
    template class VolumetricAveraging<2>;
  } // namespace Simulator
} // namespace psmpm
