// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_powell_sabin_refinement_h
#define psmpm_basis_powell_sabin_refinement_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    using namespace dealii;

    /**
     * The Powell-Sabin refinement of a conforming triangulation
     * (powell-sabin-splines.md, section 1): the incenter Z of every
     * triangle, the edge point R of every edge (on the segment between the
     * incenters of the two triangles sharing the edge, the midpoint on the
     * boundary) and the six sub-triangles of every triangle.
     *
     * Edge k of a cell is the edge from cell->vertex(k) to
     * cell->vertex((k+1)%3); R_k = w[k][0] V_k + w[k][1] V_{k+1}.
     * Each edge point is computed once per face, so that the two cells
     * sharing an edge see bit-identical points (C1 continuity to round-off).
     *
     * Kept separate from the spline space because the L2 projection
     * integrates P1 on the same sub-triangles.
     */
    class PowellSabinRefinement
    {
    public:
      struct CellRefinement
      {
        /// The macro triangle's vertices (counter-clockwise).
        std::array<Point<2>, 3> vertices;
        /// Incenter and its barycentric coordinates.
        Point<2>              split_point;
        std::array<double, 3> split_barycentric;
        /// Edge points and their weights on their edges.
        std::array<Point<2>, 3>              edge_points;
        std::array<std::array<double, 2>, 3> edge_weights;

        /// Sub-triangle 2k = (V_k, R_k, Z), 2k+1 = (R_k, V_{k+1}, Z).
        std::array<Point<2>, 3>
        sub_triangle(const unsigned int s) const;
      };

      /**
       * Compute the refinement of every active cell of @p tria. Throws
       * ExcMessage naming the vertices if a cell is inverted or degenerate
       * or an edge point falls outside its edge.
       */
      void
      reinit(const Triangulation<2> &tria);

      /// Refinement of the cell with the given active_cell_index().
      const CellRefinement &
      cell(const unsigned int active_cell_index) const
      {
        return cells[active_cell_index];
      }

      unsigned int
      n_cells() const
      {
        return cells.size();
      }

    private:
      std::vector<CellRefinement> cells;
    };
  } // namespace Basis
} // namespace psmpm

#endif
