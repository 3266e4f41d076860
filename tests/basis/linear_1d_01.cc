// ---------------------------------------------------------------------
// psmpm: the 1D linear space (hat functions) on a non-uniform mesh of
// [0, 2]: DoF layout, partition of unity, non-negativity, nodal property,
// gradients +-1/h, batch evaluation, Dirichlet constraints on the left
// (id 0), the right (id 1) and both ends, reproduction of x through the
// control points, the cell quadrature, and the 1D stability factors.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/linear.h>

#include "../tests.h"

#include <algorithm>
#include <vector>

namespace
{
  /// g(x) = 3 + x, to tell the two ends apart in the inhomogeneities.
  class Affine : public Function<1>
  {
  public:
    double
    value(const Point<1> &p, const unsigned int = 0) const override
    {
      return 3 + p[0];
    }
  };
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;

    // Five cells of different lengths: uniform meshes would hide a
    // mix-up of h between neighbouring cells.
    Triangulation<1> tria;
    GridGenerator::subdivided_hyper_cube(tria, 5, 0, 2);
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int k = 0; k < 2; ++k)
        {
          Point<1> &p = cell->vertex(k);
          if (p[0] > 1e-12 && p[0] < 2 - 1e-12)
            p[0] += 0.1 * std::sin(7. * p[0]);
        }

    Basis::Linear<1> space;
    DoFHandler<1>    dof_handler(tria);
    dof_handler.distribute_dofs(space.dof_layout());
    space.reinit(dof_handler);
    out << "cells " << tria.n_active_cells() << ", dofs "
        << dof_handler.n_dofs() << ", dofs per cell " << space.dofs_per_cell()
        << ", per vertex " << space.dofs_per_vertex() << std::endl;
    PSMPM_CHECK(out, space.name() == "linear");
    PSMPM_CHECK(out, dof_handler.n_dofs() == tria.n_vertices());

    const auto X  = space.control_points(dof_handler);
    double     pu = 0, gsum = 0, min_value = 1e300, nodal = 0, slope = 0,
           reproduction = 0, batch = 0;
    bool                                 layout = true, control = true;
    std::vector<types::global_dof_index> dofs(2);
    std::vector<unsigned int>            cells;
    std::vector<Point<1>>                points;
    std::vector<double>                  single_values;
    std::vector<Tensor<1, 1>>            single_gradients;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        cell->get_dof_indices(dofs);
        const double h = cell->vertex(1)[0] - cell->vertex(0)[0];
        for (unsigned int k = 0; k < 2; ++k)
          {
            layout  = layout && dofs[k] == cell->vertex_dof_index(k, 0);
            control = control && X[dofs[k]] == cell->vertex(k);
          }
        for (unsigned int j = 0; j <= 8; ++j)
          {
            const Point<1> p(cell->vertex(0)[0] + (j / 8.) * h);
            double         values[2];
            Tensor<1, 1>   gradients[2];
            space.evaluate(c, p, values, gradients);
            pu = std::max(pu, std::abs(values[0] + values[1] - 1));
            gsum =
              std::max(gsum, std::abs(gradients[0][0] + gradients[1][0]) * h);
            min_value = std::min({min_value, values[0], values[1]});
            // The hat of the left vertex falls with slope -1/h.
            slope = std::max({slope,
                              std::abs(gradients[0][0] * h + 1),
                              std::abs(gradients[1][0] * h - 1)});
            // sum_i X_i N_i(x) = x and sum_i X_i N_i'(x) = 1.
            double x = 0, dx = 0;
            for (unsigned int k = 0; k < 2; ++k)
              {
                x += X[dofs[k]][0] * values[k];
                dx += X[dofs[k]][0] * gradients[k][0];
              }
            reproduction =
              std::max({reproduction, std::abs(x - p[0]), std::abs(dx - 1)});
            cells.push_back(c);
            points.push_back(p);
            single_values.insert(single_values.end(), values, values + 2);
            single_gradients.insert(single_gradients.end(),
                                    gradients,
                                    gradients + 2);
          }
        for (unsigned int k = 0; k < 2; ++k)
          {
            double values[2];
            space.evaluate(c, cell->vertex(k), values, nullptr);
            for (unsigned int l = 0; l < 2; ++l)
              nodal = std::max(nodal, std::abs(values[l] - (k == l)));
          }
      }
    std::vector<double>       values(2 * cells.size());
    std::vector<Tensor<1, 1>> gradients(2 * cells.size());
    space.evaluate(cells.size(),
                   cells.data(),
                   points.data(),
                   values.data(),
                   gradients.data());
    for (unsigned int i = 0; i < values.size(); ++i)
      batch = std::max({batch,
                        std::abs(values[i] - single_values[i]),
                        std::abs(gradients[i][0] - single_gradients[i][0])});
    PSMPM_CHECK(out, layout);
    PSMPM_CHECK(out, control);
    PSMPM_CHECK(out, pu < 1e-14);
    PSMPM_CHECK(out, gsum < 1e-13);
    PSMPM_CHECK(out, min_value > -1e-15);
    PSMPM_CHECK(out, nodal < 1e-14);
    PSMPM_CHECK(out, slope < 1e-13);
    PSMPM_CHECK(out, reproduction < 1e-14);
    PSMPM_CHECK(out, batch == 0);

    // Dirichlet: GridGenerator gives the left end id 0 and the right end
    // id 1 in 1D. The constrained DoF must be the one at that end, with
    // g evaluated there.
    const Affine g;
    for (const auto &ids :
         std::vector<std::set<types::boundary_id>>{{0}, {1}, {0, 1}})
      {
        AffineConstraints<double> constraints;
        space.make_dirichlet_constraints(dof_handler, ids, g, constraints);
        constraints.close();
        out << "ids {";
        for (const auto id : ids)
          out << ' ' << id;
        out << " }: " << constraints.n_constraints() << " constrained:";
        for (const auto &line : constraints.get_lines())
          out << " x = " << X[line.index][0] << " -> " << line.inhomogeneity
              << (line.entries.empty() ? "" : " (with entries)");
        out << std::endl;
        bool right_dofs = constraints.n_constraints() == ids.size();
        for (const auto &line : constraints.get_lines())
          right_dofs =
            right_dofs && line.entries.empty() &&
            ((X[line.index][0] == 0 && ids.count(0)) ||
             (X[line.index][0] == 2 && ids.count(1))) &&
            std::abs(line.inhomogeneity - g.value(X[line.index])) < 1e-15;
        PSMPM_CHECK(out, right_dofs);
      }

    // Cell quadrature: weights add up to the length, and a degree-5
    // polynomial is integrated exactly (products need degree 2).
    double length_error = 0, polynomial_error = 0;
    bool   inside = true;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const auto q =
          space.cell_quadrature(dof_handler, cell->active_cell_index());
        const double a = cell->vertex(0)[0], b = cell->vertex(1)[0];
        double       sum = 0, integral = 0;
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            sum += q.weight(i);
            integral += q.weight(i) * std::pow(q.point(i)[0], 5);
            inside = inside && q.point(i)[0] > a && q.point(i)[0] < b;
          }
        length_error = std::max(length_error, std::abs(sum - (b - a)));
        polynomial_error =
          std::max(polynomial_error,
                   std::abs(integral - (std::pow(b, 6) - std::pow(a, 6)) / 6));
      }
    PSMPM_CHECK(out, inside);
    PSMPM_CHECK(out, length_error < 1e-15);
    PSMPM_CHECK(out, polynomial_error < 1e-13);

    const auto W = space.extrapolation_weights(0, 1);
    PSMPM_CHECK(out, W.m() == 1 && W.n() == 1 && W(0, 0) == 1);
    out << "stability factor: lumped " << space.stability_factor(true)
        << ", consistent " << space.stability_factor(false) << std::endl;
    PSMPM_CHECK(out, space.stability_factor(false) < 1 / std::sqrt(3.));
  });
}
