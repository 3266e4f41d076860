// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_time_step_control_h
#define psmpm_simulator_time_step_control_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/simulator/state.h>

#include <string>

namespace psmpm
{
  class Archive;

  namespace Simulator
  {
    using namespace dealii;

    /**
     * The time step and the end time (subsection "Time"): a fixed step, or
     * the automatic step dt = C f h_min / max_p (c_p + |v_p|), recomputed
     * before every step from the current state, with the Courant number
     * C, the measured stability factor f of the space and mass strategy,
     * the smallest triangle height (element length in 1D) of the grid now
     * (the moved cells of a grid that moves with the material), the largest
     * wave speed of the particles' current material state (a neo-Hookean
     * body stiffens as it compresses) and the particle speed (material
     * must not cross more than a cell per step). A fixed step above
     * h_min / c_p is rejected (thesis eq. 2.48 with the p-wave speed), one
     * above the measured limit warned about.
     */
    class TimeStepControl
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Choose the step for the initial state; throws for a fixed step
      /// above the bound.
      template <int dim>
      void
      initialize(const State<dim> &state);

      /// Recompute the automatic step from the current state and
      /// @p grid_h_min, the smallest cell height of the grid now
      /// (TransferScheme::minimum_height(): the initial mesh's unless the
      /// grid moves); all ranks. A fixed step is kept; if it exceeds
      /// grid_h_min / c_p (a moving grid compressed), moving_grid_warning
      /// is set once.
      template <int dim>
      void
      update(const State<dim> &state, const double grid_h_min);

      double
      next(const double time) const
      {
        return std::min(time_step, end_time - time);
      }

      /// Whether @p time has reached the end time (to round-off).
      bool
      finished(const double time) const
      {
        return !(time < end_time * (1 - 1e-12));
      }

      /// Whether the step @p dt from @p time ends the run: the step after
      /// which finished() holds (cut to land on the end time, or snapped
      /// to it).
      bool
      ends_run(const double time, const double dt) const
      {
        return finished(snap(time + dt));
      }

      /// @p time snapped to the end time if round-off in the sum of steps
      /// left a sliver of a last step.
      double
      snap(const double time) const
      {
        return std::abs(end_time - time) < 1e-9 * time_step ? end_time : time;
      }

      double
      get_time_step() const
      {
        return time_step;
      }
      double
      get_min_time_step() const
      {
        return min_time_step;
      }
      double
      get_max_time_step() const
      {
        return max_time_step;
      }
      bool
      is_automatic() const
      {
        return !(fixed_step > 0);
      }
      double
      get_end_time() const
      {
        return end_time;
      }
      /// The current, smallest and largest step (checkpoints).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

      /// Non-empty if the step is above the measured stability limit.
      const std::string &
      warning() const
      {
        return time_step_warning;
      }

      /// Non-empty once a fixed step exceeded h_min / c_p of a moving
      /// grid during the run.
      const std::string &
      grid_warning() const
      {
        return moving_grid_warning;
      }

    private:
      double      end_time        = 0.02;
      double      fixed_step      = 0;
      double      courant_number  = 0.5;
      bool        check_time_step = true;
      double      time_step       = 0;
      double      min_time_step   = 0;
      double      max_time_step   = 0;
      double      factor          = 1; ///< of the space and mass strategy
      double      h_min           = 0; ///< of the initial mesh
      std::string time_step_warning;
      std::string moving_grid_warning;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
