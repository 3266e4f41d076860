// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_strategy.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /**
       * Thesis Sec. 5.4 made symmetric: every coupling of a function of a
       * vertex on the material's free boundary (touching a filled and an
       * empty cell, or on a mesh boundary without Dirichlet condition) is
       * moved to both diagonals, so row sums (momentum) and definiteness
       * are kept while the matrix stays consistent inside the material.
       */
      template <int dim>
      class PartiallyLumped : public MassStrategy<dim>
      {
      public:
        bool
        prepare(GridSystem<dim> &grid, const std::vector<double> &) override
        {
          const auto boundary = free_boundary_dofs(grid);
          lump(grid, boundary);
          return false;
        }

      private:
        static std::vector<bool>
        free_boundary_dofs(GridSystem<dim> &grid)
        {
          const unsigned int n      = grid.dofs_per_cell;
          const auto        &cells  = grid.cell_arrays();
          const auto        &tables = grid.vertex_tables();
          const auto        &global = grid.relevant_global_indices();
          MPI_Comm           comm   = grid.get_communicator();
          // Filled cells, known where a vertex of an owned cell looks.
          std::vector<int> filled(grid.n_cells, 0);
          for (const unsigned int c : grid.owned_cells())
            for (unsigned int k = 0; k < n; ++k)
              filled[c] |= cells.lumped[c * n + k] > 0;
          grid.cell_exchange().owners_to_neighbours(filled);

          std::vector<bool> boundary_dof(global.size(), false);
          unsigned int      n_treated = 0;
          for (unsigned int v = 0; v < tables.cells.size(); ++v)
            {
              bool any_filled = false, any_empty = false;
              for (const unsigned int c : tables.cells[v])
                (filled[c] ? any_filled : any_empty) = true;
              if (any_filled && (any_empty || tables.on_free_boundary[v]))
                for (const unsigned int l : tables.dofs[v])
                  if (l != numbers::invalid_unsigned_int)
                    {
                      boundary_dof[l] = true;
                      n_treated +=
                        grid.locally_owned_dofs().is_element(global[l]);
                    }
            }
          grid.set_n_treated_dofs(Utilities::MPI::sum(n_treated, comm));
          return boundary_dof;
        }

        /// Move every coupling that involves a boundary function to both
        /// diagonals: the change, m (e_k - e_l)(e_k - e_l)^T with m >= 0,
        /// keeps row sums and the matrix symmetric positive definite.
        static void
        lump(GridSystem<dim> &grid, const std::vector<bool> &boundary_dof)
        {
          const unsigned int n    = grid.dofs_per_cell;
          const auto        &dofs = grid.cell_dofs();
          auto              &mass = grid.cell_arrays().mass;
          for (const unsigned int c : grid.owned_cells())
            {
              double *M = &mass[c * n * n];
              for (unsigned int k = 0; k < n; ++k)
                for (unsigned int l = k + 1; l < n; ++l)
                  if (boundary_dof[dofs[c * n + k]] ||
                      boundary_dof[dofs[c * n + l]])
                    {
                      const double m = M[k * n + l];
                      M[k * n + l] = M[l * n + k] = 0;
                      M[k * n + k] += m;
                      M[l * n + l] += m;
                    }
            }
        }
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, PartiallyLumped>
      register_partiallylumped(
        "partially lumped",
        "couplings of free-boundary vertices moved to the diagonal "
        "(symmetric thesis Sec. 5.4)");
  } // namespace Solver
} // namespace psmpm
