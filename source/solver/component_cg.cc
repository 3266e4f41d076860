// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/tridiagonal_matrix.h>

#include <psmpm/solver/component_cg.h>

#include <Epetra_Comm.h>
#include <Epetra_Import.h>
#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Largest over smallest eigenvalue of the Lanczos matrix of CG
      /// (SolverCG::compute_eigs_and_cond; 0 with fewer than two rows).
      double
      lanczos_condition(const std::vector<double> &diagonal,
                        const std::vector<double> &offdiagonal)
      {
        if (diagonal.size() < 2)
          return 0;
        TridiagonalMatrix<double> T(diagonal.size(), true);
        for (unsigned int i = 0; i < diagonal.size(); ++i)
          {
            T(i, i) = diagonal[i];
            if (i + 1 < diagonal.size())
              T(i, i + 1) = offdiagonal[i];
          }
        T.compute_eigenvalues();
        return std::abs(T.eigenvalue(T.n() - 1) / T.eigenvalue(0));
      }

      /// Four partial sums: one running sum is a latency-bound chain of
      /// additions (so are the products below).
      double
      dot(const double *a, const double *b, const unsigned int n)
      {
        double       s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        unsigned int i = 0;
        for (; i + 4 <= n; i += 4)
          {
            s0 += a[i] * b[i];
            s1 += a[i + 1] * b[i + 1];
            s2 += a[i + 2] * b[i + 2];
            s3 += a[i + 3] * b[i + 3];
          }
        for (; i < n; ++i)
          s0 += a[i] * b[i];
        return (s0 + s1) + (s2 + s3);
      }

      /// q_c = M p_c for the @p columns (local row indices of M's row map;
      /// p in M's column map, q in its row map), straight from the CRS
      /// arrays. Epetra's multi-vector product (a Fortran kernel,
      /// epetra_scrsmm5) took as long for two columns as two products
      /// with one column each.
      void
      multiply(const Epetra_CrsMatrix   &M,
               const Epetra_MultiVector &p,
               Epetra_MultiVector       &q,
               const std::vector<int>   &columns,
               const Epetra_MultiVector &p_owned,
               double                   *p_q)
      {
        int    *offsets, *indices;
        double *values;
        M.ExtractCrsDataPointers(offsets, indices, values);
        const int n_rows = M.NumMyRows();
        if (columns.size() == 2)
          {
            const double *p0 = p[columns[0]], *p1 = p[columns[1]];
            const double *o0 = p_owned[columns[0]], *o1 = p_owned[columns[1]];
            double       *q0 = q[columns[0]], *q1 = q[columns[1]];
            double        pq0 = 0, pq1 = 0;
            for (int i = 0; i < n_rows; ++i)
              {
                double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
                int    k = offsets[i];
                for (; k + 2 <= offsets[i + 1]; k += 2)
                  {
                    const double a = values[k], b = values[k + 1];
                    const int    j = indices[k], l = indices[k + 1];
                    s0 += a * p0[j];
                    s1 += a * p1[j];
                    t0 += b * p0[l];
                    t1 += b * p1[l];
                  }
                if (k < offsets[i + 1])
                  {
                    s0 += values[k] * p0[indices[k]];
                    s1 += values[k] * p1[indices[k]];
                  }
                q0[i] = s0 + t0, q1[i] = s1 + t1;
                pq0 += o0[i] * q0[i];
                pq1 += o1[i] * q1[i];
              }
            p_q[columns[0]] = pq0, p_q[columns[1]] = pq1;
            return;
          }
        for (const int c : columns)
          {
            const double *pc = p[c], *oc = p_owned[c];
            double       *qc = q[c];
            double        pq = 0;
            for (int i = 0; i < n_rows; ++i)
              {
                double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
                int    k = offsets[i];
                for (; k + 4 <= offsets[i + 1]; k += 4)
                  {
                    s0 += values[k] * pc[indices[k]];
                    s1 += values[k + 1] * pc[indices[k + 1]];
                    s2 += values[k + 2] * pc[indices[k + 2]];
                    s3 += values[k + 3] * pc[indices[k + 3]];
                  }
                for (; k < offsets[i + 1]; ++k)
                  s0 += values[k] * pc[indices[k]];
                qc[i] = (s0 + s1) + (s2 + s3);
                pq += oc[i] * qc[i];
              }
            p_q[c] = pq;
          }
      }

      /// The same for matrices whose rows come in triples (the three
      /// Powell-Sabin functions of a vertex) with equal columns, stored as
      /// triples of consecutive columns (checked by ComponentCG::reinit):
      /// one column index and one load of p per 3 x 3 block, and the
      /// three rows of a vertex summed together.
      void
      multiply_triples(const Epetra_CrsMatrix   &M,
                       const Epetra_MultiVector &p,
                       Epetra_MultiVector       &q,
                       const std::vector<int>   &columns,
                       const Epetra_MultiVector &p_owned,
                       double                   *p_q)
      {
        int    *offsets, *indices;
        double *values;
        M.ExtractCrsDataPointers(offsets, indices, values);
        const int n_rows = M.NumMyRows();
        if (columns.size() == 2)
          {
            // Both columns in one pass: each block of M is read once.
            const double *p0 = p[columns[0]], *p1 = p[columns[1]];
            const double *o0 = p_owned[columns[0]], *o1 = p_owned[columns[1]];
            double       *q0 = q[columns[0]], *q1 = q[columns[1]];
            double        pq0 = 0, pq1 = 0;
            for (int i = 0; i < n_rows; i += 3)
              {
                const double *a0  = values + offsets[i];
                const double *a1  = values + offsets[i + 1];
                const double *a2  = values + offsets[i + 2];
                const int    *col = indices + offsets[i];
                const int     len = offsets[i + 1] - offsets[i];
                double        s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0, t2 = 0;
                for (int k = 0; k < len; k += 3)
                  {
                    const double *x  = p0 + col[k];
                    const double *y  = p1 + col[k];
                    const double  x0 = x[0], x1 = x[1], x2 = x[2];
                    const double  y0 = y[0], y1 = y[1], y2 = y[2];
                    const double  b00 = a0[k], b01 = a0[k + 1], b02 = a0[k + 2];
                    const double  b10 = a1[k], b11 = a1[k + 1], b12 = a1[k + 2];
                    const double  b20 = a2[k], b21 = a2[k + 1], b22 = a2[k + 2];
                    s0 += b00 * x0 + b01 * x1 + b02 * x2;
                    s1 += b10 * x0 + b11 * x1 + b12 * x2;
                    s2 += b20 * x0 + b21 * x1 + b22 * x2;
                    t0 += b00 * y0 + b01 * y1 + b02 * y2;
                    t1 += b10 * y0 + b11 * y1 + b12 * y2;
                    t2 += b20 * y0 + b21 * y1 + b22 * y2;
                  }
                q0[i] = s0, q0[i + 1] = s1, q0[i + 2] = s2;
                q1[i] = t0, q1[i + 1] = t1, q1[i + 2] = t2;
                pq0 += o0[i] * s0 + o0[i + 1] * s1 + o0[i + 2] * s2;
                pq1 += o1[i] * t0 + o1[i + 1] * t1 + o1[i + 2] * t2;
              }
            p_q[columns[0]] = pq0, p_q[columns[1]] = pq1;
            return;
          }
        for (const int c : columns)
          {
            const double *pc = p[c], *oc = p_owned[c];
            double       *qc = q[c];
            double        pq = 0;
            for (int i = 0; i < n_rows; i += 3)
              {
                const double *a0  = values + offsets[i];
                const double *a1  = values + offsets[i + 1];
                const double *a2  = values + offsets[i + 2];
                const int    *col = indices + offsets[i];
                const int     len = offsets[i + 1] - offsets[i];
                double        s0 = 0, s1 = 0, s2 = 0;
                for (int k = 0; k < len; k += 3)
                  {
                    const double *x  = pc + col[k];
                    const double  x0 = x[0], x1 = x[1], x2 = x[2];
                    s0 += a0[k] * x0 + a0[k + 1] * x1 + a0[k + 2] * x2;
                    s1 += a1[k] * x0 + a1[k + 1] * x1 + a1[k + 2] * x2;
                    s2 += a2[k] * x0 + a2[k + 1] * x1 + a2[k + 2] * x2;
                  }
                qc[i] = s0, qc[i + 1] = s1, qc[i + 2] = s2;
                pq += oc[i] * s0 + oc[i + 1] * s1 + oc[i + 2] * s2;
              }
            p_q[c] = pq;
          }
      }
    } // namespace

    void
    ComponentCG::reinit(const Epetra_CrsMatrix &M)
    {
      int    *offsets, *indices;
      double *values;
      triples = M.ExtractCrsDataPointers(offsets, indices, values) == 0 &&
                M.NumMyRows() % 3 == 0;
      for (int i = 0; triples && i < M.NumMyRows(); i += 3)
        {
          const int len = offsets[i + 1] - offsets[i];
          triples = len % 3 == 0 && offsets[i + 2] - offsets[i + 1] == len &&
                    offsets[i + 3] - offsets[i + 2] == len;
          for (int k = 0; triples && k < len; k += 3)
            for (int row = 0; row < 3 && triples; ++row)
              {
                const int *col = indices + offsets[i + row] + k;
                triples        = col[0] == indices[offsets[i] + k] &&
                          col[1] == col[0] + 1 && col[2] == col[0] + 2;
              }
        }
    }

    void
    ComponentCG::product(const Epetra_CrsMatrix   &M,
                         const Epetra_MultiVector &v,
                         const std::vector<int>   &columns,
                         double                   *v_q)
    {
      // One pass over M for all the columns; other ranks' entries of v
      // imported first.
      const Epetra_MultiVector *source = &v;
      if (M.Importer() != nullptr)
        {
          if (!ghosted || !ghosted->Map().SameAs(M.ColMap()) ||
              ghosted->NumVectors() != v.NumVectors())
            ghosted = std::make_unique<Epetra_MultiVector>(M.ColMap(),
                                                           v.NumVectors(),
                                                           false);
          ghosted->Import(v, *M.Importer(), Insert);
          source = ghosted.get();
        }
      if (triples)
        multiply_triples(M, *source, *q, columns, v, v_q);
      else
        multiply(M, *source, *q, columns, v, v_q);
    }

    /// The per-column state of the CG recurrences of one solve.
    struct ComponentCG::Recurrence
    {
      explicit Recurrence(const unsigned int n_columns)
        : rz(n_columns)
        , rz_old(n_columns)
        , alpha(n_columns, 0.)
        , alpha_old(n_columns, 0.)
        , beta(n_columns, 0.)
        , eigen_beta_alpha(n_columns, 0.)
        , limit(n_columns)
        , local(2 * n_columns)
        , global(2 * n_columns)
        , active(n_columns)
        , diagonal(n_columns)
        , offdiagonal(n_columns)
      {
      }

      std::vector<double> rz, rz_old, alpha, alpha_old, beta, eigen_beta_alpha,
        limit;
      /// This rank's and all ranks' sums of the step.
      std::vector<double> local, global;
      std::vector<char>   active;
      unsigned int        n_active = 0;
      /// The active columns of the step.
      std::vector<int> columns;
      /// The Lanczos matrix of each column (condition estimate).
      std::vector<std::vector<double>> diagonal, offdiagonal;
    };

    void
    ComponentCG::allocate(const Epetra_MultiVector &b)
    {
      const int n_columns = b.NumVectors();
      if (!r || r->NumVectors() != n_columns || !r->Map().SameAs(b.Map()))
        {
          r = std::make_unique<Epetra_MultiVector>(b.Map(), n_columns, false);
          z = std::make_unique<Epetra_MultiVector>(b.Map(), n_columns, false);
          p = std::make_unique<Epetra_MultiVector>(b.Map(), n_columns, false);
          q = std::make_unique<Epetra_MultiVector>(b.Map(), n_columns, false);
        }
    }

    void
    ComponentCG::start(
      const Epetra_CrsMatrix                       &M,
      const std::vector<const VertexBlockJacobi *> &preconditioners,
      const std::vector<std::vector<unsigned int>> &fixed,
      const Epetra_MultiVector                     &x,
      const Epetra_MultiVector                     &b,
      const double                                  tolerance,
      const std::vector<double>                    &step_tolerances,
      Recurrence                                   &s)
    {
      const unsigned int n_columns = b.NumVectors();
      const unsigned int n         = b.MyLength();
      // r = b - M x (fixed rows zero), z = B r; reduce ||b||^2, ||r||^2
      // and r.z together. A zero guess needs no product.
      bool zero_guess = true;
      for (unsigned int d = 0; d < n_columns; ++d)
        {
          s.columns.push_back(d);
          const double *xd = x[d];
          for (unsigned int i = 0; i < n && zero_guess; ++i)
            zero_guess = xd[i] == 0;
        }
      // Decided over all ranks: the product is collective.
      int zero_here = zero_guess, zero_everywhere = 1;
      M.Comm().MinAll(&zero_here, &zero_everywhere, 1);
      zero_guess = zero_everywhere;
      if (!zero_guess)
        product(M, x, s.columns, s.local.data());
      std::vector<double> r_b(3 * n_columns), global_r_b(3 * n_columns);
      for (unsigned int d = 0; d < n_columns; ++d)
        {
          const double *bd = b[d];
          double       *rd = (*r)[d], *zd = (*z)[d];
          if (zero_guess)
            std::copy(bd, bd + n, rd);
          else
            {
              const double *qd = (*q)[d];
              for (unsigned int i = 0; i < n; ++i)
                rd[i] = bd[i] - qd[i];
              for (const unsigned int i : fixed[d])
                rd[i] = 0;
            }
          preconditioners[d]->vmult(zd, rd, r_b[3 * d], r_b[3 * d + 1]);
          r_b[3 * d + 2] = zero_guess ? r_b[3 * d] : dot(bd, bd, n);
        }
      M.Comm().SumAll(r_b.data(), global_r_b.data(), 3 * n_columns);
      for (unsigned int d = 0; d < n_columns; ++d)
        {
          const double residual = std::sqrt(global_r_b[3 * d]);
          s.limit[d]            = tolerance * std::sqrt(global_r_b[3 * d + 2]);
          // A warm start's residual is what the step changed; the solve
          // need not be more accurate than a fraction of that.
          if (!zero_guess)
            s.limit[d] = std::max(s.limit[d], step_tolerances[d] * residual);
          s.rz[d] = global_r_b[3 * d + 1];
          // SolverControl's test at step 0: ||r|| <= limit (a zero
          // right-hand side with a zero guess has nothing to solve).
          s.active[d] = !(residual <= s.limit[d]);
          s.n_active += s.active[d];
        }
    }

    void
    ComponentCG::update_directions(const unsigned int it, Recurrence &s)
    {
      // p = z + beta p on the active columns.
      const unsigned int n = p->MyLength();
      s.columns.clear();
      for (unsigned int d = 0; d < s.active.size(); ++d)
        if (s.active[d])
          {
            s.columns.push_back(d);
            double       *pd = (*p)[d];
            const double *zd = (*z)[d];
            if (it == 1)
              std::copy(zd, zd + n, pd);
            else
              {
                s.beta[d] = s.rz[d] / s.rz_old[d];
                for (unsigned int i = 0; i < n; ++i)
                  pd[i] = zd[i] + s.beta[d] * pd[i];
              }
          }
    }

    void
    ComponentCG::iterate(
      const Epetra_CrsMatrix                       &M,
      const std::vector<const VertexBlockJacobi *> &preconditioners,
      const std::vector<std::vector<unsigned int>> &fixed,
      Epetra_MultiVector                           &x,
      Recurrence                                   &s)
    {
      const unsigned int n_columns = s.active.size();
      const unsigned int n         = p->MyLength();
      // q = M p with p . q of every column (p is zero on fixed rows,
      // so the rows of q that the mask zeroes add nothing).
      product(M, *p, s.columns, s.local.data());
      for (const int d : s.columns)
        {
          double *qd = (*q)[d];
          for (const unsigned int i : fixed[d])
            qd[i] = 0;
        }
      M.Comm().SumAll(s.local.data(), s.global.data(), n_columns);
      // x += alpha p, r -= alpha q, z = B r; reduce ||r||^2 and r.z.
      for (const int d : s.columns)
        {
          s.alpha_old[d]   = s.alpha[d];
          s.alpha[d]       = s.rz[d] / s.global[d];
          double       *xd = x[d], *rd = (*r)[d], *zd = (*z)[d];
          const double *pd = (*p)[d], *qd = (*q)[d];
          for (unsigned int i = 0; i < n; ++i)
            {
              xd[i] += s.alpha[d] * pd[i];
              rd[i] -= s.alpha[d] * qd[i];
            }
          preconditioners[d]->vmult(zd, rd, s.local[2 * d], s.local[2 * d + 1]);
        }
      M.Comm().SumAll(s.local.data(), s.global.data(), 2 * n_columns);
    }

    void
    ComponentCG::check_convergence(const unsigned int it,
                                   const unsigned int max_iterations,
                                   Recurrence        &s,
                                   Result            &result)
    {
      for (const int d : s.columns)
        {
          // The Lanczos matrix as SolverCG builds it: a row per
          // completed pair (alpha_{k-1}, beta_k).
          if (it > 1)
            {
              s.diagonal[d].push_back(1. / s.alpha_old[d] +
                                      s.eigen_beta_alpha[d]);
              s.eigen_beta_alpha[d] = s.beta[d] / s.alpha_old[d];
              s.offdiagonal[d].push_back(std::sqrt(s.beta[d]) / s.alpha_old[d]);
            }
          const double residual = std::sqrt(s.global[2 * d]);
          s.rz_old[d]           = s.rz[d];
          s.rz[d]               = s.global[2 * d + 1];
          if (residual <= s.limit[d])
            {
              s.active[d]          = false;
              result.iterations[d] = it;
              --s.n_active;
              result.condition_number =
                std::max(result.condition_number,
                         lanczos_condition(s.diagonal[d], s.offdiagonal[d]));
            }
          else if (it >= max_iterations || !std::isfinite(residual))
            throw SolverControl::NoConvergence(it, residual);
        }
    }

    ComponentCG::Result
    ComponentCG::solve(
      const Epetra_CrsMatrix                       &M,
      const std::vector<const VertexBlockJacobi *> &preconditioners,
      const std::vector<std::vector<unsigned int>> &fixed,
      Epetra_MultiVector                           &x,
      const Epetra_MultiVector                     &b,
      const double                                  tolerance,
      const std::vector<double>                    &step_tolerances,
      const unsigned int                            max_iterations)
    {
      const unsigned int n_columns = b.NumVectors();
      AssertThrow(preconditioners.size() == n_columns &&
                    fixed.size() == n_columns &&
                    step_tolerances.size() == n_columns &&
                    x.NumVectors() == int(n_columns),
                  ExcMessage("ComponentCG: one preconditioner, fixed set "
                             "and solution column per right-hand side"));
      allocate(b);
      Result result;
      result.iterations.assign(n_columns, 0);
      Recurrence s(n_columns);
      start(M, preconditioners, fixed, x, b, tolerance, step_tolerances, s);
      for (unsigned int it = 1; s.n_active > 0; ++it)
        {
          update_directions(it, s);
          iterate(M, preconditioners, fixed, x, s);
          check_convergence(it, max_iterations, s, result);
        }
      return result;
    }
  } // namespace Solver
} // namespace psmpm
