// P1 functions on criss-cross and diagonal meshes: partition of unity,
// zero gradient sum, nodal interpolation property in deal.II's local
// DoF order, and exact reproduction of a linear function.
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/linear.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

#include <random>

using namespace psmpm;

int
main()
{
  std::ofstream out("output");
  for (const auto type : {Mesh::MeshGenerator<2>::Type::criss_cross,
                          Mesh::MeshGenerator<2>::Type::diagonal})
    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::make_blocks(tria,
                                          Point<2>(0, 0),
                                          Point<2>(3, 2),
                                          3,
                                          2,
                                          type);
      Basis::Linear<2> space;
      DoFHandler<2>    dof_handler(tria);
      dof_handler.distribute_dofs(space.dof_layout());
      space.reinit(dof_handler);

      std::mt19937                           rng(1);
      std::uniform_real_distribution<double> u(0, 1);
      double       pu = 0, gsum = 0, nodal = 0, linear = 0;
      bool         order = true;
      double       values[3];
      Tensor<1, 2> grads[3];
      std::vector<types::global_dof_index> dofs(3);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < 20; ++i)
            {
              double a = u(rng), b = u(rng);
              if (a + b > 1)
                a = 1 - a, b = 1 - b;
              const Point<2> p = cell->vertex(0) +
                                 a * (cell->vertex(1) - cell->vertex(0)) +
                                 b * (cell->vertex(2) - cell->vertex(0));
              space.evaluate(c, p, values, grads);
              pu =
                std::max(pu, std::abs(values[0] + values[1] + values[2] - 1));
              gsum = std::max(gsum, (grads[0] + grads[1] + grads[2]).norm());
              double f = 0;
              for (unsigned int k = 0; k < 3; ++k)
                f +=
                  values[k] * (2 + 3 * cell->vertex(k)[0] - cell->vertex(k)[1]);
              linear = std::max(linear, std::abs(f - (2 + 3 * p[0] - p[1])));
            }
          // Local function k is the DoF of vertex k: value 1 there.
          for (unsigned int k = 0; k < 3; ++k)
            {
              order = order && dofs[k] == cell->vertex_dof_index(k, 0);
              space.evaluate(c, cell->vertex(k), values, nullptr);
              for (unsigned int l = 0; l < 3; ++l)
                nodal =
                  std::max(nodal, std::abs(values[l] - (k == l ? 1. : 0.)));
            }
        }
      PSMPM_CHECK(out, pu < 1e-12);
      PSMPM_CHECK(out, gsum < 1e-12);
      PSMPM_CHECK(out, nodal < 1e-12);
      PSMPM_CHECK(out, linear < 1e-12);
      PSMPM_CHECK(out, order);
    }
}
