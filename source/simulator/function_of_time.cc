// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/function_of_time.h>

#include <cmath>

namespace psmpm
{
  namespace Simulator
  {
    std::unique_ptr<FunctionParser<1>>
    parse_function_of_time(const std::vector<std::string> &expressions)
    {
      auto function = std::make_unique<FunctionParser<1>>(expressions.size());
      function->initialize("t", expressions, {{"pi", numbers::PI}});
      for (unsigned int d = 0; d < expressions.size(); ++d)
        {
          const double v = function->value(Point<1>(0.), d);
          AssertThrow(std::isfinite(v),
                      ExcMessage("component " + std::to_string(d + 1) + ", '" +
                                 expressions[d] + "', is " +
                                 (std::isnan(v) ? "nan" : prm_value(v)) +
                                 " at t = 0"));
        }
      return function;
    }

    std::string
    non_finite_at(const FunctionParser<1> &function,
                  const double             t,
                  const bool              *skip)
    {
      for (unsigned int d = 0; d < function.n_components; ++d)
        {
          const double v = function.value(Point<1>(t), d);
          if ((skip == nullptr || !skip[d]) && !std::isfinite(v))
            return " is not finite at t = " + prm_value(t) + " (component " +
                   std::to_string(d + 1) + ": " +
                   (std::isnan(v) ? std::string("nan") : prm_value(v)) + ")";
        }
      return std::string();
    }
  } // namespace Simulator
} // namespace psmpm
