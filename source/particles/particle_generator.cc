// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <psmpm/particles/particle_generator.h>

namespace psmpm
{
  namespace Particles
  {
    void
    ParticleGenerator::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Particles");
      prm.declare_entry("Per block x",
                        "16",
                        Patterns::Integer(1),
                        "Particles per block in x (block meshes).");
      prm.declare_entry("Per block y",
                        "14",
                        Patterns::Integer(1),
                        "Particles per block in y (block meshes).");
      prm.declare_entry("Per cell",
                        "3",
                        Patterns::Integer(1),
                        "Gmsh meshes: each triangle is split into Per cell^2 "
                        "similar triangles with a particle at each centroid.");
      prm.declare_entry("Region",
                        "",
                        Patterns::List(Patterns::Double(), 0, 4, ","),
                        "Box x0, y0, x1, y1 that holds the material; empty "
                        "means the whole mesh.");
      prm.declare_entry("Maximum number",
                        "5e7",
                        Patterns::Double(1),
                        "Refuse to start when more particles would be made "
                        "(each needs about 0.5 kB with its caches).");
      prm.leave_subsection();
    }

    void
    ParticleGenerator::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Particles");
      per_block_x = prm.get_integer("Per block x");
      per_block_y = prm.get_integer("Per block y");
      per_cell    = prm.get_integer("Per cell");
      region      = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Region")));
      max_particles = prm.get_double("Maximum number");
      prm.leave_subsection();
      AssertThrow(region.empty() || region.size() == 4,
                  ExcMessage("Particles/Region must be empty or x0, y0, x1, "
                             "y1, got " +
                             std::to_string(region.size()) + " numbers."));
      AssertThrow(region.empty() ||
                    (region[2] > region[0] && region[3] > region[1]),
                  ExcMessage("Particles/Region: need x0 < x1 and y0 < y1."));
    }

    void
    ParticleGenerator::check_count(const Mesh::MeshGenerator &mesh) const
    {
      if (mesh.type == Mesh::MeshGenerator::Type::gmsh)
        return; // checked against the cell count once the mesh is read
      const double total =
        double(mesh.blocks_x) * mesh.blocks_y * per_block_x * per_block_y;
      AssertThrow(total <= max_particles,
                  ExcMessage(
                    "Mesh/Blocks x, Blocks y and Particles/Per block "
                    "x, Per block y ask for " +
                    std::to_string(total) +
                    " particles, more than Particles/Maximum number = " +
                    std::to_string(max_particles) + "."));
    }

    bool
    ParticleGenerator::in_region(const Point<2> &p) const
    {
      return region.empty() || (p[0] >= region[0] && p[0] <= region[2] &&
                                p[1] >= region[1] && p[1] <= region[3]);
    }

    void
    ParticleGenerator::generate(
      const Mesh::MeshGenerator               &mesh,
      const Triangulation<2>                  &tria,
      const Mesh::CellLocator                 &locator,
      const double                             density,
      const std::function<bool(unsigned int)> &is_owned,
      ParticleSet                             &particles) const
    {
      if (mesh.type != Mesh::MeshGenerator::Type::gmsh)
        {
          check_count(mesh);
          const double  hx     = mesh.length / mesh.blocks_x;
          const double  hy     = mesh.height / mesh.blocks_y;
          const double  volume = hx * hy / (per_block_x * per_block_y);
          std::uint64_t id     = 0;
          unsigned int  hint   = 0;
          for (unsigned int bj = 0; bj < mesh.blocks_y; ++bj)
            for (unsigned int bi = 0; bi < mesh.blocks_x; ++bi)
              for (unsigned int j = 0; j < per_block_y; ++j)
                for (unsigned int i = 0; i < per_block_x; ++i, ++id)
                  {
                    const Point<2> x(hx * (bi + (i + 0.5) / per_block_x),
                                     hy * (bj + (j + 0.5) / per_block_y));
                    if (!in_region(x))
                      continue;
                    const unsigned int c = locator.locate(x, hint);
                    AssertThrow(c != Mesh::CellLocator::invalid,
                                ExcInternalError());
                    hint = c;
                    if (is_owned(c))
                      particles.add(id, c, x, volume, density);
                  }
        }
      else
        {
          const unsigned int k     = per_cell;
          const double       total = double(tria.n_active_cells()) * k * k;
          AssertThrow(total <= max_particles,
                      ExcMessage(
                        "Particles/Per cell: " + std::to_string(total) +
                        " particles exceed Particles/Maximum "
                        "number = " +
                        std::to_string(max_particles) + "."));
          for (const auto &cell : tria.active_cell_iterators())
            {
              const unsigned int c      = cell->active_cell_index();
              const Point<2>     v0     = cell->vertex(0);
              const Tensor<1, 2> e1     = (cell->vertex(1) - v0) / k;
              const Tensor<1, 2> e2     = (cell->vertex(2) - v0) / k;
              const double       volume = cell->measure() / (k * k);
              std::uint64_t      id     = std::uint64_t(c) * k * k;
              // k^2 sub-triangles: upright (i, j) and inverted ones.
              for (unsigned int j = 0; j < k; ++j)
                for (unsigned int i = 0; i + j < k; ++i)
                  {
                    const Point<2> up =
                      v0 + (i + 1. / 3) * e1 + (j + 1. / 3) * e2;
                    if (is_owned(c) && in_region(up))
                      particles.add(id, c, up, volume, density);
                    ++id;
                    if (i + j + 1 < k)
                      {
                        const Point<2> down =
                          v0 + (i + 2. / 3) * e1 + (j + 2. / 3) * e2;
                        if (is_owned(c) && in_region(down))
                          particles.add(id, c, down, volume, density);
                        ++id;
                      }
                  }
            }
        }
    }
  } // namespace Particles
} // namespace psmpm
