// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Mass matrix/Preconditioner = pmg on Powell-Sabin particle mass matrices
// (8 x 8 criss-cross unit square, rho = 1000, component 0 fixed on the
// left, component 1 on the bottom, consistent mass, Direct solver size 0):
// A. the prolongation P from P1 on the same triangles reproduces an affine
//    field exactly: P f(vertices) = f(control points) to round-off;
// B. every cell filled (64 particles per triangle): pmg-CG converges to
//    the Jacobi-CG solution, fixed DoFs stay zero, the Galerkin coarse
//    matrix is symmetric;
// C. nearly empty: the top row of cells holds one light particle each
//    (mass 1e-6 of a full cell, near a corner), the regime of the soil
//    column's failing consistent step: pmg-CG (either smoother) gives
//    Jacobi-CG's velocity at the particles (to 1e-6 relative; the
//    coefficients themselves differ, those of the nearly empty cells'
//    functions are determined by one light particle), in fewer
//    than half Jacobi-CG's iterations and fewer than 100 for both
//    components, a bound that Jacobi-CG exceeds;
// D. empty cells: the top two rows of cells hold no particle, so the
//    DoFs of component 0 fixed on the left boundary there have an empty
//    row (no particle mass to put on the diagonal): pmg-CG (either
//    smoother, either coarse matrix) converges to the Jacobi-CG solution
//    and keeps the fixed DoFs at zero. The smoothers divided by that zero
//    diagonal, and the first CG residual was NaN.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/grid_system.h>

#include "../tests.h"

#include <memory>

namespace
{
  using namespace psmpm;
  const double rho = 1000;

  struct Particle
  {
    unsigned int cell;
    Point<2>     x;
    double       m;
  };

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

  struct Result
  {
    std::vector<Tensor<1, 2>> solution;
    unsigned int              iterations;
    double                    condition;
  };

  /// Assemble and solve with velocity (1 + x, y - x^2) carried by the
  /// particles.
  Result
  solve(const std::string           &preconditioner,
        const std::string           &smoother,
        const Basis::Space<2>       &space,
        const DoFHandler<2>         &dh,
        const std::vector<Particle> &particles,
        Solver::GridSystem<2>      **keep   = nullptr,
        const std::string           &coarse = "galerkin")
  {
    Solver::GridSystem<2>::Parameters p;
    p.type               = "consistent";
    p.preconditioner     = preconditioner;
    p.multigrid_smoother = smoother;
    p.multigrid_coarse   = coarse;
    p.direct_size        = 0;
    p.max_iterations     = 100000;
    auto grid =
      std::make_unique<Solver::GridSystem<2>>(p, space, dh, MPI_COMM_WORLD);
    grid->reinit({std::set<types::boundary_id>{0},
                  std::set<types::boundary_id>{2}},
                 rho);
    grid->zero_cell_mass();
    grid->zero_cell_rhs();
    const unsigned int  n     = grid->dofs_per_cell;
    auto               &cells = grid->cell_arrays();
    std::vector<double> phi(n);
    for (const auto &q : particles)
      {
        space.evaluate(q.cell, q.x, phi.data(), nullptr);
        const Tensor<1, 2> v({1 + q.x[0], q.x[1] - q.x[0] * q.x[0]});
        for (unsigned int k = 0; k < n; ++k)
          {
            cells.lumped[q.cell * n + k] += q.m * phi[k];
            cells.rhs[q.cell * n + k] += q.m * phi[k] * v;
            for (unsigned int l = 0; l < n; ++l)
              cells.mass[(q.cell * n + k) * n + l] += q.m * phi[k] * phi[l];
          }
      }
    grid->assemble_mass();
    Result r;
    grid->solve(r.solution);
    r.iterations = grid->statistics().iterations;
    r.condition  = grid->statistics().condition_number;
    if (keep != nullptr)
      *keep = grid.release();
    return r;
  }

  /// Largest difference of the two velocity fields at the particles over
  /// the largest velocity there: what MPM uses of a solution (the
  /// coefficients of functions that only a light particle supports are
  /// determined by it alone, so they may differ where the fields agree).
  double
  difference_at_particles(const Result                &a,
                          const Result                &b,
                          const Basis::Space<2>       &space,
                          const DoFHandler<2>         &dh,
                          const std::vector<Particle> &particles)
  {
    const unsigned int                   n = space.dofs_per_cell();
    std::vector<double>                  phi(n);
    std::vector<types::global_dof_index> dofs(n);
    double                               diff = 0, norm = 0;
    for (const auto &q : particles)
      {
        const typename DoFHandler<2>::active_cell_iterator
          cell(&dh.get_triangulation(), 0, q.cell, &dh);
        cell->get_dof_indices(dofs);
        space.evaluate(q.cell, q.x, phi.data(), nullptr);
        Tensor<1, 2> va, vb;
        for (unsigned int k = 0; k < n; ++k)
          va += phi[k] * a.solution[dofs[k]],
            vb += phi[k] * b.solution[dofs[k]];
        diff = std::max(diff, (va - vb).norm());
        norm = std::max(norm, vb.norm());
      }
    return diff / norm;
  }

  double
  difference(const Result &a, const Result &b)
  {
    double diff = 0, norm = 0;
    for (unsigned int i = 0; i < a.solution.size(); ++i)
      {
        diff = std::max(diff, (a.solution[i] - b.solution[i]).norm());
        norm = std::max(norm, b.solution[i].norm());
      }
    return diff / norm;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  out << std::setprecision(3);
  return run_test([&]() {
    Triangulation<2> tria;
    Mesh::MeshGenerator<2>::make_blocks(
      tria,
      Point<2>(0, 0),
      Point<2>(1, 1),
      8,
      8,
      Mesh::MeshGenerator<2>::Type::criss_cross);
    const auto    space = Basis::create_space<2>("powell-sabin");
    DoFHandler<2> dh(tria);
    dh.distribute_dofs(space->dof_layout());
    space->reinit(dh);

    std::vector<Particle> full, nearly_empty, empty;
    for (const auto &cell : dh.active_cell_iterators())
      {
        const auto pts =
          split_points(cell->vertex(0), cell->vertex(1), cell->vertex(2));
        const double m = rho * cell->measure() / pts.size();
        for (const auto &x : pts)
          full.push_back({cell->active_cell_index(), x, m});
        if (cell->center()[1] < 0.75)
          for (const auto &x : pts)
            empty.push_back({cell->active_cell_index(), x, m});
        if (cell->center()[1] < 0.875)
          for (const auto &x : pts)
            nearly_empty.push_back({cell->active_cell_index(), x, m});
        else
          nearly_empty.push_back(
            {cell->active_cell_index(),
             cell->vertex(0) + 0.05 * (cell->center() - cell->vertex(0)),
             1e-6 * rho * cell->measure()});
      }

    // A. Exact prolongation of an affine field.
    Solver::GridSystem<2> *grid = nullptr;
    const Result           full_pmg =
      solve("pmg", "gauss-seidel", *space, dh, full, &grid);
    std::unique_ptr<Solver::GridSystem<2>> owner(grid);
    const auto                            &P = grid->multigrid().prolongation();
    const auto                             points = space->control_points(dh);
    const auto f = [](const Point<2> &x) { return 1 + 2 * x[0] - 3 * x[1]; };
    Vector<double> coarse(tria.n_vertices()), fine(dh.n_dofs());
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      coarse[v] = f(tria.get_vertices()[v]);
    P.vmult(fine, coarse);
    double error = 0;
    for (unsigned int i = 0; i < dh.n_dofs(); ++i)
      error = std::max(error, std::abs(fine[i] - f(points[i])));
    out << "A P: " << P.m() << " x " << P.n() << ", affine error "
        << filter(error) << std::endl;
    PSMPM_CHECK(out, P.m() == dh.n_dofs() && P.n() == tria.n_vertices());
    PSMPM_CHECK(out, error < 1e-12);

    // B. Filled.
    const Result full_jacobi = solve("jacobi", "", *space, dh, full);
    const double d_full      = difference(full_pmg, full_jacobi);
    double       asym = 0, scale = 0;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const auto &A = grid->multigrid().coarse_matrix(d);
        for (auto e = A.begin(); e != A.end(); ++e)
          asym =
            std::max(asym, std::abs(e->value() - A(e->column(), e->row()))),
          scale = std::max(scale, std::abs(e->value()));
      }
    double fixed = 0;
    for (unsigned int l = 0; l < full_pmg.solution.size(); ++l)
      for (unsigned int d = 0; d < 2; ++d)
        if (grid->dirichlet_constraints(d).is_constrained(l))
          fixed = std::max(fixed, std::abs(full_pmg.solution[l][d]));
    out << "B filled: pmg " << full_pmg.iterations << " iterations, jacobi "
        << full_jacobi.iterations << "; relative difference "
        << filter(d_full, 1e-9) << std::endl;
    PSMPM_CHECK(out, d_full < 1e-9);
    PSMPM_CHECK(out, fixed == 0);
    PSMPM_CHECK(out, asym < 1e-12 * scale);
    PSMPM_CHECK(out, full_pmg.iterations < full_jacobi.iterations);

    // C. Nearly empty top row.
    const Result empty_jacobi = solve("jacobi", "", *space, dh, nearly_empty);
    const Result empty_pmg =
      solve("pmg", "gauss-seidel", *space, dh, nearly_empty);
    const Result empty_pmg_jacobi =
      solve("pmg", "jacobi", *space, dh, nearly_empty);
    const double d_gs = difference_at_particles(empty_pmg,
                                                empty_jacobi,
                                                *space,
                                                dh,
                                                nearly_empty);
    const double d_j  = difference_at_particles(empty_pmg_jacobi,
                                               empty_jacobi,
                                               *space,
                                               dh,
                                               nearly_empty);
    out << "C nearly empty: iterations jacobi " << empty_jacobi.iterations
        << ", pmg (gauss-seidel) " << empty_pmg.iterations << ", pmg (jacobi) "
        << empty_pmg_jacobi.iterations
        << "; relative differences at the particles " << filter(d_gs, 1e-6)
        << ", " << filter(d_j, 1e-6) << std::endl;
    PSMPM_CHECK(out, d_gs < 1e-6 && d_j < 1e-6);
    PSMPM_CHECK(out, 2 * empty_pmg.iterations < empty_jacobi.iterations);
    PSMPM_CHECK(out, empty_pmg.iterations < 100);
    PSMPM_CHECK(out, empty_jacobi.iterations >= 100);

    // D. Empty top rows: fixed DoFs without particle mass.
    const Result empty_rows_jacobi = solve("jacobi", "", *space, dh, empty);
    unsigned int unsupported_fixed = 0;
    {
      std::vector<char>                    supported(dh.n_dofs(), 0);
      std::vector<types::global_dof_index> dofs(space->dofs_per_cell());
      for (const auto &q : empty)
        {
          const typename DoFHandler<2>::active_cell_iterator cell(&tria,
                                                                  0,
                                                                  q.cell,
                                                                  &dh);
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            supported[i] = 1;
        }
      for (unsigned int i = 0; i < dh.n_dofs(); ++i)
        unsupported_fixed +=
          !supported[i] && grid->dirichlet_constraints(0).is_constrained(i);
    }
    out << "D empty top rows: " << unsupported_fixed
        << " fixed DoFs of component 0 without particles; iterations jacobi "
        << empty_rows_jacobi.iterations << std::endl;
    PSMPM_CHECK(out, unsupported_fixed > 0);
    for (const std::string coarse : {"galerkin", "particles"})
      for (const std::string smoother : {"gauss-seidel", "jacobi"})
        {
          Solver::GridSystem<2> *g = nullptr;
          const Result           r =
            solve("pmg", smoother, *space, dh, empty, &g, coarse);
          std::unique_ptr<Solver::GridSystem<2>> o(g);
          double                                 fixed_value = 0;
          for (unsigned int l = 0; l < r.solution.size(); ++l)
            for (unsigned int d = 0; d < 2; ++d)
              if (g->dirichlet_constraints(d).is_constrained(l))
                fixed_value = std::max(fixed_value, std::abs(r.solution[l][d]));
          const double d_empty = difference(r, empty_rows_jacobi);
          out << "D pmg (" << coarse << ", " << smoother
              << "): " << r.iterations << " iterations; relative difference "
              << filter(d_empty, 1e-9) << std::endl;
          PSMPM_CHECK(out, d_empty < 1e-9);
          PSMPM_CHECK(out, fixed_value == 0);
          PSMPM_CHECK(out, r.iterations < empty_rows_jacobi.iterations);
        }
  });
}
