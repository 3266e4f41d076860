// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_cell_exchange_h
#define psmpm_solver_cell_exchange_h

#include <deal.II/grid/tria.h>

#include <psmpm/solver/ghost_exchange.h>

#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * Per-cell values of the cells that share a vertex with a rank's own
     * cells (Mesh::HeldCells), copied from their owners. The mass
     * strategies decide per cell (is it filled? how well do its particles
     * sample it?) and look across a vertex at most: the ghost penalty's
     * pairs and the partially lumped rows of a vertex.
     *
     * They used to take every cell's value from a reduction (a max) over
     * the whole mesh, every step: traffic proportional to the mesh, not
     * to a rank's interface, and only possible where every rank numbers
     * every cell alike (a replicated mesh). This goes point to point
     * through the pattern of GhostExchange, over the triangulation's
     * global active cell indices.
     */
    class CellExchange
    {
    public:
      /// Pattern for @p tria's owned cells and the cells sharing a vertex
      /// with one; nothing to do on a serial triangulation or one rank.
      template <int dim>
      void
      reinit(const Triangulation<dim> &tria);

      /// values[c] (by active cell index) of every cell sharing a vertex
      /// with an owned cell := its owner's value; the owned entries are
      /// read, others are left alone (collective).
      void
      owners_to_neighbours(double *values) const;

      /// The same for integer flags (0 or 1).
      void
      owners_to_neighbours(std::vector<int> &values) const;

    private:
      /// Both overloads: the values go as doubles (0/1 flags exactly).
      template <typename Number>
      void
      copy_from_owners(Number *values) const;

      GhostExchange exchange;
      bool          active = false;
      /// Active cell index of the i-th owned cell and of the l-th cell of
      /// the exchange's relevant set.
      std::vector<unsigned int>   owned_cells, relevant_cells;
      mutable std::vector<double> owned_values, relevant_values;
    };
  } // namespace Solver
} // namespace psmpm

#endif
