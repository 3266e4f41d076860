// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>

#include <psmpm/mesh/cell_locator.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

namespace psmpm
{
  namespace Mesh
  {
    namespace
    {
      template <int dim>
      std::string
      orientation_error(const unsigned int cell)
      {
        return "Cell " + std::to_string(cell) +
               (dim == 2 ? " has non-positive area (clockwise or "
                           "degenerate triangle)." :
                           " has non-positive length (reversed or "
                           "degenerate line).");
      }
    } // namespace

    template <int dim>
    void
    CellLocator<dim>::reinit(const Triangulation<dim> &tria)
    {
      quads = dim == 2 && tria.n_active_cells() > 0 &&
              tria.begin_active()->reference_cell() ==
                ReferenceCells::get_hypercube<dim>();
      if (quads)
        set_up_cartesian(tria);
      else
        set_up_search(set_up_cells(tria));
      // A distributed mesh: each rank sees its part (the same answer on a
      // replicated one).
      if (const auto *par =
            dynamic_cast<const parallel::TriangulationBase<dim> *>(&tria))
        min_height = Utilities::MPI::min(min_height, par->get_communicator());
    }

    template <int dim>
    void
    CellLocator<dim>::set_up_cartesian(const Triangulation<dim> &tria)
    {
      // reinit() comes here for 2D meshes of quadrilaterals only.
      if constexpr (dim == 2)
        {
          grid.reinit(tria, "CellLocator");
          const unsigned int n  = tria.n_active_cells();
          const unsigned int nx = grid.lines(0).size() - 1;
          boxes.resize(n);
          maps.clear();
          neighbors.clear();
          cell_at.assign(n, invalid);
          min_height = std::numeric_limits<double>::max();
          for (const auto &cell : tria.active_cell_iterators())
            {
              const unsigned int c  = cell->active_cell_index();
              const Point<dim>   lo = cell->vertex(0);
              const Point<dim>   hi =
                cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
              for (unsigned int d = 0; d < dim; ++d)
                min_height = std::min(min_height, hi[d] - lo[d]);
              const auto &ij              = grid.position(c);
              cell_at[ij[1] * nx + ij[0]] = c;
              boxes[c]                    = {{lo, hi}};
            }
        }
      else
        {
          (void)tria;
          Assert(false, ExcInternalError());
        }
    }

    template <int dim>
    unsigned int
    CellLocator<dim>::search_cartesian(const Point<dim> &p) const
    {
      unsigned int at = 0, stride = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto  &lines  = grid.lines(d);
          const double margin = tolerance * (lines.back() - lines.front());
          if (!(p[d] >= lines.front() - margin &&
                p[d] <= lines.back() + margin))
            return invalid;
          // The last line at or left of p starts its cell (clamped: the
          // upper end belongs to the last cell).
          const std::size_t i =
            std::upper_bound(lines.begin(), lines.end(), p[d]) - lines.begin();
          at += stride * static_cast<unsigned int>(
                           std::clamp<std::size_t>(i, 1, lines.size() - 1) - 1);
          stride *= lines.size() - 1;
        }
      return cell_at[at];
    }

    template <int dim>
    std::vector<BoundingBox<dim>>
    CellLocator<dim>::set_up_cells(const Triangulation<dim> &tria)
    {
      const unsigned int n = tria.n_active_cells();
      maps.resize(n);
      std::array<unsigned int, dim + 1> none;
      none.fill(invalid);
      neighbors.assign(n, none);
      min_height = std::numeric_limits<double>::max();

      // Face (sorted vertex indices) -> (cell, local vertex opposite it).
      std::map<std::array<unsigned int, dim>,
               std::pair<unsigned int, unsigned int>>
                                    face_owner;
      std::vector<BoundingBox<dim>> boxes(n);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int              c = cell->active_cell_index();
          std::array<Point<dim>, dim + 1> v;
          for (unsigned int k = 0; k <= dim; ++k)
            v[k] = cell->vertex(k);
          const double measure = signed_measure(v);
          AssertThrow(measure > 0, ExcMessage(orientation_error<dim>(c)));
          maps[c]    = barycentric_map(v);
          min_height = std::min(min_height, Mesh::minimum_height(v));
          for (unsigned int k = 0; k <= dim; ++k)
            {
              std::array<unsigned int, dim> key;
              for (unsigned int j = 0; j < dim; ++j)
                key[j] = cell->vertex_index((k + 1 + j) % (dim + 1));
              std::sort(key.begin(), key.end());
              const auto it = face_owner.find(key);
              if (it == face_owner.end())
                face_owner[key] = {c, k};
              else
                {
                  neighbors[c][k] = it->second.first;
                  neighbors[it->second.first][it->second.second] = c;
                }
            }
          boxes[c] =
            BoundingBox<dim>(std::vector<Point<dim>>(v.begin(), v.end()));
        }
      return boxes;
    }

    template <int dim>
    void
    CellLocator<dim>::set_up_search(const std::vector<BoundingBox<dim>> &boxes)
    {
      const unsigned int n = boxes.size();
      box                  = boxes[0];
      for (const auto &b : boxes)
        box.merge_with(b);
      if constexpr (dim == 1)
        {
          box.extend(1e-10 * box.side_length(0));
          // A line mesh needs no buckets: its cells sorted by their left
          // ends make a binary search, however graded the mesh.
          bucket_cells.resize(n);
          std::iota(bucket_cells.begin(), bucket_cells.end(), 0u);
          std::stable_sort(bucket_cells.begin(),
                           bucket_cells.end(),
                           [&boxes](const unsigned int a,
                                    const unsigned int b) {
                             return boxes[a].lower_bound(0) <
                                    boxes[b].lower_bound(0);
                           });
          lower_ends.resize(n);
          for (unsigned int i = 0; i < n; ++i)
            lower_ends[i] = boxes[bucket_cells[i]].lower_bound(0);
        }
      else
        {
          // Bucket grid with about one cell per bucket.
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
    }

    template <int dim>
    std::array<unsigned int, dim>
    CellLocator<dim>::bucket_of(const Point<dim> &p) const
    {
      std::array<unsigned int, dim> ij;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double s = (p[d] - box.lower_bound(d)) / box.side_length(d);
          const int    i = static_cast<int>(std::floor(s * n_buckets[d]));
          ij[d]          = static_cast<unsigned int>(
            std::clamp(i, 0, static_cast<int>(n_buckets[d]) - 1));
        }
      return ij;
    }

    template <int dim>
    unsigned int
    CellLocator<dim>::search(const Point<dim> &p) const
    {
      if constexpr (dim == 1)
        {
          // The last cell starting at or left of p holds it, unless p is
          // within round-off left of the next cell's start.
          const std::size_t j =
            std::upper_bound(lower_ends.begin(), lower_ends.end(), p[0]) -
            lower_ends.begin();
          if (j > 0 && contains(bucket_cells[j - 1], p))
            return bucket_cells[j - 1];
          if (j < bucket_cells.size() && contains(bucket_cells[j], p))
            return bucket_cells[j];
          return invalid;
        }
      else
        {
          const auto         ij = bucket_of(p);
          const unsigned int b  = ij[1] * n_buckets[0] + ij[0];
          for (unsigned int i = bucket_start[b]; i < bucket_start[b + 1]; ++i)
            if (contains(bucket_cells[i], p))
              return bucket_cells[i];
          return nearest_within_round_off(p, b);
        }
    }

    template <int dim>
    unsigned int
    CellLocator<dim>::nearest_within_round_off(const Point<dim>  &p,
                                               const unsigned int bucket) const
    {
      // lambda_k = constant_k + gradient_k . p loses the digits of
      // |constant_k| ~ |p| / h: far from the origin, relative to the cell
      // size h, a point at a vertex shared by several cells (the centre of
      // a criss-cross block with an odd number of particles per block,
      // 80 x 80 blocks of the unit square) can lie 1e-12 outside each of
      // them. It belongs to the one it is least outside of if that is
      // within this round-off. Reached only where the 1e-12 test found no
      // cell, so every point found before keeps its cell.
      unsigned int best       = invalid;
      double       best_ratio = -1;
      if constexpr (dim == 1)
        (void)p, (void)bucket; // a line's map is relative to its vertices
      else
        for (unsigned int i = bucket_start[bucket];
             i < bucket_start[bucket + 1];
             ++i)
          {
            const unsigned int c     = bucket_cells[i];
            const auto         l     = maps[c](p);
            double             ratio = 0; // largest -lambda_k / its round-off
            for (unsigned int k = 0; k <= dim; ++k)
              {
                double scale = 1 + std::abs(maps[c].constant[k]);
                for (unsigned int d = 0; d < dim; ++d)
                  scale += std::abs(maps[c].gradient[k][d] * p[d]);
                ratio = std::max(ratio, -l[k] / (tolerance * scale));
              }
            if (ratio <= 1 && (best == invalid || ratio < best_ratio))
              {
                best       = c;
                best_ratio = ratio;
              }
          }
      return best;
    }

    template <int dim>
    unsigned int
    CellLocator<dim>::locate(const Point<dim> &p) const
    {
      if (quads)
        return search_cartesian(p);
      if (!box.point_inside(p))
        return invalid;
      return search(p);
    }

    template <int dim>
    unsigned int
    CellLocator<dim>::walk(const Point<dim> &p, const unsigned int hint) const
    {
      if (quads)
        return contains(hint, p) ? hint : search_cartesian(p);
      unsigned int cell = hint;
      // A walk in a convex mesh needs at most as many steps as cells it
      // crosses; bound it and fall back to the search from scratch.
      for (unsigned int step = 0; step < 64; ++step)
        {
          const auto   l = maps[cell](p);
          unsigned int k = 0;
          for (unsigned int j = 1; j <= dim; ++j)
            if (l[j] < l[k])
              k = j;
          if (l[k] >= -tolerance)
            return cell;
          const unsigned int next = neighbors[cell][k];
          if (next == invalid)
            break;
          cell = next;
        }
      return locate(p);
    }

    template class CellLocator<1>;
    template class CellLocator<2>;
  } // namespace Mesh
} // namespace psmpm
