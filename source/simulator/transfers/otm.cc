// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/format.h>
#include <psmpm/mesh/triangle_geometry.h>
#include <psmpm/simulator/particle_loops.h>
#include <psmpm/simulator/transfer_scheme.h>

#include <algorithm>
#include <array>
#include <limits>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /**
       * Optimal Transportation Meshfree update with P1 functions (Li et
       * al. 2010, Algorithm 1 of Wobbes et al. 2019; doc/otm.md): the grid
       * moves with the material.
       *
       * From mass, the momentum sum_p m_p v_p N_a with v_p = (x_p,k -
       * x_p,k-1) / dt (eq. 26) and the forces f_k on the grid x_k, the
       * nodal velocity u = M^{-1} (l_k + (dt_k-1 + dt_k) / 2 f_k) and the
       * nodal increment dt_k u (eqs. 7, 27); the nodes move by it, the
       * particles by the incremental transport map x_p,k+1 = sum_a
       * x_a,k+1 N_a,k(x_p,k) (eq. 30), their velocity is (x_p,k+1 -
       * x_p,k) / dt_k = sum_a u_a N_a,k(x_p,k) and their strain increment
       * sum_a Delta x_a (x) grad N_a,k (eq. 11). The functions are then
       * evaluated again on the moved grid.
       *
       * The grid is this scheme's copy of the vertex positions, not the
       * triangulation: a P1 function of a cell is affine, so it is known
       * from the cell's current vertices alone, and an affine cell map
       * keeps every particle at the same barycentric coordinates: the
       * particles never leave their cells, and the triangulation, the
       * DoF handler and the locator stay those of the initial grid; the
       * time step bound (minimum_height()) and the grid output
       * (moved_vertices()) read the moved vertices. Only cells that hold
       * particles form the OTM grid; one of them turning inside out
       * (signed measure of the opposite sign or zero) or collapsing to
       * round-off (below collapsed_ratio of its initial measure) ends the
       * run (Failure::inverted_cell) before anything moves.
       *
       * `OTM update = split` computes the nodal velocity the MPM way
       * (v_k = M^{-1} l_k, a_k = M^{-1} f_k, u = v_k + dt_k a_k; two
       * solves): with a constant step the two are the same (eqs. 27-29,
       * tests/mpm/otm_equivalence_01).
       */
      template <int dim>
      class OTM : public TransferScheme<dim>
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.declare_entry(
            "OTM update",
            "combined",
            Patterns::Selection("combined|split"),
            "How the otm scheme computes the nodal velocity: 'combined' = "
            "M^{-1} (l + (dt_old + dt) / 2 f), one solve (Algorithm 1 of "
            "Wobbes et al. 2019, eq. 7); 'split' = M^{-1} l + dt M^{-1} f, "
            "two solves, the MPM form (eq. 28), equal to 'combined' for a "
            "constant time step.");
        }

        /// @p prm is inside subsection "Transfer".
        explicit OTM(ParameterHandler &prm)
          : split(prm.get("OTM update") == "split")
        {
        }

        void
        initialize(const State<dim> &state) override
        {
          AssertThrow(state.space->name() == "linear",
                      ExcMessage(
                        "Transfer/Scheme = otm needs Basis/Type = linear "
                        "(the grid moves with the material, and only P1 "
                        "functions are determined by the moved vertices "
                        "alone); Basis/Type = " +
                        state.space->name() + " is not supported."));
          const auto &grid = *state.grid;
          AssertThrow(
            !grid.strategy().depends_on_cell_shape(),
            ExcMessage(
              "Mass matrix/Type = " + grid.parameters.type +
              " with Transfer/Scheme = otm is not supported: the strategy "
              "is computed on the shape of the initial cells, which the "
              "moving grid of otm changes (doc/otm.md). Use consistent "
              "(recommended for otm), lumped, partially lumped, blended "
              "lumping, fictitious mass or extrapolate."));
          // Vertex positions in local relevant DoF numbering (P1: one DoF
          // per vertex, the vertex is the DoF's control point).
          const auto  points = state.space->control_points(state.dof_handler);
          const auto &global = grid.relevant_global_indices();
          nodes.resize(global.size());
          for (unsigned int l = 0; l < global.size(); ++l)
            nodes[l] = points[global[l]];
          moved = nodes;
          nodal_velocity.assign(nodes.size(), Tensor<1, dim>());

          // The OTM grid: the cells that hold particles (they keep them).
          occupied.clear();
          std::vector<bool> has(grid.n_cells, false);
          for (const unsigned int c : state.particles.cell)
            has[c] = true;
          for (unsigned int c = 0; c < grid.n_cells; ++c)
            if (has[c])
              occupied.push_back(c);
          initial_measure.assign(grid.n_cells, 0.);
          for (const unsigned int c : occupied)
            initial_measure[c] = signed_measure(grid, nodes, c);
          maps.resize(grid.n_cells);
          previous_dt = 0;
        }

        bool
        moves_grid() const override
        {
          return true;
        }

        /// The smallest height of the moved cells that hold particles
        /// (the others carry no material and are not checked for
        /// inversion either); the fixed mesh's if no rank has particles.
        double
        minimum_height(const State<dim> &state) const override
        {
          double h = std::numeric_limits<double>::max();
          for (const unsigned int c : occupied)
            h = std::min(h,
                         Mesh::minimum_height(vertices(*state.grid, nodes, c)));
          h = Utilities::MPI::min(h, state.comm);
          return h < std::numeric_limits<double>::max() ?
                   h :
                   state.locator.minimum_height();
        }

        const std::vector<Point<dim>> *
        moved_vertices() const override
        {
          return &nodes;
        }

        bool
        step(State<dim>       &state,
             StabilityMonitor &monitor,
             PhaseTimer       &timer) override
        {
          const double dt = state.dt;
          // x_-1 = x_0 - dt_0 v_0: the first step is centred on dt_0.
          const double dt_mean = previous_dt > 0 ? (previous_dt + dt) / 2 : dt;
          if (split)
            {
              this->particles_to_grid(state, timer, 0., 1.);
              if (!this->solve(state, state.grid_acceleration, monitor, timer))
                return false;
              this->momentum_to_grid(state, timer);
              if (!this->solve(state, state.grid_velocity, monitor, timer))
                return false;
              for (unsigned int i = 0; i < state.grid_velocity.size(); ++i)
                state.grid_velocity[i] += dt * state.grid_acceleration[i];
            }
          else
            {
              this->particles_to_grid(state, timer, 1., dt_mean);
              if (!this->solve(state, state.grid_velocity, monitor, timer))
                return false;
              // The nodes' own acceleration: the central difference of
              // their trajectories (zero in the first step).
              state.grid_acceleration.resize(state.grid_velocity.size());
              for (unsigned int i = 0; i < state.grid_velocity.size(); ++i)
                state.grid_acceleration[i] =
                  previous_dt > 0 ?
                    (state.grid_velocity[i] - nodal_velocity[i]) / dt_mean :
                    Tensor<1, dim>();
            }
          if (!move_grid(state, monitor, timer))
            return false;
          nodal_velocity = state.grid_velocity;
          update_particles(state, monitor, timer);
          evaluate_on_moved_grid(state, timer);
          previous_dt = dt;
          return true;
        }

      private:
        /// Signed length (1D) or area (2D) of cell @p c with vertices at
        /// @p x.
        static double
        signed_measure(const Solver::GridSystem<dim> &grid,
                       const std::vector<Point<dim>> &x,
                       const unsigned int             c)
        {
          return Mesh::signed_measure(vertices(grid, x, c));
        }

        static std::array<Point<dim>, dim + 1>
        vertices(const Solver::GridSystem<dim> &grid,
                 const std::vector<Point<dim>> &x,
                 const unsigned int             c)
        {
          const unsigned int *dofs = &grid.cell_dofs()[c * (dim + 1)];
          std::array<Point<dim>, dim + 1> v;
          for (unsigned int k = 0; k <= dim; ++k)
            v[k] = x[dofs[k]];
          return v;
        }

        /// x_a,k+1 = x_a,k + dt u_a; false (and nothing moved) if a cell
        /// of the OTM grid turns inside out or collapses.
        bool
        move_grid(State<dim>       &state,
                  StabilityMonitor &monitor,
                  PhaseTimer       &timer)
        {
          PhaseTimer::Scope t(timer, "otm grid");
          for (unsigned int i = 0; i < nodes.size(); ++i)
            moved[i] = nodes[i] + state.dt * state.grid_velocity[i];
          for (const unsigned int c : occupied)
            {
              const double measure = signed_measure(*state.grid, moved, c);
              // Inverted (ratio <= 0), or collapsed to round-off: the
              // automatic step follows the cell's height down, so a cell
              // that closes (material squeezed to zero volume) would
              // otherwise be approached in ever smaller steps forever.
              if (!(measure / initial_measure[c] > collapsed_ratio))
                {
                  const auto  v = vertices(*state.grid, moved, c);
                  std::string where;
                  for (unsigned int k = 0; k <= dim; ++k)
                    {
                      where += k > 0 ? ", (" : "(";
                      for (unsigned int d = 0; d < dim; ++d)
                        where += (d > 0 ? ", " : "") + prm_value(v[k][d]);
                      where += ")";
                    }
                  monitor.report(
                    Failure::inverted_cell,
                    "otm: cell " + std::to_string(c) + " of the moving grid " +
                      (measure / initial_measure[c] > 0 ? "collapsed" :
                                                          "inverted") +
                      " (signed " + (dim == 1 ? "length " : "area ") +
                      prm_value(measure) + ", initially " +
                      prm_value(initial_measure[c]) + "; moved vertices " +
                      where + ")");
                  return false;
                }
            }
          std::swap(nodes, moved);
          return true;
        }

        /// Positions by the transport map, velocities from positions,
        /// strain increments on the grid of the step's start.
        void
        update_particles(State<dim>       &state,
                         StabilityMonitor &monitor,
                         PhaseTimer       &timer)
        {
          // v_p = sum_a u_a N_a,k(x_p) = (x_p,k+1 - x_p,k) / dt_k.
          this->template move_and_update_material<
            ParticleLoops::VelocityUpdate::grid>(state, monitor, timer);
        }

        /// The moved grid, the last nodal velocity and step, by global DoF
        /// (a checkpoint written on some ranks resumes on others).
        void
        save(Archive &archive, const State<dim> &state) const override
        {
          const auto         &grid   = *state.grid;
          const auto         &global = grid.relevant_global_indices();
          const auto          n      = state.dof_handler.n_dofs();
          std::vector<double> x(2 * dim * n, 0.), all(2 * dim * n);
          for (unsigned int l = 0; l < global.size(); ++l)
            if (grid.locally_owned_dofs().is_element(global[l]))
              for (unsigned int d = 0; d < dim; ++d)
                {
                  x[global[l] * 2 * dim + d]       = nodes[l][d];
                  x[global[l] * 2 * dim + dim + d] = nodal_velocity[l][d];
                }
          Utilities::MPI::sum(x, state.comm, all);
          archive.put("otm/grid", all, 2 * dim);
          archive.put("otm/previous_dt", previous_dt);
        }

        void
        load(const Archive &archive, State<dim> &state) override
        {
          const auto &global = state.grid->relevant_global_indices();
          const auto &x =
            archive.get("otm/grid", 2 * dim * state.dof_handler.n_dofs());
          for (unsigned int l = 0; l < global.size(); ++l)
            for (unsigned int d = 0; d < dim; ++d)
              {
                nodes[l][d]          = x[global[l] * 2 * dim + d];
                nodal_velocity[l][d] = x[global[l] * 2 * dim + dim + d];
              }
          moved       = nodes;
          previous_dt = archive.get_number("otm/previous_dt");
          // The particles (restored in their cells) on the moved grid.
          PhaseTimer timer(MPI_COMM_SELF, ConditionalOStream(std::cout, false));
          evaluate_on_moved_grid(state, timer);
        }

        /// N_a,k+1 and grad N_a,k+1 at x_p,k+1 on the moved grid.
        void
        evaluate_on_moved_grid(State<dim> &state, PhaseTimer &timer)
        {
          PhaseTimer::Scope t(timer, "otm grid");
          for (const unsigned int c : occupied)
            maps[c] = Mesh::barycentric_map(vertices(*state.grid, nodes, c));
          const auto        &particles = state.particles;
          const unsigned int n         = dim + 1;
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const auto &map = maps[particles.cell[p]];
              const auto  l   = map(particles.position[p]);
              for (unsigned int k = 0; k < n; ++k)
                state.shape_values[p * n + k] = l[k];
              if (!state.gradients_per_cell)
                for (unsigned int k = 0; k < n; ++k)
                  state.shape_gradients[p * n + k] = map.gradient[k];
            }
          // P1 keeps its gradients per cell (State::gradients()).
          if (state.gradients_per_cell)
            for (const unsigned int c : occupied)
              for (unsigned int k = 0; k < n; ++k)
                state.shape_gradients[std::size_t(c) * n + k] =
                  maps[c].gradient[k];
        }

        /// Measure ratio (moved over initial) below which a cell counts
        /// as collapsed: with coordinates O(1) and cells O(0.1) or larger
        /// its measure is then round-off (relative error ~ 1e-16 / h).
        static constexpr double collapsed_ratio = 1e-12;

        const bool split;
        /// Vertex positions x_a,k (and the tentative x_a,k+1), local
        /// relevant DoF numbering.
        std::vector<Point<dim>> nodes, moved;
        /// u of the last step (for the nodal acceleration).
        std::vector<Tensor<1, dim>>        nodal_velocity;
        std::vector<unsigned int>          occupied;
        std::vector<double>                initial_measure;
        std::vector<Mesh::SimplexMap<dim>> maps;
        double                             previous_dt = 0;
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, OTM> register_otm(
      "otm",
      "optimal transportation meshfree update with P1 functions (Wobbes et "
      "al. 2019, Algorithm 1): the grid moves with the nodal increments, "
      "particles keep their cells, positions by the transport map, "
      "velocities from positions (doc/otm.md)",
      &OTM<2>::declare_parameters);
  } // namespace Simulator
} // namespace psmpm
