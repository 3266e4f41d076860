// The locator finds the triangle that contains a point (checked against
// a brute-force barycentric search), by walking from any start cell and
// by the bucket search, and reports points outside the mesh.
#include <deal.II/base/function_lib.h>

#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

#include <random>

using namespace psmpm;

int
main()
{
  std::ofstream out("output");
  for (const auto type : {Mesh::MeshGenerator<2>::Type::criss_cross,
                          Mesh::MeshGenerator<2>::Type::diagonal})
    {
      Triangulation<2> tria;
      Mesh::MeshGenerator<2>::make_blocks(tria,
                                          Point<2>(0, 0),
                                          Point<2>(25, 2),
                                          16,
                                          3,
                                          type);
      Mesh::CellLocator<2> locator;
      locator.reinit(tria);

      std::mt19937                                rng(42);
      std::uniform_real_distribution<double>      ux(0, 25), uy(0, 2);
      std::uniform_int_distribution<unsigned int> uc(0, locator.n_cells() - 1);
      unsigned int wrong_walk = 0, wrong_bucket = 0;
      for (unsigned int i = 0; i < 2000; ++i)
        {
          const Point<2> p(ux(rng), uy(rng));
          unsigned int   brute = Mesh::CellLocator<2>::invalid;
          for (unsigned int c = 0; c < locator.n_cells(); ++c)
            if (locator.contains(c, p))
              brute = c;
          const unsigned int walk   = locator.locate(p, uc(rng));
          const unsigned int bucket = locator.locate(p);
          wrong_walk += !(walk != Mesh::CellLocator<2>::invalid &&
                          locator.contains(walk, p) &&
                          brute != Mesh::CellLocator<2>::invalid);
          wrong_bucket += !(bucket != Mesh::CellLocator<2>::invalid &&
                            locator.contains(bucket, p));
        }
      out << "wrong walks " << wrong_walk << ", wrong bucket searches "
          << wrong_bucket << std::endl;
      PSMPM_CHECK(out, wrong_walk == 0 && wrong_bucket == 0);
      PSMPM_CHECK(out,
                  locator.locate(Point<2>(25.5, 1.0), 0) ==
                    Mesh::CellLocator<2>::invalid);
      PSMPM_CHECK(out,
                  locator.locate(Point<2>(3.0, -0.01)) ==
                    Mesh::CellLocator<2>::invalid);
      // Smallest height: criss-cross blocks 25/16 x 2/3; diagonal likewise.
      out << "minimum height " << locator.minimum_height() << std::endl;
    }
}
