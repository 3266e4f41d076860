// ---------------------------------------------------------------------
// psmpm: Space::cell_quadrature integrates products of two basis
// functions exactly. For P1 (1D and 2D) and Powell-Sabin on a criss-cross
// mesh and the Gmsh L-shape: positive weights, points in the closed cell,
// the sum of the cell mass matrix entries equals the cell measure
// (partition of unity), and the mass matrix agrees with a much finer
// quadrature (each polynomial piece subdivided, a different Gauss rule).
// A rule on the whole cell, blind to the PS sub-triangles, does not agree:
// the comparison can tell.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/basis/linear.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/mesh/triangle_geometry.h>

#include "../tests.h"

#include <vector>

namespace
{
  using namespace psmpm;

  template <int dim>
  FullMatrix<double>
  mass_matrix(const Basis::Space<dim> &space,
              const unsigned int       cell,
              const Quadrature<dim>   &quadrature)
  {
    const unsigned int          n = space.dofs_per_cell();
    FullMatrix<double>          M(n, n);
    std::vector<double>         values(n);
    std::vector<Tensor<1, dim>> gradients(n);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        space.evaluate(cell,
                       quadrature.point(q),
                       values.data(),
                       gradients.data());
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            M(i, j) += quadrature.weight(q) * values[i] * values[j];
      }
    return M;
  }

  /// The n^2 triangles of the uniform subdivision of @p t, each with the
  /// degree-7 simplex Gauss rule (the space's rules have degree 5).
  Quadrature<2>
  fine_rule(const std::vector<std::array<Point<2>, 3>> &triangles,
            const unsigned int                          n)
  {
    const QGaussSimplex<2> base(4);
    std::vector<Point<2>>  points;
    std::vector<double>    weights;
    for (const auto &t : triangles)
      {
        const auto at = [&](const unsigned int i, const unsigned int j) {
          return Point<2>(t[0] + (double(i) / n) * (t[1] - t[0]) +
                          (double(j) / n) * (t[2] - t[0]));
        };
        std::vector<std::array<Point<2>, 3>> small;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i + j < n; ++i)
            {
              small.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
              if (i + j + 1 < n)
                small.push_back(
                  {{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
            }
        for (const auto &s : small)
          {
            const double area = std::abs(Mesh::signed_area(s));
            for (unsigned int q = 0; q < base.size(); ++q)
              {
                const Point<2> &r = base.point(q);
                points.emplace_back(s[0] + r[0] * (s[1] - s[0]) +
                                    r[1] * (s[2] - s[0]));
                weights.push_back(2 * area * base.weight(q));
              }
          }
      }
    return Quadrature<2>(points, weights);
  }

  struct Result
  {
    bool   positive = true, inside = true;
    double sum = 0, fine = 0, whole_cell = 0;
  };

  /// @p pieces: the triangles on which the functions of a cell are
  /// polynomials.
  template <typename PiecesFunction>
  Result
  check_2d(const Basis::Space<2> &space,
           const DoFHandler<2>   &dof_handler,
           const PiecesFunction  &pieces)
  {
    Result r;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c          = cell->active_cell_index();
        const auto         quadrature = space.cell_quadrature(dof_handler, c);
        const double       area       = cell->measure();
        const auto         bary       = Mesh::barycentric_map(
          {{cell->vertex(0), cell->vertex(1), cell->vertex(2)}});
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            r.positive = r.positive && quadrature.weight(q) > 0;
            for (const double l : bary(quadrature.point(q)))
              r.inside = r.inside && l > -1e-14;
          }
        const auto   M   = mass_matrix(space, c, quadrature);
        const auto   F   = mass_matrix(space, c, fine_rule(pieces(cell), 4));
        double       sum = 0;
        const double n   = M.m();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              sum += M(i, j);
              r.fine = std::max(r.fine, std::abs(M(i, j) - F(i, j)) / area);
            }
        r.sum = std::max(r.sum, std::abs(sum - area) / area);
        // Degree 5 on the whole cell, as for a space without sub-cells.
        const auto W = mass_matrix(
          space,
          c,
          fine_rule({{{cell->vertex(0), cell->vertex(1), cell->vertex(2)}}},
                    1));
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            r.whole_cell =
              std::max(r.whole_cell, std::abs(W(i, j) - F(i, j)) / area);
      }
    return r;
  }

  void
  check_mesh(std::ostream &out, const std::string &name, Triangulation<2> &tria)
  {
    out << name << ": cells " << tria.n_active_cells() << std::endl;
    {
      Basis::Linear<2> p1;
      DoFHandler<2>    dof_handler(tria);
      dof_handler.distribute_dofs(p1.dof_layout());
      p1.reinit(dof_handler);
      const auto r = check_2d(p1, dof_handler, [](const auto &cell) {
        return std::vector<std::array<Point<2>, 3>>{
          {{cell->vertex(0), cell->vertex(1), cell->vertex(2)}}};
      });
      out << "linear" << std::endl;
      PSMPM_CHECK(out, r.positive && r.inside);
      // P1 evaluates lambda = c + g . x in absolute coordinates, which
      // loses digits in proportion to |x| / h (h ~ 0.07 on the L-shape).
      PSMPM_CHECK(out, r.sum < 1e-13);
      PSMPM_CHECK(out, r.fine < 1e-15);
    }
    {
      Basis::PowellSabin ps;
      DoFHandler<2>      dof_handler(tria);
      dof_handler.distribute_dofs(ps.dof_layout());
      ps.reinit(dof_handler);
      const auto r = check_2d(ps, dof_handler, [&ps](const auto &cell) {
        std::vector<std::array<Point<2>, 3>> t;
        for (unsigned int s = 0; s < 6; ++s)
          t.push_back(
            ps.refinement().cell(cell->active_cell_index()).sub_triangle(s));
        return t;
      });
      out << "powell-sabin: quadrature points per cell "
          << ps.cell_quadrature(dof_handler, 0).size() << std::endl;
      PSMPM_CHECK(out, r.positive && r.inside);
      PSMPM_CHECK(out, r.sum < 1e-14);
      PSMPM_CHECK(out, r.fine < 1e-15);
      PSMPM_CHECK(out, r.whole_cell > 1e-6);
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
        3,
        2,
        Mesh::MeshGenerator<2>::Type::criss_cross);
      check_mesh(out, "criss-cross", tria);
    }
    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::read_gmsh(tria,
                                        PSMPM_SOURCE_DIR
                                        "/tests/basis/l_shape.msh");
      check_mesh(out, "l_shape", tria);
    }
    {
      // 1D: the two hats of a cell; the fine rule is Gauss with 4 points
      // on 16 sub-intervals.
      Triangulation<1> tria;
      GridGenerator::subdivided_hyper_cube(tria, 4, -1, 2);
      Basis::Linear<1> p1;
      DoFHandler<1>    dof_handler(tria);
      dof_handler.distribute_dofs(p1.dof_layout());
      p1.reinit(dof_handler);
      double sum = 0, fine = 0;
      bool   positive = true;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int c          = cell->active_cell_index();
          const auto         quadrature = p1.cell_quadrature(dof_handler, c);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            positive = positive && quadrature.weight(q) > 0;
          const double          length = cell->measure();
          const auto            M      = mass_matrix(p1, c, quadrature);
          const QIterated<1>    reference(QGauss<1>(4), 16);
          std::vector<Point<1>> points;
          std::vector<double>   weights;
          for (unsigned int q = 0; q < reference.size(); ++q)
            {
              points.push_back(cell->vertex(0) +
                               reference.point(q)[0] *
                                 (cell->vertex(1) - cell->vertex(0)));
              weights.push_back(length * reference.weight(q));
            }
          const auto F = mass_matrix(p1, c, Quadrature<1>(points, weights));
          double     s = 0;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              {
                s += M(i, j);
                fine = std::max(fine, std::abs(M(i, j) - F(i, j)) / length);
              }
          sum = std::max(sum, std::abs(s - length) / length);
        }
      out << "1D linear" << std::endl;
      PSMPM_CHECK(out, positive);
      PSMPM_CHECK(out, sum < 1e-14);
      PSMPM_CHECK(out, fine < 1e-15);
    }
  });
}
