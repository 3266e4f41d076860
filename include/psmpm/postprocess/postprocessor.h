// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_postprocessor_h
#define psmpm_postprocess_postprocessor_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/registry.h>
#include <psmpm/postprocess/state_view.h>
#include <psmpm/postprocess/statistics_table.h>
#include <psmpm/base/summary.h>

#include <cstddef>
#include <limits>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    using namespace dealii;

    /// What the stability monitor watches after every step
    /// (StabilityMonitor::check()), filled by the postprocessor that
    /// computes the energies.
    struct EnergyBalance
    {
      /// The conserved energy (the walls' work is added by the caller).
      double total = 0;
      /// The scale of energy errors.
      double scale = 0;
      /// The norm of the total momentum.
      double momentum = 0;
    };

    /**
     * A measurement of a run: per-step columns of statistics.txt, files
     * of its own, entries of summary.json, and the history it needs in a
     * checkpoint. Every postprocessor registered in
     * PostprocessorRegistry<dim> is created for every run; one that the
     * scene does not ask for (no reference, no Tracked point, ...) does
     * nothing in its hooks. The simulator calls the hooks of all of them
     * in order() at fixed points of the run; every hook has a default that
     * does nothing, so a postprocessor overrides only what it uses.
     *
     * Hooks that compute sums over the particles are collective: every
     * rank calls them in the same order.
     *
     * A new postprocessor is one source file with the class and its
     * registration, e.g.
     * @code
     * RegisterForDims<PostprocessorRegistry, MyPostprocessor> reg(
     *   "my quantity", "what it measures", &MyPostprocessor<2>::declare);
     * @endcode
     * (the declare function declares its own entries or subsection).
     */
    template <int dim>
    class Postprocessor
    {
    public:
      virtual ~Postprocessor() = default;

      /// Read the entries its registration declared; throw ExcMessage
      /// naming the entry and its value for bad input.
      virtual void
      parse_parameters(ParameterHandler &)
      {
      }

      /**
       * The place of its columns in a row of statistics.txt: at every
       * hook the postprocessors run in increasing order (equal orders by
       * name). After the simulator's step, time and dt come energies and
       * rotation (100), bodies (200), the mass solves (300), error norms
       * (400), the tracked particle (500); a postprocessor that keeps the
       * default comes after them. The simulator's own columns (the
       * walls', wall_time) close the row.
       */
      virtual unsigned int
      order() const
      {
        return 1000;
      }

      /// After setup, before anything is written: throw ExcMessage
      /// naming the entry for input the mesh contradicts (a point off
      /// the mesh), which ends the run as bad input. Collective.
      virtual void
      check_mesh(const Mesh::CellLocator<dim> &, MPI_Comm) const
      {
      }

      /// After setup, once the output directory is known; on a fresh run
      /// and on a resumed one (there before load()).
      virtual void
      initialize(const StateView<dim> &)
      {
      }

      /// A fresh run only, before the statistics of step 0 (a resumed run
      /// has its history from load()).
      virtual void
      start(const StateView<dim> &)
      {
      }

      /// Whether updated() is to be called for the chunks of particles
      /// the transfer scheme updates (not for schemes that carry affine
      /// matrices).
      virtual bool
      observes_updated_chunks() const
      {
        return false;
      }

      /// The particles [@p first, @p last) of this rank are updated for
      /// the step under way (positions, velocities, stresses, volumes
      /// final), in particle order from 0, while they are in the cache
      /// (TransferScheme::move_and_update_material()): sums over them here
      /// save a pass of their own. A chunk that does not start where the
      /// last ended, or a step without chunks, asks for a pass in
      /// execute().
      virtual void
      updated(const StateView<dim> &,
              const std::size_t /*first*/,
              const std::size_t /*last*/)
      {
      }

      /// After every step and at step 0: this step's columns. Collective.
      virtual void
      execute(const StateView<dim> &, StatisticsTable &)
      {
      }

      /// The energies of the last execute() for the stability monitor;
      /// false if this postprocessor computes none.
      virtual bool
      energy_balance(EnergyBalance &) const
      {
        return false;
      }

      /// Its own files in StateView::output_directory, at every output and
      /// after a resume (as of the checkpoint). Collective.
      virtual void
      write(const StateView<dim> &)
      {
      }

      /// Its history (what its future values depend on besides the
      /// state), under a prefix of its own.
      virtual void
      save(Archive &) const
      {
      }
      virtual void
      load(const Archive &)
      {
      }

      /// Its entries of summary.json. Collective.
      virtual void
      fill_summary(const StateView<dim> &, Summary &) const
      {
      }
    };

    /// Every postprocessor that runs; the factory takes no argument (the
    /// entries are read in parse_parameters()).
    template <int dim>
    using PostprocessorRegistry = Registry<Postprocessor<dim>>;
  } // namespace Postprocess
} // namespace psmpm

#endif
