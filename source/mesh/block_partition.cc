// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// A rank's part of a block mesh, described without the whole mesh.
// ---------------------------------------------------------------------
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/block_partition.h>
#include <psmpm/mesh/mesh_generator.h>

#include <algorithm>
#include <limits>
#include <tuple>

namespace psmpm
{
  namespace Mesh
  {
    BlockPartition::BlockPartition(const unsigned int nx,
                                   const unsigned int ny,
                                   const unsigned int n_ranks)
      : nx(nx)
      , ny(ny)
    {
      std::uint64_t best = std::numeric_limits<std::uint64_t>::max();
      for (unsigned int x = 1; x <= n_ranks; ++x)
        if (n_ranks % x == 0 && x <= nx && n_ranks / x <= ny)
          {
            const unsigned int  y = n_ranks / x;
            const std::uint64_t cost =
              std::uint64_t(x - 1) * ny + std::uint64_t(y - 1) * nx;
            if (cost < best)
              {
                best = cost;
                px   = x;
                py   = y;
              }
          }
    }



    bool
    BlockPartition::valid() const
    {
      return px > 0;
    }



    unsigned int
    BlockPartition::cut(const unsigned int t,
                        const unsigned int n_tiles,
                        const unsigned int n)
    {
      return static_cast<unsigned int>(std::uint64_t(t) * n / n_tiles);
    }



    unsigned int
    BlockPartition::tile_of(const unsigned int i,
                            const unsigned int n_tiles,
                            const unsigned int n)
    {
      // The estimate is at most one tile short (cut() rounds down).
      unsigned int t =
        static_cast<unsigned int>(std::uint64_t(i) * n_tiles / n);
      while (t + 1 < n_tiles && cut(t + 1, n_tiles, n) <= i)
        ++t;
      return t;
    }



    unsigned int
    BlockPartition::owner(const unsigned int i, const unsigned int j) const
    {
      Assert(valid(), ExcInternalError());
      return tile_of(j, py, ny) * px + tile_of(i, px, nx);
    }



    std::array<unsigned int, 4>
    BlockPartition::tile(const unsigned int rank) const
    {
      Assert(valid() && rank < px * py, ExcInternalError());
      const unsigned int tx = rank % px, ty = rank / px;
      return {{cut(tx, px, nx),
               cut(tx + 1, px, nx),
               cut(ty, py, ny),
               cut(ty + 1, py, ny)}};
    }



    namespace
    {
      /**
       * The blocks [a0, a1) x [b0, b1) of a BlockMesh and their vertices,
       * numbered corners first (row by row), then centres: the order of
       * their indices in the whole mesh. Cells are numbered block by
       * block, row by row, likewise.
       */
      class Window
      {
      public:
        Window(const BlockMesh                   &mesh,
               const std::array<unsigned int, 4> &tile,
               const unsigned int                 margin)
          : mesh(mesh)
          , a0(tile[0] >= margin ? tile[0] - margin : 0)
          , a1(std::min(tile[1] + margin, mesh.nx))
          , b0(tile[2] >= margin ? tile[2] - margin : 0)
          , b1(std::min(tile[3] + margin, mesh.ny))
          , w(a1 - a0)
          , hx((mesh.upper[0] - mesh.lower[0]) / mesh.nx)
          , hy((mesh.upper[1] - mesh.lower[1]) / mesh.ny)
        {
        }

        std::size_t
        n_corners() const
        {
          return std::size_t(w + 1) * (b1 - b0 + 1);
        }

        std::size_t
        n_vertices() const
        {
          return n_corners() +
                 (mesh.criss_cross ? std::size_t(w) * (b1 - b0) : 0);
        }

        std::size_t
        n_cells() const
        {
          return std::size_t(w) * (b1 - b0) * mesh.cells_per_block();
        }

        /// Block (i, j) and triangle t of window cell @p c.
        std::array<unsigned int, 3>
        cell(const std::size_t c) const
        {
          const std::size_t b = c / mesh.cells_per_block();
          return {{static_cast<unsigned int>(a0 + b % w),
                   static_cast<unsigned int>(b0 + b / w),
                   static_cast<unsigned int>(c % mesh.cells_per_block())}};
        }

        /// Index of window cell @p c in the whole mesh.
        types::coarse_cell_id
        global_cell(const std::size_t c) const
        {
          const auto [i, j, t] = cell(c);
          return (types::coarse_cell_id(j) * mesh.nx + i) *
                   mesh.cells_per_block() +
                 t;
        }

        /// Counter-clockwise, as MeshGenerator::make_blocks() lists them.
        std::array<unsigned int, 3>
        cell_vertices(const std::size_t c) const
        {
          const auto [i, j, t]   = cell(c);
          const unsigned int v00 = corner(i, j), v10 = corner(i + 1, j),
                             v01 = corner(i, j + 1), v11 = corner(i + 1, j + 1);
          if (!mesh.criss_cross)
            return t == 0 ? std::array<unsigned int, 3>{{v00, v10, v11}} :
                            std::array<unsigned int, 3>{{v00, v11, v01}};
          const unsigned int centre   = n_corners() + (j - b0) * w + (i - a0);
          const unsigned int outer[5] = {v00, v10, v11, v01, v00};
          return {{outer[t], outer[t + 1], centre}};
        }

        /// The same expressions as MeshGenerator::make_blocks().
        Point<2>
        point(const std::size_t v) const
        {
          if (v < n_corners())
            {
              const unsigned int i = a0 + v % (w + 1), j = b0 + v / (w + 1);
              return Point<2>(mesh.lower[0] + i * hx, mesh.lower[1] + j * hy);
            }
          const unsigned int i = a0 + (v - n_corners()) % w,
                             j = b0 + (v - n_corners()) / w;
          return Point<2>(mesh.lower[0] + (i + 0.5) * hx,
                          mesh.lower[1] + (j + 0.5) * hy);
        }

        /// Side of the mesh (left, right, bottom, top: 0-3) that the edge
        /// from @p v to @p u lies on, or internal_face_boundary_id.
        types::boundary_id
        side(const std::size_t v, const std::size_t u) const
        {
          if (v >= n_corners() || u >= n_corners())
            return numbers::internal_face_boundary_id;
          const unsigned int iv = a0 + v % (w + 1), jv = b0 + v / (w + 1),
                             iu = a0 + u % (w + 1), ju = b0 + u / (w + 1);
          if (iv == iu && iv == 0)
            return 0;
          if (iv == iu && iv == mesh.nx)
            return 1;
          if (jv == ju && jv == 0)
            return 2;
          if (jv == ju && jv == mesh.ny)
            return 3;
          return numbers::internal_face_boundary_id;
        }

        bool
        in_tile(const std::size_t                  c,
                const std::array<unsigned int, 4> &tile) const
        {
          const auto [i, j, t] = cell(c);
          (void)t;
          return i >= tile[0] && i < tile[1] && j >= tile[2] && j < tile[3];
        }

      private:
        unsigned int
        corner(const unsigned int i, const unsigned int j) const
        {
          return (j - b0) * (w + 1) + (i - a0);
        }

        const BlockMesh   &mesh;
        const unsigned int a0, a1, b0, b1, w;
        const double       hx, hy;
      };



      constexpr unsigned char not_held = 255;

      /// Layer of every window cell: 0 for the tile's own, k for a cell
      /// that shares a vertex with one of layer k - 1, up to @p layers;
      /// not_held for the others.
      std::vector<unsigned char>
      held_layers(const Window                      &window,
                  const std::array<unsigned int, 4> &tile,
                  const unsigned int                 layers)
      {
        std::vector<unsigned char> layer(window.n_cells(), not_held);
        for (std::size_t c = 0; c < window.n_cells(); ++c)
          if (window.in_tile(c, tile))
            layer[c] = 0;
        for (unsigned int k = 1; k <= layers; ++k)
          {
            std::vector<bool> marked(window.n_vertices(), false);
            for (std::size_t c = 0; c < window.n_cells(); ++c)
              if (layer[c] < k)
                for (const unsigned int v : window.cell_vertices(c))
                  marked[v] = true;
            for (std::size_t c = 0; c < window.n_cells(); ++c)
              if (layer[c] == not_held)
                for (const unsigned int v : window.cell_vertices(c))
                  if (marked[v])
                    layer[c] = k;
          }
        return layer;
      }



      /// For each of the @p held cells, the faces (bit f for face f) that
      /// lie inside the mesh but have no held neighbour: the rim of the
      /// ghost layers.
      std::vector<unsigned char>
      rim_faces(const Window &window, const std::vector<std::size_t> &held)
      {
        // Each face once per held cell beside it: (vertices, cell, face).
        std::vector<
          std::tuple<unsigned int, unsigned int, std::size_t, unsigned int>>
          faces;
        faces.reserve(3 * held.size());
        for (std::size_t h = 0; h < held.size(); ++h)
          {
            const auto v = window.cell_vertices(held[h]);
            for (unsigned int f = 0; f < 3; ++f)
              faces.emplace_back(std::min(v[f], v[(f + 1) % 3]),
                                 std::max(v[f], v[(f + 1) % 3]),
                                 h,
                                 f);
          }
        std::sort(faces.begin(), faces.end());
        std::vector<unsigned char> rim(held.size(), 0);
        for (std::size_t k = 0; k < faces.size(); ++k)
          {
            const auto &[a, b, h, f] = faces[k];
            const bool shared =
              (k > 0 && std::get<0>(faces[k - 1]) == a &&
               std::get<1>(faces[k - 1]) == b) ||
              (k + 1 < faces.size() && std::get<0>(faces[k + 1]) == a &&
               std::get<1>(faces[k + 1]) == b);
            if (!shared &&
                window.side(a, b) == numbers::internal_face_boundary_id)
              rim[h] |= 1u << f;
          }
        return rim;
      }



      /// deal.II's description of held window cell @p c with the rim
      /// faces @p rim.
      TriangulationDescription::CellData<2>
      cell_info(const Window         &window,
                const BlockPartition &partition,
                const std::size_t     c,
                const unsigned char   rim)
      {
        TriangulationDescription::CellData<2> info;
        info.id = CellId(window.global_cell(c), std::vector<std::uint8_t>())
                    .template to_binary<2>();
        const auto [i, j, t] = window.cell(c);
        (void)t;
        info.subdomain_id       = partition.owner(i, j);
        info.level_subdomain_id = numbers::artificial_subdomain_id;
        info.manifold_id        = numbers::flat_manifold_id;
        info.manifold_line_ids.fill(numbers::flat_manifold_id);
        info.manifold_quad_ids.fill(numbers::flat_manifold_id);
        const auto v = window.cell_vertices(c);
        for (unsigned int f = 0; f < 3; ++f)
          {
            const types::boundary_id id = window.side(v[f], v[(f + 1) % 3]);
            if (id != numbers::internal_face_boundary_id)
              info.boundary_ids.emplace_back(f, id);
          }
        for (unsigned int f = 0; f < 3; ++f)
          if (rim & (1u << f))
            info.boundary_ids.emplace_back(f, rim_boundary_id);
        return info;
      }
    } // namespace



    TriangulationDescription::Description<2, 2>
    describe_block_part(const BlockMesh      &mesh,
                        const BlockPartition &partition,
                        const unsigned int    rank,
                        const unsigned int    layers,
                        const MPI_Comm        comm)
    {
      const auto                       tile = partition.tile(rank);
      const Window                     window(mesh, tile, layers);
      const std::vector<unsigned char> layer =
        held_layers(window, tile, layers);
      std::vector<std::size_t> held;
      for (std::size_t c = 0; c < window.n_cells(); ++c)
        if (layer[c] != not_held)
          held.push_back(c);
      const std::vector<unsigned char> rim = rim_faces(window, held);

      TriangulationDescription::Description<2, 2> description;
      description.comm = comm;
      description.settings =
        TriangulationDescription::Settings::default_setting;
      description.smoothing = Triangulation<2>::none;
      description.cell_infos.resize(1);
      // The held vertices, numbered in the order of the whole mesh.
      std::vector<bool> used(window.n_vertices(), false);
      for (const std::size_t c : held)
        for (const unsigned int v : window.cell_vertices(c))
          used[v] = true;
      std::vector<unsigned int> local(window.n_vertices(),
                                      numbers::invalid_unsigned_int);
      for (std::size_t v = 0; v < local.size(); ++v)
        if (used[v])
          {
            local[v] = description.coarse_cell_vertices.size();
            description.coarse_cell_vertices.push_back(window.point(v));
          }
      for (std::size_t h = 0; h < held.size(); ++h)
        {
          dealii::CellData<2> data(3);
          const auto          v = window.cell_vertices(held[h]);
          for (unsigned int k = 0; k < 3; ++k)
            data.vertices[k] = local[v[k]];
          description.coarse_cells.push_back(data);
          description.coarse_cell_index_to_coarse_cell_id.push_back(
            window.global_cell(held[h]));
          description.cell_infos[0].push_back(
            cell_info(window, partition, held[h], rim[h]));
        }
      return description;
    }
  } // namespace Mesh
} // namespace psmpm
