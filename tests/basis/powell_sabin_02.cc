// ---------------------------------------------------------------------
// psmpm: Powell-Sabin space on a criss-cross mesh of the unit square, 4 x 3
// blocks: DoF layout, partition of unity, non-negativity, C1 across macro and
// sub-triangle edges, local support, linear reproduction, control
// triangles.
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
      Point<2>(1, 1),
      4,
      3,
      psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    ps.reinit(dof_handler);
    ps_checks::check_space(out, dof_handler, ps);
  });
}
