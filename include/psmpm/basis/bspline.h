// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_bspline_h
#define psmpm_basis_bspline_h

#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/basis/space.h>

#include <memory>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    /**
     * B-splines of degree p = Basis/Degree (1 to 5) with maximal
     * continuity C^{p-1} on the open knot vector of a 1D mesh (knots at
     * the vertices, the end knots repeated p + 1 times; BSMPM, Wobbes et
     * al. 2019, section 4.3), by Bezier extraction. The DoF layout is
     * FE_Q<1>(p): one DoF per vertex and p - 1 per cell, the Bezier
     * (Bernstein) coefficients of a C0 piecewise polynomial of degree p.
     * evaluate() gives the p + 1 Bernstein polynomials of the cell (local
     * order: vertex 0, vertex 1, then the interior ones from vertex 0 to
     * vertex 1), and make_space_constraints() ties the (n - 1)(p - 1)
     * surplus Bezier coefficients of n cells to the others, so that the
     * constrained C0 space is the space of the n + p B-splines. Mesh
     * vertices may be non-uniform.
     *
     * p = 1: the layout's functions are the B-splines (hat functions),
     * no ties. p = 2: every interior vertex DoF is tied to the two
     * neighbouring cell DoFs,
     *
     *   c_v = (h_R c_L + h_L c_R) / (h_L + h_R),
     *
     * the C1 condition, and the n + 2 free DoFs (the two end vertices and
     * the n cells) carry the n + 2 B-splines, B_0 and B_{n+1} at the ends
     * (interpolatory) and B_{c+1} on cell c (Greville abscissa: the cell
     * midpoint). p >= 3: the ties come from the Bezier extraction
     * operators of the cells (bezier_extraction()); the free DoFs are the
     * two end vertex DoFs and the interior DoFs of every (p - 1)-th cell
     * (plus some interior DoFs of the last cell), and their functions are
     * combinations of p - 1 neighbouring B-splines, not B-splines: the
     * middle p - 1 Bezier coefficients of a cell determine its middle
     * p - 1 B-spline coefficients, but no Bezier coefficient equals a
     * B-spline coefficient. The space is the same, so results that
     * depend on the space only (consistent mass) are those of the
     * B-splines; the lumped mass depends on the basis and is therefore
     * refused for p >= 3 (verified_mass_matrices()).
     *
     * Only the mass matrices and transfers in verified_mass_matrices()
     * and verified_transfers() have been checked (the vertex-wise
     * strategies assume one DoF set per vertex and do not see the cell
     * DoFs).
     *
     * Registered as "bspline" in SpaceRegistry<1>.
     */
    class BSpline : public Space<1>
    {
    public:
      /// The degrees whose stable time step was measured.
      static constexpr unsigned int max_degree = 5;

      /// Degree 2 until set_degree() says otherwise.
      BSpline();

      std::string
      name() const override;

      unsigned int
      degree() const override
      {
        return p;
      }

      /// Throws (naming Basis/Degree) for degrees above max_degree.
      void
      set_degree(const unsigned int degree) override;

      const FiniteElement<1> &
      dof_layout() const override;

      /// Cell geometry, the knot vector and the Bezier extraction
      /// operators (the mesh must be one interval).
      void
      reinit(const DoFHandler<1> &dof_handler) override;

      /// The Bernstein polynomials of degree p of the cell in the local
      /// order, t = (x - x_0) / (x_1 - x_0) (p = 2: (1 - t)^2, t^2,
      /// 2 t (1 - t)).
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

      /// The C^{p-1} ties of the surplus Bezier DoFs (see the class
      /// comment); none for p = 1.
      void
      make_space_constraints(
        const DoFHandler<1>       &dof_handler,
        AffineConstraints<double> &constraints) const override;

      /// u = g at the boundary vertices: the end B-splines are the only
      /// functions that do not vanish there, and they equal 1; their
      /// coefficients are the (never tied) end vertex DoFs.
      void
      make_dirichlet_constraints(
        const DoFHandler<1>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<1>                  &g,
        AffineConstraints<double>          &constraints) const override;

      /// Bezier control points: the vertices and the p - 1 equally spaced
      /// interior points of every cell, the Bezier coefficients of x, so
      /// that every tie holds for them and x is reproduced. For p <= 2
      /// these are the Greville abscissae of the free DoFs' B-splines; for
      /// p >= 3 the free DoFs carry no single B-spline, and a Greville
      /// abscissa would not reproduce x.
      std::vector<Point<1>>
      control_points(const DoFHandler<1> &dof_handler) const override;

      /// Not defined for this space (extrapolate is refused with it).
      FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const override;

      /// (p + 1)-point Gauss rule on the cell (degree 2p + 1; products
      /// need 2p).
      Quadrature<1>
      cell_quadrature(const DoFHandler<1> &dof_handler,
                      const unsigned int   cell) const override;

      double
      stability_factor(const bool lumped) const override;

      /// Consistent mass (with MUSL): measured far more accurate than
      /// lumped mass near the ends (doc/chapter.md), and the only one
      /// verified for p >= 3.
      std::string
      default_mass_matrix(const bool grid_moves = false) const override;

      /// Lumped and consistent for p <= 2, consistent only for p >= 3.
      std::vector<std::string>
      verified_mass_matrices() const override;

      std::vector<std::string>
      verified_transfers() const override;

      /**
       * Bezier extraction of cell @p cell (active index, after reinit()):
       * entry (k, i) is the coefficient of local DoF k (layout order) in
       * B-spline first_bspline(cell) + i, i = 0, ..., p, the B-splines
       * being numbered from the left end of the mesh. The ties of p >= 3
       * are built from it; tests assemble the B-splines with it.
       */
      const FullMatrix<double> &
      bezier_extraction(const unsigned int cell) const;

      /// The first of the p + 1 B-splines that do not vanish on @p cell.
      unsigned int
      first_bspline(const unsigned int cell) const;

    private:
      unsigned int p;

      std::unique_ptr<FE_Q<1>> fe;

      /// Left vertex and 1 / length of each cell (signed: either vertex
      /// order is right).
      struct CellData
      {
        double origin;
        double inverse_length;
      };
      std::vector<CellData> cell_data;

      /// Position of each cell from the left end, and its Bezier
      /// extraction operator (see bezier_extraction()).
      std::vector<unsigned int>       position;
      std::vector<FullMatrix<double>> extraction;
    };
  } // namespace Basis
} // namespace psmpm

#endif
