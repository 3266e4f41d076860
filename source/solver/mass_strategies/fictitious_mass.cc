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
       * Finite-cell (fictitious domain) stabilisation of the consistent
       * mass: on every cell, alpha rho (1 - fill) int_cell N_k N_l is added
       * to the particle mass matrix for each pair of functions that carry
       * particle mass (fill: particle mass over rho |cell|, clipped to
       * [0, 1]; alpha: Mass matrix/Stabilization). Where the cells are
       * filled the matrix is the consistent one exactly; a function whose
       * support holds few particles gets at least alpha (1 - fill) of its
       * full-support mass, so the matrix stays symmetric positive definite
       * with a condition number bounded independently of how close to the
       * edge of a support a particle sits. The price: the fictitious mass
       * receives no force, so momentum and the acceleration of the
       * surface functions are off by O(alpha (1 - fill)).
       */
      template <int dim>
      class FictitiousMass : public MassStrategy<dim>
      {
      public:
        bool
        prepare(GridSystem<dim> &grid, const std::vector<double> &) override
        {
          const double alpha = grid.strategy_parameters().stabilization;
          if (alpha == 0)
            return false;
          const unsigned int n = grid.dofs_per_cell;
          if (exact.empty())
            compute_exact_cell_matrices(grid);
          const std::vector<double> fill   = cell_fill(grid, measure);
          const auto               &dofs   = grid.cell_dofs();
          const auto               &active = grid.lumped_mass();
          auto                     &mass   = grid.cell_arrays().mass;
          const double              rho    = grid.reference_density();
          std::vector<bool>         treated(active.size(), false);
          for (const unsigned int c : grid.owned_cells())
            {
              const double w = alpha * rho * (1. - fill[c]);
              if (!(w > 0))
                continue;
              const double *E = &exact[c * n * n];
              double       *M = &mass[c * n * n];
              for (unsigned int k = 0; k < n; ++k)
                {
                  const unsigned int lk = dofs[c * n + k];
                  if (!(active[lk] > 0))
                    continue;
                  treated[lk] = true;
                  for (unsigned int l = 0; l < n; ++l)
                    if (active[dofs[c * n + l]] > 0)
                      M[k * n + l] += w * E[k * n + l];
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
        /// int_cell N_k N_l of every owned cell with the space's exact
        /// cell quadrature (the mesh does not move).
        void
        compute_exact_cell_matrices(const GridSystem<dim> &grid)
        {
          const unsigned int  n     = grid.dofs_per_cell;
          const auto         &space = grid.get_space();
          const auto         &dh    = grid.get_dof_handler();
          std::vector<double> values(n);
          exact.assign(grid.n_cells * n * n, 0.);
          for (const unsigned int c : grid.owned_cells())
            {
              const Quadrature<dim> q = space.cell_quadrature(dh, c);
              double               *E = &exact[c * n * n];
              for (unsigned int i = 0; i < q.size(); ++i)
                {
                  space.evaluate(c, q.point(i), values.data(), nullptr);
                  for (unsigned int k = 0; k < n; ++k)
                    for (unsigned int l = 0; l < n; ++l)
                      E[k * n + l] += q.weight(i) * values[k] * values[l];
                }
            }
        }

        std::vector<double> exact;
        std::vector<double> measure;
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, FictitiousMass>
      register_fictitious_mass(
        "fictitious mass",
        "consistent particle mass plus alpha rho (1 - fill) int N_k N_l on "
        "every cell (finite-cell stabilisation, alpha = Stabilization)");
  } // namespace Solver
} // namespace psmpm
