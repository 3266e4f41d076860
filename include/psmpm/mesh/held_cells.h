// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_held_cells_h
#define psmpm_mesh_held_cells_h

#include <deal.II/grid/tria.h>

#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * The cells of a replicated mesh (parallel::shared) for which this
     * rank keeps per-cell data, and where in a compact array. Every rank
     * holds the whole triangulation, but per-cell data beyond it (the
     * Powell-Sabin coefficients, 3 kB a cell) need only be where a rank
     * works: its own cells and the layer of cells sharing a vertex with
     * one (the ghost penalty couples such pairs; nothing reaches further),
     * or only its own cells where nothing looks across (the Taylor least
     * squares rules).
     * Holding all of them made a rank's memory independent of its share
     * of the mesh (doc/performance.md, "Per-rank memory").
     *
     * On one rank, or on a serial triangulation, every cell is held at its
     * active cell index: no table, and slot() is the identity.
     */
    class HeldCells
    {
    public:
      static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

      /// Holds every cell of @p tria if it is serial or on one rank, else
      /// the locally owned cells and, if @p with_neighbours, the cells
      /// sharing a vertex with one.
      template <int dim>
      void
      reinit(const Triangulation<dim> &tria, const bool with_neighbours = true);

      /// Number of cells held (the size of a compact per-cell array).
      unsigned int
      size() const
      {
        return n_held;
      }

      /// Whether every cell is held at its own index.
      bool
      holds_all() const
      {
        return slots.empty();
      }

      /// Position of active cell @p cell in a compact array, or invalid.
      unsigned int
      slot(const unsigned int cell) const
      {
        return slots.empty() ? cell : slots[cell];
      }

    private:
      std::vector<unsigned int> slots;
      unsigned int              n_held = 0;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
