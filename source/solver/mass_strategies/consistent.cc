// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/mass_strategy.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// The particle-quadrature mass matrix as it is, solved by CG
      /// (thesis Sec. 2.3); singular where functions lose their support.
      template <int dim>
      class Consistent : public MassStrategy<dim>
      {
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, Consistent>
      register_consistent("consistent",
                          "the particle mass matrix, solved by CG");
  } // namespace Solver
} // namespace psmpm
