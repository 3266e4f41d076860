// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <psmpm/mesh/cell_locator.h>
#include <psmpm/postprocess/postprocessor.h>
#include <psmpm/postprocess/tracked_particle.h>

#include <memory>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// The particle nearest to Output/Tracked point against the
      /// reference (TrackedParticle): tracked_particle.txt and its RMS
      /// differences (and the oscillation's mean and period) in
      /// summary.json. Nothing without a reference or a point.
      template <int dim>
      class TrackedParticleFile : public Postprocessor<dim>
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Output");
          prm.declare_entry(
            "Tracked point",
            "",
            Patterns::List(Patterns::Double(), 0, 2),
            "Initial position (one coordinate per dimension): the "
            "particle that starts nearest to it is recorded every "
            "step in tracked_particle.txt with the reference, and "
            "the RMS of the differences over time goes into "
            "summary.json (a grid-crossing noise measure).");
          prm.leave_subsection();
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          prm.enter_subsection("Output");
          text = prm.get("Tracked point");
          prm.leave_subsection();
          // The pattern takes numbers string_to_double refuses
          // (subnormals such as 4.9e-324).
          try
            {
              point = Utilities::string_to_double(
                Utilities::split_string_list(text, ','));
            }
          catch (const std::exception &)
            {
              AssertThrow(false,
                          ExcMessage("Output/Tracked point = '" + text +
                                     "': not a list of numbers."));
            }
          AssertThrow(point.empty() || point.size() == dim,
                      ExcMessage("Output/Tracked point must be empty or have " +
                                 std::to_string(dim) + " coordinate(s)."));
        }

        /// "Nearest particle" would quietly track a boundary particle
        /// for a point off the mesh (a typo): refused. A distributed mesh
        /// locates the point on the rank that holds it.
        void
        check_mesh(const Mesh::CellLocator<dim> &locator,
                   MPI_Comm                      comm) const override
        {
          if (point.empty())
            return;
          const int inside =
            locator.locate(tracked_point()) != Mesh::CellLocator<dim>::invalid;
          AssertThrow(Utilities::MPI::max(inside, comm) == 1,
                      ExcMessage("Output/Tracked point = '" + text +
                                 "' lies outside the mesh."));
        }

        unsigned int
        order() const override
        {
          return 500;
        }

        void
        initialize(const StateView<dim> &state) override
        {
          tracked.reset();
          if (!state.reference || point.empty())
            return;
          tracked = std::make_unique<TrackedParticle<dim>>(tracked_point(),
                                                           *state.reference);
        }

        void
        start(const StateView<dim> &state) override
        {
          if (tracked)
            tracked->initialize(state);
        }

        void
        execute(const StateView<dim> &state, StatisticsTable &) override
        {
          if (tracked)
            tracked->execute(state);
        }

        void
        write(const StateView<dim> &state) override
        {
          if (tracked)
            tracked->write(state.output_directory, state.comm);
        }

        void
        save(Archive &archive) const override
        {
          if (tracked)
            tracked->save(archive);
        }

        void
        load(const Archive &archive) override
        {
          if (tracked)
            tracked->load(archive);
        }

        void
        fill_summary(const StateView<dim> &, Summary &summary) const override
        {
          if (tracked)
            tracked->fill_summary(summary);
        }

      private:
        Point<dim>
        tracked_point() const
        {
          Point<dim> X;
          for (unsigned int d = 0; d < dim; ++d)
            X[d] = point[d];
          return X;
        }

        std::string                           text;
        std::vector<double>                   point;
        std::unique_ptr<TrackedParticle<dim>> tracked;
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, TrackedParticleFile>
      register_tracked_particle("tracked particle",
                                "the history of one particle against the "
                                "reference (tracked_particle.txt)",
                                &TrackedParticleFile<2>::declare_parameters);
  } // namespace Postprocess
} // namespace psmpm
