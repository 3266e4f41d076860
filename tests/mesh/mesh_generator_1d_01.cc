// 1D meshes: Blocks x equal lines on [0, Length] with boundary ids left = 0
// and right = 1, Mesh/Type gmsh refused, Height ignored; and the 1D cell
// locator: walks and searches from scratch (checked against a brute-force
// search), points on element boundaries and at the ends of the domain,
// points outside, graded meshes and meshes whose cells are not numbered
// left to right.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

#include <algorithm>
#include <map>
#include <random>

using namespace psmpm;

using Locator = Mesh::CellLocator<1>;

/// Whether parsing @p prm throws with a message that contains @p entry.
bool
parse_fails_naming(ParameterHandler &prm, const std::string &entry)
{
  Mesh::MeshGenerator<1> gen;
  try
    {
      gen.parse_parameters(prm);
    }
  catch (const std::exception &e)
    {
      return std::string(e.what()).find(entry) != std::string::npos;
    }
  return false;
}

/// Number of points among @p points that the walk from a random hint and
/// the search from scratch place in a cell that does not contain them, or
/// that the brute-force search finds but they do not.
unsigned int
wrong_locations(const Locator &locator, const std::vector<double> &points)
{
  std::mt19937                                rng(7);
  std::uniform_int_distribution<unsigned int> uc(0, locator.n_cells() - 1);
  unsigned int                                wrong = 0;
  for (const double x : points)
    {
      const Point<1> p(x);
      bool           inside = false;
      for (unsigned int c = 0; c < locator.n_cells(); ++c)
        inside = inside || locator.contains(c, p);
      const unsigned int walk    = locator.locate(p, uc(rng));
      const unsigned int scratch = locator.locate(p);
      for (const unsigned int c : {walk, scratch})
        wrong += inside ? (c == Locator::invalid || !locator.contains(c, p)) :
                          (c != Locator::invalid);
    }
  return wrong;
}

/// Random points in [a, b] plus all vertices of @p tria.
std::vector<double>
test_points(const Triangulation<1> &tria, const double a, const double b)
{
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> ux(a, b);
  std::vector<double>                    points;
  for (unsigned int i = 0; i < 2000; ++i)
    points.push_back(ux(rng));
  for (const auto &v : tria.get_vertices())
    points.push_back(v[0]);
  return points;
}

void
check_generator(std::ofstream &out)
{
  ParameterHandler prm;
  Mesh::MeshGenerator<1>::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  prm.set("Length", "2.5");
  prm.set("Height", "-1"); // ignored in 1D
  prm.leave_subsection();
  prm.enter_subsection("Mesh");
  prm.set("Blocks x", "10");
  prm.set("Blocks y", "3"); // ignored in 1D
  prm.set("Type", "diagonal");
  prm.leave_subsection();

  Mesh::MeshGenerator<1> gen;
  gen.parse_parameters(prm);
  Triangulation<1> tria;
  gen.create(tria);
  out << "cells " << tria.n_active_cells() << ", vertices " << tria.n_vertices()
      << std::endl;
  PSMPM_CHECK(out, tria.n_active_cells() == gen.blocks_x);

  double                                 length = 0, shortest = 1e300;
  double                                 longest = 0;
  std::map<types::boundary_id, Point<1>> ends;
  for (const auto &cell : tria.active_cell_iterators())
    {
      length += cell->measure();
      shortest = std::min(shortest, cell->measure());
      longest  = std::max(longest, cell->measure());
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          ends[cell->face(f)->boundary_id()] = cell->face(f)->center();
    }
  PSMPM_CHECK(out, std::abs(length - gen.length) < 1e-12 * gen.length);
  PSMPM_CHECK(out, longest - shortest < 1e-12 * gen.length);
  PSMPM_CHECK(out, ends.size() == 2);
  PSMPM_CHECK(out,
              std::abs(ends[gen.boundary_id("left")][0]) < 1e-12 &&
                std::abs(ends[gen.boundary_id("right")][0] - gen.length) <
                  1e-12);
  for (const auto &n : gen.boundary_names())
    out << "boundary " << n.first << " = " << int(n.second) << std::endl;
  bool threw = false;
  try
    {
      gen.boundary_id("top");
    }
  catch (const std::exception &)
    {
      threw = true;
    }
  PSMPM_CHECK(out, threw);

  // Errors name the entry at fault.
  prm.enter_subsection("Geometry");
  prm.set("Length", "0");
  prm.leave_subsection();
  PSMPM_CHECK(out, parse_fails_naming(prm, "Geometry/Length"));
  prm.enter_subsection("Geometry");
  prm.set("Length", "2.5");
  prm.leave_subsection();
  prm.enter_subsection("Mesh");
  prm.set("Type", "gmsh");
  prm.leave_subsection();
  PSMPM_CHECK(out, parse_fails_naming(prm, "Mesh/Type"));
}

void
check_locator(const std::string      &name,
              const Triangulation<1> &tria,
              const double            a,
              const double            b,
              std::ofstream          &out)
{
  Locator locator;
  locator.reinit(tria);
  double shortest = 1e300;
  for (const auto &cell : tria.active_cell_iterators())
    shortest = std::min(shortest, cell->measure());
  out << name << ": cells " << locator.n_cells() << std::endl;
  PSMPM_CHECK(out,
              std::abs(locator.minimum_height() - shortest) <=
                1e-14 * shortest);

  // Inside, on every vertex, and on both sides of the domain.
  const double pad = 0.1 * (b - a);
  out << "wrong locations "
      << wrong_locations(locator, test_points(tria, a - pad, b + pad))
      << std::endl;

  unsigned int ends_found = 0, outside_found = 0;
  for (unsigned int hint = 0; hint < locator.n_cells(); ++hint)
    {
      ends_found += locator.locate(Point<1>(a), hint) != Locator::invalid;
      ends_found += locator.locate(Point<1>(b), hint) != Locator::invalid;
      outside_found +=
        locator.locate(Point<1>(a - 1e-6 * (b - a)), hint) != Locator::invalid;
      outside_found +=
        locator.locate(Point<1>(b + 1e-6 * (b - a)), hint) != Locator::invalid;
    }
  PSMPM_CHECK(out, ends_found == 2 * locator.n_cells());
  PSMPM_CHECK(out, outside_found == 0);
  PSMPM_CHECK(out,
              locator.locate(Point<1>(a - 1e-6 * (b - a))) ==
                  Locator::invalid &&
                locator.locate(Point<1>(b + 1e-6 * (b - a))) ==
                  Locator::invalid);

  // Barycentric coordinates: 1 and 0 at the vertices, partition of unity.
  double worst_vertex = 0, worst_sum = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      const unsigned int c = cell->active_cell_index();
      for (unsigned int v = 0; v < 2; ++v)
        {
          const auto l = locator.barycentric(c, cell->vertex(v));
          worst_vertex =
            std::max({worst_vertex, std::abs(l[v] - 1), std::abs(l[1 - v])});
        }
      const auto l = locator.barycentric(c, Point<1>(0.3 * a + 0.7 * b));
      worst_sum    = std::max(worst_sum, std::abs(l[0] + l[1] - 1));
    }
  PSMPM_CHECK(out, worst_vertex < 1e-14 && worst_sum < 1e-12);
}

int
main()
{
  std::ofstream out("output");
  check_generator(out);

  // The generator's mesh, long enough that walks from far away give up
  // and fall back to the binary search.
  {
    ParameterHandler prm;
    Mesh::MeshGenerator<1>::declare_parameters(prm);
    prm.enter_subsection("Mesh");
    prm.set("Blocks x", "200");
    prm.leave_subsection();
    Mesh::MeshGenerator<1> gen;
    gen.parse_parameters(prm);
    Triangulation<1> tria;
    gen.create(tria);
    check_locator("uniform", tria, 0, gen.length, out);
  }

  // A graded mesh away from the origin.
  {
    std::vector<double> steps;
    for (unsigned int i = 0; i < 30; ++i)
      steps.push_back(1e-3 * std::pow(1.3, i));
    double total = 0;
    for (const double s : steps)
      total += s;
    Triangulation<1> tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {steps},
                                              Point<1>(1e3),
                                              Point<1>(1e3 + total));
    check_locator("graded", tria, 1e3, 1e3 + total, out);
  }

  // Cells numbered in random order: the search must not rely on it.
  {
    const unsigned int       n = 50;
    std::vector<Point<1>>    vertices;
    std::vector<CellData<1>> cells;
    for (unsigned int i = 0; i <= n; ++i)
      vertices.emplace_back(-1.0 + 2.0 * i / n);
    std::vector<unsigned int> order(n);
    for (unsigned int i = 0; i < n; ++i)
      order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    for (const unsigned int i : order)
      {
        CellData<1> cell;
        cell.vertices = {i, i + 1};
        cells.push_back(cell);
      }
    Triangulation<1> tria;
    tria.create_triangulation(vertices, cells, SubCellData());
    PSMPM_CHECK(out, tria.begin_active()->vertex(0)[0] != -1.0);
    check_locator("shuffled", tria, -1, 1, out);
  }
}
