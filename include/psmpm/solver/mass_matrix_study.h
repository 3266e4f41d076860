// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mass_matrix_study_h
#define psmpm_solver_mass_matrix_study_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <psmpm/base/summary.h>
#include <psmpm/solver/p_multigrid.h>

#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * A serial sparse matrix together with its sparsity pattern (deal.II's
     * SparseMatrix only points to its pattern).
     */
    struct OwnedSparseMatrix
    {
      SparsityPattern      sparsity;
      SparseMatrix<double> matrix;
    };

    /**
     * The Kronecker product A (x) B as a sparse matrix: entry
     * (i * B.m() + k, j * B.n() + l) = A(i, j) B(k, l), exact zeros left
     * out. The mass matrix of a tensor-product space is the product of the
     * univariate ones (the integrand and the Gauss rule factor).
     */
    std::unique_ptr<OwnedSparseMatrix>
    kronecker_product(const FullMatrix<double> &A, const FullMatrix<double> &B);

    /**
     * The "mass matrix study" problem (Wobbes et al. 2019
     * sections 4.6 and 4.7, Tables 4.2 to 4.4): consistent mass matrices
     * (rho = 1) of tensor-product B-splines of degree p on the unit square
     * with open uniform knot vectors, with homogeneous Dirichlet conditions
     * (matrix "bspline dirichlet": the first and last univariate function,
     * the only ones that do not vanish on the boundary, removed in each
     * direction) and without (matrix "bspline free": all functions); for
     * each degree and mesh width their condition number, the iterations of
     * CG without, with Jacobi and with AMG preconditioning, and the
     * V-cycles of p-multigrid, all to a relative residual of Tolerance
     * from a zero start. The chapter's values are those with Dirichlet
     * conditions and the right-hand side M f, f the constant 9.81 (its
     * "constant force vector"; see doc/solver_study.md).
     *
     * The 2D matrices are Kronecker products M1 (x) M1 of the univariate
     * ones (exact: rho = 1, integrand and Gauss rule factor), so the
     * condition number is cond(M1)^2 from the dense eigenvalues of M1,
     * exact and cheap at every h.
     *
     * p-multigrid: levels p, p - 1, ..., 1 ("stepwise") or p, 1
     * ("direct"), each level's matrix rediscretised; the spaces are not
     * nested (C^{p-1} splines of degree p do not contain the C^{p-2} ones
     * of degree p - 1), so the transfers are L2 projections with the
     * row-sum lumped mass matrix of the target space (Tielen et al., the
     * chapter's reference [235]): prolongation (M^L_p)^-1 P_{p,p-1},
     * restriction (M^L_{p-1})^-1 P_{p-1,p} ("projection") or the
     * prolongation's transpose ("transpose"), P the mixed mass matrices.
     */
    class MassMatrixStudy
    {
    public:
      /// One line of solver_study.tsv; invalid_unsigned_int where a count
      /// did not converge.
      struct Row
      {
        std::string  matrix;
        unsigned int degree               = 0;
        unsigned int inverse_h            = 0;
        unsigned int n_dofs               = 0;
        double       condition_number     = 0;
        unsigned int cg_iterations        = 0;
        unsigned int jacobi_cg_iterations = 0;
        unsigned int amg_cg_iterations    = 0;
        unsigned int pmg_vcycles          = 0;
      };

      /// Subsection "Mass matrix study" with subsection "Multigrid".
      static void
      declare_parameters(ParameterHandler &prm);

      /// Throws ExcMessage naming the entry on bad values.
      void
      parse_parameters(ParameterHandler &prm);

      /// The B-spline rows for all Boundary conditions x Degrees x
      /// Inverse h.
      std::vector<Row>
      compute() const;

      /// One row: degree @p p on @p inverse_h elements per direction, with
      /// or without the boundary functions.
      Row
      compute(const unsigned int p,
              const unsigned int inverse_h,
              const bool         dirichlet) const;

      /**
       * compute(), then solver_study.tsv into @p output_directory (rank 0)
       * and n_rows, largest condition number and iteration counts into
       * @p summary.
       */
      void
      run(const std::string    &output_directory,
          Summary &summary,
          MPI_Comm              comm) const;

      /// Writes @p rows as the tab-separated table ("-": not converged).
      static void
      write_table(const std::string &filename, const std::vector<Row> &rows);

      std::vector<unsigned int> degrees   = {1, 2, 3, 4, 5};
      std::vector<unsigned int> inverse_h = {8, 16, 32, 64, 128};
      double                    tolerance = 1e-8;
      /// "row sums": b = M f, f_j = g (the solution is the constant g; the
      /// chapter's setting); "load vector": b_i = g int phi_i (a constant
      /// body force g); "constant": b_i = g.
      std::string right_hand_side = "row sums";
      /// Rows with (true) and without (false) the boundary functions.
      std::vector<bool> dirichlet      = {true, false};
      unsigned int      max_iterations = 20000;
      /// "stepwise" (p, p-1, ..., 1) or "direct" (p, 1).
      std::string hierarchy = "stepwise";
      /// "projection" or "transpose".
      std::string restriction = "projection";
      /// Smoother default: plain (forward) Gauss-Seidel, the chapter's
      /// "Gauss-Seidel".
      PMultigrid::Parameters multigrid = forward_gauss_seidel();

    private:
      static PMultigrid::Parameters
      forward_gauss_seidel()
      {
        PMultigrid::Parameters p;
        p.smoother = "forward gauss-seidel";
        return p;
      }
    };
  } // namespace Solver
} // namespace psmpm

#endif
