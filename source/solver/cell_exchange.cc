// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/distributed/tria_base.h>

#include <psmpm/mesh/held_cells.h>
#include <psmpm/solver/cell_exchange.h>

#include <algorithm>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    void
    CellExchange::reinit(const Triangulation<dim> &tria)
    {
      const auto *par =
        dynamic_cast<const parallel::TriangulationBase<dim> *>(&tria);
      active = par != nullptr &&
               Utilities::MPI::n_mpi_processes(par->get_communicator()) > 1;
      owned_cells.clear();
      relevant_cells.clear();
      if (!active)
        return;

      const auto partitioner =
        par->global_active_cell_index_partitioner().lock();
      const IndexSet &owned = partitioner->locally_owned_range();
      // The owned cells and those sharing a vertex with one: the cells a
      // rank holds per-cell data for.
      Mesh::HeldCells held;
      held.reinit(tria);
      IndexSet relevant(owned.size());
      relevant.add_indices(owned);
      std::vector<std::pair<types::global_cell_index, unsigned int>> cells;
      for (const auto &cell : tria.active_cell_iterators())
        if (held.slot(cell->active_cell_index()) != Mesh::HeldCells::invalid)
          cells.emplace_back(cell->global_active_cell_index(),
                             cell->active_cell_index());
      std::sort(cells.begin(), cells.end());
      for (const auto &c : cells)
        relevant.add_index(c.first);
      relevant.compress();
      exchange.reinit(owned, relevant, par->get_communicator());
      // Both sets in increasing global index: the exchange's order.
      for (const auto &c : cells)
        {
          relevant_cells.push_back(c.second);
          if (owned.is_element(c.first))
            owned_cells.push_back(c.second);
        }
      AssertDimension(owned_cells.size(), owned.n_elements());
      owned_values.resize(owned_cells.size());
    }

    template <typename Number>
    void
    CellExchange::copy_from_owners(Number *values) const
    {
      if (!active)
        return;
      for (std::size_t i = 0; i < owned_cells.size(); ++i)
        owned_values[i] = values[owned_cells[i]];
      exchange.owned_to_relevant(owned_values.data(), relevant_values);
      for (std::size_t l = 0; l < relevant_cells.size(); ++l)
        values[relevant_cells[l]] = static_cast<Number>(relevant_values[l]);
    }

    void
    CellExchange::owners_to_neighbours(double *values) const
    {
      copy_from_owners(values);
    }

    void
    CellExchange::owners_to_neighbours(std::vector<int> &values) const
    {
      copy_from_owners(values.data());
    }

    template void
    CellExchange::reinit(const Triangulation<1> &);
    template void
    CellExchange::reinit(const Triangulation<2> &);
  } // namespace Solver
} // namespace psmpm
