// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_step_sums_h
#define psmpm_postprocess_step_sums_h

#include <psmpm/postprocess/energies.h>
#include <psmpm/postprocess/rotation_statistics.h>
#include <psmpm/postprocess/state_view.h>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * The particle sums of the per-step statistics (energies, momentum,
     * angular momentum and rotation angle), collected a chunk at a time
     * while the transfer scheme updates the particles
     * (TransferScheme::move_and_update_material()): the chunk is then in
     * the cache, so the statistics need no pass over the particle arrays
     * of their own, which cost a quarter of a lumped P1 step on the
     * 320,000-particle throughput scene. The sums are the same ones in the
     * same particle order as a pass after the step; only on several ranks
     * do they differ in round-off, as particles that change rank in that
     * step's location are summed on the rank they left.
     *
     * compute() falls back to the pass when the chunks did not cover all
     * particles of the step that just ended: the first statistics of a
     * run, a scheme that updates its particles otherwise (APIC), a step
     * abandoned before its update. Schemes that carry affine matrices are
     * not observed: the angular momentum's affine part reads the basis at
     * the particles' new cells, evaluated after the update.
     */
    template <int dim>
    class StepSums
    {
    public:
      StepSums(const EnergyStatistics<dim> &energies,
               RotationStatistics<dim>     &rotation);

      void
      updated(const StateView<dim> &state,
              const std::size_t     first,
              const std::size_t     last);

      /// The energies and rotation values of @p state after a step (or at
      /// the start): reduced from the chunks if they covered all its
      /// particles, else by a pass. Collective.
      std::pair<Energies<dim>, typename RotationStatistics<dim>::Values>
      compute(const StateView<dim> &state, const bool affine_part);

    private:
      const EnergyStatistics<dim>           &energies;
      RotationStatistics<dim>               &rotation;
      Energies<dim>                          energy_sums;
      typename RotationStatistics<dim>::Sums rotation_sums;
      /// Particles [0, covered) summed in order this step.
      std::size_t covered = 0;
      /// Whether the chunks reached the last particle.
      bool complete = false;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
