// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/format.h>
#include <psmpm/material/wave_speed_origin.h>
#include <psmpm/simulator/time_step_control.h>

namespace psmpm
{
  namespace Simulator
  {
    void
    TimeStepControl::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      prm.declare_entry("End time",
                        "0.02",
                        Patterns::Double(0),
                        "End time [s].");
      prm.declare_entry("Time step",
                        "1e-5",
                        Patterns::Double(0),
                        "Fixed time step [s]; 0 = automatic from the Courant "
                        "number. A fixed step above the stability bound is "
                        "an error.");
      prm.declare_entry(
        "Courant number",
        "0.5",
        Patterns::Double(0),
        "dt = C f h_min / c_p for the automatic time step (c_p: p-wave "
        "speed, h_min: smallest triangle height, of the moved cells with "
        "Transfer/Scheme = otm, f: measured stability factor of the basis "
        "and mass matrix, 0.4 to 1.5, doc/stability.md).");
      prm.declare_entry(
        "Check stability bound",
        "true",
        Patterns::Bool(),
        "Reject a fixed Time step above h_min/c_p and a Courant "
        "number above 1 before the run (and warn if the moving grid of "
        "Transfer/Scheme = otm compresses below it). Switch off only to "
        "measure stability limits (contrib/studies/stability/stability_study.py).");
      prm.leave_subsection();
    }

    void
    TimeStepControl::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      end_time        = prm.get_double("End time");
      fixed_step      = prm.get_double("Time step");
      courant_number  = prm.get_double("Courant number");
      check_time_step = prm.get_bool("Check stability bound");
      prm.leave_subsection();
      AssertThrow(end_time > 0, ExcMessage("Time/End time must be positive."));
      AssertThrow(
        courant_number > 0 && (courant_number <= 1 || !check_time_step),
        ExcMessage("Time/Courant number = " + prm_value(courant_number) +
                   ": must lie in (0, 1]."));
    }

    template <int dim>
    void
    TimeStepControl::initialize(const State<dim> &state)
    {
      h_min              = state.locator.minimum_height();
      const double c_p   = state.materials.max_p_wave_speed();
      const double bound = h_min / c_p;
      factor = state.space->stability_factor(!state.grid->uses_matrix());
      if (fixed_step > 0)
        {
          AssertThrow(fixed_step <= bound || !check_time_step,
                      ExcMessage("Time/Time step = " + prm_value(fixed_step) +
                                 " exceeds the stability bound h_min/c_p = " +
                                 prm_value(bound) +
                                 " (h_min = " + prm_value(h_min) +
                                 ", c_p = " + prm_value(c_p) + " of " +
                                 Material::wave_speed_origin(state.materials) +
                                 ")."));
          time_step = fixed_step;
        }
      else
        update(state, h_min);
      min_time_step = max_time_step = time_step;
      time_step_warning.clear();
      moving_grid_warning.clear();
      if (time_step > factor * bound)
        time_step_warning =
          "Time/Time step = " + prm_value(time_step) +
          " is above the measured stability limit of this basis and mass "
          "matrix, about " +
          prm_value(factor * bound) +
          " (doc/stability.md); the run may become unstable.";
    }

    template <int dim>
    void
    TimeStepControl::update(const State<dim> &state, const double grid_h_min)
    {
      if (!is_automatic())
        {
          // A fixed step was checked against the initial grid; a grid
          // that moves with the material (OTM) can compress below it.
          // Not an error (the run may still be stable, and the monitors
          // stop it if not), but said once, in the log and summary.json.
          const double c_p = state.materials.max_p_wave_speed();
          if (check_time_step && moving_grid_warning.empty() &&
              fixed_step > grid_h_min / c_p)
            moving_grid_warning =
              "Time/Time step = " + prm_value(fixed_step) +
              " exceeds the stability bound h_min/c_p = " +
              prm_value(grid_h_min / c_p) + " of the moving grid at step " +
              std::to_string(state.step) + " (t = " + prm_value(state.time) +
              ", h_min = " + prm_value(grid_h_min) + ", initially " +
              prm_value(h_min) +
              "); use Time/Time step = 0 for a step that follows the grid.";
          return;
        }
      const auto &particles = state.particles;
      double      speed     = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        speed = std::max(speed, particles.velocity[p].norm_square());
      // The largest wave speed and the largest particle speed, each over
      // all ranks, then added (as on one rank): the maximum over ranks of
      // their per-rank sums depended on which rank held which particle,
      // so the step changed with the number of ranks.
      const double local[2] = {std::max(state.materials.max_wave_speed(
                                          particles),
                                        state.materials.max_p_wave_speed()),
                               speed};
      double       global[2];
      Utilities::MPI::max(local, state.comm, global);
      const double c_max = global[0] + std::sqrt(global[1]);
      time_step     = courant_number * factor * grid_h_min / c_max;
      min_time_step = std::min(min_time_step, time_step);
      max_time_step = std::max(max_time_step, time_step);
    }

    void
    TimeStepControl::save(Archive &archive) const
    {
      archive.put("time_step_control/time_step", time_step);
      archive.put("time_step_control/min_time_step", min_time_step);
      archive.put("time_step_control/max_time_step", max_time_step);
      archive.put_text("time_step_control/grid_warning", moving_grid_warning);
    }

    void
    TimeStepControl::load(const Archive &archive)
    {
      time_step     = archive.get_number("time_step_control/time_step");
      min_time_step = archive.get_number("time_step_control/min_time_step");
      max_time_step = archive.get_number("time_step_control/max_time_step");
      // Absent in checkpoints of psmpm before the moving-grid check.
      moving_grid_warning =
        archive.has("time_step_control/grid_warning") ?
          archive.get_text("time_step_control/grid_warning") :
          std::string();
    }

    template void
    TimeStepControl::update(const State<1> &, const double);
    template void
    TimeStepControl::update(const State<2> &, const double);
    template void
    TimeStepControl::initialize(const State<1> &);
    template void
    TimeStepControl::initialize(const State<2> &);
  } // namespace Simulator
} // namespace psmpm
