// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <psmpm/mesh/held_cells.h>
#include <psmpm/simulator/point_accumulation.h>
#include <psmpm/simulator/reconstruction.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /**
       * Taylor least squares (TLS) reconstruction, Wobbes et al. 2019
       * (book chapter) section 4.4: in every interior cell, density,
       * momentum density and stress are fitted by least squares to the
       * cell's particle data in a quadratic Taylor basis whose functions
       * but the first have mean zero over the cell (eq. 4.32) and are
       * integrated by Gauss quadrature:
       *
       *   M_ij = sum_g rho~(x_g) w_g phi_i phi_j,
       *   p_i  = sum_g (rho v)~(x_g) w_g phi_i,
       *   f_i  = sum_g (rho~(x_g) g phi_i - sigma~(x_g) grad phi_i) w_g.
       *
       * 1D (eq. 4.31): 1, xi, xi^2 / 2 - 1/6 with xi = (x - x_c) / (h / 2),
       * Gauss rule of degree + 2 points (exact for rho~ phi_i phi_j,
       * degree 2 + 2 p). 2D (the follow-up paper of the thesis): 1,
       * l1 - 1/3, l2 - 1/3, l0^2 - 1/6, l1^2 - 1/6, l2^2 - 1/6 in the
       * barycentric coordinates of the triangle, with the space's own cell
       * rule (Powell-Sabin: 7 points on each of the six sub-triangles).
       *
       * The constant coefficient of density and momentum is fixed to the
       * cell's particle mass and momentum over its measure (eqs. 4.35,
       * 4.39, 4.40), the rest fitted to the remainder: with a rule exact
       * for the Taylor basis, grid mass and momentum equal the
       * particles'. The stress is fitted with all coefficients (eq. 4.36).
       *
       * Fields = stress and centred momentum replaces the chapter's
       * velocity mapping by one that is exact for linear velocity fields
       * (see centred_momentum()); Acceleration mass = lumped takes the
       * chapter's lumped particle mass for the acceleration (eqs. 4.5,
       * 4.8) beside the consistent mass of the velocity mapping.
       *
       * Interior cells only: a cell takes the fit if it holds at least
       * twice as many particles as there are Taylor functions and every
       * cell that shares a vertex with it holds particles. A cell at a free
       * surface of the material is partly empty, and the fit would spread
       * its mass over the whole cell; its particles stay the quadrature
       * points there (the "particles elsewhere"). A cell whose
       * particles cannot determine the quadratic fit (fewer particles than
       * functions, or normal equations that lose their rank) is fitted
       * linearly, or with the constant alone: conservation does not
       * depend on it.
       *
       * Memory: the rule, the space's values and gradients at its points
       * are kept for every owned cell (Powell-Sabin: 42 points x 9 functions x
       * 3 doubles, 9 kB per cell): meant for the chapter's and the thesis'
       * scenes.
       */
      template <int dim>
      class TaylorLeastSquares : public Reconstruction<dim>
      {
      public:
        explicit TaylorLeastSquares(ParameterHandler &prm)
        {
          prm.enter_subsection("Taylor least squares");
          const std::string fields = prm.get("Fields");
          mapping                  = fields == "stress and momentum" ?
                                       VelocityMapping::chapter :
                                     fields == "stress and centred momentum" ?
                                       VelocityMapping::centred :
                                       VelocityMapping::particles;
          lumped_accel             = prm.get("Acceleration mass") == "lumped";
          prm.leave_subsection();
        }

        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Taylor least squares");
          prm.declare_entry(
            "Fields",
            "stress",
            Patterns::Selection(
              "stress|stress and momentum|stress and centred momentum"),
            "stress: the internal force from the fitted stress (eqs. "
            "4.36-4.38), mass and momentum mapped by the particles; stress "
            "and momentum: also the velocity mapping of MUSL/USL from "
            "density and momentum fitted under the cells' mass and momentum "
            "(eqs. 4.39-4.44, the chapter's TLS), which puts each cell's "
            "particle momentum at the cell's centroid: first-order wrong "
            "where the particles' centroid is not the cell's (a particle "
            "that just crossed in; lattice particles in triangles), "
            "measured in doc/chapter.md; stress and centred momentum: the "
            "velocity mapping from a linear density with the particles' "
            "mass and mass centre and a quadratic velocity fit whose "
            "density-weighted integral is the cell's particle momentum: as "
            "conservative, and exact for linear velocity fields (a cell "
            "whose density would not stay positive keeps its particles).");
          prm.declare_entry(
            "Acceleration mass",
            "mass matrix",
            Patterns::Selection("mass matrix|lumped"),
            "mass matrix: the acceleration M^{-1} f with the mass matrix "
            "of Mass matrix/Type; lumped: with the particles' lumped mass "
            "(eqs. 4.5 and 4.8) whatever Mass matrix/Type is, which then "
            "serves the velocity mapping alone. Fields = stress and "
            "momentum, Mass matrix/Type = consistent and lumped is the "
            "chapter's TLS-BSMPM: two mass matrices per step.");
          prm.leave_subsection();
        }

        void
        initialize(const State<dim> &state) override;

        std::vector<std::string>
        verified_mass_matrices() const override
        {
          return {"lumped", "consistent"};
        }

        std::vector<std::string>
        verified_transfers() const override
        {
          return {"musl", "usl"};
        }

        bool
        fits_momentum() const override
        {
          return mapping != VelocityMapping::particles;
        }

        bool
        lumped_acceleration() const override
        {
          return lumped_accel;
        }

        void
        mass_and_forces(State<dim>  &state,
                        const double momentum_weight,
                        const double force_weight) override;

        void
        momentum(State<dim> &state) override;

      private:
        /// Taylor functions without the constant, linear ones first, are
        /// stored first; the constant is stored last, so that the leading
        /// block of the normal equations is that of the constrained fits
        /// and one Cholesky factorization serves both kinds of fit.
        static constexpr unsigned int n_linear    = dim;
        static constexpr unsigned int n_quadratic = dim == 1 ? 1 : 3;
        static constexpr unsigned int n_free      = n_linear + n_quadratic;
        static constexpr unsigned int n_max       = n_free + 1;

        /// The fit of one cell: Cholesky factor L of the normal equations
        /// D = sum_p psi psi^T over the first n_used free functions and the
        /// constant (row n_used), and the particle sums that the fits
        /// need.
        struct Fit
        {
          unsigned int n_used = 0;
          double       L[n_max][n_max];
          double       psi_sum[n_max]; ///< sum_p psi_i(x_p)
        };

        void
        taylor_basis(const unsigned int cell,
                     const Point<dim>  &x,
                     double            *psi) const;

        /// The cells that share a vertex with each cell of @p tria
        /// (neighbors, neighbor_start).
        void
        find_neighbors(const Triangulation<dim> &tria);

        /// The affine map to the reference coordinates of owned @p cell
        /// (origin, to_reference) and its measure; returns the cell's rule.
        Quadrature<dim>
        map_cell(const State<dim>                                        &state,
                 const typename Triangulation<dim>::active_cell_iterator &cell);

        /// The rule @p rule of owned cell @p c stored: weights, Taylor
        /// functions, the space's values and gradients (the arrays sized
        /// at the first cell).
        void
        store_rule(const State<dim>      &state,
                   const unsigned int     c,
                   const Quadrature<dim> &rule);

        void
        sort_particles(const State<dim> &state);

        /// Normal equations of the particles of @p cell, factorized with
        /// as many free functions as they determine.
        void
        factorize(const State<dim> &state, const unsigned int cell, Fit &fit);

        /// Coefficients of the free functions of a fit whose constant is
        /// given: L' L'^T a = b - c psi_sum over the free block.
        template <typename T>
        static void
        solve_constrained(const Fit &fit, T *b, const T &constant);

        /// All coefficients (constant last) of an unconstrained fit.
        template <typename T>
        static void
        solve_full(const Fit &fit, T *b);

        /// Solve L L^T x = b over the leading @p n rows of the factor.
        template <typename T>
        static void
        cholesky_solve(const Fit &fit, const unsigned int n, T *b);

        /// The particles of @p cell as quadrature points (as in
        /// TransferScheme::particles_to_grid()): mass, momentum_weight m v
        /// + force_weight m g, and stress_weight V sigma into the cell's
        /// arrays (@p mass: its consistent block, or nullptr).
        void
        add_particles(State<dim>        &state,
                      const unsigned int cell,
                      const double       momentum_weight,
                      const double       force_weight,
                      const double       stress_weight,
                      double            *mass) const;

        /// Which cells take the fit this step (see the class comment).
        void
        mark_interior_cells(const State<dim> &state);

        /// The chapter's velocity mapping of an interior cell (eqs.
        /// 4.39-4.43) into its arrays (@p mass: its consistent block, or
        /// nullptr).
        void
        chapter_momentum(State<dim>        &state,
                         const unsigned int cell,
                         Fit               &fit,
                         double            *mass);

        /// The centred velocity mapping of an interior cell (see the
        /// definition); false, with nothing added, if its density would
        /// not be positive at every point of the rule.
        bool
        centred_momentum(State<dim>        &state,
                         const unsigned int cell,
                         Fit               &fit,
                         double            *mass);

        /// The velocity fit of centred_momentum(): @p v holds the right-
        /// hand sides sum_p psi_k(x_p) v_p of the fit's normal equations
        /// (constant at fit.n_used) and returns the coefficients of the
        /// least squares fit under int rho~ v~ = @p momentum, with rho~
        /// given at the rule's points of @p cell by @p density.
        void
        fit_velocity(const unsigned int    cell,
                     const Fit            &fit,
                     const double         *density,
                     const Tensor<1, dim> &momentum,
                     Tensor<1, dim>       *v) const;

        /// Coefficients of the linear density of centred_momentum() in
        /// @p cell: r[j] of linear function j, r[dim] the constant, from
        /// the cell's particle mass and first moments @p first[j] =
        /// sum_p m_p psi_j(x_p).
        void
        density_coefficients(const unsigned int cell,
                             const double       cell_mass,
                             const double      *first,
                             double            *r) const;

        /// Per active cell: the affine map to the reference coordinates
        /// of the Taylor basis, xi = A (x - origin) (1D: xi in [-1, 1];
        /// 2D: the barycentric coordinates l1, l2), and the measure.
        std::vector<Point<dim>>     origin;
        std::vector<Tensor<2, dim>> to_reference;
        std::vector<double>         measure;

        /// Rule per owned cell: n_q points (the same number on every
        /// cell), their weights, the Taylor functions (n_q x n_max) and
        /// the space's values and gradients (n_q x dofs_per_cell), stored
        /// for this rank's cells only (several kB per cell, the largest
        /// per-cell data of a run that uses them).
        unsigned int    n_q = 0, n_dofs = 0;
        Mesh::HeldCells owned;
        /// Index of point @p q of owned cell @p c in the arrays below.
        unsigned int
        point(const unsigned int c, const unsigned int q) const
        {
          return owned.slot(c) * n_q + q;
        }
        std::vector<double>         weights;
        std::vector<double>         q_psi;
        std::vector<double>         q_values;
        std::vector<Tensor<1, dim>> q_gradients;

        /// The cells that share a vertex with each cell:
        /// neighbors[neighbor_start[c] .. neighbor_start[c + 1]).
        std::vector<unsigned int> neighbor_start, neighbors;
        /// Per cell this step: holds particles (on any rank), takes the
        /// fit.
        std::vector<unsigned int> occupied;
        std::vector<bool>         interior;

        /// The velocity mapping (entry Fields): the particles', the
        /// chapter's (stress and momentum), or centred_momentum().
        enum class VelocityMapping
        {
          particles,
          chapter,
          centred
        };
        VelocityMapping mapping = VelocityMapping::particles;
        /// Acceleration mass = lumped.
        bool lumped_accel = false;

        /// Particles by cell: order[offsets[c] .. offsets[c + 1]).
        std::vector<unsigned int> offsets, order;
        /// Taylor functions at the particles of the cell being fitted;
        /// density at the rule's points of that cell.
        std::vector<double> scratch_psi, scratch_density;
      };


      template <int dim>
      void
      TaylorLeastSquares<dim>::initialize(const State<dim> &state)
      {
        const auto &tria = *state.triangulation;
        // The 2D Taylor basis is written in barycentric coordinates.
        AssertThrow(dim == 1 || tria.all_reference_cells_are_simplex(),
                    ExcMessage("Transfer/Reconstruction = taylor least "
                               "squares: in 2D implemented on triangles "
                               "only, not on Mesh/Type = cartesian."));
        const unsigned int n_cells = tria.n_active_cells();
        n_dofs                     = state.space->dofs_per_cell();
        origin.assign(n_cells, Point<dim>());
        to_reference.assign(n_cells, Tensor<2, dim>());
        measure.assign(n_cells, 0.);
        find_neighbors(tria);

        owned.reinit(tria, false);
        n_q = 0;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            store_rule(state, cell->active_cell_index(), map_cell(state, cell));
        offsets.resize(n_cells + 1);
        occupied.resize(n_cells);
        interior.resize(n_cells);
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::find_neighbors(const Triangulation<dim> &tria)
      {
        // Cells around each vertex, then around each cell.
        std::vector<std::vector<unsigned int>> at_vertex(tria.n_vertices());
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            at_vertex[cell->vertex_index(v)].push_back(
              cell->active_cell_index());
        neighbor_start.assign(1, 0);
        neighbors.clear();
        std::vector<unsigned int> around;
        for (const auto &cell : tria.active_cell_iterators())
          {
            around.clear();
            for (const unsigned int v : cell->vertex_indices())
              for (const unsigned int c : at_vertex[cell->vertex_index(v)])
                if (c != cell->active_cell_index())
                  around.push_back(c);
            std::sort(around.begin(), around.end());
            around.erase(std::unique(around.begin(), around.end()),
                         around.end());
            neighbors.insert(neighbors.end(), around.begin(), around.end());
            neighbor_start.push_back(neighbors.size());
          }
      }


      template <int dim>
      Quadrature<dim>
      TaylorLeastSquares<dim>::map_cell(
        const State<dim>                                        &state,
        const typename Triangulation<dim>::active_cell_iterator &cell)
      {
        const unsigned int c = cell->active_cell_index();
        measure[c]           = cell->measure();
        Tensor<2, dim>  jacobian;
        Quadrature<dim> rule;
        if (dim == 1)
          {
            // xi = (x - centre) / (h / 2).
            origin[c]      = cell->center();
            jacobian[0][0] = (cell->vertex(1)[0] - cell->vertex(0)[0]) / 2;
            const QGauss<dim>       gauss(state.space->degree() + 2);
            std::vector<Point<dim>> points(gauss.size());
            std::vector<double>     w(gauss.size());
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                points[q] =
                  cell->vertex(0) +
                  (cell->vertex(1) - cell->vertex(0)) * gauss.point(q)[0];
                w[q] = measure[c] * gauss.weight(q);
              }
            rule = Quadrature<dim>(points, w);
          }
        else
          {
            // (l1, l2) = J^-1 (x - v0), J = [v1 - v0, v2 - v0].
            origin[c] = cell->vertex(0);
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < dim; ++e)
                jacobian[e][d] = cell->vertex(d + 1)[e] - cell->vertex(0)[e];
            rule = state.space->cell_quadrature(state.dof_handler, c);
          }
        to_reference[c] = invert(jacobian);
        return rule;
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::store_rule(const State<dim>      &state,
                                          const unsigned int     c,
                                          const Quadrature<dim> &rule)
      {
        if (n_q == 0)
          {
            n_q                  = rule.size();
            const unsigned int m = owned.size();
            weights.assign(m * n_q, 0.);
            q_psi.assign(m * n_q * n_max, 0.);
            q_values.assign(m * n_q * n_dofs, 0.);
            q_gradients.assign(m * n_q * n_dofs, Tensor<1, dim>());
          }
        AssertThrow(rule.size() == n_q,
                    ExcMessage("TaylorLeastSquares: the cell rules of the "
                               "space differ in size."));
        const std::vector<unsigned int> cells(n_q, c);
        state.space->evaluate(n_q,
                              cells.data(),
                              rule.get_points().data(),
                              &q_values[point(c, 0) * n_dofs],
                              &q_gradients[point(c, 0) * n_dofs]);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            weights[point(c, q)] = rule.weight(q);
            taylor_basis(c, rule.point(q), &q_psi[point(c, q) * n_max]);
          }
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::taylor_basis(const unsigned int cell,
                                            const Point<dim>  &x,
                                            double            *psi) const
      {
        const Tensor<1, dim> xi = to_reference[cell] * (x - origin[cell]);
        if (dim == 1)
          {
            psi[0] = xi[0];
            psi[1] = xi[0] * xi[0] / 2 - 1. / 6;
          }
        else
          {
            const double l1 = xi[0], l2 = xi[dim - 1], l0 = 1 - l1 - l2;
            psi[0] = l1 - 1. / 3;
            psi[1] = l2 - 1. / 3;
            psi[2] = l0 * l0 - 1. / 6;
            psi[3] = l1 * l1 - 1. / 6;
            psi[4] = l2 * l2 - 1. / 6;
          }
        psi[n_max - 1] = 1;
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::mark_interior_cells(const State<dim> &state)
      {
        const unsigned int n_cells = occupied.size();
        for (unsigned int c = 0; c < n_cells; ++c)
          occupied[c] = offsets[c + 1] > offsets[c];
        // Neighbours may be other ranks' cells: every rank needs every
        // cell's flag (one reduction of n_cells integers a step).
        if (Utilities::MPI::n_mpi_processes(state.comm) > 1)
          Utilities::MPI::max(occupied, state.comm, occupied);
        for (unsigned int c = 0; c < n_cells; ++c)
          {
            // Twice as many particles as Taylor functions: with fewer the
            // fit nearly interpolates, and lattice particles that line up
            // in a triangle make it extrapolate wildly to the Gauss
            // points (measured: prm/column_collapse.prm with 2-9 particles
            // per triangle grows energy within 47-176 steps; 36 per
            // triangle runs like the particles).
            bool all = offsets[c + 1] - offsets[c] >= 2 * n_max;
            for (unsigned int i = neighbor_start[c];
                 all && i < neighbor_start[c + 1];
                 ++i)
              all = occupied[neighbors[i]] != 0;
            interior[c] = all;
          }
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::sort_particles(const State<dim> &state)
      {
        // Counting sort by cell: O(particles + cells), no allocation once
        // the arrays have grown.
        const auto &cell_of = state.particles.cell;
        std::fill(offsets.begin(), offsets.end(), 0u);
        for (const unsigned int c : cell_of)
          ++offsets[c + 1];
        for (unsigned int c = 0; c + 1 < offsets.size(); ++c)
          offsets[c + 1] += offsets[c];
        order.resize(cell_of.size());
        for (unsigned int p = 0; p < cell_of.size(); ++p)
          order[offsets[cell_of[p]]++] = p;
        // offsets[c] now ends cell c: shift back.
        for (unsigned int c = offsets.size() - 1; c > 0; --c)
          offsets[c] = offsets[c - 1];
        offsets[0] = 0;
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::factorize(const State<dim>  &state,
                                         const unsigned int cell,
                                         Fit               &fit)
      {
        const unsigned int begin = offsets[cell],
                           n_p   = offsets[cell + 1] - begin;
        scratch_psi.resize(n_p * n_max);
        double D[n_max][n_max] = {};
        for (unsigned int i = 0; i < n_p; ++i)
          {
            double *psi = &scratch_psi[i * n_max];
            taylor_basis(cell, state.particles.position[order[begin + i]], psi);
            for (unsigned int r = 0; r < n_max; ++r)
              for (unsigned int s = 0; s <= r; ++s)
                D[r][s] += psi[r] * psi[s];
          }
        for (unsigned int r = 0; r < n_max; ++r)
          fit.psi_sum[r] = D[n_max - 1][r];

        // As many free functions as the particles determine: the
        // unconstrained (stress) fit needs n_used + 1 particles.
        unsigned int n_used = n_p >= n_max        ? n_free :
                              n_p >= n_linear + 1 ? n_linear :
                                                    0;
        // Cholesky of the leading block; a pivot that has lost all but
        // 1e-3 of its diagonal means the particles hardly see that
        // function (they line up): drop it and what follows it.
        const auto factor_row = [&](const unsigned int r,
                                    const unsigned int source,
                                    const unsigned int n_before) {
          for (unsigned int s = 0; s < n_before; ++s)
            {
              double v = (source >= s ? D[source][s] : D[s][source]);
              for (unsigned int t = 0; t < s; ++t)
                v -= fit.L[r][t] * fit.L[s][t];
              fit.L[r][s] = v / fit.L[s][s];
            }
          double pivot = D[source][source];
          for (unsigned int t = 0; t < n_before; ++t)
            pivot -= fit.L[r][t] * fit.L[r][t];
          const bool ok      = pivot > 1e-3 * D[source][source];
          fit.L[r][n_before] = ok ? std::sqrt(pivot) : 0.;
          return ok;
        };
        for (unsigned int r = 0; r < n_used; ++r)
          if (!factor_row(r, r, r))
            {
              // Keep complete polynomial degrees only.
              n_used = r < n_linear ? 0 : n_linear;
              break;
            }
        // The constant row: its pivot is n_p minus the part the free
        // functions explain, positive for any n_p >= 1 unless the free
        // functions are constant on the particles (then drop them).
        while (!factor_row(n_used, n_max - 1, n_used))
          n_used = 0;
        fit.n_used = n_used;
        // The constant's sums in the positions the factor uses.
        fit.psi_sum[n_used] = fit.psi_sum[n_max - 1];
      }


      template <int dim>
      template <typename T>
      void
      TaylorLeastSquares<dim>::cholesky_solve(const Fit         &fit,
                                              const unsigned int n,
                                              T                 *b)
      {
        for (unsigned int r = 0; r < n; ++r)
          {
            for (unsigned int s = 0; s < r; ++s)
              b[r] -= fit.L[r][s] * b[s];
            b[r] /= fit.L[r][r];
          }
        for (unsigned int r = n; r-- > 0;)
          {
            for (unsigned int s = r + 1; s < n; ++s)
              b[r] -= fit.L[s][r] * b[s];
            b[r] /= fit.L[r][r];
          }
      }


      template <int dim>
      template <typename T>
      void
      TaylorLeastSquares<dim>::solve_constrained(const Fit &fit,
                                                 T         *b,
                                                 const T   &constant)
      {
        for (unsigned int r = 0; r < fit.n_used; ++r)
          b[r] -= constant * fit.psi_sum[r];
        cholesky_solve(fit, fit.n_used, b);
      }


      template <int dim>
      template <typename T>
      void
      TaylorLeastSquares<dim>::solve_full(const Fit &fit, T *b)
      {
        cholesky_solve(fit, fit.n_used + 1, b);
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::add_particles(State<dim>        &state,
                                             const unsigned int cell,
                                             const double       momentum_weight,
                                             const double       force_weight,
                                             const double       stress_weight,
                                             double            *mass) const
      {
        const auto        &particles = state.particles;
        auto              &cells     = state.grid->cell_arrays();
        const unsigned int n = n_dofs, base = cell * n;
        for (unsigned int i = offsets[cell]; i < offsets[cell + 1]; ++i)
          {
            const unsigned int   p = order[i];
            const double         m = particles.mass[p];
            const Tensor<1, dim> momentum =
              momentum_weight != 0 ?
                momentum_weight * m * particles.velocity[p] :
                Tensor<1, dim>();
            add_point<dim>(n,
                           m,
                           momentum + force_weight * m * state.gravity,
                           stress_weight * particles.volume[p],
                           state.stress_for_forces()[p],
                           &state.shape_values[p * n],
                           state.gradients(p, cell),
                           &cells.lumped[base],
                           mass,
                           &cells.rhs[base]);
          }
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::mass_and_forces(State<dim>  &state,
                                               const double momentum_weight,
                                               const double force_weight)
      {
        sort_particles(state);
        mark_interior_cells(state);
        auto              &cells      = state.grid->cell_arrays();
        const bool         consistent = !cells.mass.empty();
        const unsigned int n          = n_dofs;
        Fit                fit;
        for (unsigned int c = 0; c + 1 < offsets.size(); ++c)
          {
            const unsigned int begin = offsets[c], end = offsets[c + 1];
            if (begin == end)
              continue;
            const unsigned int base = c * n;
            double *const mass = consistent ? &cells.mass[base * n] : nullptr;
            // Mass (eq. 4.5), external force and momentum from the
            // particles; their stress only where the cell is not fitted.
            const bool fitted = interior[c];
            add_particles(state,
                          c,
                          momentum_weight,
                          force_weight,
                          fitted ? 0. : force_weight,
                          mass);
            if (!fitted || force_weight == 0)
              continue;
            // Internal force of the fitted stress (eqs. 4.36-4.38).
            factorize(state, c, fit);
            const unsigned int      k            = fit.n_used;
            SymmetricTensor<2, dim> sigma[n_max] = {};
            for (unsigned int i = begin; i < end; ++i)
              {
                const double *psi = &scratch_psi[(i - begin) * n_max];
                const auto   &s   = state.stress_for_forces()[order[i]];
                for (unsigned int r = 0; r < k; ++r)
                  sigma[r] += psi[r] * s;
                sigma[k] += s;
              }
            solve_full(fit, sigma);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const unsigned int      g   = point(c, q);
                const double           *psi = &q_psi[g * n_max];
                SymmetricTensor<2, dim> s   = sigma[k];
                for (unsigned int r = 0; r < k; ++r)
                  s += sigma[r] * psi[r];
                const SymmetricTensor<2, dim> sw =
                  force_weight * weights[g] * s;
                const Tensor<1, dim> *grad = &q_gradients[g * n];
                for (unsigned int a = 0; a < n; ++a)
                  cells.rhs[base + a] -= sw * grad[a];
              }
          }
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::momentum(State<dim> &state)
      {
        // The particles have not moved since mass_and_forces(): the cells'
        // particle lists and interior flags are still those of the step.
        // The mass matrix of the velocity (eqs. 4.42-4.44) replaces that
        // of the acceleration.
        auto &grid = *state.grid;
        grid.zero_cell_mass();
        auto      &cells      = grid.cell_arrays();
        const bool consistent = !cells.mass.empty();
        Fit        fit;
        for (unsigned int c = 0; c + 1 < offsets.size(); ++c)
          {
            if (offsets[c + 1] == offsets[c])
              continue;
            double *const mass =
              consistent ? &cells.mass[c * n_dofs * n_dofs] : nullptr;
            if (interior[c] && mapping == VelocityMapping::chapter)
              chapter_momentum(state, c, fit, mass);
            else if (!interior[c] || !centred_momentum(state, c, fit, mass))
              add_particles(state, c, 1., 0., 0., mass);
          }
        grid.assemble_mass();
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::chapter_momentum(State<dim>        &state,
                                                const unsigned int c,
                                                Fit               &fit,
                                                double            *mass)
      {
        const auto        &particles = state.particles;
        auto              &cells     = state.grid->cell_arrays();
        const unsigned int n = n_dofs, base = c * n;
        const unsigned int begin = offsets[c], end = offsets[c + 1];
        factorize(state, c, fit);
        const unsigned int k            = fit.n_used;
        double             rho[n_max]   = {};
        Tensor<1, dim>     rho_v[n_max] = {};
        double             cell_mass    = 0;
        Tensor<1, dim>     cell_momentum;
        for (unsigned int i = begin; i < end; ++i)
          {
            const unsigned int   p   = order[i];
            const double        *psi = &scratch_psi[(i - begin) * n_max];
            const double         d   = particles.density[p];
            const Tensor<1, dim> dv  = d * particles.velocity[p];
            for (unsigned int r = 0; r < k; ++r)
              {
                rho[r] += psi[r] * d;
                rho_v[r] += psi[r] * dv;
              }
            cell_mass += particles.mass[p];
            cell_momentum += particles.mass[p] * particles.velocity[p];
          }
        // Eqs. 4.39-4.40: the cell's mass and momentum fix the constant
        // coefficients.
        const double         rho_0   = cell_mass / measure[c];
        const Tensor<1, dim> rho_v_0 = cell_momentum / measure[c];
        solve_constrained(fit, rho, rho_0);
        solve_constrained(fit, rho_v, rho_v_0);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int g   = point(c, q);
            const double      *psi = &q_psi[g * n_max];
            double             d   = rho_0;
            Tensor<1, dim>     dv  = rho_v_0;
            for (unsigned int r = 0; r < k; ++r)
              {
                d += rho[r] * psi[r];
                dv += rho_v[r] * psi[r];
              }
            const double w = weights[g];
            add_point<dim>(n,
                           d * w,
                           w * dv,
                           0.,
                           SymmetricTensor<2, dim>(),
                           &q_values[g * n],
                           &q_gradients[g * n],
                           &cells.lumped[base],
                           mass,
                           &cells.rhs[base]);
          }
      }


      /*
       * Why the chapter's mapping is first order, and what this one keeps.
       * The grid velocity solves  int rho~ v_h phi_i = int (rho v)~ phi_i.
       * For a linear velocity field v (which the spline space holds) v_h
       * = v exactly if (rho v)~ = rho~ v. The chapter fits rho~ and
       * (rho v)~ separately with their means fixed to M_e / |cell| and
       * P_e / |cell|: for linear v, P_e = M_e v(x_m) at the particles'
       * mass centre x_m, while the mean of rho~ v is M_e v(x_rho) at the
       * centre x_rho of the fitted density, near the cell's centroid when
       * the particle densities are even. A particle that has just crossed
       * in moves x_m by about h / 18 (9 particles where 8 fit): an error
       * v' (x_m - x_rho) in every affected cell, first order in h.
       *
       * Here instead:
       *  1. rho~ = r_0 + sum_j r_j psi_j over the linear Taylor functions
       *     with int rho~ = M_e (r_0 = M_e / |cell|, as eq. 4.39) and
       *     int rho~ psi_j = sum_p m_p psi_j(x_p): the particles' mass and
       *     mass centre (a 1x1 or 2x2 system: the linear functions have
       *     mean zero, so r_0 decouples). For every linear v then
       *     int rho~ v = sum_p m_p v(x_p).
       *  2. v~ = the least squares fit of the particle velocities in the
       *     quadratic Taylor basis (the stress fit's normal equations D)
       *     under the one constraint w . c = P_e, w_k = int rho~ psi_k:
       *     c = c_u + lambda D^{-1} w, lambda = (P_e - w . c_u) / (w .
       *     D^{-1} w).
       *  3. (rho v)~ = rho~ v~ and M = int rho~ phi phi^T by the cell's
       *     rule (exact: degree 1 + 2 + p and 1 + 2 p).
       * Conservation is algebraic: the grid mass of the cell is the rule's
       * int rho~ = M_e, its momentum sum_g w_g rho~ v~ = w . c = P_e. For
       * linear particle velocities the unconstrained fit is v itself and
       * w . c_u = sum_p m_p v(x_p) = P_e by step 1, so lambda = 0 and v_h
       * = v: the mapping is exact for linear fields (second order), with
       * the constraint only correcting curvature. A cell whose particles'
       * mass centre lies so far off-centre that rho~ is not positive at
       * every point of the rule keeps its particles as quadrature points
       * (equally conservative and exact for linear fields).
       */
      template <int dim>
      bool
      TaylorLeastSquares<dim>::centred_momentum(State<dim>        &state,
                                                const unsigned int c,
                                                Fit               &fit,
                                                double            *mass)
      {
        const auto        &particles = state.particles;
        auto              &cells     = state.grid->cell_arrays();
        const unsigned int n = n_dofs, base = c * n;
        const unsigned int begin = offsets[c], end = offsets[c + 1];
        factorize(state, c, fit);
        const unsigned int k = fit.n_used;

        // 1. Density: mass and mass centre.
        double         cell_mass = 0, first[dim] = {};
        Tensor<1, dim> cell_momentum, v_fit[n_max];
        for (unsigned int i = begin; i < end; ++i)
          {
            const unsigned int p   = order[i];
            const double      *psi = &scratch_psi[(i - begin) * n_max];
            const double       m   = particles.mass[p];
            cell_mass += m;
            cell_momentum += m * particles.velocity[p];
            for (unsigned int j = 0; j < dim; ++j)
              first[j] += m * psi[j];
            for (unsigned int r = 0; r < k; ++r)
              v_fit[r] += psi[r] * particles.velocity[p];
            v_fit[k] += particles.velocity[p];
          }
        double r[dim + 1];
        density_coefficients(c, cell_mass, first, r);
        scratch_density.resize(n_q);
        double *const density = scratch_density.data();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double *psi = &q_psi[point(c, q) * n_max];
            density[q]        = r[dim];
            for (unsigned int j = 0; j < dim; ++j)
              density[q] += r[j] * psi[j];
            if (!(density[q] > 0))
              return false;
          }

        // 2. Velocity: least squares under w . c = P_e.
        fit_velocity(c, fit, density, cell_momentum, v_fit);

        // 3. rho~ and rho~ v~ at the rule's points.
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int g   = point(c, q);
            const double      *psi = &q_psi[g * n_max];
            Tensor<1, dim>     v   = v_fit[k];
            for (unsigned int j = 0; j < k; ++j)
              v += v_fit[j] * psi[j];
            const double dw = density[q] * weights[g];
            add_point<dim>(n,
                           dw,
                           dw * v,
                           0.,
                           SymmetricTensor<2, dim>(),
                           &q_values[g * n],
                           &q_gradients[g * n],
                           &cells.lumped[base],
                           mass,
                           &cells.rhs[base]);
          }
        return true;
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::fit_velocity(const unsigned int    c,
                                            const Fit            &fit,
                                            const double         *density,
                                            const Tensor<1, dim> &momentum,
                                            Tensor<1, dim>       *v) const
      {
        // w_k = int rho~ psi_k by the rule: the constraint w . c = P_e is
        // then what the grid momentum of the cell sums to.
        const unsigned int k        = fit.n_used;
        double             w[n_max] = {}, z[n_max];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int g   = point(c, q);
            const double      *psi = &q_psi[g * n_max];
            const double       dw  = density[q] * weights[g];
            for (unsigned int j = 0; j < k; ++j)
              w[j] += dw * psi[j];
            w[k] += dw;
          }
        std::copy(w, w + k + 1, z);
        solve_full(fit, v);
        solve_full(fit, z);
        Tensor<1, dim> w_c;
        double         w_z = 0;
        for (unsigned int j = 0; j <= k; ++j)
          {
            w_c += w[j] * v[j];
            w_z += w[j] * z[j];
          }
        // The Lagrange multiplier of the constraint; w . D^-1 w > 0 as D
        // is positive definite and w_k = M_e > 0.
        const Tensor<1, dim> lambda = (momentum - w_c) / w_z;
        for (unsigned int j = 0; j <= k; ++j)
          v[j] += z[j] * lambda;
      }


      template <int dim>
      void
      TaylorLeastSquares<dim>::density_coefficients(const unsigned int c,
                                                    const double  cell_mass,
                                                    const double *first,
                                                    double       *r) const
      {
        // G_jl = int psi_j psi_l over the linear functions, by the rule
        // (exact for it).
        double G[dim][dim] = {};
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int g   = point(c, q);
            const double      *psi = &q_psi[g * n_max];
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int l = 0; l < dim; ++l)
                G[j][l] += weights[g] * psi[j] * psi[l];
          }
        r[dim] = cell_mass / measure[c];
        if constexpr (dim == 1)
          r[0] = first[0] / G[0][0];
        else
          {
            const double det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
            r[0]       = (G[1][1] * first[0] - G[0][1] * first[dim - 1]) / det;
            r[dim - 1] = (G[0][0] * first[dim - 1] - G[1][0] * first[0]) / det;
          }
      }
    } // namespace

    RegisterForDims<ReconstructionRegistry, TaylorLeastSquares>
      register_taylor_least_squares(
        "taylor least squares",
        "per cell, least squares fits of stress (and of density and "
        "momentum) in the quadratic Taylor basis, integrated by Gauss "
        "quadrature, in every cell whose vertex neighbours all hold "
        "particles (particles elsewhere); mass and momentum of each cell "
        "kept exactly (Wobbes et al. 2019, section 4.4)",
        [](ParameterHandler &prm) {
          TaylorLeastSquares<2>::declare_parameters(prm);
        });
  } // namespace Simulator
} // namespace psmpm
