// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/grid_system.h>
#include <psmpm/solver/mass_strategies/poorly_supported.h>

#include <limits>
#include <set>

namespace psmpm
{
  namespace Solver
  {
    template <int dim>
    PoorlySupported<dim>::PoorlySupported(const double threshold,
                                          const bool   extrapolate)
      : threshold(threshold)
      , extrapolate(extrapolate)
    {
    }

    template <int dim>
    std::vector<bool>
    PoorlySupported<dim>::poorly_supported_vertices(
      const GridSystem<dim>     &grid,
      const std::vector<double> &diagonal) const
    {
      // Hysteresis: a vertex that was poorly supported stays so until its
      // support has doubled past the bound, so that particles hovering at
      // the bound do not switch the discrete space back and forth.
      const auto       &tables = grid.vertex_tables();
      const auto       &full   = grid.full_support_diagonal();
      std::vector<bool> outer(tables.dofs.size(), false);
      for (unsigned int v = 0; v < tables.dofs.size(); ++v)
        {
          const double bound =
            threshold *
            (!previous_outer.empty() && previous_outer[v] ? 2. : 1.);
          for (const unsigned int l : tables.dofs[v])
            if (l != numbers::invalid_unsigned_int &&
                diagonal[l] < bound * full[l])
              outer[v] = true;
        }
      return outer;
    }

    template <int dim>
    unsigned int
    PoorlySupported<dim>::nearest_supported_vertex(
      const GridSystem<dim>   &grid,
      const std::vector<bool> &outer,
      const unsigned int       v) const
    {
      // Search ring by ring, at most four rings out.
      const auto &vertices =
        grid.get_dof_handler().get_triangulation().get_vertices();
      const auto               &neighbors = grid.vertex_tables().neighbors;
      unsigned int              from      = numbers::invalid_unsigned_int;
      std::vector<unsigned int> ring      = {v};
      std::set<unsigned int>    seen      = {v};
      for (unsigned int layer = 0;
           layer < 4 && from == numbers::invalid_unsigned_int;
           ++layer)
        {
          std::vector<unsigned int> next;
          for (const unsigned int a : ring)
            for (const unsigned int b : neighbors[a])
              if (seen.insert(b).second)
                next.push_back(b);
          double best = std::numeric_limits<double>::max();
          for (const unsigned int b : next)
            if (!outer[b] && vertices[b].distance(vertices[v]) < best)
              best = vertices[b].distance(vertices[v]), from = b;
          ring = next;
        }
      return from;
    }

    template <int dim>
    std::vector<double>
    PoorlySupported<dim>::history() const
    {
      return std::vector<double>(previous_outer.begin(), previous_outer.end());
    }

    template <int dim>
    void
    PoorlySupported<dim>::restore_history(const std::vector<double> &history)
    {
      // A vertex that this rank does not see (no relevant DoF) was
      // false here in the run that wrote the checkpoint: prepare() never
      // reads its flag.
      previous_outer.assign(history.size(), false);
      for (std::size_t v = 0; v < history.size(); ++v)
        previous_outer[v] = history[v] > 0;
      restored = true;
    }

    template <int dim>
    bool
    PoorlySupported<dim>::prepare(GridSystem<dim>           &grid,
                                  const std::vector<double> &diagonal)
    {
      const std::vector<bool> outer = poorly_supported_vertices(grid, diagonal);
      if (outer == previous_outer && !restored)
        return false;
      previous_outer = outer;
      restored       = false;

      const auto  &tables    = grid.vertex_tables();
      const auto  &global    = grid.relevant_global_indices();
      const auto  &space     = grid.get_space();
      unsigned int n_treated = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto               &dirichlet = grid.dirichlet_constraints(d);
          AffineConstraints<double> step(grid.relevant_dofs());
          for (unsigned int v = 0; v < outer.size(); ++v)
            {
              if (!outer[v])
                continue;
              const unsigned int from =
                extrapolate ? nearest_supported_vertex(grid, outer, v) :
                              numbers::invalid_unsigned_int;
              FullMatrix<double> W;
              if (from != numbers::invalid_unsigned_int)
                W = space.extrapolation_weights(from, v);
              for (unsigned int q = 0; q < tables.dofs_per_vertex; ++q)
                {
                  const unsigned int l = tables.dofs[v][q];
                  if (l == numbers::invalid_unsigned_int)
                    continue;
                  const auto g = global[l];
                  if (dirichlet.is_constrained(g) || step.is_constrained(g))
                    continue;
                  step.add_line(g);
                  ++n_treated;
                  if (from != numbers::invalid_unsigned_int)
                    for (unsigned int r = 0; r < tables.dofs_per_vertex; ++r)
                      if (std::abs(W(q, r)) > 1e-14)
                        step.add_entry(g,
                                       global[tables.dofs[from][r]],
                                       W(q, r));
                }
            }
          step.merge(dirichlet,
                     AffineConstraints<double>::left_object_wins,
                     true);
          step.close();
          grid.set_constraints(d, step);
        }
      grid.set_n_treated_dofs(n_treated / dim);
      return true;
    }

    template class PoorlySupported<1>;
    template class PoorlySupported<2>;
  } // namespace Solver
} // namespace psmpm
