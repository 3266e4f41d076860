// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_oscillation_h
#define psmpm_postprocess_oscillation_h

#include <psmpm/base/summary.h>

#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * Mean and period of a sampled oscillation x(t_i), such as the tip of
     * a cantilever released from rest under its weight.
     *
     * Crossings of the mean are interpolated linearly between samples and
     * counted with hysteresis (the signal must get further than a quarter
     * of the half range from the mean on the other side before the next
     * crossing counts), so that grid-crossing noise near the mean does not
     * add crossings. The period is the average spacing of crossings in the
     * same direction; the mean is the time average over the whole periods
     * between the first crossing and the last one in the same direction.
     * Both are computed twice, the second time about the first mean (the
     * first pass starts from the average over all samples).
     */
    class Oscillation
    {
    public:
      struct Result
      {
        /// At least one full period (three crossings) was seen.
        bool         valid = false;
        double       mean = 0, period = 0;
        unsigned int crossings = 0;
      };

      static Result
      measure(const std::vector<double> &t, const std::vector<double> &x);

      /**
       * Measure the run's @p x and the reference's @p x_reference (same
       * times) and write, under "oscillation.", tip_mean_deflection(_
       * reference, _error) and period(_reference, _error): the errors are
       * relative and signed, run / reference - 1 (a positive mean
       * deflection error: the run deflects more). Only what could be
       * measured is written.
       */
      static void
      fill_summary(const std::vector<double> &t,
                   const std::vector<double> &x,
                   const std::vector<double> &x_reference,
                   Summary                   &summary);
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
