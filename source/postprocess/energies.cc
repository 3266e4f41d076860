// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/prefetch.h>
#include <psmpm/postprocess/energies.h>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    Energies<dim>
    EnergyStatistics<dim>::compute(const StateView<dim> &state) const
    {
      Energies<dim> e;
      accumulate(state, 0, state.particles.size(), e);
      return reduce(e, state.comm);
    }

    template <int dim>
    void
    EnergyStatistics<dim>::accumulate(const StateView<dim> &state,
                                      const std::size_t     first,
                                      const std::size_t     last,
                                      Energies<dim>        &sums) const
    {
      const auto &particles = state.particles;
      // The sums in registers, not through the reference (as in
      // RotationStatistics::accumulate); same operations, same order.
      Energies<dim> e = sums;
      e.dissipative   = state.materials.dissipates();
      for (std::size_t begin = first; begin < last; begin += chunk)
        {
          const std::size_t end = std::min(last, begin + chunk);
          state.materials.energy_density(particles,
                                         begin,
                                         end,
                                         energy_density.data());
          for (std::size_t p = begin; p < end; ++p)
            {
              // The first loop of the update's chunks to read these
              // (prefetch.h).
              if (p + prefetch_distance < particles.size())
                {
                  prefetch_lines(&particles.mass[p + prefetch_distance]);
                  prefetch_lines(&particles.velocity[p + prefetch_distance]);
                }
              const double m = particles.mass[p];
              e.kinetic += 0.5 * m * particles.velocity[p].norm_square();
              e.strain += particles.volume[p] * energy_density[p - begin];
              e.gravity -= m * (state.gravity * particles.displacement[p]);
              e.momentum += m * particles.velocity[p];
              e.mass += m;
            }
          if (e.dissipative)
            {
              state.materials.dissipated_energy(particles,
                                                begin,
                                                end,
                                                dissipation.data());
              for (std::size_t p = begin; p < end; ++p)
                e.dissipated += particles.mass[p] * dissipation[p - begin];
            }
        }
      sums = e;
    }

    template <int dim>
    Energies<dim>
    EnergyStatistics<dim>::reduce(const Energies<dim> &local, MPI_Comm comm)
    {
      Energies<dim> e;
      e.kinetic     = Utilities::MPI::sum(local.kinetic, comm);
      e.strain      = Utilities::MPI::sum(local.strain, comm);
      e.gravity     = Utilities::MPI::sum(local.gravity, comm);
      e.dissipative = local.dissipative;
      if (e.dissipative)
        e.dissipated = Utilities::MPI::sum(local.dissipated, comm);
      e.mass     = Utilities::MPI::sum(local.mass, comm);
      e.momentum = Utilities::MPI::sum(local.momentum, comm);
      return e;
    }

    template <int dim>
    void
    EnergyStatistics<dim>::add_columns(const Energies<dim> &e,
                                       StatisticsTable     &statistics)
    {
      statistics.add_value("kinetic_energy", e.kinetic);
      statistics.add_value("strain_energy", e.strain);
      statistics.add_value("gravity_energy", e.gravity);
      if (e.dissipative)
        {
          statistics.add_value("dissipated_energy", e.dissipated);
          statistics.set_scientific("dissipated_energy", true);
          statistics.set_precision("dissipated_energy", 8);
        }
      statistics.add_value("total_energy", e.total());
      statistics.add_value("mass", e.mass);
      const char *names[] = {"momentum_x", "momentum_y"};
      for (unsigned int d = 0; d < dim; ++d)
        statistics.add_value(names[d], e.momentum[d]);
    }

    template class EnergyStatistics<1>;
    template class EnergyStatistics<2>;
  } // namespace Postprocess
} // namespace psmpm
