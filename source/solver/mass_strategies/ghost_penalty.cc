// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_strategies/cell_fill.h>
#include <psmpm/solver/mass_strategy.h>
#include <psmpm/solver/polynomial_complement.h>
#include <psmpm/solver/symmetric_3x3.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Whether cap_fill_by_sampling() acts: P1 (its closed form), a
      /// target, a density and the particle mass blocks.
      template <int dim>
      bool
      caps_fill(const GridSystem<dim> &grid, const double target)
      {
        return target > 0 && grid.reference_density() > 0 &&
               grid.dofs_per_cell == dim + 1 &&
               !grid.cell_arrays().mass.empty();
      }

      /**
       * The fill of each owned P1 cell that holds particles, capped at
       * lambda / @p target: lambda the smallest eigenvalue of the cell's
       * particle mass block relative to its exact one, E^-1/2 M_c E^-1/2 /
       * rho, E = |c| / ((d + 1)(d + 2)) (I + 1 1^T). A cell's particles can
       * fill it by volume and still leave a linear field unseen: one
       * particle (rank one), or particles on a line, which is where the
       * particles of a block with 2 x 2 of them sit on a criss-cross mesh.
       * Counted as filled, such a cell got no ghost penalty, its functions
       * were free, and free bodies with 2 x 2 or 3 x 2 particles per block
       * blew up within a few steps at any time step (doc/stability.md,
       * "Sampling of P1 cells"). The penalty is zero on affine fields, so
       * a rigid rotation is still reproduced exactly. Well sampled cells
       * keep their fill (lambda >= t fill: 8 x 8 and 16 x 14 particles per
       * block). Only with P1 (3
       * functions: the closed-form eigenvalues; Powell-Sabin has the
       * sampling stabilisation) and @p target > 0 (Mass matrix/Sampling
       * stabilization, 0.5 with Type = automatic).
       */
      template <int dim>
      void
      cap_fill_by_sampling(const GridSystem<dim>     &grid,
                           const std::vector<double> &measure,
                           const double               target,
                           double                    *fill)
      {
        constexpr unsigned int n    = dim + 1;
        const auto            &mass = grid.cell_arrays().mass;
        const double           rho  = grid.reference_density();
        Assert(caps_fill(grid, target), ExcInternalError());
        // E^-1/2 = k^-1/2 (I + alpha 1 1^T): (I + alpha 1 1^T)^2 must be
        // (I + 1 1^T)^-1 = I - 1 1^T / (n + 1).
        const double alpha = (-1. + std::sqrt(1. / (n + 1))) / n;
        for (const unsigned int c : grid.owned_cells())
          {
            if (!(fill[c] > 0))
              continue;
            const double *M = &mass[c * n * n];
            // W M W with W = I + alpha 1 1^T: M + alpha (r 1^T + 1 r^T)
            // + alpha^2 s 1 1^T, r the row sums, s their sum.
            double r[n] = {}, sum = 0;
            for (unsigned int k = 0; k < n; ++k)
              {
                for (unsigned int l = 0; l < n; ++l)
                  r[k] += M[k * n + l];
                sum += r[k];
              }
            const double scale   = n * (n + 1) / (measure[c] * rho);
            double       A[3][3] = {};
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int l = 0; l < n; ++l)
                A[k][l] = scale * (M[k * n + l] + alpha * (r[k] + r[l]) +
                                   alpha * alpha * sum);
            // Only lambda < t fill lowers the fill: the LDL^T screen spares
            // the well-sampled cells the closed form's acos and cos.
            if (n == 3 && !has_eigenvalue_below(A, target * fill[c]))
              continue;
            const double lambda =
              n == 3 ?
                smallest_eigenvalue(A) :
                0.5 * (A[0][0] + A[1][1]) -
                  std::sqrt(0.25 * (A[0][0] - A[1][1]) * (A[0][0] - A[1][1]) +
                            A[0][1] * A[0][1]);
            fill[c] = std::min(fill[c], std::max(lambda, 0.) / target);
          }
      }

      /**
       * Volume ghost penalty (local projection stabilisation, Burman) of
       * the particle mass matrix: for every pair of cells c, K that share
       * a vertex, both holding particles and one not filled,
       *
       *   S_cK(u, v) = gamma rho (1 - min(fill_c, fill_K))
       *                int_{c u K} (u - P u)(v - P v),
       *
       * P the L2 projection onto the polynomials of the space's degree on
       * the pair c u K, for pairs of which both cells hold particles
       * (gamma: Mass matrix/Stabilization; fill: particle
       * mass over rho |cell|, clipped to [0, 1], on P1 with a sampling
       * target capped by the particles' sampling of the cell:
       * cap_fill_by_sampling()). S vanishes for every
       * polynomial of that degree (the space reproduces them), so
       *  - constants: row sums, hence momentum, are those of the particle
       *    matrix;
       *  - affine fields (rigid rotation): the projection of an affine
       *    particle velocity stays exact, as with the consistent matrix;
       *  - filled cells: S = 0, the consistent matrix exactly.
       * What S controls is the deviation of a function on a sparse cell
       * from the polynomial that its well filled neighbour fixes, so a
       * function whose support holds a single particle at its edge is no
       * longer free: the matrix stays symmetric positive definite with a
       * bounded condition number. Pairs across a vertex, not only across
       * a face, because a particle can enter an empty cell through a
       * vertex (criss-cross meshes). Pair matrices depend on the mesh only
       * and are computed once; each step only weights them.
       */
      template <int dim>
      class GhostPenalty : public MassStrategy<dim>
      {
      public:
        bool
        needs_neighbor_couplings() const override
        {
          return true;
        }

        /// The pair matrices vanish for polynomials of the initial pair;
        /// on a grid moved non-affinely across the pair they penalise
        /// the affine fields of the current configuration.
        bool
        depends_on_cell_shape() const override
        {
          return true;
        }

        bool
        prepare(GridSystem<dim> &grid, const std::vector<double> &) override
        {
          const double gamma = grid.strategy_parameters().stabilization;
          if (gamma == 0)
            return false;
          if (!paired)
            find_pairs(grid);
          // fill decides which cells hold particles, sampled (fill capped
          // by the particles' sampling of the linear fields, where
          // caps_fill()) the weights: both in one reduction.
          const double target =
            grid.strategy_parameters().sampling_stabilization;
          std::vector<double> local = cell_fill(grid, measure);
          const unsigned int  n_c   = local.size();
          const bool          cap   = caps_fill(grid, target);
          if (cap)
            {
              local.resize(2 * n_c);
              std::copy(local.begin(),
                        local.begin() + n_c,
                        local.begin() + n_c);
              cap_fill_by_sampling(grid, measure, target, local.data() + n_c);
            }
          // The pairs reach the cells sharing a vertex with an owned one.
          std::vector<double> &fill = local;
          grid.cell_exchange().owners_to_neighbours(fill.data());
          if (cap)
            grid.cell_exchange().owners_to_neighbours(fill.data() + n_c);
          const double *sampled = fill.data() + (cap ? n_c : 0);
          const double  rho     = grid.reference_density();
          active_faces.clear();
          for (unsigned int i = 0; i < faces.size(); ++i)
            {
              const Face  &f = faces[i];
              const double w =
                gamma * rho *
                (1. - std::min(sampled[f.cells[0]], sampled[f.cells[1]]));
              if (!(w > 0))
                continue;
              // Both cells hold particles: the pair's polynomial is fixed
              // by them (a pair of a filled and an empty cell would make
              // the empty cell's functions follow a polynomial through
              // nothing). All DoFs of the pair take part, also those
              // without particle mass (a Powell-Sabin function can vanish
              // at every particle of a cell it lives on): they follow the
              // polynomial extension.
              if (!(fill[f.cells[0]] > 0 && fill[f.cells[1]] > 0))
                continue;
              active_faces.emplace_back(i, w);
            }
          compute_pair_patches(grid);
          std::vector<bool> treated(grid.lumped_mass().size(), false);
          for (const auto &[i, w] : active_faces)
            add_block(grid, pair_pool, faces[i], w, treated);
          penalize_lone_cells(grid, fill.data(), sampled, treated);
          unsigned int n_treated = 0;
          const auto  &global    = grid.relevant_global_indices();
          for (unsigned int l = 0; l < treated.size(); ++l)
            n_treated +=
              treated[l] && grid.locally_owned_dofs().is_element(global[l]);
          grid.set_n_treated_dofs(
            Utilities::MPI::sum(n_treated, grid.get_communicator()));
          return false;
        }

      private:
        struct Face;
        struct PatchPool;

        /// Adds @p f's block with weight @p w to the grid's patch blocks
        /// (its slots recomputed when the sparsity changed) and marks its
        /// DoFs as treated.
        static void
        add_block(GridSystem<dim>   &grid,
                  PatchPool         &pool,
                  Face              &f,
                  const double       w,
                  std::vector<bool> &treated)
        {
          const unsigned int *dofs  = &pool.dofs[f.first_dof];
          int                *slots = &pool.slots[f.first_value];
          if (f.generation != grid.sparsity_generation())
            {
              f.has_slots  = grid.patch_slots(dofs, f.n, slots);
              f.generation = grid.sparsity_generation();
            }
          typename GridSystem<dim>::PatchBlock b;
          b.dofs   = dofs;
          b.n      = f.n;
          b.values = &pool.values[f.first_value];
          b.weight = w;
          b.slots  = f.has_slots ? slots : nullptr;
          grid.patch_blocks().push_back(b);
          for (unsigned int k = 0; k < f.n; ++k)
            treated[dofs[k]] = true;
        }

        /**
         * A cell that holds particles while no cell sharing a vertex with
         * it does (a single particle, a fragment of a body) gets no pair:
         * nothing fixes its polynomial, and the particle mass matrix of
         * fewer than three particles is singular on it (P1: rank one for
         * one particle). The consistent solve then fails to converge, or
         * makes up a velocity gradient that strains the lone particle. Such
         * a cell gets gamma rho (1 - fill) int_c (u - P0 u)(v - P0 v), P0
         * the mean over the cell: a free particle moves with its grid
         * velocity constant over the cell, exactly as with lumped mass
         * (constants are untouched: momentum kept). Decided from the
         * particle fill of the cell and its vertex neighbours only, so the
         * same on any number of ranks; no cell of a body whose every cell
         * touches another one that holds particles is affected.
         */
        void
        penalize_lone_cells(GridSystem<dim>   &grid,
                            const double      *fill,
                            const double      *sampled,
                            std::vector<bool> &treated)
        {
          const double gamma = grid.strategy_parameters().stabilization;
          const double rho   = grid.reference_density();
          lone_now.clear();
          for (const unsigned int c : grid.owned_cells())
            {
              const double w = gamma * rho * (1. - sampled[c]);
              if (!(fill[c] > 0 && w > 0))
                continue;
              bool alone = true;
              for (const unsigned int k : neighbours[c])
                alone = alone && !(fill[k] > 0);
              if (alone)
                lone_now.emplace_back(c, w);
            }
          if (lone_now.empty())
            return;
          compute_lone_patches(grid);
          for (const auto &[c, w] : lone_now)
            add_block(grid, lone_pool, lone[c], w, treated);
        }

        /// The patches of the cells in lone_now that have none yet: their
        /// DoFs and the complement of the constants on each.
        void
        compute_lone_patches(const GridSystem<dim> &grid)
        {
          const auto                          &dh = grid.get_dof_handler();
          const unsigned int                   n  = grid.dofs_per_cell;
          std::vector<types::global_dof_index> dofs(n);
          std::vector<unsigned int>            identity(n), patch(n);
          for (unsigned int k = 0; k < n; ++k)
            identity[k] = k;
          for (const auto &cw : lone_now)
            {
              const unsigned int c = cw.first;
              if (lone[c].n > 0)
                continue;
              const auto &cell = cell_iterators[c];
              cell->get_dof_indices(dofs);
              for (unsigned int k = 0; k < n; ++k)
                patch[k] = grid.relevant_dofs().index_within_set(dofs[k]);
              lone[c].cells = {{c, c}};
              lone_pool.append(lone[c],
                               patch,
                               polynomial_complement(grid.get_space(),
                                                     dh,
                                                     {c},
                                                     {identity},
                                                     n,
                                                     0,
                                                     cell->center(),
                                                     cell->diameter()));
            }
        }

        /// A patch: its cells and where its data lies in a PatchPool.
        struct Face
        {
          std::array<unsigned int, 2> cells;
          unsigned int                n           = 0; ///< its DoFs
          std::size_t                 first_dof   = 0;
          std::size_t                 first_value = 0;
          /// Whether the pool holds the value-array positions of its
          /// entries (GridSystem::patch_slots) for the sparsity of
          /// @p generation.
          bool         has_slots  = false;
          unsigned int generation = 0;
        };

        /**
         * The patches' DoFs (local relevant, unique), their matrices
         * int (u - Pu)(v - Pv) (n x n, row-major) and the entries' value
         * slots, each in one array in the order of the patches. A step
         * reads every patch of a body that is not filled (about 12 per
         * triangle); with a vector per patch these reads went to as many
         * scattered heap blocks, and the ghost penalty's assembly took
         * most of P1's free-body step on the throughput bar.
         */
        struct PatchPool
        {
          std::vector<unsigned int> dofs;
          std::vector<double>       values;
          std::vector<int>          slots;

          void
          append(Face                            &f,
                 const std::vector<unsigned int> &patch_dofs,
                 const FullMatrix<double>        &S)
          {
            f.n           = patch_dofs.size();
            f.first_dof   = dofs.size();
            f.first_value = values.size();
            dofs.insert(dofs.end(), patch_dofs.begin(), patch_dofs.end());
            values.insert(values.end(), &S(0, 0), &S(0, 0) + f.n * f.n);
            slots.resize(values.size(), -1);
          }
        };

        /// The pairs of cells sharing a vertex, one of them owned (each
        /// pair once over all ranks: the rank of the smaller subdomain),
        /// and every cell's neighbours. Their matrices are computed when
        /// a step first needs them (compute_pair_patches()): only pairs
        /// with a cell that is not filled, both holding particles, ever
        /// get a block, and on a mesh larger than the body most pairs
        /// never do.
        void
        find_pairs(const GridSystem<dim> &grid)
        {
          const auto &dh = grid.get_dof_handler();
          cell_iterators.resize(grid.n_cells);
          for (const auto &cell : dh.active_cell_iterators())
            cell_iterators[cell->active_cell_index()] = cell;
          // Sorted and unique: the order of std::set, without a node per
          // pair.
          std::vector<std::pair<unsigned int, unsigned int>> pairs;
          for (const auto &around : grid.vertex_tables().cells)
            for (const unsigned int a : around)
              for (const unsigned int b : around)
                if (a < b)
                  pairs.emplace_back(a, b);
          std::sort(pairs.begin(), pairs.end());
          pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
          neighbours.assign(grid.n_cells, {});
          lone.resize(grid.n_cells);
          const unsigned int rank =
            Utilities::MPI::this_mpi_process(grid.get_communicator());
          for (const auto &[a, b] : pairs)
            {
              neighbours[a].push_back(b);
              neighbours[b].push_back(a);
              const auto &cell  = cell_iterators[a];
              const auto &other = cell_iterators[b];
              if (!cell->is_locally_owned() && !other->is_locally_owned())
                continue;
              if (cell->is_locally_owned() != other->is_locally_owned() &&
                  std::min(cell->subdomain_id(), other->subdomain_id()) != rank)
                continue;
              Face face;
              face.cells = {{a, b}};
              faces.push_back(face);
            }
          paired = true;
        }

        /// The matrices of the pairs in active_faces that have none yet,
        /// appended to pair_pool before any of this step's blocks points
        /// into it.
        void
        compute_pair_patches(const GridSystem<dim> &grid)
        {
          const auto                          &space = grid.get_space();
          const auto                          &dh    = grid.get_dof_handler();
          const auto                          &rel   = grid.relevant_dofs();
          std::vector<types::global_dof_index> dofs(grid.dofs_per_cell);
          // Reused from pair to pair.
          std::vector<unsigned int>              pair_cells(2), patch_dofs;
          std::vector<std::vector<unsigned int>> map(2);
          std::vector<types::global_dof_index>   patch;
          for (const auto &iw : active_faces)
            {
              Face &face = faces[iw.first];
              if (face.n > 0)
                continue;
              const auto &cell  = cell_iterators[face.cells[0]];
              const auto &other = cell_iterators[face.cells[1]];
              // Patch DoFs and, per cell, the map cell DoF -> patch.
              patch.clear();
              for (unsigned int s = 0; s < 2; ++s)
                {
                  map[s].clear();
                  (s == 0 ? cell : other)->get_dof_indices(dofs);
                  for (const auto g : dofs)
                    {
                      auto it = std::find(patch.begin(), patch.end(), g);
                      map[s].push_back(it - patch.begin());
                      if (it == patch.end())
                        patch.push_back(g);
                    }
                }
              patch_dofs.clear();
              for (const auto g : patch)
                patch_dofs.push_back(rel.index_within_set(g));
              // Polynomials centred between the cells, scaled by them.
              const Point<dim> x0 = (cell->center() + other->center()) / 2.;
              const double h = std::max(cell->diameter(), other->diameter());
              pair_cells     = {face.cells[0], face.cells[1]};
              pair_pool.append(face,
                               patch_dofs,
                               polynomial_complement(space,
                                                     dh,
                                                     pair_cells,
                                                     map,
                                                     patch.size(),
                                                     space.degree(),
                                                     x0,
                                                     h));
            }
        }

        /// Whether find_pairs() has run.
        bool              paired = false;
        std::vector<Face> faces;
        PatchPool         pair_pool;
        /// The faces that get a block this step, and their weights.
        std::vector<std::pair<unsigned int, double>> active_faces;
        /// By active cell index.
        std::vector<typename DoFHandler<dim>::active_cell_iterator>
                            cell_iterators;
        std::vector<double> measure;
        /// The cells sharing a vertex with each cell.
        std::vector<std::vector<unsigned int>> neighbours;
        /// Patches of lone cells (penalize_lone_cells()), by cell; empty
        /// until a cell is alone.
        std::vector<Face> lone;
        PatchPool         lone_pool;
        /// The lone cells of this step and their weights.
        std::vector<std::pair<unsigned int, double>> lone_now;
      };
    } // namespace

    RegisterForDims<MassStrategyRegistry, GhostPenalty> register_ghost_penalty(
      "ghost penalty",
      "consistent particle mass plus gamma rho (1 - fill) int (u - Pu)^2 on "
      "each pair of cells sharing a vertex, one not filled (P: "
      "polynomials of the space's degree on the pair; gamma = "
      "Stabilization); exact for polynomials, momentum kept");
  } // namespace Solver
} // namespace psmpm
