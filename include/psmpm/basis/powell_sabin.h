// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_powell_sabin_h
#define psmpm_basis_powell_sabin_h

#include <deal.II/fe/fe_system.h>

#include <psmpm/basis/powell_sabin_refinement.h>
#include <psmpm/basis/space.h>
#include <psmpm/mesh/held_cells.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    /**
     * Normalised quadratic Powell-Sabin B-splines: three C1 piecewise
     * quadratic functions per mesh vertex, built exactly as in
     * doc/powell_sabin.md (the standard construction of Dierckx and of
     * Speleers et al., as the thesis uses it)
     * (incenter refinement, smallest boundary-aligned control triangles,
     * triplets, Bezier ordinates on the six sub-triangles of every cell).
     *
     * The DoF layout is FESystem(FE_SimplexP(1), 3): local function 3k+q of
     * a cell is function q of cell->vertex(k), i.e. the q-th component of
     * the vertex's DoFs. Everything evaluation needs is precomputed per cell
     * in one contiguous block, so evaluate() does no allocation and no
     * search beyond three comparisons.
     *
     * Two-dimensional only; registered as "powell-sabin" in
     * SpaceRegistry<2>.
     */
    class PowellSabin : public Space<2>
    {
    public:
      /// How the control triangle of a vertex sits relative to the boundary.
      enum class VertexKind
      {
        /// Interior vertex: smallest enclosing triangle.
        interior,
        /// Straight boundary: one side on the boundary line.
        straight_boundary,
        /// Convex corner: a control point at the vertex, two sides along
        /// the boundary edges.
        corner,
        /// Reflex corner or non-manifold boundary vertex: no aligned
        /// triangle exists; Dirichlet rows are imposed in general form.
        unaligned_boundary
      };

      /// Value and gradient of one basis function at its own vertex.
      struct Triplet
      {
        double       alpha;
        Tensor<1, 2> gradient; // (beta, gamma)
      };

      PowellSabin();

      std::string
      name() const override;

      unsigned int
      degree() const override
      {
        return 2;
      }

      const FiniteElement<2> &
      dof_layout() const override;

      /**
       * Build the refinement, control triangles, triplets and Bezier
       * ordinates. Throws ExcMessage naming the vertex (index and
       * coordinates) if no valid, non-negative basis can be built there.
       */
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

      /**
       * Value and tangential derivative of u = g at every vertex of the
       * boundaries @p ids (section 5 of the construction note); the
       * tangential derivative of g is taken by a central difference along
       * each boundary edge, because a Function's gradient() silently
       * returns zero in release builds when it is not implemented.
       */
      void
      make_dirichlet_constraints(
        const DoFHandler<2>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<2>                  &g,
        AffineConstraints<double>          &constraints) const override;

      /**
       * Control point of DoF (vertex v, q) is Q_{v,q}, the q-th corner of
       * the control triangle of v: the coefficients of an affine f are its
       * values there (construction note, section 3).
       */
      std::vector<Point<2>>
      control_points(const DoFHandler<2> &dof_handler) const override;

      /**
       * Powell-Sabin coefficients are values of the vertex's linear part
       * at its control points, so W(q, r) is the r-th barycentric
       * coordinate of control point Q_{to,q} in the control triangle of
       * @p from: linear fields are extrapolated exactly.
       */
      FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const override;

      /**
       * The 7-point simplex Gauss rule of degree 5 on each of the six PS
       * sub-triangles of the cell (42 points): the functions are quadratic
       * on each sub-triangle only, so a rule on the whole cell would not
       * be exact for their products (degree 4).
       */
      Quadrature<2>
      cell_quadrature(const DoFHandler<2> &dof_handler,
                      const unsigned int   cell) const override;

      double
      stability_factor(const bool lumped) const override;

      /// Lumped mass with APIC (doc/transfers.md): the only measured
      /// Powell-Sabin combination that completes every scene of the suite;
      /// APIC restores the affine fields and angular momentum that lumping
      /// loses with MUSL. With a mass matrix the consistent projection
      /// already reproduces affine fields, and MUSL gives APIC's errors
      /// (Table 4.3 to 1e-8) with one solve less.
      std::string
      default_mass_matrix(const bool grid_moves = false) const override
      {
        (void)grid_moves;
        return "lumped";
      }
      std::string
      default_transfer(const std::string &mass_matrix) const override
      {
        return mass_matrix == "lumped" ? "apic" : "musl";
      }

      /// @name Construction data, for tests and output.
      /// @{
      const PowellSabinRefinement &
      refinement() const
      {
        return ps_refinement;
      }

      /// Control points Q_1, Q_2, Q_3 of vertex @p v (counter-clockwise).
      const std::array<Point<2>, 3> &
      control_triangle(const unsigned int v) const
      {
        return vertex_data[v].control_points;
      }

      const Triplet &
      triplet(const unsigned int v, const unsigned int q) const
      {
        return vertex_data[v].triplets[q];
      }

      VertexKind
      vertex_kind(const unsigned int v) const
      {
        return vertex_data[v].kind;
      }

      /// The PS points of vertex @p v that its control triangle contains.
      const std::vector<Point<2>> &
      ps_points(const unsigned int v) const
      {
        return vertex_ps_points[v];
      }

      /// The 19 Bezier points of a cell, numbered as the ordinates.
      std::array<Point<2>, 19>
      bezier_points(const unsigned int cell) const;

      /// Bezier ordinate of local function @p i at Bezier point @p j
      /// (recomputed per call: evaluate() does not use them).
      double
      ordinate(const unsigned int cell,
               const unsigned int i,
               const unsigned int j) const;
      /// @}

    private:
      FESystem<2>           fe;
      PowellSabinRefinement ps_refinement;

      struct VertexData
      {
        VertexKind              kind = VertexKind::interior;
        std::array<Point<2>, 3> control_points;
        std::array<Triplet, 3>  triplets;
      };
      std::vector<VertexData>            vertex_data;
      std::vector<std::vector<Point<2>>> vertex_ps_points;

      /**
       * Everything evaluate() reads for one cell, contiguous.
       * An affine function is stored as (constant, d/dx, d/dy) of
       * the coordinates relative to origin.
       */
      struct CellData
      {
        /// All affine maps below take x - origin.
        Point<2> origin;
        /// Barycentric coordinates of the macro triangle.
        double macro[3][3];
        /// 1 / barycentric coordinates of the incenter.
        double inverse_split[3];
        /// Line R_k Z, positive on the side of V_k.
        double split_line[3][3];
        /**
         * The nine functions on each sub-triangle as quadratics in its
         * first two barycentric coordinates (l0, l1) = map (x - origin),
         * coefficient-major: c[m][i] for the monomials 1, l0, l1, l0^2,
         * l0 l1, l1^2. On the sub-triangle 0 <= l0, l1 <= 1, so no term
         * is much larger than the function, however thin the triangle
         * (tests/basis/powell_sabin_05); it is a third less arithmetic
         * than the Bernstein form (the Bezier ordinates: cell_ordinates).
         */
        struct SubTriangle
        {
          double map[2][3];
          double c[6][9];
        } sub[6];
      };
      /// Per held cell (Mesh::HeldCells: on several ranks, the rank's
      /// cells and their vertex neighbours only).
      std::vector<CellData> cell_data;
      Mesh::HeldCells       held;

      /// The data of active cell @p cell; a cell this rank does not hold
      /// is an internal error, reported rather than read out of bounds.
      const CellData &
      data(const unsigned int cell) const
      {
        const unsigned int s = held.slot(cell);
        if (s >= cell_data.size())
          not_held(cell);
        return cell_data[s];
      }
      [[noreturn]] void
      not_held(const unsigned int cell) const;
      /// Vertex indices per cell, for the ordinates' triplets.
      std::vector<std::array<unsigned int, 3>> cell_vertices;

      /// The 19 x 9 Bezier ordinates of a cell, point-major.
      using Ordinates = std::array<std::array<double, 9>, 19>;
      Ordinates
      cell_ordinates(const unsigned int cell) const;

      void
      build_control_triangles(const Triangulation<2> &tria);
      void
      build_cell_data(const Triangulation<2> &tria);
    };
  } // namespace Basis
} // namespace psmpm

#endif
