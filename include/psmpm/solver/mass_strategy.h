// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_strategy_h
#define psmpm_solver_mass_strategy_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/registry.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    template <int dim>
    class GridSystem;

    /**
     * The entries of subsection "Mass matrix" that strategies read
     * (GridSystem::strategy_parameters()), so that a strategy does not
     * depend on the solver's own entries.
     */
    struct MassStrategyParameters
    {
      /// Mass matrix/Threshold: the relative support below which a
      /// function counts as poorly supported (also given to the factory).
      double threshold = 0.05;
      /// Fictitious mass fraction alpha of the stabilised strategies
      /// (Mass matrix/Stabilization).
      double stabilization = 1;
      /// beta of SamplingStabilization (Mass matrix/Sampling
      /// stabilization; "automatic" is -1 here until the simulator
      /// resolves it, 0: off).
      double sampling_stabilization = -1;
    };

    /**
     * How the grid's mass matrix is formed from the particle mass
     * (subsection "Mass matrix", entry "Type"). A strategy decides whether
     * a sparse matrix is built at all and may, once per step before
     * assembly, change the per-cell particle mass matrices (partial
     * lumping) or the step's constraints (deactivation, extrapolation).
     * Thesis chapter 5 and beyond; doc/stability.md compares them.
     *
     * Strategies register in MassStrategyRegistry<dim>; the factory gets
     * Mass matrix/Threshold (the relative support below which a function
     * counts as poorly supported), which strategies may ignore.
     */
    template <int dim>
    class MassStrategy
    {
    public:
      virtual ~MassStrategy() = default;

      /// false: the lumped (row-sum) diagonal is the mass matrix and no
      /// sparse matrix is built.
      virtual bool
      uses_matrix() const
      {
        return true;
      }

      /// true if constraints may tie a DoF to DoFs beyond the cell's
      /// neighbours, so that every DoF must be locally relevant.
      virtual bool
      needs_all_dofs() const
      {
        return false;
      }

      /// true if the strategy needs every rank to hold the whole mesh:
      /// needs_all_dofs(), or state numbered by the whole mesh's vertices.
      virtual bool
      needs_replicated_mesh() const
      {
        return needs_all_dofs();
      }

      /// true if the strategy adds patch blocks that couple the DoFs of two
      /// cells sharing a vertex (the sparsity then couples every DoF of the
      /// cells around a vertex with every other).
      virtual bool
      needs_neighbor_couplings() const
      {
        return false;
      }

      /**
       * true if the strategy uses the shape of the cells (beyond their
       * measure), computed once on the mesh: `ghost penalty` projects onto
       * the polynomials of each pair of cells. A grid that moves with the
       * material (Transfer/Scheme = otm) keeps every cell's particles, so
       * what scales with a cell's measure and its particle mass (fill,
       * full-support diagonal, int N_k N_l of P1) is the same on the
       * initial and the moved cell for material that moves with it; the
       * shape is not, and otm rejects such a strategy.
       */
      virtual bool
      depends_on_cell_shape() const
      {
        return false;
      }

      /**
       * Called once per step after the per-cell particle mass matrices
       * are accumulated and before they are assembled. @p diagonal is the
       * particle diagonal M_ii in local relevant numbering. Returns true
       * if the step's constraints changed (the sparsity is rebuilt). It
       * may also add patch blocks (GridSystem::patch_blocks()), assembled
       * with the cell blocks.
       */
      virtual bool
      prepare(GridSystem<dim> &grid, const std::vector<double> &diagonal)
      {
        (void)grid;
        (void)diagonal;
        return false;
      }

      /**
       * What later steps depend on besides the particles (checkpoints):
       * one value per triangulation vertex, or nothing. Combined over the
       * ranks by their maximum (a rank contributes 0 where it does not
       * know), so that a checkpoint resumes on any number of ranks.
       */
      virtual std::vector<double>
      history() const
      {
        return {};
      }

      /// Continue from a history() of a checkpoint; the next prepare()
      /// must then set up the step's constraints even if nothing changed.
      virtual void
      restore_history(const std::vector<double> &history)
      {
        (void)history;
      }
    };

    template <int dim>
    using MassStrategyRegistry = Registry<MassStrategy<dim>, double>;
  } // namespace Solver
} // namespace psmpm

#endif
