// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/mesh/cell_locator.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace psmpm
{
  namespace Mesh
  {
    void
    CellLocator::reinit(const Triangulation<2> &tria)
    {
      const unsigned int n = tria.n_active_cells();
      maps.resize(n);
      neighbors.assign(n, {{invalid, invalid, invalid}});
      min_height = std::numeric_limits<double>::max();

      std::map<std::pair<unsigned int, unsigned int>,
               std::pair<unsigned int, unsigned int>>
                                  edge_owner; // edge -> (cell, local vertex)
      std::vector<BoundingBox<2>> boxes(n);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int            c = cell->active_cell_index();
          const std::array<Point<2>, 3> v{
            {cell->vertex(0), cell->vertex(1), cell->vertex(2)}};
          const double area = signed_area(v);
          AssertThrow(area > 0,
                      ExcMessage("Cell " + std::to_string(c) +
                                 " has non-positive area (clockwise or "
                                 "degenerate triangle)."));
          maps[c] = barycentric_map(v);
          for (unsigned int k = 0; k < 3; ++k)
            {
              min_height =
                std::min(min_height,
                         2 * area / v[(k + 1) % 3].distance(v[(k + 2) % 3]));
              unsigned int a = cell->vertex_index((k + 1) % 3),
                           b = cell->vertex_index((k + 2) % 3);
              const auto key = std::make_pair(std::min(a, b), std::max(a, b));
              const auto it  = edge_owner.find(key);
              if (it == edge_owner.end())
                edge_owner[key] = {c, k};
              else
                {
                  neighbors[c][k] = it->second.first;
                  neighbors[it->second.first][it->second.second] = c;
                }
            }
          boxes[c] = BoundingBox<2>(std::vector<Point<2>>(v.begin(), v.end()));
        }

      // Bucket grid with about one cell per bucket.
      box = boxes[0];
      for (const auto &b : boxes)
        box.merge_with(b);
      box.extend(1e-10 * box.side_length(0) + 1e-10 * box.side_length(1));
      const double aspect = box.side_length(0) / box.side_length(1);
      const double nb     = std::sqrt(static_cast<double>(n));
      n_buckets[0] =
        std::max(1u, static_cast<unsigned int>(nb * std::sqrt(aspect)));
      n_buckets[1] =
        std::max(1u, static_cast<unsigned int>(nb / std::sqrt(aspect)));
      std::vector<std::vector<unsigned int>> buckets(n_buckets[0] *
                                                     n_buckets[1]);
      for (unsigned int c = 0; c < n; ++c)
        {
          const auto lo = bucket_of(boxes[c].get_boundary_points().first);
          const auto hi = bucket_of(boxes[c].get_boundary_points().second);
          for (unsigned int j = lo[1]; j <= hi[1]; ++j)
            for (unsigned int i = lo[0]; i <= hi[0]; ++i)
              buckets[j * n_buckets[0] + i].push_back(c);
        }
      bucket_start.assign(1, 0);
      bucket_cells.clear();
      for (const auto &b : buckets)
        {
          bucket_cells.insert(bucket_cells.end(), b.begin(), b.end());
          bucket_start.push_back(bucket_cells.size());
        }
    }

    std::array<unsigned int, 2>
    CellLocator::bucket_of(const Point<2> &p) const
    {
      std::array<unsigned int, 2> ij;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double s = (p[d] - box.lower_bound(d)) / box.side_length(d);
          const int    i = static_cast<int>(std::floor(s * n_buckets[d]));
          ij[d]          = static_cast<unsigned int>(
            std::clamp(i, 0, static_cast<int>(n_buckets[d]) - 1));
        }
      return ij;
    }

    unsigned int
    CellLocator::locate(const Point<2> &p) const
    {
      if (!box.point_inside(p))
        return invalid;
      const auto         ij = bucket_of(p);
      const unsigned int b  = ij[1] * n_buckets[0] + ij[0];
      for (unsigned int i = bucket_start[b]; i < bucket_start[b + 1]; ++i)
        if (contains(bucket_cells[i], p))
          return bucket_cells[i];
      return invalid;
    }

    unsigned int
    CellLocator::locate(const Point<2> &p, const unsigned int hint) const
    {
      unsigned int cell = hint;
      // A walk in a convex mesh needs at most as many steps as cells it
      // crosses; bound it and fall back to the bucket search.
      for (unsigned int step = 0; step < 64; ++step)
        {
          const auto   l = maps[cell](p);
          unsigned int k = 0;
          if (l[1] < l[k])
            k = 1;
          if (l[2] < l[k])
            k = 2;
          if (l[k] >= -tolerance)
            return cell;
          const unsigned int next = neighbors[cell][k];
          if (next == invalid)
            break;
          cell = next;
        }
      return locate(p);
    }
  } // namespace Mesh
} // namespace psmpm
