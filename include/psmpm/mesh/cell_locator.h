// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_cell_locator_h
#define psmpm_mesh_cell_locator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/triangle_geometry.h>

#include <array>
#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    /**
     * Finds the triangle that contains a point, with the closed-form
     * barycentric test (deal.II 9.4.1 tests "inside" against the unit
     * square on triangles, see doc/design.md). After a small move a
     * particle is found by walking from its old cell across the edge
     * opposite the most negative barycentric coordinate; a bucket grid
     * over the cells' bounding boxes finds any point from scratch and
     * catches walks that leave a non-convex domain.
     */
    class CellLocator
    {
    public:
      static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

      void
      reinit(const Triangulation<2> &tria);

      unsigned int
      n_cells() const
      {
        return maps.size();
      }

      /// Barycentric coordinates of @p p with respect to @p cell.
      std::array<double, 3>
      barycentric(const unsigned int cell, const Point<2> &p) const
      {
        return maps[cell](p);
      }

      /// Whether @p p lies in the closed cell (with relative tolerance).
      bool
      contains(const unsigned int cell, const Point<2> &p) const
      {
        const auto l = maps[cell](p);
        return l[0] >= -tolerance && l[1] >= -tolerance && l[2] >= -tolerance;
      }

      /// Cell containing @p p, starting the walk at @p hint; invalid if
      /// the point lies outside the mesh.
      unsigned int
      locate(const Point<2> &p, const unsigned int hint) const;

      /// Cell containing @p p by the bucket search; invalid if outside.
      unsigned int
      locate(const Point<2> &p) const;

      /// Smallest height of any triangle (for the time step bound).
      double
      minimum_height() const
      {
        return min_height;
      }

    private:
      static constexpr double tolerance = 1e-12;

      std::vector<BarycentricMap>              maps;
      std::vector<std::array<unsigned int, 3>> neighbors; // opposite vertex k
      double                                   min_height = 0;

      BoundingBox<2>              box;
      std::array<unsigned int, 2> n_buckets{{1, 1}};
      std::vector<unsigned int>   bucket_start;
      std::vector<unsigned int>   bucket_cells;
      std::array<unsigned int, 2>
      bucket_of(const Point<2> &p) const;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
