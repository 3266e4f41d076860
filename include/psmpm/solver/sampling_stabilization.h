// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_sampling_stabilization_h
#define psmpm_solver_sampling_stabilization_h


#include <array>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    class GridSystem;

    /**
     * Mass matrix/Sampling stabilization: the particle mass matrix
     * M = sum_p m_p N(x_p) N(x_p)^T is a quadrature of the exact one with
     * the particles as points. A quadratic space has more functions per
     * cell (Powell-Sabin: 9) than a few particles determine, and a sparse
     * layout (2 or 3 particles per triangle) leaves fields that vanish at
     * every particle: M is singular or nearly so in cells that are full,
     * where no emptying-cell strategy looks, and the run blows up at any
     * time step (doc/stability.md, "Sparse particle layouts").
     *
     * On each cell c, S_c = int_c (u - P_c u)(v - P_c v), P_c the L2
     * projection onto the polynomials of the space's degree
     * (polynomial_complement()), vanishes on those polynomials (row sums,
     * affine and quadratic fields are kept) and acts on the cell's
     * n_modes other modes. With Q_c those modes, orthonormal in the exact
     * cell mass matrix, A = Q_c^T M_c Q_c / rho_c (rho_c: particle mass
     * over |c|) is the identity where the particles integrate like the
     * exact integral. A cell whose smallest eigenvalue lambda of A is
     * below the target t gets rho_c (t - lambda) S_c, which lifts it to t
     * (Q_c^T S_c Q_c = I); well-sampled cells get nothing.
     *
     * The quadratic modes (the quadratics E_c-orthogonal to the affine
     * fields, Q_q, S_q = E_c Q_q Q_q^T E_c = S_1 - S_c with S_1 the
     * complement of the affine fields) get the same test: particles on
     * two lines per cell row do not see the quadratic that vanishes on
     * both lines, S_c is zero on it, and the matrix stays singular (the
     * thesis bar with 5 x 2 particles per block went unstable at the
     * automatic time step). There only the unseen directions, the
     * eigenvectors of Q_q^T M_c Q_q / rho_c below t, are lifted to t, so
     * the quadratics that the particles do see keep their particle mass;
     * S_q is zero on the affine fields and on the non-polynomial modes.
     *
     * S_c, Q_c and Q_q are mesh data, computed in reinit(); each step weigh()
     * reads the particle blocks (before the mass strategy changes them)
     * and apply() adds the weighted S_c and the lifts (after it).
     */
    template <int dim>
    class SamplingStabilization
    {
    public:
      /// @p target: the smallest relative mass of the non-polynomial modes
      /// that a cell keeps (0: off).
      explicit SamplingStabilization(const double target);

      /// Compute the cell matrices of @p grid's owned cells (mesh data,
      /// once per mesh or partition), if acts_on(); forget them otherwise.
      void
      reinit(const GridSystem<dim> &grid);

      /// The step's cell weights, from the particle mass blocks as the
      /// particles left them (before a mass strategy changes them).
      /// Returns the number of owned cells with a weight.
      unsigned int
      weigh(const GridSystem<dim> &grid);

      /// Add the weighted cell matrices to the particle mass blocks of
      /// @p grid's owned cells (after the mass strategy's prepare()).
      void
      apply(GridSystem<dim> &grid) const;

      /// Whether @p grid's space has the n_modes non-polynomial modes per
      /// cell this handles; P1 has none and is left alone.
      bool
      acts_on(const GridSystem<dim> &grid) const;

    private:
      /// Functions per cell and non-polynomial modes of the spaces handled
      /// (Powell-Sabin and quadratic tensor B-splines in 2D: 9 functions,
      /// the 6 quadratics).
      static constexpr unsigned int n_functions = 9;
      static constexpr unsigned int n_modes     = 3;
      const double                  target;
      /// Per owned cell (owned_cells() order): S_c, n x n row-major.
      std::vector<double> complement;
      /// Per owned cell: the factor F = E_c Q_q of the quadratic modes'
      /// S_q = F F^T, n x n_modes row-major.
      std::vector<double> quadratic_factor;
      /// Per owned cell: the E_c-orthonormal bases Q_c of the
      /// non-polynomial modes and Q_q of the quadratic ones, side by side,
      /// n x 2 n_modes row-major (Q^T S_c Q = I, Q_q^T S_q Q_q = I).
      std::vector<double> basis;
      /// Per owned cell: 1 / |c|.
      std::vector<double> inverse_measure;
      /// Per owned cell: the step's weight of S_c.
      std::vector<double> weights;
      /// A cell's lift of its unseen quadratic modes: M_c += G G^T, G
      /// n x n_modes row-major (zero columns for the modes it sees).
      struct Lift
      {
        unsigned int                              cell; ///< owned_cells() index
        std::array<double, n_functions * n_modes> columns;
      };
      /// The step's lifts (usually none: only sparse layouts need them).
      std::vector<Lift> quadratic_lifts;

      /// Add owned cell @p i's lift of the quadratic modes whose particle
      /// mass @p B (Q_q^T M_c Q_q, upper triangle) leaves below the target
      /// of the cell's density @p rho: each such eigenvector to the target.
      void
      lift_unseen_quadratics(const unsigned int i,
                             const double       rho,
                             double (&B)[n_modes][n_modes]);
    };
  } // namespace Solver
} // namespace psmpm

#endif
