// ---------------------------------------------------------------------
// psmpm: the 1D B-spline space of degree p = 1, ..., 5 (Basis/Type =
// bspline) by Bezier extraction, on a uniform mesh of [0, 1], a
// non-uniform mesh of [0, 2] given with its cells shuffled and two of them
// reversed, and a mesh of two cells. For every degree:
// * the layout has n p + 1 DoFs, (n - 1)(p - 1) of them tied, n + p free;
// * the B-splines assembled from bezier_extraction() agree on shared
//   vertices, satisfy the ties, equal Cox-de Boor's (a general recursion
//   on the knot vector here, and Basis::BSpline1D on the uniform mesh) at
//   random points to 1e-13, are non-negative and sum to one: n + p
//   independent functions in the n + p dimensional tied space, so the
//   tied space is the B-spline space;
// * every free DoF's function is C^{p-1} across every interior vertex
//   (derivatives 0 to p - 1 from both sides, from the Bezier coefficients;
//   values and first derivatives also from evaluate());
// * a polynomial of degree p is reproduced from its blossom at the knots,
//   and its Bezier coefficients satisfy the ties;
// * the control points satisfy the ties and reproduce x; the end DoFs
//   are the Dirichlet ones and never tied;
// * for p <= 2 the free DoFs' functions are the B-splines themselves.
// Degrees above 5 are refused naming Basis/Degree; lumped mass is
// verified for p <= 2 only.
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

  /// The open knot vector of degree p on the vertices.
  std::vector<double>
  open_knots(const std::vector<double> &vertices, const unsigned int p)
  {
    std::vector<double> t(p, vertices.front());
    t.insert(t.end(), vertices.begin(), vertices.end());
    t.insert(t.end(), p, vertices.back());
    return t;
  }

  /// Cox-de Boor (Piegl and Tiller, algorithm A2.2): the p + 1 B-splines
  /// first, ..., first + p that do not vanish on span [t_mu, t_mu+1],
  /// first = mu - p, at x.
  std::vector<double>
  cox_de_boor(const std::vector<double> &t,
              const unsigned int         p,
              const unsigned int         mu,
              const double               x)
  {
    std::vector<double> N(p + 1), left(p + 1), right(p + 1);
    N[0] = 1;
    for (unsigned int j = 1; j <= p; ++j)
      {
        left[j]      = x - t[mu + 1 - j];
        right[j]     = t[mu + j] - x;
        double saved = 0;
        for (unsigned int r = 0; r < j; ++r)
          {
            const double temp = N[r] / (right[r + 1] + left[j - r]);
            N[r]              = saved + right[r + 1] * temp;
            saved             = left[j - r] * temp;
          }
        N[j] = saved;
      }
    return N;
  }

  /// The blossom of f = 1 + x - 2 x^2 + ... (coefficients c_m = (-1)^m
  /// (m + 1) / 2^m, degree p) at u_1, ..., u_p: sum_m c_m e_m(u) /
  /// binomial(p, m), e_m the elementary symmetric polynomials.
  double
  blossom(const std::vector<double> &u)
  {
    const unsigned int  p = u.size();
    std::vector<double> e(p + 1, 0.);
    e[0] = 1;
    for (const double v : u)
      for (unsigned int m = p; m >= 1; --m)
        e[m] += v * e[m - 1];
    double f = 0, binomial = 1, c = 1;
    for (unsigned int m = 0; m <= p; ++m)
      {
        f += c * (m + 1) * e[m] / binomial;
        binomial = binomial * (p - m) / (m + 1);
        c *= -0.5;
      }
    return f;
  }

  /// The polynomial of blossom() and its derivative at x.
  std::pair<double, double>
  polynomial(const unsigned int p, const double x)
  {
    double f = 0, df = 0, c = 1;
    for (unsigned int m = 0; m <= p; ++m)
      {
        f += c * (m + 1) * std::pow(x, m);
        if (m > 0)
          df += c * (m + 1) * m * std::pow(x, m - 1);
        c *= -0.5;
      }
    return {f, df};
  }

  /// The space of degree p on one mesh: its free DoFs' functions and its
  /// B-splines as coefficient vectors of the layout.
  struct SplineFunctions
  {
    const unsigned int          p;
    const unsigned int          n;
    Triangulation<1>            tria;
    DoFHandler<1>               dof_handler;
    Basis::BSpline              space;
    AffineConstraints<double>   ties;
    std::vector<Vector<double>> free_functions;
    std::vector<double>         free_points;
    std::vector<Vector<double>> bsplines;
    std::vector<Point<1>>       control;
    std::vector<double>         vertices;
    double                      extraction_mismatch = 0;

    /// Cells are created in the order @p order, those in @p reversed with
    /// their vertices swapped.
    SplineFunctions(const unsigned int               degree,
                    const std::vector<double>       &vertices,
                    const std::vector<unsigned int> &order,
                    const std::set<unsigned int>    &reversed)
      : p(degree)
      , n(vertices.size() - 1)
      , vertices(vertices)
    {
      std::vector<Point<1>>    points;
      std::vector<CellData<1>> cells;
      for (const double v : vertices)
        points.emplace_back(v);
      for (const unsigned int c : order)
        {
          CellData<1> cell;
          cell.vertices = {c, c + 1};
          if (reversed.count(c) != 0)
            std::swap(cell.vertices[0], cell.vertices[1]);
          cells.push_back(cell);
        }
      tria.create_triangulation(points, cells, SubCellData());
      space.set_degree(p);
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
          free_functions.push_back(c);
          free_points.push_back(x);
        }
      // The B-splines from the extraction operators; a vertex DoF gets
      // its value from both cells, which must agree.
      bsplines.assign(n + p, Vector<double>(dof_handler.n_dofs()));
      std::vector<Vector<double>>          seen(n + p,
                                       Vector<double>(dof_handler.n_dofs()));
      std::vector<types::global_dof_index> dofs(p + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          const unsigned int c     = cell->active_cell_index();
          const auto        &E     = space.bezier_extraction(c);
          const unsigned int first = space.first_bspline(c);
          for (unsigned int i = 0; i <= p; ++i)
            for (unsigned int k = 0; k <= p; ++k)
              {
                auto &b = bsplines[first + i];
                if (seen[first + i][dofs[k]] != 0)
                  extraction_mismatch =
                    std::max(extraction_mismatch,
                             std::abs(b[dofs[k]] - E(k, i)));
                b[dofs[k]]               = E(k, i);
                seen[first + i][dofs[k]] = 1;
              }
        }
    }

    /// Value and derivative of the field with layout coefficients @p c on
    /// cell @p cell (x in the closed cell), by evaluate().
    std::pair<double, double>
    field(const Vector<double> &c,
          const unsigned int    cell,
          const double          x) const
    {
      std::vector<double>                  values(p + 1);
      std::vector<Tensor<1, 1>>            gradients(p + 1);
      std::vector<types::global_dof_index> dofs(p + 1);
      space.evaluate(cell, Point<1>(x), values.data(), gradients.data());
      DoFHandler<1>::active_cell_iterator(&tria, 0, cell, &dof_handler)
        ->get_dof_indices(dofs);
      std::pair<double, double> r(0, 0);
      for (unsigned int k = 0; k <= p; ++k)
        {
          r.first += c[dofs[k]] * values[k];
          r.second += c[dofs[k]] * gradients[k][0];
        }
      return r;
    }

    /// Derivatives 0, ..., p - 1 at vertex @p x of the field with layout
    /// coefficients @p c on cell @p cell, from its Bezier coefficients
    /// (FE_Q order: vertex 0, vertex 1, interior from vertex 0): the k-th
    /// derivative at t = 0 is p!/(p-k)! / L^k times the k-th forward
    /// difference of the Bernstein coefficients, L = x_1 - x_0 (signed).
    std::vector<double>
    derivatives(const Vector<double> &c,
                const unsigned int    cell,
                const double          x) const
    {
      const auto it =
        DoFHandler<1>::active_cell_iterator(&tria, 0, cell, &dof_handler);
      std::vector<types::global_dof_index> dofs(p + 1);
      it->get_dof_indices(dofs);
      std::vector<double> b(p + 1);
      for (unsigned int j = 0; j <= p; ++j)
        b[j] = c[dofs[j == 0 ? 0 : (j == p ? 1 : j + 1)]];
      double L = it->vertex(1)[0] - it->vertex(0)[0];
      if (x == it->vertex(1)[0])
        {
          // Differentiate from vertex 1: reverse the coefficients.
          std::reverse(b.begin(), b.end());
          L = -L;
        }
      std::vector<double> d;
      double              factor = 1;
      for (unsigned int k = 0; k < p; ++k)
        {
          d.push_back(factor * b[0]);
          for (unsigned int j = 0; j + k < p; ++j)
            b[j] = b[j + 1] - b[j];
          factor *= (p - k) / L;
        }
      return d;
    }

    unsigned int
    cell_of(const double x) const
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (x >= std::min(cell->vertex(0)[0], cell->vertex(1)[0]) &&
            x <= std::max(cell->vertex(0)[0], cell->vertex(1)[0]))
          return cell->active_cell_index();
      return numbers::invalid_unsigned_int;
    }

    /// Knot span of x in the open knot vector.
    unsigned int
    span_of(const double x) const
    {
      unsigned int k = 0;
      while (k + 1 < n && x >= vertices[k + 1])
        ++k;
      return k + p;
    }

    /// Largest violation of the ties by the coefficients @p c, relative
    /// to their largest magnitude.
    double
    tie_violation(const Vector<double> &c) const
    {
      double worst = 0;
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        if (ties.is_constrained(i))
          {
            double v = ties.get_inhomogeneity(i);
            for (const auto &[j, w] : *ties.get_constraint_entries(i))
              v += w * c[j];
            worst = std::max(worst, std::abs(v - c[i]));
          }
      return worst / c.linfty_norm();
    }
  };

  /// Checks that hold on any mesh.
  void
  check_space(std::ofstream                   &out,
              const unsigned int               p,
              const std::vector<double>       &vertices,
              const std::vector<unsigned int> &order,
              const std::set<unsigned int>    &reversed)
  {
    SplineFunctions    f(p, vertices, order, reversed);
    const unsigned int n = vertices.size() - 1;
    out << "p = " << p << ", " << n << " cells: " << f.dof_handler.n_dofs()
        << " layout DoFs, " << f.ties.n_constraints() << " tied, "
        << f.free_functions.size() << " free" << std::endl;
    PSMPM_CHECK(out, f.dof_handler.n_dofs() == n * p + 1);
    PSMPM_CHECK(out, f.ties.n_constraints() == (n - 1) * (p - 1));
    PSMPM_CHECK(out, f.free_functions.size() == n + p);

    std::mt19937                           rng(7 + p);
    std::uniform_real_distribution<double> uniform(0, 1);
    const double a = vertices.front(), b = vertices.back();
    const auto   knots = open_knots(vertices, p);

    // The B-splines of the extraction operators: consistent, in the tied
    // space, Cox-de Boor's, a non-negative partition of unity.
    double in_space = 0;
    for (const auto &c : f.bsplines)
      in_space = std::max(in_space, f.tie_violation(c));
    PSMPM_CHECK(out, f.extraction_mismatch < 1e-14);
    PSMPM_CHECK(out, in_space < 1e-13);
    double difference = 0, unity = 0, lowest = 1;
    for (unsigned int q = 0; q < 500; ++q)
      {
        const double       x    = a + (b - a) * uniform(rng);
        const unsigned int cell = f.cell_of(x), mu = f.span_of(x);
        const auto         expected = cox_de_boor(knots, p, mu, x);
        double             sum      = 0;
        for (unsigned int i = 0; i < n + p; ++i)
          {
            const double v = f.field(f.bsplines[i], cell, x).first;
            const double e = i + p >= mu && i <= mu ? expected[i + p - mu] : 0.;
            difference     = std::max(difference, std::abs(v - e));
            sum += v;
            lowest = std::min(lowest, v);
          }
        unity = std::max(unity, std::abs(sum - 1));
      }
    out << "  B-splines against Cox-de Boor at 500 random points: "
        << (difference < 1e-13 ? "< 1e-13" : "LARGER")
        << ", partition of unity " << (unity < 1e-14 ? "< 1e-14" : "LARGER")
        << ", smallest value " << (lowest >= -1e-15 ? ">= 0" : "negative")
        << std::endl;
    PSMPM_CHECK(out, difference < 1e-13);
    PSMPM_CHECK(out, unity < 1e-14);
    PSMPM_CHECK(out, lowest >= -1e-15);

    // C^{p-1} at every interior vertex: derivatives 0, ..., p - 1 of
    // every free DoF's function from both cells (Bezier coefficients),
    // relative to their size; values and first derivatives by evaluate().
    std::vector<double> jump(p, 0.), scale(p, 0.);
    double              jump_value = 0, jump_derivative = 0, slope = 0;
    for (unsigned int v = 1; v < n; ++v)
      {
        const unsigned int left =
          f.cell_of(0.5 * (vertices[v - 1] + vertices[v]));
        const unsigned int right =
          f.cell_of(0.5 * (vertices[v] + vertices[v + 1]));
        for (const auto &c : f.free_functions)
          {
            const auto l = f.derivatives(c, left, vertices[v]);
            const auto r = f.derivatives(c, right, vertices[v]);
            for (unsigned int k = 0; k < p; ++k)
              {
                jump[k]  = std::max(jump[k], std::abs(l[k] - r[k]));
                scale[k] = std::max(scale[k], std::abs(l[k]));
              }
            const auto el = f.field(c, left, vertices[v]);
            const auto er = f.field(c, right, vertices[v]);
            jump_value    = std::max(jump_value, std::abs(el.first - er.first));
            jump_derivative =
              std::max(jump_derivative, std::abs(el.second - er.second));
            slope = std::max(slope, std::abs(el.second));
          }
      }
    double continuity = 0;
    for (unsigned int k = 0; k < p; ++k)
      if (scale[k] > 0)
        continuity = std::max(continuity, jump[k] / scale[k]);
    out << "  derivatives 0 to " << p - 1
        << " continuous across the interior vertices (relative jump "
        << (continuity < 1e-12 ? "< 1e-12" : "LARGER") << ")" << std::endl;
    PSMPM_CHECK(out, continuity < 1e-12);
    PSMPM_CHECK(out, n == 1 || slope > 1);
    // (p = 1 is C0 only: its first derivatives jump.)
    PSMPM_CHECK(out,
                jump_value < 1e-13 &&
                  (p == 1 || jump_derivative < 1e-12 * slope));

    // A polynomial of degree p from its blossom at the knots (B-spline
    // coefficients), and its Bezier coefficients (blossom at the cell's
    // ends) satisfy the ties.
    Vector<double> reproduced(f.dof_handler.n_dofs()), linear(reproduced),
      bezier(reproduced);
    for (unsigned int i = 0; i < n + p; ++i)
      reproduced.add(blossom(std::vector<double>(knots.begin() + i + 1,
                                                 knots.begin() + i + p + 1)),
                     f.bsplines[i]);
    std::vector<types::global_dof_index> dofs(p + 1);
    for (const auto &cell : f.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        const double x0 = cell->vertex(0)[0], x1 = cell->vertex(1)[0];
        for (unsigned int j = 0; j <= p; ++j)
          {
            std::vector<double> u(p - j, x0);
            u.insert(u.end(), j, x1);
            bezier[dofs[j == 0 ? 0 : (j == p ? 1 : j + 1)]] = blossom(u);
          }
      }
    for (unsigned int i = 0; i < f.dof_handler.n_dofs(); ++i)
      linear[i] = f.control[i][0];
    double error = 0, error_d = 0, error_x = 0;
    for (unsigned int q = 0; q < 200; ++q)
      {
        const double       x     = a + (b - a) * uniform(rng);
        const unsigned int cell  = f.cell_of(x);
        const auto         exact = polynomial(p, x);
        const auto         g     = f.field(reproduced, cell, x);
        error   = std::max(error, std::abs(g.first - exact.first));
        error_d = std::max(error_d, std::abs(g.second - exact.second));
        error_x =
          std::max(error_x, std::abs(f.field(linear, cell, x).first - x));
      }
    PSMPM_CHECK(out, error < 1e-13 && error_d < 1e-12);
    PSMPM_CHECK(out, f.tie_violation(bezier) < 1e-13);
    // x from the control points, which satisfy the ties (APIC's affine
    // fields are then exact).
    PSMPM_CHECK(out, error_x < 1e-14);
    PSMPM_CHECK(out, f.tie_violation(linear) < 1e-14);

    // Dirichlet at both ends fixes exactly the two end vertex DoFs, which
    // are free.
    AffineConstraints<double> dirichlet;
    f.space.make_dirichlet_constraints(f.dof_handler,
                                       {0, 1},
                                       Functions::ZeroFunction<1>(),
                                       dirichlet);
    dirichlet.close();
    std::vector<types::global_dof_index> fixed;
    for (unsigned int i = 0; i < f.dof_handler.n_dofs(); ++i)
      if (dirichlet.is_constrained(i))
        fixed.push_back(i);
    PSMPM_CHECK(out,
                fixed.size() == 2 &&
                  std::min(f.control[fixed[0]][0], f.control[fixed[1]][0]) ==
                    a &&
                  std::max(f.control[fixed[0]][0], f.control[fixed[1]][0]) ==
                    b);
    PSMPM_CHECK(out,
                !f.ties.is_constrained(fixed[0]) &&
                  !f.ties.is_constrained(fixed[1]));

    // Integrals of the free DoFs' functions (the lumped masses of a unit
    // density): positive for p <= 2, where they are the B-splines; for
    // p >= 3 the function of the first cell's interior DoF next to the
    // left end is B_1 - B_2 (uniform mesh: integral h/2 - 3h/4 < 0),
    // which is why lumped mass is refused there.
    unsigned int negative = 0;
    for (const auto &c : f.free_functions)
      {
        double integral = 0;
        for (const auto &cell : f.dof_handler.active_cell_iterators())
          {
            const auto quadrature =
              f.space.cell_quadrature(f.dof_handler, cell->active_cell_index());
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              integral +=
                quadrature.weight(q) *
                f.field(c, cell->active_cell_index(), quadrature.point(q)[0])
                  .first;
          }
        if (integral < 0)
          ++negative;
      }
    out << "  free DoFs' functions with a negative integral: " << negative
        << std::endl;
    PSMPM_CHECK(out, (p <= 2) == (negative == 0));

    // p <= 2: the free DoFs' functions are the B-splines, in the order of
    // their control points (the Greville abscissae).
    if (p <= 2)
      {
        double basis = 0;
        for (unsigned int i = 0; i < n + p; ++i)
          {
            Vector<double> d = f.free_functions[i];
            d -= f.bsplines[i];
            basis = std::max(basis, d.linfty_norm());
          }
        out << "  free DoFs carry the B-splines" << std::endl;
        PSMPM_CHECK(out, basis < 1e-14);
      }
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;

    const unsigned int  n = 5;
    std::vector<double> uniform_vertices;
    for (unsigned int v = 0; v <= n; ++v)
      uniform_vertices.push_back(double(v) / n);
    const std::vector<double> vertices     = {0, 0.3, 0.45, 1.1, 1.2, 1.7, 2};
    const std::vector<double> two_vertices = {0, 0.4, 1};

    for (unsigned int p = 1; p <= Basis::BSpline::max_degree; ++p)
      {
        // Uniform mesh of [0, 1]: the B-splines are also BSpline1D's.
        check_space(out, p, uniform_vertices, {0, 1, 2, 3, 4}, {});
        {
          SplineFunctions        f(p, uniform_vertices, {0, 1, 2, 3, 4}, {});
          const Basis::BSpline1D reference(p, n);
          std::mt19937           rng(11);
          std::uniform_real_distribution<double> uniform(0, 1);
          std::vector<double>                    values(p + 1);
          double                                 difference = 0;
          for (unsigned int q = 0; q < 500; ++q)
            {
              const double       x       = uniform(rng);
              const unsigned int element = std::min(n - 1, unsigned(x * n));
              reference.values(element, x, values.data());
              for (unsigned int i = 0; i < n + p; ++i)
                {
                  const double expected =
                    i >= element && i <= element + p ? values[i - element] : 0.;
                  difference =
                    std::max(difference,
                             std::abs(f.field(f.bsplines[i], element, x).first -
                                      expected));
                }
            }
          out << "  against Basis::BSpline1D at 500 random points: "
              << (difference < 1e-13 ? "< 1e-13" : "LARGER") << std::endl;
          PSMPM_CHECK(out, difference < 1e-13);
        }
        // Non-uniform mesh of [0, 2], cells shuffled, two reversed.
        check_space(out, p, vertices, {3, 0, 5, 1, 4, 2}, {1, 4});
        // Two cells (p >= 3: one block and the end of the last cell).
        check_space(out, p, two_vertices, {0, 1}, {});
      }

    // Basis/Degree: 1 to 5.
    Basis::BSpline space;
    bool           refused = false;
    try
      {
        space.set_degree(6);
      }
    catch (const std::exception &e)
      {
        refused =
          std::string(e.what()).find("Basis/Degree = 6") != std::string::npos;
      }
    PSMPM_CHECK(out, refused);
    for (unsigned int p = 1; p <= Basis::BSpline::max_degree; ++p)
      {
        space.set_degree(p);
        out << "p = " << p << ": stability factor lumped "
            << space.stability_factor(true) << ", consistent "
            << space.stability_factor(false) << "; verified mass matrices";
        for (const auto &m : space.verified_mass_matrices())
          out << ' ' << m;
        out << std::endl;
      }
  });
}
