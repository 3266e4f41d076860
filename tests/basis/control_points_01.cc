// ---------------------------------------------------------------------
// psmpm: control points reproduce linear functions, sum_i X_i N_i(x) = x
// and sum_i X_i (x) grad N_i = I, at random points of random cells, for
// the P1 and the Powell-Sabin space, on a criss-cross mesh and the Gmsh
// L-shape and disk. The P1 control points are the vertices; the PS ones
// the control triangle corners. Swapping two control points of one PS
// vertex (a wrong (vertex, q) -> DoF map) must break the reproduction.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/linear.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

#include <memory>
#include <random>

namespace
{
  using namespace psmpm;

  /**
   * Largest |sum X_i N_i - x| / diameter and |sum X_i (x) grad N_i - I|
   * over 50 random points in each of 200 random cells.
   */
  std::pair<double, double>
  reproduction_error(const Basis::Space<2>       &space,
                     const DoFHandler<2>         &dof_handler,
                     const std::vector<Point<2>> &X)
  {
    const auto &tria = dof_handler.get_triangulation();
    std::vector<typename DoFHandler<2>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      cells.push_back(cell);
    double diameter = 0;
    for (const auto &a : tria.get_vertices())
      for (const auto &b : tria.get_vertices())
        diameter = std::max(diameter, a.distance(b));

    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const unsigned int                     n = space.dofs_per_cell();
    std::vector<double>                    values(n);
    std::vector<Tensor<1, 2>>              gradients(n);
    std::vector<types::global_dof_index>   dofs(n);
    double                                 value = 0, gradient = 0;
    const Tensor<2, 2>                     identity({{1., 0.}, {0., 1.}});
    for (unsigned int c = 0; c < 200; ++c)
      {
        const auto &cell = cells[rng() % cells.size()];
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < 50; ++i)
          {
            double a = u(rng), b = u(rng);
            if (a + b > 1)
              {
                a = 1 - a;
                b = 1 - b;
              }
            const Point<2> p = cell->vertex(0) +
                               a * (cell->vertex(1) - cell->vertex(0)) +
                               b * (cell->vertex(2) - cell->vertex(0));
            space.evaluate(cell->active_cell_index(),
                           p,
                           values.data(),
                           gradients.data());
            Tensor<1, 2> x;
            Tensor<2, 2> jacobian;
            for (unsigned int k = 0; k < n; ++k)
              {
                x += values[k] * X[dofs[k]];
                jacobian += outer_product(X[dofs[k]], gradients[k]);
              }
            value    = std::max(value, (x - p).norm() / diameter);
            gradient = std::max(gradient, (jacobian - identity).norm());
          }
      }
    return {value, gradient};
  }

  void
  check(std::ostream &out, const std::string &name, Triangulation<2> &tria)
  {
    out << name << ": cells " << tria.n_active_cells() << std::endl;
    {
      Basis::Linear<2> p1;
      DoFHandler<2>    dof_handler(tria);
      dof_handler.distribute_dofs(p1.dof_layout());
      p1.reinit(dof_handler);
      const auto X        = p1.control_points(dof_handler);
      bool       vertices = X.size() == dof_handler.n_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          vertices =
            vertices && X[cell->vertex_dof_index(k, 0)] == cell->vertex(k);
      const auto e = reproduction_error(p1, dof_handler, X);
      PSMPM_CHECK(out, vertices);
      PSMPM_CHECK(out, e.first < 1e-14 && e.second < 1e-12);
    }
    {
      Basis::PowellSabin ps;
      DoFHandler<2>      dof_handler(tria);
      dof_handler.distribute_dofs(ps.dof_layout());
      ps.reinit(dof_handler);
      auto X       = ps.control_points(dof_handler);
      bool corners = X.size() == dof_handler.n_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int q = 0; q < 3; ++q)
            corners =
              corners && X[cell->vertex_dof_index(k, q)] ==
                           ps.control_triangle(cell->vertex_index(k))[q];
      const auto e = reproduction_error(ps, dof_handler, X);
      PSMPM_CHECK(out, corners);
      PSMPM_CHECK(out, e.first < 1e-14 && e.second < 1e-12);

      // Swap Q_0 and Q_1 of every vertex: as if DoF (v, q) were mapped to
      // the wrong control point. Linear reproduction must fail clearly.
      std::vector<bool> swapped(tria.n_vertices(), false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          if (!swapped[cell->vertex_index(k)])
            {
              swapped[cell->vertex_index(k)] = true;
              std::swap(X[cell->vertex_dof_index(k, 0)],
                        X[cell->vertex_dof_index(k, 1)]);
            }
      const auto wrong = reproduction_error(ps, dof_handler, X);
      PSMPM_CHECK(out, wrong.first > 1e-3);
    }
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(3, 2),
        6,
        4,
        Mesh::MeshGenerator<2>::Type::criss_cross);
      check(out, "criss-cross", tria);
    }
    for (const std::string name : {"l_shape", "disk"})
      {
        Triangulation<2> tria;
        Mesh::MeshGenerator<2>::read_gmsh(tria,
                                          PSMPM_SOURCE_DIR "/tests/basis/" +
                                            name + ".msh");
        check(out, name, tria);
      }
  });
}
