// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/polynomial_complement.h>

#include <cmath>
#include <string>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// The highest degree of the bases (the 1D B-splines: 5).
      constexpr unsigned int max_degree = 8;

      /// Monomials of degree <= k in y = (x - x0) / h, into @p r (the
      /// order of n_monomials: by total degree, then by the power of the
      /// last coordinate). Each power is std::pow as before, computed
      /// once per coordinate instead of once per monomial, and nothing
      /// is allocated (this runs at every quadrature point of every
      /// cell at set-up).
      template <int dim>
      void
      monomials(const Point<dim>  &x,
                const Point<dim>  &x0,
                const double       h,
                const unsigned int k,
                double            *r)
      {
        const Tensor<1, dim> y = (x - x0) / h;
        double               first[max_degree + 1], last[max_degree + 1];
        // pow(y, 0) = 1 and pow(y, 1) = y exactly.
        first[0] = last[0] = 1;
        first[1]           = y[0];
        last[1]            = y[dim - 1];
        for (unsigned int a = 2; a <= k; ++a)
          {
            first[a] = std::pow(y[0], a);
            last[a]  = std::pow(y[dim - 1], a);
          }
        if (dim == 1)
          for (unsigned int a = 0; a <= k; ++a)
            *r++ = first[a];
        else
          for (unsigned int total = 0; total <= k; ++total)
            for (unsigned int a = 0; a <= total; ++a)
              *r++ = first[total - a] * last[a];
      }

      /// The matrices of one call, kept from call to call: the ghost
      /// penalty calls this for every pair of cells sharing a vertex at
      /// set-up (about six per cell), and allocating them each time took
      /// as long as the sums. reinit() to the same or a smaller size
      /// keeps the memory.
      struct Workspace
      {
        std::vector<double> values, p;
        FullMatrix<double>  M, B, G, G_k, B_k, GB, BtGB;
      };

      /// Not inlined: inlined, the compiler recomputed the thread-local
      /// address (a call to __tls_get_addr in a shared library) at every
      /// use of the reference in the sums.
      [[gnu::noinline]] Workspace &
      workspace()
      {
        thread_local Workspace w;
        return w;
      }

      /// M - B_k^T G_k^-1 B_k with B_k the first @p k rows of @p B and G_k
      /// the leading k x k block of @p G: the complement of the
      /// polynomials whose monomials come first (those of lower degree),
      /// made exactly symmetric. With every row it is S of the full
      /// degree; with fewer, the sub-blocks hold the same sums as a
      /// separate pass of that degree would, so the result is the same.
      FullMatrix<double>
      minus_projection(const FullMatrix<double> &M,
                       const FullMatrix<double> &B,
                       const FullMatrix<double> &G,
                       const unsigned int        k,
                       Workspace                &w)
      {
        const unsigned int n = M.m();
        FullMatrix<double> S(M);
        w.G_k.reinit(k, k);
        w.B_k.reinit(k, n);
        w.G_k.fill(G);
        w.B_k.fill(B);
        w.G_k.gauss_jordan();
        w.GB.reinit(k, n);
        w.BtGB.reinit(n, n);
        w.G_k.mmult(w.GB, w.B_k);
        w.B_k.Tmmult(w.BtGB, w.GB);
        S.add(-1., w.BtGB);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = a + 1; b < n; ++b)
            S(a, b) = S(b, a) = 0.5 * (S(a, b) + S(b, a));
        return S;
      }
    } // namespace

    template <int dim>
    unsigned int
    n_monomials(const unsigned int degree)
    {
      return dim == 1 ? degree + 1 : (degree + 1) * (degree + 2) / 2;
    }

    template <int dim>
    FullMatrix<double>
    polynomial_complement(
      const Basis::Space<dim>                      &space,
      const DoFHandler<dim>                        &dof_handler,
      const std::vector<unsigned int>              &cells,
      const std::vector<std::vector<unsigned int>> &to_patch,
      const unsigned int                            n_patch,
      const unsigned int                            degree,
      const Point<dim>                             &x0,
      const double                                  h,
      FullMatrix<double>                           *mass,
      const unsigned int                            lower_degree,
      FullMatrix<double>                           *lower)
    {
      const unsigned int n  = space.dofs_per_cell();
      const unsigned int np = n_monomials<dim>(degree);
      AssertThrow(degree <= max_degree,
                  ExcMessage("polynomial_complement: degree " +
                             std::to_string(degree) + " above " +
                             std::to_string(max_degree) + "."));
      Workspace           &work   = workspace();
      std::vector<double> &values = work.values, &p = work.p;
      values.resize(n);
      p.resize(np);
      FullMatrix<double> &S = work.M, &B = work.B, &G = work.G;
      S.reinit(n_patch, n_patch);
      B.reinit(np, n_patch);
      G.reinit(np, np);
      for (unsigned int s = 0; s < cells.size(); ++s)
        {
          const unsigned int    c = cells[s];
          const Quadrature<dim> q = space.cell_quadrature(dof_handler, c);
          for (unsigned int i = 0; i < q.size(); ++i)
            {
              space.evaluate(c, q.point(i), values.data(), nullptr);
              monomials(q.point(i), x0, h, degree, p.data());
              const double w = q.weight(i);
              for (unsigned int a = 0; a < n; ++a)
                {
                  for (unsigned int b = 0; b < n; ++b)
                    S(to_patch[s][a], to_patch[s][b]) +=
                      w * values[a] * values[b];
                  for (unsigned int r = 0; r < np; ++r)
                    B(r, to_patch[s][a]) += w * p[r] * values[a];
                }
              for (unsigned int r = 0; r < np; ++r)
                for (unsigned int t = 0; t < np; ++t)
                  G(r, t) += w * p[r] * p[t];
            }
        }
      if (mass != nullptr)
        *mass = S;
      if (lower != nullptr)
        *lower =
          minus_projection(S, B, G, n_monomials<dim>(lower_degree), work);
      return minus_projection(S, B, G, np, work);
    }

    template unsigned int
    n_monomials<1>(const unsigned int);
    template unsigned int
    n_monomials<2>(const unsigned int);
    template FullMatrix<double>
    polynomial_complement(const Basis::Space<1> &,
                          const DoFHandler<1> &,
                          const std::vector<unsigned int> &,
                          const std::vector<std::vector<unsigned int>> &,
                          const unsigned int,
                          const unsigned int,
                          const Point<1> &,
                          const double,
                          FullMatrix<double> *,
                          const unsigned int,
                          FullMatrix<double> *);
    template FullMatrix<double>
    polynomial_complement(const Basis::Space<2> &,
                          const DoFHandler<2> &,
                          const std::vector<unsigned int> &,
                          const std::vector<std::vector<unsigned int>> &,
                          const unsigned int,
                          const unsigned int,
                          const Point<2> &,
                          const double,
                          FullMatrix<double> *,
                          const unsigned int,
                          FullMatrix<double> *);
  } // namespace Solver
} // namespace psmpm
