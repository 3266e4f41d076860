// Block meshes: cell, vertex and boundary face counts, boundary names,
// orientation and total area, for criss-cross and diagonal splits.
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

#include <map>

using namespace psmpm;

void
check(const Mesh::MeshGenerator<2>::Type type,
      const std::string                 &name,
      std::ofstream                     &out)
{
  const unsigned int nx = 5, ny = 3;
  const double       L = 25, H = 2;
  Triangulation<2>   tria;
  Mesh::MeshGenerator<2>::make_blocks(tria,
                                      Point<2>(0, 0),
                                      Point<2>(L, H),
                                      nx,
                                      ny,
                                      type);
  out << name << ": cells " << tria.n_active_cells() << ", vertices "
      << tria.n_vertices() << std::endl;
  const unsigned int per_block =
    type == Mesh::MeshGenerator<2>::Type::criss_cross ? 4 : 2;
  PSMPM_CHECK(out, tria.n_active_cells() == per_block * nx * ny);
  const unsigned int centres =
    type == Mesh::MeshGenerator<2>::Type::criss_cross ? nx * ny : 0;
  PSMPM_CHECK(out, tria.n_vertices() == (nx + 1) * (ny + 1) + centres);

  double                                     area     = 0;
  bool                                       positive = true;
  std::map<types::boundary_id, unsigned int> faces;
  std::map<types::boundary_id, double>       lengths;
  for (const auto &cell : tria.active_cell_iterators())
    {
      area += cell->measure();
      positive = positive && cell->measure() > 0;
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            ++faces[cell->face(f)->boundary_id()];
            lengths[cell->face(f)->boundary_id()] += cell->face(f)->measure();
          }
    }
  PSMPM_CHECK(out, positive);
  PSMPM_CHECK(out, std::abs(area - L * H) < 1e-12 * L * H);
  // left = 0, right = 1, bottom = 2, top = 3
  PSMPM_CHECK(out,
              faces[0] == ny && faces[1] == ny && faces[2] == nx &&
                faces[3] == nx);
  PSMPM_CHECK(out,
              std::abs(lengths[0] - H) < 1e-12 &&
                std::abs(lengths[2] - L) < 1e-12);
  PSMPM_CHECK(out, faces.size() == 4);
}

int
main()
{
  std::ofstream out("output");
  check(Mesh::MeshGenerator<2>::Type::criss_cross, "criss-cross", out);
  check(Mesh::MeshGenerator<2>::Type::diagonal, "diagonal", out);

  // Boundary names of the generator.
  ParameterHandler prm;
  Mesh::MeshGenerator<2>::declare_parameters(prm);
  Mesh::MeshGenerator<2> gen;
  gen.parse_parameters(prm);
  Triangulation<2> tria;
  gen.create(tria);
  for (const auto &n : gen.boundary_names())
    out << "boundary " << n.first << " = " << int(n.second) << std::endl;
  bool threw = false;
  try
    {
      gen.boundary_id("side");
    }
  catch (const std::exception &)
    {
      threw = true;
    }
  PSMPM_CHECK(out, threw);
}
