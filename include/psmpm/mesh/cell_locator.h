// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_cell_locator_h
#define psmpm_mesh_cell_locator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/cartesian_grid.h>
#include <psmpm/mesh/triangle_geometry.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    /**
     * Finds the simplex (line or triangle) that contains a point, with the
     * closed-form barycentric test (deal.II 9.4.1 tests "inside" against
     * the unit square on triangles, see doc/design.md). After a small move
     * a particle is found by walking from its old cell across the face
     * opposite the most negative barycentric coordinate. From scratch, a
     * bucket grid over the cells' bounding boxes (2D) or a binary search
     * over the cells sorted by their left end (1D) finds any point and
     * catches walks that leave a non-convex domain.
     *
     * 2D meshes of quadrilaterals must be Cartesian (Mesh/Type =
     * cartesian: axis-parallel rectangles on a tensor-product grid of
     * lines x_0 < ... < x_nx, y_0 < ... < y_ny, what the tensor-product
     * B-splines need): a point is then found by two binary searches over
     * the grid lines, with no walk and no buckets.
     */
    template <int dim>
    class CellLocator
    {
    public:
      static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

      void
      reinit(const Triangulation<dim> &tria);

      unsigned int
      n_cells() const
      {
        return quads ? boxes.size() : maps.size();
      }

      /// Whether the mesh is of (Cartesian) quadrilaterals.
      bool
      cartesian() const
      {
        return quads;
      }

      /// Barycentric coordinates of @p p with respect to @p cell.
      std::array<double, dim + 1>
      barycentric(const unsigned int cell, const Point<dim> &p) const
      {
        return maps[cell](p);
      }

      /// Whether @p p lies in the closed cell (with relative tolerance).
      bool
      contains(const unsigned int cell, const Point<dim> &p) const
      {
        if (quads)
          {
            const auto &b = boxes[cell];
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double margin = tolerance * (b[1][d] - b[0][d]);
                if (!(p[d] >= b[0][d] - margin && p[d] <= b[1][d] + margin))
                  return false;
              }
            return true;
          }
        const auto l = maps[cell](p);
        for (unsigned int k = 0; k <= dim; ++k)
          if (!(l[k] >= -tolerance))
            return false;
        return true;
      }

      /// Cell containing @p p, starting the walk at @p hint; invalid if
      /// the point lies outside the mesh. Inline for the common case of a
      /// particle still in its cell (a call per particle and step
      /// otherwise); the walk itself is walk().
      unsigned int
      locate(const Point<dim> &p, const unsigned int hint) const
      {
        return !quads && contains(hint, p) ? hint : walk(p, hint);
      }

      /// Cell containing @p p by the bucket (2D) or binary (1D) search;
      /// invalid if outside.
      unsigned int
      locate(const Point<dim> &p) const;

      /// Smallest height of any triangle, length of any line, or side of
      /// any rectangle (for the time step bound).
      double
      minimum_height() const
      {
        return min_height;
      }

    private:
      /// locate(p, hint) beyond the hint cell: the walk through
      /// neighbours, or the search.
      unsigned int
      walk(const Point<dim> &p, const unsigned int hint) const;

      static constexpr double tolerance = 1e-12;

      std::vector<SimplexMap<dim>> maps;

      /// Cartesian quadrilaterals: the lower and upper corner of each
      /// cell, the grid (lines and cell positions, the same as the
      /// tensor-product B-splines'), and the cell of grid position (i, j)
      /// at cell_at[j * nx + i].
      bool                                   quads = false;
      std::vector<std::array<Point<dim>, 2>> boxes;
      CartesianGrid                          grid;
      std::vector<unsigned int>              cell_at;
      /// neighbors[c][k]: the cell across the face opposite vertex k.
      std::vector<std::array<unsigned int, dim + 1>> neighbors;
      double                                         min_height = 0;

      /// Bounding box of the mesh, slightly enlarged.
      BoundingBox<dim> box;

      /// 2D: the bucket grid, cells of bucket b in
      /// bucket_cells[bucket_start[b], bucket_start[b+1]).
      /// 1D: bucket_cells holds the cells sorted by their left ends,
      /// which are in lower_ends.
      std::array<unsigned int, dim> n_buckets{};
      std::vector<unsigned int>     bucket_start;
      std::vector<unsigned int>     bucket_cells;
      std::vector<double>           lower_ends;

      std::vector<BoundingBox<dim>>
      set_up_cells(const Triangulation<dim> &tria);
      void
      set_up_cartesian(const Triangulation<dim> &tria);
      unsigned int
      search_cartesian(const Point<dim> &p) const;
      void
      set_up_search(const std::vector<BoundingBox<dim>> &boxes);
      std::array<unsigned int, dim>
      bucket_of(const Point<dim> &p) const;
      unsigned int
      search(const Point<dim> &p) const;
      /// 2D: the cell of @p bucket that @p p lies least outside of, if
      /// only by the round-off of its barycentric map; else invalid.
      unsigned int
      nearest_within_round_off(const Point<dim>  &p,
                               const unsigned int bucket) const;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
