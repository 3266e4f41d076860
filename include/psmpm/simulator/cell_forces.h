// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_cell_forces_h
#define psmpm_simulator_cell_forces_h

#include <deal.II/base/tensor.h>

#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * Forces that belong to cells rather than to particles: for each
     * listed cell, one vector per function of the cell, added to the cell
     * right-hand sides (index cell * functions + k) by every pass that
     * sums the particles' forces there. VolumetricAveraging puts the
     * exactly integrated pressure of the cells inside one body here.
     */
    template <int dim>
    struct CellForces
    {
      std::vector<unsigned int>   cells;
      std::vector<Tensor<1, dim>> forces; ///< functions per listed cell

      void
      clear()
      {
        cells.clear();
        forces.clear();
      }

      /// rhs[c * n + k] += weight * force k of listed cell c.
      void
      add_to(Tensor<1, dim>    *rhs,
             const unsigned int n,
             const double       weight) const
      {
        for (std::size_t i = 0; i < cells.size(); ++i)
          for (unsigned int k = 0; k < n; ++k)
            rhs[std::size_t(cells[i]) * n + k] += weight * forces[i * n + k];
      }
    };
  } // namespace Simulator
} // namespace psmpm

#endif
