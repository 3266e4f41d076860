// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <psmpm/basis/bspline.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace psmpm
{
  namespace Basis
  {
    namespace
    {
      /// Local layout DoF of the Bernstein polynomial j = 0, ..., p of the
      /// cell's own parameter t (0 at vertex 0): FE_Q<1>(p) numbers the
      /// two vertices first, then the interior from vertex 0 to vertex 1.
      unsigned int
      local_dof(const unsigned int j, const unsigned int p)
      {
        return j == 0 ? 0 : (j == p ? 1 : j + 1);
      }

      /// A B-spline coefficient as a combination of free layout DoFs.
      using Combination = std::map<types::global_dof_index, double>;

      void
      add(Combination &to, const double factor, const Combination &from)
      {
        if (factor != 0)
          for (const auto &[j, w] : from)
            to[j] += factor * w;
      }



      /// The C^1 ties of degree 2: at every interior vertex, equal
      /// one-sided derivatives of the two Bezier pieces.
      void
      make_quadratic_ties(const DoFHandler<1>       &dof_handler,
                          AffineConstraints<double> &constraints)
      {
        // The shared triangulation keeps every cell, so both neighbours
        // of a vertex and their cell DoFs are always at hand.
        std::vector<types::global_dof_index> dofs(3), neighbor_dofs(3);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            for (const unsigned int f : cell->face_indices())
              {
                if (cell->at_boundary(f))
                  continue;
                // In 1D face f is vertex f; local DoF f is its vertex
                // DoF.
                const auto vertex_dof = dofs[f];
                if (!constraints.can_store_line(vertex_dof) ||
                    constraints.is_constrained(vertex_dof))
                  continue;
                const auto neighbor = cell->neighbor(f);
                neighbor->get_dof_indices(neighbor_dofs);
                const double h          = cell->measure(),
                             h_neighbor = neighbor->measure();
                // (c_v - c_L) / h_L = (c_R - c_v) / h_R.
                constraints.add_line(vertex_dof);
                constraints.add_entry(vertex_dof,
                                      dofs[2],
                                      h_neighbor / (h + h_neighbor));
                constraints.add_entry(vertex_dof,
                                      neighbor_dofs[2],
                                      h / (h + h_neighbor));
              }
          }
      }



      /**
       * The n + p B-spline coefficients d of degree p >= 3 on a mesh of n
       * cells as combinations of the free layout DoFs, and the ties of the
       * other DoFs (see BSpline::make_space_constraints()).
       */
      struct HigherDegreeTies
      {
        HigherDegreeTies(const unsigned int                     p,
                         const std::vector<FullMatrix<double>> &extraction)
          : p(p)
          , n(extraction.size())
          , extraction(extraction)
          , cell_at(n)
          , dofs(n, std::vector<types::global_dof_index>(p + 1))
          , reversed(n)
          , d(n + p)
        {
        }

        /// Local DoF of Bernstein coefficient j of cell @p c counted from
        /// the left.
        unsigned int
        row(const unsigned int c, const unsigned int j) const
        {
          return local_dof(reversed[c] ? p - j : j, p);
        }

        /// d from the free DoFs: the end vertex DoFs, then the interior
        /// blocks of cells 0, p - 1, 2 (p - 1), ..., then the last block.
        void
        solve()
        {
          const auto first = cell_at[0], last = cell_at[n - 1];
          d[0][dofs[first][row(first, 0)]]       = 1;
          d[n + p - 1][dofs[last][row(last, p)]] = 1;
          free_dofs.insert(dofs[first][row(first, 0)]);
          free_dofs.insert(dofs[last][row(last, p)]);

          // Interior blocks: d_{k+1..k+p-1} = A^{-1} b_interior.
          unsigned int covered = 0; // B-splines 1..covered are known
          for (unsigned int k = 0; k < n; k += p - 1)
            {
              const unsigned int c = cell_at[k];
              FullMatrix<double> A(p - 1, p - 1);
              for (unsigned int j = 1; j < p; ++j)
                for (unsigned int i = 1; i < p; ++i)
                  A(j - 1, i - 1) = extraction[c](row(c, j), i);
              A.gauss_jordan();
              for (unsigned int i = 1; i < p; ++i)
                for (unsigned int j = 1; j < p; ++j)
                  d[k + i][dofs[c][row(c, j)]] = A(i - 1, j - 1);
              for (unsigned int j = 1; j < p; ++j)
                free_dofs.insert(dofs[c][row(c, j)]);
              covered = k + p - 1;
            }
          const unsigned int r = n + p - 2 - covered;
          if (r > 0)
            solve_last_block(r);
        }

        /// The last @p r unknown B-splines n + p - 1 - r .. n + p - 2
        /// (offsets p - r .. p - 1 on the last cell, k = n - 1); free: the
        /// Bernstein coefficients j = p - r .. p - 1.
        void
        solve_last_block(const unsigned int r)
        {
          const unsigned int c = cell_at[n - 1], k = n - 1;
          FullMatrix<double> A(r, r);
          for (unsigned int a = 0; a < r; ++a)
            for (unsigned int i = 0; i < r; ++i)
              A(a, i) = extraction[c](row(c, p - r + a), p - r + i);
          A.gauss_jordan();
          // Right-hand sides: b_j - sum over the known B-splines.
          std::vector<Combination> rhs(r);
          for (unsigned int a = 0; a < r; ++a)
            {
              const auto dof = dofs[c][row(c, p - r + a)];
              rhs[a][dof]    = 1;
              free_dofs.insert(dof);
              for (unsigned int i = 0; i <= p; ++i)
                if (i < p - r || i == p)
                  add(rhs[a], -extraction[c](row(c, p - r + a), i), d[k + i]);
            }
          for (unsigned int i = 0; i < r; ++i)
            for (unsigned int a = 0; a < r; ++a)
              add(d[k + p - r + i], A(i, a), rhs[a]);
        }

        /// Ties: every other DoF is E d on (one of) its cell(s).
        void
        add_ties(AffineConstraints<double> &constraints) const
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int c = cell_at[k];
              for (unsigned int j = 1; j <= p; ++j)
                {
                  // Vertex j = p is tied from the cell on its left; the
                  // right end vertex is free.
                  const auto dof = dofs[c][row(c, j)];
                  if (free_dofs.count(dof) != 0 ||
                      !constraints.can_store_line(dof) ||
                      constraints.is_constrained(dof))
                    continue;
                  Combination tie;
                  for (unsigned int i = 0; i <= p; ++i)
                    add(tie, extraction[c](row(c, j), i), d[k + i]);
                  constraints.add_line(dof);
                  for (const auto &[target, w] : tie)
                    if (w != 0)
                      constraints.add_entry(dof, target, w);
                }
            }
        }

        const unsigned int                     p;
        const unsigned int                     n;
        const std::vector<FullMatrix<double>> &extraction;
        /// The cell at each position from the left.
        std::vector<unsigned int>                         cell_at;
        std::vector<std::vector<types::global_dof_index>> dofs;
        std::vector<bool>                                 reversed;
        std::vector<Combination>                          d;
        std::set<types::global_dof_index>                 free_dofs;
      };
    } // namespace

    BSpline::BSpline()
      : p(2)
      , fe(std::make_unique<FE_Q<1>>(2))
    {
    }

    std::string
    BSpline::name() const
    {
      return "bspline";
    }

    void
    BSpline::set_degree(const unsigned int degree)
    {
      AssertThrow(degree >= 1 && degree <= max_degree,
                  ExcMessage("Basis/Degree = " + std::to_string(degree) +
                             ": Basis/Type = bspline implements degrees 1 "
                             "to " +
                             std::to_string(max_degree) +
                             " (those whose stable time step was "
                             "measured)."));
      if (degree != p)
        {
          p  = degree;
          fe = std::make_unique<FE_Q<1>>(p);
          cell_data.clear();
          position.clear();
          extraction.clear();
        }
    }

    const FiniteElement<1> &
    BSpline::dof_layout() const
    {
      return *fe;
    }

    void
    BSpline::reinit(const DoFHandler<1> &dof_handler)
    {
      AssertThrow(dof_handler.get_fe().n_dofs_per_vertex() == 1 &&
                    dof_handler.get_fe().n_dofs_per_cell() == p + 1,
                  ExcMessage("BSpline::reinit: the DoFHandler must use the "
                             "space's dof_layout()."));
      const auto        &tria = dof_handler.get_triangulation();
      const unsigned int n    = tria.n_active_cells();
      cell_data.resize(n);
      // Cells from left to right (ends taken from the vertices themselves,
      // so that shared vertices compare equal), for the knot vector.
      struct Interval
      {
        double       left, right;
        unsigned int cell;
      };
      std::vector<Interval> intervals;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const double a = cell->vertex(0)[0], b = cell->vertex(1)[0];
          AssertThrow(b != a,
                      ExcMessage("BSpline::reinit: cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 " has zero length."));
          cell_data[cell->active_cell_index()] = {a, 1 / (b - a)};
          intervals.push_back(
            {std::min(a, b), std::max(a, b), cell->active_cell_index()});
        }
      std::sort(intervals.begin(),
                intervals.end(),
                [](const Interval &u, const Interval &w) {
                  return u.left < w.left;
                });

      // Knots x_0 < ... < x_n at the vertices; the B-splines' knot vector
      // is t_k = x_{min(max(k - p, 0), n)}, k = 0, ..., n + 2p.
      std::vector<double> x(n + 1);
      position.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          AssertThrow(k == 0 || intervals[k].left == intervals[k - 1].right,
                      ExcMessage("Basis/Type = bspline: the 1D mesh must "
                                 "be one interval of consecutive cells."));
          x[k]                        = intervals[k].left;
          x[k + 1]                    = intervals[k].right;
          position[intervals[k].cell] = k;
        }
      const auto knot = [&](const int k) {
        return x[std::min(std::max(k - int(p), 0), int(n))];
      };

      // Bezier extraction of cell k (interval [x_k, x_{k+1}] = [t_mu,
      // t_{mu+1}], mu = k + p, B-splines k, ..., k + p): the Bernstein
      // coefficient j of B_i there is its blossom at (x_k^{p-j},
      // x_{k+1}^j). The blossom of the vector of B-splines of span mu is
      // R_1(u_1) ... R_p(u_p), the Cox-de Boor recursion with argument u_r
      // at level r (Lyche and Morken, Spline Methods, the matrix form:
      // R_r(u) R_{r+1}(w) is symmetric in u, w). With every u_r at an end
      // of the span all weights lie in [0, 1]: no cancellation, unlike
      // blossoms at knots outside the span.
      extraction.assign(n, FullMatrix<double>(p + 1, p + 1));
      std::vector<double> level(p + 1), next(p + 1);
      for (unsigned int k = 0; k < n; ++k)
        {
          const int          mu       = k + p;
          const unsigned int cell     = intervals[k].cell;
          const bool         reversed = cell_data[cell].inverse_length < 0;
          for (unsigned int j = 0; j <= p; ++j)
            {
              // level[m] is function mu - r + m after level r.
              level[0] = 1;
              for (unsigned int r = 1; r <= p; ++r)
                {
                  const double u = r <= p - j ? x[k] : x[k + 1];
                  for (unsigned int m = 0; m <= r; ++m)
                    {
                      const int i = mu - int(r) + int(m);
                      double    v = 0;
                      if (m >= 1) // B_{i, r-1} is level[m - 1]
                        v += (u - knot(i)) / (knot(i + r) - knot(i)) *
                             level[m - 1];
                      if (m < r) // B_{i+1, r-1} is level[m]
                        v += (knot(i + r + 1) - u) /
                             (knot(i + r + 1) - knot(i + 1)) * level[m];
                      next[m] = v;
                    }
                  std::copy(next.begin(), next.begin() + r + 1, level.begin());
                }
              const unsigned int row = local_dof(reversed ? p - j : j, p);
              for (unsigned int i = 0; i <= p; ++i)
                extraction[cell](row, i) = level[i];
            }
        }
    }

    const FullMatrix<double> &
    BSpline::bezier_extraction(const unsigned int cell) const
    {
      AssertIndexRange(cell, extraction.size());
      return extraction[cell];
    }

    unsigned int
    BSpline::first_bspline(const unsigned int cell) const
    {
      AssertIndexRange(cell, position.size());
      return position[cell];
    }

    void
    BSpline::evaluate(const unsigned int cell,
                      const Point<1>    &x,
                      double            *values,
                      Tensor<1, 1>      *gradients) const
    {
      AssertIndexRange(cell, cell_data.size());
      const CellData &d = cell_data[cell];
      const double    t = (x[0] - d.origin) * d.inverse_length;
      const double    s = 1 - t;
      if (p == 2)
        {
          // The quadratic case as it was written first (results of p = 2
          // are bit for bit those of the quadratic-only space).
          values[0] = s * s;
          values[1] = t * t;
          values[2] = 2 * t * s;
          if (gradients != nullptr)
            {
              gradients[0][0] = -2 * s * d.inverse_length;
              gradients[1][0] = 2 * t * d.inverse_length;
              gradients[2][0] = 2 * (s - t) * d.inverse_length;
            }
          return;
        }
      // Bernstein polynomials of degree p and p - 1 by de Casteljau's
      // triangle (non-negative terms only): b[j] after level r is
      // B^r_j(t).
      double b[max_degree + 1], lower[max_degree + 1] = {};
      b[0] = 1;
      for (unsigned int r = 1; r <= p; ++r)
        {
          if (r == p)
            std::copy(b, b + p, lower);
          b[r] = t * b[r - 1];
          for (unsigned int j = r - 1; j >= 1; --j)
            b[j] = s * b[j] + t * b[j - 1];
          b[0] = s * b[0];
        }
      for (unsigned int j = 0; j <= p; ++j)
        values[local_dof(j, p)] = b[j];
      if (gradients != nullptr)
        // d/dx B^p_j = p (B^{p-1}_{j-1} - B^{p-1}_j) / (x_1 - x_0).
        for (unsigned int j = 0; j <= p; ++j)
          gradients[local_dof(j, p)][0] =
            p * d.inverse_length *
            ((j >= 1 ? lower[j - 1] : 0.) - (j < p ? lower[j] : 0.));
    }

    void
    BSpline::evaluate(const unsigned int  n,
                      const unsigned int *cells,
                      const Point<1>     *points,
                      double             *values,
                      Tensor<1, 1>       *gradients) const
    {
      // Qualified call: no virtual dispatch per point.
      const unsigned int k = p + 1;
      for (unsigned int i = 0; i < n; ++i)
        BSpline::evaluate(cells[i],
                          points[i],
                          values + k * i,
                          gradients != nullptr ? gradients + k * i : nullptr);
    }

    void
    BSpline::make_space_constraints(
      const DoFHandler<1>       &dof_handler,
      AffineConstraints<double> &constraints) const
    {
      if (p == 1)
        return;
      if (p == 2)
        {
          make_quadratic_ties(dof_handler, constraints);
          return;
        }

      // p >= 3. Per cell, b = E d (Bezier coefficients b of the cell from
      // its p + 1 B-spline coefficients d, E = bezier_extraction()). The
      // first and the last B-spline vanish on the cell to order p at the
      // far and the near vertex: the p - 1 interior Bezier coefficients
      // involve the p - 1 middle B-splines only, through an invertible
      // block (the only polynomial of the cell with zero interior Bezier
      // coefficients and zero first and last B-spline coefficient is 0).
      // So the interior DoFs of cells 0, p - 1, 2 (p - 1), ... (from the
      // left) determine B-splines 1 to n + p - 2 block by block, the last
      // r = (n - 1) mod (p - 1) through r interior DoFs of the last cell
      // (those next to its right vertex, where B-spline n + p - 1 - m
      // vanishes to order m: a triangular block); the end vertex DoFs are
      // the end B-splines' coefficients. Every other DoF is E times these,
      // which ties it to free DoFs of cells at most p - 1 cells away (the
      // blocks that hold its cell's p + 1 B-splines).
      const unsigned int n = dof_handler.get_triangulation().n_active_cells();
      AssertThrow(extraction.size() == n,
                  ExcMessage("BSpline::make_space_constraints: call reinit() "
                             "with this mesh first."));
      HigherDegreeTies ties(p, extraction);
      for (unsigned int c = 0; c < n; ++c)
        ties.cell_at[position[c]] = c;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          cell->get_dof_indices(ties.dofs[c]);
          ties.reversed[c] = cell_data[c].inverse_length < 0;
        }
      ties.solve();
      ties.add_ties(constraints);
    }

    void
    BSpline::make_dirichlet_constraints(
      const DoFHandler<1>                &dof_handler,
      const std::set<types::boundary_id> &ids,
      const Function<1>                  &g,
      AffineConstraints<double>          &constraints) const
    {
      std::vector<types::global_dof_index> dofs(p + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          cell->get_dof_indices(dofs);
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f) &&
                ids.count(cell->face(f)->boundary_id()) != 0)
              {
                const auto dof = dofs[f];
                if (constraints.can_store_line(dof) &&
                    !constraints.is_constrained(dof))
                  {
                    constraints.add_line(dof);
                    constraints.set_inhomogeneity(dof,
                                                  g.value(cell->vertex(f)));
                  }
              }
        }
    }

    std::vector<Point<1>>
    BSpline::control_points(const DoFHandler<1> &dof_handler) const
    {
      std::vector<Point<1>>                points(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(p + 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          points[dofs[0]] = cell->vertex(0);
          points[dofs[1]] = cell->vertex(1);
          if (p == 2)
            points[dofs[2]] = cell->center();
          else
            for (unsigned int j = 1; j < p; ++j)
              points[dofs[j + 1]] =
                Point<1>(cell->vertex(0)[0] +
                         (cell->vertex(1)[0] - cell->vertex(0)[0]) * j / p);
        }
      return points;
    }

    FullMatrix<double>
    BSpline::extrapolation_weights(const unsigned int, const unsigned int) const
    {
      AssertThrow(false,
                  ExcMessage("Basis/Type = bspline has no extrapolation "
                             "weights (Mass matrix/Type = extrapolate is not "
                             "available with it)."));
      return FullMatrix<double>();
    }

    Quadrature<1>
    BSpline::cell_quadrature(const DoFHandler<1> &dof_handler,
                             const unsigned int   cell) const
    {
      AssertThrow(cell < cell_data.size() &&
                    cell_data.size() ==
                      dof_handler.get_triangulation().n_active_cells(),
                  ExcMessage("BSpline::cell_quadrature: call reinit() with "
                             "this mesh first."));
      const CellData       &d      = cell_data[cell];
      const double          length = 1 / d.inverse_length;
      const QGauss<1>       reference(p + 1);
      std::vector<Point<1>> points(reference.size());
      std::vector<double>   weights(reference.size());
      for (unsigned int q = 0; q < reference.size(); ++q)
        {
          points[q]  = Point<1>(d.origin + length * reference.point(q)[0]);
          weights[q] = std::abs(length) * reference.weight(q);
        }
      return Quadrature<1>(points, weights);
    }

    double
    BSpline::stability_factor(const bool lumped) const
    {
      // Measured (contrib/studies/chapter/chapter_bar_study.py --stability [--degree p],
      // doc/chapter.md): bisection of the fixed step on the chapter's
      // bar, 10 elements, 2000 steps, stable = no monitor trips, fixed and
      // free ends; the smaller value, rounded down.
      // p = 2: consistent 0.528 (fixed ends), 0.423 (free ends; the
      // exact-mass eigenvalue bound 2 / omega_max is 0.431); lumped 0.571
      // and 0.651, the energy monitor tripping before the eigenvalue bound
      // (0.862 free, 1.269 fixed), as for P1 (0.632 against its analytic
      // 1): 0.5 and 0.4, to one decimal as first published.
      // The other degrees to a multiple of 0.05 (eigenvalue bounds of 40
      // elements in brackets): p = 1 lumped 0.632, 0.643 (1.0, 1.0: MPM's
      // values), consistent 0.597, 0.574 (0.579, 0.577); p = 3
      // consistent 0.524, 0.285 (0.524, 0.291); p = 4 0.408, 0.205
      // (0.404, 0.212); p = 5 0.327, 0.156 (0.319, 0.163). The free bar's
      // highest mode, that of the end functions, sets the limit, and it
      // falls with the degree. Lumped mass is refused for p >= 3; the
      // consistent value is returned there as the conservative one.
      switch (p)
        {
          case 1:
            return lumped ? 0.6 : 0.55;
          case 2:
            return lumped ? 0.5 : 0.4;
          case 3:
            return 0.25;
          case 4:
            return 0.2;
          default:
            Assert(p == 5, ExcInternalError());
            return 0.15;
        }
    }

    std::string
    BSpline::default_mass_matrix(const bool) const
    {
      // Measured on the chapter's bar (doc/chapter.md): consistent mass
      // converges with rate 3 in displacement and 2 in stress; lumped
      // mass (the chapter's standard mapping) misplaces the coefficients
      // of the open-knot end functions by O(h), and its errors near the
      // ends converge with rates 1.5 and 0.5 only.
      return "consistent";
    }

    std::vector<std::string>
    BSpline::verified_mass_matrices() const
    {
      // The lumped path lumps the rows of the free DoFs' functions. For
      // p <= 2 these are the B-splines (non-negative, the chapter's
      // lumping); for p >= 3 they are combinations of B-splines with
      // coefficients of both signs, whose row sums depend on the choice
      // of free DoFs and can be negative or zero (no sound lumped mass),
      // while the consistent mass depends on the space only.
      // Ghost penalty mass: the consistent matrix on filled cells and on
      // polynomials of degree p, which the B-splines reproduce; measured
      // stable where consistent mass fails on nearly empty cells
      // (doc/chapter.md "BSMPM in 2D", 1D and 2D).
      if (p <= 2)
        return {"lumped", "consistent", "ghost penalty"};
      return {"consistent", "ghost penalty"};
    }

    std::vector<std::string>
    BSpline::verified_transfers() const
    {
      return {"musl", "usl"};
    }

    namespace
    {
      std::unique_ptr<Space<1>>
      make_bspline()
      {
        return std::make_unique<BSpline>();
      }

      const Registration<SpaceRegistry<1>> register_bspline(
        {"bspline",
         "B-splines of Basis/Degree p (1 to 5) with maximal continuity on "
         "the open knot vector of the 1D mesh (BSMPM), by Bezier "
         "extraction on the FE_Q(p) layout; lumped mass for p <= 2 only",
         &make_bspline,
         nullptr});
    } // namespace
  }   // namespace Basis
} // namespace psmpm
