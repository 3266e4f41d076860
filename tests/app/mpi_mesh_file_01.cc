// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// On two ranks, every rank reads the Gmsh file of Mesh/File itself. A file
// that only one rank cannot read ends both ranks with bad input naming the
// rank and the file, never a wait; so does a file whose bytes differ
// between the ranks (each would build another mesh). The same for a
// body's Gmsh geometry (Bodies/Body k/File). Each rank reads the
// same scene from a directory of its own (r0/scene.prm, r1/scene.prm), so
// that Mesh/File = meshes/bar.msh, relative to the parameter file, names
// another file on each rank while the parameters agree (a rank that does
// not find it there looks for it relative to the working directory, and
// names it as given).
#include "../app_tests.h"

#include <filesystem>

namespace fs = std::filesystem;

int
main(int argc, char **argv)
{
  psmpm::MPISession  mpi(argc, argv);
  const bool         root   = is_root_rank();
  const unsigned int rank   = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  std::ofstream      out    = root_output();
  const std::string  meshes = std::string(PSMPM_SOURCE_DIR) + "/prm/meshes/";
  const std::string  scene  = "subsection Mesh\n"
                              "  set Type = gmsh\n"
                              "  set File = meshes/bar.msh\n"
                              "end\n"
                              "subsection Basis\n"
                              "  set Type = powell-sabin\n"
                              "end\n"
                              "subsection Particles\n"
                              "  set Per cell = 4\n"
                              "end\n"
                              "subsection Time\n"
                              "  set End time = 0.005\n"
                              "  set Time step = 0\n"
                              "end\n"
                              "subsection Output\n"
                              "  set Interval = 0\n"
                              "end\n";
  // The file of rank r: the sliver bar, another mesh, or none.
  const auto place = [&](const std::string &r0, const std::string &r1) {
    if (root)
      {
        fs::remove_all("mesh_out");
        for (const auto &[dir, mesh] :
             {std::make_pair("r0", r0), std::make_pair("r1", r1)})
          {
            fs::remove_all(dir);
            fs::create_directories(std::string(dir) + "/meshes");
            std::ofstream(std::string(dir) + "/scene.prm") << scene;
            if (!mesh.empty())
              fs::copy_file(meshes + mesh,
                            std::string(dir) + "/meshes/bar.msh");
          }
      }
    MPI_Barrier(MPI_COMM_WORLD);
  };
  const auto run = [&](const std::string &name, std::string &message) {
    std::string screen;
    const int   code = run_app({"r" + std::to_string(rank) + "/scene.prm",
                                "--set",
                                "Output directory=mesh_out"},
                             screen,
                             message);
    const int   low  = Utilities::MPI::min(code, MPI_COMM_WORLD);
    const int   high = Utilities::MPI::max(code, MPI_COMM_WORLD);
    out << name << ": exit codes " << low << " to " << high << std::endl;
    return std::make_pair(low, high);
  };
  const auto bad_input = [](const std::pair<int, int> &codes) {
    return codes.first == psmpm::App::bad_input &&
           codes.second == psmpm::App::bad_input;
  };

  std::string message;
  place("sliver_bar.msh", "");
  auto codes = run("mesh file missing on rank 1", message);
  PSMPM_CHECK(out, bad_input(codes));
  if (root)
    {
      PSMPM_CHECK(out,
                  message.find("on rank 1: Mesh/File = meshes/bar.msh: cannot "
                               "open the file") != std::string::npos);
      out << "  " << message;
    }
  PSMPM_CHECK(out, !fs::exists("mesh_out"));

  place("", "sliver_bar.msh");
  codes = run("mesh file missing on rank 0", message);
  PSMPM_CHECK(out, bad_input(codes));
  if (root)
    PSMPM_CHECK(out,
                message.find("on rank 0: Mesh/File = meshes/bar.msh: cannot "
                             "open the file") != std::string::npos);
  PSMPM_CHECK(out, !fs::exists("mesh_out"));

  place("sliver_bar.msh", "strip_footing.msh");
  codes = run("another mesh file on rank 1", message);
  PSMPM_CHECK(out, bad_input(codes));
  if (root)
    {
      PSMPM_CHECK(out,
                  message.find("rank 0 and rank 1 read different content") !=
                    std::string::npos);
      out << "  " << message;
    }
  PSMPM_CHECK(out, !fs::exists("mesh_out"));

  place("sliver_bar.msh", "sliver_bar.msh");
  codes = run("the same mesh file on both ranks", message);
  PSMPM_CHECK(out, codes.first == 0 && codes.second == 0);
  if (root && codes.first != 0)
    out << message;

  // A body's Gmsh geometry (Bodies/Body 1/File) that rank 1 cannot read.
  if (root)
    for (const std::string dir : {"r0", "r1"})
      {
        fs::remove_all(dir);
        fs::create_directories(dir + "/geometry");
        fs::copy_file(std::string(PSMPM_SOURCE_DIR) + "/prm/ring_impact.prm",
                      dir + "/ring.prm");
      }
  if (root)
    {
      fs::remove_all("mesh_out");
      fs::copy_file(std::string(PSMPM_SOURCE_DIR) + "/prm/geometry/ring.msh",
                    "r0/geometry/ring.msh");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  std::string screen;
  const int   code = run_app({"r" + std::to_string(rank) + "/ring.prm",
                              "--set",
                              "Output directory=mesh_out"},
                           screen,
                           message);
  out << "body file missing on rank 1: exit codes "
      << Utilities::MPI::min(code, MPI_COMM_WORLD) << " to "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  PSMPM_CHECK(out,
              Utilities::MPI::min(code, MPI_COMM_WORLD) ==
                  psmpm::App::bad_input &&
                Utilities::MPI::max(code, MPI_COMM_WORLD) ==
                  psmpm::App::bad_input);
  if (root)
    {
      PSMPM_CHECK(out,
                  message.find("on rank 1: Bodies/Body 1/File = "
                               "geometry/ring.msh: cannot open the file") !=
                    std::string::npos);
      out << "  " << message;
    }
  PSMPM_CHECK(out, !fs::exists("mesh_out"));
}
