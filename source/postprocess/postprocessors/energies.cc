// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/archive.h>
#include <psmpm/base/summary.h>
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
       * 2D, angular_momentum and rotation_angle (with affine transfers also
       * affine_kinetic_energy; RotationStatistics), with
       * the rotation's entries of summary.json and its history in
       * checkpoints; the energies (without the affine part) go to the
       * stability monitor. One
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
          rotation.add_columns(values, statistics, state.carries_affine);
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
          // Without the affine fields' kinetic energy: with prescribed
          // boundaries the book's work term lags the first steps, and the
          // particles' energy without the affine part leaves the slack
          // that keeps it from tripping (a driven Powell-Sabin footing
          // with apic would stop at step 2). affine_kinetic_energy is in
          // statistics.txt for the reader.
          balance.total    = e.total();
          balance.scale    = e.scale();
          balance.momentum = e.momentum.norm();
          if (!have_initial_momentum)
            initial_momentum = e.momentum;
          have_initial_momentum = true;
          momentum              = e.momentum;
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
          std::vector<double> p(&initial_momentum[0],
                                &initial_momentum[0] + dim);
          if (have_initial_momentum)
            archive.put("energies/initial_momentum", p);
        }

        void
        load(const Archive &archive) override
        {
          rotation.load(archive);
          // Checkpoints written before the entry existed: the resumed
          // run's first statistics stand in for the initial momentum.
          have_initial_momentum = archive.has("energies/initial_momentum");
          if (have_initial_momentum)
            {
              const auto &p = archive.get("energies/initial_momentum", dim);
              for (unsigned int d = 0; d < dim; ++d)
                initial_momentum[d] = p[d];
            }
        }

        void
        fill_summary(const StateView<dim> &, Summary &summary) const override
        {
          rotation.fill_summary(summary);
          // Full precision (statistics.txt keeps 9 digits): what a free
          // body conserves to round-off.
          const char *names[] = {"x", "y"};
          if (have_initial_momentum)
            for (unsigned int d = 0; d < dim; ++d)
              {
                summary.set(std::string("momentum_") + names[d] + "_initial",
                            initial_momentum[d]);
                summary.set(std::string("momentum_") + names[d] + "_final",
                            momentum[d]);
              }
        }

      private:
        EnergyStatistics<dim>   energies;
        RotationStatistics<dim> rotation;
        StepSums<dim>           sums{energies, rotation};
        EnergyBalance           balance;
        /// The particles' momentum at the first and the last statistics.
        bool           have_initial_momentum = false;
        Tensor<1, dim> initial_momentum, momentum;
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, EnergiesAndRotation>
      register_energies("energies",
                        "kinetic, strain, gravity (and dissipated) energy, "
                        "mass and momentum; in 2D angular momentum and mean "
                        "rotation angle");
  } // namespace Postprocess
} // namespace psmpm
