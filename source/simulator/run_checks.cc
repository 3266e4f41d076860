// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// Checks of a run that has been set up but not started: the size of the
// work ahead (for App::RunLimits) and a finite initial state.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/format.h>
#include <psmpm/material/wave_speed_origin.h>
#include <psmpm/simulator/simulator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    RunSize
    Simulator<dim>::estimate_size() const
    {
      RunSize      size;
      const double dt  = time_step_control.get_time_step();
      const double end = time_step_control.get_end_time();
      // A step of 0 (a speed beyond double range) never ends the run.
      size.steps =
        dt > 0 ? std::ceil(end / dt) : std::numeric_limits<double>::infinity();
      size.end_time  = end;
      size.time_step = describe_time_step();
      size.n_cells   = state.triangulation->n_global_active_cells();
      size.n_particles =
        Utilities::MPI::sum(double(state.particles.size()), comm);
      size.n_outputs = 2;
      if (output.interval > 0)
        size.n_outputs += std::floor(size.steps / output.interval);
      if (output_time_interval > 0)
        size.n_outputs += std::floor(end / output_time_interval);
      // Compressed VTU: about 100 bytes per particle, and per sampling
      // point of the grid (a cell of s x s sub-triangles has about s^2
      // points of its own); a statistics row of about 400 bytes per step.
      const double s = output.grid_subdivisions(state.space->degree());
      // HDF5 particle output is uncompressed doubles: 2 coordinates, a
      // 4-byte cell, 7 scalars, 2 vectors of 3, the dim x dim stress and
      // the material state.
      const double per_particle =
        output.particle_format == Postprocess::ParticleFormat::hdf5 ?
          4. + 8. * (2 + 7 + 6 + dim * dim +
                     state.particles.get_state_names().size()) :
          100.;
      const double per_output = per_particle * size.n_particles +
                                100. * size.n_cells * std::max(1., s * s);
      size.output_bytes = size.n_outputs * per_output + 400. * size.steps;
      return size;
    }

    template <int dim>
    std::string
    Simulator<dim>::describe_time_step() const
    {
      const double dt = time_step_control.get_time_step();
      if (!time_step_control.is_automatic())
        return "Time/Time step = " + prm_value(dt);
      const std::string origin = Material::wave_speed_origin(state.materials);
      const double      c_p    = state.materials.max_p_wave_speed();
      return "the automatic time step " + prm_value(dt) +
             " s (Time/Courant number times h_min/c_p, with the p-wave "
             "speed c_p = " +
             prm_value(c_p) + " m/s" +
             (origin.empty() ? std::string() : " of " + origin) + ")";
    }

    template <int dim>
    void
    Simulator<dim>::check_initial_state() const
    {
      const auto        &particles = state.particles;
      long long          bad       = -1;
      const unsigned int n         = particles.size();
      for (unsigned int i = 0; i < n && bad < 0; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          if (!std::isfinite(particles.velocity[i][d]))
            bad = i;
      std::string where;
      if (bad >= 0)
        {
          where = initial_conditions.velocity_entry(particles.body_id[bad]) +
                  " is not finite: the particle at (" +
                  prm_value(particles.position[bad][0]);
          for (unsigned int d = 1; d < dim; ++d)
            where += ", " + prm_value(particles.position[bad][d]);
          where += ") gives " + prm_value(particles.velocity[bad][0]);
          for (unsigned int d = 1; d < dim; ++d)
            where += "; " + prm_value(particles.velocity[bad][d]);
        }
      // The first rank with a bad particle speaks for all.
      const auto all = Utilities::MPI::all_gather(comm, where);
      for (const auto &w : all)
        AssertThrow(w.empty(), ExcMessage(w + "."));
    }

    template RunSize
    Simulator<1>::estimate_size() const;
    template RunSize
    Simulator<2>::estimate_size() const;
    template void
    Simulator<1>::check_initial_state() const;
    template void
    Simulator<2>::check_initial_state() const;
  } // namespace Simulator
} // namespace psmpm
