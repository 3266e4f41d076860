// ---------------------------------------------------------------------
// psmpm: Powell-Sabin spaces on meshes with obtuse and sliver triangles
// build a valid (non-negative, C1, partition of unity) space; a mesh with
// a degenerate (zero-area) triangle is rejected with an error that names
// the vertices and their coordinates instead of building garbage.
// ---------------------------------------------------------------------
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "ps_checks.h"

namespace
{
  /// Unit square split into four triangles around p (near the bottom).
  void
  fan(Triangulation<2> &tria, const Point<2> &p)
  {
    const std::vector<Point<2>> vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, p};
    std::vector<CellData<2>>    cells;
    for (const auto &v : std::vector<std::array<unsigned int, 3>>{{{0, 1, 4}},
                                                                  {{1, 2, 4}},
                                                                  {{2, 3, 4}},
                                                                  {{3, 0, 4}}})
      {
        CellData<2> c(3);
        c.vertices = {v[0], v[1], v[2]};
        cells.push_back(c);
      }
    tria.create_triangulation(vertices, cells, SubCellData());
  }

  void
  build_and_check(std::ostream &out, Triangulation<2> &tria)
  {
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    try
      {
        ps.reinit(dof_handler);
        ps_checks::check_space(out, dof_handler, ps);
      }
    catch (const std::exception &e)
      {
        // The message without deal.II's file and line decoration.
        // deal.II wraps the message over several lines: join them.
        const std::string what  = e.what();
        const auto        begin = what.find("Powell-Sabin");
        const auto        end   = what.find("\n\n", begin);
        std::string       message;
        for (const char c : what.substr(begin, end - begin))
          if (c == '\n' || c == ' ')
            {
              if (message.empty() || message.back() != ' ')
                message += ' ';
            }
          else
            message += c;
        out << "error: " << message << std::endl;
      }
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    for (const double y : {0.02, 1e-4})
      {
        out << "fan around (0.5, " << y << "): obtuse sliver on the bottom edge"
            << std::endl;
        Triangulation<2> tria;
        fan(tria, Point<2>(0.5, y));
        build_and_check(out, tria);
      }

    out << "diagonal mesh with strongly perturbed interior vertices"
        << std::endl;
    {
      Triangulation<2> tria;
      psmpm::Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(1, 1),
        6,
        6,
        psmpm::Mesh::MeshGenerator<2>::Type::diagonal);
      // Deterministic pseudo-random shifts of up to 0.4 h.
      std::vector<bool> moved(tria.n_vertices(), false);
      for (const auto &cell : tria.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int v = cell->vertex_index(k);
            Point<2>          &p = cell->vertex(k);
            if (moved[v] || p[0] < 1e-12 || p[0] > 1 - 1e-12 || p[1] < 1e-12 ||
                p[1] > 1 - 1e-12)
              continue;
            moved[v] = true;
            p[0] += 0.4 / 6 * std::sin(12.9898 * v);
            p[1] += 0.4 / 6 * std::cos(78.233 * v);
          }
      unsigned int n_obtuse = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (unsigned int k = 0; k < 3; ++k)
          n_obtuse += (cell->vertex((k + 1) % 3) - cell->vertex(k)) *
                        (cell->vertex((k + 2) % 3) - cell->vertex(k)) <
                      0;
      out << "obtuse triangles: " << n_obtuse << std::endl;
      build_and_check(out, tria);
    }

    out << "fan around (0.5, 0): a zero-area triangle" << std::endl;
    {
      Triangulation<2> tria;
      fan(tria, Point<2>(0.5, 0));
      build_and_check(out, tria);
    }
  });
}
