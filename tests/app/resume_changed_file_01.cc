// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// --resume refuses a run whose Gmsh mesh file (Mesh/File, relative to the
// parameter file) was edited in place since the run started: one vertex
// moved by 1e-9 gives exit code 2 and a message naming the entry, the
// file and that its content changed; with the file restored, the same
// resume runs to its end. The same for a body's Gmsh geometry file
// (Bodies/Body 1/File of the ring impact) with one line appended.
#include "../app_tests.h"

#include <filesystem>

namespace fs = std::filesystem;

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string prm = std::string(PSMPM_SOURCE_DIR) + "/prm/";

  fs::remove_all("scene");
  fs::create_directories("scene/meshes");
  fs::copy_file(prm + "sliver_mesh_bar.prm", "scene/bar.prm");
  fs::copy_file(prm + "meshes/sliver_bar.msh", "scene/meshes/sliver_bar.msh");
  const std::string original = read_file("scene/meshes/sliver_bar.msh");

  const std::vector<std::string> scene = {"scene/bar.prm",
                                          "--set",
                                          "Output directory=changed_file",
                                          "--set",
                                          "Particles/Per cell=1",
                                          "--set",
                                          "Time/Courant number=0.1"};
  std::string                    screen, message;
  auto                           args = scene;
  args.insert(args.end(), {"--set", "Time/End time=0.02"});
  int code = run_app(args, screen, message);
  out << "run: exit code " << code << std::endl;

  // Vertex 18 moves by 1e-9 in y.
  const std::string vertex = "\n18 4.59056068382 0.614487257334 0\n";
  std::string       moved  = original;
  const auto        at     = moved.find(vertex);
  PSMPM_CHECK(out, at != std::string::npos);
  if (at != std::string::npos)
    moved.replace(at, vertex.size(), "\n18 4.59056068382 0.614487258334 0\n");
  std::ofstream("scene/meshes/sliver_bar.msh") << moved;

  args = scene;
  args.insert(args.end(), {"--set", "Time/End time=0.04", "--resume"});
  code = run_app(args, screen, message);
  out << "resume with the mesh file changed: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out, message.find("Mesh/File") != std::string::npos);
  PSMPM_CHECK(out, message.find("meshes/sliver_bar.msh") != std::string::npos);
  PSMPM_CHECK(out,
              message.find("changed since the checkpoint") !=
                std::string::npos);
  if (code != psmpm::App::bad_input)
    out << message << std::endl;

  std::ofstream("scene/meshes/sliver_bar.msh") << original;
  code = run_app(args, screen, message);
  out << "resume with the mesh file restored: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::success);
  if (code != psmpm::App::success)
    out << message << std::endl;
  PSMPM_CHECK(out,
              read_file("changed_file/summary.json").find("\"resumed_step\"") !=
                std::string::npos);

  fs::create_directories("scene/geometry");
  fs::copy_file(prm + "ring_impact.prm", "scene/ring.prm");
  fs::copy_file(prm + "geometry/ring.msh", "scene/geometry/ring.msh");
  const std::string              ring = read_file("scene/geometry/ring.msh");
  const std::vector<std::string> ring_scene = {"scene/ring.prm",
                                               "--set",
                                               "Output directory=changed_body"};
  args                                      = ring_scene;
  args.insert(args.end(), {"--set", "Time/End time=3e-5"});
  code = run_app(args, screen, message);
  out << "ring: exit code " << code << std::endl;
  std::ofstream("scene/geometry/ring.msh") << ring << "\n";
  args = ring_scene;
  args.insert(args.end(), {"--set", "Time/End time=6e-5", "--resume"});
  code = run_app(args, screen, message);
  out << "resume with the body file changed: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out,
              message.find("Bodies/Body 1/File: the content of "
                           "scene/geometry/ring.msh changed since the "
                           "checkpoint") != std::string::npos);
  if (code != psmpm::App::bad_input)
    out << message << std::endl;
  std::ofstream("scene/geometry/ring.msh") << ring;
  code = run_app(args, screen, message);
  out << "resume with the body file restored: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::success);
}
