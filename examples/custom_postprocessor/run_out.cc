// ---------------------------------------------------------------------
// custom_postprocessor: a postprocessor defined outside psmpm.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <psmpm/base/registry.h>
#include <psmpm/base/summary.h>
#include <psmpm/postprocess/postprocessor.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace psmpm;

  /**
   * The run-out of the material: how far its front has advanced along a
   * direction d since the start,
   *
   *   run_out = max_p (x_p . d) - max_p (X_p . d),
   *
   * with x_p a particle's position, X_p its initial position and d the
   * unit vector of Run-out/Direction (downslope for a landslide or a
   * collapsing column). Column run_out of statistics.txt at every step,
   * its final value run_out in summary.json.
   *
   * The initial front comes from the particles' initial positions, which
   * psmpm keeps (and checkpoints) itself, so this postprocessor has no
   * history and needs neither save() nor load(): a resumed run continues
   * the column unchanged.
   */
  class RunOut : public Postprocess::Postprocessor<2>
  {
  public:
    /// The registration's declare function: a subsection of its own.
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Run-out");
      prm.declare_entry("Direction",
                        "1, 0",
                        Patterns::List(Patterns::Double(), 2, 2, ","),
                        "The direction along which column run_out of "
                        "statistics.txt measures the advance of the "
                        "material's front (any length but zero; it is "
                        "normalized).");
      prm.leave_subsection();
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      prm.enter_subsection("Run-out");
      const std::string text = prm.get("Direction");
      prm.leave_subsection();
      std::vector<double> d;
      // The pattern admits numbers that string_to_double refuses
      // (subnormals such as 4.9e-324).
      try
        {
          d = Utilities::string_to_double(
            Utilities::split_string_list(text, ','));
        }
      catch (const std::exception &)
        {
          d.clear();
        }
      const double length = d.size() == 2 ? std::hypot(d[0], d[1]) : 0.0;
      AssertThrow(std::isfinite(length) && length > 0,
                  ExcMessage("Run-out/Direction = '" + text +
                             "': not a nonzero vector of two numbers."));
      direction[0] = d[0] / length;
      direction[1] = d[1] / length;
    }

    /// Its column goes after psmpm's own (they end at 500).
    unsigned int
    order() const override
    {
      return 1000;
    }

    /// Collective: the front is the largest projection over all ranks.
    void
    execute(const Postprocess::StateView<2> &state,
            Postprocess::StatisticsTable    &statistics) override
    {
      statistics.add_value("run_out", run_out(state));
      statistics.set_scientific("run_out", true);
      statistics.set_precision("run_out", 10);
    }

    void
    fill_summary(const Postprocess::StateView<2> &state,
                 Summary                         &summary) const override
    {
      summary.set("run_out", run_out(state));
    }

  private:
    double
    run_out(const Postprocess::StateView<2> &state) const
    {
      const auto &particles = state.particles;
      // A rank without particles takes no part in either maximum.
      double front = -std::numeric_limits<double>::max();
      double start = -std::numeric_limits<double>::max();
      for (std::size_t i = 0; i < particles.position.size(); ++i)
        {
          front = std::max(front, particles.position[i] * direction);
          start = std::max(start, particles.initial_position[i] * direction);
        }
      front = Utilities::MPI::max(front, state.comm);
      start = Utilities::MPI::max(start, state.comm);
      return front - start;
    }

    Tensor<1, 2> direction;
  };

  // The one registration that runs it in every 2D scene of this
  // executable and declares subsection Run-out.
  Registration<Postprocess::PostprocessorRegistry<2>>
    register_run_out({"run-out",
                      "the advance of the material's front along "
                      "Run-out/Direction (examples/custom_postprocessor)",
                      [] { return std::make_unique<RunOut>(); },
                      &RunOut::declare_parameters});
} // namespace
