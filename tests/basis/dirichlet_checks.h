// ---------------------------------------------------------------------
// psmpm: evaluate a spline with constrained coefficients on boundary edges.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_basis_dirichlet_checks_h
#define psmpm_tests_basis_dirichlet_checks_h

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/space.h>

#include <algorithm>
#include <set>

namespace dirichlet_checks
{
  using namespace dealii;

  /// Coefficients: deterministic "random" values, then the constraints.
  inline Vector<double>
  constrained_coefficients(const DoFHandler<2>             &dof_handler,
                           const AffineConstraints<double> &constraints)
  {
    Vector<double> c(dof_handler.n_dofs());
    for (unsigned int i = 0; i < c.size(); ++i)
      c(i) = std::sin(1.3 * i + 0.7);
    constraints.distribute(c);
    return c;
  }

  /**
   * Largest |u - g| and |d(u - g)/dt| * h over points of the boundary edges
   * with the given ids (h = edge length, to compare derivatives with
   * values).
   */
  inline std::pair<double, double>
  boundary_deviation(const psmpm::Basis::Space<2>       &space,
                     const DoFHandler<2>                &dof_handler,
                     const Vector<double>               &c,
                     const std::set<types::boundary_id> &ids,
                     const Function<2>                  &g)
  {
    const unsigned int                   n = space.dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  values(n);
    std::vector<Tensor<1, 2>>            gradients(n);
    double                               value = 0, derivative = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->at_boundary(f) && ids.count(cell->face(f)->boundary_id()))
          {
            cell->get_dof_indices(dofs);
            const Point<2>     A = cell->face(f)->vertex(0);
            const Point<2>     B = cell->face(f)->vertex(1);
            const Tensor<1, 2> t = (B - A) / A.distance(B);
            for (unsigned int j = 0; j <= 12; ++j)
              {
                const Point<2> p = A + (j / 12.) * (B - A);
                space.evaluate(cell->active_cell_index(),
                               p,
                               values.data(),
                               gradients.data());
                double       u = 0;
                Tensor<1, 2> gu;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    u += c(dofs[i]) * values[i];
                    gu += c(dofs[i]) * gradients[i];
                  }
                value = std::max(value, std::abs(u - g.value(p)));
                derivative =
                  std::max(derivative,
                           std::abs((gu - g.gradient(p)) * t) * A.distance(B));
              }
          }
    return {value, derivative};
  }

  /// Constraint lines that have entries (i.e. are not "c = value").
  inline unsigned int
  n_lines_with_entries(const AffineConstraints<double> &constraints)
  {
    unsigned int n = 0;
    for (const auto &line : constraints.get_lines())
      n += !line.entries.empty();
    return n;
  }
} // namespace dirichlet_checks

#endif
