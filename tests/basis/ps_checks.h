// ---------------------------------------------------------------------
// psmpm: shared checks of the basis tests. Each check samples the space
// on every cell and sub-triangle and prints one PSMPM_CHECK line; the
// .output files expect "OK".
// ---------------------------------------------------------------------
#ifndef psmpm_tests_basis_ps_checks_h
#define psmpm_tests_basis_ps_checks_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/triangle_geometry.h>

#include "../tests.h"

#include <algorithm>
#include <map>
#include <vector>

namespace ps_checks
{
  using namespace psmpm;

  /// Sample points in barycentric coordinates of a (sub-)triangle:
  /// vertices, edge points, interior points.
  inline std::vector<std::array<double, 3>>
  sample_barycentric()
  {
    std::vector<std::array<double, 3>> s;
    const unsigned int                 n = 5;
    for (unsigned int i = 0; i <= n; ++i)
      for (unsigned int j = 0; i + j <= n; ++j)
        s.push_back({{double(i) / n, double(j) / n, double(n - i - j) / n}});
    s.push_back({{0.2113, 0.5774, 0.2113}});
    return s;
  }

  inline Point<2>
  point_of(const std::array<Point<2>, 3> &t, const std::array<double, 3> &l)
  {
    return Point<2>(l[0] * t[0][0] + l[1] * t[1][0] + l[2] * t[2][0],
                    l[0] * t[0][1] + l[1] * t[1][1] + l[2] * t[2][1]);
  }

  /**
   * Independent evaluation of the quadratic piece of sub-triangle @p s
   * from the ordinates and Bezier points (extrapolated if p is outside
   * it): used to compare neighbouring sub-triangles on their common edge.
   */
  inline void
  evaluate_piece(const Basis::PowellSabin &ps,
                 const unsigned int        cell,
                 const unsigned int        s,
                 const Point<2>           &p,
                 double                   *values,
                 Tensor<1, 2>             *gradients)
  {
    static const unsigned int points[6][6] = {{0, 3, 6, 7, 16, 13},
                                              {3, 1, 6, 8, 14, 16},
                                              {1, 4, 6, 9, 17, 14},
                                              {4, 2, 6, 10, 15, 17},
                                              {2, 5, 6, 11, 18, 15},
                                              {5, 0, 6, 12, 13, 18}};
    const auto                bp           = ps.bezier_points(cell);
    // The Bezier point list itself defines the sub-triangle: checks that
    // the numbering agrees with the refinement.
    // Relative to the first point, for precision independent of position.
    const Point<2>                o   = bp[points[s][0]];
    const std::array<Point<2>, 3> t   = {{Point<2>(bp[points[s][0]] - o),
                                          Point<2>(bp[points[s][1]] - o),
                                          Point<2>(bp[points[s][2]] - o)}};
    const auto                    map = Mesh::barycentric_map(t);
    const auto                    l   = map(Point<2>(p - o));
    for (unsigned int i = 0; i < 9; ++i)
      {
        double o[6];
        for (unsigned int j = 0; j < 6; ++j)
          o[j] = ps.ordinate(cell, i, points[s][j]);
        values[i] = o[0] * l[0] * l[0] + o[1] * l[1] * l[1] +
                    o[2] * l[2] * l[2] + 2 * o[3] * l[0] * l[1] +
                    2 * o[4] * l[1] * l[2] + 2 * o[5] * l[2] * l[0];
        gradients[i] =
          2 * o[0] * l[0] * map.gradient[0] +
          2 * o[1] * l[1] * map.gradient[1] +
          2 * o[2] * l[2] * map.gradient[2] +
          2 * o[3] * (l[0] * map.gradient[1] + l[1] * map.gradient[0]) +
          2 * o[4] * (l[1] * map.gradient[2] + l[2] * map.gradient[1]) +
          2 * o[5] * (l[2] * map.gradient[0] + l[0] * map.gradient[2]);
      }
  }

  /// Smallest altitude of any triangle: gradients of the basis scale like
  /// its inverse.
  inline double
  min_altitude(const Triangulation<2> &tria)
  {
    double h = 1e300;
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int k = 0; k < 3; ++k)
        h = std::min(h,
                     2 * cell->measure() /
                       cell->vertex(k).distance(cell->vertex((k + 1) % 3)));
    return h;
  }

  /// Largest ratio of longest edge to altitude over all triangles.
  inline double
  max_aspect_ratio(const Triangulation<2> &tria)
  {
    double r = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        double longest = 0;
        for (unsigned int k = 0; k < 3; ++k)
          longest =
            std::max(longest,
                     cell->vertex(k).distance(cell->vertex((k + 1) % 3)));
        r = std::max(r, longest * longest / (2 * cell->measure()));
      }
    return r;
  }

  /**
   * All properties of section 6 of the construction note except the
   * projection, on the mesh of @p dof_handler (which must use the dof
   * layout of @p ps, already reinit'ed).
   */
  inline void
  check_space(std::ostream             &out,
              const DoFHandler<2>      &dof_handler,
              const Basis::PowellSabin &ps)
  {
    const auto &tria   = dof_handler.get_triangulation();
    const auto  sample = sample_barycentric();
    // Gradients scale like 1/altitude: compare them relative to that.
    const double gscale = 1. / min_altitude(tria);
    // Barycentric coordinates of a triangle lose digits in proportion to
    // its aspect ratio: 1e-12 for reasonable meshes (aspect ratio below
    // 100), proportionally more for slivers.
    const double aspect = max_aspect_ratio(tria);
    const double tol    = 1e-12 * std::max(1., aspect / 100);
    double       values[9];
    Tensor<1, 2> gradients[9];
    std::vector<types::global_dof_index> dofs(9);

    unsigned int n_kind[4] = {0, 0, 0, 0};
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      if (tria.get_used_vertices()[v])
        ++n_kind[static_cast<int>(ps.vertex_kind(v))];
    out << "cells " << tria.n_active_cells() << ", vertices "
        << tria.n_used_vertices() << ", dofs " << dof_handler.n_dofs()
        << std::endl
        << "vertex kinds: interior " << n_kind[0] << ", straight boundary "
        << n_kind[1] << ", corner " << n_kind[2] << ", unaligned boundary "
        << n_kind[3] << std::endl
        << "aspect ratio below 100: " << (aspect < 100 ? "yes" : "no")
        << std::endl;

    // DoF layout: local 3k+q is component q of cell vertex k.
    bool        layout_ok = dof_handler.n_dofs() == 3 * tria.n_used_vertices();
    const auto &fe        = dof_handler.get_fe();
    for (unsigned int i = 0; i < 9; ++i)
      layout_ok = layout_ok && fe.system_to_component_index(i).first == i % 3 &&
                  fe.system_to_component_index(i).second == i / 3;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int q = 0; q < 3; ++q)
            layout_ok =
              layout_ok && cell->vertex_dof_index(k, q) == dofs[3 * k + q];
      }
    PSMPM_CHECK(out, layout_ok);

    // Partition of unity, zero gradient sum, non-negativity, agreement of
    // evaluate() with the independent piece evaluation.
    double pu = 0, gsum = 0, min_value = 1e300, agree = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c   = cell->active_cell_index();
        const auto        &ref = ps.refinement().cell(c);
        for (unsigned int s = 0; s < 6; ++s)
          for (const auto &l : sample)
            {
              const Point<2> p = point_of(ref.sub_triangle(s), l);
              ps.evaluate(c, p, values, gradients);
              double       sum = 0;
              Tensor<1, 2> gs;
              for (unsigned int i = 0; i < 9; ++i)
                {
                  sum += values[i];
                  gs += gradients[i];
                  min_value = std::min(min_value, values[i]);
                }
              pu   = std::max(pu, std::abs(sum - 1));
              gsum = std::max(gsum, gs.norm() / gscale);
              double       v2[9];
              Tensor<1, 2> g2[9];
              evaluate_piece(ps, c, s, p, v2, g2);
              for (unsigned int i = 0; i < 9; ++i)
                agree = std::max({agree,
                                  std::abs(v2[i] - values[i]),
                                  (g2[i] - gradients[i]).norm() / gscale});
            }
      }
    PSMPM_CHECK(out, pu < tol);
    PSMPM_CHECK(out, gsum < tol);
    PSMPM_CHECK(out, min_value > -1e-14);
    PSMPM_CHECK(out, agree < tol);

    // C1 across the sub-triangle edges inside each cell: the pieces of two
    // neighbouring sub-triangles agree in value and gradient on their
    // common edge (R_k Z between 2k and 2k+1, V_{k+1} Z between 2k+1 and
    // 2k+2).
    double jump_sub = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c   = cell->active_cell_index();
        const auto        &ref = ps.refinement().cell(c);
        for (unsigned int s = 0; s < 6; ++s)
          {
            const unsigned int s2 = (s + 1) % 6;
            const Point<2>     a  = ref.sub_triangle(s)[1];
            const Point<2>     z  = ref.split_point;
            for (unsigned int j = 0; j <= 8; ++j)
              {
                const Point<2> p = a + (j / 8.) * (z - a);
                double         v1[9], v2[9];
                Tensor<1, 2>   g1[9], g2[9];
                evaluate_piece(ps, c, s, p, v1, g1);
                evaluate_piece(ps, c, s2, p, v2, g2);
                for (unsigned int i = 0; i < 9; ++i)
                  jump_sub = std::max({jump_sub,
                                       std::abs(v1[i] - v2[i]),
                                       (g1[i] - g2[i]).norm() / gscale});
              }
          }
      }
    PSMPM_CHECK(out, jump_sub < tol);

    // C1 across macro edges: each global function evaluated from both
    // cells at points of their common edge (including R). And each
    // function vanishes with its gradient on the edge opposite its vertex,
    // i.e. on the boundary of its molecule.
    double                               jump_macro = 0, molecule = 0;
    std::vector<types::global_dof_index> dofs2(9);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c   = cell->active_cell_index();
        const auto        &ref = ps.refinement().cell(c);
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Point<2> A = ref.vertices[k], B = ref.vertices[(k + 1) % 3];
            std::vector<Point<2>> on_edge = {ref.edge_points[k]};
            for (unsigned int j = 0; j <= 10; ++j)
              on_edge.push_back(A + (j / 10.) * (B - A));
            // Functions of the vertex opposite edge k.
            const unsigned int opposite = (k + 2) % 3;
            for (const auto &p : on_edge)
              {
                ps.evaluate(c, p, values, gradients);
                for (unsigned int q = 0; q < 3; ++q)
                  molecule =
                    std::max({molecule,
                              std::abs(values[3 * opposite + q]),
                              gradients[3 * opposite + q].norm() / gscale});
              }
            // Find the face with these vertices and its neighbour.
            for (const auto f : cell->face_indices())
              {
                const auto face = cell->face(f);
                const bool same =
                  (face->vertex(0) == A && face->vertex(1) == B) ||
                  (face->vertex(0) == B && face->vertex(1) == A);
                if (!same || cell->at_boundary(f))
                  continue;
                const auto other = cell->neighbor(f);
                other->get_dof_indices(dofs2);
                double       v2[9];
                Tensor<1, 2> g2[9];
                for (const auto &p : on_edge)
                  {
                    ps.evaluate(c, p, values, gradients);
                    ps.evaluate(other->active_cell_index(), p, v2, g2);
                    std::map<types::global_dof_index,
                             std::pair<double, Tensor<1, 2>>>
                      diff;
                    for (unsigned int i = 0; i < 9; ++i)
                      {
                        diff[dofs[i]].first += values[i];
                        diff[dofs[i]].second += gradients[i];
                        diff[dofs2[i]].first -= v2[i];
                        diff[dofs2[i]].second -= g2[i];
                      }
                    for (const auto &d : diff)
                      jump_macro = std::max({jump_macro,
                                             std::abs(d.second.first),
                                             d.second.second.norm() / gscale});
                  }
              }
          }
      }
    PSMPM_CHECK(out, jump_macro < tol);
    PSMPM_CHECK(out, molecule < tol);

    // Linear reproduction with coefficients c_v^q = f(Q_v^q).
    const auto f = [](const Point<2> &p) {
      return 0.3 - 1.7 * p[0] + 2.9 * p[1];
    };
    Tensor<1, 2> grad_f;
    grad_f[0]     = -1.7;
    grad_f[1]     = 2.9;
    double linear = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c   = cell->active_cell_index();
        const auto        &ref = ps.refinement().cell(c);
        for (unsigned int s = 0; s < 6; ++s)
          for (const auto &l : sample)
            {
              const Point<2> p = point_of(ref.sub_triangle(s), l);
              ps.evaluate(c, p, values, gradients);
              double       u = 0;
              Tensor<1, 2> gu;
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int q = 0; q < 3; ++q)
                  {
                    const double coefficient =
                      f(ps.control_triangle(cell->vertex_index(k))[q]);
                    u += coefficient * values[3 * k + q];
                    gu += coefficient * gradients[3 * k + q];
                  }
              linear =
                std::max({linear, std::abs(u - f(p)), (gu - grad_f).norm()});
            }
      }
    PSMPM_CHECK(out, linear < tol);

    // Every PS point lies in its control triangle (the reason for
    // non-negativity), and boundary-aligned triangles are aligned.
    bool contains = true, aligned = true;
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      if (tria.get_used_vertices()[v])
        {
          const auto map = Mesh::barycentric_map(ps.control_triangle(v));
          for (const auto &p : ps.ps_points(v))
            for (const double l : map(p))
              contains = contains && l > -1e-12;
          const auto   kind       = ps.vertex_kind(v);
          unsigned int zero_alpha = 0;
          for (unsigned int q = 0; q < 3; ++q)
            zero_alpha += std::abs(ps.triplet(v, q).alpha) < 1e-12;
          // On a side: one alpha vanishes; at a vertex of Q: two do.
          if (kind == Basis::PowellSabin::VertexKind::straight_boundary)
            aligned = aligned && zero_alpha == 1;
          if (kind == Basis::PowellSabin::VertexKind::corner)
            aligned = aligned && zero_alpha == 2;
        }
    PSMPM_CHECK(out, contains);
    PSMPM_CHECK(out, aligned);
  }
} // namespace ps_checks

#endif
