// ---------------------------------------------------------------------
// psmpm: Mesh::CellLocator on a Cartesian mesh of rectangles (Mesh/Type =
// cartesian) with non-uniform grid lines: every random point of the
// domain is found (from scratch and by the hint of a random other cell)
// in the cell that contains it, by brute force over all cells; points on
// grid lines are found in a cell that contains them; points outside are
// invalid; the smallest side is the time step length; a mesh of
// rectangles that is not a tensor-product grid is refused.
// ---------------------------------------------------------------------
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/cell_locator.h>

#include "../tests.h"

#include <random>

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;
    Triangulation<2>                       tria;
    const std::vector<std::vector<double>> steps{{0.3, 0.5, 0.2, 0.4},
                                                 {0.7, 0.25, 0.45}};
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              steps,
                                              Point<2>(-1, 2),
                                              Point<2>(0.4, 3.4),
                                              true);
    Mesh::CellLocator<2> locator;
    locator.reinit(tria);
    PSMPM_CHECK(out, locator.cartesian());
    PSMPM_CHECK(out, locator.n_cells() == 12);
    out << "minimum height " << locator.minimum_height() << std::endl;

    std::vector<typename Triangulation<2>::active_cell_iterator> cells;
    for (const auto &cell : tria.active_cell_iterators())
      cells.push_back(cell);
    std::mt19937                                rng(7);
    std::uniform_real_distribution<double>      x(-1, 0.4), y(2, 3.4);
    std::uniform_int_distribution<unsigned int> any(0, 11);
    unsigned int                                wrong = 0;
    for (unsigned int i = 0; i < 2000; ++i)
      {
        Point<2> p(x(rng), y(rng));
        // Every 10th point on a grid line of the cell it is drawn in.
        if (i % 10 == 0)
          p[0] = cells[any(rng)]->vertex(1)[0];
        for (const unsigned int c :
             {locator.locate(p), locator.locate(p, any(rng))})
          if (c == Mesh::CellLocator<2>::invalid ||
              !cells[c]->point_inside(p) || !locator.contains(c, p))
            ++wrong;
      }
    out << "points not found in a cell that holds them: " << wrong << std::endl;
    PSMPM_CHECK(out, wrong == 0);
    unsigned int found_outside = 0;
    for (const Point<2> &p : {Point<2>(-1.01, 2.5),
                              Point<2>(0.41, 2.5),
                              Point<2>(0, 1.99),
                              Point<2>(0, 3.41)})
      if (locator.locate(p) != Mesh::CellLocator<2>::invalid ||
          locator.locate(p, 3) != Mesh::CellLocator<2>::invalid)
        ++found_outside;
    PSMPM_CHECK(out, found_outside == 0);

    // An L of three squares has rectangles but is not a tensor grid.
    Triangulation<2> l_shape;
    GridGenerator::hyper_L(l_shape);
    bool refused = false;
    try
      {
        locator.reinit(l_shape);
      }
    catch (const std::exception &e)
      {
        refused = std::string(e.what()).find("Cartesian") != std::string::npos;
      }
    PSMPM_CHECK(out, refused);
  });
}
