// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_function_of_time_h
#define psmpm_simulator_function_of_time_h

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * A velocity given as a function of time (Boundary conditions/
     * Prescribed velocity, Bodies/Body k/Velocity): one muParser
     * expression of t per component, with the constant pi. It is
     * evaluated once at t = 0 here, because muParser reports an unknown
     * variable or a malformed expression only at the first evaluation,
     * which would otherwise come in the middle of a run; a component that
     * is not finite at t = 0 (0/0, 1e309) is refused too. Throws the
     * parser's exception or ExcMessage naming the component; the caller
     * names its entry.
     */
    std::unique_ptr<FunctionParser<1>>
    parse_function_of_time(const std::vector<std::string> &expressions);

    /**
     * For the run's check before a step: " is not finite at t = ...
     * (component d: value)" for the first component of @p function that
     * is not finite at @p t (a component d with @p skip and skip[d] is
     * not looked at), empty if every one is. The caller puts its entry
     * in front.
     */
    std::string
    non_finite_at(const FunctionParser<1> &function,
                  const double             t,
                  const bool              *skip = nullptr);
  } // namespace Simulator
} // namespace psmpm

#endif
