// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/basis/linear.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/basis/space.h>

namespace psmpm
{
  namespace Basis
  {
    void
    Space::evaluate(const unsigned int  n,
                    const unsigned int *cells,
                    const Point<2>     *points,
                    double             *values,
                    Tensor<1, 2>       *gradients) const
    {
      const unsigned int n_dofs = dofs_per_cell();
      for (unsigned int i = 0; i < n; ++i)
        evaluate(cells[i],
                 points[i],
                 values + n_dofs * i,
                 gradients != nullptr ? gradients + n_dofs * i : nullptr);
    }

    std::unique_ptr<Space>
    create_space(const std::string &name)
    {
      if (name == "linear")
        return std::make_unique<Linear>();
      if (name == "powell-sabin")
        return std::make_unique<PowellSabin>();
      AssertThrow(false,
                  ExcMessage("Basis/Type = " + name +
                             ": unknown basis (known: linear, powell-sabin)."));
      return nullptr;
    }
  } // namespace Basis
} // namespace psmpm
