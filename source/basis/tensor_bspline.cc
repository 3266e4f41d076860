// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/basis/bspline.h>
#include <psmpm/basis/tensor_bspline.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Basis
  {

    TensorBSpline::TensorBSpline()
      : p(2)
      , fe(std::make_unique<FE_Q<2>>(2))
    {
    }

    std::string
    TensorBSpline::name() const
    {
      return "bspline";
    }

    void
    TensorBSpline::set_degree(const unsigned int degree)
    {
      // The univariate spaces check the range, naming Basis/Degree.
      for (auto &u : univariate)
        u.set_degree(degree);
      if (degree != p)
        {
          p  = degree;
          fe = std::make_unique<FE_Q<2>>(p);
          grid.clear();
        }
    }

    const FiniteElement<2> &
    TensorBSpline::dof_layout() const
    {
      return *fe;
    }

    void
    TensorBSpline::reinit(const DoFHandler<2> &dof_handler)
    {
      const auto &tria = dof_handler.get_triangulation();
      AssertThrow(tria.all_reference_cells_are_hyper_cube(),
                  ExcMessage("Basis/Type = bspline in 2D needs a mesh of "
                             "rectangles: Mesh/Type = cartesian."));
      AssertThrow(dof_handler.has_active_dofs() &&
                    dof_handler.get_fe().n_dofs_per_cell() == (p + 1) * (p + 1),
                  ExcMessage("TensorBSpline::reinit: the DoFHandler must use "
                             "the space's dof_layout()."));

      // Lattice offsets of the local DoFs: the rank of each coordinate of
      // the unit support point among the p + 1 distinct ones.
      const auto         &support = fe->get_unit_support_points();
      std::vector<double> levels;
      for (const auto &q : support)
        levels.push_back(q[0]);
      std::sort(levels.begin(), levels.end());
      levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
      AssertThrow(levels.size() == p + 1, ExcInternalError());
      local_lattice.resize(support.size());
      local_univariate.resize(support.size());
      for (unsigned int k = 0; k < support.size(); ++k)
        for (unsigned int d = 0; d < 2; ++d)
          {
            const unsigned int j =
              std::lower_bound(levels.begin(), levels.end(), support[k][d]) -
              levels.begin();
            local_lattice[k][d] = j;
            // FE_Q<1>(p): vertex 0, vertex 1, then the interior.
            local_univariate[k][d] = j == 0 ? 0 : (j == p ? 1 : j + 1);
          }

      grid.reinit(tria, "Basis/Type = bspline in 2D");
      for (unsigned int d = 0; d < 2; ++d)
        ties[d] = univariate_ties(d);
    }

    std::vector<TensorBSpline::Tie>
    TensorBSpline::univariate_ties(const unsigned int d)
    {
      // The univariate space on the grid lines of direction d, cells
      // numbered left to right with vertex 0 on the left.
      const unsigned int    n = grid.lines(d).size() - 1;
      std::vector<Point<1>> vertices;
      for (const double x : grid.lines(d))
        vertices.emplace_back(x);
      std::vector<dealii::CellData<1>> cells(n);
      for (unsigned int k = 0; k < n; ++k)
        cells[k].vertices = {k, k + 1};
      Triangulation<1> line;
      line.create_triangulation(vertices, cells, SubCellData());
      DoFHandler<1> dof_handler(line);
      dof_handler.distribute_dofs(univariate[d].dof_layout());
      // The univariate space keeps its cell geometry for evaluate(); its
      // cell k is the k-th between grid lines.
      univariate[d].reinit(dof_handler);
      AffineConstraints<double> constraints;
      univariate[d].make_space_constraints(dof_handler, constraints);

      // Lattice line of every univariate DoF: Bernstein j of cell k is
      // k p + j; FE_Q<1> numbers vertex 0, vertex 1, then the interior.
      std::vector<unsigned int>            lattice_of(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(p + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          const unsigned int k = cell->vertex_index(0);
          AssertThrow(cell->active_cell_index() == k, ExcInternalError());
          for (unsigned int j = 0; j <= p; ++j)
            lattice_of[dofs[j == 0 ? 0 : (j == p ? 1 : j + 1)]] = k * p + j;
        }
      std::vector<Tie> result(n * p + 1);
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        if (const auto *entries = constraints.get_constraint_entries(i))
          for (const auto &[target, w] : *entries)
            {
              // BSpline ties every DoF to free DoFs directly (no chains).
              Assert(!constraints.is_constrained(target), ExcInternalError());
              result[lattice_of[i]].emplace_back(lattice_of[target], w);
            }
      return result;
    }

    std::array<unsigned int, 2>
    TensorBSpline::lattice(const unsigned int c, const unsigned int k) const
    {
      const auto &ij = grid.position(c);
      return {
        {ij[0] * p + local_lattice[k][0], ij[1] * p + local_lattice[k][1]}};
    }

    Point<2>
    TensorBSpline::control_point(const std::array<unsigned int, 2> &IJ) const
    {
      Point<2> x;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const auto        &lines = grid.lines(d);
          const unsigned int i =
            std::min<unsigned int>(IJ[d] / p, lines.size() - 2);
          const unsigned int a = IJ[d] - i * p;
          x[d]                 = lines[i] + (lines[i + 1] - lines[i]) * a / p;
        }
      return x;
    }

    void
    TensorBSpline::evaluate(const unsigned int cell,
                            const Point<2>    &x,
                            double            *values,
                            Tensor<1, 2>      *gradients) const
    {
      AssertIndexRange(cell, grid.n_cells());
      // The univariate Bernstein polynomials (and x- or y-derivatives) of
      // the cell's column and row, in FE_Q<1>(p) order.
      double       b[2][BSpline::max_degree + 1];
      Tensor<1, 1> db[2][BSpline::max_degree + 1];
      for (unsigned int d = 0; d < 2; ++d)
        univariate[d].BSpline::evaluate(grid.position(cell)[d],
                                        Point<1>(x[d]),
                                        b[d],
                                        gradients != nullptr ? db[d] : nullptr);
      const unsigned int n = local_univariate.size();
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto [i, j] = local_univariate[k];
          values[k]         = b[0][i] * b[1][j];
          if (gradients != nullptr)
            {
              gradients[k][0] = db[0][i][0] * b[1][j];
              gradients[k][1] = b[0][i] * db[1][j][0];
            }
        }
    }

    void
    TensorBSpline::evaluate(const unsigned int  n,
                            const unsigned int *cells,
                            const Point<2>     *points,
                            double             *values,
                            Tensor<1, 2>       *gradients) const
    {
      // Qualified call: no virtual dispatch per point.
      const unsigned int k = local_lattice.size();
      for (unsigned int i = 0; i < n; ++i)
        TensorBSpline::evaluate(cells[i],
                                points[i],
                                values + k * i,
                                gradients != nullptr ? gradients + k * i :
                                                       nullptr);
    }

    void
    TensorBSpline::make_space_constraints(
      const DoFHandler<2>       &dof_handler,
      AffineConstraints<double> &constraints) const
    {
      if (p == 1)
        return;
      AssertThrow(grid.n_cells() ==
                    dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("TensorBSpline::make_space_constraints: call "
                             "reinit() with this mesh first."));
      const unsigned int columns = (grid.lines(0).size() - 1) * p + 1;
      const unsigned int rows    = (grid.lines(1).size() - 1) * p + 1;
      // The shared triangulation keeps every cell: every lattice point's
      // DoF is at hand.
      std::vector<types::global_dof_index> dof_at(columns * rows);
      std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < dofs.size(); ++k)
            {
              const auto IJ = lattice(cell->active_cell_index(), k);
              dof_at[IJ[1] * columns + IJ[0]] = dofs[k];
            }
        }
      for (unsigned int J = 0; J < rows; ++J)
        for (unsigned int I = 0; I < columns; ++I)
          {
            if (ties[0][I].empty() && ties[1][J].empty())
              continue;
            const auto dof = dof_at[J * columns + I];
            if (!constraints.can_store_line(dof) ||
                constraints.is_constrained(dof))
              continue;
            const Tie x = ties[0][I].empty() ? Tie{{I, 1.}} : ties[0][I];
            const Tie y = ties[1][J].empty() ? Tie{{J, 1.}} : ties[1][J];
            constraints.add_line(dof);
            for (const auto &[L, wy] : y)
              for (const auto &[K, wx] : x)
                if (wx * wy != 0)
                  constraints.add_entry(dof, dof_at[L * columns + K], wx * wy);
          }
    }

    void
    TensorBSpline::make_dirichlet_constraints(
      const DoFHandler<2>                &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<2>                  &g,
      AffineConstraints<double>          &constraints) const
    {
      std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          const unsigned int c = cell->active_cell_index();
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->at_boundary(f) ||
                  ids.count(cell->face(f)->boundary_id()) == 0)
                continue;
              // Faces 0, 1: x = x_lo, x_hi; 2, 3: y = y_lo, y_hi.
              const unsigned int d = f / 2, end = (f % 2) * p;
              for (unsigned int k = 0; k < dofs.size(); ++k)
                if (local_lattice[k][d] == end &&
                    constraints.can_store_line(dofs[k]) &&
                    !constraints.is_constrained(dofs[k]))
                  {
                    constraints.add_line(dofs[k]);
                    constraints.set_inhomogeneity(dofs[k],
                                                  g.value(control_point(
                                                    lattice(c, k))));
                  }
            }
        }
    }

    std::vector<Point<2>>
    TensorBSpline::control_points(const DoFHandler<2> &dof_handler) const
    {
      std::vector<Point<2>>                points(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < dofs.size(); ++k)
            points[dofs[k]] =
              control_point(lattice(cell->active_cell_index(), k));
        }
      return points;
    }

    FullMatrix<double>
    TensorBSpline::extrapolation_weights(const unsigned int from,
                                         const unsigned int to) const
    {
      return univariate[0].extrapolation_weights(from, to); // refused
    }

    Quadrature<2>
    TensorBSpline::cell_quadrature(const DoFHandler<2> &dof_handler,
                                   const unsigned int   cell) const
    {
      AssertThrow(cell < grid.n_cells() &&
                    grid.n_cells() ==
                      dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("TensorBSpline::cell_quadrature: call reinit() "
                             "with this mesh first."));
      // The rectangle between the cell's grid lines.
      Point<2>     lo;
      Tensor<1, 2> size;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const unsigned int i = grid.position(cell)[d];
          lo[d]                = grid.lines(d)[i];
          size[d]              = grid.lines(d)[i + 1] - lo[d];
        }
      const QGauss<2>       reference(p + 1);
      std::vector<Point<2>> points(reference.size());
      std::vector<double>   weights(reference.size());
      for (unsigned int q = 0; q < reference.size(); ++q)
        {
          for (unsigned int d = 0; d < 2; ++d)
            points[q][d] = lo[d] + reference.point(q)[d] * size[d];
          weights[q] = size[0] * size[1] * reference.weight(q);
        }
      return Quadrature<2>(points, weights);
    }

    double
    TensorBSpline::stability_factor(const bool lumped) const
    {
      // The tensor-product stiffness and mass matrices are Kronecker sums
      // and products of the univariate ones, K = K_x (x) M_y + M_x (x) K_y
      // and M = M_x (x) M_y for a scalar wave, so the largest eigenvalue of
      // M^-1 K on square cells is twice the univariate one: the univariate
      // factor (BSpline::stability_factor(), relative to the cell length)
      // over sqrt(2), relative to the shorter side.
      return univariate[0].stability_factor(lumped) / std::sqrt(2.);
    }

    std::string
    TensorBSpline::default_mass_matrix(const bool) const
    {
      // p >= 3: the ghost penalty, which completes the free body and the
      // column collapse where consistent mass fails on nearly empty cells
      // (doc/chapter.md "BSMPM in 2D"), and is the consistent matrix on
      // filled cells. p <= 2: lumped, which also survives Courant numbers
      // at which consistent and ghost penalty mass go unstable on a free
      // boundary, at a fraction of the ghost penalty's CPU time.
      return p <= 2 ? "lumped" : "ghost penalty";
    }

    std::string
    TensorBSpline::closed_mass_matrix() const
    {
      return "consistent";
    }

    std::vector<std::string>
    TensorBSpline::verified_mass_matrices() const
    {
      // As in 1D: for p >= 3 the free DoFs' functions are not the
      // B-splines (products of the univariate free functions) and their
      // lumped rows are not a sound mass.
      // The ghost penalty projects onto P_p on pairs of rectangles, which
      // Q_p reproduces; its pair matrices live on the Bezier layout and
      // reach the B-splines through the ties, like the cell matrices.
      return univariate[0].verified_mass_matrices();
    }

    std::vector<std::string>
    TensorBSpline::verified_transfers() const
    {
      return univariate[0].verified_transfers();
    }

    namespace
    {
      std::unique_ptr<Space<2>>
      make_tensor_bspline()
      {
        return std::make_unique<TensorBSpline>();
      }

      const Registration<SpaceRegistry<2>> register_tensor_bspline(
        {"bspline",
         "tensor-product B-splines of Basis/Degree p (1 to 5) with maximal "
         "continuity on the open knot vectors of a Cartesian mesh "
         "(Mesh/Type = cartesian; BSMPM), by Bezier extraction on the "
         "FE_Q(p) layout; lumped mass for p <= 2 only",
         &make_tensor_bspline,
         nullptr});
    } // namespace
  }   // namespace Basis
} // namespace psmpm
