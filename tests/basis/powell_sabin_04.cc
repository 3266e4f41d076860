// ---------------------------------------------------------------------
// psmpm: Dirichlet constraints of the Powell-Sabin space. Homogeneous on
// part of a structured mesh: boundary-aligned control triangles make them
// "coefficient = 0" lines (two per straight-boundary vertex, three at a
// corner with both sides constrained) and the spline vanishes with its
// tangential derivative on the constrained edges, not on the others.
// Inhomogeneous with a quadratic g: u = g on the whole boundary. On the
// unstructured L-shape (reflex corner: unaligned control triangle):
// homogeneous on every boundary.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"
#include "dirichlet_checks.h"

namespace
{
  /// 1 + 2x - y + x^2 + xy - y^2/2 with its exact gradient.
  class Quadratic : public Function<2>
  {
  public:
    double
    value(const Point<2> &p, const unsigned int = 0) const override
    {
      const double x = p[0], y = p[1];
      return 1 + 2 * x - y + x * x + x * y - 0.5 * y * y;
    }
    Tensor<1, 2>
    gradient(const Point<2> &p, const unsigned int = 0) const override
    {
      Tensor<1, 2> g;
      g[0] = 2 + 2 * p[0] + p[1];
      g[1] = -1 + p[0] - p[1];
      return g;
    }
  };
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;
    using namespace dirichlet_checks;

    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(2, 1),
        4,
        3,
        Mesh::MeshGenerator<2>::Type::diagonal);
      Basis::PowellSabin ps;
      DoFHandler<2>      dof_handler(tria);
      dof_handler.distribute_dofs(ps.dof_layout());
      ps.reinit(dof_handler);

      // Left (0) and bottom (2): homogeneous.
      const std::set<types::boundary_id> ids = {0, 2};
      AffineConstraints<double>          constraints;
      ps.make_dirichlet_constraints(dof_handler,
                                    ids,
                                    Functions::ZeroFunction<2>(),
                                    constraints);
      constraints.close();
      // 4 + 3 vertices on left and bottom without the corners; corner
      // (0, 0) has both sides constrained, corners (2, 0) and (0, 1) one.
      out << "homogeneous on left and bottom: " << constraints.n_constraints()
          << " constrained coefficients (expected 2 * 5 + 3 + 2 * 2 = 17)"
          << std::endl;
      PSMPM_CHECK(out, constraints.n_constraints() == 17);
      PSMPM_CHECK(out, n_lines_with_entries(constraints) == 0);
      bool corner_all = true;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          if (cell->vertex(k).norm() < 1e-12)
            for (unsigned int q = 0; q < 3; ++q)
              corner_all = corner_all && constraints.is_constrained(
                                           cell->vertex_dof_index(k, q));
      PSMPM_CHECK(out, corner_all);
      // The zeroed coefficients are those whose control points lie on the
      // constrained boundary lines x = 0 or y = 0.
      bool on_line = true;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int q = 0; q < 3; ++q)
            if (constraints.is_constrained(cell->vertex_dof_index(k, q)))
              {
                const Point<2> Q =
                  ps.control_triangle(cell->vertex_index(k))[q];
                const Point<2> V = cell->vertex(k);
                on_line          = on_line &&
                          ((std::abs(V[0]) < 1e-12 && std::abs(Q[0]) < 1e-12) ||
                           (std::abs(V[1]) < 1e-12 && std::abs(Q[1]) < 1e-12));
              }
      PSMPM_CHECK(out, on_line);

      const auto c    = constrained_coefficients(dof_handler, constraints);
      const auto zero = boundary_deviation(ps,
                                           dof_handler,
                                           c,
                                           ids,
                                           Functions::ZeroFunction<2>());
      PSMPM_CHECK(out, zero.first < 1e-13 && zero.second < 1e-13);
      const auto free = boundary_deviation(ps,
                                           dof_handler,
                                           c,
                                           {1, 3},
                                           Functions::ZeroFunction<2>());
      PSMPM_CHECK(out, free.first > 0.1);

      // Inhomogeneous, quadratic g on all four sides: the trace of a PS
      // spline on an edge is determined by the values and tangential
      // derivatives at its ends, and the central difference is exact for
      // quadratics up to round-off of order eps / step = 1e-16 / 1e-6.
      const Quadratic           g;
      AffineConstraints<double> inhomogeneous;
      ps.make_dirichlet_constraints(dof_handler,
                                    {0, 1, 2, 3},
                                    g,
                                    inhomogeneous);
      inhomogeneous.close();
      const auto ci  = constrained_coefficients(dof_handler, inhomogeneous);
      const auto dev = boundary_deviation(ps, dof_handler, ci, {0, 1, 2, 3}, g);
      out << "inhomogeneous on all sides: " << inhomogeneous.n_constraints()
          << " constrained coefficients" << std::endl;
      PSMPM_CHECK(out, dev.first < 1e-9 && dev.second < 1e-8);
    }
    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::read_gmsh(tria,
                                        PSMPM_SOURCE_DIR
                                        "/tests/basis/l_shape.msh");
      Basis::PowellSabin ps;
      DoFHandler<2>      dof_handler(tria);
      dof_handler.distribute_dofs(ps.dof_layout());
      ps.reinit(dof_handler);
      const std::set<types::boundary_id> ids = {0, 1, 2, 3, 4};
      AffineConstraints<double>          constraints;
      ps.make_dirichlet_constraints(dof_handler,
                                    ids,
                                    Functions::ZeroFunction<2>(),
                                    constraints);
      constraints.close();
      out << "L-shape, homogeneous everywhere: " << constraints.n_constraints()
          << " constrained coefficients" << std::endl;
      const auto c    = constrained_coefficients(dof_handler, constraints);
      const auto zero = boundary_deviation(ps,
                                           dof_handler,
                                           c,
                                           ids,
                                           Functions::ZeroFunction<2>());
      PSMPM_CHECK(out, zero.first < 1e-13 && zero.second < 1e-13);
    }
  });
}
