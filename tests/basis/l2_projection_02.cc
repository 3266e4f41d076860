// ---------------------------------------------------------------------
// psmpm: L2 projection of sin(pi x) sin(pi y) on the unit square with
// Powell-Sabin splines on diagonal meshes of 2 and 4 blocks (3 and 5
// vertices a side) against thesis Table 3.1 (1.19e-2, 1.14e-3): within
// 10 %, and a rate of at least 2.95.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/base/summary.h>
#include <psmpm/solver/l2_projection.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;
    const double thesis[2] = {1.19e-2, 1.14e-3};
    double       error[2];
    for (unsigned int i = 0; i < 2; ++i)
      {
        Mesh::MeshGenerator<2> mesh;
        mesh.type     = Mesh::MeshGenerator<2>::Type::diagonal;
        mesh.blocks_x = mesh.blocks_y = 2 << i;
        Solver::L2Projection projection;
        projection.write_output = false;
        Summary summary;
        projection.run(mesh, "powell-sabin", ".", summary, MPI_COMM_WORLD);
        error[i] = summary.get_number("errors.L2");
        out << "blocks " << mesh.blocks_x << ", dofs "
            << static_cast<long>(summary.get_number("n_dofs")) << ", error "
            << std::setprecision(2) << std::scientific << error[i] << std::endl;
        const double relative = std::abs(error[i] / thesis[i] - 1);
        PSMPM_CHECK(out, relative < 0.1);
      }
    const double rate = std::log2(error[0] / error[1]);
    out << "rate " << std::fixed << std::setprecision(1) << rate << std::endl;
    PSMPM_CHECK(out, rate >= 2.95);
  });
}
