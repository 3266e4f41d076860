// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/basis/linear.h>
#include <psmpm/mesh/triangle_geometry.h>

namespace psmpm
{
  namespace Basis
  {
    Linear::Linear()
      : fe(1)
    {
    }

    std::string
    Linear::name() const
    {
      return "linear";
    }

    const FiniteElement<2> &
    Linear::dof_layout() const
    {
      return fe;
    }

    void
    Linear::reinit(const DoFHandler<2> &dof_handler)
    {
      const auto &tria = dof_handler.get_triangulation();
      cell_data.resize(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        {
          const auto bary = Mesh::barycentric_map(
            {{cell->vertex(0), cell->vertex(1), cell->vertex(2)}});
          CellData &d = cell_data[cell->active_cell_index()];
          for (unsigned int k = 0; k < 3; ++k)
            {
              d.constant[k] = bary.constant[k];
              d.gradient[k] = bary.gradient[k];
            }
        }
    }

    void
    Linear::evaluate(const unsigned int cell,
                     const Point<2>    &p,
                     double            *values,
                     Tensor<1, 2>      *gradients) const
    {
      const CellData &d = cell_data[cell];
      for (unsigned int k = 0; k < 3; ++k)
        {
          values[k] =
            d.constant[k] + d.gradient[k][0] * p[0] + d.gradient[k][1] * p[1];
          if (gradients != nullptr)
            gradients[k] = d.gradient[k];
        }
    }

    void
    Linear::evaluate(const unsigned int  n,
                     const unsigned int *cells,
                     const Point<2>     *points,
                     double             *values,
                     Tensor<1, 2>       *gradients) const
    {
      for (unsigned int i = 0; i < n; ++i)
        Linear::evaluate(cells[i],
                         points[i],
                         values + 3 * i,
                         gradients != nullptr ? gradients + 3 * i : nullptr);
    }

    void
    Linear::make_dirichlet_constraints(
      const DoFHandler<2>                &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<2>                  &g,
      AffineConstraints<double>          &constraints) const
    {
      std::vector<types::global_dof_index> dofs(3);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                ids.count(cell->face(f)->boundary_id()) > 0)
              for (const auto v : cell->face(f)->vertex_indices())
                for (unsigned int k = 0; k < 3; ++k)
                  if (cell->vertex_index(k) == cell->face(f)->vertex_index(v))
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
  } // namespace Basis
} // namespace psmpm
