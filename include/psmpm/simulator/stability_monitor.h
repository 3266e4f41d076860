// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_stability_monitor_h
#define psmpm_simulator_stability_monitor_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace psmpm
{
  class Archive;

  namespace Simulator
  {
    using namespace dealii;

    /// Which monitor stopped a run; each has its own exit code.
    enum class Failure : int
    {
      none = 0,
      non_finite,
      energy_growth,
      left_mesh,
      non_positive_volume,
      solver,
      inverted_cell ///< a cell of a moving grid (OTM) turned inside out
    };

    /// The one table of failures: name and process exit code.
    struct FailureInfo
    {
      Failure     failure;
      const char *name;
      int         exit_code;
    };
    const FailureInfo &
    failure_info(const Failure f);

    /**
     * Collects the first failure a component reports during a step
     * (report(): kernels call it, cheaply, from their loops) and checks
     * the energy balance once per step (check()); all ranks agree on the
     * verdict. Subsection "Stability".
     */
    class StabilityMonitor
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Record a failure unless one is recorded already.
      void
      report(const Failure f, const std::string &reason)
      {
        if (failure == Failure::none)
          failure = f, failure_reason = reason;
      }

      bool
      failed() const
      {
        return failure != Failure::none;
      }

      /**
       * The energy and finiteness checks of a step, given the total
       * energy (the caller's balance: less the work of walls and the
       * friction work of sliding contact, both dissipation), the energy scale (kinetic + strain + |gravity|) and the
       * momentum norm, plus the failures reported on any rank; the
       * initial energy is the one of the first call. Returns true if the
       * run must stop.
       */
      bool
      check(const double total_energy,
            const double energy_scale_now,
            const double momentum_norm,
            MPI_Comm     comm);

      /// The energy balance so far (checkpoints; taken when no failure
      /// is recorded).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

      Failure
      get_failure() const
      {
        return failure;
      }
      const std::string &
      reason() const
      {
        return failure_reason;
      }

    private:
      double      energy_tolerance = 0.1;
      bool        initialized      = false;
      double      initial_energy   = 0;
      double      energy_scale     = 0;
      Failure     failure          = Failure::none;
      std::string failure_reason;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
