// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_bspline_h
#define psmpm_basis_bspline_h

#include <deal.II/fe/fe_q.h>

#include <psmpm/basis/space.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    /**
     * Quadratic C1 B-splines on the open knot vector of a 1D mesh (knots
     * at the vertices, the end knots repeated three times; BSMPM, Wobbes
     * et al. 2019, section 4.3), by Bezier extraction: the DoF layout is
     * FE_Q<1>(2) (one DoF per vertex and one per cell), evaluate() gives
     * the three Bernstein polynomials of the cell (local order: vertex 0,
     * vertex 1, the cell's own DoF), and make_space_constraints() ties
     * every interior vertex DoF to the two neighbouring cell DoFs,
     *
     *   c_v = (h_R c_L + h_L c_R) / (h_L + h_R),
     *
     * the C1 condition at the vertex. The constrained C0 quadratic space is
     * the B-spline space: its n + 2 free DoFs (the two end vertices and
     * the n cells) carry the n + 2 B-splines, B_0 and B_{n+1} at the ends
     * (interpolatory) and B_{c+1} on cell c (Greville abscissa: the cell
     * midpoint). Mesh vertices may be non-uniform.
     *
     * Only `Basis/Degree = 2` is implemented; only the mass matrices and
     * transfers in verified_mass_matrices() and verified_transfers() have
     * been checked with it (the vertex-wise strategies assume one DoF set
     * per vertex and do not see the cell DoFs).
     *
     * Registered as "bspline" in SpaceRegistry<1>.
     */
    class BSpline : public Space<1>
    {
    public:
      BSpline();

      std::string
      name() const override;

      unsigned int
      degree() const override
      {
        return 2;
      }

      /// Throws (naming Basis/Degree) for any degree but 2.
      void
      set_degree(const unsigned int degree) override;

      const FiniteElement<1> &
      dof_layout() const override;

      void
      reinit(const DoFHandler<1> &dof_handler) override;

      /// The Bernstein polynomials of the cell: (1 - t)^2, t^2, 2 t (1 - t)
      /// with t = (x - x_0) / (x_1 - x_0).
      void
      evaluate(const unsigned int cell,
               const Point<1>    &p,
               double            *values,
               Tensor<1, 1>      *gradients) const override;

      void
      evaluate(const unsigned int  n,
               const unsigned int *cells,
               const Point<1>     *points,
               double             *values,
               Tensor<1, 1>       *gradients) const override;

      /// The C1 ties of the interior vertex DoFs (see the class comment).
      void
      make_space_constraints(
        const DoFHandler<1>       &dof_handler,
        AffineConstraints<double> &constraints) const override;

      /// u = g at the boundary vertices: B_0 and B_{n+1} are the only
      /// functions that do not vanish there, and they equal 1.
      void
      make_dirichlet_constraints(
        const DoFHandler<1>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<1>                  &g,
        AffineConstraints<double>          &constraints) const override;

      /// Bezier control points: vertices and cell midpoints; for the free
      /// DoFs these are the Greville abscissae of the B-splines, and the
      /// tied vertex DoFs satisfy the ties (x is reproduced).
      std::vector<Point<1>>
      control_points(const DoFHandler<1> &dof_handler) const override;

      /// Not defined for this space (extrapolate is refused with it).
      FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const override;

      /// Three-point Gauss rule on the cell (degree 5; products need 4).
      Quadrature<1>
      cell_quadrature(const DoFHandler<1> &dof_handler,
                      const unsigned int   cell) const override;

      double
      stability_factor(const bool lumped) const override;

      /// Consistent mass (with MUSL): measured far more accurate than
      /// lumped mass near the ends (doc/chapter.md).
      std::string
      default_mass_matrix(const bool grid_moves = false) const override;

      std::vector<std::string>
      verified_mass_matrices() const override;

      std::vector<std::string>
      verified_transfers() const override;

    private:
      FE_Q<1> fe;

      /// Left vertex and 1 / length of each cell (signed: either vertex
      /// order is right).
      struct CellData
      {
        double origin;
        double inverse_length;
      };
      std::vector<CellData> cell_data;
    };
  } // namespace Basis
} // namespace psmpm

#endif
