// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/energies.h>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    Energies<dim>
    EnergyStatistics<dim>::compute(const Simulator::State<dim> &state) const
    {
      const auto &particles = state.particles;
      Particles::resize_per_particle(energy_density, particles);
      state.materials.energy_density(particles, energy_density.data());
      Energies<dim> e;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const double m = particles.mass[p];
          e.kinetic += 0.5 * m * particles.velocity[p].norm_square();
          e.strain += particles.volume[p] * energy_density[p];
          e.gravity -= m * (state.gravity * particles.displacement[p]);
          e.momentum += m * particles.velocity[p];
          e.mass += m;
        }
      e.kinetic  = Utilities::MPI::sum(e.kinetic, state.comm);
      e.strain   = Utilities::MPI::sum(e.strain, state.comm);
      e.gravity  = Utilities::MPI::sum(e.gravity, state.comm);
      e.mass     = Utilities::MPI::sum(e.mass, state.comm);
      e.momentum = Utilities::MPI::sum(e.momentum, state.comm);
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
