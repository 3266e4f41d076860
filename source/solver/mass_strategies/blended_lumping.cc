// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_strategies/cell_fill.h>
#include <psmpm/solver/mass_strategy.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /**
       * Cell-wise partial lumping graded by the fill of the cell: the
       * particle mass block of cell c becomes (1 - theta) M_c +
       * theta lump(M_c), theta = min(1, 2 (1 - fill)) (fill: particle mass
       * over rho |cell|). Filled cells stay consistent (also at a free
       * mesh boundary, unlike `partially lumped`), cells at most half
       * filled are lumped, in between the couplings move to the diagonal
       * in proportion. Each moved coupling is m (e_k - e_l)(e_k - e_l)^T
       * with m >= 0, so row sums (momentum) and definiteness are kept.
       */
      template <int dim>
      class BlendedLumping : public MassStrategy<dim>
      {
      public:
        bool
        prepare(GridSystem<dim> &grid, const std::vector<double> &) override
        {
          const unsigned int        n    = grid.dofs_per_cell;
          const std::vector<double> fill = cell_fill(grid, measure);
          const auto               &dofs = grid.cell_dofs();
          auto                     &mass = grid.cell_arrays().mass;
          std::vector<bool>         treated(grid.lumped_mass().size(), false);
          for (const unsigned int c : grid.owned_cells())
            {
              const double theta = std::min(1., 2. * (1. - fill[c]));
              if (!(theta > 0))
                continue;
              double *M = &mass[c * n * n];
              for (unsigned int k = 0; k < n; ++k)
                for (unsigned int l = k + 1; l < n; ++l)
                  {
                    const double m = theta * M[k * n + l];
                    if (m == 0)
                      continue;
                    M[k * n + l] -= m;
                    M[l * n + k] -= m;
                    M[k * n + k] += m;
                    M[l * n + l] += m;
                    treated[dofs[c * n + k]] = treated[dofs[c * n + l]] = true;
                  }
            }
          unsigned int n_treated = 0;
          const auto  &global    = grid.relevant_global_indices();
          for (unsigned int l = 0; l < treated.size(); ++l)
            n_treated +=
              treated[l] && grid.locally_owned_dofs().is_element(global[l]);
          grid.set_n_treated_dofs(
            Utilities::MPI::sum(n_treated, grid.get_communicator()));
          return false;
        }

      private:
        std::vector<double> measure;
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, BlendedLumping>
      register_blended_lumping(
        "blended lumping",
        "particle mass block of each cell lumped in proportion to its "
        "emptiness, theta = min(1, 2 (1 - fill)); filled cells consistent");
  } // namespace Solver
} // namespace psmpm
