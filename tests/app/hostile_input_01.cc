// Malformed or hostile input never crashes psmpm: truncated and randomly
// corrupted parameter files, broken and inverted Gmsh meshes and particle
// counts that would not fit in memory all end with a clear error and exit
// code 2, and nothing is written.
#include "../app_tests.h"

#include <filesystem>
#include <random>
#include <sstream>

int
run_quietly(const std::vector<std::string> &args, std::string &message)
{
  std::string screen;
  return run_app(args, screen, message);
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string scene = std::string(psmpm::App::default_scene);
  std::mt19937      rng(2026);
  std::string       message;
  std::filesystem::remove_all("never");

  // Truncated parameter files: every cut either parses (a valid prefix of
  // the scene, which --validate accepts) or is rejected with exit code 2.
  unsigned int truncated_ok = 0, truncated_rejected = 0, bad = 0;
  for (std::size_t cut = 0; cut < scene.size(); cut += 7)
    {
      std::ofstream("cut.prm") << scene.substr(0, cut);
      const int code = run_quietly({"cut.prm", "--validate"}, message);
      if (code == 0)
        ++truncated_ok;
      else if (code == psmpm::App::bad_input &&
               message.find("cut.prm") != std::string::npos)
        ++truncated_rejected;
      else
        ++bad;
    }
  out << "truncated files: some accepted " << (truncated_ok > 0)
      << ", some rejected " << (truncated_rejected > 0) << std::endl;
  PSMPM_CHECK(out, bad == 0);

  // Random corruption: bytes replaced by random printable and control
  // characters.
  bad = 0;
  std::uniform_int_distribution<int>         byte(0, 255);
  std::uniform_int_distribution<std::size_t> where(0, scene.size() - 1);
  for (unsigned int trial = 0; trial < 150; ++trial)
    {
      std::string text = scene;
      for (unsigned int k = 0; k < 1 + trial % 8; ++k)
        text[where(rng)] = static_cast<char>(byte(rng));
      std::ofstream("random.prm") << text;
      const int code = run_quietly({"random.prm", "--validate"}, message);
      bad += !(code == 0 || code == psmpm::App::bad_input);
    }
  PSMPM_CHECK(out, bad == 0);

  // Broken meshes.
  const std::string head =
    "set Output directory = never\nsubsection Mesh\n set Type = gmsh\n"
    " set File = mesh.msh\nend\nsubsection Boundary conditions\n"
    " set Fixed x =\n set Fixed y =\nend\nsubsection Reference solution\n"
    " set Type = none\nend\n";
  std::ofstream("mesh.prm") << head;
  const std::vector<std::pair<std::string, std::string>> meshes = {
    {"empty file", ""},
    {"garbage", "this is not a mesh\n\x01\x02\x03"},
    {"truncated",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"},
    {"inverted triangle",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
     "4 1 1 0\n$EndNodes\n$Elements\n2\n1 2 2 0 1 1 2 3\n2 2 2 0 1 2 3 4\n"
     "$EndElements\n"},
    {"degenerate triangle",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 2 0 0\n$EndNodes\n"
     "$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n"},
    {"node index out of range",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
     "$Elements\n1\n1 2 2 0 1 1 2 9\n$EndElements\n"}};
  for (const auto &m : meshes)
    {
      std::ofstream("mesh.msh") << m.second;
      const int code = run_quietly({"mesh.prm"}, message);
      out << m.first << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::bad_input);
      PSMPM_CHECK(out, message.find("mesh.msh") != std::string::npos);
    }

  // Particle counts that would not fit in memory.
  const int code = run_quietly({"--set",
                                "Mesh/Blocks x=100000",
                                "--set",
                                "Particles/Per block x=1000",
                                "--set",
                                "Output directory=never"},
                               message);
  out << "huge particle count: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out, message.find("Maximum number") != std::string::npos);
  PSMPM_CHECK(out, !std::filesystem::exists("never"));
}
