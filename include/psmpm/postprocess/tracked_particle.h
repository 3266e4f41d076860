// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_tracked_particle_h
#define psmpm_postprocess_tracked_particle_h

#include <psmpm/base/growing_text_file.h>
#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/state_view.h>
#include <psmpm/base/summary.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    /**
     * The history of the particle that starts nearest to Output/Tracked
     * point, with the reference's, along the reference's axis:
     * tracked_particle.txt and the RMS of the differences over time (a
     * grid-crossing noise measure) in summary.json; for references that
     * oscillate about an equilibrium also the mean and period of both
     * (Oscillation).
     */
    template <int dim>
    class TrackedParticle
    {
    public:
      TrackedParticle(const Point<dim> &point, const Reference<dim> &reference);

      /// Find the particle (smallest id among equally near ones).
      void
      initialize(const StateView<dim> &state);

      void
      execute(const StateView<dim> &state);

      /// tracked_particle.txt in @p directory (rank 0), appended to.
      void
      write(const std::string &directory, MPI_Comm comm);

      void
      fill_summary(Summary &summary) const;

      /// The particle's id and history (checkpoints).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

    private:
      const Point<dim>                   point;
      const Reference<dim>              &reference;
      const unsigned int                 axis;
      std::uint64_t                      id = 0;
      std::vector<std::array<double, 5>> history;
      std::unique_ptr<GrowingTextFile>   file;
      double                             velocity2     = 0;
      double                             displacement2 = 0;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
