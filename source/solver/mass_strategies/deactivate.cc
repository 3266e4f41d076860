// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/solver/mass_strategy.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /**
       * Removed. `deactivate` constrained the functions of poorly
       * supported vertices to zero for the step: a zero Dirichlet
       * condition inside the body, which holds the particles near it
       * (measured on the free rotating block, doc/stability.md: it turns
       * by 0 instead of a quarter turn). Setting the switched-off
       * coefficients from their active neighbours instead is exactly
       * `extrapolate`, so the name is kept only to point there.
       */
      template <int dim>
      class Deactivate : public MassStrategy<dim>
      {
      public:
        explicit Deactivate(const double)
        {
          AssertThrow(
            false,
            ExcMessage(
              "Mass matrix/Type = deactivate was removed: constraining "
              "poorly supported functions to zero pins the material (a "
              "fixed support inside the body, doc/stability.md). Use "
              "'fictitious mass' (consistent mass, stabilised where cells "
              "empty), 'partially lumped' or 'extrapolate' (switched-off "
              "functions continued from their neighbours)."));
        }
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, Deactivate> register_deactivate(
      "deactivate",
      "removed (it pinned the material); selecting it is an error that "
      "names the replacements");
  } // namespace Solver
} // namespace psmpm
