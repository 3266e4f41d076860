// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_strategies_poorly_supported_h
#define psmpm_solver_mass_strategies_poorly_supported_h

#include <psmpm/solver/mass_strategy.h>

#include <vector>

namespace psmpm
{
  namespace Solver
  {
    /**
     * The common part of the vertex-wise strategies: a vertex is poorly
     * supported when one of its functions has a particle diagonal M_ii
     * below Threshold times its full-support diagonal; the coefficients of
     * such vertices are constrained for the step, to zero (deactivate,
     * thesis Sec. 5.2 with a relative bound) or to the local linear part
     * of the nearest well supported vertex (extrapolate: extended
     * B-splines, Basis::Space::extrapolation_weights()).
     */
    template <int dim>
    class PoorlySupported : public MassStrategy<dim>
    {
    public:
      PoorlySupported(const double threshold, const bool extrapolate);

      bool
      needs_all_dofs() const override
      {
        return extrapolate;
      }

      /// The history (and the nearest supported vertex) is numbered by
      /// the vertices of the whole mesh.
      bool
      needs_replicated_mesh() const override
      {
        return true;
      }

      bool
      prepare(GridSystem<dim>           &grid,
              const std::vector<double> &diagonal) override;

      /// The poorly supported vertices of the last step (1 or 0): the
      /// hysteresis of the next one.
      std::vector<double>
      history() const override;

      void
      restore_history(const std::vector<double> &history) override;

    private:
      std::vector<bool>
      poorly_supported_vertices(const GridSystem<dim>     &grid,
                                const std::vector<double> &diagonal) const;
      unsigned int
      nearest_supported_vertex(const GridSystem<dim>   &grid,
                               const std::vector<bool> &outer,
                               const unsigned int       v) const;

      const double      threshold;
      const bool        extrapolate;
      std::vector<bool> previous_outer;
      /// Restored from a checkpoint: the constraints must be rebuilt.
      bool restored = false;
    };
  } // namespace Solver
} // namespace psmpm

#endif
