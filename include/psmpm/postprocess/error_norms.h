// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_error_norms_h
#define psmpm_postprocess_error_norms_h

#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/state_view.h>
#include <psmpm/postprocess/statistics_table.h>
#include <psmpm/base/summary.h>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    /// Global error norms (thesis eq. 4.4) against a reference.
    struct Errors
    {
      double displacement = 0, velocity = 0, stress = 0;
    };

    /**
     * Error norms against the reference every Output/Error interval steps
     * and at the last step (columns displacement_L2, velocity_L2,
     * stress_L2; "-" where not computed), with their maximum and RMS over
     * time for summary.json.
     */
    template <int dim>
    class ErrorNorms
    {
    public:
      ErrorNorms(const Reference<dim> &reference, const unsigned int interval);

      static Errors
      compute(const StateView<dim> &state, const Reference<dim> &reference);

      void
      execute(const StateView<dim> &state,
              const bool            last,
              StatisticsTable      &statistics);

      /// The errors now: the last computed ones if they are of this step.
      Errors
      current(const StateView<dim> &state) const;

      void
      fill_summary(const StateView<dim> &state, Summary &summary) const;

      /// Maximum and sums over time, the latest errors (checkpoints).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

    private:
      const Reference<dim> &reference;
      const unsigned int    interval;
      double                max_displacement  = 0;
      double                sum_displacement2 = 0;
      double                sum_velocity2     = 0;
      unsigned int          n                 = 0;
      Errors                latest;
      unsigned int          latest_step = numbers::invalid_unsigned_int;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
