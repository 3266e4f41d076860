// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/postprocess/deposit_front.h>
#include <psmpm/postprocess/postprocessor.h>

#include <cmath>
#include <limits>
#include <string>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// The deposit's front along x of every body (DepositFront), with
      /// Output/Deposit front gap > 0: columns body<k>_x_front (x_front
      /// for a scene without Bodies).
      template <int dim>
      class DepositFrontColumns : public Postprocessor<dim>
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Output");
          prm.declare_entry(
            "Deposit front gap",
            "0",
            Patterns::Double(0),
            "0: off. A length g > 0: statistics.txt gets the column "
            "body<k>_x_front for every body (x_front without Bodies): "
            "its particles sorted by x from the smallest, the largest x "
            "before the first gap wider than g. The run-out of the "
            "connected deposit of a granular flow, where body<k>_x_max "
            "is the front particle, thrown ahead or not (about one cell "
            "is the usual g).");
          prm.leave_subsection();
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          prm.enter_subsection("Output");
          gap = prm.get_double("Deposit front gap");
          prm.leave_subsection();
          AssertThrow(std::isfinite(gap) && gap >= 0,
                      ExcMessage(
                        "Output/Deposit front gap = " + std::to_string(gap) +
                        ": must be a finite length >= 0."));
        }

        unsigned int
        order() const override
        {
          return 210;
        }

        void
        execute(const StateView<dim> &state,
                StatisticsTable      &statistics) override
        {
          if (!(gap > 0))
            return;
          const auto        &particles = state.particles;
          const unsigned int n         = std::max(1u, particles.n_bodies);
          for (unsigned int b = 1; b <= n; ++b)
            {
              values.clear();
              double low  = std::numeric_limits<double>::max();
              double high = -low;
              for (std::size_t i = 0; i < particles.size(); ++i)
                if (particles.n_bodies == 0 || particles.body_id[i] == b)
                  {
                    const double x = particles.position[i][0];
                    values.push_back(x);
                    low  = std::min(low, x);
                    high = std::max(high, x);
                  }
              low  = Utilities::MPI::min(low, state.comm);
              high = Utilities::MPI::max(high, state.comm);
              const std::string column =
                particles.n_bodies == 0 ?
                  std::string("x_front") :
                  "body" + std::to_string(b) + "_x_front";
              statistics.add_value(
                column,
                front.compute(values, low, high, gap, state.comm));
              statistics.set_scientific(column, true);
              statistics.set_precision(column, 8);
            }
        }

      private:
        double              gap = 0;
        std::vector<double> values;
        DepositFront        front;
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, DepositFrontColumns>
      register_deposit_front("deposit front",
                             "the front of every body's connected deposit "
                             "along x (Output/Deposit front gap)",
                             &DepositFrontColumns<2>::declare_parameters);
  } // namespace Postprocess
} // namespace psmpm
