// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/archive.h>
#include <psmpm/postprocess/error_norms.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    ErrorNorms<dim>::ErrorNorms(const Reference<dim> &reference,
                                const unsigned int    interval)
      : reference(reference)
      , interval(interval)
    {
    }

    template <int dim>
    Errors
    ErrorNorms<dim>::compute(const StateView<dim> &state,
                             const Reference<dim> &reference)
    {
      Errors      e;
      const auto &particles = state.particles;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const auto r =
            reference.evaluate(particles.initial_position[p], state.time);
          const double V = particles.volume[p];
          e.displacement +=
            V * (particles.displacement[p] - r.displacement).norm_square();
          e.velocity += V * (particles.velocity[p] - r.velocity).norm_square();
          const SymmetricTensor<2, dim> ds = particles.stress[p] - r.stress;
          e.stress += V * (ds * ds);
        }
      e.displacement =
        std::sqrt(Utilities::MPI::sum(e.displacement, state.comm));
      e.velocity = std::sqrt(Utilities::MPI::sum(e.velocity, state.comm));
      e.stress   = std::sqrt(Utilities::MPI::sum(e.stress, state.comm));
      return e;
    }

    template <int dim>
    void
    ErrorNorms<dim>::execute(const StateView<dim> &state,
                             const bool            last,
                             StatisticsTable      &statistics)
    {
      const char *columns[] = {"displacement_L2", "velocity_L2", "stress_L2"};
      if (state.step % interval != 0 && !last)
        {
          // "-": not computed at this step (see Output/Error interval)
          for (const char *c : columns)
            statistics.add_value(c, std::string("-"));
          return;
        }
      const Errors err = compute(state, reference);
      latest           = err;
      latest_step      = state.step;
      statistics.add_value(columns[0], err.displacement);
      statistics.add_value(columns[1], err.velocity);
      statistics.add_value(columns[2], err.stress);
      max_displacement = std::max(max_displacement, err.displacement);
      sum_displacement2 += err.displacement * err.displacement;
      sum_velocity2 += err.velocity * err.velocity;
      ++n;
    }

    template <int dim>
    Errors
    ErrorNorms<dim>::current(const StateView<dim> &state) const
    {
      return latest_step == state.step ? latest : compute(state, reference);
    }

    template <int dim>
    void
    ErrorNorms<dim>::fill_summary(const StateView<dim> &state,
                                  Summary              &summary) const
    {
      const Errors e = current(state);
      summary.set("errors.displacement_L2", e.displacement);
      summary.set("errors.velocity_L2", e.velocity);
      summary.set("errors.stress_L2", e.stress);
      summary.set("errors.displacement_L2_max_over_time", max_displacement);
      if (n > 0)
        {
          summary.set("errors.displacement_L2_rms_over_time",
                      std::sqrt(sum_displacement2 / n));
          summary.set("errors.velocity_L2_rms_over_time",
                      std::sqrt(sum_velocity2 / n));
        }
    }

    template <int dim>
    void
    ErrorNorms<dim>::save(Archive &archive) const
    {
      archive.put("error_norms/sums",
                  std::vector<double>{max_displacement,
                                      sum_displacement2,
                                      sum_velocity2});
      archive.put_integer("error_norms/n", n);
      archive.put("error_norms/latest",
                  std::vector<double>{latest.displacement,
                                      latest.velocity,
                                      latest.stress});
      archive.put_integer("error_norms/latest_step", latest_step);
    }

    template <int dim>
    void
    ErrorNorms<dim>::load(const Archive &archive)
    {
      const auto &s     = archive.get("error_norms/sums", 3);
      max_displacement  = s[0];
      sum_displacement2 = s[1];
      sum_velocity2     = s[2];
      n                 = archive.get_integer("error_norms/n");
      const auto &l     = archive.get("error_norms/latest", 3);
      latest            = {l[0], l[1], l[2]};
      latest_step       = archive.get_integer("error_norms/latest_step");
    }

    template class ErrorNorms<1>;
    template class ErrorNorms<2>;
  } // namespace Postprocess
} // namespace psmpm
