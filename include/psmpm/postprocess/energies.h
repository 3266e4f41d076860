// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_energies_h
#define psmpm_postprocess_energies_h

#include <psmpm/postprocess/statistics_table.h>

#include <psmpm/simulator/state.h>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /// Global sums over the particles of all ranks.
    template <int dim>
    struct Energies
    {
      double         kinetic = 0, strain = 0, gravity = 0;
      Tensor<1, dim> momentum;
      double         mass = 0;
      double
      total() const
      {
        return kinetic + strain + gravity;
      }
      /// kinetic + strain + |gravity|: the scale of energy errors.
      double
      scale() const
      {
        return kinetic + strain + std::abs(gravity);
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
      compute(const Simulator::State<dim> &state) const;

      /// Columns kinetic_energy ... momentum_y of @p e.
      static void
      add_columns(const Energies<dim> &e, StatisticsTable &statistics);

    private:
      mutable std::vector<double> energy_density; // scratch
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
