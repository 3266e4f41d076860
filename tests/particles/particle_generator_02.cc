// Particles at mesh vertices: an odd number of particles per block of a
// criss-cross mesh puts one exactly where the block's diagonals cross,
// a vertex shared by four triangles. Every particle must be placed (in
// one of the cells that hold it) on a mesh whose bucket search lines run
// through those vertices (80 x 80 blocks of the unit square), and on a
// small one.
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>

#include "../tests.h"

using namespace psmpm;

void
check(const unsigned int blocks,
      const unsigned int per_block,
      std::ofstream     &out)
{
  ParameterHandler prm;
  Mesh::MeshGenerator<2>::declare_parameters(prm);
  Particles::ParticleGenerator<2>::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  prm.set("Length", "1");
  prm.set("Height", "1");
  prm.leave_subsection();
  prm.enter_subsection("Mesh");
  prm.set("Type", "criss-cross");
  prm.set("Blocks x", std::to_string(blocks));
  prm.set("Blocks y", std::to_string(blocks));
  prm.leave_subsection();
  prm.enter_subsection("Particles");
  prm.set("Per block x", std::to_string(per_block));
  prm.set("Per block y", std::to_string(per_block));
  prm.leave_subsection();

  Mesh::MeshGenerator<2> mesh;
  mesh.parse_parameters(prm);
  Particles::ParticleGenerator<2> generator;
  generator.parse_parameters(prm);
  Triangulation<2> tria;
  mesh.create(tria);
  Mesh::CellLocator<2> locator;
  locator.reinit(tria);

  Particles::ParticleSet<2> particles;
  generator.generate(
    mesh,
    tria,
    locator,
    1.0,
    [](unsigned int) { return true; },
    particles);
  double volume = 0, worst = 0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    {
      volume += particles.volume[p];
      const auto l =
        locator.barycentric(particles.cell[p], particles.position[p]);
      worst = std::max(worst, -std::min({l[0], l[1], l[2]}));
    }
  out << blocks << " x " << blocks << " blocks, " << per_block << " x "
      << per_block << " per block: " << particles.size() << " particles"
      << std::endl;
  PSMPM_CHECK(out,
              particles.size() ==
                std::size_t(blocks) * blocks * per_block * per_block);
  // Summation round-off of n volumes 1 / n.
  PSMPM_CHECK(out, std::abs(volume - 1) < 1e-15 * particles.size());
  // Inside its cell up to the round-off of the barycentric coordinates
  // (about |x| / h times 1e-16: 1.1e-12 at the block centres of 80 x 80
  // blocks).
  PSMPM_CHECK(out, worst <= 1e-10);
}

int
main()
{
  std::ofstream out("output");
  check(8, 3, out);
  check(80, 3, out);
  check(80, 5, out);
  check(7, 1, out);
}
