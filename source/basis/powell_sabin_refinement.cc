// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/base/cross.h>
#include <psmpm/basis/powell_sabin_refinement.h>
#include <psmpm/mesh/triangle_geometry.h>

#include <cmath>
#include <sstream>

namespace psmpm
{
  namespace Basis
  {
    namespace
    {
      std::string
      describe_vertex(const unsigned int index, const Point<2> &p)
      {
        std::ostringstream s;
        s.precision(17);
        s << "vertex " << index << " at (" << p[0] << ", " << p[1] << ")";
        return s.str();
      }



      /// Refuse a cell whose incenter is not usable: a cell of @p area
      /// at most 1e-14 of its @p perimeter squared (relative, so that a
      /// sliver fails whatever the mesh size) has none in double
      /// precision.
      void
      check_not_sliver(const Triangulation<2>::active_cell_iterator &cell,
                       const std::array<Point<2>, 3>                &vertices,
                       const double                                  area,
                       const double                                  perimeter)
      {
        if (!(area > 1e-14 * perimeter * perimeter))
          {
            std::string msg =
              "Powell-Sabin refinement: cell " +
              std::to_string(cell->active_cell_index()) +
              (area <= 0 ? " is inverted or degenerate" : " is too thin") +
              " (area " +
              [area]() {
                std::ostringstream s;
                s.precision(3);
                s << area;
                return s.str();
              }() +
              "); its vertices: ";
            for (unsigned int k = 0; k < 3; ++k)
              msg += (k > 0 ? ", " : "") +
                     describe_vertex(cell->vertex_index(k), vertices[k]);
            AssertThrow(false, ExcMessage(msg + "."));
          }
      }



      /// The vertices of @p cell and its split point, the incenter, into
      /// @p c.
      void
      set_split_point(const Triangulation<2>::active_cell_iterator &cell,
                      PowellSabinRefinement::CellRefinement        &c)
      {
        AssertThrow(cell->reference_cell() == ReferenceCells::Triangle,
                    ExcMessage("Powell-Sabin splines need a mesh of "
                               "triangles only."));
        for (unsigned int k = 0; k < 3; ++k)
          c.vertices[k] = cell->vertex(k);

        // a = |V2 V3| etc.: the side opposite each vertex.
        std::array<double, 3> side;
        for (unsigned int k = 0; k < 3; ++k)
          side[k] = c.vertices[(k + 1) % 3].distance(c.vertices[(k + 2) % 3]);
        const double perimeter = side[0] + side[1] + side[2];
        const double area      = Mesh::signed_area(c.vertices);
        check_not_sliver(cell, c.vertices, area, perimeter);

        c.split_point = Point<2>();
        for (unsigned int k = 0; k < 3; ++k)
          {
            c.split_barycentric[k] = side[k] / perimeter;
            c.split_point += c.split_barycentric[k] * c.vertices[k];
          }
      }



      /// The face of @p cell along its edge k (from vertex k to k + 1),
      /// which must have one neighbour of the same level or none.
      unsigned int
      face_of_edge(const Triangulation<2>::active_cell_iterator &cell,
                   const unsigned int                            k)
      {
        const unsigned int a = cell->vertex_index(k);
        const unsigned int b = cell->vertex_index((k + 1) % 3);
        unsigned int       f = numbers::invalid_unsigned_int;
        for (const unsigned int g : cell->face_indices())
          {
            const unsigned int f0 = cell->face(g)->vertex_index(0);
            const unsigned int f1 = cell->face(g)->vertex_index(1);
            if ((f0 == a && f1 == b) || (f0 == b && f1 == a))
              f = g;
          }
        Assert(f != numbers::invalid_unsigned_int, ExcInternalError());
        // Edge points need one neighbour per edge: no hanging nodes.
        AssertThrow(cell->at_boundary(f) ||
                      (!cell->neighbor(f)->has_children() &&
                       cell->neighbor(f)->level() == cell->level()),
                    ExcMessage("Powell-Sabin splines need a conforming "
                               "mesh without hanging nodes; cell " +
                               std::to_string(cell->active_cell_index()) +
                               " has a refined or coarser neighbour."));
        return f;
      }



      /// One edge point per face, stored as the weight of face->vertex(0).
      struct FacePoint
      {
        bool     computed = false;
        Point<2> point;
        double   weight_of_vertex_0 = 0;
      };



      /**
       * The edge point of face @p f of @p cell: its midpoint on the
       * boundary, else where the segment between the split points @p zt
       * of @p cell and @p zs of its neighbour crosses it.
       */
      FacePoint
      edge_point(const Triangulation<2>::active_cell_iterator &cell,
                 const unsigned int                            f,
                 const Point<2>                               &zt,
                 const Point<2>                               &zs)
      {
        const auto     face = cell->face(f);
        const Point<2> A    = face->vertex(0);
        const Point<2> B    = face->vertex(1);
        double         w    = 0.5; // weight of B
        if (!cell->at_boundary(f))
          {
            // A + w (B - A) = zt + s (zs - zt)
            const Tensor<1, 2> e = B - A, d = zs - zt, r = zt - A;
            const double       det = -cross(e, d);
            const bool         ok = std::abs(det) > 1e-14 * e.norm() * d.norm();
            if (ok)
              w = -cross(r, d) / det;
            // Incenters guarantee 0 < w < 1; anything else means a
            // degenerate pair of triangles.
            if (!ok || !(w > 1e-12 && w < 1 - 1e-12))
              AssertThrow(
                false,
                ExcMessage(
                  "Powell-Sabin refinement: the segment between "
                  "the incenters of cells " +
                  std::to_string(cell->active_cell_index()) + " and " +
                  std::to_string(cell->neighbor(f)->active_cell_index()) +
                  " does not cross their common edge from " +
                  describe_vertex(face->vertex_index(0), A) + " to " +
                  describe_vertex(face->vertex_index(1), B) + "."));
          }
        FacePoint fp;
        fp.computed           = true;
        fp.weight_of_vertex_0 = 1 - w;
        fp.point              = A + w * (B - A);
        return fp;
      }
    } // namespace

    std::array<Point<2>, 3>
    PowellSabinRefinement::CellRefinement::sub_triangle(
      const unsigned int s) const
    {
      const unsigned int k = s / 2;
      if (s % 2 == 0)
        return {{vertices[k], edge_points[k], split_point}};
      return {{edge_points[k], vertices[(k + 1) % 3], split_point}};
    }

    void
    PowellSabinRefinement::reinit(const Triangulation<2> &tria)
    {
      cells.clear();
      cells.resize(tria.n_active_cells());

      // Incenters first: the edge points need both neighbours' incenters.
      for (const auto &cell : tria.active_cell_iterators())
        set_split_point(cell, cells[cell->active_cell_index()]);

      std::vector<FacePoint> face_points(tria.n_raw_faces());
      for (const auto &cell : tria.active_cell_iterators())
        {
          CellRefinement &c = cells[cell->active_cell_index()];
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int f    = face_of_edge(cell, k);
              const auto         face = cell->face(f);
              FacePoint         &fp   = face_points[face->index()];
              if (!fp.computed)
                fp = edge_point(
                  cell,
                  f,
                  c.split_point,
                  cell->at_boundary(f) ?
                    c.split_point :
                    cells[cell->neighbor(f)->active_cell_index()].split_point);
              c.edge_points[k] = fp.point;
              if (face->vertex_index(0) == cell->vertex_index(k))
                c.edge_weights[k] = {
                  {fp.weight_of_vertex_0, 1 - fp.weight_of_vertex_0}};
              else
                c.edge_weights[k] = {
                  {1 - fp.weight_of_vertex_0, fp.weight_of_vertex_0}};
            }
        }
    }
  } // namespace Basis
} // namespace psmpm
