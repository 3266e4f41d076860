// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The mass matrix of each matrix strategy from hand-placed particles on a
// 2 x 2 criss-cross Powell-Sabin mesh of the unit square (rho = 1000):
// A. the left half filled (64 particles per triangle at the centroids of
//    an 8 x 8 split, so that the fill is 1), the right half empty but for
//    ONE particle that has just crossed x = 0.5, at distance eps from
//    the edge (eps = 1e-1, 1e-2, 1e-3): the functions of the vertex
//    (0.75, 0.25) are then supported by that one particle, at the edge of
//    their support; the particle matrix has rank one there. Checked: every
//    assembled matrix is symmetric; the consistent one is singular
//    (Jacobi-scaled condition over the DoFs with particle mass above 1e10);
//    `ghost penalty`, `fictitious mass` and `blended lumping` are positive
//    definite with a condition number below 1e4 that does not grow as eps -> 0.
// B. every cell filled: both new strategies give the consistent matrix
//    (to round-off).
// C. every cell half filled: `ghost penalty` differs from the consistent
//    matrix but not on constants and affine fields (momentum, rigid
//    motion); `fictitious mass` minus consistent is
//    alpha rho / 2 times the exact mass matrix, i.e. linear in alpha
//    (alpha = 1e-2 and 1e-3); `blended lumping` keeps the row sums.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/grid_system.h>

#include "../tests.h"
#include "particle_mass.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>

namespace
{
  using namespace psmpm;
  const double rho = 1000;

  using particle_mass::Particle;

  /// Centroids of the 8 x 8 split of a triangle (64 points, equal weight).
  std::vector<Point<2>>
  split_points(const Point<2> &a, const Point<2> &b, const Point<2> &c)
  {
    const unsigned int    k = 8;
    std::vector<Point<2>> r;
    for (unsigned int j = 0; j < k; ++j)
      for (unsigned int i = 0; i + j < k; ++i)
        for (const double s : {1. / 3, 2. / 3})
          if (!(s > 0.5 && i + j + 1 >= k))
            r.push_back(a + ((i + s) / k) * (b - a) + ((j + s) / k) * (c - a));
    return r;
  }

  /// Assembled matrix (component 0) of strategy @p type as a dense matrix;
  /// @p active: DoFs with particle mass.
  FullMatrix<double>
  assemble(const std::string           &type,
           const double                 alpha,
           const Basis::Space<2>       &space,
           const DoFHandler<2>         &dh,
           const std::vector<Particle> &particles,
           std::vector<bool>           &active)
  {
    Solver::GridSystem<2>::Parameters p;
    p.type          = type;
    p.stabilization = alpha;
    const auto grid = particle_mass::assemble(p, space, dh, particles, rho);
    const unsigned int N = dh.n_dofs();
    active.assign(N, false);
    for (unsigned int i = 0; i < N; ++i)
      active[i] =
        grid->lumped_mass()[grid->relevant_dofs().index_within_set(i)] > 0;
    return particle_mass::dense(*grid, N);
  }

  using particle_mass::asymmetry;

  /// Smallest eigenvalue over the largest of D^-1/2 A D^-1/2 restricted
  /// to the active DoFs (what Jacobi-preconditioned CG sees): returns
  /// {lambda_min, condition number}.
  std::pair<double, double>
  jacobi_spectrum(const FullMatrix<double> &A, const std::vector<bool> &active)
  {
    std::vector<unsigned int> idx;
    for (unsigned int i = 0; i < A.m(); ++i)
      if (active[i])
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

  double
  frobenius(const FullMatrix<double> &A)
  {
    return A.frobenius_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  out << std::setprecision(3);

  Triangulation<2> tria;
  Mesh::MeshGenerator<2>::make_blocks(
    tria,
    Point<2>(0, 0),
    Point<2>(1, 1),
    2,
    2,
    Mesh::MeshGenerator<2>::Type::criss_cross);
  const auto    space = Basis::create_space<2>("powell-sabin");
  DoFHandler<2> dh(tria);
  dh.distribute_dofs(space->dof_layout());
  space->reinit(dh);

  // Fill with particles: fraction of rho |cell| per cell by predicate.
  const auto fill = [&](const std::function<double(const Point<2> &)> &f) {
    std::vector<Particle> ps;
    for (const auto &cell : dh.active_cell_iterators())
      {
        const double fraction = f(cell->center());
        if (fraction == 0)
          continue;
        const auto pts =
          split_points(cell->vertex(0), cell->vertex(1), cell->vertex(2));
        for (const auto &x : pts)
          ps.push_back({cell->active_cell_index(),
                        x,
                        fraction * rho * cell->measure() / pts.size()});
      }
    return ps;
  };

  // A. One particle that has just left the filled half: at distance eps
  // from the edge x = 0.5 inside the triangle (0.5, 0), (0.5, 0.5),
  // (0.75, 0.25), where the functions of (0.75, 0.25) have it at the edge
  // of their support.
  const std::vector<std::string>             types = {"consistent",
                                                      "ghost penalty",
                                                      "fictitious mass",
                                                      "blended lumping",
                                                      "partially lumped"};
  std::map<std::string, std::vector<double>> conditions;
  for (const double eps : {1e-1, 1e-2, 1e-3})
    {
      auto ps = fill([](const Point<2> &c) { return c[0] < 0.5 ? 1. : 0.; });
      const Point<2> x(0.5 + eps, 0.25);
      unsigned int   host = numbers::invalid_unsigned_int;
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->center()[0] > 0.5 && cell->center()[0] < 0.6 &&
            cell->center()[1] < 0.5)
          host = cell->active_cell_index();
      ps.push_back({host, x, rho * 0.25 * 0.25 / 64});
      for (const auto &type : types)
        {
          std::vector<bool>        active;
          const FullMatrix<double> A =
            assemble(type, 0.1, *space, dh, ps, active);
          const auto [lmin, cond] = jacobi_spectrum(A, active);
          conditions[type].push_back(cond);
          out << "A eps " << eps << " " << type << ": asymmetry "
              << filter(asymmetry(A), 1e-14) << ", lambda_min/lambda_max "
              << filter(lmin, 1e-10) << ", condition "
              << (cond > 1e10 ? std::string("> 1e10") :
                                Utilities::to_string(std::round(cond)))
              << std::endl;
          PSMPM_CHECK(out, asymmetry(A) < 1e-14);
        }
    }
  PSMPM_CHECK(out, conditions["consistent"].back() > 1e10);
  for (const std::string type :
       {"ghost penalty", "fictitious mass", "blended lumping"})
    {
      const auto &c = conditions[type];
      out << type << ": condition bounded as eps -> 0" << std::endl;
      PSMPM_CHECK(out, *std::max_element(c.begin(), c.end()) < 1e4);
      PSMPM_CHECK(out, c.back() < 2 * c.front());
    }

  // B. Every cell filled: the consistent matrix.
  {
    const auto        ps = fill([](const Point<2> &) { return 1.; });
    std::vector<bool> active;
    const auto consistent = assemble("consistent", 0.1, *space, dh, ps, active);
    for (const std::string type :
         {"ghost penalty", "fictitious mass", "blended lumping"})
      {
        FullMatrix<double> D = assemble(type, 0.1, *space, dh, ps, active);
        D.add(-1., consistent);
        const double rel = frobenius(D) / frobenius(consistent);
        out << "B filled " << type << ": |M - M_consistent| / |M_consistent| "
            << filter(rel, 1e-13) << std::endl;
        PSMPM_CHECK(out, rel < 1e-13);
      }
  }

  // C. Every cell half filled.
  {
    const auto        ps = fill([](const Point<2> &) { return 0.5; });
    std::vector<bool> active;
    const auto consistent = assemble("consistent", 0.1, *space, dh, ps, active);
    std::vector<double> differences;
    for (const double alpha : {1e-2, 1e-3})
      {
        FullMatrix<double> D =
          assemble("fictitious mass", alpha, *space, dh, ps, active);
        D.add(-1., consistent);
        differences.push_back(frobenius(D) / frobenius(consistent));
        out << "C half filled, alpha " << alpha
            << ": |M - M_consistent| / |M_consistent| " << differences.back()
            << std::endl;
      }
    // The particle matrix of a half-filled mesh is half the exact one
    // (to quadrature error), so the relative difference is ~ alpha.
    PSMPM_CHECK(out, std::abs(differences[0] / differences[1] - 10) < 1e-8);
    PSMPM_CHECK(out, differences[0] > 0.9e-2 && differences[0] < 1.1e-2);

    // Ghost penalty: nonzero, but zero on affine fields (coefficients:
    // the field at the control points) and on constants (row sums).
    {
      FullMatrix<double> D =
        assemble("ghost penalty", 0.1, *space, dh, ps, active);
      D.add(-1., consistent);
      const auto     X = space->control_points(dh);
      Vector<double> v(X.size()), one(X.size()), Dv(X.size()), Mv(X.size());
      for (unsigned int i = 0; i < X.size(); ++i)
        v[i] = 1 + 2 * X[i][0] - 3 * X[i][1], one[i] = 1;
      D.vmult(Dv, v);
      consistent.vmult(Mv, v);
      const double affine = Dv.l2_norm() / Mv.l2_norm();
      D.vmult(Dv, one);
      consistent.vmult(Mv, one);
      const double constant = Dv.l2_norm() / Mv.l2_norm();
      out << "C half filled, ghost penalty: |M - M_consistent| / "
             "|M_consistent| "
          << frobenius(D) / frobenius(consistent) << ", on an affine field "
          << filter(affine, 1e-12) << ", on a constant "
          << filter(constant, 1e-12) << std::endl;
      PSMPM_CHECK(out, frobenius(D) > 1e-3 * frobenius(consistent));
      PSMPM_CHECK(out, affine < 1e-12 && constant < 1e-12);
    }

    const auto blended =
      assemble("blended lumping", 0.1, *space, dh, ps, active);
    double row_error = 0, row_scale = 0;
    for (unsigned int i = 0; i < blended.m(); ++i)
      {
        double a = 0, b = 0;
        for (unsigned int j = 0; j < blended.n(); ++j)
          a += blended(i, j), b += consistent(i, j);
        row_error = std::max(row_error, std::abs(a - b));
        row_scale = std::max(row_scale, std::abs(b));
      }
    out << "C half filled, blended lumping: row sums kept" << std::endl;
    PSMPM_CHECK(out, row_error < 1e-13 * row_scale);
    FullMatrix<double> D = blended;
    D.add(-1., consistent);
    PSMPM_CHECK(out, frobenius(D) > 1e-3 * frobenius(consistent));
  }
}
