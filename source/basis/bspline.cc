// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <psmpm/basis/bspline.h>

#include <cmath>

namespace psmpm
{
  namespace Basis
  {
    BSpline::BSpline()
      : fe(2)
    {
    }

    std::string
    BSpline::name() const
    {
      return "bspline";
    }

    void
    BSpline::set_degree(const unsigned int degree)
    {
      AssertThrow(degree == 2,
                  ExcMessage("Basis/Degree = " + std::to_string(degree) +
                             ": Basis/Type = bspline implements quadratic "
                             "C1 B-splines only (Basis/Degree = 2)."));
    }

    const FiniteElement<1> &
    BSpline::dof_layout() const
    {
      return fe;
    }

    void
    BSpline::reinit(const DoFHandler<1> &dof_handler)
    {
      AssertThrow(dof_handler.get_fe().n_dofs_per_vertex() == 1 &&
                    dof_handler.get_fe().n_dofs_per_cell() == 3,
                  ExcMessage("BSpline::reinit: the DoFHandler must use the "
                             "space's dof_layout()."));
      const auto &tria = dof_handler.get_triangulation();
      cell_data.resize(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        {
          const double a = cell->vertex(0)[0], b = cell->vertex(1)[0];
          AssertThrow(b != a,
                      ExcMessage("BSpline::reinit: cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 " has zero length."));
          cell_data[cell->active_cell_index()] = {a, 1 / (b - a)};
        }
    }

    void
    BSpline::evaluate(const unsigned int cell,
                      const Point<1>    &p,
                      double            *values,
                      Tensor<1, 1>      *gradients) const
    {
      AssertIndexRange(cell, cell_data.size());
      const CellData &d = cell_data[cell];
      const double    t = (p[0] - d.origin) * d.inverse_length;
      const double    s = 1 - t;
      values[0]         = s * s;
      values[1]         = t * t;
      values[2]         = 2 * t * s;
      if (gradients != nullptr)
        {
          gradients[0][0] = -2 * s * d.inverse_length;
          gradients[1][0] = 2 * t * d.inverse_length;
          gradients[2][0] = 2 * (s - t) * d.inverse_length;
        }
    }

    void
    BSpline::evaluate(const unsigned int  n,
                      const unsigned int *cells,
                      const Point<1>     *points,
                      double             *values,
                      Tensor<1, 1>       *gradients) const
    {
      // Qualified call: no virtual dispatch per point.
      for (unsigned int i = 0; i < n; ++i)
        BSpline::evaluate(cells[i],
                          points[i],
                          values + 3 * i,
                          gradients != nullptr ? gradients + 3 * i : nullptr);
    }

    void
    BSpline::make_space_constraints(
      const DoFHandler<1>       &dof_handler,
      AffineConstraints<double> &constraints) const
    {
      // The shared triangulation keeps every cell, so both neighbours of
      // a vertex and their cell DoFs are always at hand.
      std::vector<types::global_dof_index> dofs(3), neighbor_dofs(3);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (const unsigned int f : cell->face_indices())
            {
              if (cell->at_boundary(f))
                continue;
              // In 1D face f is vertex f; local DoF f is its vertex DoF.
              const auto vertex_dof = dofs[f];
              if (!constraints.can_store_line(vertex_dof) ||
                  constraints.is_constrained(vertex_dof))
                continue;
              const auto neighbor = cell->neighbor(f);
              neighbor->get_dof_indices(neighbor_dofs);
              const double h          = cell->measure(),
                           h_neighbor = neighbor->measure();
              // Equal one-sided derivatives of the two Bezier pieces:
              // (c_v - c_L) / h_L = (c_R - c_v) / h_R.
              constraints.add_line(vertex_dof);
              constraints.add_entry(vertex_dof,
                                    dofs[2],
                                    h_neighbor / (h + h_neighbor));
              constraints.add_entry(vertex_dof,
                                    neighbor_dofs[2],
                                    h / (h + h_neighbor));
            }
        }
    }

    void
    BSpline::make_dirichlet_constraints(
      const DoFHandler<1>                &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<1>                  &g,
      AffineConstraints<double>          &constraints) const
    {
      std::vector<types::global_dof_index> dofs(3);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f) &&
                ids.count(cell->face(f)->boundary_id()) != 0)
              {
                const auto dof = dofs[f];
                if (constraints.can_store_line(dof) &&
                    !constraints.is_constrained(dof))
                  {
                    constraints.add_line(dof);
                    constraints.set_inhomogeneity(dof,
                                                  g.value(cell->vertex(f)));
                  }
              }
        }
    }

    std::vector<Point<1>>
    BSpline::control_points(const DoFHandler<1> &dof_handler) const
    {
      std::vector<Point<1>>                points(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(3);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          points[dofs[0]] = cell->vertex(0);
          points[dofs[1]] = cell->vertex(1);
          points[dofs[2]] = cell->center();
        }
      return points;
    }

    FullMatrix<double>
    BSpline::extrapolation_weights(const unsigned int, const unsigned int) const
    {
      AssertThrow(false,
                  ExcMessage("Basis/Type = bspline has no extrapolation "
                             "weights (Mass matrix/Type = extrapolate is not "
                             "available with it)."));
      return FullMatrix<double>();
    }

    Quadrature<1>
    BSpline::cell_quadrature(const DoFHandler<1> &dof_handler,
                             const unsigned int   cell) const
    {
      AssertThrow(cell < cell_data.size() &&
                    cell_data.size() ==
                      dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("BSpline::cell_quadrature: call reinit() with "
                             "this mesh first."));
      const CellData       &d      = cell_data[cell];
      const double          length = 1 / d.inverse_length;
      const QGauss<1>       reference(3);
      std::vector<Point<1>> points(reference.size());
      std::vector<double>   weights(reference.size());
      for (unsigned int q = 0; q < reference.size(); ++q)
        {
          points[q]  = Point<1>(d.origin + length * reference.point(q)[0]);
          weights[q] = std::abs(length) * reference.weight(q);
        }
      return Quadrature<1>(points, weights);
    }

    double
    BSpline::stability_factor(const bool lumped) const
    {
      // Measured (contrib/chapter_bar_study.py --stability, doc/chapter.md):
      // bisection of the fixed step on the chapter's bar, 10 elements,
      // 2000 steps, stable = no monitor trips. Consistent: 0.528 (fixed
      // ends), 0.423 (free ends; the exact-mass eigenvalue bound 2 /
      // omega_max is 0.431). Lumped: 0.571 and 0.651, the energy monitor
      // tripping before the eigenvalue bound (0.862 free, 1.269 fixed), as
      // for P1 (0.632 against its analytic 1). Rounded down.
      return lumped ? 0.5 : 0.4;
    }

    std::string
    BSpline::default_mass_matrix(const bool) const
    {
      // Measured on the chapter's bar (doc/chapter.md): consistent mass
      // converges with rate 3 in displacement and 2 in stress; lumped
      // mass (the chapter's standard mapping) misplaces the coefficients
      // of the open-knot end functions by O(h), and its errors near the
      // ends converge with rates 1.5 and 0.5 only.
      return "consistent";
    }

    std::vector<std::string>
    BSpline::verified_mass_matrices() const
    {
      return {"lumped", "consistent"};
    }

    std::vector<std::string>
    BSpline::verified_transfers() const
    {
      return {"musl", "usl"};
    }

    namespace
    {
      std::unique_ptr<Space<1>>
      make_bspline()
      {
        return std::make_unique<BSpline>();
      }

      const Registration<SpaceRegistry<1>> register_bspline(
        {"bspline",
         "quadratic C1 B-splines on the open knot vector of the 1D mesh "
         "(BSMPM, Basis/Degree = 2), by Bezier extraction on the "
         "FE_Q(2) layout",
         &make_bspline,
         nullptr});
    } // namespace
  }   // namespace Basis
} // namespace psmpm
