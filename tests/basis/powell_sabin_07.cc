// ---------------------------------------------------------------------
// psmpm: Powell-Sabin space on a Gmsh disk, a polygonal approximation of a
// curved boundary: every boundary vertex is a convex corner with an angle
// close to 180 degrees. The space is valid (all checks of ps_checks.h)
// and homogeneous Dirichlet conditions make the spline vanish on the
// boundary polygon. Also prints how large the corner-aligned control
// triangles get compared with the mesh, the price of aligning them.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "dirichlet_checks.h"
#include "ps_checks.h"

int
main()
{
  return run_test([]() {
    std::ofstream    out("output");
    Triangulation<2> tria;
    psmpm::Mesh::MeshGenerator<2>::read_gmsh(tria,
                                             PSMPM_SOURCE_DIR
                                             "/tests/basis/disk.msh");
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    ps.reinit(dof_handler);
    ps_checks::check_space(out, dof_handler, ps);

    double max_ratio = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int v = cell->vertex_index(k);
          if (ps.vertex_kind(v) ==
              psmpm::Basis::PowellSabin::VertexKind::corner)
            max_ratio =
              std::max(max_ratio,
                       psmpm::Mesh::signed_area(ps.control_triangle(v)) /
                         cell->measure());
        }
    out << "largest corner control triangle / adjacent cell area: "
        << (max_ratio < 10  ? "below 10" :
            max_ratio < 100 ? "10 to 100" :
                              "above 100")
        << std::endl;

    AffineConstraints<double> constraints;
    ps.make_dirichlet_constraints(dof_handler,
                                  {0},
                                  Functions::ZeroFunction<2>(),
                                  constraints);
    constraints.close();
    const auto c =
      dirichlet_checks::constrained_coefficients(dof_handler, constraints);
    const auto zero =
      dirichlet_checks::boundary_deviation(ps,
                                           dof_handler,
                                           c,
                                           {0},
                                           Functions::ZeroFunction<2>());
    PSMPM_CHECK(out, zero.first < 1e-13 && zero.second < 1e-13);
  });
}
