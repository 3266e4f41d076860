// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_particles_particle_generator_h
#define psmpm_particles_particle_generator_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/body.h>
#include <psmpm/particles/particle_set.h>

#include <functional>

namespace psmpm
{
  namespace Particles
  {
    /**
     * Initial material points (subsection "Particles").
     *
     * 2D: on block meshes a regular "Per block x" by "Per block y" layout
     * at the centres of a uniform sub-grid of every block (thesis
     * Sec. 4.1); on Gmsh meshes each triangle is split into "Per cell"^2
     * similar triangles with a particle at each centroid.
     *
     * 1D: "Per block x" particles in every element, at the centres of
     * equal sub-intervals.
     *
     * Volume = covered measure (area in 2D, length in 1D) / particles in
     * it, mass = density x volume. "Region" limits the material to a box.
     *
     * With subsection "Bodies" (2D): the same candidate points, each kept
     * if it lies in one of the bodies' shapes and given that body's
     * density and id, so that particles per cell and volumes stay those of
     * the layout above (a body's boundary cuts through cells; its mass is
     * its area to within the particle spacing). Bodies must lie in the
     * mesh, hold a particle and not share one.
     */
    template <int dim>
    class ParticleGenerator
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Add the particles whose cell satisfies @p is_owned to @p particles.
       * Ids are global and independent of the number of ranks.
       */
      void
      generate(const Mesh::MeshGenerator<dim>          &mesh,
               const Triangulation<dim>                &tria,
               const Mesh::CellLocator<dim>            &locator,
               const double                             density,
               const std::function<bool(unsigned int)> &is_owned,
               ParticleSet<dim>                        &particles) const;

      unsigned int per_block_x = 16;
      unsigned int per_block_y = 14;
      unsigned int per_cell    = 3;
      /// Empty, or the box {x0, x1} (1D) or {x0, y0, x1, y1} (2D).
      std::vector<double> region;
      double              max_particles = 5e7;
      /// Subsection Bodies (empty: none).
      Bodies bodies;

      /// Refuse particle counts above Maximum number before any mesh is
      /// built (block meshes; every 1D mesh).
      void
      check_count(const Mesh::MeshGenerator<dim> &mesh) const;

      /// Whether every cell of @p tria receives particles: no Bodies and
      /// no Region, or a Region that contains the whole mesh.
      bool
      fills_mesh(const Triangulation<dim> &tria) const;

    private:
      bool
      in_region(const Point<dim> &p) const;
    };
  } // namespace Particles
} // namespace psmpm

#endif
