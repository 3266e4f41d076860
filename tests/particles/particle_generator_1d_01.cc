// 1D particles: Per block x particles per element at the centres of equal
// sub-intervals, volumes (lengths) summing to the length of the domain,
// mass = rho V, every particle inside its cell, the Region x0, x1, ids that
// do not depend on how cells are shared among ranks, and the errors of the
// 1D Region and of Maximum number.
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>

#include "../tests.h"

#include <set>

using namespace psmpm;

/// Whether @p f throws an exception whose message contains @p text.
template <typename F>
bool
throws_naming(F &&f, const std::string &text)
{
  try
    {
      f();
    }
  catch (const std::exception &e)
    {
      return std::string(e.what()).find(text) != std::string::npos;
    }
  return false;
}

int
main()
{
  std::ofstream    out("output");
  ParameterHandler prm;
  Mesh::MeshGenerator<1>::declare_parameters(prm);
  Particles::ParticleGenerator<1>::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  prm.set("Length", "2.5");
  prm.leave_subsection();
  prm.enter_subsection("Mesh");
  prm.set("Blocks x", "5");
  prm.leave_subsection();
  prm.enter_subsection("Particles");
  prm.set("Per block x", "4");
  prm.leave_subsection();

  Mesh::MeshGenerator<1> mesh;
  mesh.parse_parameters(prm);
  Particles::ParticleGenerator<1> generator;
  generator.parse_parameters(prm);
  Triangulation<1> tria;
  mesh.create(tria);
  Mesh::CellLocator<1> locator;
  locator.reinit(tria);

  const double              density = 3.0;
  const auto                all     = [](unsigned int) { return true; };
  Particles::ParticleSet<1> particles;
  generator.generate(mesh, tria, locator, density, all, particles);
  out << "particles " << particles.size() << std::endl;
  const unsigned int n = mesh.blocks_x * generator.per_block_x;
  PSMPM_CHECK(out, particles.size() == n);

  const double L = mesh.length, h = L / mesh.blocks_x;
  double       volume = 0, mass = 0, worst_inside = 0, worst_position = 0;
  double       worst_volume = 0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    {
      volume += particles.volume[p];
      mass += particles.mass[p];
      const auto l =
        locator.barycentric(particles.cell[p], particles.position[p]);
      worst_inside = std::max(worst_inside, -std::min(l[0], l[1]));
      // Particle k sits at the centre of the k-th of n equal intervals.
      const double k = particles.id[p];
      worst_position =
        std::max(worst_position,
                 std::abs(particles.position[p][0] - (k + 0.5) * L / n));
      worst_volume =
        std::max(worst_volume, std::abs(particles.volume[p] - L / n));
    }
  PSMPM_CHECK(out, std::abs(volume - L) < 1e-12 * L);
  PSMPM_CHECK(out, std::abs(mass - density * L) < 1e-12 * density * L);
  PSMPM_CHECK(out, worst_inside <= 1e-12);
  PSMPM_CHECK(out, worst_position < 1e-12 * L && worst_volume < 1e-12 * L);
  PSMPM_CHECK(out,
              particles.position[0].distance(
                Point<1>(h / (2 * generator.per_block_x))) < 1e-12);
  std::set<std::uint64_t> ids(particles.id.begin(), particles.id.end());
  PSMPM_CHECK(out, ids.size() == particles.size());

  // Ids do not depend on how the cells are shared: two "ranks" by parity.
  std::set<std::uint64_t> shared;
  for (const unsigned int rank : {0u, 1u})
    {
      Particles::ParticleSet<1> mine;
      generator.generate(
        mesh,
        tria,
        locator,
        density,
        [rank](unsigned int c) { return c % 2 == rank; },
        mine);
      for (std::size_t p = 0; p < mine.size(); ++p)
        shared.insert(mine.id[p]);
    }
  PSMPM_CHECK(out, shared == ids);

  // Region x0, x1: the particles with centres in [0.5, 1.5].
  prm.enter_subsection("Particles");
  prm.set("Region", "0.5, 1.5");
  prm.leave_subsection();
  generator.parse_parameters(prm);
  Particles::ParticleSet<1> part;
  generator.generate(mesh, tria, locator, density, all, part);
  unsigned int expected = 0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    expected +=
      particles.position[p][0] >= 0.5 && particles.position[p][0] <= 1.5;
  out << "particles in [0.5, 1.5] " << part.size() << std::endl;
  PSMPM_CHECK(out, part.size() == expected && expected > 0);

  // 1D Region errors.
  for (const std::string region : {"0, 0, 1, 1", "1.5, 0.5"})
    {
      prm.enter_subsection("Particles");
      prm.set("Region", region);
      prm.leave_subsection();
      out << "Region = " << region << ": ";
      PSMPM_CHECK(out,
                  throws_naming([&]() { generator.parse_parameters(prm); },
                                "Particles/Region"));
    }
  prm.enter_subsection("Particles");
  prm.set("Region", "");
  prm.set("Maximum number", "19");
  prm.leave_subsection();
  generator.parse_parameters(prm);
  Particles::ParticleSet<1> none;
  PSMPM_CHECK(out,
              throws_naming(
                [&]() {
                  generator.generate(mesh, tria, locator, density, all, none);
                },
                "Particles/Maximum number"));
}
