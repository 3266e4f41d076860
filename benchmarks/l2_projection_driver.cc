// ---------------------------------------------------------------------
// psmpm: runs the "l2 projection" scene once without the application, so
// that the convergence study (contrib/studies/thesis/l2_projection_study.sh) can be
// reproduced from the library alone.
//
//   l2_projection_driver <linear|powell-sabin> <diagonal|criss-cross>
//                        <blocks> <output directory> [lumped|consistent]
//                        [function] [basis function "vertex,q"]
//
// An output directory "-" writes no files: the wall time is then that of
// mesh, space, assembly, solve and error alone.
//
// Prints one tab-separated line: blocks, vertices per side, n_dofs,
// L2 error, h, wall time of L2Projection::run in seconds.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/mpi_session.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/base/summary.h>
#include <psmpm/solver/l2_projection.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  if (argc < 5)
    {
      std::cerr << "usage: " << argv[0]
                << " <linear|powell-sabin> <diagonal|criss-cross> <blocks>"
                   " <output directory> [lumped|consistent] [function]"
                   " [vertex,q]"
                << std::endl;
      return 1;
    }
  try
    {
      const std::string  basis  = argv[1];
      const std::string  type   = argv[2];
      const unsigned int blocks = std::stoul(argv[3]);
      const std::string  output = argv[4];

      psmpm::Mesh::MeshGenerator<2> mesh;
      mesh.type =
        (type == "diagonal" ? psmpm::Mesh::MeshGenerator<2>::Type::diagonal :
                              psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
      mesh.length   = 1;
      mesh.height   = 1;
      mesh.blocks_x = blocks;
      mesh.blocks_y = blocks;

      psmpm::Solver::L2Projection projection;
      projection.lumped       = (argc > 5 && std::string(argv[5]) == "lumped");
      projection.write_output = (output != "-");
      if (argc > 6)
        projection.function_expression = argv[6];
      if (argc > 7)
        {
          const std::string pair           = argv[7];
          const auto        comma          = pair.find(',');
          projection.output_basis_vertex   = std::stoul(pair.substr(0, comma));
          projection.output_basis_function = std::stoul(pair.substr(comma + 1));
        }

      psmpm::Summary summary;
      const auto                  start = std::chrono::steady_clock::now();
      projection.run(mesh, basis, output, summary, MPI_COMM_WORLD);
      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      summary.set("wall_time_s", wall);
      if (output != "-")
        summary.write(output + "/summary.json");

      std::printf("%u\t%u\t%lld\t%.6e\t%.6e\t%.4f\n",
                  blocks,
                  blocks + 1,
                  static_cast<long long>(summary.get_number("n_dofs")),
                  summary.get_number("errors.L2"),
                  summary.get_number("h"),
                  wall);
    }
  catch (const std::exception &e)
    {
      std::cerr << "Error: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
