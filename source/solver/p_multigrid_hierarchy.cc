// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/p_multigrid_hierarchy.h>
#include <psmpm/solver/solver_failure.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <limits>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// One V-cycle from a zero guess as a CG preconditioner (a fixed
      /// symmetric operator: symmetric smoothing, R = P^T, exact coarse
      /// solve).
      struct VCyclePreconditioner
      {
        const PMultigrid &multigrid;
        void
        vmult(Vector<double> &dst, const Vector<double> &src) const
        {
          dst = 0;
          multigrid.vcycle(1, src, dst);
        }
      };

      /// The barycentric coordinates of @p x in @p cell (entry 0 for
      /// vertex 0).
      template <int dim>
      std::array<double, dim + 1>
      barycentric(const typename Triangulation<dim>::active_cell_iterator &cell,
                  const Tensor<2, dim> &inverse_jacobian,
                  const Point<dim>     &x)
      {
        const Tensor<1, dim> l = inverse_jacobian * (x - cell->vertex(0));
        std::array<double, dim + 1> lambda;
        lambda[0] = 1;
        for (unsigned int k = 0; k < dim; ++k)
          lambda[k + 1] = l[k], lambda[0] -= l[k];
        return lambda;
      }

      /// The Jacobian of @p cell's affine map from the reference simplex.
      template <int dim>
      Tensor<2, dim>
      jacobian(const typename Triangulation<dim>::active_cell_iterator &cell)
      {
        Tensor<2, dim> J;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int r = 0; r < dim; ++r)
            J[r][k] = cell->vertex(k + 1)[r] - cell->vertex(0)[r];
        return J;
      }

      template <int dim>
      std::vector<typename Triangulation<dim>::active_cell_iterator>
      cells_by_index(const Triangulation<dim> &tria)
      {
        std::vector<typename Triangulation<dim>::active_cell_iterator> cell_of(
          tria.n_active_cells());
        for (const auto &cell : tria.active_cell_iterators())
          cell_of[cell->active_cell_index()] = cell;
        return cell_of;
      }
    } // namespace

    template <int dim>
    PMultigridHierarchy<dim>::PMultigridHierarchy(const Parameters &parameters)
      : parameters(parameters)
    {
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::clear()
    {
      prolongation_matrix.clear();
      for (unsigned int d = 0; d < dim; ++d)
        cycle[d].reset();
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::reinit(const GridSystem<dim> &grid)
    {
      // The coarse level is P1 on the same triangles, whose affine
      // pieces the Powell-Sabin space reproduces through its control
      // points; other spaces have no such pair here.
      const auto &space = grid.get_space();
      AssertThrow(space.name() == "powell-sabin",
                  ExcMessage("Mass matrix/Preconditioner = pmg: needs "
                             "Basis/Type = powell-sabin (its coarse "
                             "level is P1 on the same triangulation), "
                             "not " +
                             space.name() + "; use jacobi or amg."));
      const MPI_Comm comm = grid.get_communicator();
      AssertThrow(Utilities::MPI::n_mpi_processes(comm) == 1,
                  ExcMessage(
                    "Mass matrix/Preconditioner = pmg: runs on one "
                    "MPI process only (its levels are serial deal.II "
                    "matrices), this run has " +
                    std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
                    "; use jacobi or amg."));
      if (!grid.uses_matrix())
        return;
      build_prolongation(grid);
      build_cell_weights(grid);
      // No copy of the grid's matrix matches its sparsity yet.
      generation = numbers::invalid_unsigned_int;
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::build_prolongation(const GridSystem<dim> &grid)
    {
      // One process: the local relevant numbering is the global one.
      const auto &tria = grid.get_dof_handler().get_triangulation();
      const auto  points =
        grid.get_space().control_points(grid.get_dof_handler());
      const auto  cell_of  = cells_by_index(tria);
      const auto &vertices = grid.vertex_tables();
      const auto &global   = grid.relevant_global_indices();

      // Row i: the vertices of one cell around DoF i's vertex and the
      // barycentric coordinates of i's control point in it. Any such cell
      // gives the exact coefficients f(X_i) of an affine f; the cell that
      // contains X_i (largest smallest coordinate) gives the hat
      // function's own piece there, and the nearest one where X_i lies
      // outside the mesh (control triangles of boundary vertices).
      const unsigned int                             n = global.size();
      std::vector<std::array<unsigned int, dim + 1>> row_vertices(n);
      std::vector<std::array<double, dim + 1>>       row_weights(n);
      DynamicSparsityPattern                         dsp(n, tria.n_vertices());
      for (unsigned int v = 0; v < vertices.dofs.size(); ++v)
        for (const unsigned int i : vertices.dofs[v])
          {
            double best = -std::numeric_limits<double>::max();
            for (const unsigned int c : vertices.cells[v])
              {
                const auto                       &cell = cell_of[c];
                const std::array<double, dim + 1> lambda =
                  barycentric<dim>(cell,
                                   invert(jacobian<dim>(cell)),
                                   points[global[i]]);
                const double smallest =
                  *std::min_element(lambda.begin(), lambda.end());
                if (smallest > best)
                  {
                    best           = smallest;
                    row_weights[i] = lambda;
                    for (unsigned int k = 0; k <= dim; ++k)
                      row_vertices[i][k] = cell->vertex_index(k);
                  }
              }
            for (unsigned int k = 0; k <= dim; ++k)
              dsp.add(i, row_vertices[i][k]);
          }

      prolongation_pattern.copy_from(dsp);
      prolongation_matrix.reinit(prolongation_pattern);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k <= dim; ++k)
          prolongation_matrix.set(i, row_vertices[i][k], row_weights[i][k]);
      for (unsigned int d = 0; d < dim; ++d)
        transfer[d].reinit(prolongation_pattern);
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::build_cell_weights(const GridSystem<dim> &grid)
    {
      const auto &tria = grid.get_dof_handler().get_triangulation();
      const auto  points =
        grid.get_space().control_points(grid.get_dof_handler());
      const auto  cell_of   = cells_by_index(tria);
      const auto &global    = grid.relevant_global_indices();
      const auto &cell_dofs = grid.cell_dofs();

      // The cells' own pieces (coarse = particles) and the P1 pattern.
      const unsigned int n_dofs = grid.dofs_per_cell;
      cell_weights.assign(grid.n_cells * n_dofs * (dim + 1), 0.);
      cell_vertices.assign(grid.n_cells * (dim + 1), 0);
      DynamicSparsityPattern p1(tria.n_vertices(), tria.n_vertices());
      for (const unsigned int c : grid.owned_cells())
        {
          const auto          &cell = cell_of[c];
          const Tensor<2, dim> Jinv = invert(jacobian<dim>(cell));
          for (unsigned int k = 0; k < n_dofs; ++k)
            {
              const unsigned int                i = cell_dofs[c * n_dofs + k];
              const std::array<double, dim + 1> lambda =
                barycentric<dim>(cell, Jinv, points[global[i]]);
              std::copy(lambda.begin(),
                        lambda.end(),
                        &cell_weights[(c * n_dofs + k) * (dim + 1)]);
            }
          for (const unsigned int a : cell->vertex_indices())
            {
              cell_vertices[c * (dim + 1) + a] = cell->vertex_index(a);
              for (const unsigned int b : cell->vertex_indices())
                p1.add(cell->vertex_index(a), cell->vertex_index(b));
            }
        }
      for (unsigned int v = 0; v < tria.n_vertices(); ++v)
        p1.add(v, v);
      p1_pattern.copy_from(p1);

      const auto &vertices = grid.vertex_tables();
      for (unsigned int d = 0; d < dim; ++d)
        {
          // A P1 vertex is fixed where the space fixes any of its
          // functions (Powell-Sabin: value and tangential derivative on a
          // fixed edge), as P1's Dirichlet constraints fix its vertices.
          fixed_vertex[d].assign(tria.n_vertices(), 0);
          for (unsigned int v = 0; v < vertices.dofs.size(); ++v)
            for (const unsigned int i : vertices.dofs[v])
              if (grid.dirichlet_constraints(d).is_constrained(global[i]))
                fixed_vertex[d][v] = 1;
        }
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::assemble(const GridSystem<dim>   &grid,
                                       const unsigned int       d,
                                       const std::vector<char> &constrained)
    {
      copy_fine_matrix(grid, d);
      mask_transfer(d, constrained);
      if (parameters.coarse == "particles")
        assemble_particle_coarse(grid, d);
      else
        assemble_galerkin_coarse(d);
      set_up_cycle(d);
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::copy_fine_matrix(const GridSystem<dim> &grid,
                                               const unsigned int     d)
    {
      const Epetra_CrsMatrix &A = grid.mass_matrix(d).trilinos_matrix();
      const unsigned int      n = grid.relevant_global_indices().size();
      const unsigned int      sparsity_generation = grid.sparsity_generation();
      int                    *offsets, *columns;
      double                 *entries;
      const_cast<Epetra_CrsMatrix &>(A).ExtractCrsDataPointers(offsets,
                                                               columns,
                                                               entries);
      if (generation != sparsity_generation)
        {
          // The pattern of the copy and where each of its entries lies in
          // the Epetra value array; all components share the sparsity.
          DynamicSparsityPattern dsp(n, n);
          for (unsigned int r = 0; r < n; ++r)
            for (int p = offsets[r]; p < offsets[r + 1]; ++p)
              dsp.add(A.RowMap().GID(r), A.ColMap().GID(columns[p]));
          fine_pattern.copy_from(dsp);
          fine_slots.assign(fine_pattern.n_nonzero_elements(), -1);
          for (unsigned int r = 0; r < n; ++r)
            for (int p = offsets[r]; p < offsets[r + 1]; ++p)
              fine_slots[fine_pattern(A.RowMap().GID(r),
                                      A.ColMap().GID(columns[p]))] = p;
          for (unsigned int c = 0; c < dim; ++c)
            {
              fine[c].reinit(fine_pattern);
              rebuild[c] = true;
            }
          generation = sparsity_generation;
        }
      // The entries of a SparseMatrix, row by row, are its value array in
      // order.
      unsigned int k = 0;
      for (auto e = fine[d].begin(); e != fine[d].end(); ++e, ++k)
        e->value() = fine_slots[k] < 0 ? 0. : entries[fine_slots[k]];
      // A fixed DoF whose support holds no particle has an empty row and
      // column: GridSystem puts the cell's diagonal (or the cell's average
      // one), zero in an empty cell, on a fixed DoF's diagonal, and a unit
      // diagonal on free DoFs only. Jacobi (a zero inverse) and block
      // Jacobi (masked rows) keep such a DoF at its zero guess, but both
      // smoothers divide by the diagonal: one such row made the first
      // V-cycle, hence CG's first residual, NaN. With a unit diagonal the
      // DoF stays at zero (right-hand side and guess are zero there, its
      // transfer row is zero), so CG's iterates on the other DoFs are
      // unchanged. The matrix is symmetric positive semidefinite: a zero
      // diagonal means a zero row.
      for (unsigned int i = 0; i < n; ++i)
        if (fine[d].diag_element(i) == 0)
          fine[d].diag_element(i) = 1;
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::mask_transfer(
      const unsigned int       d,
      const std::vector<char> &constrained)
    {
      // Constrained DoFs take no correction (their rows and columns hold
      // only the diagonal, their right-hand side is zero); with the
      // particle coarse matrix, fixed P1 vertices give none either.
      const bool particles = parameters.coarse == "particles";
      transfer[d].copy_from(prolongation_matrix);
      for (unsigned int i = 0; i < transfer[d].m(); ++i)
        for (auto e = transfer[d].begin(i); e != transfer[d].end(i); ++e)
          if (constrained[i] || (particles && fixed_vertex[d][e->column()]))
            e->value() = 0;
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::assemble_particle_coarse(
      const GridSystem<dim> &grid,
      const unsigned int     d)
    {
      // sum over cells of P_K^T M_K P_K: M_K holds sum_p m_p N_k N_l and
      // the hat of vertex a is sum_k P_K(k, a) N_k on cell K, so this is
      // sum_p m_p phi_a phi_b, the P1 particle mass, with no particle loop
      // and no sparse product.
      if (rebuild[d])
        coarse[d].reinit(p1_pattern);
      else
        coarse[d] = 0;
      const unsigned int                m    = grid.dofs_per_cell;
      const std::vector<double>        &mass = grid.cell_arrays().mass;
      std::array<unsigned int, dim + 1> v;
      double                            MP[64 * (dim + 1)];
      AssertThrow(m <= 64, ExcInternalError());
      for (const unsigned int c : grid.owned_cells())
        {
          for (unsigned int a = 0; a <= dim; ++a)
            v[a] = cell_vertices[c * (dim + 1) + a];
          const double *M = &mass[c * m * m];
          const double *W = &cell_weights[c * m * (dim + 1)];
          for (unsigned int k = 0; k < m; ++k)
            for (unsigned int a = 0; a <= dim; ++a)
              {
                double sum = 0;
                for (unsigned int l = 0; l < m; ++l)
                  sum += M[k * m + l] * W[l * (dim + 1) + a];
                MP[k * (dim + 1) + a] = sum;
              }
          for (unsigned int a = 0; a <= dim; ++a)
            for (unsigned int b = 0; b <= dim; ++b)
              {
                if (fixed_vertex[d][v[a]] || fixed_vertex[d][v[b]])
                  continue;
                double sum = 0;
                for (unsigned int k = 0; k < m; ++k)
                  sum += W[k * (dim + 1) + a] * MP[k * (dim + 1) + b];
                coarse[d].add(v[a], v[b], sum);
              }
        }
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::assemble_galerkin_coarse(const unsigned int d)
    {
      // The products' patterns are computed once per sparsity generation
      // (mmult and Tmmult rebuild the pattern a matrix points to).
      if (rebuild[d])
        {
          product[d].reinit(product_pattern[d]);
          coarse[d].reinit(coarse_pattern[d]);
        }
      else
        {
          product[d] = 0;
          coarse[d]  = 0;
        }
      fine[d].mmult(product[d], transfer[d], Vector<double>(), rebuild[d]);
      transfer[d].Tmmult(coarse[d], product[d], Vector<double>(), rebuild[d]);
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::set_up_cycle(const unsigned int d)
    {
      // A vertex all of whose DoFs are fixed (with the particle coarse
      // matrix also one whose hat holds no particle) has an empty row.
      for (unsigned int v = 0; v < coarse[d].m(); ++v)
        if (coarse[d].diag_element(v) == 0)
          coarse[d].diag_element(v) = 1;
      // A particle layout that leaves the P1 level rank deficient (two
      // particles in a bar of 24 DoFs) makes UMFPACK fail. That is the
      // layout's fault, not a bug: no cycle this step, and solve()
      // reports the solver's failure.
      try
        {
          coarse_direct[d].initialize(coarse[d]);
        }
      catch (const SparseDirectUMFPACK::ExcUMFPACKError &)
        {
          cycle[d].reset();
          return;
        }
      // The cycle keeps pointers to the levels, whose patterns change
      // only with a rebuild; it is kept between steps otherwise.
      if (rebuild[d] || !cycle[d])
        {
          cycle[d] = std::make_unique<PMultigrid>(
            parameters.cycle,
            std::vector<const SparseMatrix<double> *>{&coarse[d], &fine[d]},
            std::vector<const SparseMatrix<double> *>{nullptr, &transfer[d]},
            std::vector<const SparseMatrix<double> *>{nullptr, nullptr});
          cycle[d]->set_coarse_solver(
            [this, d](Vector<double> &x, const Vector<double> &b) {
              coarse_direct[d].vmult(x, b);
            });
          rebuild[d] = false;
        }
    }

    template <int dim>
    void
    PMultigridHierarchy<dim>::solve(const unsigned int d,
                                    SolverControl     &control,
                                    const TrilinosWrappers::MPI::Vector &rhs,
                                    TrilinosWrappers::MPI::Vector       &x,
                                    double &condition_number)
    {
      if (!cycle[d])
        throw SolverFailure(
          "the P1 coarse matrix of the p-multigrid preconditioner is "
          "singular: the particles do not determine the P1 level (Mass "
          "matrix/Preconditioner = pmg; block jacobi or more particles "
          "per block)");
      // CG on the serial copy that the cycle smooths (the same matrix),
      // one V-cycle from zero per iteration.
      rhs_copy.reinit(rhs.locally_owned_size(), true);
      solution_copy.reinit(rhs.locally_owned_size(), true);
      std::copy(rhs.begin(), rhs.end(), rhs_copy.begin());
      std::copy(x.begin(), x.end(), solution_copy.begin());
      SolverCG<Vector<double>> cg(control);
      cg.connect_condition_number_slot([&condition_number](const double c) {
        condition_number = std::max(condition_number, c);
      });
      cg.solve(fine[d],
               solution_copy,
               rhs_copy,
               VCyclePreconditioner{*cycle[d]});
      std::copy(solution_copy.begin(), solution_copy.end(), x.begin());
    }

    template class PMultigridHierarchy<1>;
    template class PMultigridHierarchy<2>;
  } // namespace Solver
} // namespace psmpm
