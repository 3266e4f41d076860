// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <psmpm/base/format.h>
#include <psmpm/particles/particle_generator.h>

#include <boost/serialization/string.hpp>
#include <cmath>

namespace psmpm
{
  namespace Particles
  {
    namespace
    {
      /// "(x, y)" of a point, as in a parameter file.
      template <int dim>
      std::string
      where(const Point<dim> &p)
      {
        std::string text = "(" + prm_value(p[0]);
        for (unsigned int d = 1; d < dim; ++d)
          text += ", " + prm_value(p[d]);
        return text + ")";
      }

      /// Add the particle @p id at @p x of a block mesh if it lies in a
      /// body and in a cell this rank owns. @p hint is the cell of the
      /// previous point (the points come in block order).
      template <int dim, typename Classify>
      void
      add_block_particle(const std::uint64_t                      id,
                         const Point<dim>                        &x,
                         const double                             volume,
                         const Mesh::CellLocator<dim>            &locator,
                         const std::vector<double>               &density,
                         const std::function<bool(unsigned int)> &is_owned,
                         const Classify                          &classify,
                         const bool                               partial,
                         unsigned int                            &hint,
                         ParticleSet<dim>                        &particles)
      {
        const int body = classify(x);
        if (body < 0)
          return;
        const unsigned int c = locator.locate(x, hint);
        if (c == Mesh::CellLocator<dim>::invalid && partial)
          return; // in a part of the mesh this rank does not hold
        AssertThrow(c != Mesh::CellLocator<dim>::invalid,
                    ExcMessage("The particle position " + where(x) +
                               " lies in no cell of the mesh."));
        hint = c;
        if (is_owned(c))
          particles.add(id, c, x, volume, density[body], body);
      }

      /// 1D: per_block_x particles at the centres of equal sub-intervals
      /// of every element (= block), numbered left to right; @p add
      /// (id, x, volume) places each (add_block_particle()).
      template <typename Add>
      void
      generate_lines(const ParticleGenerator<1>   &generator,
                     const Mesh::MeshGenerator<1> &mesh,
                     const Add                    &add)
      {
        const unsigned int n      = generator.per_block_x;
        const double       h      = mesh.length / mesh.blocks_x;
        const double       volume = h / n;
        std::uint64_t      id     = 0;
        for (unsigned int b = 0; b < mesh.blocks_x; ++b)
          for (unsigned int i = 0; i < n; ++i, ++id)
            // The same x as the 2D block layout with these blocks.
            add(id, Point<1>(h * (b + (i + 0.5) / n)), volume);
      }

      /// 2D block meshes: a per_block_x by per_block_y sub-grid of every
      /// block, numbered block by block; @p add as for generate_lines().
      template <typename Add>
      void
      generate_blocks(const ParticleGenerator<2>   &generator,
                      const Mesh::MeshGenerator<2> &mesh,
                      const Add                    &add)
      {
        const unsigned int per_block_x = generator.per_block_x;
        const unsigned int per_block_y = generator.per_block_y;
        const double       hx          = mesh.length / mesh.blocks_x;
        const double       hy          = mesh.height / mesh.blocks_y;
        const double       volume      = hx * hy / (per_block_x * per_block_y);
        std::uint64_t      id          = 0;
        for (unsigned int bj = 0; bj < mesh.blocks_y; ++bj)
          for (unsigned int bi = 0; bi < mesh.blocks_x; ++bi)
            for (unsigned int j = 0; j < per_block_y; ++j)
              for (unsigned int i = 0; i < per_block_x; ++i, ++id)
                add(id,
                    Point<2>(hx * (bi + (i + 0.5) / per_block_x),
                             hy * (bj + (j + 0.5) / per_block_y)),
                    volume);
      }

      /// 2D Gmsh meshes: every triangle split into per_cell^2 similar
      /// triangles, a particle at each centroid.
      template <typename Classify>
      void
      generate_per_cell(const ParticleGenerator<2>              &generator,
                        const Triangulation<2>                  &tria,
                        const std::vector<double>               &density,
                        const std::function<bool(unsigned int)> &is_owned,
                        const Classify                          &classify,
                        ParticleSet<2>                          &particles)
      {
        const unsigned int k     = generator.per_cell;
        const double       total = double(tria.n_global_active_cells()) * k * k;
        AssertThrow(total <= generator.max_particles,
                    ExcMessage("Particles/Per cell: " + std::to_string(total) +
                               " particles exceed Particles/Maximum "
                               "number = " +
                               std::to_string(generator.max_particles) + "."));
        for (const auto &cell : tria.active_cell_iterators())
          {
            const unsigned int c      = cell->active_cell_index();
            const Point<2>     v0     = cell->vertex(0);
            const Tensor<1, 2> e1     = (cell->vertex(1) - v0) / k;
            const Tensor<1, 2> e2     = (cell->vertex(2) - v0) / k;
            const double       volume = cell->measure() / (k * k);
            // Numbered by the cell's index in the whole mesh (its coarse
            // cell id; the mesh is not refined), also where a rank holds
            // only part of it.
            std::uint64_t id =
              std::uint64_t(cell->id().get_coarse_cell_id()) * k * k;
            // k^2 sub-triangles: upright (i, j) and inverted ones.
            for (unsigned int j = 0; j < k; ++j)
              for (unsigned int i = 0; i + j < k; ++i)
                {
                  const Point<2> up =
                    v0 + (i + 1. / 3) * e1 + (j + 1. / 3) * e2;
                  const int body_up = classify(up);
                  if (is_owned(c) && body_up >= 0)
                    particles.add(id, c, up, volume, density[body_up], body_up);
                  ++id;
                  if (i + j + 1 < k)
                    {
                      const Point<2> down =
                        v0 + (i + 2. / 3) * e1 + (j + 2. / 3) * e2;
                      const int body_down = classify(down);
                      if (is_owned(c) && body_down >= 0)
                        particles.add(id,
                                      c,
                                      down,
                                      volume,
                                      density[body_down],
                                      body_down);
                      ++id;
                    }
                }
          }
      }

      /// What the placement of particles needs besides the body of each
      /// point: the layout, the mesh, the ranks' ownership and the set
      /// that receives them.
      template <int dim>
      struct Placement
      {
        const ParticleGenerator<dim>            &generator;
        const Mesh::MeshGenerator<dim>          &mesh;
        const Triangulation<dim>                &tria;
        const Mesh::CellLocator<dim>            &locator;
        const std::function<bool(unsigned int)> &is_owned;
        /// The distributed mesh of which this rank holds a part, or null.
        const parallel::fullydistributed::Triangulation<dim> *par;
        ParticleSet<dim>                                     &particles;

        /// Add the candidate points of the mesh's layout (lines, blocks or
        /// per cell) that @p classify puts in body b >= 0, with density
        /// @p density[b].
        template <typename Classify>
        void
        place(const std::vector<double> &density,
              const Classify            &classify) const
        {
          // The block layouts' points come in block order: each one's
          // cell is searched from the previous point's.
          unsigned int hint = 0;
          const auto   add  = [&](const std::uint64_t id,
                               const Point<dim>   &x,
                               const double        volume) {
            add_block_particle(id,
                               x,
                               volume,
                               locator,
                               density,
                               is_owned,
                               classify,
                               par != nullptr,
                               hint,
                               particles);
          };
          if constexpr (dim == 1)
            {
              generator.check_count(mesh);
              generate_lines(generator, mesh, add);
            }
          else if (mesh.type != Mesh::MeshGenerator<dim>::Type::gmsh)
            {
              generator.check_count(mesh);
              generate_blocks(generator, mesh, add);
            }
          else
            generate_per_cell(generator,
                              tria,
                              density,
                              is_owned,
                              classify,
                              particles);
        }
      };

      /// The whole boundary of every body must lie in the mesh: a body cut
      /// by the mesh boundary would silently lose material. The outline is
      /// pulled towards the inside by a relative 1e-9 so that a body flush
      /// with the mesh boundary is accepted.
      void
      check_bodies_inside_mesh(
        const Bodies                                       &bodies,
        const Mesh::CellLocator<2>                         &locator,
        const parallel::fullydistributed::Triangulation<2> *par)
      {
        for (const Body &body : bodies.bodies)
          {
            const double h       = std::sqrt(body.shape.area()) / 64;
            const auto   outline = body.shape.outline(h);
            Point<2>     mean;
            for (const auto &p : outline)
              mean += p / double(outline.size());
            // On a distributed mesh a point is inside if some rank holds
            // its cell.
            std::vector<unsigned int> inside(outline.size());
            for (std::size_t i = 0; i < outline.size(); ++i)
              inside[i] =
                locator.locate(outline[i] + 1e-9 * (mean - outline[i])) !=
                Mesh::CellLocator<2>::invalid;
            if (par != nullptr)
              Utilities::MPI::max(inside, par->get_communicator(), inside);
            for (std::size_t i = 0; i < outline.size(); ++i)
              AssertThrow(inside[i],
                          ExcMessage(body.name() + " (" +
                                     body.shape.description() +
                                     ") reaches outside the mesh at " +
                                     where(outline[i]) + "."));
          }
      }

      /// Place the particles of the bodies (each point in the body whose
      /// shape holds it, density its own or @p density) and refuse bodies
      /// that overlap or hold no particle.
      void
      place_bodies(const Bodies       &bodies,
                   const double        density,
                   const Placement<2> &placement)
      {
        std::vector<double> densities{density};
        for (const Body &body : bodies.bodies)
          densities.push_back(body.density > 0 ? body.density : density);
        // Counted over every candidate point, owned or not, so that all
        // ranks reach the same verdict without communication.
        std::vector<std::uint64_t> count(bodies.bodies.size() + 1, 0);
        std::string                overlap;
        placement.place(densities, [&](const Point<2> &p) {
          int         found = -1;
          const Body *first = nullptr;
          for (const Body &body : bodies.bodies)
            if (body.shape.inside(p))
              {
                if (found < 0)
                  found = body.number, first = &body;
                else if (overlap.empty())
                  overlap = body.name() + " (" + body.shape.description() +
                            ") overlaps " + first->name() + " (" +
                            first->shape.description() +
                            "): both contain the particle position " +
                            where(p) + ".";
              }
          if (found > 0)
            ++count[found];
          return found;
        });
        // A distributed Gmsh mesh: each rank placed its part's points.
        if (placement.par != nullptr &&
            placement.mesh.type == Mesh::MeshGenerator<2>::Type::gmsh)
          {
            const MPI_Comm comm = placement.par->get_communicator();
            for (const auto &o : Utilities::MPI::all_gather(comm, overlap))
              if (overlap.empty())
                overlap = o;
            Utilities::MPI::sum(count, comm, count);
          }
        AssertThrow(overlap.empty(), ExcMessage(overlap));
        for (const Body &body : bodies.bodies)
          AssertThrow(count[body.number] > 0,
                      ExcMessage(body.name() + " (" + body.shape.description() +
                                 ") holds no particle: it is smaller than "
                                 "the particle spacing or falls between "
                                 "the particle positions."));
      }
    } // namespace



    template <int dim>
    void
    ParticleGenerator<dim>::declare_parameters(ParameterHandler &prm)
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
      Bodies::declare_parameters(prm);
    }



    template <int dim>
    void
    ParticleGenerator<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Particles");
      per_block_x = prm.get_integer("Per block x");
      per_block_y = prm.get_integer("Per block y");
      per_cell    = prm.get_integer("Per cell");
      try
        {
          region = Utilities::string_to_double(
            Utilities::split_string_list(prm.get("Region")));
        }
      catch (const std::exception &)
        {
          // The pattern takes subnormals string_to_double refuses.
          AssertThrow(false,
                      ExcMessage("Particles/Region = '" + prm.get("Region") +
                                 "': not a list of numbers."));
        }
      max_particles = prm.get_double("Maximum number");
      prm.leave_subsection();
      if constexpr (dim == 1)
        {
          AssertThrow(region.empty() || region.size() == 2,
                      ExcMessage("Particles/Region must be empty or x0, x1 "
                                 "in 1D, got " +
                                 std::to_string(region.size()) + " numbers."));
          AssertThrow(region.empty() || region[1] > region[0],
                      ExcMessage("Particles/Region: need x0 < x1."));
        }
      else
        {
          AssertThrow(region.empty() || region.size() == 4,
                      ExcMessage("Particles/Region must be empty or x0, y0, "
                                 "x1, y1, got " +
                                 std::to_string(region.size()) + " numbers."));
          AssertThrow(
            region.empty() || (region[2] > region[0] && region[3] > region[1]),
            ExcMessage("Particles/Region: need x0 < x1 and y0 < y1."));
        }
      bodies.parse_parameters(prm);
      AssertThrow(bodies.empty() || dim == 2,
                  ExcMessage("Bodies/Number of bodies = " +
                             std::to_string(bodies.bodies.size()) +
                             ": bodies need Geometry/Dimension = 2."));
      AssertThrow(bodies.empty() || region.empty(),
                  ExcMessage("Bodies/Number of bodies = " +
                             std::to_string(bodies.bodies.size()) +
                             " and Particles/Region: the bodies say where the "
                             "material is; leave Region empty."));
    }



    template <int dim>
    void
    ParticleGenerator<dim>::check_count(
      const Mesh::MeshGenerator<dim> &mesh) const
    {
      if constexpr (dim == 1)
        {
          const double total = double(mesh.blocks_x) * per_block_x;
          AssertThrow(total <= max_particles,
                      ExcMessage(
                        "Mesh/Blocks x and Particles/Per block x ask for " +
                        std::to_string(total) +
                        " particles, more than Particles/Maximum number = " +
                        std::to_string(max_particles) + "."));
        }
      else
        {
          if (mesh.type == Mesh::MeshGenerator<dim>::Type::gmsh)
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
    }



    template <int dim>
    bool
    ParticleGenerator<dim>::in_region(const Point<dim> &p) const
    {
      if (region.empty())
        return true;
      // region = {lower corner, upper corner}.
      for (unsigned int d = 0; d < dim; ++d)
        if (!(p[d] >= region[d] && p[d] <= region[dim + d]))
          return false;
      return true;
    }



    template <int dim>
    bool
    ParticleGenerator<dim>::fills_mesh(const Triangulation<dim> &tria) const
    {
      // Bodies are taken to leave room around them (a body that happens
      // to fill the mesh is not worth a geometric test).
      if (!bodies.bodies.empty())
        return false;
      if (region.empty())
        return true;
      for (const auto &x : tria.get_vertices())
        if (!in_region(x))
          return false;
      return true;
    }

    template <int dim>
    void
    ParticleGenerator<dim>::generate(
      const Mesh::MeshGenerator<dim>          &mesh,
      const Triangulation<dim>                &tria,
      const Mesh::CellLocator<dim>            &locator,
      const double                             density,
      const std::function<bool(unsigned int)> &is_owned,
      ParticleSet<dim>                        &particles) const
    {
      // A distributed mesh: this rank holds its cells and their ghost
      // layer only.
      const auto *par =
        dynamic_cast<const parallel::fullydistributed::Triangulation<dim> *>(
          &tria);
      // One placement for every scene: classify(x) says which body the
      // candidate point x belongs to (0: the one material of a scene
      // without Bodies) or -1 for none.
      const Placement<dim>
        placement{*this, mesh, tria, locator, is_owned, par, particles};
      if (bodies.empty())
        {
          // Counted over every candidate point, owned or not (as for the
          // bodies): a region that misses the mesh would otherwise run
          // without particles and fail on the statistics' NaN.
          std::uint64_t count = 0;
          placement.place({density}, [this, &count](const Point<dim> &p) {
            if (!in_region(p))
              return -1;
            ++count;
            return 0;
          });
          if (par != nullptr &&
              mesh.type == Mesh::MeshGenerator<dim>::Type::gmsh)
            count = Utilities::MPI::sum(count, par->get_communicator());
          std::string text;
          for (const double r : region)
            text += (text.empty() ? "" : ", ") + prm_value(r);
          AssertThrow(count > 0,
                      ExcMessage("Particles/Region = '" + text +
                                 "' holds no particle: it lies outside the "
                                 "mesh or between the particle positions "
                                 "of Particles/Per block."));
          return;
        }
      if constexpr (dim == 2)
        {
          check_bodies_inside_mesh(bodies, locator, par);
          place_bodies(bodies, density, placement);
          particles.n_bodies = bodies.bodies.size();
        }
    }



    template class ParticleGenerator<1>;
    template class ParticleGenerator<2>;
  } // namespace Particles
} // namespace psmpm
