// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Mesh/Distribution = distributed on 2 ranks (.mpirun=2): each rank holds
// its cells and their ghost layer (parallel::fullydistributed), rank 0
// alone builds the whole mesh (Mesh/Partitioner = metis; the block
// partition is distributed_mesh_02's). With the same METIS partition as the
// replicated mesh, the runs repeat the replicated ones: statistics.txt
// equal in every column but wall time, for particles that cross between
// ranks (column collapse), the automatic mass matrix on a free body (the
// ghost penalty with its sampling cap, rotating block), bodies (two
// disks), a Gmsh mesh (ring impact) and Powell-Sabin (spreading block,
// with two ghost layers). A distributed checkpoint resumes
// bit-identically. What is not verified there is refused with exit 2.
#include "../app_tests.h"
#include "../checkpoint_tests.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace
{
  std::vector<std::string>
  scene_args(const std::string &scene, const std::vector<std::string> &settings)
  {
    std::vector<std::string> args = {std::string(PSMPM_SOURCE_DIR) + "/prm/" +
                                     scene + ".prm"};
    for (const auto &s : settings)
      args.insert(args.end(), {"--set", s});
    return args;
  }

  /// Run @p scene replicated and distributed into rep and dist.
  void
  compare(std::ostream                   &out,
          const std::string              &scene,
          const std::vector<std::string> &settings)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    int        codes[2];
    for (const unsigned int k : {0, 1})
      {
        const std::string dir = k == 0 ? "rep" : "dist";
        if (root)
          fs::remove_all(dir);
        MPI_Barrier(MPI_COMM_WORLD);
        auto args = scene_args(scene, settings);
        args.insert(args.end(),
                    {"--set",
                     "Output directory=" + dir,
                     "--set",
                     "Mesh/Partitioner=metis",
                     "--set",
                     std::string("Mesh/Distribution=") +
                       (k == 0 ? "replicated" : "distributed")});
        std::string screen, errors;
        codes[k] =
          Utilities::MPI::max(run_app(args, screen, errors), MPI_COMM_WORLD);
      }
    out << scene << ": exit codes " << codes[0] << ", " << codes[1]
        << std::endl;
    if (!root)
      return;
    const auto rep  = statistics_rows("rep/statistics.txt");
    const auto dist = statistics_rows("dist/statistics.txt");
    PSMPM_CHECK(out, rep.size() > 10);
    PSMPM_CHECK(out, rep == dist);
    const auto a     = read_file("rep/summary.json");
    const auto b     = read_file("dist/summary.json");
    const auto value = [](const std::string &summary, const std::string &key) {
      const auto at = summary.find("\"" + key + "\":");
      return at == std::string::npos ?
               -1. :
               std::stod(summary.substr(at + key.size() + 3));
    };
    PSMPM_CHECK(out, value(a, "n_cells") == value(b, "n_cells"));
    // Replicated, a rank holds every cell; distributed, fewer.
    PSMPM_CHECK(out, value(a, "max_cells_per_rank") == value(a, "n_cells"));
    PSMPM_CHECK(out, value(b, "max_cells_per_rank") < value(b, "n_cells"));
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();

  compare(out, "column_collapse", {"Time/End time=0.2", "Output/Interval=0"});
  compare(out,
          "rotating_block",
          {"Time/End time=0.1",
           "Output/Interval=0",
           "Mass matrix/Type=automatic",
           "Transfer/Scheme=automatic"});
  compare(out, "two_disks", {"Time/End time=0.2", "Output/Interval=0"});
  compare(out, "ring_impact", {"Time/End time=0.03", "Output/Interval=0"});
  // Powell-Sabin: two ghost layers (the functions of the first layer's
  // cells are built from the cells around their vertices), the free
  // surface's automatic mass and transfer.
  compare(out,
          "spreading_block",
          {"Time/End time=0.6",
           "Output/Interval=0",
           "Mass matrix/Type=automatic",
           "Transfer/Scheme=automatic"});

  // A checkpoint of the distributed mesh (cells named by their index in
  // the whole mesh) resumes bit-identically.
  const std::vector<std::string> checkpointed = {"Time/End time=0.2",
                                                 "Output/Interval=0",
                                                 "Checkpoint/Interval=50",
                                                 "Mesh/Distribution="
                                                 "distributed"};
  if (root)
    fs::remove_all("full");
  MPI_Barrier(MPI_COMM_WORLD);
  std::string screen, errors;
  auto        args = scene_args("column_collapse", checkpointed);
  args.insert(args.end(), {"--set", "Output directory=full"});
  int code = Utilities::MPI::max(run_app(args, screen, errors), MPI_COMM_WORLD);
  const std::string last = "/" + psmpm::Simulator::Checkpoint::file_name(105);
  if (root)
    {
      PSMPM_CHECK(out, code == 0);
      PSMPM_CHECK(out, fs::exists("full" + last));
      copy_directory("full", "resumed");
      fs::remove("resumed" + last);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  args = scene_args("column_collapse", checkpointed);
  args.insert(args.end(), {"--set", "Output directory=resumed", "--resume"});
  code = Utilities::MPI::max(run_app(args, screen, errors), MPI_COMM_WORLD);
  out << "resumed: exit code " << code << std::endl;
  if (root)
    {
      PSMPM_CHECK(out, screen.find("step 100") != std::string::npos);
      PSMPM_CHECK(out,
                  statistics_rows("full/statistics.txt") ==
                    statistics_rows("resumed/statistics.txt"));
      PSMPM_CHECK(out,
                  differing_entries(psmpm::Archive::read_hdf5("full" + last),
                                    psmpm::Archive::read_hdf5("resumed" + last))
                    .empty());
    }

  // Refused: a mesh with fewer cells than ranks (a rank would hold an
  // empty mesh), on every rank (no rank waits for a part).
  if (root)
    {
      std::ofstream msh("one_cell.msh");
      msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n"
             "2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 3\n"
             "$EndElements\n";
    }
  MPI_Barrier(MPI_COMM_WORLD);
  code = run_app(scene_args("column_collapse",
                            {"Mesh/Type=gmsh",
                             "Mesh/File=one_cell.msh",
                             "Boundary conditions/Fixed x=",
                             "Boundary conditions/Fixed y=",
                             "Mesh/Distribution=distributed",
                             "Output directory=refused"}),
                 screen,
                 errors);
  out << "one cell, distributed: exit code "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  if (root)
    {
      PSMPM_CHECK(out,
                  errors.find("without cells of its own") != std::string::npos);
      PSMPM_CHECK(out, !fs::exists("refused"));
    }

  // A fixed step that carries particles past a rank's ghost layers stops
  // the run as unstable (exit 5), and summary.json, which rank 0 writes,
  // names the particle even where another rank found it.
  if (root)
    fs::remove_all("too_far");
  code = run_app(scene_args("column_collapse",
                            {"Bodies/Body 1/Initial velocity=40; 0",
                             "Time/Time step=0.004",
                             "Time/End time=0.02",
                             "Output/Interval=0",
                             "Boundary conditions/Fixed x=",
                             "Boundary conditions/Fixed y=",
                             "Body force/Gravity=0, 0",
                             "Mass matrix/Type=lumped",
                             "Mesh/Distribution=distributed",
                             "Mesh/Partitioner=metis",
                             "Output directory=too_far"}),
                 screen,
                 errors);
  out << "a step past the ghost layers: exit code "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  if (root)
    {
      std::ifstream     in("too_far/summary.json");
      std::stringstream summary;
      summary << in.rdbuf();
      PSMPM_CHECK(out,
                  summary.str().find("left the mesh") != std::string::npos);
    }

  // Refused: a basis whose functions reach past the ghost layers.
  code = run_app(scene_args("column_collapse",
                            {"Basis/Type=bspline",
                             "Mesh/Type=cartesian",
                             "Mesh/Distribution=distributed",
                             "Output directory=refused"}),
                 screen,
                 errors);
  out << "B-splines, distributed: exit code "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;
  if (root)
    {
      PSMPM_CHECK(out,
                  errors.find("Mesh/Distribution = distributed: Basis/Type = "
                              "bspline") != std::string::npos);
      PSMPM_CHECK(out, !fs::exists("refused"));
    }
}
