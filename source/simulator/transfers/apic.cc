// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/transfer_scheme.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /**
       * Affine Particle-In-Cell (Jiang et al. 2015) for any space, with the
       * space's control points X_i (sum_i X_i N_i(x) = x) in place of the
       * grid nodes. Each particle carries v(x) = v_p + C_p (x - x_p):
       *
       * - P2G: lumped (and, for matrix strategies, consistent) mass, grid
       *   momentum sum_p m_p N_ip (v_p + C_p (X_i - x_p)), solve for v_i;
       *   forces, solve for a_i; v_i += dt a_i.
       * - G2P: v_p = sum_i N_ip v_i, C_p = B_p D_p^{-1} with
       *   B_p = sum_i N_ip v_i (X_i - x_p)^T and
       *   D_p = sum_i N_ip (X_i - x_p)(X_i - x_p)^T.
       *
       * With lumped mass an affine v is carried exactly and angular
       * momentum (including the particles' affine part) is conserved,
       * because G2P then P2G is the identity on affine fields. D_p is
       * singular where the particle's weights sit on a line (P1: a particle
       * on an edge, and every particle at a vertex); in the directions where
       * D_p has no support the velocity gradient L_p = sum_i v_i grad N_ip
       * stands in (equal to C_p for affine fields, so exactness is kept).
       */
      template <int dim>
      class APIC : public TransferScheme<dim>
      {
      public:
        bool
        step(State<dim>       &state,
             StabilityMonitor &monitor,
             TimerOutput      &timer) override
        {
          update_control_points(state);
          particles_to_grid(state, timer);
          if (!solve(state, state.grid_velocity, monitor, timer))
            return false;
          forces_to_grid(state, timer);
          if (!solve(state, state.grid_acceleration, monitor, timer))
            return false;
          for (std::size_t l = 0; l < state.grid_velocity.size(); ++l)
            state.grid_velocity[l] += state.dt * state.grid_acceleration[l];
          grid_to_particles(state, monitor, timer);
          return true;
        }

      private:
        static bool
        solve(State<dim>                  &state,
              std::vector<Tensor<1, dim>> &solution,
              StabilityMonitor            &monitor,
              TimerOutput                 &timer)
        {
          try
            {
              TimerOutput::Scope t(timer, "solve");
              state.grid->solve(solution);
            }
          catch (const SolverControl::NoConvergence &e)
            {
              monitor.report(Failure::solver,
                             "mass matrix solver did not converge (" +
                               std::to_string(e.last_step) +
                               " iterations, residual " +
                               prm_value(e.last_residual) + ")");
              return false;
            }
          return true;
        }

        /// The control points in local relevant numbering; they depend only
        /// on the mesh and the DoF numbering, so they are computed again
        /// only if the relevant DoFs change (a strategy may widen them).
        void
        update_control_points(const State<dim> &state)
        {
          const auto &global = state.grid->relevant_global_indices();
          if (control_points.size() == global.size() && !global.empty())
            return;
          const std::vector<Point<dim>> all =
            state.space->control_points(state.dof_handler);
          control_points.resize(global.size());
          for (std::size_t l = 0; l < global.size(); ++l)
            control_points[l] = all[global[l]];
        }

        void
        particles_to_grid(State<dim> &state, TimerOutput &timer) const
        {
          TimerOutput::Scope t(timer, "particle to grid");
          auto              &grid = *state.grid;
          grid.zero_cell_mass();
          grid.zero_cell_rhs();
          const auto         &particles  = state.particles;
          const unsigned int  n          = grid.dofs_per_cell;
          const unsigned int *dofs       = grid.cell_dofs().data();
          auto               &cells      = grid.cell_arrays();
          const bool          consistent = !cells.mass.empty();
          double             *lumped     = cells.lumped.data();
          double             *mass_mat   = cells.mass.data();
          Tensor<1, dim>     *rhs        = cells.rhs.data();
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int    base = particles.cell[p] * n;
              const double          m    = particles.mass[p];
              const Point<dim>     &x    = particles.position[p];
              const Tensor<1, dim> &v    = particles.velocity[p];
              const Tensor<2, dim> &C    = particles.affine[p];
              const double         *phi  = &state.shape_values[p * n];
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double mk = m * phi[k];
                  lumped[base + k] += mk;
                  rhs[base + k] +=
                    mk * (v + C * (control_points[dofs[base + k]] - x));
                  if (consistent)
                    {
                      double *row = mass_mat + (base + k) * n;
                      for (unsigned int l = 0; l < n; ++l)
                        row[l] += mk * phi[l];
                    }
                }
            }
          grid.assemble_mass();
        }

        static void
        forces_to_grid(State<dim> &state, TimerOutput &timer)
        {
          TimerOutput::Scope t(timer, "particle to grid");
          auto              &grid = *state.grid;
          grid.zero_cell_rhs();
          const auto     &particles = state.particles;
          const unsigned  n         = grid.dofs_per_cell;
          Tensor<1, dim> *rhs       = grid.cell_arrays().rhs.data();
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int             base = particles.cell[p] * n;
              const double                   V    = particles.volume[p];
              const SymmetricTensor<2, dim> &s    = particles.stress[p];
              const Tensor<1, dim> external = particles.mass[p] * state.gravity;
              const double        *phi      = &state.shape_values[p * n];
              const Tensor<1, dim> *grad    = &state.shape_gradients[p * n];
              for (unsigned int k = 0; k < n; ++k)
                rhs[base + k] += phi[k] * external - V * (s * grad[k]);
            }
        }

        /**
         * C = B D^{-1} on the eigendirections of D with support, L on the
         * others. "Support" is relative to the trace of D, the particle's
         * squared spread of control points, so the test is scale-free.
         */
        static Tensor<2, dim>
        affine_matrix(const Tensor<2, dim>          &B,
                      const SymmetricTensor<2, dim> &D,
                      const Tensor<2, dim>          &L)
        {
          const double   threshold = 1e-3;
          const double   scale     = trace(D);
          Tensor<2, dim> C;
          if (!(scale > 0))
            return L;
          for (const auto &[lambda, e] : eigenvectors(D))
            {
              const Tensor<1, dim> Ce =
                lambda > threshold * scale ? (B * e) / lambda : L * e;
              C += outer_product(Ce, e);
            }
          return C;
        }

        void
        grid_to_particles(State<dim>       &state,
                          StabilityMonitor &monitor,
                          TimerOutput      &timer)
        {
          TimerOutput::Scope  t(timer, "grid to particle");
          auto               &particles = state.particles;
          const unsigned int  n         = state.grid->dofs_per_cell;
          const unsigned int *dofs      = state.grid->cell_dofs().data();
          const double        dt        = state.dt;
          increments.resize(particles.size());
          volume_ratio.resize(particles.size());
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              const unsigned int      base = particles.cell[p] * n;
              const Point<dim>       &x    = particles.position[p];
              const double           *phi  = &state.shape_values[p * n];
              const Tensor<1, dim>   *grad = &state.shape_gradients[p * n];
              Tensor<1, dim>          v;
              Tensor<2, dim>          B, L; // L_ij = dv_i/dx_j
              SymmetricTensor<2, dim> D;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const unsigned int    l  = dofs[base + k];
                  const Tensor<1, dim> &vk = state.grid_velocity[l];
                  const Tensor<1, dim>  r  = control_points[l] - x;
                  v += phi[k] * vk;
                  B += phi[k] * outer_product(vk, r);
                  D += phi[k] * symmetrize(outer_product(r, r));
                  L += outer_product(vk, grad[k]);
                }
              particles.velocity[p]   = v;
              particles.affine[p]     = affine_matrix(B, D, L);
              increments[p]           = dt * L;
              const Tensor<1, dim> du = dt * v;
              particles.displacement[p] += du;
              particles.position[p] += du;
            }
          state.material->update(particles.size(),
                                 increments.data(),
                                 particles.stress.data(),
                                 particles.state.data(),
                                 volume_ratio.data());
          for (std::size_t p = 0; p < particles.size(); ++p)
            {
              particles.volume[p] *= volume_ratio[p];
              particles.density[p] /= volume_ratio[p];
              if (!(particles.volume[p] > 0))
                monitor.report(Failure::non_positive_volume,
                               "non-positive particle volume (particle " +
                                 std::to_string(particles.id[p]) + ")");
            }
        }

        std::vector<Point<dim>> control_points; ///< local relevant numbering
        // Per-step scratch, kept to avoid reallocation.
        std::vector<Tensor<2, dim>> increments;
        std::vector<double>         volume_ratio;
      };
    } // namespace

    RegisterForDims<TransferSchemeRegistry, APIC> register_apic(
      "apic",
      "affine particle-in-cell (Jiang et al. 2015) with the space's control "
      "points: carries affine velocity fields, conserves angular momentum "
      "with lumped mass");
  } // namespace Simulator
} // namespace psmpm
