// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_tensor_bspline_h
#define psmpm_basis_tensor_bspline_h

#include <deal.II/fe/fe_q.h>

#include <psmpm/basis/bspline.h>
#include <psmpm/basis/space.h>
#include <psmpm/mesh/cartesian_grid.h>

#include <array>
#include <utility>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    /**
     * Tensor-product B-splines of degree p = Basis/Degree (1 to 5) with
     * maximal continuity C^{p-1} in x and in y on a Cartesian mesh of
     * rectangles (Mesh/Type = cartesian; the grid lines are the knots, the
     * end knots repeated p + 1 times: Wobbes et al. 2019, section 4.3, in
     * 2D), by Bezier extraction: the 2D version of BSpline.
     *
     * The DoF layout is FE_Q<2>(p): per cell the (p + 1)^2 Bezier
     * (Bernstein) coefficients of a C0 piecewise polynomial of degree p in
     * each variable. On a grid of nx by ny cells they form a lattice of
     * (p nx + 1) x (p ny + 1) coefficients, lattice point (I, J) belonging
     * to the Bernstein polynomial I mod p (or p) in x of cell column
     * I / p, and likewise in y. The B-spline space is the tensor product
     * S_x (x) S_y of two univariate spline spaces, each a subspace of the
     * univariate C0 layout cut out by BSpline's ties c_I = sum_K w_IK c_K
     * (K free). The tensor product of the two tie maps is therefore the
     * tie map of S_x (x) S_y:
     *
     *   c_IJ = sum_K sum_L w^x_IK w^y_JL c_KL,
     *
     * with w = identity for free rows; lattice points free in both
     * directions are the free DoFs. For p <= 2 their functions are the
     * tensor-product B-splines (non-negative, partition of unity), which
     * the lumped mass lumps; for p >= 3 they are combinations (see
     * BSpline), so lumped mass is refused there, as in 1D.
     *
     * Dirichlet conditions: on a boundary line x = x_0 only the B-splines
     * of the first column (I = 0) are non-zero, and they reduce to the
     * univariate B-splines in y; their coefficients are the lattice points
     * on that line, which are set to g at their Bezier control points
     * (exact for homogeneous and affine g).
     *
     * Registered as "bspline" in SpaceRegistry<2>.
     */
    class TensorBSpline : public Space<2>
    {
    public:
      /// Degree 2 until set_degree() says otherwise.
      TensorBSpline();

      std::string
      name() const override;

      unsigned int
      degree() const override
      {
        return p;
      }

      /// Throws (naming Basis/Degree) outside 1 to BSpline::max_degree.
      void
      set_degree(const unsigned int degree) override;

      const FiniteElement<2> &
      dof_layout() const override;

      /// Grid lines, cell positions and geometry, and the univariate ties
      /// in x and y. Throws if the mesh is not Cartesian.
      void
      reinit(const DoFHandler<2> &dof_handler) override;

      /// Products of the Bernstein polynomials in x and y of the cell, in
      /// FE_Q<2>(p)'s local DoF order.
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

      /// The tensor product of the univariate C^{p-1} ties (class comment).
      void
      make_space_constraints(
        const DoFHandler<2>       &dof_handler,
        AffineConstraints<double> &constraints) const override;

      /// u = g at the Bezier control points of the lattice points on the
      /// boundary lines with the given ids.
      void
      make_dirichlet_constraints(
        const DoFHandler<2>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<2>                  &g,
        AffineConstraints<double>          &constraints) const override;

      /// Bezier control points: (x_i + a h_x / p, y_j + b h_y / p) for
      /// lattice point (a, b) of cell (i, j); they reproduce x and y.
      std::vector<Point<2>>
      control_points(const DoFHandler<2> &dof_handler) const override;

      /// Not defined for this space (extrapolate is refused with it).
      FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const override;

      /// (p + 1)^2-point Gauss rule on the rectangle.
      Quadrature<2>
      cell_quadrature(const DoFHandler<2> &dof_handler,
                      const unsigned int   cell) const override;

      /// Relative to the shortest side of any cell.
      double
      stability_factor(const bool lumped) const override;

      /// p <= 2: lumped, the one that stays stable as cells empty (a free
      /// body completes at every Courant number to 2, consistent mass
      /// fails within 115 steps, ghost penalty mass from Courant number
      /// 0.96 on, doc/chapter.md "BSMPM in 2D"), and the cheapest; p >= 3:
      /// ghost penalty (lumped mass is not sound there, consistent mass
      /// fails on nearly empty cells).
      std::string
      default_mass_matrix(const bool grid_moves = false) const override;

      /// Consistent: where no cell empties it is the accurate one (soil
      /// column on 4 cells: displacement error 6.3e-3 against 4.2e-2
      /// lumped).
      std::string
      closed_mass_matrix() const override;

      /// Lumped, consistent and ghost penalty for p <= 2, consistent and
      /// ghost penalty for p >= 3.
      std::vector<std::string>
      verified_mass_matrices() const override;

      std::vector<std::string>
      verified_transfers() const override;

    private:
      unsigned int p;

      std::unique_ptr<FE_Q<2>> fe;

      /// The univariate spaces on the grid lines in x and y: their ties
      /// and their Bernstein polynomials (cell k = k-th column or row).
      std::array<BSpline, 2> univariate;

      /// Lattice offset (a, b) in the cell of every local DoF, and the
      /// univariate local DoFs (FE_Q<1>(p) order) of its two factors.
      std::vector<std::array<unsigned int, 2>> local_lattice;
      std::vector<std::array<unsigned int, 2>> local_univariate;

      /// Grid lines in x and y and the grid position (column, row) of
      /// each cell; a cell's geometry is that of its grid lines (and of
      /// the univariate spaces' cells).
      Mesh::CartesianGrid grid;

      /// Univariate ties per direction: ties[d][I] lists (K, w) with K
      /// free; empty for a free lattice line I.
      using Tie = std::vector<std::pair<unsigned int, double>>;
      std::array<std::vector<Tie>, 2> ties;

      /// Lattice point (I, J) of local DoF @p k of cell @p c.
      std::array<unsigned int, 2>
      lattice(const unsigned int c, const unsigned int k) const;

      /// The Bezier control point of lattice point @p IJ.
      Point<2>
      control_point(const std::array<unsigned int, 2> &IJ) const;

      /// Set up univariate[d] on the grid lines of direction @p d and
      /// return the ties of its lattice lines.
      std::vector<Tie>
      univariate_ties(const unsigned int d);
    };
  } // namespace Basis
} // namespace psmpm

#endif
