// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/basis/space.h>

namespace psmpm
{
  namespace Basis
  {
    template <int dim>
    void
    Space<dim>::evaluate(const unsigned int  n,
                         const unsigned int *cells,
                         const Point<dim>   *points,
                         double             *values,
                         Tensor<1, dim>     *gradients) const
    {
      const unsigned int n_dofs = dofs_per_cell();
      for (unsigned int i = 0; i < n; ++i)
        evaluate(cells[i],
                 points[i],
                 values + n_dofs * i,
                 gradients != nullptr ? gradients + n_dofs * i : nullptr);
    }

    template <int dim>
    std::unique_ptr<Space<dim>>
    create_space(const std::string &name)
    {
      // The spaces register themselves from their own source files
      // (linear.cc, powell_sabin.cc), so this file names none of them.
      return SpaceRegistry<dim>::instance().create(name, "Basis/Type");
    }

    template class Space<1>;
    template class Space<2>;
    template std::unique_ptr<Space<1>>
    create_space<1>(const std::string &);
    template std::unique_ptr<Space<2>>
    create_space<2>(const std::string &);
  } // namespace Basis
} // namespace psmpm
