// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/format.h>
#include <psmpm/simulator/stability_monitor.h>

#include <cmath>

namespace psmpm
{
  namespace Simulator
  {
    const FailureInfo &
    failure_info(const Failure f)
    {
      static const FailureInfo table[] = {
        {Failure::none, "none", 0},
        {Failure::non_finite, "non-finite energy or momentum", 3},
        {Failure::energy_growth, "energy growth", 4},
        {Failure::left_mesh, "particle left the mesh", 5},
        {Failure::non_positive_volume, "non-positive particle volume", 6},
        {Failure::solver, "mass matrix solver did not converge", 7},
        {Failure::inverted_cell, "inverted cell of the moving grid", 9}};
      return table[static_cast<int>(f)];
    }

    void
    StabilityMonitor::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Stability");
      prm.declare_entry(
        "Energy tolerance",
        "0.1",
        Patterns::Double(0),
        "Stop as unstable when the total energy rises above its "
        "initial value by more than this fraction of the "
        "largest energy seen so far.");
      prm.leave_subsection();
    }

    void
    StabilityMonitor::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Stability");
      energy_tolerance = prm.get_double("Energy tolerance");
      prm.leave_subsection();
    }

    bool
    StabilityMonitor::check(const double total_energy,
                            const double energy_scale_now,
                            const double momentum_norm,
                            MPI_Comm     comm)
    {
      if (!initialized)
        initial_energy = total_energy, initialized = true;
      // Every rank must agree on the verdict.
      const int any = Utilities::MPI::max(failed() ? 1 : 0, comm);
      if (any > 0)
        {
          const Failure f = static_cast<Failure>(
            Utilities::MPI::max(static_cast<int>(failure), comm));
          // The reason of the first rank that found this failure: on a
          // distributed mesh, where a particle leaving a rank's cells is
          // reported, it is often not rank 0, which writes summary.json.
          const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
          const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
          const unsigned int first =
            Utilities::MPI::min(failure == f ? rank : n_ranks, comm);
          const std::string reason =
            Utilities::MPI::broadcast(comm, failure_reason, first);
          if (!failed())
            report(f, reason + " (on MPI rank " + std::to_string(first) + ")");
          failure = f;
          return true;
        }
      if (!std::isfinite(total_energy) || !std::isfinite(momentum_norm))
        {
          report(Failure::non_finite, "non-finite energy or momentum");
          return true;
        }
      energy_scale        = std::max(energy_scale, energy_scale_now);
      const double growth = total_energy - initial_energy;
      if (growth > energy_tolerance * energy_scale && growth > 1e-300)
        {
          report(Failure::energy_growth,
                 "total energy grew by " + prm_value(growth) + " (" +
                   prm_value(100 * growth / energy_scale) +
                   " % of the energy scale) without external work");
          return true;
        }
      return false;
    }

    void
    StabilityMonitor::save(Archive &archive) const
    {
      archive.put_integer("stability_monitor/initialized", initialized);
      archive.put("stability_monitor/initial_energy", initial_energy);
      archive.put("stability_monitor/energy_scale", energy_scale);
    }

    void
    StabilityMonitor::load(const Archive &archive)
    {
      initialized = archive.get_integer("stability_monitor/initialized") != 0;
      initial_energy = archive.get_number("stability_monitor/initial_energy");
      energy_scale   = archive.get_number("stability_monitor/energy_scale");
    }
  } // namespace Simulator
} // namespace psmpm
