// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// Mesh/Distribution = distributed: the whole mesh is built on rank 0
// only, and each rank receives its cells and their ghost layer.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/base/root_errors.h>
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

      /// Rank @p rank's part of @p whole (whose subdomain ids are the
      /// owners, @p owner): its cells and @p layers layers of cells around
      /// them (a cell of layer k shares a vertex with one of layer k - 1).
      /// deal.II's description holds one layer; for two, the first layer
      /// is described as the rank's own and then given back to its owners.
      template <int dim>
      TriangulationDescription::Description<dim, dim>
      describe(Triangulation<dim>              &whole,
               const std::vector<unsigned int> &owner,
               const unsigned int               rank,
               const unsigned int               layers,
               const MPI_Comm                   comm)
      {
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
    } // namespace

    template <int dim>
    std::vector<unsigned int>
    MeshGenerator<dim>::create_distributed(
      parallel::fullydistributed::Triangulation<dim> &tria,
      const unsigned int                              ghost_layers) const
    {
      AssertThrow(ghost_layers == 1 || ghost_layers == 2, ExcInternalError());
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
              const std::vector<char> buffer =
                Utilities::pack(describe(whole, owner, r, ghost_layers, comm),
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
          mine = describe(whole, owner, 0, ghost_layers, comm);
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
