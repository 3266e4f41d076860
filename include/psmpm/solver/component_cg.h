// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_component_cg_h
#define psmpm_solver_component_cg_h

#include <psmpm/solver/vertex_block_jacobi.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <memory>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    /**
     * Preconditioned CG for the velocity (or acceleration) components of
     * MPM at once: column d of X solves P_d M P_d x_d = P_d b_d, with M
     * one mass matrix shared by all components and P_d the projection
     * that zeroes the DoFs of component d fixed by homogeneous Dirichlet
     * conditions. Every column runs its own CG recurrence (its own
     * alpha, beta, stopping test and iteration count; the iterates are
     * those of separate CG solves with the constrained matrices), but
     * the columns share each product with M and each reduction.
     *
     * Why: the mass solves of Powell-Sabin are bound by reading the
     * matrix (about 27 entries per row, 12 bytes each, against 8 bytes
     * per vector entry), so dim separate solves read the same values dim
     * times and assemble dim copies. Here M is assembled once and read
     * once per iteration for all components, and the per-column dot products of
     * an iteration go through two MPI reductions for all columns.
     *
     * The preconditioner of column d is a VertexBlockJacobi built from M
     * with the fixed DoFs of component d masked (zero rows and columns).
     */
    class ComponentCG
    {
    public:
      /// Per column: iterations to convergence, and the largest CG
      /// (Lanczos) estimate of the preconditioned condition number, as
      /// SolverCG's condition-number signal computes it.
      struct Result
      {
        std::vector<unsigned int> iterations;
        double                    condition_number = 0;
      };

      /// Check the structure of @p M after every change of its sparsity
      /// (not of its values): whether its rows come in vertex triples.
      void
      reinit(const Epetra_CrsMatrix &M);

      /// Whether the last reinit() found vertex triples.
      bool
      uses_triples() const
      {
        return triples;
      }

      /**
       * Solve from the guess in @p x (zero on the fixed rows) until
       * ||r_d|| <= @p tolerance ||b_d|| or, from a guess that is not zero,
       * ||r_d|| <= @p step_tolerances[d] ||b_d - M x_d|| (the residual of
       * the guess: what the step changes), for every column d.
       * @p fixed[d] lists the locally owned rows (local indices of M's row
       * map) fixed for column d; their entries of @p b must be zero and stay
       * zero in @p x. Throws
       * SolverControl::NoConvergence if a column needs more than
       * @p max_iterations.
       */
      Result
      solve(const Epetra_CrsMatrix                       &M,
            const std::vector<const VertexBlockJacobi *> &preconditioners,
            const std::vector<std::vector<unsigned int>> &fixed,
            Epetra_MultiVector                           &x,
            const Epetra_MultiVector                     &b,
            const double                                  tolerance,
            const std::vector<double>                    &step_tolerances,
            const unsigned int                            max_iterations);

    private:
      struct Recurrence;

      /// The work vectors r, z, p, q for the map and width of @p b.
      void
      allocate(const Epetra_MultiVector &b);
      /// r = b - M x, z = B r, each column's stopping limit and whether
      /// it is still active.
      void
      start(const Epetra_CrsMatrix                       &M,
            const std::vector<const VertexBlockJacobi *> &preconditioners,
            const std::vector<std::vector<unsigned int>> &fixed,
            const Epetra_MultiVector                     &x,
            const Epetra_MultiVector                     &b,
            const double                                  tolerance,
            const std::vector<double>                    &step_tolerances,
            Recurrence                                   &s);
      /// p = z + beta p on the active columns (iteration @p it).
      void
      update_directions(const unsigned int it, Recurrence &s);
      /// q = M p, then x += alpha p, r -= alpha q, z = B r, with one
      /// reduction for alpha and one for ||r|| and r.z.
      void
      iterate(const Epetra_CrsMatrix                       &M,
              const std::vector<const VertexBlockJacobi *> &preconditioners,
              const std::vector<std::vector<unsigned int>> &fixed,
              Epetra_MultiVector                           &x,
              Recurrence                                   &s);
      /// The Lanczos rows of the step and each column's stopping test;
      /// throws SolverControl::NoConvergence past @p max_iterations.
      void
      check_convergence(const unsigned int it,
                        const unsigned int max_iterations,
                        Recurrence        &s,
                        Result            &result);

      /// q = M v on @p columns (the work vector q), and v . q per column
      /// into @p v_q[column].
      void
      product(const Epetra_CrsMatrix   &M,
              const Epetra_MultiVector &v,
              const std::vector<int>   &columns,
              double                   *v_q);

      /// Work vectors, kept between solves of the same map and width.
      std::unique_ptr<Epetra_MultiVector> r, z, p, q;
      /// p in the matrix' column map (other ranks' entries), if it has one.
      std::unique_ptr<Epetra_MultiVector> ghosted;
      /// reinit(): rows in triples of equal columns, stored as triples of
      /// consecutive columns (3 x 3 blocks, Powell-Sabin).
      bool triples = false;
    };
  } // namespace Solver
} // namespace psmpm

#endif
