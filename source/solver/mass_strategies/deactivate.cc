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
      /// Poorly supported functions are switched off for the step.
      template <int dim>
      class Deactivate : public PoorlySupported<dim>
      {
      public:
        explicit Deactivate(const double threshold)
          : PoorlySupported<dim>(threshold, false)
        {
        }
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, Deactivate> register_deactivate(
      "deactivate",
      "functions with a particle diagonal below Threshold x their "
      "full-support diagonal set to zero for the step");
  } // namespace Solver
} // namespace psmpm
