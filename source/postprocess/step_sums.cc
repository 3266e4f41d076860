// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/step_sums.h>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    StepSums<dim>::StepSums(const EnergyStatistics<dim> &energies,
                            RotationStatistics<dim>     &rotation)
      : energies(energies)
      , rotation(rotation)
    {
    }

    template <int dim>
    void
    StepSums<dim>::updated(const StateView<dim> &state,
                           const std::size_t     first,
                           const std::size_t     last)
    {
      if (first == 0)
        {
          energy_sums   = Energies<dim>();
          rotation_sums = typename RotationStatistics<dim>::Sums();
          covered       = 0;
          complete      = false;
        }
      // Chunks out of order, or a rotation statistic that still has
      // collective work to do (its first call), fall back to the pass.
      if (first != covered || !rotation.prepared())
        {
          covered = std::numeric_limits<std::size_t>::max();
          return;
        }
      energies.accumulate(state, first, last, energy_sums);
      rotation.accumulate(state, first, last, false, rotation_sums);
      covered  = last;
      complete = last == state.particles.size();
    }

    template <int dim>
    std::pair<Energies<dim>, typename RotationStatistics<dim>::Values>
    StepSums<dim>::compute(const StateView<dim> &state, const bool affine_part)
    {
      // Every rank makes the same collective calls on either path: the
      // energies' reduction, then the rotation's (prepare() has nothing
      // collective left once the chunks are used).
      const bool use_chunks = complete && !affine_part;
      complete              = false;
      covered               = 0;
      if (use_chunks)
        return {EnergyStatistics<dim>::reduce(energy_sums, state.comm),
                rotation.finish(rotation_sums, state.comm)};
      const Energies<dim> e = energies.compute(state);
      return {e, rotation.compute(state, affine_part)};
    }

    template class StepSums<1>;
    template class StepSums<2>;
  } // namespace Postprocess
} // namespace psmpm
