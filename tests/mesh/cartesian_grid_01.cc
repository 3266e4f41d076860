// ---------------------------------------------------------------------
// psmpm: Mesh::CartesianGrid, the grid that the cell locator and the
// tensor-product B-splines share. On a non-uniform 4 x 3 grid: the lines
// are the distinct vertex coordinates and every cell's position is that
// of its lower corner. Coordinates that differ by less than 1e-12 of the
// span are one line (two squares 1e-14 apart are one grid, 1e-3 apart
// not).
// A mesh of rectangles that is not one tensor-product grid (an L; a
// moved interior vertex) is refused with a message naming Mesh/Type =
// cartesian.
// ---------------------------------------------------------------------
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/mesh/cartesian_grid.h>

#include "../tests.h"

#include <cctype>

namespace
{
  using namespace psmpm;

  void
  make_grid(Triangulation<2> &tria)
  {
    const std::vector<std::vector<double>> steps{{0.3, 0.5, 0.2, 0.4},
                                                 {0.7, 0.25, 0.45}};
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              steps,
                                              Point<2>(-1, 2),
                                              Point<2>(0.4, 3.4));
  }

  /// Whether the grid's lines and positions are those of the cells'
  /// lower and upper corners.
  bool
  matches(const Mesh::CartesianGrid &grid, const Triangulation<2> &tria)
  {
    bool ok = grid.n_cells() == tria.n_active_cells();
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int d = 0; d < 2; ++d)
        {
          const auto  &ij    = grid.position(cell->active_cell_index());
          const auto  &lines = grid.lines(d);
          const double h     = lines.back() - lines.front();
          ok                 = ok && ij[d] + 1 < lines.size() &&
               std::abs(lines[ij[d]] - cell->vertex(0)[d]) <= 1e-12 * h &&
               std::abs(lines[ij[d] + 1] - cell->vertex(3)[d]) <= 1e-12 * h;
        }
    return ok;
  }

  /// The message of the refusal of @p tria, or "accepted".
  std::string
  refusal(const Triangulation<2> &tria)
  {
    Mesh::CartesianGrid grid;
    try
      {
        grid.reinit(tria, "The test");
      }
    catch (const std::exception &e)
      {
        // The message, which deal.II wraps over lines, on one line.
        const std::string what = e.what();
        std::string       message;
        bool              blank = false;
        for (std::size_t i = what.find("The test");
             i < what.size() && what.compare(i, 3, "---") != 0 &&
             what.compare(i, 10, "Stacktrace") != 0;
             ++i)
          if (std::isspace(static_cast<unsigned char>(what[i])))
            blank = true;
          else
            {
              message += (blank ? " " : "") + std::string(1, what[i]);
              blank = false;
            }
        return message;
      }
    return "accepted";
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");

    Triangulation<2> tria;
    make_grid(tria);
    Mesh::CartesianGrid grid;
    grid.reinit(tria, "The test");
    out << "lines: " << grid.lines(0).size() << " x " << grid.lines(1).size()
        << std::endl;
    PSMPM_CHECK(out, matches(grid, tria));

    // Two unit squares that share no vertices, the second shifted by
    // @p gap: within 1e-12 of the span they are one 2 x 1 grid.
    const auto squares = [](Triangulation<2> &t, const double gap) {
      std::vector<Point<2>>    vertices;
      std::vector<CellData<2>> cells(2);
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int v = 0; v < 4; ++v)
          {
            vertices.emplace_back(c * (1 + gap) + (v & 1), v >> 1);
            cells[c].vertices[v] = 4 * c + v;
          }
      t.create_triangulation(vertices, cells, SubCellData());
    };
    Triangulation<2> nearly;
    squares(nearly, 1e-14);
    Mesh::CartesianGrid merged;
    merged.reinit(nearly, "The test");
    out << "lines with a gap of 1e-14: " << merged.lines(0).size() << " x "
        << merged.lines(1).size() << std::endl;
    PSMPM_CHECK(out, matches(merged, nearly));
    Triangulation<2> apart;
    squares(apart, 1e-3);
    out << refusal(apart) << std::endl;

    // Not one tensor-product grid.
    Triangulation<2> l_shape;
    GridGenerator::hyper_L(l_shape);
    out << refusal(l_shape) << std::endl;
    Triangulation<2> moved;
    make_grid(moved);
    for (const auto &cell : moved.active_cell_iterators())
      if (cell->active_cell_index() == 5)
        cell->vertex(3)[0] += 0.05;
    out << refusal(moved) << std::endl;
  });
}
