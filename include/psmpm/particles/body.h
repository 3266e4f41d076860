// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_particles_body_h
#define psmpm_particles_body_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Particles
  {
    using namespace dealii;

    /**
     * A 2D region that holds material: a rectangle, a disk, a simple
     * polygon, or the triangles of physical surfaces in a Gmsh geometry
     * file. One class with a switch rather than a hierarchy: the generator
     * asks inside() for every candidate point, and the tests are a few
     * flops each (a Gmsh shape: one per edge of its outline).
     */
    class Shape
    {
    public:
      enum class Type
      {
        rectangle,
        disk,
        polygon,
        gmsh
      };

      /// Rectangle from Corners = x0, y0, x1, y1.
      static Shape
      rectangle(const Point<2> &lower, const Point<2> &upper);
      static Shape
      disk(const Point<2> &center, const double radius);
      /// Vertices in order (either orientation), the last joined to the
      /// first.
      static Shape
      polygon(const std::vector<Point<2>> &vertices);
      /**
       * The union of the cells of an ASCII Gmsh file (msh 2 or 4) whose
       * physical surface is in @p surfaces (names from $PhysicalNames or
       * numeric tags; empty: every cell). Holes and several pieces are
       * allowed. @p entry ("Bodies/Body 2") prefixes every error message.
       * Defined in gmsh_shape.cc.
       */
      static Shape
      from_gmsh(const std::string              &file,
                const std::vector<std::string> &surfaces,
                const std::string              &entry);

      /// Points on the boundary count as inside (closed shapes), so that
      /// a rectangle flush with a block edge keeps the particles on it.
      bool
      inside(const Point<2> &p) const;

      double
      area() const;

      /// Points along the boundary, at most @p spacing apart (and every
      /// corner): what must lie in the mesh for the shape to be in it.
      std::vector<Point<2>>
      outline(const double spacing) const;

      /// True if two non-adjacent edges of a polygon meet (always false
      /// for the others).
      bool
      self_intersecting() const;

      /// The shape as its parameter entries ("Shape = disk, Center = 0.5,
      /// 0.5, Radius = 0.2"), for messages.
      std::string
      description() const;

      Type                  type = Type::rectangle;
      std::vector<Point<2>> vertices; ///< rectangle: lower, upper corner
      Point<2>              center;
      double                radius = 0;
      /// Gmsh: the outline (edges of exactly one selected cell), its
      /// bounding box, the cells' area, the file and surfaces as given.
      std::vector<std::array<Point<2>, 2>> edges;
      Point<2>                             box_lower, box_upper;
      double                               gmsh_area = 0;
      std::string                          file;
      std::string                          surfaces;
    };

    /// One entry of subsection Bodies: its shape and initial state.
    struct Body
    {
      /// "Bodies/Body <number>", the prefix of every message about it.
      std::string
      name() const
      {
        return "Bodies/Body " + std::to_string(number);
      }

      unsigned int number = 0; ///< 1-based, also the particles' body_id
      Shape        shape;
      /// 0: subsection Material, j: subsection Materials/Material j.
      unsigned int material = 0;
      double       density  = 0;
      /// Initial velocity, one expression per component separated by ';',
      /// in x, y with Initial conditions/Function constants.
      std::string velocity;
      /// Motion = prescribed: a driven (rigid) body whose particles move
      /// with the velocity @p motion_velocity, one function of t per
      /// component separated by ';' (Simulator::DrivenBodies).
      bool        prescribed_motion = false;
      std::string motion_velocity;
    };

    /**
     * Subsection "Bodies": "Number of bodies" (0: the material fills the
     * blocks or Particles/Region as before) and "Body 1" ... "Body 8".
     * parse_parameters() checks each body on its own (shape data, sizes,
     * polygon simplicity); what needs the mesh (inside it, not empty, no
     * overlap) is checked by the particle generator.
     */
    class Bodies
    {
    public:
      static constexpr unsigned int max_bodies = 8;
      /// Materials/Material 1 ... this (MaterialSet::max_materials).
      static constexpr unsigned int max_materials = 8;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      bool
      empty() const
      {
        return bodies.empty();
      }

      std::vector<Body> bodies;
    };
  } // namespace Particles
} // namespace psmpm

#endif
