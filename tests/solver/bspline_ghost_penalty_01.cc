// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Ghost penalty mass with tensor-product B-splines (Basis::TensorBSpline,
// p = 2 and 3) on a Cartesian 4 x 2 mesh of [0, 2] x [0, 1], rho = 1000,
// hand-placed particles (an n x n grid of equal masses per cell, fill 1):
// the pair matrices are built on the Bezier (FE_Q) layout and reach the
// B-splines through their C^{p-1} ties, so the patch couplings have to be
// in the sparsity through the ties (GridSystem::build_sparsity()).
// A. The left half filled, the right half empty but for ONE particle at
//    distance eps from x = 1 (eps = 1e-1, 1e-2, 1e-3): the B-splines that
//    start at x = 1 are supported by that one particle at the edge of
//    their support. Checked on the free (untied) DoFs with particle mass,
//    Jacobi-scaled as CG sees them: the consistent matrix is singular
//    (condition above 1e10), the ghost penalty matrix is symmetric
//    positive definite with a condition number that stays bounded as
//    eps -> 0.
// B. Every cell filled: the ghost penalty matrix is the consistent one.
// C. Every cell half filled: the ghost penalty matrix differs from the
//    consistent one, but not on constants (row sums: momentum) and affine
//    fields (rigid motion), on the free rows.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/tensor_bspline.h>
#include <psmpm/solver/grid_system.h>

#include "../tests.h"
#include "particle_mass.h"

#include <algorithm>
#include <functional>

namespace
{
  using namespace psmpm;
  const double rho = 1000;

  using particle_mass::Particle;

  /// Assembled matrix (component 0) of strategy @p type as a dense
  /// matrix; @p free_active: untied DoFs with particle mass.
  FullMatrix<double>
  assemble(const std::string           &type,
           const Basis::Space<2>       &space,
           const DoFHandler<2>         &dh,
           const std::vector<Particle> &particles,
           std::vector<bool>           &free_active)
  {
    Solver::GridSystem<2>::Parameters p;
    p.type          = type;
    p.stabilization = 1;
    const auto grid = particle_mass::assemble(p, space, dh, particles, rho);
    const unsigned int N = dh.n_dofs();
    free_active.assign(N, false);
    for (unsigned int i = 0; i < N; ++i)
      free_active[i] =
        !grid->constraints(0).is_constrained(i) &&
        grid->lumped_mass()[grid->relevant_dofs().index_within_set(i)] > 0;
    return particle_mass::dense(*grid, N);
  }

  using particle_mass::asymmetry;

  /// {lambda_min / lambda_max, condition number} of D^-1/2 A D^-1/2 on
  /// the DoFs @p use (what Jacobi-preconditioned CG sees).
  std::pair<double, double>
  jacobi_spectrum(const FullMatrix<double> &A, const std::vector<bool> &use)
  {
    std::vector<unsigned int> idx;
    for (unsigned int i = 0; i < A.m(); ++i)
      if (use[i])
        idx.push_back(i);
    LAPACKFullMatrix<double> S(idx.size(), idx.size());
    for (unsigned int a = 0; a < idx.size(); ++a)
      for (unsigned int b = 0; b < idx.size(); ++b)
        S(a, b) =
          A(idx[a], idx[b]) / std::sqrt(A(idx[a], idx[a]) * A(idx[b], idx[b]));
    Vector<double>     ev;
    FullMatrix<double> dummy;
    S.compute_eigenvalues_symmetric(-1e300, 1e300, 0, ev, dummy);
    const double lmin = *std::min_element(ev.begin(), ev.end());
    const double lmax = *std::max_element(ev.begin(), ev.end());
    return {lmin / lmax, lmin > 0 ? lmax / lmin : 1e300};
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  out << std::setprecision(3);

  for (const unsigned int degree : {2u, 3u})
    {
      out << "p = " << degree << std::endl;
      Triangulation<2> tria;
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                {4, 2},
                                                Point<2>(0, 0),
                                                Point<2>(2, 1),
                                                true);
      Basis::TensorBSpline space;
      space.set_degree(degree);
      DoFHandler<2> dh(tria);
      dh.distribute_dofs(space.dof_layout());
      space.reinit(dh);

      // A fraction f(center) of rho |cell| in each cell, on a 4 x 4 grid
      // of particles.
      const auto fill = [&](const std::function<double(const Point<2> &)> &f) {
        std::vector<Particle> ps;
        for (const auto &cell : dh.active_cell_iterators())
          {
            const double fraction = f(cell->center());
            if (fraction == 0)
              continue;
            for (unsigned int i = 0; i < 4; ++i)
              for (unsigned int j = 0; j < 4; ++j)
                {
                  const Point<2> x(cell->vertex(0)[0] +
                                     (i + 0.5) / 4 *
                                       cell->extent_in_direction(0),
                                   cell->vertex(0)[1] +
                                     (j + 0.5) / 4 *
                                       cell->extent_in_direction(1));
                  ps.push_back({cell->active_cell_index(),
                                x,
                                fraction * rho * cell->measure() / 16});
                }
          }
        return ps;
      };

      // A.
      std::vector<double> conditions;
      for (const double eps : {1e-1, 1e-2, 1e-3})
        {
          auto ps = fill([](const Point<2> &c) { return c[0] < 1 ? 1. : 0.; });
          const Point<2> x(1 + eps, 0.25);
          unsigned int   host = numbers::invalid_unsigned_int;
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->point_inside(x))
              host = cell->active_cell_index();
          ps.push_back({host, x, rho * 0.25 * 0.25 / 16});
          for (const std::string type : {"consistent", "ghost penalty"})
            {
              std::vector<bool>        use;
              const FullMatrix<double> A = assemble(type, space, dh, ps, use);
              const auto [lmin, cond]    = jacobi_spectrum(A, use);
              out << "A eps " << eps << " " << type << ": asymmetry "
                  << filter(asymmetry(A), 1e-14) << ", lambda_min/lambda_max "
                  << filter(lmin, 1e-10) << ", condition "
                  << (cond > 1e10 ? std::string("> 1e10") :
                                    Utilities::to_string(std::round(cond)))
                  << std::endl;
              PSMPM_CHECK(out, asymmetry(A) < 1e-14);
              if (type == "consistent")
                PSMPM_CHECK(out, cond > 1e10);
              else
                conditions.push_back(cond);
            }
        }
      out << "ghost penalty: condition bounded as eps -> 0" << std::endl;
      PSMPM_CHECK(out,
                  *std::max_element(conditions.begin(), conditions.end()) <
                    1e5);
      PSMPM_CHECK(out, conditions.back() < 2 * conditions.front());

      // B. Every cell filled: the consistent matrix.
      {
        const auto        ps = fill([](const Point<2> &) { return 1.; });
        std::vector<bool> use;
        const auto consistent = assemble("consistent", space, dh, ps, use);
        FullMatrix<double> D  = assemble("ghost penalty", space, dh, ps, use);
        D.add(-1., consistent);
        const double rel = D.frobenius_norm() / consistent.frobenius_norm();
        out << "B filled: |M - M_consistent| / |M_consistent| "
            << filter(rel, 1e-13) << std::endl;
        PSMPM_CHECK(out, rel < 1e-13);
      }

      // C. Every cell half filled: zero on constants and affine fields
      // (coefficients: the field at the control points) on the free rows.
      {
        const auto        ps = fill([](const Point<2> &) { return 0.5; });
        std::vector<bool> use;
        const auto consistent = assemble("consistent", space, dh, ps, use);
        FullMatrix<double> D  = assemble("ghost penalty", space, dh, ps, use);
        D.add(-1., consistent);
        const auto     X = space.control_points(dh);
        Vector<double> v(X.size()), one(X.size()), Dv(X.size()), Mv(X.size());
        for (unsigned int i = 0; i < X.size(); ++i)
          v[i] = 1 + 2 * X[i][0] - 3 * X[i][1], one[i] = 1;
        const auto on_free = [&](const Vector<double> &u) {
          D.vmult(Dv, u);
          consistent.vmult(Mv, u);
          double d = 0, m = 0;
          for (unsigned int i = 0; i < u.size(); ++i)
            if (use[i])
              d += Dv[i] * Dv[i], m += Mv[i] * Mv[i];
          return std::sqrt(d / m);
        };
        const double affine   = on_free(v);
        const double constant = on_free(one);
        out << "C half filled: |M - M_consistent| / |M_consistent| "
            << D.frobenius_norm() / consistent.frobenius_norm()
            << ", on an affine field " << filter(affine, 1e-12)
            << ", on a constant " << filter(constant, 1e-12) << std::endl;
        PSMPM_CHECK(out,
                    D.frobenius_norm() > 1e-3 * consistent.frobenius_norm());
        PSMPM_CHECK(out, affine < 1e-12 && constant < 1e-12);
      }
    }
}
