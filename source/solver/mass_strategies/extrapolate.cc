// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/mass_strategies/poorly_supported.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Poorly supported vertices follow their nearest well supported one.
      template <int dim>
      class Extrapolate : public PoorlySupported<dim>
      {
      public:
        explicit Extrapolate(const double threshold)
          : PoorlySupported<dim>(threshold, true)
        {
        }
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, Extrapolate> register_extrapolate(
      "extrapolate",
      "vertices with such a function follow the linear part of the "
      "nearest well supported vertex (extended B-splines)");
  } // namespace Solver
} // namespace psmpm
