// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/mesh/cartesian_grid.h>

#include <algorithm>

namespace psmpm
{
  namespace Mesh
  {
    void
    CartesianGrid::reinit(const Triangulation<2> &tria, const std::string &user)
    {
      clear();
      const std::string not_cartesian =
        user + " needs a Cartesian mesh (axis-parallel rectangles on one "
               "tensor-product grid of lines, Mesh/Type = cartesian)";
      AssertThrow(tria.all_reference_cells_are_hyper_cube(),
                  ExcMessage(not_cartesian + "; the mesh has triangles."));
      const unsigned int    n = tria.n_active_cells();
      std::array<double, 2> margin{};
      for (unsigned int d = 0; d < 2; ++d)
        {
          auto &lines = grid_lines[d];
          for (const auto &v : tria.get_vertices())
            lines.push_back(v[d]);
          std::sort(lines.begin(), lines.end());
          margin[d] =
            lines.empty() ? 0. : tolerance * (lines.back() - lines.front());
          lines.erase(std::unique(lines.begin(),
                                  lines.end(),
                                  [m = margin[d]](const double a,
                                                  const double b) {
                                    return b - a <= m;
                                  }),
                      lines.end());
        }
      // The grid line of coordinate x: the first line not left of x by
      // more than the margin.
      const auto line_of = [&](const unsigned int d, const double x) {
        return static_cast<unsigned int>(std::lower_bound(grid_lines[d].begin(),
                                                          grid_lines[d].end(),
                                                          x - margin[d]) -
                                         grid_lines[d].begin());
      };
      const unsigned int nx =
        std::max<std::size_t>(grid_lines[0].size(), 1) - 1;
      const unsigned int ny =
        std::max<std::size_t>(grid_lines[1].size(), 1) - 1;
      AssertThrow(nx * ny == n,
                  ExcMessage(not_cartesian + "; " + std::to_string(n) +
                             " cells on " + std::to_string(nx) + " x " +
                             std::to_string(ny) + " grid lines."));
      positions.resize(n);
      // Each grid rectangle holds one cell.
      std::vector<bool> taken(n, false);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int c  = cell->active_cell_index();
          const Point<2>     lo = cell->vertex(0);
          const Point<2>     hi = cell->vertex(3);
          bool               ok = true;
          for (unsigned int d = 0; d < 2; ++d)
            {
              const unsigned int i = line_of(d, lo[d]);
              ok                   = ok && i + 1 < grid_lines[d].size() &&
                   line_of(d, hi[d]) == i + 1;
              positions[c][d] = i;
            }
          // Every vertex on a corner of the box (lexicographic order).
          for (unsigned int v = 0; ok && v < cell->n_vertices(); ++v)
            for (unsigned int d = 0; d < 2; ++d)
              ok = ok && cell->vertex(v)[d] == (((v >> d) & 1) ? hi[d] : lo[d]);
          const unsigned int at =
            ok ? positions[c][1] * nx + positions[c][0] : 0;
          AssertThrow(ok && !taken[at],
                      ExcMessage(not_cartesian + "; cell " + std::to_string(c) +
                                 " is not one of its rectangles."));
          taken[at] = true;
        }
    }

    void
    CartesianGrid::clear()
    {
      for (auto &lines : grid_lines)
        lines.clear();
      positions.clear();
    }
  } // namespace Mesh
} // namespace psmpm
