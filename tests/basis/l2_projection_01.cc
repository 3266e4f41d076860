// ---------------------------------------------------------------------
// psmpm: every quadratic polynomial lies in the Powell-Sabin space, so its
// L2 projection is exact to round-off, on a structured and an
// unstructured non-uniform mesh; P1 is not exact for it. Also runs the
// scene's VTU output with a basis function and checks the files.
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
    const std::string quadratic = "1 + 2*x - 3*y + 0.5*x^2 - 1.5*x*y + 2.5*y^2";

    Mesh::MeshGenerator<2> diagonal;
    diagonal.type     = Mesh::MeshGenerator<2>::Type::diagonal;
    diagonal.blocks_x = 3;
    diagonal.blocks_y = 2;
    Mesh::MeshGenerator<2> gmsh;
    gmsh.type = Mesh::MeshGenerator<2>::Type::gmsh;
    gmsh.file = PSMPM_SOURCE_DIR "/tests/basis/l_shape.msh";

    Solver::L2Projection projection;
    projection.function_expression = quadratic;
    projection.write_output        = false;
    for (const auto *mesh : {&diagonal, &gmsh})
      {
        Summary summary;
        projection.run(*mesh, "powell-sabin", ".", summary, MPI_COMM_WORLD);
        out << "powell-sabin: cells " << summary.get_number("n_cells")
            << ", dofs " << summary.get_number("n_dofs") << std::endl;
        PSMPM_CHECK(out, summary.get_number("errors.L2") < 1e-10);

        Summary p1;
        projection.run(*mesh, "linear", ".", p1, MPI_COMM_WORLD);
        out << "linear: dofs " << p1.get_number("n_dofs") << std::endl;
        PSMPM_CHECK(out, p1.get_number("errors.L2") > 1e-4);
      }

    // Output with a basis function: the files exist and carry the fields.
    projection.function_expression   = "sin(pi*x)*sin(pi*y)";
    projection.write_output          = true;
    projection.output_basis_vertex   = 4;
    projection.output_basis_function = 1;
    Summary summary;
    projection.run(diagonal, "powell-sabin", ".", summary, MPI_COMM_WORLD);
    std::ifstream     vtu("projection.vtu");
    const std::string text((std::istreambuf_iterator<char>(vtu)),
                           std::istreambuf_iterator<char>());
    for (const std::string name :
         {"projection", "exact", "error", "basis_function"})
      {
        const bool has_field =
          text.find("Name=\"" + name + "\"") != std::string::npos;
        out << name << ": ";
        PSMPM_CHECK(out, has_field);
      }
    PSMPM_CHECK(out, std::ifstream("mesh.vtu").good());
    PSMPM_CHECK(out, std::ifstream("ps_refinement.vtu").good());

    // A vertex that does not exist is an error naming the entry.
    projection.output_basis_vertex = 1000;
    try
      {
        projection.run(diagonal, "powell-sabin", ".", summary, MPI_COMM_WORLD);
        out << "FAIL no exception for vertex 1000" << std::endl;
      }
    catch (const std::exception &e)
      {
        const bool names_entry =
          std::string(e.what()).find("Output/Basis function") !=
          std::string::npos;
        PSMPM_CHECK(out, names_entry);
      }
  });
}
