// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_transfer_scheme_templates_h
#define psmpm_simulator_transfer_scheme_templates_h

#include <psmpm/simulator/transfer_scheme.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    template <typename Kernels>
    void
    TransferScheme<dim>::update_in_chunks(State<dim>       &state,
                                          StabilityMonitor &monitor,
                                          PhaseTimer       &timer,
                                          Kernels          &kernels)
    {
      const std::size_t n = state.particles.size();
      // A cell's mean strain needs all its particles' increments before
      // the first of them is updated: then one pass moves them all. The
      // forces of the next step then take the stresses averaged on the
      // cells the particles are in by then (prepare_step()): not summed
      // here.
      const bool average = averages(state);
      state.force_stress.clear();
      state.cell_forces.clear();
      const bool accumulate =
        relocation != nullptr && kernels.accumulates(state) && !average;
      PhaseTimer::Laps laps(timer);
      if (relocation != nullptr)
        relocation->begin(state);
      if (accumulate)
        {
          kernels.start_cells(state);
          laps.lap("particle to grid");
        }
      if (average)
        {
          all_increments.resize(n);
          for (std::size_t first = 0; first < n; first += chunk)
            kernels.move(state,
                         first,
                         std::min(n, first + chunk),
                         all_increments.data() + first);
          averaging->apply(state, all_increments.data());
        }
      for (std::size_t first = 0; first < n; first += chunk)
        {
          const std::size_t last = std::min(n, first + chunk);
          Tensor<2, dim>   *increments =
            average ? all_increments.data() + first : chunk_increments.data();
          if (!average)
            kernels.move(state, first, last, increments);
          update_material(state,
                          first,
                          last,
                          increments,
                          chunk_volume_ratio.data(),
                          monitor);
          if (chunk_observer != nullptr)
            chunk_observer->updated(state, first, last);
          laps.lap("update");
          if (relocation == nullptr)
            continue;
          const bool some_left =
            relocation->locate(state, monitor, first, last) > 0;
          laps.lap("locate");
          if (!accumulate)
            continue;
          add_located_to_cells(state, first, last, some_left, kernels);
          laps.lap("particle to grid");
        }
      // Every rank enters every section (PhaseTimer), also a rank
      // without particles.
      laps.lap("update");
      if (relocation == nullptr)
        return;
      const std::size_t received = relocation->finish(state);
      relocated_now              = true;
      laps.lap("locate");
      if (!accumulate)
        return;
      kernels.add_to_cells(state, received, state.particles.size());
      kernels.finish_cells(state);
      state.forces_in_cells = true;
      laps.lap("particle to grid");
    }

    template <int dim>
    template <typename Kernels>
    void
    TransferScheme<dim>::add_located_to_cells(State<dim>       &state,
                                              const std::size_t first,
                                              const std::size_t last,
                                              const bool        some_left,
                                              Kernels          &kernels) const
    {
      if (!some_left)
        {
          kernels.add_to_cells(state, first, last);
          return;
        }
      // The runs between the particles that left (their owner adds them).
      std::size_t begin = first;
      for (std::size_t p = first; p <= last; ++p)
        if (p == last || relocation->leaving(p))
          {
            kernels.add_to_cells(state, begin, p);
            begin = p + 1;
          }
    }
  } // namespace Simulator
} // namespace psmpm

#endif
