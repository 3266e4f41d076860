// Regular per-block layout (thesis Sec. 4.1): counts, positions at the
// centres of the sub-grid, volumes summing to the area, mass = rho V,
// every particle inside its cell; and the per-cell layout of Gmsh meshes.
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>

#include "../tests.h"

using namespace psmpm;

void
report(const Particles::ParticleSet<2> &particles,
       const Mesh::CellLocator<2>      &locator,
       const double                     area,
       const double                     density,
       std::ofstream                   &out)
{
  double volume = 0, mass = 0, worst = 0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    {
      volume += particles.volume[p];
      mass += particles.mass[p];
      const auto l =
        locator.barycentric(particles.cell[p], particles.position[p]);
      worst = std::max(worst, -std::min({l[0], l[1], l[2]}));
    }
  out << "particles " << particles.size() << std::endl;
  PSMPM_CHECK(out, std::abs(volume - area) < 1e-12 * area);
  PSMPM_CHECK(out, std::abs(mass - density * area) < 1e-12 * density * area);
  PSMPM_CHECK(out, worst <= 1e-12);
}

int
main()
{
  std::ofstream    out("output");
  ParameterHandler prm;
  Mesh::MeshGenerator<2>::declare_parameters(prm);
  Particles::ParticleGenerator<2>::declare_parameters(prm);
  prm.enter_subsection("Mesh");
  prm.set("Blocks x", "3");
  prm.set("Blocks y", "2");
  prm.leave_subsection();
  prm.enter_subsection("Particles");
  prm.set("Per block x", "4");
  prm.set("Per block y", "3");
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
    2.0,
    [](unsigned int) { return true; },
    particles);
  report(particles, locator, 25 * 2, 2.0, out);
  PSMPM_CHECK(out, particles.size() == 3 * 2 * 4 * 3);
  // First particle: centre of the first sub-cell of block (0, 0).
  const double hx = 25. / 3, hy = 1.;
  PSMPM_CHECK(out,
              particles.position[0].distance(Point<2>(hx / 8, hy / 6)) < 1e-12);
  PSMPM_CHECK(out, std::abs(particles.volume[0] - hx * hy / 12) < 1e-12);
  // Ids are unique.
  std::set<std::uint64_t> ids(particles.id.begin(), particles.id.end());
  PSMPM_CHECK(out, ids.size() == particles.size());

  // Region: only the left half holds material.
  prm.enter_subsection("Particles");
  prm.set("Region", "0, 0, 12.5, 2");
  prm.leave_subsection();
  generator.parse_parameters(prm);
  Particles::ParticleSet<2> half;
  generator.generate(
    mesh,
    tria,
    locator,
    2.0,
    [](unsigned int) { return true; },
    half);
  out << "particles in left half " << half.size() << std::endl;

  // Per-cell layout on a diagonal mesh (as used for Gmsh meshes).
  Triangulation<2> tri2;
  Mesh::MeshGenerator<2>::make_blocks(tri2,
                                      Point<2>(0, 0),
                                      Point<2>(1, 1),
                                      3,
                                      3,
                                      Mesh::MeshGenerator<2>::Type::diagonal);
  Mesh::CellLocator<2> loc2;
  loc2.reinit(tri2);
  Mesh::MeshGenerator<2> gmsh_like = mesh;
  gmsh_like.type                   = Mesh::MeshGenerator<2>::Type::gmsh;
  Particles::ParticleSet<2> per_cell;
  generator.region.clear();
  generator.per_cell = 3;
  generator.generate(
    gmsh_like,
    tri2,
    loc2,
    1.0,
    [](unsigned int) { return true; },
    per_cell);
  report(per_cell, loc2, 1.0, 1.0, out);
  PSMPM_CHECK(out, per_cell.size() == 18 * 9);
}
