// Gmsh meshes psmpm cannot use are refused with a message naming the file
// and the problem, exit code 2, and nothing written: a binary file, a
// hanging node (non-conforming mesh), a physical name defined twice, a
// boundary name without edges and physical tag 0. The conforming mesh
// they are made from is accepted.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  std::filesystem::remove_all("never");
  std::ofstream("mesh.prm")
    << "set Output directory = never\nsubsection Mesh\n set Type = gmsh\n"
       " set File = mesh.msh\nend\nsubsection Boundary conditions\n"
       " set Fixed x = left\n set Fixed y =\nend\nsubsection Reference solution\n"
       " set Type = none\nend\nsubsection Initial conditions\n"
       " set Velocity = 0; 0\nend\n";
  const std::string format = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  // The unit square as two triangles, left edge named "left" (tag 1).
  const std::string names =
    "$PhysicalNames\n1\n1 1 \"left\"\n$EndPhysicalNames\n";
  const std::string square =
    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
    "$Elements\n3\n1 1 2 1 1 4 1\n2 2 2 0 1 1 2 3\n3 2 2 0 1 1 3 4\n"
    "$EndElements\n";
  // Three triangles: the lower left one's edge (2,3) holds the vertex 5 of the
  // two on the right.
  const std::string hanging =
    "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 0.5 0.5 0\n$EndNodes\n"
    "$Elements\n4\n1 1 2 1 1 3 1\n2 2 2 0 1 1 2 3\n3 2 2 0 1 2 4 5\n"
    "4 2 2 0 1 5 4 3\n$EndElements\n";
  const std::vector<std::tuple<std::string, std::string, std::string>> meshes =
    {{"binary file",
      "$MeshFormat\n2.2 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n",
      "binary"},
     {"hanging node", format + names + hanging, "not conforming"},
     {"physical name defined twice",
      format +
        "$PhysicalNames\n2\n1 1 \"left\"\n1 2 \"left\"\n$EndPhysicalNames\n" +
        square,
      "defined twice"},
     {"boundary name without edges",
      format +
        "$PhysicalNames\n2\n1 1 \"left\"\n1 7 \"right\"\n$EndPhysicalNames\n" +
        square,
      "\"right\" (tag 7) has no edges"},
     {"physical tag 0",
      format + "$PhysicalNames\n1\n1 0 \"left\"\n$EndPhysicalNames\n" + square,
      "tag 0"}};
  for (const auto &m : meshes)
    {
      std::ofstream("mesh.msh", std::ios::binary) << std::get<1>(m);
      std::string screen, message;
      const int   code  = run_app({"mesh.prm"}, screen, message);
      const bool  named = message.find("mesh.msh") != std::string::npos &&
                         message.find(std::get<2>(m)) != std::string::npos;
      out << std::get<0>(m) << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::bad_input);
      PSMPM_CHECK(out, named);
      PSMPM_CHECK(out, message.find("Stacktrace") == std::string::npos);
      PSMPM_CHECK(out, !std::filesystem::exists("never"));
      if (!named)
        out << "  message: " << message;
    }
  std::ofstream("mesh.msh") << format << names << square;
  std::string screen, message;
  const int   code = run_app({"mesh.prm", "--validate"}, screen, message);
  out << "conforming square: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::success);
  if (code != 0)
    out << "  message: " << message;
}
