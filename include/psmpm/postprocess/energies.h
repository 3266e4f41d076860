// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_energies_h
#define psmpm_postprocess_energies_h

#include <psmpm/postprocess/state_view.h>
#include <psmpm/postprocess/statistics_table.h>

#include <array>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /// Global sums over the particles of all ranks.
    template <int dim>
    struct Energies
    {
      double kinetic = 0, strain = 0, gravity = 0;
      /// Energy dissipated by plastic flow so far (materials that
      /// dissipate only; the column dissipated_energy exists then).
      double         dissipated  = 0;
      bool           dissipative = false;
      Tensor<1, dim> momentum;
      double         mass = 0;
      /// What is conserved: kinetic + strain + gravity + dissipated.
      double
      total() const
      {
        return kinetic + strain + gravity + dissipated;
      }
      /// kinetic + strain + |gravity| + dissipated: the scale of energy
      /// errors.
      double
      scale() const
      {
        return kinetic + strain + std::abs(gravity) + dissipated;
      }
    };

    /**
     * Energies (strain energy from the material's stored energy density),
     * mass and momentum of the particles. The gravity energy is measured
     * from the initial positions.
     */
    template <int dim>
    class EnergyStatistics
    {
    public:
      Energies<dim>
      compute(const StateView<dim> &state) const;

      /// This rank's particles [@p first, @p last) added to the local
      /// sums @p sums, in particle order (compute() is accumulate() over all
      /// particles, then reduce()).
      void
      accumulate(const StateView<dim> &state,
                 const std::size_t     first,
                 const std::size_t     last,
                 Energies<dim>        &sums) const;

      /// The sums of all ranks.
      static Energies<dim>
      reduce(const Energies<dim> &local, MPI_Comm comm);

      /// Columns kinetic_energy ... momentum_y of @p e.
      static void
      add_columns(const Energies<dim> &e, StatisticsTable &statistics);

    private:
      /// Energy densities of a chunk of particles (scratch): computed and
      /// summed while the chunk is in the cache.
      static constexpr std::size_t      chunk = 512;
      mutable std::array<double, chunk> energy_density;
      mutable std::array<double, chunk> dissipation;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
