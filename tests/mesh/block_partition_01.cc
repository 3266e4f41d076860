// ---------------------------------------------------------------------
// psmpm: Mesh::BlockPartition and describe_block_part() on 4 ranks
// (.mpirun=4). The tiling gives every block one owner, every rank a
// rectangle of blocks, cell counts within a row and a column of blocks of
// each other, and the fewest cut edges (strips along the long side of a
// long mesh). The description of every rank's part of criss-cross and
// diagonal meshes, for 2, 3 and 4 ranks and 1 and 2 ghost layers, equals
// the one made from the whole mesh with the same owners (describe_part(),
// deal.II's create_description_from_triangulation()) in every field: the
// same cells with the same indices, vertices, owners, boundary ids and
// rim faces. On the 4 ranks, a parallel::fullydistributed mesh built from
// the parts holds every cell of the whole mesh once.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <psmpm/mesh/block_partition.h>
#include <psmpm/mesh/distributed_mesh.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

namespace
{
  using psmpm::Mesh::BlockMesh;
  using psmpm::Mesh::BlockPartition;
  using Generator   = psmpm::Mesh::MeshGenerator<2>;
  using Description = TriangulationDescription::Description<2, 2>;

  /// deal.II leaves the manifold id of a triangle's fourth (missing) line
  /// unset: compare the three. The level subdomain ids are left out: the
  /// whole mesh's (0) and the parts' (artificial) are both unused without
  /// Settings::construct_multigrid_hierarchy.
  bool
  same(const Description &a, const Description &b)
  {
    if (!(a.coarse_cells == b.coarse_cells &&
          a.coarse_cell_vertices == b.coarse_cell_vertices &&
          a.coarse_cell_index_to_coarse_cell_id ==
            b.coarse_cell_index_to_coarse_cell_id &&
          a.cell_infos.size() == 1 && b.cell_infos.size() == 1 &&
          a.cell_infos[0].size() == b.cell_infos[0].size() &&
          a.settings == b.settings && a.smoothing == b.smoothing))
      return false;
    for (unsigned int c = 0; c < a.cell_infos[0].size(); ++c)
      {
        const auto &x = a.cell_infos[0][c], &y = b.cell_infos[0][c];
        if (x.id != y.id || x.subdomain_id != y.subdomain_id ||
            x.manifold_id != y.manifold_id || x.boundary_ids != y.boundary_ids)
          return false;
        for (unsigned int l = 0; l < 3; ++l)
          if (x.manifold_line_ids[l] != y.manifold_line_ids[l])
            return false;
      }
    return true;
  }

  /// The parts of @p mesh for 2-4 ranks against those from the whole mesh.
  void
  check_descriptions(std::ostream &out, const BlockMesh &mesh)
  {
    Triangulation<2> whole;
    Generator::make_blocks(whole,
                           mesh.lower,
                           mesh.upper,
                           mesh.nx,
                           mesh.ny,
                           mesh.criss_cross ? Generator::Type::criss_cross :
                                              Generator::Type::diagonal);
    unsigned int n_parts = 0, n_equal = 0, n_cells = 0;
    for (unsigned int n_ranks = 2; n_ranks <= 4; ++n_ranks)
      {
        const BlockPartition      partition(mesh.nx, mesh.ny, n_ranks);
        std::vector<unsigned int> owner(whole.n_active_cells());
        for (unsigned int c = 0; c < owner.size(); ++c)
          owner[c] = partition.owner(mesh.block_of(c)[0], mesh.block_of(c)[1]);
        for (unsigned int layers = 1; layers <= 2; ++layers)
          for (unsigned int rank = 0; rank < n_ranks; ++rank)
            {
              const Description a =
                psmpm::Mesh::describe_block_part(mesh,
                                                 partition,
                                                 rank,
                                                 layers,
                                                 MPI_COMM_WORLD);
              const Description b = psmpm::Mesh::describe_part(whole,
                                                               owner,
                                                               rank,
                                                               layers,
                                                               MPI_COMM_WORLD);
              ++n_parts;
              n_equal += same(a, b);
              n_cells += a.coarse_cells.size();
            }
      }
    out << (mesh.criss_cross ? "criss-cross " : "diagonal ") << mesh.nx << " x "
        << mesh.ny << ": " << n_parts << " parts, " << n_cells << " cells held"
        << std::endl;
    PSMPM_CHECK(out, n_equal == n_parts);
  }

  /// Every block one owner; every rank a rectangle whose owner it is.
  void
  check_tiling(std::ostream      &out,
               const unsigned int nx,
               const unsigned int ny,
               const unsigned int n_ranks)
  {
    const BlockPartition      partition(nx, ny, n_ranks);
    std::vector<unsigned int> n_blocks(n_ranks, 0);
    unsigned int              wrong = 0;
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const auto t = partition.tile(r);
        for (unsigned int j = t[2]; j < t[3]; ++j)
          for (unsigned int i = t[0]; i < t[1]; ++i)
            {
              wrong += partition.owner(i, j) != r;
              ++n_blocks[r];
            }
      }
    unsigned int total = 0;
    for (const unsigned int n : n_blocks)
      total += n;
    out << nx << " x " << ny << " blocks, " << n_ranks << " ranks: tiles "
        << partition.px << " x " << partition.py << ", blocks per rank "
        << *std::min_element(n_blocks.begin(), n_blocks.end()) << " to "
        << *std::max_element(n_blocks.begin(), n_blocks.end()) << std::endl;
    PSMPM_CHECK(out, partition.valid());
    PSMPM_CHECK(out, wrong == 0 && total == nx * ny);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  return run_test([]() {
    const MPI_Comm comm = MPI_COMM_WORLD;
    std::ofstream  out  = root_output();

    check_tiling(out, 1000, 80, 8);
    check_tiling(out, 80, 1000, 8);
    check_tiling(out, 100, 100, 16);
    check_tiling(out, 7, 5, 6);
    check_tiling(out, 10, 3, 7);
    // No tiling: 7 ranks on 5 x 5 blocks (7 is prime and above 5).
    PSMPM_CHECK(out, !BlockPartition(5, 5, 7).valid());

    BlockMesh mesh;
    mesh.lower       = Point<2>(-1, 0.5);
    mesh.upper       = Point<2>(2.3, 1.7);
    mesh.nx          = 7;
    mesh.ny          = 5;
    mesh.criss_cross = true;
    check_descriptions(out, mesh);
    mesh.criss_cross = false;
    mesh.nx          = 6;
    mesh.ny          = 4;
    check_descriptions(out, mesh);
    // A strip one block high: the ghost layers reach the far side.
    mesh.criss_cross = true;
    mesh.nx          = 9;
    mesh.ny          = 1;
    check_descriptions(out, mesh);

    // The parts on the ranks make one mesh of every cell once.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    mesh.nx                    = 12;
    mesh.ny                    = 6;
    const BlockPartition partition(mesh.nx, mesh.ny, n_ranks);
    for (unsigned int layers = 1; layers <= 2; ++layers)
      {
        parallel::fullydistributed::Triangulation<2> tria(comm);
        tria.create_triangulation(psmpm::Mesh::describe_block_part(
          mesh,
          partition,
          Utilities::MPI::this_mpi_process(comm),
          layers,
          comm));
        out << n_ranks << " ranks, " << layers
            << " ghost layers: " << tria.n_global_active_cells() << " cells"
            << std::endl;
        PSMPM_CHECK(out, tria.n_global_active_cells() == mesh.n_cells());
      }
  });
}
