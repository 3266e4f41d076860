// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/particle_relocation.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    ParticleRelocation<dim>::begin(State<dim> &state)
    {
      state.prepare_shape_functions();
      outgoing.clear();
      any_leaving = false;
    }

    template <int dim>
    std::size_t
    ParticleRelocation<dim>::locate(State<dim>       &state,
                                    StabilityMonitor &monitor,
                                    const std::size_t first,
                                    const std::size_t last)
    {
      auto              &particles = state.particles;
      const unsigned int rank = Utilities::MPI::this_mpi_process(state.comm);
      const bool  several     = Utilities::MPI::n_mpi_processes(state.comm) > 1;
      std::size_t left        = 0;
      for (std::size_t p = first; p < last; ++p)
        {
          const unsigned int c =
            state.locator.locate(particles.position[p], particles.cell[p]);
          if (c == Mesh::CellLocator<dim>::invalid)
            {
              std::string where = prm_value(particles.position[p][0]);
              for (unsigned int d = 1; d < dim; ++d)
                where += ", " + prm_value(particles.position[p][d]);
              // A distributed mesh: the rank sees its part only.
              monitor.report(Failure::left_mesh,
                             "particle " + std::to_string(particles.id[p]) +
                               " left the mesh" +
                               (state.whole_index.empty() ?
                                  "" :
                                  " (or its rank's cells and ghost layers "
                                  "in one step)") +
                               " at (" + where + ")");
              continue; // keep its old cell; the run stops after this step
            }
          crossings += c != particles.cell[p];
          particles.cell[p] = c;
          if (several && state.cell_owner[c] != rank)
            {
              if (!any_leaving)
                keep.assign(particles.size(), true);
              particles.pack(p, outgoing[state.cell_owner[c]]);
              keep[p]     = false;
              any_leaving = true;
              ++left;
            }
        }
      state.evaluate_shape_functions(first, last);
      return left;
    }

    template <int dim>
    std::size_t
    ParticleRelocation<dim>::finish(State<dim> &state)
    {
      auto &particles = state.particles;
      sent            = 0;
      if (Utilities::MPI::n_mpi_processes(state.comm) == 1)
        return particles.size();
      if (any_leaving)
        {
          sent = particles.size();
          particles.compress(keep);
          sent -= particles.size();
          Particles::compress_per_particle(state.shape_values,
                                           keep,
                                           state.functions_per_cell);
          if (!state.gradients_per_cell)
            Particles::compress_per_particle(state.shape_gradients,
                                             keep,
                                             state.functions_per_cell);
        }
      const std::size_t first = particles.size();
      const auto incoming = Utilities::MPI::some_to_some(state.comm, outgoing);
      for (const auto &in : incoming)
        {
          const std::size_t from = particles.size();
          particles.unpack(in.second);
          for (std::size_t p = from; p < particles.size(); ++p)
            particles.cell[p] = state.locator.locate(particles.position[p]);
        }
      state.prepare_shape_functions();
      state.evaluate_shape_functions(first, particles.size());
      return first;
    }

    template class ParticleRelocation<1>;
    template class ParticleRelocation<2>;
  } // namespace Simulator
} // namespace psmpm
