// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_mesh_generator_h
#define psmpm_mesh_mesh_generator_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * Creates the mesh of a scene from the subsections "Geometry"
     * and "Mesh".
     *
     * 2D: rectangles of Blocks x by Blocks y blocks, each split into four
     * triangles around its centre ("criss-cross", thesis Fig. 4.2) or into
     * two ("diagonal"), or kept as one quadrilateral ("cartesian", for
     * the tensor-product B-splines), or a Gmsh file. Rectangle boundaries get
     * the ids of left, right, bottom, top (0, 1, 2, 3); Gmsh physical line tags
     * become boundary ids and their physical names become boundary names.
     *
     * 1D: Blocks x equal lines on [0, Length] with the boundary ids of
     * left (x = 0) and right (x = Length), 0 and 1. Type (other than gmsh,
     * which is an error), Height and Blocks y are ignored.
     */
    template <int dim>
    class MeshGenerator
    {
    public:
      enum class Type
      {
        criss_cross,
        diagonal,
        cartesian,
        gmsh
      };

      static void
      declare_parameters(ParameterHandler &prm);

      /// Throws ExcMessage naming the entry for invalid values.
      void
      parse_parameters(ParameterHandler &prm);

      /// Fill the (empty) triangulation @p tria.
      void
      create(Triangulation<dim> &tria) const;

      /// Map from boundary name to boundary id for the created mesh.
      const std::map<std::string, types::boundary_id> &
      boundary_names() const;

      /// Id of the boundary called @p name; throws if there is none.
      types::boundary_id
      boundary_id(const std::string &name) const;

      /// A rectangle [lower, upper] of nx by ny blocks split as @p type
      /// (2D only, whatever dim).
      static void
      make_blocks(Triangulation<2>  &tria,
                  const Point<2>    &lower,
                  const Point<2>    &upper,
                  const unsigned int nx,
                  const unsigned int ny,
                  const Type         type);

      /// Read a Gmsh .msh file of triangles; returns the physical names
      /// found in it (2D only, whatever dim).
      static std::map<std::string, types::boundary_id>
      read_gmsh(Triangulation<2> &tria, const std::string &filename);

      Type         type     = Type::criss_cross;
      double       length   = 1.0;
      double       height   = 1.0;
      unsigned int blocks_x = 1;
      unsigned int blocks_y = 1;
      std::string  file;

    private:
      mutable std::map<std::string, types::boundary_id> names;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
