// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/energies.h>
#include <psmpm/postprocess/postprocessor.h>
#include <psmpm/postprocess/rotation_statistics.h>
#include <psmpm/postprocess/step_sums.h>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * Columns kinetic_energy ... momentum_y (EnergyStatistics) and, in
       * 2D, angular_momentum and rotation_angle (RotationStatistics), with
       * the rotation's entries of summary.json and its history in
       * checkpoints; the energies go to the stability monitor. One
       * postprocessor for both: their particle sums are collected on the
       * same chunks (StepSums), and both fall back to a pass together, so
       * that the sums are added in the same order on every rank as a
       * pass would (on several ranks chunks and pass differ in round-off).
       */
      template <int dim>
      class EnergiesAndRotation : public Postprocessor<dim>
      {
      public:
        unsigned int
        order() const override
        {
          return 100;
        }

        bool
        observes_updated_chunks() const override
        {
          return true;
        }

        void
        updated(const StateView<dim> &state,
                const std::size_t     first,
                const std::size_t     last) override
        {
          sums.updated(state, first, last);
        }

        void
        execute(const StateView<dim> &state,
                StatisticsTable      &statistics) override
        {
          const auto [e, values] = sums.compute(state, state.carries_affine);
          EnergyStatistics<dim>::add_columns(e, statistics);
          rotation.add_columns(values, statistics);
          for (const char *c : {"kinetic_energy",
                                "strain_energy",
                                "gravity_energy",
                                "total_energy",
                                "mass",
                                "momentum_x",
                                "momentum_y"})
            if (dim > 1 || std::string(c) != "momentum_y")
              {
                statistics.set_scientific(c, true);
                statistics.set_precision(c, 8);
              }
          balance.total    = e.total();
          balance.scale    = e.scale();
          balance.momentum = e.momentum.norm();
        }

        bool
        energy_balance(EnergyBalance &b) const override
        {
          b = balance;
          return true;
        }

        void
        save(Archive &archive) const override
        {
          rotation.save(archive);
        }

        void
        load(const Archive &archive) override
        {
          rotation.load(archive);
        }

        void
        fill_summary(const StateView<dim> &, Summary &summary) const override
        {
          rotation.fill_summary(summary);
        }

      private:
        EnergyStatistics<dim>   energies;
        RotationStatistics<dim> rotation;
        StepSums<dim>           sums{energies, rotation};
        EnergyBalance           balance;
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, EnergiesAndRotation>
      register_energies("energies",
                        "kinetic, strain, gravity (and dissipated) energy, "
                        "mass and momentum; in 2D angular momentum and mean "
                        "rotation angle");
  } // namespace Postprocess
} // namespace psmpm
