// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Test helpers shared by the mass matrix tests of this directory: the
// particle mass matrix of a strategy from hand-placed particles, as a
// dense matrix.
#ifndef psmpm_tests_solver_particle_mass_h
#define psmpm_tests_solver_particle_mass_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/basis/space.h>
#include <psmpm/solver/grid_system.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace particle_mass
{
  using namespace dealii;

  struct Particle
  {
    unsigned int cell;
    Point<2>     x;
    double       m;
  };

  /// A grid system of parameters @p p (reference density @p rho, no
  /// boundary conditions) with the particle blocks of @p particles
  /// accumulated and the mass matrix assembled.
  inline std::unique_ptr<psmpm::Solver::GridSystem<2>>
  assemble(const psmpm::Solver::GridSystem<2>::Parameters &p,
           const psmpm::Basis::Space<2>                   &space,
           const DoFHandler<2>                            &dh,
           const std::vector<Particle>                    &particles,
           const double                                    rho)
  {
    auto grid = std::make_unique<psmpm::Solver::GridSystem<2>>(p,
                                                               space,
                                                               dh,
                                                               MPI_COMM_WORLD);
    grid->reinit({}, rho);
    grid->zero_cell_mass();
    grid->zero_cell_rhs();
    const unsigned int  n     = grid->dofs_per_cell;
    auto               &cells = grid->cell_arrays();
    std::vector<double> phi(n);
    for (const auto &q : particles)
      {
        space.evaluate(q.cell, q.x, phi.data(), nullptr);
        for (unsigned int k = 0; k < n; ++k)
          {
            cells.lumped[q.cell * n + k] += q.m * phi[k];
            for (unsigned int l = 0; l < n; ++l)
              cells.mass[(q.cell * n + k) * n + l] += q.m * phi[k] * phi[l];
          }
      }
    grid->assemble_mass();
    return grid;
  }

  /// The assembled matrix of component 0 as a dense matrix.
  inline FullMatrix<double>
  dense(const psmpm::Solver::GridSystem<2> &grid, const unsigned int n_dofs)
  {
    const auto        &M = grid.mass_matrix(0);
    FullMatrix<double> A(n_dofs, n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = 0; j < n_dofs; ++j)
        A(i, j) = M.el(i, j);
    return A;
  }

  /// Largest |A_ij - A_ji| over the largest |A_ij|.
  inline double
  asymmetry(const FullMatrix<double> &A)
  {
    double a = 0, s = 0;
    for (unsigned int i = 0; i < A.m(); ++i)
      for (unsigned int j = 0; j < A.n(); ++j)
        a = std::max(a, std::abs(A(i, j) - A(j, i))),
        s = std::max(s, std::abs(A(i, j)));
    return a / s;
  }
} // namespace particle_mass

#endif
