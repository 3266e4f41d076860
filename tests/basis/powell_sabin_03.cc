// ---------------------------------------------------------------------
// psmpm: Powell-Sabin space on a unstructured non-uniform Gmsh mesh of an
// L-shape (reflex corner): DoF layout, partition of unity, non-negativity, C1
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
    psmpm::Mesh::MeshGenerator<2>::read_gmsh(tria,
                                             PSMPM_SOURCE_DIR
                                             "/tests/basis/l_shape.msh");
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    ps.reinit(dof_handler);
    ps_checks::check_space(out, dof_handler, ps);
  });
}
