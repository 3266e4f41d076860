// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/vector.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/polynomial_complement.h>
#include <psmpm/solver/sampling_stabilization.h>

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
      /// Smallest eigenvalue of the symmetric 3 x 3 matrix with entries
      /// a00, a11, a22 (diagonal), a01, a02, a12 (closed form, Smith 1961).
      double
      smallest_eigenvalue(const double a00,
                          const double a11,
                          const double a22,
                          const double a01,
                          const double a02,
                          const double a12)
      {
        const double q  = (a00 + a11 + a22) / 3;
        const double p1 = a01 * a01 + a02 * a02 + a12 * a12;
        const double p2 = (a00 - q) * (a00 - q) + (a11 - q) * (a11 - q) +
                          (a22 - q) * (a22 - q) + 2 * p1;
        if (!(p2 > 0))
          return q;
        const double p   = std::sqrt(p2 / 6);
        const double b00 = (a00 - q) / p, b11 = (a11 - q) / p,
                     b22 = (a22 - q) / p, b01 = a01 / p, b02 = a02 / p,
                     b12 = a12 / p;
        const double r =
          (b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) +
           b02 * (b01 * b12 - b11 * b02)) /
          2;
        const double phi = std::acos(std::clamp(r, -1., 1.)) / 3;
        return q + 2 * p * std::cos(phi + 2 * M_PI / 3);
      }

      /// An E-orthonormal basis of the non-polynomial modes, as the
      /// columns of an n x n_modes matrix. E is the cell's exact mass
      /// matrix and S its polynomial complement, so X = E^-1 S is the
      /// E-orthogonal projection I - P onto the modes, and the E-inner
      /// products of X's columns are X^T E X = S X = S (P is
      /// E-self-adjoint). A Cholesky factorization of S with diagonal
      /// pivoting, stopped after n_modes steps, picks n_modes columns of
      /// X that span the modes: with S_pp = R^T R, Q = X_p R^-1 has
      /// Q^T E Q = I. Three solves with E and a 3 x 3 triangle, where a
      /// symmetric eigensolver (LAPACK, before stop 33) cost three
      /// quarters of the set-up's instructions.
      FullMatrix<double>
      non_polynomial_modes(const FullMatrix<double> &E,
                           const FullMatrix<double> &S,
                           const unsigned int        n_modes,
                           const unsigned int        cell)
      {
        const unsigned int n = E.m();
        // Pivoted Cholesky of S: W holds the Schur complement.
        FullMatrix<double>        W(S), R(n_modes, n_modes);
        std::vector<unsigned int> pivots;
        double                    largest = 0;
        for (unsigned int k = 0; k < n; ++k)
          largest = std::max(largest, S(k, k));
        const double tolerance = 1e-8 * largest;
        const auto   error     = [&](const std::string &what) {
          return ExcMessage("Sampling stabilization: cell " +
                            std::to_string(cell) + " has " + what +
                            " non-polynomial modes, expected " +
                            std::to_string(n_modes) + ".");
        };
        std::vector<bool>                used(n, false);
        std::vector<std::vector<double>> rows;
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
            const double        root = std::sqrt(d);
            std::vector<double> row(n);
            for (unsigned int k = 0; k < n; ++k)
              row[k] = W(j, k) / root;
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int l = 0; l < n; ++l)
                W(k, l) -= row[k] * row[l];
            rows.push_back(row);
          }
        // R(r, q) = row_r[p_q] gives S_pp = R^T R; it is upper
        // triangular, since a pivot's row and column of W vanish after
        // its step. Stored transposed: Q = X_p R^-1 is, row by row, a
        // forward substitution with R^T.
        FullMatrix<double> RT(n_modes, n_modes);
        for (unsigned int r = 0; r < n_modes; ++r)
          for (unsigned int q = 0; q < n_modes; ++q)
            RT(q, r) = rows[r][pivots[q]];

        // X_p = E^-1 S_:p, with E = L L^T.
        FullMatrix<double> L(n, n), LT(n, n), X(n, n_modes);
        L.cholesky(E);
        LT.copy_transposed(L);
        Vector<double> column(n), y(n), x(n);
        for (unsigned int q = 0; q < n_modes; ++q)
          {
            for (unsigned int k = 0; k < n; ++k)
              column(k) = S(k, pivots[q]);
            L.forward(y, column);
            LT.backward(x, y);
            for (unsigned int k = 0; k < n; ++k)
              X(k, q) = x(k);
          }
        FullMatrix<double> Q(n, n_modes);
        Vector<double>     x_row(n_modes), q_row(n_modes);
        for (unsigned int k = 0; k < n; ++k)
          {
            for (unsigned int q = 0; q < n_modes; ++q)
              x_row(q) = X(k, q);
            RT.forward(q_row, x_row);
            for (unsigned int q = 0; q < n_modes; ++q)
              Q(k, q) = q_row(q);
          }
        return Q;
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
      basis.clear();
      inverse_measure.clear();
      weights.clear();
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
      basis.resize(owned.size() * n * n_modes);
      inverse_measure.resize(owned.size());
      // owned_cells() lists the owned cells in active cell order.
      unsigned int i = 0;
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c = cell->active_cell_index();
            AssertDimension(c, owned[i]);
            FullMatrix<double> E;
            const auto         S = polynomial_complement(space,
                                                 dh,
                                                 {c},
                                                 {identity},
                                                 n,
                                                 space.degree(),
                                                 cell->center(),
                                                 cell->diameter(),
                                                 &E);
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int l = 0; l < n; ++l)
                complement[(i * n + k) * n + l] = S(k, l);
            inverse_measure[i]         = 1. / cell->measure();
            const FullMatrix<double> Q = non_polynomial_modes(E, S, n_modes, c);
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int r = 0; r < n_modes; ++r)
                basis[(i * n + k) * n_modes + r] = Q(k, r);
            ++i;
          }
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
      // n_functions at compile time lets the compiler unroll the
      // products (this runs every step on every cell).
      constexpr unsigned int n = n_functions;
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
          // A = Q^T M_c Q / rho: the particles' mass of the
          // non-polynomial modes relative to the exact one (the
          // identity where they integrate like the exact integral).
          const double *M = &mass[c * n * n];
          const double *Q = &basis[i * n * n_modes];
          double        MQ[n * n_modes];
          for (unsigned int k = 0; k < n; ++k)
            {
              double v[n_modes] = {};
              for (unsigned int l = 0; l < n; ++l)
                for (unsigned int r = 0; r < n_modes; ++r)
                  v[r] += M[k * n + l] * Q[l * n_modes + r];
              for (unsigned int r = 0; r < n_modes; ++r)
                MQ[k * n_modes + r] = v[r];
            }
          double A[n_modes][n_modes] = {};
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int r = 0; r < n_modes; ++r)
              for (unsigned int s = r; s < n_modes; ++s)
                A[r][s] += Q[k * n_modes + r] * MQ[k * n_modes + s];
          const double rho    = m * inverse_measure[i];
          const double lambda = smallest_eigenvalue(A[0][0],
                                                    A[1][1],
                                                    A[2][2],
                                                    A[0][1],
                                                    A[0][2],
                                                    A[1][2]) /
                                rho;
          // Lift the smallest to the target (Q^T S_c Q = I).
          if (lambda < target)
            {
              weights[i] = rho * (target - lambda);
              ++n_weighted;
            }
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
    }

    template class SamplingStabilization<1>;
    template class SamplingStabilization<2>;
  } // namespace Solver
} // namespace psmpm
