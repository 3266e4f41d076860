// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/vector.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/polynomial_complement.h>
#include <psmpm/solver/sampling_stabilization.h>
#include <psmpm/solver/symmetric_3x3.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Eigenvalues @p values and eigenvectors (the columns of @p V) of
      /// the symmetric 3 x 3 matrix @p A, by cyclic Jacobi rotations to
      /// round-off (repeated and zero eigenvalues alike; no allocation).
      void
      eigen_3x3(double (&A)[3][3], double (&values)[3], double (&V)[3][3])
      {
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            V[i][j] = i == j;
        for (unsigned int sweep = 0; sweep < 50; ++sweep)
          {
            const double off =
              A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
            const double diagonal =
              A[0][0] * A[0][0] + A[1][1] * A[1][1] + A[2][2] * A[2][2];
            if (!(off > 1e-32 * diagonal))
              break;
            for (unsigned int p = 0; p < 2; ++p)
              for (unsigned int q = p + 1; q < 3; ++q)
                {
                  if (A[p][q] == 0)
                    continue;
                  const double theta = (A[q][q] - A[p][p]) / (2 * A[p][q]);
                  const double t =
                    (theta >= 0 ? 1. : -1.) /
                    (std::abs(theta) + std::sqrt(theta * theta + 1));
                  const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                  // A <- J^T A J, V <- V J with the rotation J in (p, q).
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const double akp = A[k][p], akq = A[k][q];
                      A[k][p] = c * akp - s * akq;
                      A[k][q] = s * akp + c * akq;
                    }
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const double apk = A[p][k], aqk = A[q][k];
                      A[p][k] = c * apk - s * aqk;
                      A[q][k] = s * apk + c * aqk;
                    }
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const double vkp = V[k][p], vkq = V[k][q];
                      V[k][p] = c * vkp - s * vkq;
                      V[k][q] = s * vkp + c * vkq;
                    }
                }
          }
        for (unsigned int i = 0; i < 3; ++i)
          values[i] = A[i][i];
      }

      /// Eigenpairs of the symmetric 3 x 3 matrix @p A as eigen_3x3(),
      /// in closed form: the eigenvalues from closed_form(), an
      /// eigenvector as the longest cross product of two rows of
      /// A - lambda I. Where two eigenvalues are too close for that to
      /// be accurate, eigen_3x3(). A tenth of the Jacobi rotations'
      /// instructions (the throughput bar lifts ~5,000 cells per step).
      void
      eigenpairs_3x3(double (&A)[3][3], double (&values)[3], double (&V)[3][3])
      {
        const auto   c = closed_form(A);
        const double q = c.q, p = c.p, phi = c.phi;
        const double scale =
          std::max({std::abs(A[0][0]), std::abs(A[1][1]), std::abs(A[2][2])});
        if (!(p > 1e-6 * scale))
          return eigen_3x3(A, values, V);
        values[0] = q + 2 * p * std::cos(phi);
        values[2] = q + 2 * p * std::cos(phi + 2 * M_PI / 3);
        values[1] = 3 * q - values[0] - values[2];
        if (!(values[0] - values[1] > 1e-6 * p &&
              values[1] - values[2] > 1e-6 * p))
          return eigen_3x3(A, values, V);
        for (unsigned int j = 0; j < 3; ++j)
          {
            double R[3][3];
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                R[a][b] = A[a][b] - (a == b ? values[j] : 0.);
            double best[3] = {}, best_norm = 0;
            for (unsigned int a = 0; a < 3; ++a)
              {
                const unsigned int b = (a + 1) % 3;
                const double c[3]    = {R[a][1] * R[b][2] - R[a][2] * R[b][1],
                                        R[a][2] * R[b][0] - R[a][0] * R[b][2],
                                        R[a][0] * R[b][1] - R[a][1] * R[b][0]};
                const double norm    = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
                if (norm > best_norm)
                  {
                    best_norm = norm;
                    for (unsigned int k = 0; k < 3; ++k)
                      best[k] = c[k];
                  }
              }
            const double length = std::sqrt(best_norm);
            for (unsigned int k = 0; k < 3; ++k)
              V[k][j] = best[k] / length;
          }
      }

      /// Scratch space of modes_of(), kept across the cells of reinit():
      /// allocated at the first cell and reused (FullMatrix and Vector
      /// keep their memory when reinitialised to the same size).
      struct ModesScratch
      {
        FullMatrix<double>        W, rows, RT, L, LT, X;
        Vector<double>            column, y, x, x_row, q_row;
        std::vector<unsigned int> pivots;
        std::vector<bool>         used;
      };

      /// An E-orthonormal basis of the modes that S acts on, as the
      /// columns of the n x n_modes matrix @p Q (@p name names them in the
      /// error). E is the cell's exact mass matrix and S = E P, P the
      /// E-orthogonal projection onto the modes (I - P_2 for the
      /// non-polynomial modes, P_2 - P_1 for the quadratic ones), so
      /// X = E^-1 S = P and the E-inner products of X's columns are
      /// X^T E X = S X = S. A Cholesky factorization of S with diagonal
      /// pivoting, stopped after n_modes steps, picks n_modes columns of
      /// X that span the modes: with S_pp = R^T R, Q = X_p R^-1 has
      /// Q^T E Q = I. Three solves with E and a 3 x 3 triangle, where a
      /// symmetric eigensolver (LAPACK) would cost three
      /// quarters of the set-up's instructions.
      void
      modes_of(const FullMatrix<double> &E,
               const FullMatrix<double> &S,
               const unsigned int        n_modes,
               const unsigned int        cell,
               const std::string        &name,
               ModesScratch             &scratch,
               FullMatrix<double>       &Q)
      {
        const unsigned int n = E.m();
        // Pivoted Cholesky of S: W holds the Schur complement, the rows
        // of R (below) are the rows of `rows`.
        auto &W = scratch.W, &rows = scratch.rows;
        W = S;
        rows.reinit(n_modes, n);
        auto &pivots = scratch.pivots;
        pivots.clear();
        double largest = 0;
        for (unsigned int k = 0; k < n; ++k)
          largest = std::max(largest, S(k, k));
        const double tolerance = 1e-8 * largest;
        const auto   error     = [&](const std::string &what) {
          return ExcMessage("Sampling stabilization: cell " +
                            std::to_string(cell) + " has " + what + " " + name +
                            " modes, expected " + std::to_string(n_modes) +
                            ".");
        };
        auto &used = scratch.used;
        used.assign(n, false);
        for (unsigned int r = 0; r <= n_modes; ++r)
          {
            unsigned int j = n;
            for (unsigned int k = 0; k < n; ++k)
              if (!used[k] && (j == n || W(k, k) > W(j, j)))
                j = k;
            const double d = j < n ? W(j, j) : 0.;
            if (r == n_modes)
              {
                // The rank of S is n_modes: nothing may be left.
                AssertThrow(!(d > tolerance), error("more"));
                break;
              }
            AssertThrow(d > tolerance, error("fewer"));
            used[j] = true;
            pivots.push_back(j);
            const double root = std::sqrt(d);
            for (unsigned int k = 0; k < n; ++k)
              rows(r, k) = W(j, k) / root;
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int l = 0; l < n; ++l)
                W(k, l) -= rows(r, k) * rows(r, l);
          }
        // R(r, q) = row_r[p_q] gives S_pp = R^T R; it is upper
        // triangular, since a pivot's row and column of W vanish after
        // its step. Stored transposed: Q = X_p R^-1 is, row by row, a
        // forward substitution with R^T.
        auto &RT = scratch.RT;
        RT.reinit(n_modes, n_modes);
        for (unsigned int r = 0; r < n_modes; ++r)
          for (unsigned int q = 0; q < n_modes; ++q)
            RT(q, r) = rows(r, pivots[q]);

        // X_p = E^-1 S_:p, with E = L L^T.
        auto &L = scratch.L, &LT = scratch.LT, &X = scratch.X;
        L.cholesky(E);
        LT.reinit(n, n);
        LT.copy_transposed(L);
        X.reinit(n, n_modes);
        auto &column = scratch.column, &y = scratch.y, &x = scratch.x;
        column.reinit(n);
        y.reinit(n);
        x.reinit(n);
        for (unsigned int q = 0; q < n_modes; ++q)
          {
            for (unsigned int k = 0; k < n; ++k)
              column(k) = S(k, pivots[q]);
            L.forward(y, column);
            LT.backward(x, y);
            for (unsigned int k = 0; k < n; ++k)
              X(k, q) = x(k);
          }
        Q.reinit(n, n_modes);
        auto &x_row = scratch.x_row, &q_row = scratch.q_row;
        x_row.reinit(n_modes);
        q_row.reinit(n_modes);
        for (unsigned int k = 0; k < n; ++k)
          {
            for (unsigned int q = 0; q < n_modes; ++q)
              x_row(q) = X(k, q);
            RT.forward(q_row, x_row);
            for (unsigned int q = 0; q < n_modes; ++q)
              Q(k, q) = q_row(q);
          }
      }
    } // namespace

    template <int dim>
    SamplingStabilization<dim>::SamplingStabilization(const double target)
      : target(target)
    {
    }

    template <int dim>
    bool
    SamplingStabilization<dim>::acts_on(const GridSystem<dim> &grid) const
    {
      return target > 0 && grid.uses_matrix() &&
             grid.dofs_per_cell == n_functions &&
             n_monomials<dim>(grid.get_space().degree()) ==
               n_functions - n_modes;
    }

    template <int dim>
    void
    SamplingStabilization<dim>::reinit(const GridSystem<dim> &grid)
    {
      complement.clear();
      quadratic_factor.clear();
      basis.clear();
      inverse_measure.clear();
      weights.clear();
      quadratic_lifts.clear();
      if (!acts_on(grid))
        return;
      const auto               &space = grid.get_space();
      const auto               &dh    = grid.get_dof_handler();
      const unsigned int        n     = grid.dofs_per_cell;
      std::vector<unsigned int> identity(n);
      for (unsigned int k = 0; k < n; ++k)
        identity[k] = k;
      const auto &owned = grid.owned_cells();
      complement.resize(owned.size() * n * n);
      quadratic_factor.resize(owned.size() * n * n_modes);
      basis.resize(owned.size() * n * 2 * n_modes);
      inverse_measure.resize(owned.size());
      ModesScratch       scratch;
      FullMatrix<double> Q, Q_q, EQ_q;
      // owned_cells() lists the owned cells in active cell order.
      unsigned int i = 0;
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c = cell->active_cell_index();
            AssertDimension(c, owned[i]);
            // S_1, the complement of the affine fields, from the same
            // quadrature as S (the affine monomials come first).
            FullMatrix<double> E, S_q;
            const auto         S = polynomial_complement(space,
                                                 dh,
                                                 {c},
                                                 {identity},
                                                 n,
                                                 space.degree(),
                                                 cell->center(),
                                                 cell->diameter(),
                                                 &E,
                                                 1,
                                                 &S_q);
            // S_1 - S = E (P_2 - P_1): the quadratic modes.
            S_q.add(-1., S);
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int l = 0; l < n; ++l)
                complement[(i * n + k) * n + l] = S(k, l);
            inverse_measure[i] = 1. / cell->measure();
            modes_of(E, S, n_modes, c, "non-polynomial", scratch, Q);
            modes_of(E, S_q, n_modes, c, "quadratic", scratch, Q_q);
            // S_q = E Q_q Q_q^T E: its factor E Q_q is a third of S_q.
            EQ_q.reinit(n, n_modes);
            E.mmult(EQ_q, Q_q);
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int r = 0; r < n_modes; ++r)
                {
                  basis[(i * n + k) * 2 * n_modes + r]           = Q(k, r);
                  basis[(i * n + k) * 2 * n_modes + n_modes + r] = Q_q(k, r);
                  quadratic_factor[(i * n + k) * n_modes + r]    = EQ_q(k, r);
                }
            ++i;
          }
    }

    template <int dim>
    void
    SamplingStabilization<dim>::lift_unseen_quadratics(
      const unsigned int i,
      const double       rho,
      double (&B)[n_modes][n_modes])
    {
      constexpr unsigned int n = n_functions;
      for (unsigned int r = 0; r < n_modes; ++r)
        for (unsigned int s = 0; s < r; ++s)
          B[r][s] = B[s][r];
      double values[n_modes], V[n_modes][n_modes];
      eigenpairs_3x3(B, values, V);
      // g_j = sqrt(rho (t - lambda_j)) F v_j, F = E Q_q: the
      // lift is sum_j g_j g_j^T (Q_q^T F = I).
      Lift        lift{i, {}};
      const auto *F = &quadratic_factor[i * n * n_modes];
      for (unsigned int j = 0; j < n_modes; ++j)
        if (values[j] / rho < target)
          {
            const double w = std::sqrt(rho * (target - values[j] / rho));
            for (unsigned int k = 0; k < n; ++k)
              {
                double g = 0;
                for (unsigned int r = 0; r < n_modes; ++r)
                  g += F[k * n_modes + r] * V[r][j];
                lift.columns[k * n_modes + j] = w * g;
              }
          }
      quadratic_lifts.push_back(lift);
    }

    template <int dim>
    unsigned int
    SamplingStabilization<dim>::weigh(const GridSystem<dim> &grid)
    {
      weights.clear();
      // basis is empty unless acts_on() held at reinit() (or this rank
      // owns no cell).
      if (basis.empty())
        return 0;
      unsigned int n_weighted = 0;
      const auto  &owned      = grid.owned_cells();
      const auto  &lumped     = grid.cell_arrays().lumped;
      const auto  &mass       = grid.cell_arrays().mass;
      weights.assign(owned.size(), 0.);
      quadratic_lifts.clear();
      // n_functions at compile time lets the compiler unroll the
      // products (this runs every step on every cell).
      constexpr unsigned int n = n_functions, m2 = 2 * n_modes;
      for (unsigned int i = 0; i < owned.size(); ++i)
        {
          const unsigned int c = owned[i];
          // The functions of a cell sum to one: its lumped rows add up
          // to its particle mass.
          double m = 0;
          for (unsigned int k = 0; k < n; ++k)
            m += lumped[c * n + k];
          if (!(m > 0))
            continue;
          // A = Q^T M_c Q / rho for both sets of modes: the particles'
          // mass of the modes relative to the exact one (the identity
          // where they integrate like the exact integral).
          const double *M = &mass[c * n * n];
          const double *Q = &basis[i * n * m2];
          double        MQ[n * m2];
          for (unsigned int k = 0; k < n; ++k)
            {
              double v[m2] = {};
              for (unsigned int l = 0; l < n; ++l)
                for (unsigned int r = 0; r < m2; ++r)
                  v[r] += M[k * n + l] * Q[l * m2 + r];
              for (unsigned int r = 0; r < m2; ++r)
                MQ[k * m2 + r] = v[r];
            }
          const double rho = m * inverse_measure[i];
          // Upper triangle of Q^T M_c Q for the n_modes columns from o.
          const auto project = [&](const unsigned int o,
                                   double(&G)[n_modes][n_modes]) {
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int r = 0; r < n_modes; ++r)
                for (unsigned int s = r; s < n_modes; ++s)
                  G[r][s] += Q[k * m2 + o + r] * MQ[k * m2 + o + s];
          };
          // A of the non-polynomial modes (the first n_modes columns).
          double A[n_modes][n_modes] = {};
          project(0, A);
          bool weighted = false;
          if (has_eigenvalue_below(A, target * rho))
            {
              const double lambda = smallest_eigenvalue(A) / rho;
              // Lift the smallest to the target (Q^T S_c Q = I).
              weighted = lambda < target;
              if (weighted)
                weights[i] = rho * (target - lambda);
            }
          // The quadratic modes (the other n_modes columns): a layout
          // that leaves a quadratic unseen (particles on two lines do not
          // see (y - y_1)(y - y_2)) gets a singular matrix that S_c does
          // not touch. Only the unseen directions are lifted, each to
          // the target, so the quadratics the particles see keep their
          // particle mass.
          double B[n_modes][n_modes] = {};
          project(n_modes, B);
          if (has_eigenvalue_below(B, target * rho))
            {
              lift_unseen_quadratics(i, rho, B);
              weighted = true;
            }
          n_weighted += weighted;
        }
      return n_weighted;
    }

    template <int dim>
    void
    SamplingStabilization<dim>::apply(GridSystem<dim> &grid) const
    {
      if (weights.empty())
        return;
      const unsigned int n     = grid.dofs_per_cell;
      const auto        &owned = grid.owned_cells();
      auto              &mass  = grid.cell_arrays().mass;
      for (unsigned int i = 0; i < owned.size(); ++i)
        if (weights[i] > 0)
          {
            const double  w = weights[i];
            const double *S = &complement[i * n * n];
            double       *M = &mass[owned[i] * n * n];
            for (unsigned int kl = 0; kl < n * n; ++kl)
              M[kl] += w * S[kl];
          }
      for (const auto &lift : quadratic_lifts)
        {
          double       *M = &mass[owned[lift.cell] * n * n];
          const double *G = lift.columns.data();
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = 0; l < n; ++l)
              {
                double s = 0;
                for (unsigned int j = 0; j < n_modes; ++j)
                  s += G[k * n_modes + j] * G[l * n_modes + j];
                M[k * n + l] += s;
              }
        }
    }

    template class SamplingStabilization<1>;
    template class SamplingStabilization<2>;
  } // namespace Solver
} // namespace psmpm
