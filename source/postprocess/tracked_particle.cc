// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/postprocess/oscillation.h>
#include <psmpm/postprocess/tracked_particle.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    TrackedParticle<dim>::TrackedParticle(const Point<dim>     &point,
                                          const Reference<dim> &reference)
      : point(point)
      , reference(reference)
      , axis(reference.axis())
    {
    }

    template <int dim>
    void
    TrackedParticle<dim>::initialize(const StateView<dim> &state)
    {
      const auto   &particles = state.particles;
      double        best      = std::numeric_limits<double>::max();
      std::uint64_t mine      = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const double d = particles.initial_position[p].distance(point);
          if (d < best || (d == best && particles.id[p] < mine))
            best = d, mine = particles.id[p];
        }
      const auto min = Utilities::MPI::min_max_avg(best, state.comm).min;
      // Smallest id among the ranks at the minimal distance.
      const double candidate = best == min ? double(mine) : 1e300;
      id =
        static_cast<std::uint64_t>(Utilities::MPI::min(candidate, state.comm));
    }

    template <int dim>
    void
    TrackedParticle<dim>::execute(const StateView<dim> &state)
    {
      // Sum over ranks: only the owner contributes.
      std::vector<double> v(5, 0.);
      const auto         &particles = state.particles;
      for (std::size_t p = 0; p < particles.size(); ++p)
        if (particles.id[p] == id)
          {
            const auto r =
              reference.evaluate(particles.initial_position[p], state.time);
            v = {particles.displacement[p][axis],
                 particles.velocity[p][axis],
                 r.displacement[axis],
                 r.velocity[axis],
                 0.};
          }
      std::vector<double> total(v.size());
      MPI_Allreduce(v.data(),
                    total.data(),
                    v.size(),
                    MPI_DOUBLE,
                    MPI_SUM,
                    state.comm);
      history.push_back({{state.time, total[0], total[1], total[2], total[3]}});
      velocity2 += (total[1] - total[3]) * (total[1] - total[3]);
      displacement2 += (total[0] - total[2]) * (total[0] - total[2]);
    }

    template <int dim>
    void
    TrackedParticle<dim>::write(const std::string &directory, MPI_Comm comm)
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      const std::string name = directory + "/tracked_particle.txt";
      if (!file || file->name() != name)
        file = std::make_unique<GrowingTextFile>(name);
      std::ostringstream header;
      header
        << "# particle starting nearest to (" << point << "), id " << id
        << ", component " << axis << "\n"
        << "# time displacement velocity reference_displacement reference_velocity\n";
      file->write(
        header.str(),
        history.size(),
        [&](std::ostream &out) { out << header.str(); },
        [&](std::ostream      &out,
            const unsigned int begin,
            const unsigned int end) {
          out.precision(10);
          for (unsigned int i = begin; i < end; ++i)
            {
              const auto &r = history[i];
              out << r[0] << ' ' << r[1] << ' ' << r[2] << ' ' << r[3] << ' '
                  << r[4] << '\n';
            }
        });
    }

    template <int dim>
    void
    TrackedParticle<dim>::fill_summary(Summary &summary) const
    {
      if (history.empty())
        return;
      summary.set("errors.tracked_velocity_rms",
                  std::sqrt(velocity2 / history.size()));
      summary.set("errors.tracked_displacement_rms",
                  std::sqrt(displacement2 / history.size()));
      if (reference.oscillates_about_equilibrium())
        {
          std::vector<double> t, x, x_reference;
          for (const auto &r : history)
            {
              t.push_back(r[0]);
              x.push_back(r[1]);
              x_reference.push_back(r[3]);
            }
          Oscillation::fill_summary(t, x, x_reference, summary);
        }
    }

    template <int dim>
    void
    TrackedParticle<dim>::save(Archive &archive) const
    {
      archive.put_integer("tracked_particle/id", id);
      std::vector<double> h;
      for (const auto &r : history)
        h.insert(h.end(), r.begin(), r.end());
      archive.put("tracked_particle/history", h, 5);
      archive.put("tracked_particle/sums",
                  std::vector<double>{velocity2, displacement2});
    }

    template <int dim>
    void
    TrackedParticle<dim>::load(const Archive &archive)
    {
      id            = archive.get_integer("tracked_particle/id");
      const auto &h = archive.get("tracked_particle/history");
      AssertThrow(h.size() % 5 == 0,
                  ExcMessage("entry 'tracked_particle/history' is not a "
                             "table of 5 columns"));
      history.resize(h.size() / 5);
      for (std::size_t i = 0; i < history.size(); ++i)
        for (unsigned int k = 0; k < 5; ++k)
          history[i][k] = h[5 * i + k];
      const auto &s = archive.get("tracked_particle/sums", 2);
      velocity2     = s[0];
      displacement2 = s[1];
    }

    template class TrackedParticle<1>;
    template class TrackedParticle<2>;
  } // namespace Postprocess
} // namespace psmpm
