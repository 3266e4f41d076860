// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_strategies_cell_fill_h
#define psmpm_solver_mass_strategies_cell_fill_h

#include <psmpm/solver/grid_system.h>

#include <algorithm>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    /**
     * Fill fraction of every owned cell (active index; 0 elsewhere): the
     * particle mass in the cell over rho |cell|, clipped to [0, 1], with
     * rho the reference (material) density. The particle mass in a cell is
     * the sum of its lumped rows (the functions of a cell sum to one).
     * @p measure caches the cell measures between calls.
     */
    template <int dim>
    std::vector<double>
    cell_fill(const GridSystem<dim> &grid, std::vector<double> &measure)
    {
      if (measure.size() != grid.n_cells)
        {
          measure.assign(grid.n_cells, 0.);
          for (const auto &cell :
               grid.get_dof_handler().active_cell_iterators())
            measure[cell->active_cell_index()] = cell->measure();
        }
      const unsigned int  n      = grid.dofs_per_cell;
      const auto         &lumped = grid.cell_arrays().lumped;
      const double        rho    = grid.reference_density();
      std::vector<double> fill(grid.n_cells, 0.);
      for (const unsigned int c : grid.owned_cells())
        {
          double m = 0;
          for (unsigned int k = 0; k < n; ++k)
            m += lumped[c * n + k];
          fill[c] = rho > 0 ? std::clamp(m / (rho * measure[c]), 0., 1.) : 1.;
        }
      return fill;
    }
  } // namespace Solver
} // namespace psmpm

#endif
