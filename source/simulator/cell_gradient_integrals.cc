// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <psmpm/simulator/cell_gradient_integrals.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /// The face points of @p cell with their weights times the outward
      /// normal (length: the face's measure times the weight).
      template <int dim>
      void
      face_points(const typename Triangulation<dim>::active_cell_iterator &cell,
                  const Quadrature<1>                                     &q,
                  std::vector<Point<dim>>     &points,
                  std::vector<Tensor<1, dim>> &weighted_normals)
      {
        points.clear();
        weighted_normals.clear();
        if constexpr (dim == 1)
          {
            // The faces are the end points; vertex 0 is the left one.
            for (unsigned int f = 0; f < 2; ++f)
              {
                const double sign = cell->vertex(1)[0] > cell->vertex(0)[0] ?
                                      (f == 0 ? -1. : 1.) :
                                      (f == 0 ? 1. : -1.);
                points.push_back(cell->vertex(f));
                weighted_normals.push_back(Tensor<1, dim>({sign}));
              }
          }
        else
          {
            const Point<dim> centre = cell->center();
            for (unsigned int f = 0; f < cell->n_faces(); ++f)
              {
                const Point<dim> a = cell->face(f)->vertex(0),
                                 b = cell->face(f)->vertex(1);
                // The edge turned by -90 degrees has the edge's length;
                // it points out of the (convex) cell.
                Tensor<1, dim> normal({b[1] - a[1], a[0] - b[0]});
                if (normal * (a - centre) < 0)
                  normal = -normal;
                for (unsigned int i = 0; i < q.size(); ++i)
                  {
                    points.push_back(a + q.point(i)[0] * (b - a));
                    weighted_normals.push_back(q.weight(i) * normal);
                  }
              }
          }
      }
    } // namespace

    template <int dim>
    void
    CellGradientIntegrals<dim>::reinit(const Triangulation<dim> &triangulation,
                                       const Basis::Space<dim>  &space)
    {
      n = space.dofs_per_cell();
      values.assign(std::size_t(triangulation.n_active_cells()) * n,
                    Tensor<1, dim>());
      measures.assign(triangulation.n_active_cells(), 0.);
      const QIterated<1>          q(QGauss<1>(3), 4);
      std::vector<Point<dim>>     points;
      std::vector<Tensor<1, dim>> normals;
      std::vector<unsigned int>   cells;
      std::vector<double>         basis;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const unsigned int c = cell->active_cell_index();
          face_points<dim>(cell, q, points, normals);
          cells.assign(points.size(), c);
          basis.resize(points.size() * n);
          space.evaluate(points.size(),
                         cells.data(),
                         points.data(),
                         basis.data(),
                         nullptr);
          Tensor<1, dim> *G = &values[std::size_t(c) * n];
          for (unsigned int i = 0; i < points.size(); ++i)
            {
              measures[c] += (points[i] * normals[i]) / dim;
              for (unsigned int k = 0; k < n; ++k)
                G[k] += basis[i * n + k] * normals[i];
            }
        }
    }

    template class CellGradientIntegrals<1>;
    template class CellGradientIntegrals<2>;
  } // namespace Simulator
} // namespace psmpm
