// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_run_record_h
#define psmpm_simulator_run_record_h

#include <deal.II/base/timer.h>

#include <cstdint>
#include <string>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Simulator
  {
    using namespace dealii;

    /// How a run ended; unstable runs carry the reason, interrupted ones
    /// the signal (SIGINT, SIGTERM; see StopRequest).
    enum class Status
    {
      completed,
      unstable,
      interrupted
    };

    /// "completed", "unstable" or "interrupted" (summary.json).
    inline const char *
    status_name(const Status s)
    {
      return s == Status::completed ? "completed" :
             s == Status::unstable  ? "unstable" :
                                      "interrupted";
    }

    /**
     * What happened in a run so far, beyond the state: how it ended, the
     * solver iterations, the outputs of Output/Time interval, the times
     * the reference was advanced to, the checkpoint it resumed from and
     * its wall and CPU time. Checkpoints carry the counters
     * (save()/load()).
     */
    struct RunRecord
    {
      /// The counters, the wall time so far and the step times, under
      /// "simulator/".
      void
      save(Archive &archive) const;

      /// The counters and the wall time before the checkpoint (the step
      /// times are read where the reference is advanced through them).
      void
      load(const Archive &archive);

      Status       status      = Status::completed;
      unsigned int failed_step = 0;
      double       failed_time = 0;
      /// CG iterations of all steps.
      unsigned int total_iterations = 0;
      /// Multiples of Output/Time interval passed.
      unsigned int time_outputs = 0;
      /// The times at which the reference was advanced (checkpoints).
      std::vector<double> step_times;
      /// The checkpoint this run resumed from ("" if none).
      std::string  resumed_from;
      unsigned int resumed_step = 0;
      /// Wall time of the run before the checkpoint it resumed from.
      double wall_offset = 0;
      /// Particles' cell changes (all ranks) before the checkpoint it
      /// resumed from ("simulator/cell_crossings", absent in checkpoints
      /// of older versions: 0).
      std::uint64_t cell_crossings_offset = 0;
      /// Wall time of this process's part of the run.
      Timer wall;
      /// CPU seconds (user + sys, this rank) of the time loop of run().
      double cpu_time_loop = 0;
      /// The part of cpu_time_loop spent in the steps and their
      /// statistics, without output and checkpoints: the CPU counterpart
      /// of the phases that time_loop_s and the throughput count.
      double cpu_time_steps = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
