// ---------------------------------------------------------------------
// psmpm: the 1D quadratic B-spline space (Basis/Type = bspline) by Bezier
// extraction. The n + 2 functions are the free DoFs of the FE_Q(2) layout
// with the space's C1 ties distributed; on a uniform mesh of [0, 1] they
// must equal Cox-de Boor's B-splines (Basis::BSpline1D) at random points,
// sum to one, be non-negative, have equal values and derivatives from
// both sides of every interior vertex, and reproduce a quadratic from its
// blossom coefficients exactly; the same holds on a non-uniform mesh
// (h-weighted ties). The end DoFs are the Dirichlet ones, and the control
// points reproduce x.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/bspline.h>
#include <psmpm/basis/bspline_1d.h>

#include "../tests.h"

#include <algorithm>
#include <random>
#include <vector>

namespace
{
  using namespace psmpm;

  /// The space on one mesh: its functions as coefficient vectors of the
  /// layout, ordered by Greville abscissa.
  struct SplineFunctions
  {
    Triangulation<1>            tria;
    DoFHandler<1>               dof_handler;
    Basis::BSpline              space;
    AffineConstraints<double>   ties;
    std::vector<Vector<double>> coefficients;
    std::vector<double>         greville;
    std::vector<Point<1>>       control;

    explicit SplineFunctions(const std::vector<double> &vertices)
    {
      std::vector<Point<1>>    points;
      std::vector<CellData<1>> cells(vertices.size() - 1);
      for (const double v : vertices)
        points.emplace_back(v);
      for (unsigned int c = 0; c < cells.size(); ++c)
        cells[c].vertices = {c, c + 1};
      tria.create_triangulation(points, cells, SubCellData());
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(space.dof_layout());
      space.reinit(dof_handler);
      space.make_space_constraints(dof_handler, ties);
      ties.close();
      control = space.control_points(dof_handler);
      std::vector<std::pair<double, unsigned int>> free;
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        if (!ties.is_constrained(i))
          free.emplace_back(control[i][0], i);
      std::sort(free.begin(), free.end());
      for (const auto &[x, i] : free)
        {
          Vector<double> c(dof_handler.n_dofs());
          c[i] = 1;
          ties.distribute(c);
          coefficients.push_back(c);
          greville.push_back(x);
        }
    }

    /// Value and derivative of the field with layout coefficients @p c on
    /// cell @p cell (x in the closed cell).
    std::pair<double, double>
    field(const Vector<double> &c,
          const unsigned int    cell,
          const double          x) const
    {
      double       values[3];
      Tensor<1, 1> gradients[3];
      space.evaluate(cell, Point<1>(x), values, gradients);
      std::vector<types::global_dof_index> dofs(3);
      DoFHandler<1>::active_cell_iterator(&tria, 0, cell, &dof_handler)
        ->get_dof_indices(dofs);
      std::pair<double, double> r(0, 0);
      for (unsigned int k = 0; k < 3; ++k)
        {
          r.first += c[dofs[k]] * values[k];
          r.second += c[dofs[k]] * gradients[k][0];
        }
      return r;
    }

    unsigned int
    cell_of(const double x) const
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (x >= cell->vertex(0)[0] && x <= cell->vertex(1)[0])
          return cell->active_cell_index();
      return numbers::invalid_unsigned_int;
    }
  };

  /// Checks that hold on any mesh; returns the largest deviations.
  void
  check_space(std::ofstream &out, const std::vector<double> &vertices)
  {
    SplineFunctions    f(vertices);
    const unsigned int n = vertices.size() - 1;
    out << n << " cells: " << f.dof_handler.n_dofs() << " layout DoFs, "
        << f.ties.n_constraints() << " tied, " << f.coefficients.size()
        << " functions" << std::endl;
    PSMPM_CHECK(out, f.coefficients.size() == n + 2);

    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    const double a = vertices.front(), b = vertices.back();

    // Partition of unity and non-negativity at random points.
    double unity = 0, lowest = 1;
    for (unsigned int q = 0; q < 200; ++q)
      {
        const double       x    = a + (b - a) * uniform(rng);
        const unsigned int cell = f.cell_of(x);
        double             sum  = 0;
        for (const auto &c : f.coefficients)
          {
            const double v = f.field(c, cell, x).first;
            sum += v;
            lowest = std::min(lowest, v);
          }
        unity = std::max(unity, std::abs(sum - 1));
      }
    out << "  partition of unity error " << (unity < 1e-14 ? "< 1e-14" : "")
        << ", smallest value >= " << (lowest >= 0 ? "0" : "negative")
        << std::endl;
    PSMPM_CHECK(out, unity < 1e-14);
    PSMPM_CHECK(out, lowest >= -1e-15);

    // C1 at every interior vertex: value and derivative from both cells.
    double jump_value = 0, jump_derivative = 0, scale = 0;
    for (unsigned int v = 1; v < n; ++v)
      for (const auto &c : f.coefficients)
        {
          const auto left  = f.field(c, v - 1, vertices[v]);
          const auto right = f.field(c, v, vertices[v]);
          jump_value = std::max(jump_value, std::abs(left.first - right.first));
          jump_derivative =
            std::max(jump_derivative, std::abs(left.second - right.second));
          scale = std::max(scale, std::abs(left.second));
        }
    out << "  largest derivative " << std::setprecision(3) << scale
        << std::endl;
    PSMPM_CHECK(out, scale > 1);
    PSMPM_CHECK(out, jump_value < 1e-14);
    PSMPM_CHECK(out, jump_derivative < 1e-12 * scale);

    // f = 1 + 2x - 3x^2 from its blossom at the knot pairs of the open
    // knot vector: F(u, v) = 1 + (u + v) - 3 u v.
    std::vector<double> knots = {a, a};
    knots.insert(knots.end(), vertices.begin(), vertices.end());
    knots.push_back(b), knots.push_back(b);
    Vector<double> quadratic(f.dof_handler.n_dofs()), linear(quadratic);
    for (unsigned int i = 0; i < n + 2; ++i)
      {
        const double u = knots[i + 1], w = knots[i + 2];
        quadratic.add(1 + (u + w) - 3 * u * w, f.coefficients[i]);
        linear.add(f.greville[i], f.coefficients[i]);
      }
    double error_q = 0, error_dq = 0, error_x = 0;
    for (unsigned int q = 0; q < 200; ++q)
      {
        const double       x    = a + (b - a) * uniform(rng);
        const unsigned int cell = f.cell_of(x);
        const auto         g    = f.field(quadratic, cell, x);
        error_q =
          std::max(error_q, std::abs(g.first - (1 + 2 * x - 3 * x * x)));
        error_dq = std::max(error_dq, std::abs(g.second - (2 - 6 * x)));
        error_x =
          std::max(error_x, std::abs(f.field(linear, cell, x).first - x));
      }
    PSMPM_CHECK(out, error_q < 1e-13 && error_dq < 1e-12);
    PSMPM_CHECK(out, error_x < 1e-14);
    // The control points of the tied DoFs satisfy the ties (APIC's
    // affine fields are then exact).
    double control_tie = 0;
    for (unsigned int i = 0; i < f.dof_handler.n_dofs(); ++i)
      if (f.ties.is_constrained(i))
        {
          double x = 0;
          for (const auto &[j, w] : *f.ties.get_constraint_entries(i))
            x += w * f.control[j][0];
          control_tie = std::max(control_tie, std::abs(x - f.control[i][0]));
        }
    PSMPM_CHECK(out, control_tie < 1e-14);
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;

    // Uniform mesh of [0, 1]: the functions are Cox-de Boor's.
    const unsigned int  n = 5;
    std::vector<double> uniform_vertices;
    for (unsigned int v = 0; v <= n; ++v)
      uniform_vertices.push_back(double(v) / n);
    check_space(out, uniform_vertices);
    {
      SplineFunctions                        f(uniform_vertices);
      const Basis::BSpline1D                 reference(2, n);
      std::mt19937                           rng(11);
      std::uniform_real_distribution<double> uniform(0, 1);
      double                                 difference = 0;
      for (unsigned int q = 0; q < 500; ++q)
        {
          const double       x       = uniform(rng);
          const unsigned int element = std::min(n - 1, unsigned(x * n));
          double             values[3];
          reference.values(element, x, values);
          for (unsigned int i = 0; i < n + 2; ++i)
            {
              const double expected =
                i >= element && i <= element + 2 ? values[i - element] : 0.;
              difference =
                std::max(difference,
                         std::abs(f.field(f.coefficients[i], element, x).first -
                                  expected));
            }
        }
      out << "  against Cox-de Boor at 500 random points: "
          << (difference < 1e-14 ? "< 1e-14" : "LARGER") << std::endl;
      PSMPM_CHECK(out, difference < 1e-14);
      out << "  Greville abscissae";
      for (const double g : f.greville)
        out << ' ' << g;
      out << std::endl;
      PSMPM_CHECK(out,
                  std::abs(f.greville[1] - 0.1) < 1e-15 &&
                    std::abs(f.greville[n] - 0.9) < 1e-15);

      // Dirichlet at both ends fixes exactly the two end functions.
      AffineConstraints<double> dirichlet;
      f.space.make_dirichlet_constraints(f.dof_handler,
                                         {0, 1},
                                         Functions::ZeroFunction<1>(),
                                         dirichlet);
      dirichlet.close();
      PSMPM_CHECK(out, dirichlet.n_constraints() == 2);
      std::vector<types::global_dof_index> fixed;
      for (unsigned int i = 0; i < f.dof_handler.n_dofs(); ++i)
        if (dirichlet.is_constrained(i))
          fixed.push_back(i);
      PSMPM_CHECK(out,
                  f.control[fixed[0]][0] + f.control[fixed[1]][0] == 1 &&
                    f.control[fixed[0]][0] * f.control[fixed[1]][0] == 0);
      PSMPM_CHECK(out,
                  !f.ties.is_constrained(fixed[0]) &&
                    !f.ties.is_constrained(fixed[1]));
    }

    // Non-uniform mesh of [0, 2].
    std::vector<double> vertices = {0, 0.3, 0.45, 1.1, 1.2, 1.7, 2};
    check_space(out, vertices);

    // Basis/Degree: 2 only.
    Basis::BSpline space;
    bool           refused = false;
    try
      {
        space.set_degree(3);
      }
    catch (const std::exception &e)
      {
        refused =
          std::string(e.what()).find("Basis/Degree = 3") != std::string::npos;
      }
    PSMPM_CHECK(out, refused);
    out << "stability factor lumped " << space.stability_factor(true)
        << ", consistent " << space.stability_factor(false) << std::endl;
  });
}
