// ---------------------------------------------------------------------
// psmpm: the P1 space through the same interface: partition of unity,
// zero gradient sum, non-negativity, linear reproduction with nodal
// coefficients, and homogeneous Dirichlet constraints, on a criss-cross
// mesh and the unstructured L-shape.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/linear.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"
#include "dirichlet_checks.h"

namespace
{
  void
  check(std::ostream &out, const Triangulation<2> &tria)
  {
    psmpm::Basis::Linear<2> p1;
    DoFHandler<2>           dof_handler(tria);
    dof_handler.distribute_dofs(p1.dof_layout());
    p1.reinit(dof_handler);
    out << "cells " << tria.n_active_cells() << ", dofs "
        << dof_handler.n_dofs() << std::endl;

    const auto f = [](const Point<2> &p) {
      return 0.3 - 1.7 * p[0] + 2.9 * p[1];
    };
    double pu = 0, gsum = 0, min_value = 1e300, linear = 0;
    std::vector<types::global_dof_index> dofs(3);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i <= 6; ++i)
          for (unsigned int j = 0; i + j <= 6; ++j)
            {
              const Point<2> p(cell->vertex(0) +
                               (i / 6.) * (cell->vertex(1) - cell->vertex(0)) +
                               (j / 6.) * (cell->vertex(2) - cell->vertex(0)));
              double         values[3];
              Tensor<1, 2>   gradients[3];
              p1.evaluate(cell->active_cell_index(), p, values, gradients);
              double       sum = 0, u = 0;
              Tensor<1, 2> gs;
              for (unsigned int k = 0; k < 3; ++k)
                {
                  sum += values[k];
                  gs += gradients[k];
                  min_value = std::min(min_value, values[k]);
                  // The dof of local function k is that of cell vertex k.
                  u += f(cell->vertex(k)) * values[k];
                }
              pu     = std::max(pu, std::abs(sum - 1));
              gsum   = std::max(gsum, gs.norm());
              linear = std::max(linear, std::abs(u - f(p)));
            }
      }
    PSMPM_CHECK(out, pu < 1e-12);
    PSMPM_CHECK(out, gsum < 1e-12);
    PSMPM_CHECK(out, min_value > -1e-14);
    PSMPM_CHECK(out, linear < 1e-12);

    std::set<types::boundary_id> ids;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        ids.insert(face->boundary_id());
    AffineConstraints<double> constraints;
    p1.make_dirichlet_constraints(dof_handler,
                                  ids,
                                  Functions::ZeroFunction<2>(),
                                  constraints);
    constraints.close();
    out << "boundary vertices constrained: " << constraints.n_constraints()
        << std::endl;
    const auto c =
      dirichlet_checks::constrained_coefficients(dof_handler, constraints);
    const auto zero =
      dirichlet_checks::boundary_deviation(p1,
                                           dof_handler,
                                           c,
                                           ids,
                                           Functions::ZeroFunction<2>());
    PSMPM_CHECK(out, zero.first < 1e-13 && zero.second < 1e-13);
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    {
      Triangulation<2> tria;
      psmpm::Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(1, 1),
        4,
        3,
        psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
      check(out, tria);
    }
    {
      Triangulation<2> tria;
      psmpm::Mesh::MeshGenerator<2>::read_gmsh(tria,
                                               PSMPM_SOURCE_DIR
                                               "/tests/basis/l_shape.msh");
      check(out, tria);
    }
  });
}
