// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_mesh_generator_h
#define psmpm_mesh_mesh_generator_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

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
    /// Boundary id of the faces that bound a rank's ghost layer inside
    /// a distributed mesh (never a boundary of the mesh).
    constexpr types::boundary_id rim_boundary_id = 254;

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

      /// Throws ExcMessage naming the entry for invalid values. Collective
      /// over @p comm, whose ranks must all be able to read a Gmsh
      /// Mesh/File (check_msh_on_all_ranks()).
      void
      parse_parameters(ParameterHandler &prm, MPI_Comm comm = MPI_COMM_SELF);

      /// Fill the (empty) triangulation @p tria.
      void
      create(Triangulation<dim> &tria) const;

      /**
       * Mesh/Distribution = distributed: fill @p tria with this rank's
       * cells and @p ghost_layers (1 or 2) layers of ghost cells around
       * them: the cells sharing a vertex with one, and with two also the
       * cells sharing a vertex with those (a Powell-Sabin function of a
       * cell of the first layer is built from the cells around its
       * vertices). The block meshes (criss-cross, diagonal) with
       * Mesh/Partitioner = automatic or blocks: every rank describes its
       * own part (a BlockPartition tile) from the mesh's parameters, and
       * no rank holds the whole mesh. Otherwise (Gmsh, cartesian,
       * Mesh/Partitioner = metis, or ranks that do not tile the blocks):
       * rank 0 alone builds the whole mesh, partitions it with METIS (as
       * parallel::shared does) and sends every rank its part. The faces that
       * bound the ghost layer but not the mesh get rim_boundary_id
       * (deal.II would give them boundary id 0, which a scene may fix).
       * Collective; an error in the mesh (a bad Gmsh file) is thrown on
       * every rank. Returns the owning rank of every cell of the whole
       * mesh, by its index there (= the coarse cell id of the cell in
       * @p tria), for the checkpoints.
       */
      std::vector<unsigned int>
      create_distributed(parallel::fullydistributed::Triangulation<dim> &tria,
                         const unsigned int ghost_layers = 1) const;

      /// Map from boundary name to boundary id for the created mesh.
      const std::map<std::string, types::boundary_id> &
      boundary_names() const;

      /// Id of the boundary called @p name; throws if there is none.
      types::boundary_id
      boundary_id(const std::string &name) const;

      /// Name boundary id @p id (made after create(), e.g. a part of a
      /// boundary: Boundary conditions/Boundary parts).
      void
      add_boundary_name(const std::string       &name,
                        const types::boundary_id id) const;

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
      /// Mesh/Distribution = distributed.
      bool distributed = false;
      /// Mesh/Partitioner: automatic, blocks or metis.
      std::string partitioner = "automatic";

    private:
      /// The checks of a block mesh's shape that create() makes.
      void
      check_block_shape() const;

      /// create_distributed() with every rank describing its BlockPartition
      /// tile; false (nothing done) where that does not apply.
      bool
      create_distributed_blocks(
        parallel::fullydistributed::Triangulation<dim> &tria,
        const unsigned int                              ghost_layers,
        std::vector<unsigned int>                      &owner) const;

      /// create_distributed() from the whole mesh on rank 0 (METIS).
      std::vector<unsigned int>
      create_distributed_on_root(
        parallel::fullydistributed::Triangulation<dim> &tria,
        const unsigned int                              ghost_layers) const;

      mutable std::map<std::string, types::boundary_id> names;
    };
  } // namespace Mesh
} // namespace psmpm

#endif
