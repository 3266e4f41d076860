// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_progress_h
#define psmpm_postprocess_progress_h

#include <chrono>
#include <ostream>
#include <string>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * The progress line of a run: step, simulated time, percent of the end
     * time, wall time and the estimated time to the end, printed at most
     * every @p interval seconds of wall time (and not at all when
     * inactive, e.g. on ranks other than 0 or in test output mode).
     */
    class Progress
    {
    public:
      Progress(std::ostream &out, const bool active, const double interval = 2);

      /// Print the line if @p interval seconds passed since the last one.
      void
      update(const unsigned int step, const double time, const double end_time);

      /// The line for a state (without the time check).
      std::string
      line(const unsigned int step,
           const double       time,
           const double       end_time,
           const double       wall_seconds) const;

    private:
      std::ostream                         &out;
      const bool                            active;
      const double                          interval;
      std::chrono::steady_clock::time_point start, last;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
