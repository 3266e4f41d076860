// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_cartesian_grid_h
#define psmpm_mesh_cartesian_grid_h

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * The tensor-product grid of a Cartesian mesh of rectangles (Mesh/Type
     * = cartesian): the grid lines x_0 < ... < x_nx and y_0 < ... < y_ny,
     * and the grid position (i, j) of every cell, the rectangle [x_i,
     * x_i+1] x [y_j, y_j+1]. The cell locator searches the lines and the
     * tensor-product B-splines take them as knots; one construction keeps
     * the two in agreement on every mesh.
     *
     * The lines are the distinct vertex coordinates, merged within
     * 1e-12 of the grid's span in that direction: vertices shared by
     * cells are the same points, so the merge only guards against input
     * that nearly repeats a coordinate; the first (smallest) of merged
     * coordinates is the line.
     */
    class CartesianGrid
    {
    public:
      /// An empty grid (no cells) until reinit().
      CartesianGrid() = default;

      /// The grid of @p tria, a mesh of quadrilaterals. Throws ExcMessage,
      /// starting with @p user and naming Mesh/Type = cartesian, if the
      /// cells are not the rectangles of one tensor-product grid (each
      /// grid rectangle one cell, every vertex at a corner of its cell's
      /// rectangle, in deal.II's lexicographic vertex order).
      void
      reinit(const Triangulation<2> &tria, const std::string &user);

      /// Forget the grid (n_cells() = 0).
      void
      clear();

      /// Grid lines in direction @p d (0: x, 1: y), increasing.
      const std::vector<double> &
      lines(const unsigned int d) const
      {
        AssertIndexRange(d, 2);
        return grid_lines[d];
      }

      /// Grid position (column, row) of the cell with active index @p c.
      const std::array<unsigned int, 2> &
      position(const unsigned int c) const
      {
        AssertIndexRange(c, positions.size());
        return positions[c];
      }

      /// Number of cells (active cells of the mesh of the last reinit()).
      unsigned int
      n_cells() const
      {
        return positions.size();
      }

      /// Relative tolerance (of the span) within which coordinates are the
      /// same grid line.
      static constexpr double tolerance = 1e-12;

    private:
      std::array<std::vector<double>, 2>       grid_lines;
      std::vector<std::array<unsigned int, 2>> positions;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
