// ---------------------------------------------------------------------
// psmpm: Powell-Sabin space on a diagonal mesh of 2 x 1 rectangle, 5 x 3 blocks
// (non-square blocks): DoF layout, partition of unity, non-negativity, C1
// across macro and sub-triangle edges, local support, linear reproduction,
// control triangles.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "ps_checks.h"

int
main()
{
  return run_test([]() {
    std::ofstream    out("output");
    Triangulation<2> tria;
    psmpm::Mesh::MeshGenerator<2>::make_blocks(
      tria,
      Point<2>(0, 0),
      Point<2>(2, 1),
      5,
      3,
      psmpm::Mesh::MeshGenerator<2>::Type::diagonal);
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    ps.reinit(dof_handler);
    ps_checks::check_space(out, dof_handler, ps);
  });
}
