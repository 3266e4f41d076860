// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_linear_h
#define psmpm_basis_linear_h

#include <deal.II/fe/fe_simplex_p.h>

#include <psmpm/basis/space.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    /**
     * Classical linear (P1) Lagrange functions on triangles: the
     * barycentric coordinates of each cell, stored as affine functions so
     * that evaluation is three multiply-adds per function.
     */
    class Linear : public Space
    {
    public:
      Linear();

      std::string
      name() const override;

      const FiniteElement<2> &
      dof_layout() const override;

      void
      reinit(const DoFHandler<2> &dof_handler) override;

      void
      evaluate(const unsigned int cell,
               const Point<2>    &p,
               double            *values,
               Tensor<1, 2>      *gradients) const override;

      void
      evaluate(const unsigned int  n,
               const unsigned int *cells,
               const Point<2>     *points,
               double             *values,
               Tensor<1, 2>       *gradients) const override;

      void
      make_dirichlet_constraints(
        const DoFHandler<2>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<2>                  &g,
        AffineConstraints<double>          &constraints) const override;

    private:
      FE_SimplexP<2> fe;

      /// lambda_k(x) = constant[k] + gradient[k] . x, per cell.
      struct CellData
      {
        std::array<double, 3>       constant;
        std::array<Tensor<1, 2>, 3> gradient;
      };
      std::vector<CellData> cell_data;
    };
  } // namespace Basis
} // namespace psmpm

#endif
