// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// Mesh/Distribution = distributed: each rank describes its own tile of a
// block mesh, or the whole mesh is built on rank 0 only and each rank
// receives its cells and their ghost layers.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/base/root_errors.h>
#include <psmpm/mesh/block_partition.h>
#include <psmpm/mesh/distributed_mesh.h>
#include <psmpm/mesh/mesh_generator.h>

#include <algorithm>
#include <boost/serialization/array.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cstdint>
#include <sstream>

namespace psmpm
{
  namespace Mesh
  {
    namespace
    {
      /// Give the faces of @p description's ghost cells that lie inside
      /// @p whole but have no neighbour in the description the rim id:
      /// deal.II would make them boundary faces with id 0.
      template <int dim>
      void
      mark_rim_faces(
        const Triangulation<dim>                        &whole,
        TriangulationDescription::Description<dim, dim> &description,
        const unsigned int                               rank)
      {
        std::vector<types::coarse_cell_id> held;
        for (const auto &info : description.cell_infos[0])
          held.push_back(CellId(info.id).get_coarse_cell_id());
        std::sort(held.begin(), held.end());
        for (auto &info : description.cell_infos[0])
          if (info.subdomain_id != rank)
            {
              const typename Triangulation<dim>::active_cell_iterator
                cell(&whole, 0, CellId(info.id).get_coarse_cell_id());
              for (const unsigned int f : cell->face_indices())
                if (!cell->at_boundary(f) &&
                    !std::binary_search(held.begin(),
                                        held.end(),
                                        cell->neighbor(f)->index()))
                  info.boundary_ids.emplace_back(f, rim_boundary_id);
            }
      }

    } // namespace



    template <int dim>
    TriangulationDescription::Description<dim, dim>
    describe_part(Triangulation<dim>              &whole,
                  const std::vector<unsigned int> &owner,
                  const unsigned int               rank,
                  const unsigned int               layers,
                  const MPI_Comm                   comm)
    {
      for (const auto &cell : whole.active_cell_iterators())
        cell->set_subdomain_id(owner[cell->active_cell_index()]);
      if (layers == 2)
        {
          std::vector<bool> marked(whole.n_vertices(), false);
          for (const auto &cell : whole.active_cell_iterators())
            if (cell->subdomain_id() == rank)
              for (const unsigned int v : cell->vertex_indices())
                marked[cell->vertex_index(v)] = true;
          for (const auto &cell : whole.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              if (marked[cell->vertex_index(v)])
                cell->set_subdomain_id(rank);
        }
      auto description = TriangulationDescription::Utilities::
        create_description_from_triangulation(
          whole,
          comm,
          TriangulationDescription::Settings::default_setting,
          rank);
      if (layers == 2)
        {
          for (auto &info : description.cell_infos[0])
            {
              const auto c = CellId(info.id).get_coarse_cell_id();
              if (info.subdomain_id == rank && owner[c] != rank)
                info.subdomain_id = owner[c];
              if (info.level_subdomain_id == rank && owner[c] != rank)
                info.level_subdomain_id = owner[c];
            }
          for (const auto &cell : whole.active_cell_iterators())
            cell->set_subdomain_id(owner[cell->active_cell_index()]);
        }
      mark_rim_faces(whole, description, rank);
      return description;
    }

    template <int dim>
    std::vector<unsigned int>
    MeshGenerator<dim>::create_distributed(
      parallel::fullydistributed::Triangulation<dim> &tria,
      const unsigned int                              ghost_layers) const
    {
      AssertThrow(ghost_layers == 1 || ghost_layers == 2, ExcInternalError());
      std::vector<unsigned int> owner;
      if (create_distributed_blocks(tria, ghost_layers, owner))
        return owner;
      return create_distributed_on_root(tria, ghost_layers);
    }



    template <int dim>
    bool
    MeshGenerator<dim>::create_distributed_blocks(
      parallel::fullydistributed::Triangulation<dim> &tria,
      const unsigned int                              ghost_layers,
      std::vector<unsigned int>                      &owner) const
    {
      if constexpr (dim != 2)
        return false;
      else
        {
          const MPI_Comm       comm    = tria.get_communicator();
          const unsigned int   n_ranks = Utilities::MPI::n_mpi_processes(comm);
          const BlockPartition partition(blocks_x, blocks_y, n_ranks);
          const bool           blocks =
            type == Type::criss_cross || type == Type::diagonal;
          if (partitioner == "metis" || !blocks ||
              (partitioner == "automatic" && !partition.valid()))
            return false;
          AssertThrow(
            partition.valid(),
            ExcMessage("Mesh/Partitioner = blocks: " + std::to_string(n_ranks) +
                       " ranks do not tile " + std::to_string(blocks_x) +
                       " x " + std::to_string(blocks_y) +
                       " blocks (Mesh/Blocks x, Mesh/Blocks y) so that "
                       "each rank has a block; use fewer ranks or "
                       "Mesh/Partitioner = metis."));
          // Every rank finds what create() would refuse: all throw alike.
          check_block_shape();
          BlockMesh mesh;
          mesh.lower       = Point<2>(0, 0);
          mesh.upper       = Point<2>(length, height);
          mesh.nx          = blocks_x;
          mesh.ny          = blocks_y;
          mesh.criss_cross = type == Type::criss_cross;
          tria.create_triangulation(
            describe_block_part(mesh,
                                partition,
                                Utilities::MPI::this_mpi_process(comm),
                                ghost_layers,
                                comm));
          names = {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
          // The checkpoints' owner of every cell (4 bytes a cell).
          owner.resize(mesh.n_cells());
          for (std::size_t c = 0; c < owner.size(); ++c)
            {
              const auto [i, j] = mesh.block_of(c);
              owner[c]          = partition.owner(i, j);
            }
          return true;
        }
    }



    template <int dim>
    std::vector<unsigned int>
    MeshGenerator<dim>::create_distributed_on_root(
      parallel::fullydistributed::Triangulation<dim> &tria,
      const unsigned int                              ghost_layers) const
    {
      using Description = TriangulationDescription::Description<dim, dim>;
      const MPI_Comm            comm = tria.get_communicator();
      const unsigned int        rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int        n_ranks = Utilities::MPI::n_mpi_processes(comm);
      std::vector<unsigned int> owner;
      Triangulation<dim>        whole;
      // Every rank throws what rank 0 found: none waits for a part.
      on_root_or_throw_everywhere(comm, [&]() {
        create(whole);
        AssertThrow(whole.n_levels() == 1, ExcInternalError());
        for (const auto &face : whole.active_face_iterators())
          AssertThrow(!face->at_boundary() ||
                        face->boundary_id() != rim_boundary_id,
                      ExcMessage("Mesh/File = " + file + ": boundary tag " +
                                 std::to_string(rim_boundary_id) +
                                 " is reserved with Mesh/Distribution = "
                                 "distributed (the inner edges of a "
                                 "rank's part)."));
        GridTools::partition_triangulation(n_ranks,
                                           whole,
                                           SparsityTools::Partitioner::metis);
        owner.resize(whole.n_active_cells());
        std::vector<unsigned int> n_owned(n_ranks, 0);
        for (const auto &cell : whole.active_cell_iterators())
          {
            owner[cell->active_cell_index()] = cell->subdomain_id();
            ++n_owned[cell->subdomain_id()];
          }
        // A rank without cells would hold an empty mesh.
        AssertThrow(*std::min_element(n_owned.begin(), n_owned.end()) > 0,
                    ExcMessage("Mesh/Distribution = distributed: the mesh's " +
                               std::to_string(whole.n_active_cells()) +
                               " cells leave a rank of " +
                               std::to_string(n_ranks) +
                               " without cells of its own; use fewer ranks or "
                               "Mesh/Distribution = replicated."));
      });
      names = Utilities::MPI::broadcast(comm, names, 0);
      owner = Utilities::MPI::broadcast(comm, owner, 0);
      // One part at a time: rank 0 holds the whole mesh and one
      // description, not all of them (together about a second whole mesh).
      // The size first, then chunks below MPI's int counts.
      Description           mine;
      const int             tag   = 4711;
      constexpr std::size_t chunk = std::size_t(1) << 30;
      if (rank == 0)
        {
          for (unsigned int r = 1; r < n_ranks; ++r)
            {
              const std::vector<char> buffer = Utilities::pack(
                describe_part(whole, owner, r, ghost_layers, comm),
                false);
              const std::uint64_t size = buffer.size();
              int ierr = MPI_Send(&size, 1, MPI_UINT64_T, r, tag, comm);
              AssertThrowMPI(ierr);
              for (std::size_t k = 0; k < size; k += chunk)
                {
                  ierr = MPI_Send(buffer.data() + k,
                                  static_cast<int>(std::min(chunk, size - k)),
                                  MPI_CHAR,
                                  r,
                                  tag,
                                  comm);
                  AssertThrowMPI(ierr);
                }
            }
          mine = describe_part(whole, owner, 0, ghost_layers, comm);
          whole.clear();
        }
      else
        {
          std::uint64_t size = 0;
          int           ierr =
            MPI_Recv(&size, 1, MPI_UINT64_T, 0, tag, comm, MPI_STATUS_IGNORE);
          AssertThrowMPI(ierr);
          std::vector<char> buffer(size);
          for (std::size_t k = 0; k < size; k += chunk)
            {
              ierr = MPI_Recv(buffer.data() + k,
                              static_cast<int>(std::min(chunk, size - k)),
                              MPI_CHAR,
                              0,
                              tag,
                              comm,
                              MPI_STATUS_IGNORE);
              AssertThrowMPI(ierr);
            }
          mine = Utilities::unpack<Description>(buffer, false);
        }
      tria.create_triangulation(mine);
      return owner;
    }

    template TriangulationDescription::Description<1, 1>
    describe_part(Triangulation<1> &,
                  const std::vector<unsigned int> &,
                  unsigned int,
                  unsigned int,
                  MPI_Comm);
    template TriangulationDescription::Description<2, 2>
    describe_part(Triangulation<2> &,
                  const std::vector<unsigned int> &,
                  unsigned int,
                  unsigned int,
                  MPI_Comm);
    template std::vector<unsigned int>
    MeshGenerator<1>::create_distributed(
      parallel::fullydistributed::Triangulation<1> &,
      unsigned int) const;
    template std::vector<unsigned int>
    MeshGenerator<2>::create_distributed(
      parallel::fullydistributed::Triangulation<2> &,
      unsigned int) const;
  } // namespace Mesh
} // namespace psmpm
