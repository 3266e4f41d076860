// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>

#include <psmpm/mesh/held_cells.h>

namespace psmpm
{
  namespace Mesh
  {
    template <int dim>
    void
    HeldCells::reinit(const Triangulation<dim> &tria,
                      const bool                with_neighbours)
    {
      slots.clear();
      n_held = tria.n_active_cells();
      const auto *par =
        dynamic_cast<const parallel::TriangulationBase<dim> *>(&tria);
      if (par == nullptr ||
          Utilities::MPI::n_mpi_processes(par->get_communicator()) == 1)
        return;

      // Owned cells mark their vertices; a cell touching a marked vertex
      // is held. Slots follow the active cell order, so a loop over the
      // held cells reads the compact array forwards.
      std::vector<bool> marked(tria.n_vertices(), false);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            marked[cell->vertex_index(v)] = true;
      slots.assign(tria.n_active_cells(), invalid);
      n_held = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          bool held = cell->is_locally_owned();
          if (with_neighbours)
            for (const unsigned int v : cell->vertex_indices())
              held = held || marked[cell->vertex_index(v)];
          if (held)
            slots[cell->active_cell_index()] = n_held++;
        }
    }

    template void
    HeldCells::reinit(const Triangulation<1> &, bool);
    template void
    HeldCells::reinit(const Triangulation<2> &, bool);
  } // namespace Mesh
} // namespace psmpm
