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
     * Classical linear Lagrange functions on simplices (hat functions on
     * lines in 1D, P1 on triangles in 2D): the barycentric coordinates of
     * each cell, stored as affine functions so that evaluation is dim + 1
     * multiply-adds per function. The DoF layout is FE_SimplexP<dim>(1),
     * whose local function k is the DoF of cell->vertex(k).
     *
     * Registered as "linear" in SpaceRegistry<1> and SpaceRegistry<2>.
     */
    template <int dim>
    class Linear : public Space<dim>
    {
    public:
      Linear();

      std::string
      name() const override;

      unsigned int
      degree() const override
      {
        return 1;
      }

      const FiniteElement<dim> &
      dof_layout() const override;

      void
      reinit(const DoFHandler<dim> &dof_handler) override;

      void
      evaluate(const unsigned int cell,
               const Point<dim>  &p,
               double            *values,
               Tensor<1, dim>    *gradients) const override;

      void
      evaluate(const unsigned int  n,
               const unsigned int *cells,
               const Point<dim>   *points,
               double             *values,
               Tensor<1, dim>     *gradients) const override;

      bool
      gradients_constant_on_cells() const override
      {
        return true;
      }

      /// u = g(V) at every vertex V of the boundaries @p ids.
      void
      make_dirichlet_constraints(
        const DoFHandler<dim>              &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<dim>                &g,
        AffineConstraints<double>          &constraints) const override;

      /// The mesh vertices: the nodal coefficients f(V) reproduce affine f.
      std::vector<Point<dim>>
      control_points(const DoFHandler<dim> &dof_handler) const override;

      /// The 1 x 1 identity: the linear part of a hat function at its
      /// vertex is its nodal value.
      FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const override;

      /**
       * The simplex Gauss rule of degree 5 mapped to the cell. Products of
       * two functions need degree 2 only; the higher degree makes the
       * right-hand side of an L2 projection of a smooth function accurate
       * to well below the projection error.
       */
      Quadrature<dim>
      cell_quadrature(const DoFHandler<dim> &dof_handler,
                      const unsigned int     cell) const override;

      double
      stability_factor(const bool lumped) const override;

    private:
      FE_SimplexP<dim> fe;

      /// lambda_k(x) = constant[k] + gradient[k] . x, per cell.
      struct CellData
      {
        std::array<double, dim + 1>         constant;
        std::array<Tensor<1, dim>, dim + 1> gradient;
      };
      std::vector<CellData> cell_data;

      /// Vertices per cell, for cell_quadrature(); kept apart from
      /// cell_data so that evaluate() touches one small block per cell.
      std::vector<std::array<Point<dim>, dim + 1>> cell_vertices;
    };
  } // namespace Basis
} // namespace psmpm

#endif
