// ---------------------------------------------------------------------
// psmpm: the 2D tensor-product B-spline space of degree p = 1, ..., 5
// (Basis/Type = bspline on Mesh/Type = cartesian). For every degree:
// * on a uniform 4 x 3 mesh of the unit square, every tensor-product
//   B-spline B_i(x) B_j(y) (Basis::BSpline1D, Cox-de Boor) lies in the
//   tied layout space: its per-cell Bezier coefficients (interpolated with
//   evaluate()) agree on shared DoFs and satisfy every tie to 1e-12. With
//   n_free = (nx + p)(ny + p) free DoFs, the tied space is therefore the
//   B-spline space; for p <= 2 every free DoF's function is one of the
//   B-splines;
// * on a non-uniform 5 x 4 mesh: the free DoF count, the partition of
//   unity (values and gradients) of evaluate(), C1 across every interior
//   edge of a random tied function, control points that satisfy the ties
//   and reproduce x and y, and Dirichlet constraints (g = 0 and g = 2 on
//   the left side) that hold along that whole side.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/bspline_1d.h>
#include <psmpm/basis/tensor_bspline.h>

#include "../tests.h"

#include <random>
#include <vector>

namespace
{
  using namespace psmpm;

  struct Setup
  {
    Triangulation<2>          tria;
    DoFHandler<2>             dof_handler;
    Basis::TensorBSpline      space;
    AffineConstraints<double> ties;
    std::vector<unsigned int> n_cells{0, 0};

    Setup(const unsigned int p, const std::vector<std::vector<double>> &steps)
    {
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                steps,
                                                Point<2>(0, 0),
                                                Point<2>(1, 1),
                                                true);
      n_cells = {static_cast<unsigned int>(steps[0].size()),
                 static_cast<unsigned int>(steps[1].size())};
      space.set_degree(p);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(space.dof_layout());
      space.reinit(dof_handler);
      space.make_space_constraints(dof_handler, ties);
      ties.close();
    }

    /// Value and gradient of the function with layout coefficients c in
    /// cell at x.
    std::pair<double, Tensor<1, 2>>
    field(const Vector<double>                               &c,
          const typename DoFHandler<2>::active_cell_iterator &cell,
          const Point<2>                                     &x) const
    {
      const unsigned int                   n = space.dofs_per_cell();
      std::vector<double>                  v(n);
      std::vector<Tensor<1, 2>>            g(n);
      std::vector<types::global_dof_index> dofs(n);
      cell->get_dof_indices(dofs);
      space.evaluate(cell->active_cell_index(), x, v.data(), g.data());
      std::pair<double, Tensor<1, 2>> r{0., Tensor<1, 2>()};
      for (unsigned int k = 0; k < n; ++k)
        {
          r.first += c[dofs[k]] * v[k];
          r.second += c[dofs[k]] * g[k];
        }
      return r;
    }

    /// A point of the cell at local coordinates (s, t).
    static Point<2>
    at(const typename DoFHandler<2>::active_cell_iterator &cell,
       const double                                        s,
       const double                                        t)
    {
      const Point<2> lo = cell->vertex(0), hi = cell->vertex(3);
      return Point<2>(lo[0] + s * (hi[0] - lo[0]), lo[1] + t * (hi[1] - lo[1]));
    }
  };

  /// Largest violation of the ties by the layout vector c.
  double
  tie_violation(const AffineConstraints<double> &ties, const Vector<double> &c)
  {
    Vector<double> d = c;
    ties.distribute(d);
    d -= c;
    return d.linfty_norm();
  }

  void
  check_span(std::ofstream &out, const unsigned int p)
  {
    const unsigned int     nx = 4, ny = 3;
    Setup                  s(p,
            {std::vector<double>(nx, 1. / nx),
                              std::vector<double>(ny, 1. / ny)});
    const Basis::BSpline1D bx(p, nx), by(p, ny);
    const unsigned int     n = s.space.dofs_per_cell();
    // Interpolation points of a cell: (p + 1)^2 equispaced ones.
    std::vector<Point<2>> unit;
    for (unsigned int j = 0; j <= p; ++j)
      for (unsigned int i = 0; i <= p; ++i)
        unit.emplace_back(double(i) / p, double(j) / p);

    double              worst_tie = 0, worst_shared = 0;
    std::vector<double> vx(p + 1), vy(p + 1);
    unsigned int        matched = 0;
    for (unsigned int i = 0; i < bx.n_functions(); ++i)
      for (unsigned int j = 0; j < by.n_functions(); ++j)
        {
          Vector<double>    c(s.dof_handler.n_dofs());
          std::vector<bool> set(s.dof_handler.n_dofs(), false);
          std::vector<types::global_dof_index> dofs(n);
          for (const auto &cell : s.dof_handler.active_cell_iterators())
            {
              const Point<2>     lo = cell->vertex(0);
              const unsigned int ex = std::lround(lo[0] * nx),
                                 ey = std::lround(lo[1] * ny);
              FullMatrix<double>  A(n, n);
              Vector<double>      f(n), b(n);
              std::vector<double> v(n);
              for (unsigned int q = 0; q < n; ++q)
                {
                  const Point<2> x = Setup::at(cell, unit[q][0], unit[q][1]);
                  s.space.evaluate(cell->active_cell_index(),
                                   x,
                                   v.data(),
                                   nullptr);
                  for (unsigned int k = 0; k < n; ++k)
                    A(q, k) = v[k];
                  bx.values(ex, x[0], vx.data());
                  by.values(ey, x[1], vy.data());
                  // Functions ex .. ex + p are non-zero on element ex.
                  f[q] = (i >= ex && i <= ex + p ? vx[i - ex] : 0.) *
                         (j >= ey && j <= ey + p ? vy[j - ey] : 0.);
                }
              A.gauss_jordan();
              A.vmult(b, f);
              cell->get_dof_indices(dofs);
              for (unsigned int k = 0; k < n; ++k)
                {
                  if (set[dofs[k]])
                    worst_shared =
                      std::max(worst_shared, std::abs(c[dofs[k]] - b[k]));
                  c[dofs[k]]   = b[k];
                  set[dofs[k]] = true;
                }
            }
          worst_tie = std::max(worst_tie, tie_violation(s.ties, c));
          // p <= 2: the B-spline is one free DoF's function: its free
          // coefficients are one 1 and zeros.
          unsigned int ones = 0, others = 0;
          for (types::global_dof_index k = 0; k < c.size(); ++k)
            if (!s.ties.is_constrained(k))
              {
                if (std::abs(c[k] - 1) < 1e-12)
                  ++ones;
                else if (std::abs(c[k]) > 1e-12)
                  ++others;
              }
          if (ones == 1 && others == 0)
            ++matched;
        }
    const unsigned int n_free = s.dof_handler.n_dofs() - s.ties.n_constraints();
    out << "p = " << p << ", uniform " << nx << " x " << ny << ": free DoFs "
        << n_free << " (B-splines " << bx.n_functions() * by.n_functions()
        << "), B-splines that are one free DoF's function " << matched
        << std::endl;
    PSMPM_CHECK(out, n_free == bx.n_functions() * by.n_functions());
    PSMPM_CHECK(out, worst_shared < 1e-12);
    // The Bezier coefficients come from the (p + 1)^2 Bernstein
    // interpolation matrix at equispaced points, condition number 5.4,
    // 26, 139 and 820 for p = 2 to 5: a 1e-11 tie violation is round-off
    // at p = 5, a wrong tie is O(1).
    PSMPM_CHECK(out, worst_tie < 1e-11);
    PSMPM_CHECK(out, p > 2 || matched == n_free);
  }

  void
  check_nonuniform(std::ofstream &out, const unsigned int p)
  {
    const std::vector<std::vector<double>> steps{{0.3, 0.5, 0.2, 0.4, 0.6},
                                                 {0.7, 0.25, 0.45, 0.5}};
    Setup                                  s(p, steps);
    const unsigned int                     n = s.space.dofs_per_cell();
    const unsigned int n_free = s.dof_handler.n_dofs() - s.ties.n_constraints();
    PSMPM_CHECK(out, n_free == (5 + p) * (4 + p));

    std::mt19937                           rng(42 + p);
    std::uniform_real_distribution<double> u(0, 1), w(-1, 1);
    std::vector<double>                    v(n);
    std::vector<Tensor<1, 2>>              g(n);
    double                                 unity = 0;
    for (const auto &cell : s.dof_handler.active_cell_iterators())
      for (unsigned int q = 0; q < 10; ++q)
        {
          s.space.evaluate(cell->active_cell_index(),
                           Setup::at(cell, u(rng), u(rng)),
                           v.data(),
                           g.data());
          double       sum = 0;
          Tensor<1, 2> grad;
          for (unsigned int k = 0; k < n; ++k)
            {
              sum += v[k];
              grad += g[k];
            }
          unity = std::max({unity, std::abs(sum - 1), grad.norm()});
        }
    PSMPM_CHECK(out, unity < 1e-12);

    // C1 across interior edges: a random tied function from both sides.
    Vector<double> c(s.dof_handler.n_dofs());
    for (auto &x : c)
      x = w(rng);
    s.ties.distribute(c);
    double jump = 0;
    for (const auto &cell : s.dof_handler.active_cell_iterators())
      for (const unsigned int f : {1u, 3u}) // right and top faces
        if (!cell->at_boundary(f))
          {
            const auto other = cell->neighbor(f);
            for (unsigned int q = 0; q < 5; ++q)
              {
                const double   t = u(rng);
                const Point<2> x =
                  f == 1 ? Setup::at(cell, 1, t) : Setup::at(cell, t, 1);
                const auto a = s.field(c, cell, x), b = s.field(c, other, x);
                jump = std::max({jump,
                                 std::abs(a.first - b.first),
                                 (a.second - b.second).norm()});
              }
          }
    out << "p = " << p << ", non-uniform 5 x 4: free DoFs " << n_free
        << ", C1 jumps below 1e-12 of the largest coefficient: "
        << (jump < 1e-12 * c.linfty_norm() ? "yes" : "no") << std::endl;
    // P1 (p = 1) is C0 only.
    PSMPM_CHECK(out, (p == 1) == !(jump < 1e-12 * c.linfty_norm()));

    // Control points: satisfy the ties, reproduce x and y.
    const auto points    = s.space.control_points(s.dof_handler);
    double     reproduce = 0, tie = 0;
    for (unsigned int d = 0; d < 2; ++d)
      {
        Vector<double> cp(points.size());
        for (unsigned int k = 0; k < points.size(); ++k)
          cp[k] = points[k][d];
        tie = std::max(tie, tie_violation(s.ties, cp));
        for (const auto &cell : s.dof_handler.active_cell_iterators())
          {
            const Point<2> x = Setup::at(cell, u(rng), u(rng));
            reproduce =
              std::max(reproduce, std::abs(s.field(cp, cell, x).first - x[d]));
          }
      }
    PSMPM_CHECK(out, tie < 1e-12);
    PSMPM_CHECK(out, reproduce < 1e-12);

    // Dirichlet on the left side (id 0), then the ties, as GridSystem
    // builds them: the whole side takes g.
    for (const double g : {0., 2.})
      {
        AffineConstraints<double> constraints;
        s.space.make_dirichlet_constraints(s.dof_handler,
                                           {0},
                                           Functions::ConstantFunction<2>(g),
                                           constraints);
        s.space.make_space_constraints(s.dof_handler, constraints);
        constraints.close();
        Vector<double> d(s.dof_handler.n_dofs());
        for (auto &x : d)
          x = w(rng);
        constraints.distribute(d);
        double off = 0, inside = 0;
        for (const auto &cell : s.dof_handler.active_cell_iterators())
          if (cell->at_boundary(0))
            for (unsigned int q = 0; q < 5; ++q)
              off =
                std::max(off,
                         std::abs(
                           s.field(d, cell, Setup::at(cell, 0, u(rng))).first -
                           g));
          else
            inside =
              std::max(inside,
                       std::abs(s.field(d, cell, cell->center()).first - g));
        PSMPM_CHECK(out, off < 1e-12);
        // ... and the interior is not forced to g.
        PSMPM_CHECK(out, inside > 1e-3);
      }
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    for (unsigned int p = 1; p <= 5; ++p)
      {
        check_span(out, p);
        check_nonuniform(out, p);
      }
    // Wrong meshes are refused naming the entry.
    Triangulation<2> triangles;
    GridGenerator::subdivided_hyper_cube_with_simplices(triangles, 2);
    DoFHandler<2>        dof_handler(triangles);
    Basis::TensorBSpline space;
    bool                 refused = false;
    try
      {
        space.reinit(dof_handler);
      }
    catch (const std::exception &e)
      {
        refused = std::string(e.what()).find("cartesian") != std::string::npos;
      }
    PSMPM_CHECK(out, refused);
  });
}
