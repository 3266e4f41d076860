// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_block_partition_h
#define psmpm_mesh_block_partition_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria_description.h>

#include <array>
#include <cstdint>
#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * The triangles of a rectangle of nx by ny blocks as
     * MeshGenerator::make_blocks() numbers them, computed block by block
     * without the whole mesh: corner (i, j) is vertex j (nx + 1) + i, the
     * centre of block (i, j) (criss-cross) is vertex (nx + 1)(ny + 1) +
     * j nx + i, and triangle t of block (i, j) is cell (j nx + i) k + t
     * with k = 4 (criss-cross: bottom, right, top, left) or 2 (diagonal:
     * below and above the diagonal). The coordinates are computed with the
     * same expressions, so they are the same doubles.
     */
    struct BlockMesh
    {
      Point<2>     lower;
      Point<2>     upper;
      unsigned int nx          = 1;
      unsigned int ny          = 1;
      bool         criss_cross = true;

      unsigned int
      cells_per_block() const
      {
        return criss_cross ? 4 : 2;
      }

      std::uint64_t
      n_cells() const
      {
        return std::uint64_t(nx) * ny * cells_per_block();
      }

      /// Block (i, j) of cell @p c.
      std::array<unsigned int, 2>
      block_of(const std::uint64_t c) const
      {
        const std::uint64_t b = c / cells_per_block();
        return {{static_cast<unsigned int>(b % nx),
                 static_cast<unsigned int>(b / nx)}};
      }
    };

    /**
     * The ranks as px by py tiles of whole blocks over a BlockMesh, px py =
     * n_ranks, of the factorisation with the fewest cut block edges
     * ((px - 1) ny + (py - 1) nx): a rank's cells are a rectangle of
     * blocks, so every rank computes any cell's owner from nx, ny and the
     * number of ranks alone, and a rank's ghost layers are a rim of blocks
     * around its rectangle. Tile column t holds the block columns
     * [t nx / px, (t + 1) nx / px) (rounded down), likewise in y: the
     * ranks' cell counts differ by at most a row and a column of blocks.
     * Rank ty px + tx owns tile (tx, ty).
     */
    class BlockPartition
    {
    public:
      BlockPartition(const unsigned int nx,
                     const unsigned int ny,
                     const unsigned int n_ranks);

      /// Whether a tiling gives every rank a block (px <= nx, py <= ny).
      bool
      valid() const;

      /// Owner of block (i, j).
      unsigned int
      owner(const unsigned int i, const unsigned int j) const;

      /// Blocks [i0, i1) x [j0, j1) of @p rank as {i0, i1, j0, j1}.
      std::array<unsigned int, 4>
      tile(const unsigned int rank) const;

      unsigned int px = 0, py = 0;

    private:
      /// First block of tile @p t of @p n_tiles over @p n blocks.
      static unsigned int
      cut(const unsigned int t,
          const unsigned int n_tiles,
          const unsigned int n);

      /// Tile of block @p i of @p n, in @p n_tiles tiles.
      static unsigned int
      tile_of(const unsigned int i,
              const unsigned int n_tiles,
              const unsigned int n);

      unsigned int nx, ny;
    };

    /**
     * Rank @p rank's part of @p mesh under @p partition, as deal.II's
     * create_description_from_triangulation() describes it from the whole
     * mesh (coarse cells in the order of their index in the whole mesh,
     * vertices in the order of theirs, the boundary ids of the mesh's sides
     * 0-3), with @p layers (1 or 2) ghost layers (a cell of layer k shares a
     * vertex with one of layer k - 1) and rim_boundary_id on the ghost
     * faces whose neighbour is not held. Built from the blocks of the rank's
     * tile widened by @p layers blocks: memory follows the part.
     */
    TriangulationDescription::Description<2, 2>
    describe_block_part(const BlockMesh      &mesh,
                        const BlockPartition &partition,
                        const unsigned int    rank,
                        const unsigned int    layers,
                        const MPI_Comm        comm);
  } // namespace Mesh
} // namespace psmpm

#endif
