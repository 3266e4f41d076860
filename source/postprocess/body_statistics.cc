// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/postprocess/body_statistics.h>

#include <limits>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    void
    BodyStatistics<dim>::add_columns(const StateView<dim> &state,
                                     StatisticsTable      &statistics)
    {
      const auto        &particles = state.particles;
      const unsigned int n         = particles.n_bodies;
      if (n == 0)
        return;
      // Per body: mass, then mass-weighted position.
      std::vector<double> sums(n * (dim + 1), 0.);
      for (std::size_t i = 0; i < particles.size(); ++i)
        {
          const unsigned int b = particles.body_id[i];
          if (b == 0 || b > n)
            continue;
          double *s = sums.data() + (b - 1) * (dim + 1);
          s[0] += particles.mass[i];
          for (unsigned int d = 0; d < dim; ++d)
            s[1 + d] += particles.mass[i] * particles.position[i][d];
        }
      Utilities::MPI::sum(sums, state.comm, sums);
      const char *suffix[] = {"_x", "_y", "_z"};
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const std::string column =
              "body" + std::to_string(b + 1) + suffix[d];
            const double m = sums[b * (dim + 1)];
            statistics.add_value(column,
                                 m > 0 ? sums[b * (dim + 1) + 1 + d] / m : 0.);
            statistics.set_scientific(column, true);
            statistics.set_precision(column, 8);
          }
      // Per body the largest coordinate of its particles: the run-out
      // (front) and the height of a collapsing column.
      std::vector<double> front(n * dim, -std::numeric_limits<double>::max());
      for (std::size_t i = 0; i < particles.size(); ++i)
        {
          const unsigned int b = particles.body_id[i];
          if (b == 0 || b > n)
            continue;
          for (unsigned int d = 0; d < dim; ++d)
            front[(b - 1) * dim + d] =
              std::max(front[(b - 1) * dim + d], particles.position[i][d]);
        }
      Utilities::MPI::max(front, state.comm, front);
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const std::string column =
              "body" + std::to_string(b + 1) + suffix[d] + "_max";
            statistics.add_value(column, front[b * dim + d]);
            statistics.set_scientific(column, true);
            statistics.set_precision(column, 8);
          }
    }

    template class BodyStatistics<1>;
    template class BodyStatistics<2>;
  } // namespace Postprocess
} // namespace psmpm
