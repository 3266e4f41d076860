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
      /// Row-sum diagonal: no sparse matrix is built at all.
      template <int dim>
      class Lumped : public MassStrategy<dim>
      {
      public:
        bool
        uses_matrix() const override
        {
          return false;
        }
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, Lumped>
      register_lumped("lumped", "row-sum diagonal (no sparse matrix is built)");
  } // namespace Solver
} // namespace psmpm
