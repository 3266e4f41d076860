// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_p_multigrid_h
#define psmpm_solver_p_multigrid_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * A multigrid V-cycle over a hierarchy of discretisations that need
     * not be nested (p-multigrid, Wobbes et al. 2019 section 4.7, after
     * Tielen et al.): on every level but the coarsest, pre-smoothing, the
     * restricted residual, the coarse correction (recursively), its
     * prolongation and post-smoothing; on the coarsest level the residual
     * equation is solved by unpreconditioned CG to a relative residual of
     * coarse_tolerance (the chapter: 1e-4 at p = 1). With one level only
     * (p = 1 itself) a cycle is smoothing, the CG correction and smoothing
     * on that level, so that p = 1 is counted the same way as the others.
     *
     * The operators are serial deal.II matrices owned by the caller; the
     * transfers are arbitrary matrices (for p-multigrid the lumped L2
     * projections, see MassMatrixStudy), so the class knows nothing of
     * splines.
     */
    class PMultigrid
    {
    public:
      struct Parameters
      {
        /// nu_1 and nu_2 (the chapter: 8 and 8).
        unsigned int pre_smoothing  = 8;
        unsigned int post_smoothing = 8;
        /// "gauss-seidel": forward sweeps before, backward sweeps after the
        /// coarse correction (a symmetric cycle); "forward gauss-seidel":
        /// forward sweeps both times; "jacobi": damped Jacobi.
        std::string smoother = "gauss-seidel";
        /// Damping of the Jacobi smoother.
        double jacobi_damping = 2. / 3.;
        /// Relative residual of the coarsest-level CG.
        double coarse_tolerance = 1e-4;
        /// Cycles before solve() gives up.
        unsigned int max_cycles = 1000;
      };

      /**
       * Level l = 0 (coarsest) to L (finest): matrices[l];
       * prolongations[l] maps level l - 1 to level l, restrictions[l] level
       * l to level l - 1 (entries 0 are unused). A null restriction is the
       * transpose of the prolongation (applied by Tvmult: a Galerkin
       * hierarchy needs no second matrix). The matrices must outlive this
       * object.
       */
      PMultigrid(const Parameters                                &parameters,
                 const std::vector<const SparseMatrix<double> *> &matrices,
                 const std::vector<const SparseMatrix<double> *> &prolongations,
                 const std::vector<const SparseMatrix<double> *> &restrictions);

      /**
       * V-cycles on the finest level from @p x until the residual is below
       * @p tolerance times the initial one (chapter eq. 4.53); returns the
       * number of cycles, or numbers::invalid_unsigned_int if max_cycles
       * did not suffice.
       */
      unsigned int
      solve(const Vector<double> &b,
            Vector<double>       &x,
            const double          tolerance) const;

      /**
       * Replace the coarsest-level CG by @p solver (x = A_0^{-1} b, e.g. a
       * direct factorisation): a V-cycle used as a CG preconditioner must
       * be a fixed linear operator, which an inner CG to a loose tolerance
       * is not.
       */
      void
      set_coarse_solver(
        std::function<void(Vector<double> &, const Vector<double> &)> solver)
      {
        coarse_solver = std::move(solver);
      }

      /// One V-cycle on level @p level.
      void
      vcycle(const unsigned int    level,
             const Vector<double> &b,
             Vector<double>       &x) const;

    private:
      void
      smooth(const unsigned int    level,
             const Vector<double> &b,
             Vector<double>       &x,
             const bool            pre) const;

      void
      coarse_correction(const Vector<double> &b, Vector<double> &x) const;

      Parameters                                parameters;
      std::vector<const SparseMatrix<double> *> matrices;
      std::vector<const SparseMatrix<double> *> prolongations;
      std::vector<const SparseMatrix<double> *> restrictions;
      std::function<void(Vector<double> &, const Vector<double> &)>
        coarse_solver;
      /// Per level: residual, restricted residual and coarse correction
      /// (kept so that a cycle, which a CG preconditioner runs once per
      /// iteration, allocates nothing).
      mutable std::vector<Vector<double>> residuals, coarse_rhs,
        coarse_solution;
    };
  } // namespace Solver
} // namespace psmpm

#endif
