// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/fe/fe_simplex_p.h>

#include <psmpm/base/cross.h>
#include <psmpm/base/pair.h>
#include <psmpm/base/registry.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/triangle_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

namespace psmpm
{
  namespace Basis
  {
    namespace
    {
      /*
       * Numbering of the 19 Bezier points of a macro triangle:
       *   0-2    V_k
       *   3-5    R_k (edge k from V_k to V_{k+1})
       *   6      Z
       *   7+2k   midpoint V_k R_k,  8+2k midpoint V_{k+1} R_k
       *   13+k   midpoint V_k Z
       *   16+k   midpoint R_k Z
       * Sub-triangle 2k = (V_k, R_k, Z), 2k+1 = (R_k, V_{k+1}, Z); each row
       * lists its Bezier points as (P1, P2, P3, mid P1P2, mid P2P3,
       * mid P3P1).
       */
      constexpr unsigned int sub_triangle_points[6][6] = {
        {0, 3, 6, 7, 16, 13},
        {3, 1, 6, 8, 14, 16},
        {1, 4, 6, 9, 17, 14},
        {4, 2, 6, 10, 15, 17},
        {2, 5, 6, 11, 18, 15},
        {5, 0, 6, 12, 13, 18}};

      std::string
      describe_vertex(const unsigned int index, const Point<2> &p)
      {
        std::ostringstream s;
        s.precision(17);
        s << "vertex " << index << " at (" << p[0] << ", " << p[1] << ")";
        return s.str();
      }


      /// The half-plane n . x <= c (n a unit outward normal).
      struct Line
      {
        Tensor<1, 2> normal;
        double       c;
      };

      /**
       * The triangle bounded by three half-planes, if it is bounded: that
       * is the case when the outward normals positively span the plane,
       * i.e. when the three cross products of consecutive normals have one
       * sign.
       */
      bool
      triangle_from_lines(const Line              &l1,
                          const Line              &l2,
                          const Line              &l3,
                          std::array<Point<2>, 3> &triangle,
                          double                  &area)
      {
        const double s12 = cross(l1.normal, l2.normal);
        const double s23 = cross(l2.normal, l3.normal);
        const double s31 = cross(l3.normal, l1.normal);
        const double tol = 1e-10;
        if (!((s12 > tol && s23 > tol && s31 > tol) ||
              (s12 < -tol && s23 < -tol && s31 < -tol)))
          return false;
        const auto intersect = [](const Line &a, const Line &b) {
          const double det = cross(a.normal, b.normal);
          return Point<2>((a.c * b.normal[1] - b.c * a.normal[1]) / det,
                          (a.normal[0] * b.c - b.normal[0] * a.c) / det);
        };
        triangle = {{intersect(l1, l2), intersect(l2, l3), intersect(l3, l1)}};
        double a = Mesh::signed_area(triangle);
        if (a < 0)
          {
            std::swap(triangle[1], triangle[2]);
            a = -a;
          }
        area = a;
        return true;
      }

      /// Convex hull, counter-clockwise, without collinear points.
      std::vector<Point<2>>
      convex_hull(std::vector<Point<2>> points, const double scale)
      {
        std::sort(points.begin(),
                  points.end(),
                  [](const Point<2> &a, const Point<2> &b) {
                    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
                  });
        const double          tol = 1e-12 * scale * scale;
        std::vector<Point<2>> hull(2 * points.size());
        std::size_t           k = 0;
        for (std::size_t i = 0; i < points.size(); ++i)
          {
            while (k >= 2 && cross(hull[k - 1] - hull[k - 2],
                                   points[i] - hull[k - 2]) <= tol)
              --k;
            hull[k++] = points[i];
          }
        for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i)
          {
            while (k >= t && cross(hull[k - 1] - hull[k - 2],
                                   points[i - 1] - hull[k - 2]) <= tol)
              --k;
            hull[k++] = points[i - 1];
          }
        hull.resize(k > 0 ? k - 1 : 0);
        return hull;
      }

      Tensor<1, 2>
      outward_normal(const Point<2> &from, const Point<2> &to)
      {
        // Interior on the left of a counter-clockwise edge.
        const Tensor<1, 2> e = to - from;
        Tensor<1, 2>       n;
        n[0] = e[1];
        n[1] = -e[0];
        return n / n.norm();
      }

      /**
       * Smallest triangle that contains @p points among those whose sides
       * lie on (a) the given fixed lines and (b) supporting lines through
       * edges of the convex hull, or lines orthogonal to the bisector of two
       * such lines, pushed out to the farthest point (construction note,
       * section 2). Returns false if there is no such triangle.
       */
      bool
      smallest_control_triangle(const std::vector<Point<2>> &points,
                                const std::vector<Line>     &fixed,
                                const double                 scale,
                                std::array<Point<2>, 3>     &best)
      {
        const auto support = [&points](const Tensor<1, 2> &n) {
          double c = -std::numeric_limits<double>::max();
          for (const auto &p : points)
            c = std::max(c, n * p);
          return Line{n, c};
        };
        const auto bisector =
          [&support](const Line &a, const Line &b, bool &ok) {
            const Tensor<1, 2> d = -(a.normal + b.normal);
            ok                   = d.norm() > 1e-10;
            return support(ok ? d / d.norm() : d);
          };

        const auto        hull = convex_hull(points, scale);
        std::vector<Line> hull_lines;
        for (std::size_t i = 0; i < hull.size(); ++i)
          hull_lines.push_back(
            support(outward_normal(hull[i], hull[(i + 1) % hull.size()])));

        double                  best_area = std::numeric_limits<double>::max();
        std::array<Point<2>, 3> t;
        double                  area;
        const auto consider = [&](const Line &a, const Line &b, const Line &c) {
          // Strict improvement only, so the first of equal candidates wins
          // and the choice is deterministic.
          if (triangle_from_lines(a, b, c, t, area) &&
              area < best_area * (1 - 1e-12))
            {
              best_area = area;
              best      = t;
            }
        };
        const auto consider_with_bisector = [&](const Line &a, const Line &b) {
          bool       ok;
          const Line c = bisector(a, b, ok);
          if (ok)
            consider(a, b, c);
        };

        const std::size_t n = hull_lines.size();
        if (fixed.size() == 2)
          {
            for (std::size_t i = 0; i < n; ++i)
              consider(fixed[0], fixed[1], hull_lines[i]);
            consider_with_bisector(fixed[0], fixed[1]);
          }
        else if (fixed.size() == 1)
          for (std::size_t i = 0; i < n; ++i)
            {
              consider_with_bisector(fixed[0], hull_lines[i]);
              for (std::size_t j = i + 1; j < n; ++j)
                consider(fixed[0], hull_lines[i], hull_lines[j]);
            }
        else
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
              {
                consider_with_bisector(hull_lines[i], hull_lines[j]);
                for (std::size_t k = j + 1; k < n; ++k)
                  consider(hull_lines[i], hull_lines[j], hull_lines[k]);
              }
        return best_area < std::numeric_limits<double>::max();
      }



      /**
       * If face @p f of @p cell is on the boundary, the neighbours along
       * it, oriented with the interior on the left: the vertex it leaves
       * to (for the vertex at its start) and the vertex it arrives from
       * (for the vertex at its end).
       */
      void
      add_boundary_edge(const Triangulation<2>::active_cell_iterator &cell,
                        const unsigned int                            f,
                        std::vector<std::vector<Point<2>>> &arriving_from,
                        std::vector<std::vector<Point<2>>> &leaving_to)
      {
        if (!cell->at_boundary(f))
          return;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int a = cell->vertex_index(k),
                               b = cell->vertex_index((k + 1) % 3);
            const auto face      = cell->face(f);
            if ((face->vertex_index(0) == a && face->vertex_index(1) == b) ||
                (face->vertex_index(0) == b && face->vertex_index(1) == a))
              {
                leaving_to[a].push_back(cell->vertex((k + 1) % 3));
                arriving_from[b].push_back(cell->vertex(k));
              }
          }
      }



      /**
       * The kind of vertex @p V from its boundary neighbours @p
       * arriving_from and @p leaving_to, and the lines its control
       * triangle must have as sides (@p fixed): the boundary tangent at a
       * straight boundary vertex, both edges at a convex corner.
       */
      PowellSabin::VertexKind
      classify_vertex(const Point<2>              &V,
                      const std::vector<Point<2>> &arriving_from,
                      const std::vector<Point<2>> &leaving_to,
                      std::vector<Line>           &fixed)
      {
        using VertexKind = PowellSabin::VertexKind;
        if (arriving_from.empty() && leaving_to.empty())
          return VertexKind::interior;
        if (arriving_from.size() != 1 || leaving_to.size() != 1)
          return VertexKind::unaligned_boundary;
        const Point<2>    &W1 = arriving_from[0];
        const Point<2>    &W2 = leaving_to[0];
        const Tensor<1, 2> n1 = outward_normal(W1, V);
        const Tensor<1, 2> n2 = outward_normal(V, W2);
        const double       turn =
          cross(V - W1, W2 - V) / ((V - W1).norm() * (W2 - V).norm());
        if (std::abs(turn) <= 1e-10)
          {
            const Tensor<1, 2> n = (n1 + n2) / (n1 + n2).norm();
            fixed.push_back(Line{n, n * V});
            return VertexKind::straight_boundary;
          }
        if (turn > 0)
          {
            fixed.push_back(Line{n1, n1 * V});
            fixed.push_back(Line{n2, n2 * V});
            return VertexKind::corner;
          }
        return VertexKind::unaligned_boundary;
      }



      /**
       * The triplets of vertex @p v at @p V from its control triangle
       * @p control_points: value and gradient at V of the linear functions
       * that are 1 at one control point and 0 at the other two. Checks
       * that the triangle is not degenerate and holds every PS point of
       * @p points (@p scale: their largest distance from V).
       */
      void
      set_triplets(const std::array<Point<2>, 3>       &control_points,
                   const std::vector<Point<2>>         &points,
                   const Point<2>                      &V,
                   const unsigned int                   v,
                   const double                         scale,
                   std::array<PowellSabin::Triplet, 3> &triplets)
      {
        const double area = Mesh::signed_area(control_points);
        AssertThrow(area > 1e-12 * scale * scale,
                    ExcMessage("Powell-Sabin: degenerate control triangle "
                               "at " +
                               describe_vertex(v, V) + "."));
        // Relative to V: in absolute coordinates the constant of the
        // map is of size |V|/h and cancellation would cost digits.
        std::array<Point<2>, 3> local;
        for (unsigned int q = 0; q < 3; ++q)
          local[q] = Point<2>(control_points[q] - V);
        const auto bary = Mesh::barycentric_map(local);
        for (unsigned int q = 0; q < 3; ++q)
          triplets[q] =
            PowellSabin::Triplet{bary.constant[q], bary.gradient[q]};

        // Non-negativity of the basis is equivalent to every PS point
        // lying in the control triangle: check it rather than trust the
        // geometry of a sliver.
        for (const auto &p : points)
          {
            const auto l = bary(Point<2>(p - V));
            for (unsigned int q = 0; q < 3; ++q)
              AssertThrow(l[q] > -1e-10,
                          ExcMessage("Powell-Sabin: the control triangle of " +
                                     describe_vertex(v, V) +
                                     " does not contain all its PS points; "
                                     "the basis would not be non-negative."));
          }
      }



      /// The points of triangle @p t relative to @p o.
      std::array<Point<2>, 3>
      to_local(const std::array<Point<2>, 3> &t, const Point<2> &o)
      {
        return std::array<Point<2>, 3>{
          {Point<2>(t[0] - o), Point<2>(t[1] - o), Point<2>(t[2] - o)}};
      }



      /**
       * The quadratic Bernstein basis in monomials of (l0, l1), with l2 =
       * 1 - l0 - l1: row j holds the coefficients of b_j on 1, l0, l1,
       * l0^2, l0 l1, l1^2. l_k = A_k + G_k . (l0, l1), and l_a l_b has the
       * coefficients A_a A_b, A_a G_b + A_b G_a, G_a G_b (symmetrised for
       * l0 l1).
       */
      std::array<std::array<double, 6>, 6>
      bernstein_to_monomials()
      {
        constexpr double A[3]    = {0, 0, 1};
        constexpr double G[3][2] = {{1, 0}, {0, 1}, {-1, -1}};
        // Bernstein b_j = w_j l_{pa_j} l_{pb_j}, in the Bezier point
        // order of sub_triangle_points (P1, P2, P3, mid P1P2, ...).
        constexpr unsigned int               pa[6] = {0, 1, 2, 0, 1, 2};
        constexpr unsigned int               pb[6] = {0, 1, 2, 1, 2, 0};
        constexpr double                     w[6]  = {1, 1, 1, 2, 2, 2};
        std::array<std::array<double, 6>, 6> m;
        for (unsigned int j = 0; j < 6; ++j)
          {
            const unsigned int a = pa[j], b = pb[j];
            m[j][0] = w[j] * A[a] * A[b];
            m[j][1] = w[j] * (A[a] * G[b][0] + A[b] * G[a][0]);
            m[j][2] = w[j] * (A[a] * G[b][1] + A[b] * G[a][1]);
            m[j][3] = w[j] * G[a][0] * G[b][0];
            m[j][4] = w[j] * (G[a][0] * G[b][1] + G[a][1] * G[b][0]);
            m[j][5] = w[j] * G[a][1] * G[b][1];
          }
        return m;
      }



      /// Per constrained vertex: its three DoFs and the rows
      /// (coefficients on c_0..c_2, right-hand side).
      struct VertexRows
      {
        std::array<types::global_dof_index, 3> dofs;
        std::vector<std::array<double, 4>>     rows;
      };



      /**
       * Gauss-Jordan elimination with full pivoting on the m x 3 system
       * @p M (rows scaled to largest coefficient 1 first, so that one rank
       * tolerance fits values and derivatives alike). Returns its rank;
       * @p column holds the order of the unknowns after pivoting.
       */
      unsigned int
      eliminate(std::vector<std::array<double, 4>> &M,
                std::array<unsigned int, 3>        &column)
      {
        for (auto &row : M)
          {
            const double s =
              std::max({std::abs(row[0]), std::abs(row[1]), std::abs(row[2])});
            for (auto &x : row)
              x /= s;
          }
        column            = {{0, 1, 2}};
        unsigned int rank = 0;
        for (; rank < std::min<std::size_t>(3, M.size()); ++rank)
          {
            unsigned int pi = rank, pj = rank;
            for (unsigned int i = rank; i < M.size(); ++i)
              for (unsigned int j = rank; j < 3; ++j)
                if (std::abs(M[i][column[j]]) > std::abs(M[pi][column[pj]]))
                  {
                    pi = i;
                    pj = j;
                  }
            if (std::abs(M[pi][column[pj]]) < 1e-10)
              break;
            std::swap(M[rank], M[pi]);
            std::swap(column[rank], column[pj]);
            const double p = M[rank][column[rank]];
            for (auto &x : M[rank])
              x /= p;
            for (unsigned int i = 0; i < M.size(); ++i)
              if (i != rank)
                {
                  const double f = M[i][column[rank]];
                  for (unsigned int j = 0; j < 4; ++j)
                    M[i][j] -= f * M[rank][j];
                }
          }
        return rank;
      }



      /// The constraints of the vertex @p r from its rows: c_{column[i]} =
      /// rhs_i - sum_{free j} M[i][j] c_j for i < rank.
      void
      add_vertex_constraints(VertexRows                &r,
                             AffineConstraints<double> &constraints)
      {
        std::array<unsigned int, 3> column;
        const unsigned int          rank = eliminate(r.rows, column);
        const auto                 &M    = r.rows;
        for (unsigned int i = 0; i < rank; ++i)
          {
            const auto dof = r.dofs[column[i]];
            if (!constraints.can_store_line(dof) ||
                constraints.is_constrained(dof))
              continue;
            constraints.add_line(dof);
            for (unsigned int j = rank; j < 3; ++j)
              if (std::abs(M[i][column[j]]) > 1e-12)
                constraints.add_entry(dof, r.dofs[column[j]], -M[i][column[j]]);
            if (std::abs(M[i][3]) > 1e-14)
              constraints.set_inhomogeneity(dof, M[i][3]);
          }
      }
    } // namespace

    PowellSabin::PowellSabin()
      : fe(FE_SimplexP<2>(1), 3)
    {
    }

    std::string
    PowellSabin::name() const
    {
      return "powell-sabin";
    }

    const FiniteElement<2> &
    PowellSabin::dof_layout() const
    {
      return fe;
    }

    void
    PowellSabin::reinit(const DoFHandler<2> &dof_handler)
    {
      AssertThrow(dof_handler.get_fe().n_dofs_per_vertex() == 3 &&
                    dof_handler.get_fe().n_dofs_per_cell() == 9,
                  ExcMessage("PowellSabin::reinit: the DoFHandler must use "
                             "the space's dof_layout()."));
      const auto &tria = dof_handler.get_triangulation();
      ps_refinement.reinit(tria);
      build_control_triangles(tria);
      build_cell_data(tria);
    }

    void
    PowellSabin::build_control_triangles(const Triangulation<2> &tria)
    {
      const unsigned int n_vertices = tria.n_vertices();
      vertex_data.assign(n_vertices, VertexData());
      vertex_ps_points.assign(n_vertices, {});

      // Boundary edges oriented with the interior on their left: the one
      // arriving at and the one leaving each boundary vertex.
      std::vector<std::vector<Point<2>>> arriving_from(n_vertices),
        leaving_to(n_vertices);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const auto &c = ps_refinement.cell(cell->active_cell_index());
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int v    = cell->vertex_index(k);
              const Point<2>    &V    = c.vertices[k];
              auto              &list = vertex_ps_points[v];
              if (list.empty())
                list.push_back(V);
              list.push_back(0.5 * (V + c.split_point));
              list.push_back(0.5 * (V + c.edge_points[k]));
              list.push_back(0.5 * (V + c.edge_points[(k + 2) % 3]));
            }
          for (const unsigned int f : cell->face_indices())
            add_boundary_edge(cell, f, arriving_from, leaving_to);
        }

      const std::vector<bool> &used     = tria.get_used_vertices();
      const auto              &vertices = tria.get_vertices();
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          auto &points = vertex_ps_points[v];
          if (!used[v] || points.empty())
            continue;
          const Point<2> &V     = vertices[v];
          double          scale = 0;
          for (const auto &p : points)
            scale = std::max(scale, p.distance(V));

          VertexData       &data = vertex_data[v];
          std::vector<Line> fixed;
          data.kind =
            classify_vertex(V, arriving_from[v], leaving_to[v], fixed);
          const bool found = smallest_control_triangle(points,
                                                       fixed,
                                                       scale,
                                                       data.control_points);
          AssertThrow(found,
                      ExcMessage("Powell-Sabin: no control triangle contains "
                                 "the PS points of " +
                                 describe_vertex(v, V) + "."));
          set_triplets(data.control_points, points, V, v, scale, data.triplets);
        }
    }

    void
    PowellSabin::not_held(const unsigned int cell) const
    {
      AssertThrow(false,
                  ExcMessage("Powell-Sabin: evaluation on cell " +
                             std::to_string(cell) +
                             ", which this rank does not hold (only its own "
                             "cells and their vertex neighbours)."));
      std::abort();
    }

    void
    PowellSabin::build_cell_data(const Triangulation<2> &tria)
    {
      held.reinit(tria);
      cell_data.clear();
      cell_data.resize(held.size());
      cell_vertices.resize(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          cell_vertices[cell->active_cell_index()][k] = cell->vertex_index(k);

      const std::array<std::array<double, 6>, 6> m = bernstein_to_monomials();
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          if (held.slot(index) == Mesh::HeldCells::invalid)
            continue;
          const auto &c = ps_refinement.cell(index);
          CellData   &d = cell_data[held.slot(index)];

          // Affine maps relative to the cell's first vertex keep their
          // constants of order one whatever the cell's position.
          d.origin = c.vertices[0];
          const auto macro =
            Mesh::barycentric_map(to_local(c.vertices, d.origin));
          for (unsigned int k = 0; k < 3; ++k)
            {
              d.macro[k][0]      = macro.constant[k];
              d.macro[k][1]      = macro.gradient[k][0];
              d.macro[k][2]      = macro.gradient[k][1];
              d.inverse_split[k] = 1. / c.split_barycentric[k];
              const Point<2> R(c.edge_points[k] - d.origin);
              const Point<2> Z(c.split_point - d.origin);
              const Point<2> Vk(c.vertices[k] - d.origin);
              // s(x) = cross(Z - R, x - R), positive left of R->Z.
              const Tensor<1, 2> e  = Z - R;
              double             a  = -e[0] * R[1] + e[1] * R[0];
              double             gx = -e[1], gy = e[0];
              if (a + gx * Vk[0] + gy * Vk[1] < 0)
                {
                  a  = -a;
                  gx = -gx;
                  gy = -gy;
                }
              d.split_line[k][0] = a;
              d.split_line[k][1] = gx;
              d.split_line[k][2] = gy;
            }

          // A Bezier form with non-negative ordinates is non-negative; with
          // every PS point in its control triangle they all are.
          const Ordinates ordinates = cell_ordinates(index);
          for (unsigned int j = 0; j < 19; ++j)
            for (unsigned int i = 0; i < 9; ++i)
              AssertThrow(ordinates[j][i] > -1e-10,
                          ExcMessage(
                            "Powell-Sabin: negative Bezier ordinate of a "
                            "basis function of " +
                            describe_vertex(cell->vertex_index(i / 3),
                                            cell->vertex(i / 3)) +
                            " in cell " + std::to_string(index) + "."));

          // Bernstein form -> monomials in (l0, l1) on each sub-triangle.
          for (unsigned int s = 0; s < 6; ++s)
            {
              auto      &q = d.sub[s];
              const auto sub =
                Mesh::barycentric_map(to_local(c.sub_triangle(s), d.origin));
              for (unsigned int k = 0; k < 2; ++k)
                {
                  q.map[k][0] = sub.constant[k];
                  q.map[k][1] = sub.gradient[k][0];
                  q.map[k][2] = sub.gradient[k][1];
                }
              for (unsigned int k = 0; k < 6; ++k)
                for (unsigned int i = 0; i < 9; ++i)
                  {
                    double sum = 0;
                    for (unsigned int j = 0; j < 6; ++j)
                      sum += ordinates[sub_triangle_points[s][j]][i] * m[j][k];
                    q.c[k][i] = sum;
                  }
            }
        }
    }

    PowellSabin::Ordinates
    PowellSabin::cell_ordinates(const unsigned int index) const
    {
      // Construction note, section 4: function 3k+q is the PS Hermite
      // interpolant of value alpha_q and gradient (beta_q, gamma_q) at V_k
      // and zero data at the other vertices.
      AssertIndexRange(index, cell_vertices.size());
      const auto &c = ps_refinement.cell(index);
      Ordinates   o;
      for (auto &row : o)
        row.fill(0);
      const Point<2> &Z = c.split_point;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int km1 = (k + 2) % 3; // edge k-1 ends at V_k
          const Point<2>    &V   = c.vertices[k];
          const auto        &vd  = vertex_data[cell_vertices[index][k]];
          for (unsigned int q = 0; q < 3; ++q)
            {
              const unsigned int i = 3 * k + q;
              const Triplet     &t = vd.triplets[q];
              const auto         T = [&](const Point<2> &P) {
                return t.alpha + 0.5 * (t.gradient * (P - V));
              };
              const double w_next = c.edge_weights[k][0];   // V_k in R_k
              const double w_prev = c.edge_weights[km1][1]; // in R_{k-1}
              o[k][i]             = t.alpha;
              o[7 + 2 * k][i]     = T(c.edge_points[k]);
              o[8 + 2 * km1][i]   = T(c.edge_points[km1]);
              o[13 + k][i]        = T(Z);
              o[3 + k][i]         = w_next * T(c.edge_points[k]);
              o[3 + km1][i]       = w_prev * T(c.edge_points[km1]);
              o[16 + k][i]        = w_next * T(Z);
              o[16 + km1][i]      = w_prev * T(Z);
              o[6][i]             = c.split_barycentric[k] * T(Z);
            }
        }
      return o;
    }

    double
    PowellSabin::ordinate(const unsigned int cell,
                          const unsigned int i,
                          const unsigned int j) const
    {
      return cell_ordinates(cell)[j][i];
    }

    std::array<Point<2>, 19>
    PowellSabin::bezier_points(const unsigned int cell) const
    {
      const auto              &c = ps_refinement.cell(cell);
      std::array<Point<2>, 19> p;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Point<2> &V = c.vertices[k];
          p[k]              = V;
          p[3 + k]          = c.edge_points[k];
          p[7 + 2 * k]      = 0.5 * (V + c.edge_points[k]);
          p[8 + 2 * k] = 0.5 * (c.vertices[(k + 1) % 3] + c.edge_points[k]);
          p[13 + k]    = 0.5 * (V + c.split_point);
          p[16 + k]    = 0.5 * (c.edge_points[k] + c.split_point);
        }
      p[6] = c.split_point;
      return p;
    }

    namespace
    {
      /// The sub-triangle of the cell (x relative to its origin) holding x:
      /// the smallest lambda_k / zb_k names the vertex opposite the macro
      /// edge whose two sub-triangles contain x, and the line R Z splits
      /// those two.
      template <typename CellData>
      inline unsigned int
      find_sub_triangle(const CellData &d, const double x, const double y)
      {
        double r[3];
        for (unsigned int k = 0; k < 3; ++k)
          r[k] = (d.macro[k][0] + d.macro[k][1] * x + d.macro[k][2] * y) *
                 d.inverse_split[k];
        // argmin without branches (ties to the lower index): particles of
        // a cell fall into its sub-triangles at random, so a branch here
        // is mispredicted about every other point.
        const unsigned int     m1      = r[1] < r[0];
        const double           r01     = m1 ? r[1] : r[0];
        const unsigned int     m2      = r[2] < r01;
        const unsigned int     m       = m1 + m2 * (2 - m1);
        constexpr unsigned int next[3] = {1, 2, 0};
        const unsigned int     edge    = next[m];
        const double          *sl      = d.split_line[edge];
        return 2 * edge + (sl[0] + sl[1] * x + sl[2] * y >= 0 ? 0 : 1);
      }

      template <typename SubTriangle>
      inline void
      evaluate_on(const SubTriangle &q,
                  const double       x,
                  const double       y,
                  double *__restrict values,
                  Tensor<1, 2> *__restrict gradients)
      {
        const double *m0 = q.map[0], *m1 = q.map[1];
        const double  l0  = m0[0] + m0[1] * x + m0[2] * y;
        const double  l1  = m1[0] + m1[1] * x + m1[2] * y;
        const double  l00 = l0 * l0, l01 = l0 * l1, l11 = l1 * l1;
        const double  t0 = 2 * l0, t1 = 2 * l1;
        // Functions 0..7 in pairs, function 8 alone.
        for (unsigned int i = 0; i < 8; i += 2)
          {
            const Pair c0 = load_pair(&q.c[0][i]), c1 = load_pair(&q.c[1][i]),
                       c2 = load_pair(&q.c[2][i]), c3 = load_pair(&q.c[3][i]),
                       c4 = load_pair(&q.c[4][i]), c5 = load_pair(&q.c[5][i]);
            const Pair v =
              c0 + l0 * c1 + l1 * c2 + l00 * c3 + l01 * c4 + l11 * c5;
            std::memcpy(values + i, &v, sizeof(v));
            if (gradients == nullptr)
              continue;
            // Derivatives in l0 and l1, then the chain rule.
            const Pair d0       = c1 + t0 * c3 + l1 * c4;
            const Pair d1       = c2 + l0 * c4 + t1 * c5;
            const Pair gx       = d0 * m0[1] + d1 * m1[1];
            const Pair gy       = d0 * m0[2] + d1 * m1[2];
            gradients[i][0]     = gx[0];
            gradients[i][1]     = gy[0];
            gradients[i + 1][0] = gx[1];
            gradients[i + 1][1] = gy[1];
          }
        const unsigned int i = 8;
        values[i]            = q.c[0][i] + l0 * q.c[1][i] + l1 * q.c[2][i] +
                    l00 * q.c[3][i] + l01 * q.c[4][i] + l11 * q.c[5][i];
        if (gradients == nullptr)
          return;
        const double d0 = q.c[1][i] + t0 * q.c[3][i] + l1 * q.c[4][i];
        const double d1 = q.c[2][i] + l0 * q.c[4][i] + t1 * q.c[5][i];
        gradients[i][0] = d0 * m0[1] + d1 * m1[1];
        gradients[i][1] = d0 * m0[2] + d1 * m1[2];
      }
    } // namespace

    void
    PowellSabin::evaluate(const unsigned int cell,
                          const Point<2>    &p,
                          double            *values,
                          Tensor<1, 2>      *gradients) const
    {
      const CellData &d = data(cell);
      const double    x = p[0] - d.origin[0], y = p[1] - d.origin[1];
      evaluate_on(d.sub[find_sub_triangle(d, x, y)], x, y, values, gradients);
    }

    void
    PowellSabin::evaluate(const unsigned int  n,
                          const unsigned int *cells,
                          const Point<2>     *points,
                          double             *values,
                          Tensor<1, 2>       *gradients) const
    {
      // Finding the sub-triangle is a chain of dependent operations, and
      // the coefficients it selects are a load that depends on the point,
      // so out-of-order execution overlaps little of one point with the
      // next, and a cell whose data is not cached stalls on memory (3 kB
      // per cell: a mesh's data does not stay in the caches from one step
      // to the next). Hence a software pipeline: the first part of the
      // cell data of point i + 2 a is requested, the sub-triangle of point
      // i + a found and its coefficients requested, point i evaluated.
      // On the throughput bar this halved the time per point
      // (doc/performance.md, "Powell-Sabin evaluation").
      constexpr unsigned int a = 8;
      // One rank holds every cell at its own index: the loop reads
      // cell_data[cell] as before the held cells existed. Several ranks
      // hold some (Mesh::HeldCells): a point's data are looked up through
      // the table and checked once, when its sub-triangle is found.
      const auto run = [&](const auto all_held) {
        const auto at = [&](const unsigned int cell) -> const CellData & {
          if constexpr (all_held)
            {
              AssertIndexRange(cell, cell_data.size());
              return cell_data[cell];
            }
          else
            return data(cell);
        };
        // The slot of a cell that find() has checked.
        const auto slot = [&](const unsigned int cell) {
          return all_held ? cell : held.slot(cell);
        };
        unsigned int ring[a];
        const auto   request = [](const void *begin, const std::size_t size) {
          const char *p = static_cast<const char *>(begin);
          for (std::size_t b = 0; b < size; b += 64)
            __builtin_prefetch(p + b);
          __builtin_prefetch(p + size - 1);
        };
        const auto find = [&](const unsigned int j) {
          const CellData    &d = at(cells[j]);
          const unsigned int s = find_sub_triangle(d,
                                                   points[j][0] - d.origin[0],
                                                   points[j][1] - d.origin[1]);
          request(&d.sub[s], sizeof(d.sub[s]));
          return s;
        };
        for (unsigned int j = 0; j < std::min(n, a); ++j)
          ring[j] = find(j);
        for (unsigned int i = 0; i < n; ++i)
          {
            if (i + 2 * a < n)
              {
                // A hint only (a prefetch does not fault); find() checks
                // the cell before its data are read.
                const unsigned int ahead = slot(cells[i + 2 * a]);
                if (all_held || ahead < cell_data.size())
                  request(&cell_data[ahead], offsetof(CellData, sub));
              }
            const unsigned int s = ring[i % a];
            if (i + a < n)
              ring[i % a] = find(i + a);
            const CellData &d = cell_data[slot(cells[i])];
            evaluate_on(d.sub[s],
                        points[i][0] - d.origin[0],
                        points[i][1] - d.origin[1],
                        values + 9 * i,
                        gradients != nullptr ? gradients + 9 * i : nullptr);
          }
      };
      if (held.holds_all())
        run(std::true_type());
      else
        run(std::false_type());
    }

    void
    PowellSabin::make_dirichlet_constraints(
      const DoFHandler<2>                &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<2>                  &g,
      AffineConstraints<double>          &constraints) const
    {
      std::map<unsigned int, VertexRows> vertex_rows;
      AssertThrow(vertex_data.size() ==
                    dof_handler.get_triangulation().n_vertices(),
                  ExcMessage("PowellSabin::make_dirichlet_constraints: call "
                             "reinit() with this mesh first."));

      std::vector<types::global_dof_index> dofs(9);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                ids.count(cell->face(f)->boundary_id()) > 0)
              {
                const auto         face = cell->face(f);
                const Point<2>     A = face->vertex(0), B = face->vertex(1);
                const double       length = A.distance(B);
                const Tensor<1, 2> t      = (B - A) / length;
                // Central difference along the edge: step cbrt(eps) balances
                // truncation and round-off.
                const double h = 6e-6 * length;
                for (unsigned int k = 0; k < 3; ++k)
                  for (const auto fv : face->vertex_indices())
                    if (cell->vertex_index(k) == face->vertex_index(fv))
                      {
                        const unsigned int v  = cell->vertex_index(k);
                        const Point<2>    &V  = cell->vertex(k);
                        const auto        &vd = vertex_data[v];
                        VertexRows        &r  = vertex_rows[v];
                        for (unsigned int q = 0; q < 3; ++q)
                          r.dofs[q] = dofs[3 * k + q];
                        if (r.rows.empty())
                          r.rows.push_back({{vd.triplets[0].alpha,
                                             vd.triplets[1].alpha,
                                             vd.triplets[2].alpha,
                                             g.value(V)}});
                        const double dgdt =
                          (g.value(V + h * t) - g.value(V - h * t)) / (2 * h);
                        r.rows.push_back({{vd.triplets[0].gradient * t,
                                           vd.triplets[1].gradient * t,
                                           vd.triplets[2].gradient * t,
                                           dgdt}});
                      }
              }
        }

      for (auto &entry : vertex_rows)
        add_vertex_constraints(entry.second, constraints);
    }

    std::vector<Point<2>>
    PowellSabin::control_points(const DoFHandler<2> &dof_handler) const
    {
      AssertThrow(vertex_data.size() ==
                    dof_handler.get_triangulation().n_vertices(),
                  ExcMessage("PowellSabin::control_points: call reinit() "
                             "with this mesh first."));
      std::vector<Point<2>>                points(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(9);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            // Local DoF 3k+q is component q of cell vertex k, i.e. the
            // function whose coefficient is the value at Q_{v,q}.
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int q = 0; q < 3; ++q)
                points[dofs[3 * k + q]] =
                  vertex_data[cell->vertex_index(k)].control_points[q];
          }
      return points;
    }

    FullMatrix<double>
    PowellSabin::extrapolation_weights(const unsigned int from,
                                       const unsigned int to) const
    {
      AssertIndexRange(from, vertex_data.size());
      AssertIndexRange(to, vertex_data.size());
      const auto         bary = Mesh::barycentric_map(control_triangle(from));
      const auto        &Q    = control_triangle(to);
      FullMatrix<double> W(3, 3);
      for (unsigned int q = 0; q < 3; ++q)
        {
          const auto l = bary(Q[q]);
          for (unsigned int r = 0; r < 3; ++r)
            W(q, r) = l[r];
        }
      return W;
    }

    Quadrature<2>
    PowellSabin::cell_quadrature(const DoFHandler<2> &dof_handler,
                                 const unsigned int   cell) const
    {
      AssertThrow(cell < ps_refinement.n_cells() &&
                    ps_refinement.n_cells() ==
                      dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("PowellSabin::cell_quadrature: call reinit() "
                             "with this mesh first."));
      static const Mesh::TriangleRule rule;
      const auto                     &c = ps_refinement.cell(cell);
      std::vector<Point<2>>           points;
      std::vector<double>             weights;
      points.reserve(6 * 7);
      weights.reserve(6 * 7);
      for (unsigned int s = 0; s < 6; ++s)
        {
          const auto   t    = c.sub_triangle(s);
          const double area = Mesh::signed_area(t);
          for (unsigned int q = 0; q < 7; ++q)
            {
              const auto &l = rule.points[q];
              points.emplace_back(l[0] * t[0][0] + l[1] * t[1][0] +
                                    l[2] * t[2][0],
                                  l[0] * t[0][1] + l[1] * t[1][1] +
                                    l[2] * t[2][1]);
              weights.push_back(area * rule.weights[q]);
            }
        }
      return Quadrature<2>(points, weights);
    }

    double
    PowellSabin::stability_factor(const bool lumped) const
    {
      // Measured by bisection on the vibrating bar with criss-cross blocks
      // (contrib/studies/stability/stability_study.py: 1.61 lumped, 0.43 consistent),
      // rounded down; doc/stability.md. Lumped: a free body turning
      // through empty cells with APIC (prm/rotating_block.prm, nu = 0.49
      // and 0.499) is stable at 0.675 h / c and not at 0.75, so the
      // factor is 1.2 (0.6 h / c at Courant number 0.5), below the bar's.
      return lumped ? 1.2 : 0.4;
    }

    namespace
    {
      const Registration<SpaceRegistry<2>> register_powell_sabin(
        {"powell-sabin",
         "quadratic C1 Powell-Sabin splines, three per vertex",
         []() -> std::unique_ptr<Space<2>> {
           return std::make_unique<PowellSabin>();
         },
         nullptr});
    } // namespace
  }   // namespace Basis
} // namespace psmpm
