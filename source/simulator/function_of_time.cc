// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/simulator/function_of_time.h>

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
        function->value(Point<1>(0.), d);
      return function;
    }
  } // namespace Simulator
} // namespace psmpm
