// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <psmpm/basis/linear.h>
#include <psmpm/mesh/triangle_geometry.h>

#include <cmath>

namespace psmpm
{
  namespace Basis
  {
    template <int dim>
    Linear<dim>::Linear()
      : fe(1)
    {
    }

    template <int dim>
    std::string
    Linear<dim>::name() const
    {
      return "linear";
    }

    template <int dim>
    const FiniteElement<dim> &
    Linear<dim>::dof_layout() const
    {
      return fe;
    }

    template <int dim>
    void
    Linear<dim>::reinit(const DoFHandler<dim> &dof_handler)
    {
      AssertThrow(dof_handler.get_fe().n_dofs_per_vertex() == 1 &&
                    dof_handler.get_fe().n_dofs_per_cell() == dim + 1,
                  ExcMessage("Linear::reinit: the DoFHandler must use the "
                             "space's dof_layout()."));
      const auto &tria = dof_handler.get_triangulation();
      cell_data.resize(tria.n_active_cells());
      cell_vertices.resize(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          CellData          &d     = cell_data[index];
          for (unsigned int k = 0; k <= dim; ++k)
            cell_vertices[index][k] = cell->vertex(k);
          if constexpr (dim == 1)
            {
              // lambda_0 = (b - x) / (b - a), lambda_1 = (x - a) / (b - a):
              // the signed length makes either vertex order right.
              const double a = cell->vertex(0)[0], b = cell->vertex(1)[0];
              const double length = b - a;
              AssertThrow(length != 0,
                          ExcMessage("Linear::reinit: cell " +
                                     std::to_string(index) +
                                     " has zero length."));
              d.constant[0]    = b / length;
              d.gradient[0][0] = -1 / length;
              d.constant[1]    = -a / length;
              d.gradient[1][0] = 1 / length;
            }
          else
            {
              // The same closed form as everywhere else in 2D, so that
              // results do not depend on which code evaluated them.
              const auto bary = Mesh::barycentric_map(
                {{cell->vertex(0), cell->vertex(1), cell->vertex(2)}});
              for (unsigned int k = 0; k < 3; ++k)
                {
                  d.constant[k] = bary.constant[k];
                  d.gradient[k] = bary.gradient[k];
                }
            }
        }
    }

    namespace
    {
      /// One point: values c_k + g_k . x and the constant gradients g_k.
      /// A function of this file, so that the batch loop inlines it: the
      /// exported one-point evaluate() is reached through the PLT even
      /// from its own file (-fPIC code lets another library interpose an
      /// exported function), which was a call per particle.
      template <int dim, typename CellData>
      inline void
      evaluate_at(const CellData   &d,
                  const Point<dim> &p,
                  double           *values,
                  Tensor<1, dim>   *gradients)
      {
        for (unsigned int k = 0; k <= dim; ++k)
          {
            // Summed left to right: in 2D the same operations as
            // c + g_x x + g_y y, so the values are bit-identical to the
            // earlier 2D-only implementation.
            double v = d.constant[k];
            for (unsigned int c = 0; c < dim; ++c)
              v += d.gradient[k][c] * p[c];
            values[k] = v;
            if (gradients != nullptr)
              gradients[k] = d.gradient[k];
          }
      }
    } // namespace

    template <int dim>
    void
    Linear<dim>::evaluate(const unsigned int cell,
                          const Point<dim>  &p,
                          double            *values,
                          Tensor<1, dim>    *gradients) const
    {
      AssertIndexRange(cell, cell_data.size());
      evaluate_at(cell_data[cell], p, values, gradients);
    }

    template <int dim>
    void
    Linear<dim>::evaluate(const unsigned int  n,
                          const unsigned int *cells,
                          const Point<dim>   *points,
                          double             *values,
                          Tensor<1, dim>     *gradients) const
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          AssertIndexRange(cells[i], cell_data.size());
          evaluate_at(cell_data[cells[i]],
                      points[i],
                      values + (dim + 1) * i,
                      gradients != nullptr ? gradients + (dim + 1) * i :
                                             nullptr);
        }
    }

    template <int dim>
    void
    Linear<dim>::make_dirichlet_constraints(
      const DoFHandler<dim>              &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<dim>                &g,
      AffineConstraints<double>          &constraints) const
    {
      std::vector<types::global_dof_index> dofs(dim + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          for (const auto f : cell->face_indices())
            {
              const auto face = cell->face(f);
              // (Mesh::rim_boundary_id, the outer faces of a distributed
              // mesh's ghost layer, is never among the fixed ids.)
              if (!face->at_boundary() || ids.count(face->boundary_id()) == 0)
                continue;
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
                for (unsigned int k = 0; k <= dim; ++k)
                  if (cell->vertex_index(k) == face->vertex_index(v))
                    {
                      const auto dof = dofs[k];
                      if (constraints.can_store_line(dof) &&
                          !constraints.is_constrained(dof))
                        {
                          constraints.add_line(dof);
                          constraints.set_inhomogeneity(dof,
                                                        g.value(
                                                          cell->vertex(k)));
                        }
                    }
            }
        }
    }

    template <int dim>
    std::vector<Point<dim>>
    Linear<dim>::control_points(const DoFHandler<dim> &dof_handler) const
    {
      std::vector<Point<dim>>              points(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(dim + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k <= dim; ++k)
              points[dofs[k]] = cell->vertex(k);
          }
      return points;
    }

    template <int dim>
    FullMatrix<double>
    Linear<dim>::extrapolation_weights(const unsigned int,
                                       const unsigned int) const
    {
      // A linear field restricted to one hat function's vertex is just its
      // value there, which the extrapolated coefficient takes over.
      FullMatrix<double> W(1, 1);
      W(0, 0) = 1;
      return W;
    }

    template <int dim>
    Quadrature<dim>
    Linear<dim>::cell_quadrature(const DoFHandler<dim> &dof_handler,
                                 const unsigned int     cell) const
    {
      AssertThrow(cell < cell_vertices.size() &&
                    cell_vertices.size() ==
                      dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("Linear::cell_quadrature: call reinit() with "
                             "this mesh first."));
      // Reference vertex k of the unit simplex (origin, then the unit
      // vectors) is cell->vertex(k), as for deal.II's simplex mappings.
      const auto    &v = cell_vertices[cell];
      Tensor<2, dim> jacobian;
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int r = 0; r < dim; ++r)
          jacobian[r][c] = v[c + 1][r] - v[0][r];
      const double det = std::abs(determinant(jacobian));

      // Built once: constructing the rule cost more than mapping it (per
      // cell of every ghost-penalty patch at set-up, per cell and step of
      // the Taylor least squares reconstruction).
      static const QGaussSimplex<dim> reference(3);
      std::vector<Point<dim>>         points(reference.size());
      std::vector<double>             weights(reference.size());
      for (unsigned int q = 0; q < reference.size(); ++q)
        {
          points[q]  = v[0] + jacobian * reference.point(q);
          weights[q] = det * reference.weight(q);
        }
      return Quadrature<dim>(points, weights);
    }

    template <int dim>
    double
    Linear<dim>::stability_factor(const bool lumped) const
    {
      if constexpr (dim == 1)
        // Analytic: the highest frequency of the chain of linear elements
        // gives dt <= h / c lumped and h / (sqrt(3) c) = 0.577 h / c
        // consistent; rounded down.
        return lumped ? 1.0 : 0.57;
      else
        // Measured by bisection on the vibrating bar with criss-cross
        // blocks (contrib/studies/stability/stability_study.py: 1.58 lumped, 0.64
        // consistent), rounded down; doc/stability.md. With a mass matrix
        // and cells that empty, the limit is lower: the cantilever of
        // prm/cantilever.prm on 2 blocks through the depth (partially
        // lumped, MUSL) grows unstable at 0.3 h / c and completes at 0.21
        // (3 blocks: completes at 0.15), so the factor is 0.3.
        return lumped ? 1.5 : 0.3;
    }

    template class Linear<1>;
    template class Linear<2>;

    namespace
    {
      template <int dim>
      std::unique_ptr<Space<dim>>
      make_linear()
      {
        return std::make_unique<Linear<dim>>();
      }

      const Registration<SpaceRegistry<1>> register_linear_1d(
        {"linear",
         "hat functions, one per vertex (FE_SimplexP(1) layout)",
         &make_linear<1>,
         nullptr});

      const Registration<SpaceRegistry<2>> register_linear_2d(
        {"linear",
         "P1 Lagrange functions on triangles, one per vertex, C0",
         &make_linear<2>,
         nullptr});
    } // namespace
  }   // namespace Basis
} // namespace psmpm
