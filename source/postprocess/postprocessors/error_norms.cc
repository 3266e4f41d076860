// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/error_norms.h>
#include <psmpm/postprocess/postprocessor.h>

#include <memory>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// Columns displacement_L2, velocity_L2 and stress_L2 against the
      /// scene's reference every Output/Error interval steps (ErrorNorms),
      /// their maximum and RMS over time in summary.json. Nothing without
      /// a reference.
      template <int dim>
      class ErrorNormColumns : public Postprocessor<dim>
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Output");
          prm.declare_entry("Error interval",
                            "1",
                            Patterns::Integer(1),
                            "Compute error norms against the reference every "
                            "this many steps (and at the end).");
          prm.leave_subsection();
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          prm.enter_subsection("Output");
          interval = prm.get_integer("Error interval");
          prm.leave_subsection();
        }

        unsigned int
        order() const override
        {
          return 400;
        }

        void
        initialize(const StateView<dim> &state) override
        {
          norms.reset();
          if (state.reference)
            norms =
              std::make_unique<ErrorNorms<dim>>(*state.reference, interval);
        }

        void
        execute(const StateView<dim> &state,
                StatisticsTable      &statistics) override
        {
          if (!norms)
            return;
          norms->execute(state, state.last_step, statistics);
          for (const char *c : {"displacement_L2", "velocity_L2", "stress_L2"})
            {
              statistics.set_scientific(c, true);
              statistics.set_precision(c, 8);
            }
        }

        void
        save(Archive &archive) const override
        {
          if (norms)
            norms->save(archive);
        }

        void
        load(const Archive &archive) override
        {
          if (norms)
            norms->load(archive);
        }

        void
        fill_summary(const StateView<dim> &state,
                     Summary              &summary) const override
        {
          if (norms)
            norms->fill_summary(state, summary);
        }

      private:
        unsigned int                     interval = 1;
        std::unique_ptr<ErrorNorms<dim>> norms;
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, ErrorNormColumns>
      register_error_norms("error norms",
                           "L2 errors against the reference solution "
                           "(thesis eq. 4.4)",
                           &ErrorNormColumns<2>::declare_parameters);
  } // namespace Postprocess
} // namespace psmpm
