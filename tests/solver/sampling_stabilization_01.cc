// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Mass matrix/Sampling stabilization (Solver::SamplingStabilization) on
// the particle mass matrix of a 3 x 2 criss-cross Powell-Sabin mesh of
// [0, 1.5] x [0, 1] (rho = 1000), particles placed by hand, every cell
// filled (so no emptying-cell strategy acts):
// A. 64 particles per triangle (centroids of an 8 x 8 split): the
//    particles sample every cell well, no weight is set and the matrix is
//    the consistent one exactly;
// B. two particles per triangle, on a line through its centroid: the
//    consistent matrix is singular (Jacobi-scaled condition > 1e10); with
//    the stabilisation (target 0.5 and 1) it is symmetric positive
//    definite with a condition number below 1e6, the change
//    D = M - M_consistent is positive semi-definite and vanishes on the
//    coefficients of every affine field (1, x, y: momentum and affine
//    fields kept; row sums zero). Particles on a line do not see the
//    quadratics that vanish on it, so D acts on quadratics too here;
// C. P1 on the same sparse layout: unchanged (no non-polynomial modes);
// D. the thesis bar (Powell-Sabin, 4 blocks, automatic mass matrix,
//    dt = 1e-3 to t = 0.1): with 3 x 3 particles per block the run
//    without the stabilisation ends unstable and the default run
//    completes; with 16 x 14 per block (56 particles per triangle) both
//    complete with errors within 1 % (measured: 0.3 %): where the
//    particles sample the cells, the stabilisation changes little.
//    With 5 x 2 per block (two lines of particles per block row) at the
//    automatic time step the default run completes (it grew its energy
//    by 10 % in 2 steps before the quadratic modes were lifted);
// E. one block row (3 x 1 criss-cross blocks of [0, 1.5] x [0, 0.5]),
//    particles on the lines y = 0.1 and y = 0.4 only, every cell full:
//    (y - 0.1)(y - 0.4) vanishes at every particle, so the consistent
//    matrix is singular (condition > 1e10); the stabilised one
//    (target 0.5) has a condition below 1e6, D is positive
//    semi-definite and vanishes on the affine fields. (With the lift of
//    the quadratic modes removed, the non-polynomial modes alone, E's
//    stabilised matrix is not positive definite and D's 5 x 2 run ends
//    unstable: both checks fail.)
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/grid_system.h>

#include "../mpm_tests.h"
#include "particle_mass.h"

#include <filesystem>
#include <functional>

namespace
{
  using namespace psmpm;
  const double rho = 1000;

  using particle_mass::Particle;

  /// Particles at the given barycentric points of every cell, the cell's
  /// mass rho |c| shared equally: every cell is filled.
  std::vector<Particle>
  place(const DoFHandler<2> &dh, const std::vector<Point<2>> &barycentric)
  {
    std::vector<Particle> ps;
    for (const auto &cell : dh.active_cell_iterators())
      for (const auto &b : barycentric)
        ps.push_back({cell->active_cell_index(),
                      cell->vertex(0) +
                        b[0] * (cell->vertex(1) - cell->vertex(0)) +
                        b[1] * (cell->vertex(2) - cell->vertex(0)),
                      rho * cell->measure() / barycentric.size()});
    return ps;
  }

  /// Particles at the given points, each in the cell that contains it,
  /// a cell's mass rho |c| shared equally among its particles (every
  /// cell must receive one).
  std::vector<Particle>
  place_physical(const DoFHandler<2> &dh, const std::vector<Point<2>> &points)
  {
    std::vector<Particle> ps;
    for (const auto &cell : dh.active_cell_iterators())
      {
        const Point<2> a = cell->vertex(0), b = cell->vertex(1),
                       c = cell->vertex(2);
        std::vector<Point<2>> inside;
        for (const auto &x : points)
          {
            // Barycentric coordinates of x (strictly inside).
            const double det =
              (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            const double l1 =
              ((x[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (x[1] - a[1])) /
              det;
            const double l2 =
              ((b[0] - a[0]) * (x[1] - a[1]) - (x[0] - a[0]) * (b[1] - a[1])) /
              det;
            if (l1 > 0 && l2 > 0 && l1 + l2 < 1)
              inside.push_back(x);
          }
        AssertThrow(!inside.empty(), ExcMessage("a cell without particles"));
        for (const auto &x : inside)
          ps.push_back({cell->active_cell_index(),
                        x,
                        rho * cell->measure() / inside.size()});
      }
    return ps;
  }

  /// Centroids of the 8 x 8 split of the reference triangle.
  std::vector<Point<2>>
  split_points()
  {
    const unsigned int    k = 8;
    std::vector<Point<2>> r;
    for (unsigned int j = 0; j < k; ++j)
      for (unsigned int i = 0; i + j < k; ++i)
        for (const double s : {1. / 3, 2. / 3})
          if (!(s > 0.5 && i + j + 1 >= k))
            r.emplace_back((i + s) / k, (j + s) / k);
    return r;
  }

  /// Assembled matrix (component 0, no boundary conditions) of the
  /// consistent strategy with sampling target @p target, as a dense matrix.
  FullMatrix<double>
  assemble(const double                 target,
           const Basis::Space<2>       &space,
           const DoFHandler<2>         &dh,
           const std::vector<Particle> &particles)
  {
    Solver::GridSystem<2>::Parameters p;
    p.type                   = "consistent";
    p.sampling_stabilization = target;
    return particle_mass::dense(
      *particle_mass::assemble(p, space, dh, particles, rho),
      dh.n_dofs());
  }

  using particle_mass::asymmetry;

  /// Condition number of D^-1/2 A D^-1/2 (what Jacobi-CG sees); 1e300 if
  /// it is not positive definite.
  double
  jacobi_condition(const FullMatrix<double> &A)
  {
    LAPACKFullMatrix<double> S(A.m(), A.n());
    for (unsigned int a = 0; a < A.m(); ++a)
      for (unsigned int b = 0; b < A.n(); ++b)
        S(a, b) = A(a, b) / std::sqrt(A(a, a) * A(b, b));
    Vector<double>     ev;
    FullMatrix<double> dummy;
    S.compute_eigenvalues_symmetric(-1e300, 1e300, 0, ev, dummy);
    const double lmin = *std::min_element(ev.begin(), ev.end());
    const double lmax = *std::max_element(ev.begin(), ev.end());
    return lmin > 0 ? lmax / lmin : 1e300;
  }

  /// Smallest eigenvalue of the symmetric @p D relative to its largest
  /// absolute one (0 for D = 0).
  double
  relative_smallest_eigenvalue(const FullMatrix<double> &D)
  {
    LAPACKFullMatrix<double> S(D.m(), D.n());
    S = D;
    Vector<double>     ev;
    FullMatrix<double> dummy;
    S.compute_eigenvalues_symmetric(-1e300, 1e300, 0, ev, dummy);
    double largest = 0;
    for (const double e : ev)
      largest = std::max(largest, std::abs(e));
    return largest > 0 ? *std::min_element(ev.begin(), ev.end()) / largest : 0.;
  }

  /// Calls @p f(dofs, quadrature point, weight, values) at every
  /// quadrature point of every cell.
  template <typename F>
  void
  for_each_point(const Basis::Space<2> &space,
                 const DoFHandler<2>   &dh,
                 const F               &f)
  {
    const unsigned int                   n = space.dofs_per_cell();
    std::vector<double>                  phi(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dh.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        const unsigned int c = cell->active_cell_index();
        const auto         q = space.cell_quadrature(dh, c);
        for (unsigned int j = 0; j < q.size(); ++j)
          {
            space.evaluate(c, q.point(j), phi.data(), nullptr);
            f(dofs, q.point(j), q.weight(j), phi);
          }
      }
  }

  /// The space's coefficients of the polynomial @p f: the L2 projection
  /// with the exact mass matrix (exact, the space reproduces quadratics);
  /// @p error: the largest deviation at the quadrature points.
  Vector<double>
  coefficients(const Basis::Space<2>                         &space,
               const DoFHandler<2>                           &dh,
               const std::function<double(const Point<2> &)> &f,
               double                                        &error)
  {
    const unsigned int N = dh.n_dofs();
    FullMatrix<double> E(N, N);
    Vector<double>     b(N), c(N);
    for_each_point(
      space,
      dh,
      [&](const auto &dofs, const auto &x, const double w, const auto &phi) {
        for (unsigned int k = 0; k < phi.size(); ++k)
          {
            b(dofs[k]) += w * phi[k] * f(x);
            for (unsigned int l = 0; l < phi.size(); ++l)
              E(dofs[k], dofs[l]) += w * phi[k] * phi[l];
          }
      });
    E.gauss_jordan();
    E.vmult(c, b);
    error = 0;
    for_each_point(
      space,
      dh,
      [&](const auto &dofs, const auto &x, const double, const auto &phi) {
        double v = 0;
        for (unsigned int k = 0; k < phi.size(); ++k)
          v += c(dofs[k]) * phi[k];
        error = std::max(error, std::abs(v - f(x)));
      });
    return c;
  }

  /// The properties of a stabilised matrix @p A against the @p consistent
  /// one it came from: symmetric, Jacobi-scaled condition below 1e6, the
  /// change D = A - consistent positive semi-definite, not zero, and
  /// zero on the coefficients of the affine fields.
  void
  check_stabilized(std::ostream             &out,
                   const Basis::Space<2>    &space,
                   const DoFHandler<2>      &dh,
                   const FullMatrix<double> &A,
                   const FullMatrix<double> &consistent)
  {
    const double c = jacobi_condition(A);
    out << " asymmetry " << filter(asymmetry(A), 1e-14) << ", condition "
        << (c < 1e6 ? "< 1e6" : Utilities::to_string(c)) << std::endl;
    PSMPM_CHECK(out, asymmetry(A) < 1e-14);
    PSMPM_CHECK(out, c < 1e6);
    FullMatrix<double> D = A;
    D.add(-1., consistent);
    PSMPM_CHECK(out, D.frobenius_norm() > 1e-3 * consistent.frobenius_norm());
    PSMPM_CHECK(out, relative_smallest_eigenvalue(D) > -1e-12);
    const std::vector<std::function<double(const Point<2> &)>> affine = {
      [](const Point<2> &) { return 1.; },
      [](const Point<2> &x) { return x[0]; },
      [](const Point<2> &x) { return x[1]; }};
    double worst = 0, fit = 0;
    for (const auto &f : affine)
      {
        double         e;
        const auto     v = coefficients(space, dh, f, e);
        Vector<double> Dv(v.size()), Mv(v.size());
        D.vmult(Dv, v);
        consistent.vmult(Mv, v);
        worst = std::max(worst, Dv.l2_norm() / Mv.l2_norm());
        fit   = std::max(fit, e);
      }
    out << "  affine fields reproduced to " << filter(fit, 1e-10)
        << ", change on them " << filter(worst, 1e-11) << std::endl;
    PSMPM_CHECK(out, fit < 1e-10);
    PSMPM_CHECK(out, worst < 1e-11);
  }

  /// Final status and displacement error of the thesis bar.
  std::pair<bool, double>
  run_bar(const std::string &layout_x,
          const std::string &layout_y,
          const std::string &target,
          const std::string &directory,
          const std::string &time_step = "1e-3")
  {
    auto solver =
      make_scene_solver("vibrating_bar_small_ps.prm",
                        {"Mesh/Blocks x=4",
                         "Particles/Per block x=" + layout_x,
                         "Particles/Per block y=" + layout_y,
                         "Mass matrix/Type=automatic",
                         "Mass matrix/Sampling stabilization=" + target,
                         "Time/Time step=" + time_step,
                         "Time/End time=0.1",
                         "Output/Interval=0"});
    std::filesystem::create_directories(directory);
    const auto status = solver->run(directory);
    const auto e      = StatisticsTable(directory).column("displacement_L2");
    return {status == psmpm::Simulator::Status::completed,
            e.empty() ? std::nan("") : e.back()};
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
    Point<2>(1.5, 1),
    3,
    2,
    Mesh::MeshGenerator<2>::Type::criss_cross);
  const auto    space = Basis::create_space<2>("powell-sabin");
  DoFHandler<2> dh(tria);
  dh.distribute_dofs(space->dof_layout());
  space->reinit(dh);

  // A. Well sampled.
  {
    const auto ps         = place(dh, split_points());
    const auto consistent = assemble(0, *space, dh, ps);
    auto       D          = assemble(0.5, *space, dh, ps);
    D.add(-1., consistent);
    out << "A 64 per triangle: |M - M_consistent| = " << D.frobenius_norm()
        << std::endl;
    PSMPM_CHECK(out, D.frobenius_norm() == 0);
  }

  // B. Two particles per triangle on a line through the centroid.
  const std::vector<Point<2>> sparse = {Point<2>(0.2, 0.4),
                                        Point<2>(0.46, 0.27)};
  {
    const auto   ps         = place(dh, sparse);
    const auto   consistent = assemble(0, *space, dh, ps);
    const double c0         = jacobi_condition(consistent);
    out << "B 2 per triangle, consistent: condition "
        << (c0 > 1e10 ? std::string("> 1e10") : Utilities::to_string(c0))
        << std::endl;
    PSMPM_CHECK(out, c0 > 1e10);
    for (const double target : {0.5, 1.})
      {
        const auto A = assemble(target, *space, dh, ps);
        out << "B target " << target << ":";
        check_stabilized(out, *space, dh, A, consistent);
      }
  }

  // C. P1: unchanged.
  {
    const auto    p1 = Basis::create_space<2>("linear");
    DoFHandler<2> dh1(tria);
    dh1.distribute_dofs(p1->dof_layout());
    p1->reinit(dh1);
    const auto ps = place(dh1, sparse);
    auto       D  = assemble(1, *p1, dh1, ps);
    D.add(-1., assemble(0, *p1, dh1, ps));
    out << "C P1: |M - M_consistent| = " << D.frobenius_norm() << std::endl;
    PSMPM_CHECK(out, D.frobenius_norm() == 0);
  }

  // D. The thesis bar.
  {
    const auto off = run_bar("3", "3", "0", "bar-3x3-off");
    const auto on  = run_bar("3", "3", "automatic", "bar-3x3-automatic");
    out << "D 3 x 3 per block: without "
        << (off.first ? "completed" : "unstable") << ", automatic "
        << (on.first ? "completed" : "unstable") << std::endl;
    PSMPM_CHECK(out, !off.first && on.first);
    const auto a = run_bar("16", "14", "0", "bar-16x14-off");
    const auto b = run_bar("16", "14", "automatic", "bar-16x14-automatic");
    out << "D 16 x 14 per block: errors " << a.second << ", " << b.second
        << std::endl;
    PSMPM_CHECK(out, a.first && b.first);
    PSMPM_CHECK(out, std::abs(a.second / b.second - 1) < 1e-2);
    const auto lines = run_bar("5", "2", "automatic", "bar-5x2-automatic", "0");
    out << "D 5 x 2 per block, automatic time step: "
        << (lines.first ? "completed" : "unstable") << std::endl;
    PSMPM_CHECK(out, lines.first);
  }

  // E. One block row, particles on two horizontal lines.
  {
    Triangulation<2> row;
    Mesh::MeshGenerator<2>::make_blocks(
      row,
      Point<2>(0, 0),
      Point<2>(1.5, 0.5),
      3,
      1,
      Mesh::MeshGenerator<2>::Type::criss_cross);
    DoFHandler<2> dh_row(row);
    dh_row.distribute_dofs(space->dof_layout());
    space->reinit(dh_row);
    std::vector<Point<2>> points;
    for (const double y : {0.1, 0.4})
      for (unsigned int k = 0; k < 60; ++k)
        points.emplace_back(0.0125 + 0.025 * k, y);
    const auto   ps         = place_physical(dh_row, points);
    const auto   consistent = assemble(0, *space, dh_row, ps);
    const double c0         = jacobi_condition(consistent);
    out << "E two lines, " << ps.size() << " particles in "
        << row.n_active_cells() << " cells, consistent: condition "
        << (c0 > 1e10 ? std::string("> 1e10") : Utilities::to_string(c0))
        << std::endl;
    PSMPM_CHECK(out, c0 > 1e10);
    out << "E target 0.5:";
    check_stabilized(out,
                     *space,
                     dh_row,
                     assemble(0.5, *space, dh_row, ps),
                     consistent);
  }
}
